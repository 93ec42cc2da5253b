"""What a design sweep is asked to do: axes, outputs, a limit, all checked.

``crane-sym sweep SCENE --vary NAME=START:STOP:N[:log] [UNIT] ... --output NAME
[--at NAME=VALUE [UNIT]] [--limit "NAME<=VALUE UNIT"]`` is read here into a
:class:`SweepPlan`: the scene gives every fixed value (SI, from
:func:`crane_sym.scenes.reading.load_scene`); each ``--vary`` turns one of its
parameters into a grid axis whose values are in the unit the scene file gives
that parameter (``m1`` in t for ``"4.4 t"``), unless the argument names
another unit of the same dimension. Every argument is matched by a strict
regular expression and its units by :mod:`crane_sym.units`; nothing the user
types is evaluated. Each error is a :class:`SweepError` whose message starts
with the option and the text that broke it.

Outputs are the derivation's generated closed forms (``kind = "closed"``)
or the simulated responses a paper declares in ``SWEEP_OUTPUTS``
(``kind = "simulated"``, :class:`crane_sym.derivation.SweepOutput`). An axis
must be an argument of an output: one its generated function computes with
for a closed form (:func:`crane_sym.codegen.module.used_arguments`: a function may
accept an argument its expression has lost, such as the masses of a dynamic
coefficient written with Ω), a declared parameter for a simulated response.

One unit per quantity: an axis is shown in its ``--vary`` unit (the scene's by
default), an output in the one unit the scene file gives parameters of the
same SI unit (kN for a force when ``P_t`` and ``W`` are in kN), else in the
``--limit``'s unit, else in SI; a dimensionless quantity in no unit (``""``).
The plan's types are in :mod:`crane_sym.sweep.plan`.
"""
from __future__ import annotations

import math
import re
from functools import partial
from typing import Callable

from crane_sym import registry, units
from crane_sym.codegen.module import used_arguments
from crane_sym.scenes.reading import Scene, SceneError, read_toml
from crane_sym.symbols import TIME
from crane_sym.sweep.plan import (Axis, Limit, OutputSpec, SweepError, SweepPlan, Window,
                                  shown_unit)

__all__ = ["MIN_CHUNK_MIB", "SweepError", "display_units", "parse_at", "parse_chunk_mib",
           "parse_limit", "parse_vary", "plan"]

#: The smallest block ``--chunk-mib`` accepts: below it Dask's cost per task
#: (~0.1 ms) outweighs a block's work.
MIN_CHUNK_MIB = 0.1

_NUM = r"[+-]?(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?"
_NAME = r"[A-Za-z_][A-Za-z0-9_]{0,63}"
#: A name, or ``component.field`` (the fields and outputs of a component file).
_DOTTED = rf"{_NAME}(?:\.{_NAME})?"
_VARY = re.compile(rf"({_DOTTED})=({_NUM}):({_NUM}):(\d{{1,12}})(:log)?(?:\s+(\S.{{0,60}}))?")
_LIMIT = re.compile(rf"\s*({_DOTTED})\s*(<=|>=)\s*({_NUM})\s*(\S.{{0,60}})?")
_AT = re.compile(rf"({_NAME})=({_NUM})(?::({_NUM}):(\d{{1,7}}))?(?:\s*([A-Za-zµμ].{{0,60}}))?")


def _unit(option: str, text: str, unit: str, dimension) -> float:
    """Factor to SI of ``unit``; SweepError naming ``option`` if it is not a
    unit or not of ``dimension``."""
    try:
        factor, dim = units.parse_unit(unit or "1")
    except units.UnitError as exc:
        raise SweepError(f"{option} {text!r}: {exc}") from None
    if not units.same_dimension(dim, dimension):
        raise SweepError(f"{option} {text!r}: unit {unit or '1'!r} does not fit: expected "
                         f"{units.format_dimension(dimension)}, got "
                         f"{units.format_dimension(dim)}")
    return factor


