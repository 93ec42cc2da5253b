"""``[[span]]``: an elastic element with a mass of its own between two points,
each point a linear combination of bodies' coordinates, or the fixed frame.

::

    [[span]]
    name = "tight"                          # a rope branch
    start = { run = 1 }                     # point A: x_A = z (omitted or {}: the frame)
    end = { drum = "250 mm", hub = -1 }     # point B: x_B = r φ_drum − y_hub
    stiffness = "5e4 N/m"
    damping = "0 N*s/m"                     # optional
    mass = "1440 kg"                        # optional: the element's q L

Its stretch is a length, u = x_B − x_A, with Π = c u²/2 and Φ = d u̇²/2. Its own mass
m moves at a speed linear along it from v_A to v_B (Martyntsiv et al., (6)),
so

.. math:: T = \\int_0^L \\frac{q}{2} v(\\xi)^2 d\\xi
            = \\frac{m}{6}\\left(v_A^2 + v_A v_B + v_B^2\\right),

a quadratic form in several coordinates' speeds: the mass matrix is no
longer diagonal. A factor is the point's displacement per unit of the
body's coordinate (m/rad for a rotating body, a number for a translating
one); a bare integer enters the equations as that
integer, any other factor as its sign times a symbol ``a_<body>_<text>`` of
its magnitude (``a_drum_250_mm``: spans that write a radius alike share it),
the parameter ``<span>.<start|end>.<body>`` of a [[formula]]. A span with one point on the frame is a spring to the ground.

A span whose stiffness is written per radian (``"2e4 N*m/rad"``) twists: its
points are angles (a factor is rad per unit of the body's coordinate, a bare
number on a shaft), its damping is in N·m·s/rad, its ``mass`` is the moment of
inertia of its own shaft (kg·m², the angular speed linear along it: the same
T), and its load is a torque in N·m. Its force, ∂Π/∂u + ∂Φ/∂u̇, is derived
from these energies (:mod:`crane_sym.components.coupling_loads`).
"""
from __future__ import annotations

import re
from dataclasses import dataclass

import sympy as sp

from crane_sym.components.kinds.base import Coupling, Factor, Key, Kind, Symbolic
from crane_sym.components.parts import (DIMENSIONS, ROTATING, TRANSLATING, UNITS, Body,
                                        Component, ComponentError, Given, Value, _at_least,
                                        _name, value)
from crane_sym.units import same_dimension

__all__ = ["KIND", "Span"]

SIDES = ("start", "end")


@dataclass(frozen=True)
class Span(Component):
    """An elastic element between two points (see the module docstring):
    ``start`` and ``end`` are (body, factor) each, the factor a
    :class:`~crane_sym.components.parts.Value`; ``motion`` is ``rotating``
    where its stiffness is written per radian (its points angles)."""

    name: str
    start: tuple[tuple[str, Value], ...]
    end: tuple[tuple[str, Value], ...]
    stiffness: Value
    damping: Value
    mass: Value
    motion: str
    kind = "span"

    def __init__(self, name: str, start: dict[str, Given] | None, end: dict[str, Given] | None,
                 stiffness: Given, damping: Given = 0.0, mass: Given = 0.0) -> None:
        name = _name("span", name)
        owner = f"span {name!r}"
        sides = []
        for side, terms in zip(SIDES, (start or {}, end or {})):
            row = []
            for body, factor in dict(terms).items():
                f = value(owner, f"{side} factor of {body!r}", factor)
                if f.si == 0:
                    raise ComponentError(f"{owner}: {side} factor of {body!r} is 0; leave "
                                         "the body out")
                row.append((str(body), f))
            sides.append(tuple(row))
        if not sides[0] and not sides[1]:
            raise ComponentError(f"{owner}: both its start and its end are the frame; name a "
                                 "body in start or end")
        c, d, m = (value(owner, w, v) for w, v in (("stiffness", stiffness),
                                                  ("damping", damping), ("mass", mass)))
        _at_least(owner, "stiffness", c, 0.0, True)
        _at_least(owner, "damping", d, 0.0, False)
        _at_least(owner, "mass", m, 0.0, False)
        twists = c.dimension is not None and same_dimension(c.dimension,
                                                            DIMENSIONS["stiffness"][ROTATING])
        for key, v in (("name", name), ("start", sides[0]), ("end", sides[1]),
                       ("stiffness", c), ("damping", d), ("mass", m),
                       ("motion", ROTATING if twists else TRANSLATING)):
            object.__setattr__(self, key, v)


def _exact(f: Value) -> bool:
    """A bare integer factor (``-1``), which the equations hold as that integer."""
    return f.dimension is None and f.si == int(f.si) and "." not in f.text and \
        "e" not in f.text.lower()


