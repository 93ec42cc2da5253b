"""Steps (1)–(31) of paper 002: equations of motion, initial conditions,
Duhamel's integral, dynamic coefficients and drive laws.

Each function adds one section of the paper to a ``Derivation``, in the
paper's order; ``build()`` in ``__init__`` calls them. The load cases
(32)–(53) are in ``steps_load_cases``, the optimum (54)–(66) in
``steps_optimum``.
"""
from __future__ import annotations

import sympy as sp

from crane_sym.derivation import Derivation
from crane_sym.mechanics.duhamel import impulse_response
from crane_sym.mechanics.exp_trig_integrals import definite_integral
from crane_sym.mechanics.elimination import relative_coordinate
from crane_sym.mechanics.lagrange import lagrange_equations
from crane_sym.mechanics.odes import solve_constant_coefficient

from .model import (A_LAW, C1, C2, LAW_SHAPES, PRINTED_LAWS, C, F_r, K, K1, K2, Omega, P,
                    P_at0, P_d, Q, Q_0, Q_at0, S, S_at0, S_f, T, Y, a, a_at0, convolution,
                    g, m1, m2, t, t_n, tau0, v0, v_end, vt, x, x0, x0_dot, x1, x2, x_s,
                    x_s0, x_s0_dot)


def rhs(d: Derivation, label: str) -> sp.Expr:
    """Right-hand side of the step ``label`` of ``d``.

    Parameters
    ----------
    d : Derivation
    label : str
        A step label such as ``"(17)"``.

    Returns
    -------
    sympy.Expr
    """
    return d.step(label).statement.rhs


def equations_of_motion(d: Derivation):
    """(1)–(6): Lagrange's equations, the stretch equation, general solution."""
    T_, V_, dA = sp.Symbol("T_kin"), sp.Symbol("Pi"), sp.Symbol(r"\delta A")
    energy = m1 * x1.diff(t) ** 2 / 2 + m2 * x2.diff(t) ** 2 / 2
    strain = C * (x1 - x2) ** 2 / 2
    forces = {x1: P, x2: -Q}
    d.add("kinetic energy", sp.Eq(T_, energy), "Sum of ½·m·v² of drive and load.",
          "Lagrange's equations need the energies of the model.", "Energies and forces")
    d.add("potential energy", sp.Eq(V_, strain), "Strain energy ½·C·x² of the rope.")
    d.add("virtual work", sp.Eq(dA, P * sp.Symbol(r"\delta x_{1}")
                                - Q * sp.Symbol(r"\delta x_{2}")),
          "P(t) drives m1 up, Q(t) holds m2 down.",
          "The generalized forces are the coefficients of the virtual displacements.")
    eq1, eq2 = lagrange_equations(energy, strain, [x1, x2], t, forces).equations
    d.add("(1)", eq1, "Lagrange's equation for x1 with Q1 = P(t).",
          title="Equations of motion")
    d.add("(1), load", eq2, "Lagrange's equation for x2 with Q2 = −Q(t).")

    rel = relative_coordinate(eq2, eq1, x2, x1, x)
    d.add("(2)", sp.Eq(x.diff(t, 2) + Omega ** 2 * x, S),
          "Each equation solved for its acceleration and the load's subtracted from "
          "the drive's, in x = x1 − x2; the coefficients are named Ω² and S(t).",
          "The rope force depends on the stretch only, so one coordinate suffices.",
          "One equation for the stretch")
    d.add("(2), Ω²", sp.Eq(Omega ** 2, rel.omega2), "The coefficient of x.")
    d.add("(2), S(t)", sp.Eq(S, sp.factor(rel.forcing)), "The right-hand side.")
    d.add("(3)", sp.Eq(P_d, C * x), "The rope force ∂Π/∂x1 = C·(x1 − x2) in x.")
    d.add("(3), in x1 and x2", sp.Eq(P_d, sp.diff(strain, x1)),
          "The rope force is the derivative of the strain energy.")

    hom = solve_constant_coefficient(sp.Eq(x.diff(t, 2) + Omega ** 2 * x, 0), x, (C1, C2))
    general = x_s + C1 * hom.basis[0] + C2 * hom.basis[1]
    d.add("(4)", sp.Eq(x, general),
          "A particular solution x_* plus the solution of the homogeneous (2) for "
          "the roots ±iΩ.", title="General solution")
    d.add("(5)", sp.Eq(P_d, C * general), "(4) put into (3).")
    d.add("(6)", sp.Eq(T, sp.periodicity(hom.basis[0], t)),
          "The period of cos Ωt, the free part of (4).")
    return eq1, eq2


