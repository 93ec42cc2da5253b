"""What the toolkit generates code from for paper 000: the Outputs (every
result in the paper's own symbols) and the ODE systems of (1)–(2) and (4).
"""
from __future__ import annotations

import sympy as sp

from crane_sym.derivation import Derivation, ODESystem, Output
from crane_sym.mechanics.elimination import RelativeEquation

from .model import P_t, W, c, m1, m2, p, t, u, v0, x1, x2


def outputs(d: Derivation, omega: sp.Expr) -> list[Output]:
    """Generated functions: every result in the paper's own symbols."""
    def rhs(label: str) -> sp.Expr:
        return d.step(label).statement.rhs.subs(p, omega)

    loads = (t, m1, m2, c, P_t, W)
    return [
        Output("natural_frequency", rhs("(6)"), (m1, m2, c), ("(6)",),
               "Natural frequency p of the relative motion.", "rad/s"),
        Output("relative_displacement", rhs("(13)"), loads, ("(13)",),
               "Stretch x2 - x1 of the elastic link.", "m"),
        Output("elastic_force", rhs("(14)"), loads, ("(14)",),
               "Force F(t) in the elastic link.", "N"),
        Output("peak_elastic_force", rhs("peak force"), (m1, m2, P_t, W), ("(14)",),
               "Extreme link force F_max = F(pi/p); a maximum when P_t*m2 > W*m1.",
               "N"),
        Output("peak_time", rhs("peak time"), (m1, m2, c), ("(6)", "(14)"),
               "Time t_max = pi/p of the extreme link force.", "s"),
        Output("rigid_link_force", rhs("rigid limit"), (m1, m2, P_t, W), ("(14)",),
               "Link force of a rigid drive (c -> oo), the static reference.", "N"),
        Output("velocity_m1", rhs("velocity of m1"), loads + (v0,), ("(1)", "(13)"),
               "Velocity of the motor-side mass m1.", "m/s"),
        Output("velocity_m2", rhs("velocity of m2"), loads + (v0,), ("(2)", "(13)"),
               "Velocity of the crane-side mass m2.", "m/s"),
    ]


def ode_systems(eq1: sp.Eq, eq2: sp.Eq, rel: RelativeEquation) -> list[ODESystem]:
    """The model as ODEs for the bench: absolute coordinates (1)–(2) and the
    relative coordinate (4), both starting unstretched with both masses at v0."""
    return [
        ODESystem("absolute coordinates, (1)-(2)", (eq1, eq2), (x1, x2),
                  ((x1, 0), (x2, 0), (x1.diff(t), v0), (x2.diff(t), v0)),
                  (("relative_displacement", x2 - x1), ("elastic_force", c * (x2 - x1)),
                   ("velocity_m1", x1.diff(t)), ("velocity_m2", x2.diff(t)))),
        ODESystem("relative coordinate, (4)", (rel.equation,), (u,),
                  ((u, 0), (u.diff(t), 0)),
                  (("relative_displacement", u), ("elastic_force", c * u))),
    ]
