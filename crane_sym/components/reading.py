"""The component file: a drive train in TOML, values with units.

::

    [model]
    name = "hoist_fig9"
    title = "Table 1 hoist, emergency stop while lowering"

    [[inertia]]                 # a rotating body
    name = "motor"
    inertia = "20 kg*m^2"

    [[mass]]                    # a translating body
    name = "hook"
    mass = "62 t"

    [[gear]]                    # input turns `ratio` times as far as output
    name = "gearbox"
    input = "shaft"
    output = "drum"
    ratio = 26.2

    [[drum]]                    # the load moves radius/reeving per radian of the drum
    name = "rope"
    drum = "drum"
    load = "hook"
    radius = "0.5 m"
    reeving = 4

    [[elastic]]                 # F = c (u - flank) + d u', u = x(second) - x(first)
    name = "coupling"
    between = ["motor", "shaft"]   # or ["ground", "girder"]: "ground" is the fixed end
    stiffness = "4e4 N*m/rad"
    damping = "0 N*m*s/rad"     # optional
    backlash = "78.6 deg"       # optional; contact = "positive" (gap below 0) or "negative"
    reference = "2.9 kN*m"      # optional: the load the dynamic factor divides by

    [[brake]]
    name = "safety"
    body = "drum"
    torque = "130 kN*m"         # `force` on a translating body
    delay = "0.1 s"
    build_up = "step"           # or "ramp", "exponential", with time = "0.2 s"

    [[motor]]
    name = "drive"
    body = "motor"
    torque = "steady"           # or a value; `force` on a translating body
    off_at = "0 s"              # optional

    [[gravity]]
    name = "weight"
    body = "hook"
    g = "9.81 m/s^2"            # optional
    direction = "+"             # the body's coordinate points down

    [[resistance]]
    name = "rolling"
    body = "trolley"
    force = "-1.2 kN"           # `torque` on a rotating body

    [[motor_law]]               # a law in time, piecewise polynomial (paper 002)
    name = "hoist"
    body = "drive"
    law = "acceleration"        # a(t) of the rigid drive; "torque" (a force on a mass);
                                # or "speed": the body follows v(t) exactly
    unit = "m/s^2"              # of the values; c_kj in unit / time_unit^j
    time_unit = "s"             # optional
    breakpoints = [0.0, 0.25, 1.0, 1.25]
    coefficients = [[0.0, 2.0], [0.5], [0.5, -2.0]]   # numbers only, never text

    [[characteristic]]          # a motor's β (v0 − v), stepped at the hold times
    name = "motors"
    body = "left"
    speed = "0.57 m/s"          # no-load speed v0
    slopes = ["1.7e5 N*s/m", "3.4e5 N*s/m"]
    holds = ["0.4 s"]           # one fewer than slopes

    [[span]]                    # an elastic element of its own mass between two points,
    name = "tight"              # each a linear combination of coordinates (kinds.span)
    start = { run = 1 }         # omitted or {}: the frame
    end = { drum = "250 mm", hub = -1 }   # x_end = r phi_drum - x_hub
    stiffness = "5e4 N/m"       # Pi = c u^2/2, u = x_end - x_start
    damping = "0 N*s/m"         # optional
    mass = "1440 kg"            # optional: T = m (v_start^2 + v_start v_end + v_end^2)/6

    [[initial]]                 # a body's state at t = 0 (components.initial)
    name = "lifted"
    body = "hook"
    displacement = "-0.1 m"     # from where the start puts it; and/or
    velocity = "0.5 m/s"        # its velocity (no [run] speed beside it)

    [[formula]]                 # a formula of your source, for `crane-sym audit FILE`
    name = "(12)"               # (crane_sym.components.formulas)
    latex = "M_{st} = \\frac{m g r}{n i}"
    symbols = { m = "hook.mass", g = "weight.g", r = "rope.radius", n = "rope.reeving",
                i = "gearbox.ratio" }
    quantity = "coupling.static"

    [run]
    duration = "1 s"
    start = "steady"            # or "rest": at rest, zero twist, every gap open
    body = "motor"              # the body whose speed is given (default: the first)
    speed = "1500 rpm"          # every part moves steadily at the start

Every value with a dimension is text with its unit, read by
:mod:`crane_sym.units` (parsed, never evaluated); ratios and reevings may be
bare numbers. An unknown table or key is an error naming the closest known
one, as in scenes; every error is one line. Reading builds the parts and
checks their tables; it derives nothing: the model of the file's run is
:func:`crane_sym.components.component_file.read_component_file`'s.
"""
from __future__ import annotations

import re
import tomllib
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from crane_sym.components.kinds import Key, by_table
from crane_sym.components.model_limits import check_counts
from crane_sym.components.parts import ComponentError
from crane_sym.scenes.fields import toml_reason
from crane_sym.scenes.options import did_you_mean

