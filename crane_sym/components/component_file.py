"""A component file read and derived: its parts read by
:func:`crane_sym.components.reading.read_parts`, the model of its run built
from them (components that cannot act over the run dropped before the
derivation, :mod:`crane_sym.components.pruning`, and named), and its
[[formula]] tables checked against that model.
"""
from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from crane_sym.components.formulas import read_formulas
from crane_sym.components.kinds import by_table
from crane_sym.components.model import Model
from crane_sym.components.parts import ComponentError
from crane_sym.components.reading import read_parts

__all__ = ["ComponentFile", "read_component_file"]


@dataclass(frozen=True)
class ComponentFile:
    """A read component file: the model (of what its run needs), its run's
    settings, where it came from, its [[formula]] tables
    (:class:`~crane_sym.components.formulas.FileFormula`), its component tables
    as written (kind -> list of tables) and every component as built (``parts``:
    a sweep that changes a value builds its model again from these)."""

    model: Model
    duration: str
    body: str | None
    speed: Any
    path: Path
    rest: bool = False
    formulas: tuple = ()
    tables: dict = field(default_factory=dict)
    parts: tuple = ()


def read_component_file(path: str | Path) -> ComponentFile:
    """Read, check and derive the model of a component file (its format:
    :mod:`crane_sym.components.reading`); ComponentError, one line, for
    anything it cannot take.

    Parameters
    ----------
    path : str or Path
        The component TOML file.
    """
    read = read_parts(path)
    where_file = f"component model {read.name!r}"
    try:
        model = Model.for_run(read.parts, read.duration, read.rest, read.name, read.title)
    except ComponentError as exc:
        raise ComponentError(f"{where_file}: {exc}") from None
    formulas = read_formulas(read.data.get("formula", []), model, where_file,
                             (read.body, read.speed))
    return ComponentFile(model, read.duration, read.body, read.speed, read.path, read.rest,
                         formulas, {k: read.data.get(k, []) for k in by_table()},
                         tuple(read.parts))