def _at_start(expr: sp.Expr) -> sp.Expr:
    """``expr`` at t = 0 with x_*(0), ẋ_*(0) named x̃_*, dx̃_* as in (8)."""
    return expr.subs(t, 0).xreplace({x_s.subs(t, 0): x_s0,
                                     x_s.diff(t).subs(t, 0): x_s0_dot})


def _constants(d: Derivation, start: sp.Expr, rate: sp.Expr) -> tuple[sp.Expr, sp.Expr]:
    """C1, C2 of (4) for x(0) = start, ẋ(0) = rate."""
    general = rhs(d, "(4)")
    (sol,) = sp.solve([_at_start(general) - start, _at_start(general.diff(t)) - rate],
                      [C1, C2], dict=True)
    return sol[C1], sol[C2]


def initial_conditions(d: Derivation, eq2: sp.Eq) -> None:
    """(7)–(14): constants for lifting with pick-up and from weight."""
    general = rhs(d, "(4)")
    d.add("(7)", sp.Eq(x0, 0),
          "With pick-up the rope is slack before the start: P_дин(0) = C·x(0) = 0.",
          "The two lifting methods start from different states of the rope.",
          "Case 1: lifting with pick-up")
    d.add("(7), velocity", sp.Eq(x0_dot, 0), "Drive and load are at rest.")
    c1, c2 = _constants(d, 0, 0)
    d.add("(8)", sp.Eq(C1, c1), "x(0) = 0 put into (4), with x̃_* = x_*(0).")
    d.add("(8), C2", sp.Eq(C2, c2), "ẋ(0) = 0 put into (4) differentiated.")
    case1 = general.subs({C1: c1, C2: c2})
    d.add("(9)", sp.Eq(x, case1), "(8) put into (4).")
    d.add("(10)", sp.Eq(P_d, sp.expand(C * case1)), "(9) put into (3).")

    rest = eq2.subs(x2.diff(t, 2), 0).subs({x1: x2 + x0, Q: Q_at0})
    (stretch0,) = sp.solve(rest, x0)
    d.add("(11)", sp.Eq(x0, stretch0),
          "Load hanging at rest before the start: (1) for m2 with ẍ2 = 0 gives "
          "C·x(0) = Q(0).", title="Case 2: lifting from weight")
    d.add("(11), velocity", sp.Eq(x0_dot, 0), "Drive and load are at rest.")
    c1, c2 = _constants(d, stretch0, 0)
    d.add("(12)", sp.Eq(C1, c1), "x(0) = Q(0)/C put into (4).")
    d.add("(12), C2", sp.Eq(C2, c2), "ẋ(0) = 0 put into (4) differentiated.")
    case2 = general.subs({C1: c1, C2: c2})
    d.add("(13)", sp.Eq(x, case2), "(12) put into (4).")
    d.add("(14)", sp.Eq(P_d, sp.expand(C * case2)), "(13) put into (3).")


def pull_constants(expr: sp.Expr) -> sp.Expr:
    """Move factors free of the integration variable out of each Integral."""
    def pull(integral: sp.Integral) -> sp.Expr:
        (var, lo, hi), = integral.limits
        total = sp.Integer(0)
        for term in sp.Add.make_args(sp.expand(integral.function, deep=False)):
            outside, inside = term.as_independent(var, as_Add=False)
            total += outside * sp.Integral(inside, (var, lo, hi))
        return total
    return expr.replace(lambda e: isinstance(e, sp.Integral), pull)


