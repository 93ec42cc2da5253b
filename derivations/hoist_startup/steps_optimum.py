"""Steps (54)–(66) of paper 002: the load's fourth-order equation and the
Euler–Poisson "optimum", with the maxima stated after (66)."""
from __future__ import annotations

import sympy as sp

from crane_sym.derivation import Derivation
from crane_sym.mechanics.extrema import maximum_on_interval
from crane_sym.latex import latex
from crane_sym.mechanics.variational import euler_poisson

from .model import (K_OPT, LATEX_NAMES, PRINTED_LAWS, C, F_ref, J, Omega, P, Q, Q_0, a, a_at0,
                    dQdot_tau0, dk_tau0, g, k3_max, k4_max, k_d, kt_d, m1, m2, t, t3_star,
                    t4_star, t_n, tau0, v0, x1, x2)
from .steps import rhs


def optimum(d: Derivation, eq1: sp.Eq, eq2: sp.Eq) -> None:
    """(54)–(66): the load's fourth-order equation and the Euler–Poisson optimum."""
    (x1_of_x2,) = sp.solve(eq2, x1)
    fourth = sp.expand(eq1.lhs.subs(x1, x1_of_x2).doit() - eq1.rhs)
    lead = fourth.coeff(x2.diff(t, 4))
    fourth = sp.expand(fourth / lead)
    omega2 = rhs(d, "(2), Ω²")
    coeff = fourth.coeff(x2.diff(t, 2))
    if sp.simplify(coeff - omega2) != 0:
        raise RuntimeError(f"coefficient of ẍ2 is {coeff}, not Ω²")
    lhs = x2.diff(t, 4) + Omega ** 2 * x2.diff(t, 2)
    right = sp.expand(-(fourth - x2.diff(t, 4) - coeff * x2.diff(t, 2)))
    d.add("(54)", sp.Eq(lhs, right),
          "x1 from the load's equation (1) put into the drive's, divided by m1 m2/C.",
          "The optimum is sought for the load's own motion.", "The optimum")
    rigid = rhs(d, "(28)")
    d.add("(55)", sp.Eq(P, rigid), "The rigid-hoist law of (28).")
    with_law = sp.expand(right.subs(P, rigid))
    d.add("(56)", sp.Eq(lhs, sp.expand(with_law.subs(C, Omega ** 2 * m1 * m2 / (m1 + m2)))),
          "(55) put into (54); C (m1 + m2)/(m1 m2) = Ω².")
    ref = m2 * v0 / t_n
    d.add("(57), rope force", sp.Eq(k_d, C * (x1 - x2) / ref),
          "Definition: rope force over m2·v0/t_п.")
    d.add("(57)", sp.Eq(k_d, (m2 * x2.diff(t, 2) + Q) / ref),
          "(1) for the load gives C·(x1 − x2) = m2 ẍ2 + Q.")
    coefficient = rhs(d, "(57)")
    d.add("(58)", sp.Eq(J, sp.Integral(coefficient ** 2, (t, 0, t_n))),
          "The criterion to be made smallest.")
    ep = euler_poisson(coefficient ** 2, x2, t).lhs
    factor, core = sp.factor_terms(ep).as_coeff_Mul()
    scale, body = core.as_independent(x2, Q, as_Add=False)
    d.add("(59)", sp.Eq(sp.expand(body), 0),
          "Euler–Poisson equation of (58) for x2, divided by the constant factor "
          f"${latex(factor * scale, symbol_names=LATEX_NAMES)}$.")
    q_ramp = rhs(d, "(28), Q(t)")
    q_held = rhs(d, "(28), Q(t), t ≥ τ_0")
    if any(sp.diff(p, t, 2) != 0 for p in (q_ramp, q_held, m2 * g)):
        raise RuntimeError("Q is not linear on its pieces")
    d.add("Q̈ = 0 (before (60))", sp.Eq(Q.diff(t, 2), 0),
          "Q of (28) and (31) is linear in t on each piece.")
    jump = sp.diff(q_held, t) - sp.diff(q_ramp, t)
    d.add("Q̇ at τ_0 (before (60))", sp.Eq(dQdot_tau0, jump),
          "With pick-up Q̇ drops from Q_0/τ_0 to 0 at τ_0, so Q̈ holds a delta there.")
    d.add("(60)", sp.Eq(x2.diff(t, 4), 0), "(59) with Q̈ = 0.")
    reduced = d.step("(56)").statement.subs(Q.diff(t, 2), 0).subs(x2.diff(t, 4), 0)
    (acc,) = sp.solve(reduced, x2.diff(t, 2))
    d.add("(61)", sp.Eq(x2.diff(t, 2), acc), "(60) put into (56) with Q̈ = 0.")
    for i in range(1, 5):
        d.add(f"(61), i = {i}", sp.Eq(x2.diff(t, 4), sp.expand(
            PRINTED_LAWS[i].diff(t, 2))),
              f"ẍ2 = a_{i} of (30) differentiated twice.")
    optimal = coefficient.subs(x2.diff(t, 2), acc)
    d.add("(62)", sp.Eq(k_d, optimal), "(61) put into (57).")
    static = (m2 * g) / ref
    weight_only = sp.simplify(optimal.subs(Q, m2 * g) - static)
    d.add("(63)", sp.Eq(kt_d, weight_only),
          "(62) from weight, less the static part m2 g/(m2 v0/t_п).")
    early = optimal.subs(Q, q_ramp.subs(Q_0, m2 * g))
    d.add("(64)", sp.Eq(kt_d, early), "(62) with Q = m2 g t/τ_0 of (28), for t ≤ τ_0.")
    d.add("(64), τ_0 < t", sp.Eq(kt_d, weight_only), "(63) once the load is lifted.")
    d.add("(64), jump at τ_0", sp.Eq(dk_tau0, sp.simplify(
        early.subs(t, tau0) - weight_only.subs(t, tau0))),
          "k̃ just before τ_0 less k̃ just after.")
    for i in range(1, 5):
        d.add(f"(65), i = {i}", sp.Eq(K_OPT[i], sp.expand(weight_only.subs(
            a, PRINTED_LAWS[i]))), f"(63) with a_{i} of (30).")
    for i in range(1, 5):
        d.add(f"(66), i = {i}", sp.Eq(K_OPT[i], sp.expand(early.subs(
            a, PRINTED_LAWS[i]))), f"(64) with a_{i} of (30).")
    for i in (3, 4):
        s = sp.Symbol("s", nonnegative=True)
        shape = sp.expand(weight_only.subs(a, PRINTED_LAWS[i]).subs(t, s * t_n))
        best = maximum_on_interval(shape, s, 0, 1)
        d.add(f"t{i}* (after (66))", sp.Eq(t3_star if i == 3 else t4_star,
                                          best.location * t_n),
              f"Largest (65), i = {i} on [0, t_п], by its critical points.")
        d.add(f"max k̃{i} (after (66))", sp.Eq(k3_max if i == 3 else k4_max, best.value),
              f"(65), i = {i} at t_{i}^*.")
    # Beyond the paper: the reference forces behind its coefficients.
    d.add("reference of (25), from weight", sp.Eq(F_ref, sp.expand(
        rhs(d, "rigid rope force").subs(
            {P: rhs(d, "(31)"), Q: m2 * g}).subs(a, a_at0))),
          "The rigid rope force of (25) with the law (31) at t = 0.",
          "Compares the normalisations of (25) and (57).")
