"""What a design sweep is asked to do: axes, outputs, a limit, all checked.

``crane-sym sweep SCENE --vary NAME=START:STOP:N[:log] [UNIT] ... --output NAME
[--at NAME=VALUE [UNIT]] [--limit "NAME<=VALUE UNIT"]`` is read here into a
:class:`SweepPlan`: the scene gives every fixed value (SI, from
:func:`crane_sym.scenes.load_scene`); each ``--vary`` turns one of its
parameters into a grid axis whose values are in the unit the scene file gives
that parameter (``m1`` in t for ``"4.4 t"``), unless the argument names
another unit of the same dimension. Every argument is matched by a strict
regular expression and its units by :mod:`crane_sym.units`; nothing the user
types is evaluated. Each error is a :class:`SweepError` whose message starts
with the option and the text that broke it.

Outputs are the derivation's generated closed forms (``kind = "closed"``)
or the simulated responses a paper declares in ``SWEEP_OUTPUTS``
(``kind = "simulated"``, :class:`crane_sym.derivation.SweepOutput`).
"""
from __future__ import annotations

import math
import re
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from . import registry, units
from .scenes import Scene, SceneError, read_toml
from .symbols import TIME

__all__ = ["Axis", "Limit", "OutputSpec", "SweepError", "SweepPlan", "parse_at",
           "parse_limit", "parse_vary", "plan"]

_NUM = r"[+-]?(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?"
_NAME = r"[A-Za-z_][A-Za-z0-9_]{0,63}"
_VARY = re.compile(rf"({_NAME})=({_NUM}):({_NUM}):(\d{{1,12}})(:log)?(?:\s+(\S.{{0,60}}))?")
_LIMIT = re.compile(rf"\s*({_NAME})\s*(<=|>=)\s*({_NUM})\s*(\S.{{0,60}})?")
_AT = re.compile(rf"({_NAME})=({_NUM})(?::({_NUM}):(\d{{1,7}}))?(?:\s*([A-Za-zµμ].{{0,60}}))?")


class SweepError(ValueError):
    """A sweep argument that cannot be honoured; the message names it."""


@dataclass(frozen=True)
class Axis:
    """One swept parameter: ``n`` values from ``start`` to ``stop`` (both
    included) in ``unit``, evenly or (``log``) geometrically spaced; ``to_si``
    is the factor from ``unit`` to SI, applied once to the whole axis."""

    name: str
    start: float
    stop: float
    n: int
    log: bool
    unit: str
    to_si: float

    def values(self) -> np.ndarray:
        """The axis in the user's unit, endpoints exact."""
        make = np.geomspace if self.log else np.linspace
        out = make(self.start, self.stop, self.n)
        out[0], out[-1] = self.start, self.stop
        return out

    def si(self) -> np.ndarray:
        """The axis in SI."""
        return self.values() * self.to_si


@dataclass(frozen=True)
class Limit:
    """``output <= value`` (or ``>=``), ``value`` in ``unit``."""

    output: str
    op: str
    value: float
    unit: str
    to_si: float

    @property
    def si(self) -> float:
        """The bound in SI."""
        return self.value * self.to_si

    def text(self) -> str:
        """As the user wrote it, normalised: ``peak_elastic_force <= 40 kN``."""
        return f"{self.output} {self.op} {self.value:g} {self.unit}".rstrip()


@dataclass(frozen=True)
class OutputSpec:
    """An output to sweep: its generated function (``closed``) or the paper's
    simulated response (``simulated``), arguments in order, SI unit."""

    name: str
    kind: str
    args: tuple[str, ...]
    unit: str
    summary: str = ""


