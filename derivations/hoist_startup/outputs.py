"""Paper 002's outputs: the generated functions, the ODE systems and the bench
parameters of ``crane-sym bench``.

``code_outputs(d, loads)`` lists the functions ``crane-sym generate`` writes
(natural frequency, contact time, the dynamic coefficient of each load case
(38)–(53) and of each drive law a_i of (30) in both lifting cases, the
coefficients k̃ of (65)–(66)).

For each generated dynamic coefficient K(t) of a load case (38)–(52) and of a
drive law (26)–(31), two ODE systems: the two-mass equations (1) in absolute
coordinates x1, x2, and the stretch equation (2) in x = x1 − x2. Their
right-hand sides are piecewise in t (a pulse ends, the drive law stops at t_п,
the pick-up ramp ends at τ_0): that is what a user would hand to a solver.

Each system takes the generated function's own arguments: the rope stiffness
is written C = Ω² m1 m2/(m1 + m2) and the pick-up time is the argument τ_0, so
the integrators and the closed form see the same model for any argument
values. The absolute coordinates also need m1, m2 and g (the load cases
normalise them away). ``attach(d)`` is called by ``build()``.
"""
from __future__ import annotations

import sympy as sp

from crane_sym.derivation import Derivation, ODESystem, Output
from crane_sym.mechanics.duhamel import duhamel
from crane_sym.mechanics.loads import PiecewiseLoad, ramp, step

from . import model as hs
from .model import PRINTED_LAWS, C, Omega, g, m1, m2, t, t_n, tau0, theta, v0
from .steps import rhs


# --- Generated functions ---------------------------------------------------------
def windowed(expr: sp.Expr) -> sp.Expr:
    """Every ``Piecewise`` in time, ``(e0, t < b1), (e1, t < b2), ..., (en, True)``,
    written as ``Σ e_k·[H(t − b_k) − H(t − b_{k+1})]`` with H(0) = 0.

    ``codegen.module.hoist`` cannot yet take a Piecewise apart; windows keep each
    superposed part on its own breakpoints, so no order of τ_0 and t_п is
    assumed.
    """
    def window(pw: sp.Piecewise) -> sp.Expr:
        total, start = sp.Integer(0), None
        for e, cond in pw.args:
            if cond == sp.true:
                end = None
            elif isinstance(cond, (sp.StrictLessThan, sp.LessThan)) and cond.lhs == t:
                end = cond.rhs
            else:
                raise ValueError(f"cannot window the condition {cond}")
            low = 1 if start is None else sp.Heaviside(t - start, 0)
            high = 0 if end is None else sp.Heaviside(t - end, 0)
            total += e * (low - high)
            start = end
        return total
    return expr.replace(lambda e: isinstance(e, sp.Piecewise) and e.has(t), window)


def _polynomial_response(shape: sp.Expr, until: sp.Expr, basis: dict) -> sp.Expr:
    """Duhamel response (x_* of (17)) to ``shape`` on [0, until), 0 after, from the
    responses to t^j on [0, until) (superposition, as the paper advises)."""
    poly = sp.Poly(sp.expand(shape), t)
    total = sp.Integer(0)
    for (j,), c in zip(poly.monoms(), poly.coeffs()):
        if j not in basis:
            basis[j] = duhamel(PiecewiseLoad((0, until), (t ** j, 0), t), Omega, t,
                               simplify=False).piecewise()
        total += c * basis[j]
    return total


def _drive_law_coefficients() -> dict[tuple[int, int], sp.Expr]:
    """K^(1)(t), K^(2)(t) of (26)–(27) for each law a_i, by Duhamel's integral.

    S = P/m1 + Q/m2 with (28) or (31); after t_п the drive runs steadily (a = 0).
    By superposition: the a_i part (switched off at t_п), the weight part of P
    (a step) and Q (a ramp to τ_0 or a step), each with its own breakpoints."""
    basis: dict = {}
    weight_step = duhamel(step(sp.Integer(1), t=t), Omega, t).piecewise()
    pickup = duhamel(ramp(sp.Integer(1), tau0, t=t), Omega, t, simplify=False).piecewise()
    result = {}
    for i in range(1, 5):
        law = _polynomial_response(PRINTED_LAWS[i], t_n, basis)
        drive = (m1 + m2) / m1 * law + m2 * g / m1 * weight_step
        for case, (q_part, q0) in {1: (m2 * g / m2 * pickup, 0),
                                   2: (m2 * g / m2 * weight_step, m2 * g)}.items():
            x_star = drive + q_part
            p0 = (m1 + m2) * PRINTED_LAWS[i].subs(t, 0) + m2 * g
            reference = (m2 * p0 + m1 * q0) / (m1 + m2)
            result[(case, i)] = (C * x_star + q0 * sp.cos(Omega * t)) / reference
    return result