def duhamel_integral(d: Derivation) -> None:
    """(15)–(24): the particular solution as a Duhamel integral."""
    h = impulse_response(Omega, t)
    particular = convolution(S_f(vt) * h.subs(t, t - vt))
    residual = particular.diff(t, 2) + Omega ** 2 * particular - S
    if sp.simplify(pull_constants(residual)) != 0:
        raise RuntimeError(f"(15) does not solve (2): residual {residual}")
    if particular.subs(t, 0).doit() != 0 or particular.diff(t).subs(t, 0).doit() != 0:
        raise RuntimeError("(15) does not start from rest")
    d.add("(15)", sp.Eq(x_s, particular),
          "Convolution of S with the unit-impulse response; differentiated under the "
          "integral sign (Leibniz) it satisfies (2) and starts from rest.",
          "A particular solution valid for any load S(t).", "Duhamel's integral")
    d.add("(16)", sp.Eq(Y, h),
          "Free motion of (2) from x(0) = 0, ẋ(0) = 1: the velocity a unit impulse of S "
          "gives.")
    xs_expr = pull_constants(particular)
    d.add("(17)", sp.Eq(x_s, xs_expr), "(16) put into (15), 1/Ω taken out.")
    xs_dot = pull_constants(xs_expr.diff(t))
    d.add("(18)", sp.Eq(x_s.diff(t), xs_dot),
          "(17) differentiated by Leibniz's rule; the boundary term S(t)·sin 0 vanishes.")
    d.add("(19)", sp.Eq(x_s.diff(t, 2), pull_constants(xs_dot.diff(t))),
          "(18) differentiated; the boundary term is S(t)·cos 0.")
    d.add("(19), via (2)", sp.Eq(x_s.diff(t, 2), S - Omega ** 2 * x_s),
          "(2) solved for the acceleration of the particular solution.")
    d.add("(20)", sp.Eq(x_s0, xs_expr.subs(t, 0).doit()),
          "(17) at t = 0: the integral over [0, 0] vanishes.")
    d.add("(20), velocity", sp.Eq(x_s0_dot, xs_dot.subs(t, 0).doit()), "(18) at t = 0.")
    zero = {x_s0: 0, x_s0_dot: 0}
    case1 = rhs(d, "(9)").subs(zero).subs(x_s, xs_expr)
    case2 = rhs(d, "(13)").subs(zero).subs(x_s, xs_expr)
    d.add("(21)", sp.Eq(x, case1), "(20) and (17) put into (9).",
          title="Both lifting cases")
    d.add("(22)", sp.Eq(P_d, C * case1), "(21) put into (3).")
    d.add("(23)", sp.Eq(x, case2), "(20) and (17) put into (13).")
    d.add("(24)", sp.Eq(P_d, sp.expand(C * case2)), "(23) put into (3).")


def _rigid_rope_force(eq1: sp.Eq, eq2: sp.Eq) -> sp.Expr:
    """Rope force when x1 = x2: add the equations for the common acceleration,
    then read C·(x1 − x2) off the load's equation."""
    acc, link = sp.symbols("acc link")
    total = (eq1.lhs + eq2.lhs - eq1.rhs - eq2.rhs).subs(
        {x1.diff(t, 2): acc, x2.diff(t, 2): acc}).subs(x2, x1)
    (common,) = sp.solve(total, acc)
    on_load = eq2.subs(x1, x2 + link / C).doit().subs(x2.diff(t, 2), common)
    return sp.factor(sp.solve(on_load, link)[0])


