"""The printed numbers of paper 001 rebuilt from Table 1: one step per number
and per reading of the data, so that each printed number is checked against
what each reading gives (the model text says which reading is chosen, and why).

Table 1 counts J1, J2 and M_SB once for a hoist with two motors and two drums:
``totals`` reads them as the values of the whole drive (the paper's reading,
``published.TABLE1_COUNTING``), ``per train`` counts each twice (one per motor,
one per drum): the rejected reading, derived so that a printed number only it
reproduces can be named.
"""
from __future__ import annotations

import sympy as sp

from crane_sym.derivation import Derivation

from .model import (BF_BB, BF_SB, G, LF, MF, TABLE1, J, J1, J2, M_L, M_SB, M_st, N, d_omega,
                    d_t, g, i_g, i_t, m_h, m_p, m_r, omega1, phi5, r)

COUNTINGS = {"per train": 2, "totals": 1}
#: The two brake factors the text gives after (5).
TEXT_BF = (sp.Rational(17, 10), sp.Rational(33, 10))
PHI5_RANGE = (1, 2)   # EN 13001-2: φ5 from 1 (smooth) to 2 (sudden)


def table1(d: Derivation, payload: sp.Expr, trains: int = 1) -> dict:
    """Table 1 as values of the model's symbols, J1, J2, M_SB counted ``trains`` times."""
    t = TABLE1
    return {omega1: t["n1"] * 2 * sp.pi / 60, J1: trains * t["J1"], J2: trains * t["J2"],
            m_h: t["m_h"], m_r: t["m_r"], m_p: payload, r: t["r"], i_g: t["i_g"],
            i_t: t["i_t"], g: G, M_SB: trains * t["M_SB"]}


def numbers(d: Derivation) -> None:
    """One step per printed number and reading (Table 1, after (5), Figs 8, 11, 12)."""
    d.add("Table 1, hoist speed", sp.Eq(N, 60 * value_of(d, d.step("hoist speed").statement.rhs,
                                                          table1(d, 0))),
          "n1, r, i_g and i_t of Table 1 in the hoist speed, in m/min.",
          "Table 1 prints v = 45 m/min beside n1 = 1500 1/min.", "Table 1's numbers")
    mf = {}
    for name, trains in COUNTINGS.items():
        mf[name] = tuple(sp.nsimplify(value_of(d, J1 / J, table1(d, p, trains)))
                         for p in (TABLE1["m_r"], 0))
        d.add(f"MF rated load, {name}", sp.Eq(N, mf[name][0]),
              f"MF = J1/J with the rated payload, J1 and J2 counted {name}.")
        d.add(f"MF hook only, {name}", sp.Eq(N, mf[name][1]),
              f"MF = J1/J with the hook alone, J1 and J2 counted {name}.")
        rated = table1(d, TABLE1["m_r"], trains)
        d.add(f"BF_SB of Table 1, {name}", sp.Eq(N, sp.nsimplify(
            value_of(d, M_SB / (i_g * M_st), rated))),
              f"M_SB/(i_g·M_st) with 130 kN·m counted {name}.")
    three = d.step("(3)").statement.rhs
    four = d.step("(4)").statement.rhs
    for bf in TEXT_BF:
        for name in COUNTINGS:
            lo, hi = mf[name]
            d.add(f"after (5), BF_SB = {bf}, lower, {name}",
                  sp.Eq(N, three.subs({BF_SB: bf, MF: lo, phi5: PHI5_RANGE[0]})),
                  f"(3) with φ5 = 1 and the smallest MF (rated load, {name}).")
            d.add(f"after (5), BF_SB = {bf}, upper, {name}",
                  sp.Eq(N, three.subs({BF_SB: bf, MF: hi, phi5: PHI5_RANGE[1]})),
                  f"(3) with φ5 = 2 and the largest MF (hook only, {name}).")
            d.add(f"rigid, (4), BF_SB = {bf}, {name}", sp.Eq(N, four.subs(
                {BF_SB: bf, MF: hi})), f"(4) with the largest MF ({name}).")
    d.add("(5) at Table 1, per drum", sp.Eq(N, d.step("(5)").statement.rhs.subs(
        BF_SB, d.step("BF_SB of Table 1, per train").statement.rhs)),
          "(5) with BF_SB of 130 kN·m on each of the two drums.")
    coordinated(d)


def coordinated(d: Derivation) -> None:
    """Figs 11–12: the brake factors (6)–(7) at the ends of the payload axis (as
    fractions; the text prints percent), stopping from n1 in Δt (unstated), and
    at Δt = 1 s."""
    for mode in ("hoisting", "lowering"):
        for payload, end in ((0, "0 t"), (TABLE1["m_r"], "52 t")):
            vals = table1(d, payload)
            for factor, label in ((BF_SB, "(7)"), (BF_BB, "(6)")):
                expr = d.step(f"{label}, {mode}").statement.rhs
                expr = expr.subs({MF: d.step("MF").statement.rhs,
                                  LF: d.step("LF").statement.rhs}).subs(d_omega, omega1)
                factor_value = sp.simplify(value_of(d, expr, vals))
                name = f"Fig. {11 if mode == 'hoisting' else 12}, {factor}, {end}"
                d.add(name, sp.Eq(N, factor_value),
                      f"{label}, {mode}, payload {end}, stopping from n1 (Δω = ω1) in Δt "
                      "(a fraction; the text prints percent).",
                      title="Figs 11–12" if (mode, end, label) ==
                      ("hoisting", "0 t", "(7)") else "")
                d.add(name + ", Δt = 1 s", sp.Eq(N, sp.nsimplify(factor_value.subs(d_t, 1))),
                      "The same with Δt = 1 s.")


def value_of(d: Derivation, expr: sp.Expr, values: dict) -> sp.Expr:
    """``expr`` with the definitions of J, M_L, M_st and then ``values`` put in."""
    for _ in range(3):
        expr = expr.subs({J: d.step("reduced inertia").statement.rhs,
                          M_L: d.step("static torque").statement.rhs,
                          M_st: d.step("rated static torque").statement.rhs})
    return expr.subs(values)