def parse_vary(text: str, scene_units: dict[str, str], symbols) -> Axis:
    """One ``--vary NAME=START:STOP:N[:log] [UNIT]``; ``scene_units`` maps each
    parameter of the scene to the unit text its file gives it."""
    m = _VARY.fullmatch(text.strip())
    if m is None:
        raise SweepError(f"--vary {text!r}: expected NAME=START:STOP:N[:log] [UNIT], "
                         "e.g. m1=1:100:200:log")
    name, start, stop, n, log, unit = m.groups()
    if name not in scene_units:
        raise SweepError(f"--vary {text!r}: {name!r} is not a parameter of the scene; "
                         f"it has {', '.join(scene_units)}")
    start_f, stop_f, count = float(start), float(stop), int(n)
    if not (math.isfinite(start_f) and math.isfinite(stop_f)):
        raise SweepError(f"--vary {text!r}: START and STOP must be finite")
    if count < 2 or start_f == stop_f:
        raise SweepError(f"--vary {text!r}: the range is empty (need START < STOP and N >= 2)")
    if start_f > stop_f:
        raise SweepError(f"--vary {text!r}: the range is reversed (START > STOP)")
    if log and start_f <= 0:
        raise SweepError(f"--vary {text!r}: a log axis cannot reach or cross zero")
    entry = symbols[name]
    unit = unit.strip() if unit else scene_units[name]
    factor = _unit("--vary", text, unit, entry.dimension)
    low = start_f * factor
    if not (math.isfinite(low) and math.isfinite(stop_f * factor)):
        raise SweepError(f"--vary {text!r}: START and STOP must be finite in SI")
    if (entry.sign == "positive" and not low > 0) or (entry.sign == "nonnegative"
                                                      and not low >= 0):
        raise SweepError(f"--vary {text!r}: {name} must be "
                         f"{'> 0' if entry.sign == 'positive' else '>= 0'}")
    return Axis(name, start_f, stop_f, count, bool(log), shown_unit(unit), factor)


def parse_limit(text: str, outputs: tuple[OutputSpec, ...]) -> Limit:
    """``--limit "NAME<=VALUE UNIT"`` (or ``>=``) on one of the outputs."""
    m = _LIMIT.fullmatch(text)
    if m is None:
        raise SweepError(f"--limit {text!r}: expected NAME<=VALUE UNIT, e.g. "
                         "\"peak_elastic_force<=40 kN\"")
    name, op, value, unit = m.groups()
    known = {o.name: o for o in outputs}
    if name not in known:
        raise SweepError(f"--limit {text!r}: {name!r} is not an output of the sweep "
                         f"({', '.join(known)})")
    _, dimension = units.parse_unit(known[name].unit)
    unit = (unit or "").strip() or known[name].unit
    factor = _unit("--limit", text, unit, dimension)
    if not (math.isfinite(float(value)) and math.isfinite(float(value) * factor)):
        raise SweepError(f"--limit {text!r}: the bound must be a finite number")
    return Limit(name, op, float(value), shown_unit(unit), factor, float(value) * factor)


def parse_at(text: str, symbols) -> Window:
    """``--at NAME=VALUE [UNIT]``: a value for an argument the scene does not
    fix, such as the time ``t`` of a time response (unit s by default), as a
    :class:`Window` of one point; ``--at NAME=START:STOP:N [UNIT]``: N samples
    of a window over which the sweep takes the output's maximum."""
    m = _AT.fullmatch(text.strip())
    if m is None:
        raise SweepError(f"--at {text!r}: expected NAME=VALUE [UNIT] or NAME=START:STOP:N "
                         "[UNIT], e.g. t=0.12, t=120 ms or t=0:1.5:301")
    name, value, stop, n, unit = m.groups()
    try:
        entry = symbols[name]
    except KeyError:
        raise SweepError(f"--at {text!r}: {name!r} is not a symbol of the derivation") \
            from None
    unit = (unit or ("s" if entry.role == TIME else entry.unit)).strip()
    factor = _unit("--at", text, unit, entry.dimension)
    ends = [float(value)] + ([float(stop)] if stop is not None else [])
    if not all(math.isfinite(v) and math.isfinite(v * factor) for v in ends):
        raise SweepError(f"--at {text!r}: the value must be a finite number")
    if stop is None:
        return Window(name, float(value), float(value), 1, shown_unit(unit), factor)
    if int(n) < 2 or not float(value) < float(stop):
        raise SweepError(f"--at {text!r}: the window is empty or reversed (need START < STOP "
                         "and N >= 2)")
    return Window(name, float(value), float(stop), int(n), shown_unit(unit), factor)


