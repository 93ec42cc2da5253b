"""The start-up of Fig. 11 / Table 1 as steps: the equations of motion from
Lagrange's equations, the drive reduced to the wheel rim, the stepped start, and
the model's Table 1 (phases in closed form, ``startup.py``)."""
from __future__ import annotations

import sympy as sp

from crane_sym.derivation import Derivation
from crane_sym.mechanics.lagrange import lagrange_equations

from .model import (F_1, F_peak, beta_k, t, x_1, x_2, x_k, J_r, a_cell, t_s, v_gap, P_m,
                    P_nom, W_f, W_w, a_0, b_l, beta_1, c_l, lam, m_d, m_k, n_m, omega_0,
                    omega_n, phi_b, psi_cell, q_step, s_b, v_0, v_n, zeta)
from .startup import table1_results, table1_sensitivities



def equations_of_motion(d: Derivation) -> None:
    """Newton/Lagrange for the two motor masses and the crane, both stages."""
    x1, x2, xk = x_1, x_2, x_k
    beta = beta_k
    T = m_d * (x1.diff(t) ** 2 + x2.diff(t) ** 2) / 2 + m_k * xk.diff(t) ** 2 / 2
    V = c_l * ((x1 - xk - s_b) ** 2 + (x2 - xk - s_b) ** 2) / 2
    R = b_l * ((x1 - xk).diff(t) ** 2 + (x2 - xk).diff(t) ** 2) / 2
    Q = {x1: beta * (v_0 - x1.diff(t)), x2: beta * (v_0 - x2.diff(t)), xk: -W_w - W_f}
    eqs = lagrange_equations(T, V, (x1, x2, xk), t, Q, R).equations
    how = ("Lagrange's equations with T = m_d(ẋ1² + ẋ2²)/2 + m_к ẋ_к²/2, both links on "
           "their driving flanks (Π = c Σ(x_i − x_к − s)²/2, Rayleigh Φ = b Σ(ẋ_i − ẋ_к)²/2), "
           "the motor forces β_k(v0 − ẋ_i) and the resistance −(W_w + W_f) as generalized "
           "forces. The paper's (1)–(2) are lost in the OCR: this is the system its text "
           "defines (model text).")
    for i, (name, eq) in enumerate(zip(("left motors", "right motors", "crane"), eqs)):
        d.add(f"start-up, {name}", eq, how if i == 0 else "The same Lagrangian.",
              "Second stage: joint motion of the motor and crane masses. Fig. 12 (loads and "
              "speeds for backlash 0, π, 2π): the paper's start-up scene draws it."
              if i == 2 else "",
              "Start-up with backlash (Fig. 11)" if i == 0 else "")
    d.add("start-up, first stage", sp.Eq(m_d * x1.diff(t, 2),
                                         beta * (v_0 - x1.diff(t)) - F_1),
          "While the crane stands (W_w − W_f ≤ F_1 + F_2 ≤ W_w + W_f) only the motors move; "
          "F_1 = 0 in the gap (0 < x_1 − x_к < s), c(x_1 − x_к − s) + b(ẋ_1 − ẋ_к) once the "
          "flank closes: the first stage, 'taking up the backlash until the link load "
          "reaches the resistance to travel'.", "Each phase is linear: x' = A x + b, "
          "solved in closed form; the instants where a flank closes or opens, the crane "
          "breaks away or stops, are roots of those closed forms.")