__all__ = ["ComponentParts", "is_component_file", "read_parts"]

MODEL_KEYS, RUN_KEYS = ("name", "title"), ("duration", "start", "body", "speed")
_RUN_BODY = Key("body", "word")
_SAFE_NAME = re.compile(r"[A-Za-z0-9_][A-Za-z0-9_-]{0,63}")


def is_component_file(path: str | Path) -> bool:
    """True for an existing TOML file with a ``[model]`` table and no ``[scene]``.

    Parameters
    ----------
    path : str or Path
        A file name given on the command line.
    """
    p = Path(path)
    if p.suffix != ".toml" or not p.is_file():
        return False
    try:
        data = tomllib.loads(p.read_text(encoding="utf-8"))
    except (tomllib.TOMLDecodeError, UnicodeDecodeError, OSError, RecursionError):
        return False
    return "model" in data and "scene" not in data


def _keys(table: dict, known: tuple[str, ...], where: str, what: str = "key") -> None:
    for key in table:
        if key not in known:
            raise ComponentError(f"{where}: unknown {what} {key!r}; "
                                 f"{did_you_mean(key, known)}expected {', '.join(known)}")


@dataclass(frozen=True)
class ComponentParts:
    """A component file read and checked, its model not yet derived."""

    parts: list
    name: str
    title: str
    duration: str
    body: str | None
    speed: Any
    path: Path
    rest: bool = False
    data: dict = field(default_factory=dict)       # the file's tables, as read


def read_parts(path: str | Path) -> ComponentParts:
    """Read and check a component file into its parts and run settings, without
    assembling or deriving the model (what ``crane-sym bench --components``
    times apart); ComponentError, one line, for anything it cannot take.

    Parameters
    ----------
    path : str or Path
        The component TOML file.
    """
    p = Path(path)
    if not p.is_file():
        raise ComponentError(f"no component file {str(p)!r}")
    try:
        data = tomllib.loads(p.read_text(encoding="utf-8"))
    except (tomllib.TOMLDecodeError, UnicodeDecodeError, RecursionError) as exc:
        raise ComponentError(f"{p.name}: not valid TOML: {toml_reason(exc)}") from None
    kinds = by_table()
    tables = ("model", "run", "formula", *kinds)
    _keys(data, tables, f"component file {p.name!r}", "table")
    head = data.get("model")
    if not isinstance(head, dict):
        raise ComponentError(f"component file {p.name!r}: missing table [model]")
    _keys(head, MODEL_KEYS, f"component file {p.name!r}: [model]")
    name = head.get("name", p.stem)
    if not isinstance(name, str) or not _SAFE_NAME.fullmatch(name):
        raise ComponentError(f"component file {p.name!r}: [model] name must be letters, "
                             f"digits, '_' or '-', got {name!r}")
    where_file = f"component model {name!r}"
    parts = []
    for kind, declared in kinds.items():
        entries = data.get(kind, [])
        if not isinstance(entries, list) or not all(isinstance(e, dict) for e in entries):
            raise ComponentError(f"{where_file}: [[{kind}]] must be an array of tables "
                                 f"(write [[{kind}]], not [{kind}])")
        for number, entry in enumerate(entries, 1):
            where = f"{where_file}: [[{kind}]] {entry.get('name', f'number {number}')!r}"
            _keys(entry, declared.required + declared.optional, where)
            missing = [k for k in declared.required if k not in entry]
            if missing:
                raise ComponentError(f"{where}: lacks {', '.join(map(repr, missing))}")
            parts.append(declared.read(entry, where))
    check_counts(parts, where_file)
    run = data.get("run", {})
    if not isinstance(run, dict):
        raise ComponentError(f"{where_file}: [run] must be a table")
    _keys(run, RUN_KEYS, f"{where_file}: [run]")
    if "duration" not in run:
        raise ComponentError(f"{where_file}: [run] lacks 'duration', e.g. duration = \"1 s\"")
    settings = {k: _RUN_BODY.given(run[k], f"{where_file}: [run]") if k == "body" else run[k]
                for k in run}
    start = run.get("start", "steady")
    if start not in ("steady", "rest"):
        raise ComponentError(f"{where_file}: [run] start must be 'steady' or 'rest', "
                             f"got {start!r}")
    if start == "rest" and ("speed" in run or "body" in run):
        raise ComponentError(f"{where_file}: [run] a start at rest takes no body or speed")
    for key in ("duration", "speed"):
        if key in settings and not isinstance(settings[key], str):
            raise ComponentError(f"{where_file}: [run] {key} needs a value with its unit as "
                                 f"text, got {settings[key]!r}")
    return ComponentParts(parts, name, str(head.get("title", "")), settings["duration"],
                          settings.get("body"), settings.get("speed", 0.0), p, start == "rest",
                          data)