def parse_chunk_mib(value: float, free_bytes: int | None = None,
                    workers: int | None = None) -> int:
    """``--chunk-mib`` as bytes: a finite size from :data:`MIN_CHUNK_MIB` up to
    what fits in the free memory (``free_bytes``, the machine's available
    memory by default) once per worker (``workers``, the cores by default:
    each holds a block at a time), else SweepError naming the option.

    Parameters
    ----------
    value : float
        The option's value [MiB].
    free_bytes : int, optional
        Free memory.
    workers : int, optional
        Workers holding a block each.
    """
    import os
    if free_bytes is None:
        import psutil
        free_bytes = psutil.virtual_memory().available
    workers = workers or os.cpu_count() or 1
    if not math.isfinite(value) or value < MIN_CHUNK_MIB:
        raise SweepError(f"--chunk-mib {value:g}: expected a finite block size of at least "
                         f"{MIN_CHUNK_MIB:g} MiB (smaller blocks cost Dask more than "
                         "they compute)")
    if value * 2**20 * workers > free_bytes:
        raise SweepError(f"--chunk-mib {value:g}: {workers} blocks at once (one per core) "
                         f"need more than the {free_bytes / 2**20:.0f} MiB of free memory")
    return int(value * 2**20)


def _scene_units(scene: Scene, extra: tuple[str, ...]) -> dict[str, str]:
    """Parameter -> unit text as the scene file writes it (``"4.4 t"`` -> ``t``);
    ``extra`` names values the scene gives in ``[options]``."""
    data = read_toml(scene.path)
    found = {}
    for table, names in (("parameters", list(scene.parameters)), ("options", extra)):
        for name in names:
            raw = data.get(table, {}).get(name)
            if isinstance(raw, dict):
                found[name] = str(raw.get("unit", "")) or "1"
            elif isinstance(raw, str):
                found[name] = units.unit_text(raw) or "1"
            elif raw is not None:
                found[name] = "1"
    return found


def _output_specs(derivation: str, names: list[str]) -> tuple[OutputSpec, ...]:
    d = registry.get(derivation)
    closed = {o.name: o for o in d.outputs if not o.expr.is_Matrix}
    simulated = registry.sweep_outputs(derivation)
    specs = []
    for name in names:
        if name in closed:
            o = closed[name]
            specs.append(OutputSpec(name, "closed", tuple(str(a) for a in o.args), o.unit,
                                    o.summary, tuple(map(str, used_arguments(o, d.symbols)))))
        elif name in simulated:
            s = simulated[name]
            specs.append(OutputSpec(name, "simulated", s.parameters + s.options, s.unit,
                                    s.summary))
        else:
            raise SweepError(f"--output {name!r}: not a sweepable output of {derivation!r}; "
                             f"known: {', '.join([*closed, *simulated])}")
    if len({s.name for s in specs}) != len(specs):
        raise SweepError(f"--output: an output is given twice in {names}")
    return tuple(specs)


def _not_an_argument(name: str, specs: tuple[OutputSpec, ...]) -> str:
    """Why an axis ``name`` is refused: the output(s) it is no argument of."""
    if len(specs) > 1:
        return (f"{name} is not an argument of any output "
                f"({', '.join(s.name for s in specs)})")
    s = specs[0]
    why = (f" (its generated function accepts {name}, its value does not depend on it)"
           if name in s.args else "")
    return (f"{name} is not an argument of {s.name}{why}; it depends on "
            f"{', '.join(s.depends) or 'nothing'}")


def _same_unit(a: str, b: str) -> bool:
    return a.replace(" ", "").replace("·", "*") == b.replace(" ", "").replace("·", "*")


def _scene_given(scene_units: dict[str, str], symbols, output: OutputSpec) -> set[str]:
    """The units the scene file gives its parameters of ``output``'s SI unit in."""
    return {shown_unit(u) for n, u in scene_units.items()
            if n in symbols and _same_unit(symbols[n].unit, output.unit)}