def factor_symbol(body: str, f: Value) -> sp.Symbol:
    """The symbol of a factor that is not a bare integer: its magnitude, named
    after the body and the text, so that spans writing one radius alike share
    it (a drum's r in both branches: the drive's rigid motion stays exact)."""
    text = re.sub(r"[^A-Za-z0-9]+", "_", f.text.strip().lstrip("+-")).strip("_")
    return sp.Symbol(f"a_{body}_{text}", positive=True)


def _factor(body: str, f: Value) -> sp.Expr:
    if _exact(f):
        return sp.Integer(int(f.si))
    return (1 if f.si > 0 else -1) * factor_symbol(body, f)


def _bodies(span: Span) -> tuple[str, ...]:
    names = [b for side in (span.start, span.end) for b, _ in side]
    return tuple(dict.fromkeys(names))


def _check(span: Span, bodies: dict[str, Body]) -> None:
    """Its values' dimensions by its motion, and each factor's: a length (an
    angle) per unit of the body's coordinate."""
    for key, kind in (("stiffness", "stiffness"), ("damping", "damping"),
                      ("mass", "own inertia")):
        getattr(span, key).check(span.label, key, DIMENSIONS[kind][span.motion])
    own = DIMENSIONS["displacement"][span.motion]
    for side, terms in zip(SIDES, (span.start, span.end)):
        for body, f in terms:
            f.check(span.label, f"{side} factor of {body!r}",
                    own / DIMENSIONS["displacement"][bodies[body].motion])


def _points(span: Span, where: dict) -> tuple[sp.Expr, sp.Expr]:
    """(x_A, x_B) of the span, given each body's (κ, q(t))."""
    return tuple(sum((_factor(b, f) * where[b][0] * where[b][1] for b, f in terms),
                     sp.Integer(0)) for terms in (span.start, span.end))


def _energies(span: Span, where: dict) -> tuple[sp.Expr, sp.Expr, sp.Expr]:
    """(T, Π, Φ) of the span, given each body's (κ, q(t))."""
    (xa, xb), t = _points(span, where), next(iter(where.values()))[1].args[0]
    va, vb = xa.diff(t), xb.diff(t)
    c, d, m = (s.symbol(span.name) for s in SYMBOLS)
    u = xb - xa
    return (m * (va**2 + va * vb + vb**2) / 6, c * u**2 / 2, d * u.diff(t)**2 / 2)


def _stretch(span: Span, where: dict, bodies: dict[str, Body]) -> tuple[sp.Expr, str, str]:
    """Its stretch u = x_B − x_A, and what its load ∂Π/∂u + ∂Φ/∂u̇ is, with its
    unit: a force, or a torque where it twists."""
    xa, xb = _points(span, where)
    return xb - xa, "torque" if span.motion == ROTATING else "force", UNITS["load"][span.motion]


def _factors(span: Span, bodies: dict[str, Body]) -> tuple[Factor, ...]:
    """Its factors that are symbols, each a parameter ``<span>.<side>.<body>``."""
    own = DIMENSIONS["displacement"][span.motion]
    return tuple(Factor(f"{side}.{b}", factor_symbol(b, f), abs(f.si),
                        own / DIMENSIONS["displacement"][bodies[b].motion],
                        f"factor of {b} in the {side} point of the span {span.name}")
                 for side, terms in zip(SIDES, (span.start, span.end)) for b, f in terms
                 if not _exact(f))


SYMBOLS = (Symbolic("stiffness", "c", "positive", lambda span: span.stiffness.si,
                    "stiffness of the span {name}"),
           Symbolic("damping", "d", "nonnegative", lambda span: span.damping.si,
                    "damping of the span {name}"),
           Symbolic("mass", "m", "nonnegative", lambda span: span.mass.si,
                    "own mass of the span {name} (speed linear along it)"))

KIND = Kind("span", (Key("name", "word"), Key("stiffness", value="stiffness", sign="positive"),
                     Key("start", "terms", required=False, default=None),
                     Key("end", "terms", required=False, default=None),
                     Key("damping", value="damping", sign="nonnegative", required=False,
                         default=0.0),
                     Key("mass", value="own inertia", sign="nonnegative", required=False,
                         default=0.0)),
            lambda g, entry, where: Span(g["name"], g["start"], g["end"], g["stiffness"],
                                         g["damping"], g["mass"]),
            "an elastic element of its own mass between two points, each a linear "
            "combination of bodies' coordinates (or the frame)",
            symbols=SYMBOLS, couples=Coupling(_bodies, _check, _energies, _factors, _stretch))
