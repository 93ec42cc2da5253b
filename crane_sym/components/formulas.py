"""The ``[[formula]]`` tables of a component file: formulas printed in the
user's source, to be audited against the model derived from the components.

::

    [[formula]]
    name = "(12)"                            # the source's label
    latex = "M_{st} = \\\\frac{m g r}{n i}"     # the print, LaTeX (read by machine)
    symbols = { m = "hook.mass", g = "weight.g", r = "rope.radius",
                n = "rope.reeving", i = "gearbox.ratio" }
    quantity = "gearbox_mesh.static"         # what the formula gives
    tolerance = 0.0                          # optional: relative, for a rounded print
    cause = "..."                            # optional: the user's diagnosis of a finding
    mode = "lowest"                          # optional, for a frequency: "lowest", k, or a link
    at = "0.2 s"                             # optional, for a frequency: the run's instant

``symbols`` maps each name the print uses to a parameter of the model
(``<component>.<key>``, :func:`crane_sym.components.parameters.parameters`),
to ``"time"``, or to a derived quantity (its expression is put in);
``quantity`` names what the formula's left side is
(:mod:`crane_sym.components.quantities`). ``mode`` and ``at`` say which
natural frequency a modal quantity (``frequency``, ``period``,
``damping_ratio``, ``damped_frequency``, named by ``quantity`` or in
``symbols``) means: the lowest (the default), the k-th from the lowest
(``mode = 2``), or the one whose mode loads a link most (``mode = "rope"``),
of the mode the run is in at ``at`` (default: its start;
:mod:`crane_sym.components.vibration`). The names are checked when the
file is read: an unknown key, parameter or quantity is one line naming it.
The LaTeX itself is read only when the file is audited
(:mod:`crane_sym.components.file_audit`), never evaluated.
"""
from __future__ import annotations

import re
from dataclasses import dataclass
from typing import Any

from sympy.physics.units import time

from crane_sym.components.model import Model
from crane_sym.components.parts import ComponentError, value
from crane_sym.components.parameters import parameters
from crane_sym.components.quantities import QUANTITIES, quantity_table
from crane_sym.components.vibration import LOWEST, MODAL
from crane_sym.scenes.options import did_you_mean

__all__ = ["FORMULA_KEYS", "FileFormula", "TIME", "read_formulas"]

#: Keys of a [[formula]] table: required, then optional.
FORMULA_KEYS = (("name", "latex", "quantity"),
                ("symbols", "tolerance", "cause", "mode", "at"))
#: The word a symbol maps to for time.
TIME = "time"
_PRINTED_NAME = re.compile(r"\S{1,40}")


@dataclass(frozen=True)
class FileFormula:
    """One [[formula]] of a component file, its names checked."""

    name: str
    latex: str
    quantity: str
    symbols: tuple[tuple[str, str], ...]
    tolerance: float = 0.0
    cause: str = ""
    mode: int | str = LOWEST
    at: float | None = None

    @property
    def modal(self) -> bool:
        """Whether the formula names a natural frequency or a quantity of one."""
        return any(p.partition(".")[2] in MODAL
                   for p in [self.quantity, *(t for _, t in self.symbols)])


def _quantity_names(model: Model) -> dict[str, str]:
    """Every quantity the model's components have a name for -> its kind."""
    a = model.assembly
    out = {}
    owners = {"body": list(a.bodies), "link": [l.part.name for l in a.links],
              "contact": [c.part.name for c in a.contacts]}
    for what, (owner, _) in quantity_table().items():
        names = owners.get(owner) or [p.name for p in (*[l.part for l in a.loads],
                                                       *a.couplings) if p.kind == owner]
        out |= {f"{n}.{what}": what for n in names}
    return out


def _of(owner: str) -> list[str]:
    """The quantities a component of ``owner``'s kind has (``link``, ``contact``)."""
    return [what for what, (kind, _) in QUANTITIES.items() if kind == owner]


def _declared() -> str:
    """The quantities the kinds declare, as a message lists them
    (``<dc motor>.time_constant, ``)."""
    return "".join(f"<{owner}>.{what}, " for what, (owner, _) in quantity_table().items()
                   if what not in QUANTITIES)


def _check_quantity(path: object, model: Model, where: str, key: str) -> str:
    if not isinstance(path, str):
        raise ComponentError(f"{where}: {key} must be text like \"coupling.static\", "
                             f"got {path!r}")
    known = _quantity_names(model)
    if path not in known:
        raise ComponentError(f"{where}: unknown quantity {path!r}; "
                             f"{did_you_mean(path, list(known))}a quantity is "
                             f"<body>.reduced_inertia, {_declared()}<span>."
                             f"{{{', '.join(_of('span'))}}}, <link>."
                             f"{{{', '.join(_of('link'))}}} or <ground contact>."
                             f"{{{', '.join(_of('contact'))}}}")
    return path