def display_units(specs: tuple[OutputSpec, ...], given: Callable[[OutputSpec], set[str]],
                  limit: Limit | None) -> dict[str, tuple[str, float]]:
    """Output -> (unit it is shown in, factor to SI): ``""`` for a
    dimensionless output; else the one unit ``given`` names for it (the units
    its input file writes values of its kind in), else the limit's unit for
    the limited output, else SI. The rule of a scene's sweep and of a
    component file's.

    Parameters
    ----------
    specs : tuple of OutputSpec
        The outputs.
    given : callable
        Output -> the set of unit texts the input file gives values of the
        output's kind in (asked only for an output with a unit).
    limit : Limit or None
        The ``--limit``, its unit as typed.
    """
    shown = {}
    for s in specs:
        if not shown_unit(s.unit):
            shown[s.name] = ("", 1.0)
            continue
        found = given(s)
        if len(found) == 1 and "" not in found:
            unit = next(iter(found))
            shown[s.name] = (unit, units.parse_unit(unit)[0])
        elif limit is not None and limit.output == s.name:
            shown[s.name] = (limit.unit, limit.to_si)
        else:
            shown[s.name] = (s.unit, 1.0)
    return shown


def plan(scene: Scene, vary: list[str], outputs: list[str], at: list[str] = (),
         limit: str | None = None) -> SweepPlan:
    """Check the sweep's arguments against the scene and its derivation.

    Parameters
    ----------
    scene : Scene
        The validated scene (the fixed values).
    vary : list of str
        ``--vary`` texts, one axis each.
    outputs : list of str
        ``--output`` names.
    at : list of str, optional
        ``--at`` texts.
    limit : str, optional
        The ``--limit`` text.

    Raises
    ------
    SweepError
        Naming the option and its text: an unknown or repeated parameter or
        output, an axis that is no argument of the outputs, an empty or
        reversed range, a log axis through zero, a unit of the wrong
        dimension, an argument no value is given for.
    """
    if not vary:
        raise SweepError("--vary: give at least one axis, e.g. --vary m1=1:100:200:log")
    if not outputs:
        raise SweepError("--output: give at least one output to sweep")
    d = registry.get(scene.derivation)
    specs = _output_specs(scene.derivation, list(outputs))
    simulated = registry.sweep_outputs(scene.derivation)
    extra = tuple(dict.fromkeys(n for s in specs if s.kind == "simulated"
                                for n in simulated[s.name].options))
    fixed = dict(scene.parameters)
    try:
        fixed.update({n: units.convert(n, scene.options[n], d.symbols[n].dimension)
                      for n in extra})
    except (KeyError, units.UnitError) as exc:
        raise SceneError(f"scene {scene.name!r}: [options] lacks or garbles {exc}") from None
    scene_units = _scene_units(scene, extra)
    axes = tuple(parse_vary(v, scene_units, d.symbols) for v in vary)
    names = [a.name for a in axes]
    if len(set(names)) != len(names):
        raise SweepError(f"--vary: a parameter is varied twice in {names}")
    for axis in axes:
        if not any(axis.name in s.depends for s in specs):
            raise SweepError(f"--vary {axis.name}: {_not_an_argument(axis.name, specs)}")
    window = None
    for text in at:
        found = parse_at(text, d.symbols)
        if found.name in names or found.name in scene.parameters or found.name in fixed:
            raise SweepError(f"--at {text!r}: {found.name!r} is already given by "
                             f"{'--vary' if found.name in names else 'the scene or --at'}")
        if found.n > 1:
            if window is not None:
                raise SweepError(f"--at {text!r}: one window at most")
            window = found
        fixed[found.name] = float(found.si()[0])
    for s in specs:
        missing = [a for a in s.args if a not in fixed and a not in names]
        if missing:
            hint = " (e.g. --at t=0.1 for a time response)" if "t" in missing else ""
            raise SweepError(f"--output {s.name}: no value for {', '.join(missing)}; "
                             f"give it with --at NAME=VALUE{hint}")
    found = parse_limit(limit, specs) if limit else None
    display = display_units(specs, partial(_scene_given, scene_units, d.symbols), found)
    if found is not None:
        found = found.shown_in(*display[found.output])
    options = {k: scene.options[k] for k in ("duration", "points") if k in scene.options}
    if window is not None:
        options["window"] = (window.name, tuple(float(v) for v in window.si()))
    return SweepPlan(scene.name, scene.derivation, axes, specs, fixed, found, display, options,
                     window)
