"""A scene's results as data: ``crane-sym run --format json``.

The report of a scene gives its numbers in SI (``SceneReport.values``); the
paper declares the unit of each (``VALUE_UNITS``: a ``fnmatch`` pattern of the
names -> unit, the first that matches, :func:`crane_sym.registry.value_units`).
:func:`scene_results` puts them together: the scene's name, every result as
``{"value": number, "unit": text}`` (``"1"`` for a ratio; a value that is not
a finite number, such as an event that did not happen, is ``null``), the
warnings as a list, the lines the text format prints, the files written.
"""
from __future__ import annotations

import math
from fnmatch import fnmatchcase
from pathlib import Path
from typing import Any, Mapping, Sequence

from crane_sym import registry
from crane_sym.scenes.reading import Scene, SceneReport

__all__ = ["number", "scene_results", "unit_of"]


def number(value: Any) -> float | None:
    """``value`` as a JSON number: a float, or None where it is not finite.

    Parameters
    ----------
    value : number
        A result.
    """
    f = float(value)
    return f if math.isfinite(f) else None


def unit_of(name: str, units: Mapping[str, str]) -> str | None:
    """The unit the first pattern of ``units`` that matches ``name`` gives
    (None when none does).

    Parameters
    ----------
    name : str
        A result's name.
    units : mapping
        Pattern -> unit, in order.
    """
    return next((unit for pattern, unit in units.items() if fnmatchcase(name, pattern)), None)


def scene_results(scene: Scene, report: SceneReport, files: Sequence[Path]) -> dict[str, Any]:
    """What ``crane-sym run --format json`` prints for a scene of a paper.

    Parameters
    ----------
    scene : Scene
        The scene run.
    report : SceneReport
        Its report.
    files : sequence of Path
        The files written (the module, the plots).
    """
    units = registry.value_units(scene.derivation)
    return {"scene": scene.name, "title": scene.title, "derivation": scene.derivation,
            "results": {name: {"value": number(v), "unit": unit_of(name, units)}
                        for name, v in report.values.items()},
            "warnings": list(report.warnings), "lines": list(report.lines),
            "files": [str(f) for f in files]}