def _check_symbols(table: object, model: Model, where: str,
                   start: tuple | None = None) -> tuple[tuple[str, str], ...]:
    if not isinstance(table, dict):
        raise ComponentError(f"{where}: symbols must be a table like {{ c = "
                             f"\"coupling.stiffness\" }}, got {table!r}")
    known = parameters(model, start)
    out = []
    for printed, target in table.items():
        if not _PRINTED_NAME.fullmatch(printed):
            raise ComponentError(f"{where}: symbols: {printed!r} is not a printed name")
        if not isinstance(target, str):
            raise ComponentError(f"{where}: symbols: {printed!r} must map to a parameter "
                                 f"name as text, got {target!r}")
        if target != TIME and target not in known:
            name, _, what = target.partition(".")
            if what in quantity_table():
                _check_quantity(target, model, f"{where}: symbols: {printed!r}", "it")
            else:
                raise ComponentError(
                    f"{where}: symbols: {printed!r} maps to unknown parameter {target!r}; "
                    f"{did_you_mean(target, list(known))}parameters: {', '.join(known)}, "
                    f"or \"{TIME}\", or a quantity")
        out.append((printed, target))
    return tuple(out)


def read_formulas(entries: Any, model: Model, where: str,
                  start: tuple | None = None) -> tuple[FileFormula, ...]:
    """The [[formula]] tables of a file, their keys and names checked against
    ``model``; ComponentError, one line naming the formula and what is wrong.

    Parameters
    ----------
    entries : Any
        ``data.get("formula", [])`` of the parsed TOML.
    model : Model
        The file's model, whose parameters and quantities the names must be.
    where : str
        How errors name the file's model.
    start : (body, speed), optional
        The [run] table's start, so that ``run.speed`` is a name a formula may map.
    """
    if not isinstance(entries, list) or not all(isinstance(e, dict) for e in entries):
        raise ComponentError(f"{where}: [[formula]] must be an array of tables "
                             "(write [[formula]], not [formula])")
    required, optional = FORMULA_KEYS
    out, seen = [], set()
    for number, entry in enumerate(entries, 1):
        here = f"{where}: [[formula]] {entry.get('name', f'number {number}')!r}"
        for key in entry:
            if key not in required + optional:
                raise ComponentError(f"{here}: unknown key {key!r}; "
                                     f"{did_you_mean(key, required + optional)}expected "
                                     f"{', '.join(required + optional)}")
        missing = [k for k in required if k not in entry]
        if missing:
            raise ComponentError(f"{here}: lacks {', '.join(map(repr, missing))}")
        for key in ("name", "latex", "cause"):
            if key in entry and not (isinstance(entry[key], str) and entry[key].strip()):
                raise ComponentError(f"{here}: {key} must be non-empty text")
        if entry["name"] in seen:
            raise ComponentError(f"{here}: the name is given twice")
        seen.add(entry["name"])
        tolerance = entry.get("tolerance", 0.0)
        if isinstance(tolerance, bool) or not isinstance(tolerance, (int, float)) \
                or not 0 <= tolerance < 1:
            raise ComponentError(f"{here}: tolerance must be a number in [0, 1), "
                                 f"got {tolerance!r}")
        f = FileFormula(entry["name"], entry["latex"],
                        _check_quantity(entry["quantity"], model, here, "quantity"),
                        _check_symbols(entry.get("symbols", {}), model, here, start),
                        float(tolerance), entry.get("cause", ""),
                        *_check_choice(entry, model, here))
        if not f.modal and ("mode" in entry or "at" in entry):
            raise ComponentError(f"{here}: mode and at choose a natural frequency; the "
                                 f"formula names none ({', '.join(MODAL)})")
        out.append(f)
    return tuple(out)


def _check_choice(entry: dict, model: Model, where: str) -> tuple[int | str, float | None]:
    """(mode, at) of a formula: which natural frequency, at which instant of the run."""
    mode = entry.get("mode", LOWEST)
    links = [l.part.name for l in model.assembly.links]
    if isinstance(mode, bool) or not (isinstance(mode, int) and mode >= 1 or
                                      mode == LOWEST or mode in links):
        raise ComponentError(f"{where}: mode must be \"{LOWEST}\", a number k >= 1 (the k-th "
                             f"from the lowest) or an elastic link ({', '.join(links)}), "
                             f"got {mode!r}")
    at = entry.get("at")
    if at is not None:
        at = value(where, "at", at, time).si
        if not at >= 0:
            raise ComponentError(f"{where}: at must be an instant >= 0 s, got {at:g} s")
    return mode, at