def dynamic_coefficients(d: Derivation, eq1: sp.Eq, eq2: sp.Eq) -> None:
    """(25)–(27): the rope force over the rigid hoist's force at t = 0."""
    rigid = _rigid_rope_force(eq1, eq2)
    d.add("rigid rope force", sp.Eq(F_r, rigid),
          "x1 = x2 in (1): (m1 + m2)·a = P − Q, and the load's equation gives the "
          "rope force.", "The reference of the dynamic coefficient (25).",
          "Dynamic coefficients")
    at0 = rigid.subs({P: P_at0, Q: Q_at0})
    d.add("(25)", sp.Eq(K, P_d / at0), "P_дин(t) over the rigid rope force at t = 0.")
    s0 = rhs(d, "(2), S(t)").subs({P: P_at0, Q: Q_at0})
    (p0,) = sp.solve(sp.Eq(S_at0, s0), P_at0)
    via_s0 = sp.factor(at0.subs(P_at0, p0))
    d.add("(25), via S(0)", sp.Eq(K, P_d / via_s0),
          "The reference written with S(0) from (2).")
    d.add("(26)", sp.Eq(K1, rhs(d, "(22)") / at0), "(22) put into (25).")
    d.add("(27)", sp.Eq(K2, rhs(d, "(24)") / at0), "(24) put into (25).")


def drive_laws(d: Derivation) -> None:
    """(28)–(31): drive force, resistance and the acceleration laws."""
    acc = sp.Symbol("acc")
    # Rigid hoist accelerating at a_i against Q: (m1 + m2) a = P − Q.
    (drive,) = sp.solve(sp.Eq((m1 + m2) * acc, P - Q), P)
    drive = drive.subs(acc, a)
    d.add("(28)", sp.Eq(P, drive),
          "Both masses accelerating at a_i(t) against Q(t): the rigid-hoist law "
          "(m1 + m2)·a_i = P − Q.", "The drive force that gives the load the "
          "acceleration a_i.", "Drive laws")
    d.add("(28), P(0)", sp.Eq(P_at0, drive.subs({a: a_at0, Q: 0})),
          "The law at t = 0, where Q(0) = 0 with pick-up.")
    rope_speed = C * v0 * t          # the drum winds in rope at v0, load resting
    (contact,) = sp.solve(sp.Eq(rope_speed.subs(t, tau0), m2 * g), tau0)
    ramp_q = rope_speed.subs(C, sp.solve(sp.Eq(tau0, contact), C)[0]).subs(m2 * g, Q_0)
    d.add("(28), Q(t)", sp.Eq(Q, ramp_q),
          "For 0 ≤ t ≤ τ_0 the rope stretches at v0 while the load rests: "
          "Q = C·v0·t, with C·v0 = m2 g/τ_0 from (29).")
    d.add("(28), Q(t), t ≥ τ_0", sp.Eq(Q, Q_0),
          "Once the rope holds the weight Q_0 = m2 g the load leaves the ground.")
    d.add("(28), Q(0)", sp.Eq(Q_at0, ramp_q.subs(t, 0)), "(28), Q(t) at t = 0.")
    d.add("(28), Q_0", sp.Eq(Q_0, m2 * g), "The weight of the load.")
    d.add("(29)", sp.Eq(tau0, contact), "C·v0·τ_0 = m2 g: the load leaves the ground.")
    for i in range(1, 5):
        amp = sp.Symbol("A")
        (value,) = sp.solve(definite_integral(amp * LAW_SHAPES[i], t, 0, t_n) - v0, amp)
        d.add(f"(30), a_{i}", sp.Eq(A_LAW[i], value * LAW_SHAPES[i]),
              f"Shape of a_{i} from ref. [7], scaled so that ∫₀^tп a dt = v0 (the "
              "drive reaches the steady speed at the end of the start).")
    d.add("(30), speed of a_2", sp.Eq(v_end, definite_integral(PRINTED_LAWS[2], t, 0, t_n)),
          "The printed a_2 integrated over the start.")
    weight = drive.subs(Q, m2 * g)
    d.add("(31)", sp.Eq(P, weight), "(28) with Q = m2 g: the load hangs on the rope.")
    d.add("(31), P(0)", sp.Eq(P_at0, weight.subs(a, a_at0)), "(31) at t = 0.")
    d.add("(31), Q", sp.Eq(Q, m2 * g), "The resistance is the weight throughout.")
    d.add("(31), Q(0)", sp.Eq(Q_at0, m2 * g), "The same at t = 0.")
