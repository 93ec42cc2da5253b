"""Paper 002 as a user would integrate it, for ``crane-sym bench``.

For each generated dynamic coefficient K(t) of a load case (38)–(52) and of a
drive law (26)–(31), two ODE systems: the two-mass equations (1) in absolute
coordinates x1, x2, and the stretch equation (2) in x = x1 − x2. Their
right-hand sides are piecewise in t (a pulse ends, the drive law stops at t_п,
the pick-up ramp ends at τ_0): that is what a user would hand to a solver.

Each system takes the generated function's own arguments: the rope stiffness
is written C = Ω² m1 m2/(m1 + m2) and the pick-up time is the argument τ_0, so
the integrators and the closed form see the same model for any argument
values. The absolute coordinates also need m1, m2 and g (the load cases
normalise them away). ``attach(d)`` is called by ``hoist_startup.build()``.
"""
from __future__ import annotations

import sympy as sp

from crane_sym.derivation import Derivation, ODESystem

from . import hoist_startup as hs

#: Values the bench gives to arguments no paper-002 scene sets [SI].
#: θ = 0.3 s: the pulse (45)–(46) and the rise (51)–(52) last longer than half
#: a period π/Ω = 0.126 s at the scenes' Ω = 25 rad/s (the long-pulse case).
BENCH_PARAMETERS = {hs.theta: sp.Float(0.3)}

_t = hs.t
_stiffness = hs.Omega ** 2 * hs.m1 * hs.m2 / (hs.m1 + hs.m2)   # C from (2), Ω²
_weight = hs.m2 * hs.g


def attach(d: Derivation) -> None:
    """Add the ODE systems and the bench parameters of paper 002 to ``d``."""
    d.ode_systems.extend(ode_systems(d))
    d.bench_parameters.update(BENCH_PARAMETERS)


def _before(value: sp.Expr, end: sp.Expr, after: sp.Expr) -> sp.Piecewise:
    return sp.Piecewise((value, _t < end), (after, True))


def _load_cases() -> dict[str, tuple[sp.Expr, sp.Expr]]:
    """Reduced force P̄(t) of (32) and the force that makes K = C·x/force.

    P̄_0 = m2 g and k = m2 g/t_п (any values give the same K)."""
    p0, k = _weight, _weight / hs.t_n
    return {
        "dynamic_coefficient_instant": (p0, p0),                          # (35)–(38)
        "dynamic_coefficient_ramp": (k * _t, k * hs.t_n),                # (39)–(42)
        "dynamic_coefficient_pulse": (_before(p0, hs.theta, 0), p0),     # (43)–(46)
        "dynamic_coefficient_ramp_hold": (_before(p0 * _t / hs.theta, hs.theta, p0), p0),
    }


def _drive_laws() -> dict[str, tuple[sp.Expr, sp.Expr, sp.Expr, sp.Expr]]:
    """P(t), Q(t), x(0) and the reference force of (25) for each K^(1), K^(2).

    As in ``hoist_startup._drive_law_coefficients``: P = (m1 + m2)·a_i + m2 g
    while t < t_п, m2 g after (28), (31); Q ramps to m2 g over τ_0 with
    pick-up (28)–(29) and is m2 g from weight; the reference is the rigid
    rope force at t = 0."""
    laws = {}
    for i, law in hs.PRINTED_LAWS.items():
        drive = _before((hs.m1 + hs.m2) * law + _weight, hs.t_n, _weight)
        p0 = (hs.m1 + hs.m2) * law.subs(_t, 0) + _weight
        for name, resist, start, q0 in (
                ("pickup", _before(_weight * _t / hs.tau0, hs.tau0, _weight), 0, 0),
                ("from_weight", _weight, _weight / _stiffness, _weight)):
            reference = (hs.m2 * p0 + hs.m1 * q0) / (hs.m1 + hs.m2)
            laws[f"dynamic_coefficient_{name}_a{i}"] = (drive, resist, start, reference)
    return laws


def _pair(d: Derivation, name: str, drive: sp.Expr, resist: sp.Expr, start: sp.Expr,
          force: sp.Expr) -> list[ODESystem]:
    """(1) and (2) driven by P = ``drive``, Q = ``resist`` from x(0) = ``start``
    at rest; the quantity ``name`` is C·x/``force``."""
    fill = {hs.P: drive, hs.Q: resist, hs.C: _stiffness}
    absolute = tuple(d.step(label).statement.subs(fill) for label in ("(1)", "(1), load"))
    forcing = d.step("(2), S(t)").statement.rhs.subs(fill)
    relative = d.step("(2)").statement.subs(hs.S, forcing)
    x1, x2, x = hs.x1, hs.x2, hs.x
    rest = ((x1.diff(_t), 0), (x2.diff(_t), 0))
    return [
        ODESystem(f"absolute coordinates, (1): {name}", absolute, (x1, x2),
                  ((x1, start), (x2, 0)) + rest,
                  ((name, _stiffness * (x1 - x2) / force),)),
        ODESystem(f"relative coordinate, (2): {name}", (relative,), (x,),
                  ((x, start), (x.diff(_t), 0)), ((name, _stiffness * x / force),)),
    ]


def ode_systems(d: Derivation) -> list[ODESystem]:
    """Absolute and relative systems for every load case and drive law."""
    systems = []
    for name, (load, force) in _load_cases().items():
        # The load cases give only S = P̄/m; applied to the drive mass as
        # P = P̄·(m1 + m2)/m2 with Q = 0 it gives the same S in (2).
        drive = load * (hs.m1 + hs.m2) / hs.m2
        systems += _pair(d, name, drive, sp.Integer(0), sp.Integer(0), force)
    for name, (drive, resist, start, reference) in _drive_laws().items():
        systems += _pair(d, name, drive, resist, start, reference)
    return systems