def reduction(d: Derivation) -> None:
    """The drive at the wheel rim and the stepped rheostat start."""
    d.add("start-up, motor mass at the rim", sp.Eq(m_d, n_m * J_r * (omega_n / v_n) ** 2),
          "Equal kinetic energy: n_m rotors J_r at ω = ω_n·v/v_n move like a mass m_d at "
          "the rim speed v.", "m_d of Fig. 11, one side.", "The drive at the rim")
    d.add("start-up, rated force", sp.Eq(P_nom, n_m * P_m / v_n),
          "Power at the rated speed: n_m motors of P_m drive one side at v_n.")
    d.add("start-up, no-load speed", sp.Eq(v_0, v_n * omega_0 / omega_n),
          "The rim speed is proportional to the motor speed.")
    d.add("start-up, backlash at the rim", sp.Eq(s_b, phi_b * v_n / omega_n),
          "A turn φ_b of the fast shaft moves the rim by φ_b·v_n/ω_n.")
    d.add("start-up, first characteristic", sp.Eq(beta_1, lam * P_nom / v_0),
          "The first characteristic β_1(v0 − v) starts at P_p1 = λ·P_n at standstill.")
    d.add("start-up, slope ratio",
          sp.Eq(q_step, (v_0 / (lam * (v_0 - v_n))) ** sp.Rational(1, 3)),
          "Three rheostat steps with slopes β_1·q^k up to the natural characteristic, "
          "slope P_n/(v0 − v_n): q³ = (P_n/(v0 − v_n))/(λP_n/v0).")
    d.add("start-up, link damping", sp.Eq(b_l, 2 * zeta * sp.sqrt(c_l * m_d)),
          "A link against its motors as an oscillator of damping ratio ζ.")
    d.add("start-up, rigid break-away", sp.Eq(a_0, (2 * lam * P_nom - W_w - W_f)
                                                / (m_k + 2 * m_d)),
          "Rigid drive, no backlash: at standstill both sides pull λ·P_n; what exceeds the "
          "resistance accelerates all three masses.", "A reference for the elastic start.")
    v = sp.Function("v")(t_s)
    gap_speed = v_0 * (1 - sp.exp(-beta_1 / m_d * t_s))
    ode = sp.Eq(m_d * v.diff(t_s), beta_1 * (v_0 - v))
    residual = (ode.lhs - ode.rhs).subs(v, gap_speed).doit()
    if sp.simplify(residual) != 0 or gap_speed.subs(t_s, 0) != 0:
        raise AssertionError("the gap speed does not solve the first-stage equation")
    d.add("start-up, motor speed in the gap", sp.Eq(v_gap, gap_speed),
          "First stage, gap open (F_1 = 0): m_d·v̇ = β_1(v0 − v) from rest, a first-order "
          "equation solved in closed form; the time constant m_d/β_1 = J_r·ω_0·ω_n/(λ·P_m) "
          "does not depend on the gearing.", "How fast the motors run into the backlash: "
          "the speed at which a flank closes sets the impact.")


def table1_model(d: Derivation) -> None:
    """The model's F_max, ψ and step accelerations for each backlash of Table 1."""
    results, swing = table1_results(), table1_sensitivities()
    for i, (gap, r) in enumerate(results.items()):
        head = "The model's Table 1" if i == 0 else ""
        d.add(f"start-up model, F_max, backlash {gap}",
              sp.Eq(F_peak, sp.Float(r["F_max_kN"], 15)),
              f"Largest F_1 + F_2 (at t = {r['t_max']:.3f} s), backlash {gap} rad in both "
              "drives, the chosen parameters (model text); per phase at the zeros of the "
              "closed form's rate.", "Table 1's 'largest longitudinal load' [kN].", head,
              sensitivity=swing[f"F_max, {gap}"])
        d.add(f"start-up model, psi, backlash {gap}", sp.Eq(psi_cell, sp.Float(r["psi"], 15)),
              "F_max over Table 1's F_ср = 150 kN.", sensitivity=swing[f"psi, {gap}"])
        for k in (1, 2, 3):
            d.add(f"start-up model, acceleration {k}, backlash {gap}",
                  sp.Eq(a_cell, sp.Float(r[f"a{k}"], 15)),
                  f"The crane's speed gained over start step {k} over its hold time [m/s²].",
                  sensitivity=swing[f"a{k}, {gap}"])