def code_outputs(d: Derivation, loads: dict) -> list[Output]:
    """Generated functions, with the paper's symbols as arguments."""
    omega = sp.sqrt(rhs(d, "(2), Ω²"))
    contact = rhs(d, "(29)")
    outs = [
        Output("natural_frequency", omega, (m1, m2, C), ("(2)",),
               "Natural circular frequency Omega of the rope stretch.", "rad/s"),
        Output("pickup_contact_time", contact, (m2, g, C, v0), ("(29)",),
               "Duration tau_0 of the load's contact with the ground (pick-up).", "s"),
        Output("dynamic_coefficient_instant", loads["instant"], (t, Omega), ("(38)",),
               "K_din(t) under a suddenly applied constant load.", "1"),
        Output("dynamic_coefficient_ramp", loads["ramp"], (t, Omega, t_n), ("(42)",),
               "K_din(t) under a linearly growing load, over the static deflection "
               "at t_n.", "1"),
        Output("dynamic_coefficient_pulse", windowed(loads["pulse"]), (t, Omega, theta),
               ("(45)", "(46)"), "K_din(t) under a rectangular pulse of length theta.",
               "1"),
        Output("pulse_peak_factor", loads["pulse_peak"], (Omega, theta), ("(47)",),
               "Largest x/x_st under a rectangular pulse of length theta.", "1"),
        Output("pulse_peak_time", loads["pulse_peak_time"], (Omega, theta), ("(47)",),
               "Time of the largest displacement under the pulse.", "s"),
        Output("dynamic_coefficient_ramp_hold", windowed(loads["ramp_hold"]), (t, Omega, theta),
               ("(51)", "(52)"), "K_din(t) under a load rising over theta, then held.",
               "1"),
        Output("ramp_hold_peak_factor", loads["ramp_hold_peak"], (Omega, theta),
               ("(53)",), "Largest x/x_st under the rise-then-hold load.", "1"),
    ]
    # Ω and τ_0 are arguments (from natural_frequency and pickup_contact_time):
    # with C = m Ω² the expressions stay a quarter of their size in m1, m2, C.
    stiff = Omega ** 2 * m1 * m2 / (m1 + m2)
    for (case, i), expr in sorted(_drive_law_coefficients().items()):
        name, label = ("pickup", "(26)") if case == 1 else ("from_weight", "(27)")
        args = ((t, Omega, tau0) if case == 1 else (t, Omega)) + (m1, m2, g, v0, t_n)
        how = ("lifting with pick-up (tau_0 from pickup_contact_time)" if case == 1
               else "lifting from weight")
        outs.append(Output(f"dynamic_coefficient_{name}_a{i}",
                           windowed(expr.subs(C, stiff)), args, (label, "(28)", "(30)"),
                           f"K_din^({case})(t) for the drive law a_{i} of (30), {how}; "
                           "Omega from natural_frequency.", "1"))
    for i in range(1, 5):
        outs.append(Output(f"optimal_coefficient_from_weight_a{i}",
                           rhs(d, f"(65), i = {i}"), (t, t_n),
                           ("(63)", "(65)"),
                           f"k~_din{i}^(opt)(t) from weight, 0 <= t <= t_n.", "1"))
        early = rhs(d, f"(66), i = {i}")
        late = rhs(d, f"(65), i = {i}")
        outs.append(Output(f"optimal_coefficient_pickup_a{i}",
                           windowed(sp.Piecewise((early, t <= tau0), (late, True))),
                           (t, t_n, v0, g, tau0), ("(64)", "(65)", "(66)"),
                           f"k~_din{i}^(opt)(t) with pick-up, 0 <= t <= t_n.", "1"))
    return outs


# --- ODE systems: paper 002 as a user would integrate it, for `crane-sym bench` ----
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

    As in ``_drive_law_coefficients``: P = (m1 + m2)·a_i + m2 g
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
