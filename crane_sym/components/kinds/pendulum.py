"""``[[pendulum]]``: a load hanging from a trolley on a rope of length L,
linearized about the vertical.

.. code-block:: text

    trolley x ──┬──▶           [[pendulum]]
                │ L            name = "sway"
                │              between = ["trolley", "hook"]   # from the suspension to the load
                ● hook y       length = "12 m"                 # L > 0
                               g = "9.81 m/s^2"                # default 9.81 m/s^2
                                                               # damping = "0 N*s/m": on y - x

With x the trolley's and y the load's horizontal position (both of one
positive direction), the load's kinetic energy stays m ẏ²/2 (T diagonal) and,
to second order in the sway angle θ = (y − x)/L, its height gives
Π = m g (y − x)²/(2L): a spring of stiffness m g/L between trolley and load
(m the load's mass), whose load is the rope's horizontal pull m g θ. So the
pendulum is an elastic link (its run, peaks, sweeps and walkthrough are a
link's), its stiffness in the equations m_<load> g_<name>/L_<name>, its
reference load the load's weight m g: its dynamic factor is the peak sway angle
in rad (``<name>.angle`` in a sweep). The first end may be ``"ground"`` (a
load swinging from a fixed point).
"""
from __future__ import annotations

from dataclasses import dataclass

import sympy as sp
from sympy.physics.units import force, length, time

from crane_sym.components.kinds.base import Key, Kind, Symbolic
from crane_sym.components.parts import (GROUND, TRANSLATING, Body, ComponentError, ElasticLink,
                                        Value, value)


@dataclass(frozen=True, init=False)
class Pendulum(ElasticLink):
    """A load ``second`` hanging at ``length`` below ``first`` (a trolley, or
    the ground) under gravity ``g``: an elastic link of stiffness m g/L."""

    length: float = 0.0
    g: float = 0.0
    kind = "pendulum"
    reports_angle = True

    def __init__(self, name: str, first: str, second: str, length_: str | float,
                 g: str | float = "9.81 m/s^2", damping: str | float = 0.0) -> None:
        super().__init__(name, first, second, 1.0, damping)
        owner = f"pendulum {name!r}"
        L = value(owner, "length", length_, length)
        acceleration = value(owner, "g", g, length / time**2)
        for what, v in (("length", L), ("g", acceleration)):
            if v.si <= 0:
                raise ComponentError(f"{owner}: {what} must be > 0, got {v.text!r}")
        if second == GROUND:
            raise ComponentError(f"{owner}: the load hangs at the second end of between; "
                                 "it cannot be the ground")
        object.__setattr__(self, "stiffness", None)
        object.__setattr__(self, "length", L.si)
        object.__setattr__(self, "g", acceleration.si)

    def assembled(self, bodies: dict[str, Body]) -> tuple[Value, Value]:
        """Stiffness m g/L and reference m g, m the mass of the load it holds."""
        load = bodies[self.second]
        if load.motion != TRANSLATING or load.inertia <= 0:
            raise ComponentError(f"{self.label}: its load {load.label} must be a mass > 0 "
                                 f"(the pendulum's pull is m g θ), got {load.inertia:g} "
                                 f"{'kg' if load.motion == TRANSLATING else 'kg*m^2'}")
        weight = load.inertia * self.g
        return (Value(weight / self.length, force / length, f"m g/L of {self.label}"),
                Value(weight, force, f"weight of {load.label}"))


def _stiffness(part: Pendulum) -> sp.Expr:
    """m g/L in the parts' symbols."""
    return (sp.Symbol(f"m_{part.second}", positive=True) * G.symbol(part.name)
            / L.symbol(part.name))


L = Symbolic("length", "L", "positive", lambda link: link.part.length,
             "length of the pendulum {name}")
G = Symbolic("g", "g", "positive", lambda link: link.part.g,
             "acceleration of gravity of the pendulum {name}")

KIND = Kind("pendulum", (Key("name", "word"), Key("between", "ends"),
                         Key("length", value=length, sign="positive"),
                         Key("g", value=length / time**2, sign="positive", required=False,
                             default="9.81 m/s^2"),
                         Key("damping", value="damping", sign="nonnegative", required=False,
                             default=0.0)),
            lambda g, entry, where: Pendulum(g["name"], *g["between"], g["length"], g["g"],
                                             g["damping"]),
            "a load swinging below a trolley, linearized about the vertical",
            symbols=(L, G, Symbolic("damping", "d", "nonnegative", lambda link: link.damping,
                                    "damping of the sway of the pendulum {name}")),
            stiffness=_stiffness)