@dataclass(frozen=True)
class SweepPlan:
    """Everything a sweep needs, checked: the fixed SI values of every other
    argument (``fixed``), the axes in grid order, the outputs, the limit."""

    scene: str
    derivation: str
    axes: tuple[Axis, ...]
    outputs: tuple[OutputSpec, ...]
    fixed: dict[str, float]
    limit: Limit | None = None
    display: dict[str, tuple[str, float]] = field(default_factory=dict)
    options: dict[str, Any] = field(default_factory=dict)

    @property
    def window(self) -> tuple[str, tuple[float, ...]] | None:
        """``(name, SI samples)`` of an ``--at`` window, or None."""
        return self.options.get("window")

    @property
    def shape(self) -> tuple[int, ...]:
        """Points per axis."""
        return tuple(a.n for a in self.axes)

    @property
    def points(self) -> int:
        """Designs in the grid."""
        return math.prod(self.shape)

    def unit_of(self, output: str) -> tuple[str, float]:
        """The unit an output is reported in and its factor to SI: the limit's
        unit for the limited output, else the output's own SI unit."""
        return self.display.get(output, (self.output(output).unit, 1.0))

    def output(self, name: str) -> OutputSpec:
        """The output spec called ``name``."""
        return next(o for o in self.outputs if o.name == name)


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
    if (entry.sign == "positive" and not low > 0) or (entry.sign == "nonnegative"
                                                      and not low >= 0):
        raise SweepError(f"--vary {text!r}: {name} must be "
                         f"{'> 0' if entry.sign == 'positive' else '>= 0'}")
    return Axis(name, start_f, stop_f, count, bool(log), unit, factor)


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
    return Limit(name, op, float(value), unit, _unit("--limit", text, unit, dimension))


def parse_at(text: str, symbols) -> tuple[str, np.ndarray]:
    """``--at NAME=VALUE [UNIT]``: a value (SI) for an argument the scene does
    not fix, such as the time ``t`` of a time response (unit s by default);
    ``--at NAME=START:STOP:N [UNIT]``: N samples of a window over which the
    sweep takes the output's maximum. Returns the name and the SI values."""
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
    default = "s" if entry.role == TIME else entry.unit
    factor = _unit("--at", text, (unit or default).strip(), entry.dimension)
    if stop is None:
        return name, np.array([float(value) * factor])
    if int(n) < 2 or not float(value) < float(stop):
        raise SweepError(f"--at {text!r}: the window is empty or reversed (need START < STOP "
                         "and N >= 2)")
    return name, np.linspace(float(value), float(stop), int(n)) * factor


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
                                    o.summary))
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


def plan(scene: Scene, vary: list[str], outputs: list[str], at: list[str] = (),
         limit: str | None = None) -> SweepPlan:
    """Check the sweep's arguments against the scene and its derivation.

    Raises
    ------
    SweepError
        Naming the option and its text: an unknown or repeated parameter or
        output, an empty or reversed range, a log axis through zero, a unit of
        the wrong dimension, an argument no value is given for.
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
    axes = tuple(parse_vary(v, _scene_units(scene, extra), d.symbols) for v in vary)
    names = [a.name for a in axes]
    if len(set(names)) != len(names):
        raise SweepError(f"--vary: a parameter is varied twice in {names}")
    for axis in axes:
        if not any(axis.name in s.args for s in specs):
            raise SweepError(f"--vary {axis.name}: none of the outputs "
                             f"({', '.join(s.name for s in specs)}) depends on it")
    window = None
    for text in at:
        name, value = parse_at(text, d.symbols)
        if name in names or name in scene.parameters or name in fixed:
            raise SweepError(f"--at {text!r}: {name!r} is already given by "
                             f"{'--vary' if name in names else 'the scene or --at'}")
        if len(value) > 1:
            if window is not None:
                raise SweepError(f"--at {text!r}: one window at most")
            window = (name, tuple(float(v) for v in value))
        fixed[name] = float(value[0])
    for s in specs:
        missing = [a for a in s.args if a not in fixed and a not in names]
        if missing:
            hint = " (e.g. --at t=0.1 for a time response)" if "t" in missing else ""
            raise SweepError(f"--output {s.name}: no value for {', '.join(missing)}; "
                             f"give it with --at NAME=VALUE{hint}")
    found = parse_limit(limit, specs) if limit else None
    display = {found.output: (found.unit, found.to_si)} if found else {}
    options = {k: scene.options[k] for k in ("duration", "points") if k in scene.options}
    if window is not None:
        options["window"] = window
    return SweepPlan(scene.name, scene.derivation, axes, specs, fixed, found, display, options)
