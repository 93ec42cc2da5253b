"""A component model's parameters by name (``<component>.<key>``, as the
component file writes it: ``gearbox_mesh.stiffness``, ``hook.mass``), each
with its symbol, SI value, dimension and unit, and the values that switch the
model rather than enter its equations: what a [[formula]] may name beside the
quantities of :mod:`crane_sym.components.quantities`.
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import sympy as sp
from sympy.physics.units import Dimension

from crane_sym.components import kinds
from crane_sym.components.kinds.base import FIXED_UNITS, Key
from crane_sym.components.model import Model
from crane_sym.components.parts import (DIMENSIONS, GROUND, ROTATING, TRANSLATING, UNITS,
                                        value)

__all__ = ["Parameter", "motion_of", "parameters", "signed", "switching_values"]


@dataclass(frozen=True)
class Parameter:
    """One parameter of the model: its symbol, value (SI), dimension and what it is."""

    path: str
    symbol: sp.Symbol
    value: float
    dimension: Dimension
    unit: str
    description: str


def signed(model: Model) -> dict[sp.Symbol, sp.Symbol]:
    """Each parameter symbol whose value the file gives negative -> its twin of the
    same name declared negative: what every quantity and formula uses instead.

    Parameters
    ----------
    model : Model
        The assembled and derived model.
    """
    return {s: sp.Symbol(s.name, negative=True) for s, v in model.equations.values.items()
            if v < 0}


def parameters(model: Model, start: tuple[str | None, Any] | None = None
               ) -> dict[str, Parameter]:
    """Every parameter of ``model`` that its equations hold, by ``<component>.<key>``,
    then its switching values (:func:`switching_values`) and, given the run's
    ``start``, the run's speed as ``run.speed``.

    Parameters
    ----------
    model : Model
        The assembled and derived model.
    start : (body, speed), optional
        The [run] table's ``body`` (None: the first) and ``speed``.
    """
    a, eq = model.assembly, model.equations
    symbols = {s.name: s for s in eq.values} | {s.name: s for s in eq.motor_loads}
    twins = signed(model)
    out: dict[str, Parameter] = {}

    def add(path: str, name: str, dimension: Dimension, unit: str, what: str) -> None:
        s = symbols.get(name)
        if s is not None:
            out[path] = Parameter(path, twins.get(s, s), float(eq.values.get(s, float("nan"))),
                                  dimension, unit, what)
    for item in (*a.bodies.values(), *a.rigid, *a.links, *a.loads, *a.couplings):
        part = getattr(item, "part", item)
        kind = kinds.of(part)
        for declared in kind.symbols:
            dimension, unit, key = _dimension(a, kind.key(declared.key), part)
            what = declared.what.format(name=part.name, body=getattr(part, "body", ""), key=key)
            add(f"{part.name}.{key}", declared.symbol(part.name).name, dimension, unit,
                what + (" (steady: solved at the start)" if declared.value(item) is None else ""))
        for factor in (kind.couples.factors(part, a.bodies) if kind.couples else ()):
            add(f"{part.name}.{factor.key}", factor.symbol.name, factor.dimension,
                FIXED_UNITS[factor.dimension], factor.what)
    return out | switching_values(model) | (_run_speed(model, *start) if start else {})


def _dimension(a, key: Key, part) -> tuple[Dimension, str, str]:
    """The dimension and SI unit of a part's ``key`` and the key's name on its
    body: a kind of value by the body's motion (``torque`` is ``force`` on a
    translating body), or the fixed dimension the key declares."""
    if not isinstance(key.value, str):
        return key.value, FIXED_UNITS[key.value], key.name
    motion = motion_of(a, part)
    name = "force" if key.name == "torque" and motion != ROTATING else key.name
    return DIMENSIONS[key.value][motion], UNITS[key.value][motion], name


def motion_of(a, part) -> str:
    """The motion of the body a part is, acts on, or (a link) starts at; a
    span's stretch is a length, or an angle (its ``motion``)."""
    if kinds.of(part).couples is not None:
        return getattr(part, "motion", TRANSLATING)
    body = part.name if part.name in a.bodies else getattr(part, "body", None) or next(
        e for e in part.ends if e != GROUND)
    return a.bodies[body].motion


def _run_speed(model: Model, body: str | None, speed: Any) -> dict[str, Parameter]:
    a = model.assembly
    body = body or next(iter(a.bodies))
    if body not in a.bodies:                # the run itself names it (Model.start)
        return {}
    motion = a.bodies[body].motion
    v = value("run", "speed", speed, DIMENSIONS["speed"][motion]).si
    symbol = sp.Symbol("value_run_speed", **({"nonnegative": True} if v >= 0 else
                                             {"real": True}))
    return {"run.speed": Parameter("run.speed", symbol, v, DIMENSIONS["speed"][motion],
                                   UNITS["speed"][motion], f"the run's speed of {body}")}


def switching_values(model: Model) -> dict[str, Parameter]:
    """The values that switch the model rather than enter its equations (a
    link's backlash, a brake's torque and delay, a motor law's breakpoints and
    values), each under a symbol of its own, so that a [[formula]] of a shock
    load or a lift-off can name them (none of them is in a derived quantity).

    Parameters
    ----------
    model : Model
        The assembled and derived model.
    """
    a, out = model.assembly, {}

    def add(path: str, value: float, dimension: Dimension, unit: str, what: str) -> None:
        symbol = sp.Symbol("value_" + path.replace(".", "_"), nonnegative=True)
        out[path] = Parameter(path, symbol, float(value), dimension, unit, what)
    for item in (*a.links, *a.loads):
        switching = kinds.of(item.part).switching
        if switching is None:
            continue
        for key, v, dimension, unit, what in switching(item.part, motion_of(a, item.part)):
            add(f"{item.part.name}.{key}", v, dimension, unit, what)
    return out
