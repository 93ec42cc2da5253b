"""The derivation steps of paper 001: kinematics, reduced inertia, static
torque, the rigid drive (1), the cut at the gearbox input, the factors MF, LF,
BF_SB, BF_BB, φ5 as the text defines them, then (2)–(7).

Each function adds one section's steps to the ``Derivation``; ``build()`` in
``__init__`` calls them in order.
"""
from __future__ import annotations

import sympy as sp

from crane_sym.derivation import Derivation

from .model import (BF_BB, BF_SB, LF, MF, J, J1, J2, J_d, M_BB, M_G, M_L, M_M, M_SB,
                    M_rel, M_rel_max, M_st, alpha, d_omega, d_t, g, i_g, i_t, m_h, m_p,
                    m_r, omega1, phi5, r, v)

#: Direction of travel: +1 hoisting, −1 lowering (the print's ± in (2), ∓ in (6)).
MODES = {"hoisting": 1, "lowering": -1}


def drive(d: Derivation) -> None:
    """Kinematics, reduced inertia and static torque of the drive (Table 1)."""
    w = sp.Symbol("w", positive=True)
    hook = w * r / (i_g * i_t)
    d.add("hoist speed", sp.Eq(v, hook.subs(w, omega1)),
          "The drum turns at ω1/i_g, the rope at ω1·r/i_g, the hook at 1/i_t of that.",
          "Table 1 prints both n1 and v; they must agree.", "Kinematics")
    T = (J1 * w ** 2 + J2 * (w / i_g) ** 2 + (m_h + m_p) * hook ** 2) / 2
    d.add("reduced inertia", sp.Eq(J, sp.expand(2 * T / w ** 2)),
          "Kinetic energy of motors, drums and hook with payload at motor speed ω, "
          "divided by ω²/2.", "The rigid drive is one inertia at the motor shaft.",
          "Reduced inertia and static torque")
    d.add("inertia beyond the cut", sp.Eq(J_d, sp.expand(2 * T / w ** 2) - J1),
          "Everything in J but the motor shafts.")
    d.add("static torque", sp.Eq(M_L, (m_h + m_p) * g * hook / w),
          "The weight's power (m_h + m_p)·g·v equals M_L·ω.")
    d.add("rated static torque", sp.Eq(M_st, (m_h + m_r) * g * hook / w),
          "The static torque with the rated payload: the reference of every factor.")


def rigid_drive(d: Derivation) -> dict[str, sp.Expr]:
    """(1) and the cut at the gearbox input; returns mode -> M_G of the rigid drive
    braked by the safety brakes alone, motor torque lost."""
    s = sp.Symbol("s")   # +1 hoisting, -1 lowering
    # Moments positive in the direction of travel: the weight always lowers,
    # brakes oppose the motion.
    total = M_M - s * (M_BB + M_SB / i_g) - M_L
    for mode, sign in MODES.items():
        d.add(f"(1), {mode}", sp.Eq(alpha, total.subs(s, sign) / J),
              f"Sum of the moments at the motor shaft over the reduced inertia, "
              f"{mode}: motor torque, brakes against the motion, weight downwards.",
              "The paper's first formula, α1 = ΣM_i / J_red.",
              "The rigid drive" if sign == 1 else "")
    cut = sp.Eq(M_G, M_M - s * M_BB - J1 * alpha)
    d.add("gearbox input", cut,
          "The motor shafts cut off at the gearbox input: J1·α = M_M ∓ M_BB − M_G, "
          "M_G the torque the shafts pass into the gearbox (s = +1 hoisting, −1 lowering).",
          "Fig. 6: the paper's section at the gearbox input.", "The cut at the gearbox")
    factors = {J1: MF * J, M_L: LF * M_st, M_SB: BF_SB * i_g * M_st, M_BB: BF_BB * M_st}
    d.add("MF", sp.Eq(MF, J1 / J), "The share of the motor shafts in J.",
          "The text: 'the inertia factor reduced to the motor shaft'.", "The factors")
    d.add("LF", sp.Eq(LF, M_L / M_st), "The static torque of the load over the rated one.")
    d.add("BF_SB", sp.Eq(BF_SB, M_SB / (i_g * M_st)),
          "Safety-brake torque at the motor shaft over the rated static torque.")
    d.add("BF_BB", sp.Eq(BF_BB, M_BB / M_st),
          "Service-brake torque over the rated static torque.")
    before = sp.Eq(M_rel, LF)
    steady = cut.rhs.subs(alpha, total / J).subs({M_M: M_L, M_BB: 0, M_SB: 0})
    d.add("before braking", sp.Eq(M_rel, sp.simplify(steady.subs(s, 1) / M_st
                                                     ).subs(factors).subs(factors)),
          "Steady travel (M_M = M_L, no brake): the cut carries M_L, i.e. LF·M_st.")
    rigid = {}
    for mode, sign in MODES.items():
        after = cut.rhs.subs(s, sign).subs(alpha, total.subs(s, sign) / J).subs(
            {M_M: 0, M_BB: 0})
        rel = sp.factor(sp.expand(after.subs(factors) / M_st))
        rigid[mode] = rel
        d.add(f"rigid jump, {mode}", sp.Eq(M_rel, rel),
              f"{mode.capitalize()}, motor torque lost, safety brakes acting, service "
              "brakes not yet (their delay is longer): α from (1) put into the cut, "
              "then J1 = MF·J, M_L = LF·M_st, M_SB = BF_SB·i_g·M_st.",
              "The rigid drive's gearbox torque right after the safety brakes act.")
    d.add("φ5", sp.Eq(M_rel_max, before.rhs + phi5 * (M_rel - before.rhs)),
          "EN 13001-2: φ5 multiplies the change of a load caused by a change of drive "
          "or brake force, so the peak is the load before plus φ5 times the jump.",
          "The paper applies φ5 to the jump without writing how; this is the standard's "
          "definition.")
    for mode in MODES:
        d.add(f"(2), {mode}", sp.Eq(M_rel_max, sp.expand(
            before.rhs + phi5 * (rigid[mode] - before.rhs))),
              f"φ5 applied to the rigid jump, {mode}.",
              title="Peak relative gearbox torque" if mode == "hoisting" else "")
    d.add("(3)", sp.Eq(M_rel_max, sp.expand((before.rhs + phi5 * (rigid["hoisting"]
                                                                  - before.rhs)).subs(LF, 1))),
          "(2), hoisting, with the rated load (LF = 1).")
    d.add("(4)", sp.Eq(M_rel, rigid["hoisting"].subs(LF, 1)),
          "The rigid jump, hoisting the rated load (φ5 = 1).")
    d.add("(5)", sp.Eq(M_rel, rigid["hoisting"].subs({LF: 1, MF: 1})),
          "(4) when all inertia sits on the motor shaft (MF = 1), the worst case.")
    return rigid


def coordinated_brakes(d: Derivation) -> None:
    """(6)–(7): the brake factors that keep the static torque in the gearbox."""
    a = d_omega / d_t
    mb, ms = sp.symbols("mb ms")
    for mode, sign in MODES.items():
        # uniform deceleration against the motion; motor torque gone; M_G = M_L.
        motor = sp.Eq(J1 * (-sign * a), -sign * mb - M_L)
        beyond = sp.Eq((J - J1) * (-sign * a), M_L - M_L - sign * ms / i_g)
        sol = sp.solve([motor, beyond], [mb, ms], dict=True)[0]
        sub = {J1: MF * J, M_L: LF * M_st}
        bb = sp.expand((sol[mb] / M_st).subs(sub))
        sb = sp.factor((sol[ms] / (i_g * M_st)).subs(sub))
        d.add(f"(6), {mode}", sp.Eq(BF_BB, bb),
              f"{mode.capitalize()}: the gearbox input keeps M_G = M_L while the drive "
              "decelerates uniformly by Δω in Δt; the motor shafts' equation gives M_BB.",
              "The paper's condition: the static torque stays in the gearbox while all "
              "brakes act.", "Coordinated (smart) brakes" if sign == 1 else "")
        d.add(f"(7), {mode}", sp.Eq(BF_SB, sb),
              "The equation of everything beyond the cut (J − J1 = (1 − MF)·J) gives M_SB.")


def elastic_no_backlash(d: Derivation) -> sp.Expr:
    """Fig. 9 without backlash: the two-mass drive in closed form while the drum
    slides (the limit the piecewise solution with backlash must reach).

    Returns the relative gearbox torque as a Piecewise in t (before/after t_SB).
    """
    from .model import J_d, c, t, t_SB
    u = sp.Function("u")(t)
    omega2 = c * (J1 + J_d) / (J1 * J_d)
    brake = M_SB / i_g
    ode = sp.Eq(u.diff(t, 2) + omega2 * u,
                (M_L - brake * sp.Heaviside(t - t_SB)) / J_d)
    d.add("Fig. 9, two masses", ode,
          "Lowering is +; the motor shafts J1 feel only the gearbox torque c·u once the "
          "motor torque is lost (t = 0), the drum side J_d the weight M_L, −c·u and the "
          "safety brakes M_SB/i_g from t_SB; (drum − motor equation) gives one equation "
          "in the twist u.", "The elasto-kinetic case of Fig. 9 with no backlash, "
          "valid while the drum slides and the motor is unbraked.", "Fig. 9 without backlash")
    W = sp.sqrt(omega2)
    u0, ue = M_L / c, M_L / (J_d * omega2)
    before = ue + (u0 - ue) * sp.cos(W * t)
    after = before - brake / (J_d * omega2) * (1 - sp.cos(W * (t - t_SB)))
    for piece, rhs in ((before, M_L / J_d), (after, (M_L - brake) / J_d)):
        if sp.simplify(piece.diff(t, 2) + omega2 * piece - rhs) != 0:
            raise AssertionError("the twist does not solve the Fig. 9 equation")
    if sp.simplify(after.subs(t, t_SB) - before.subs(t, t_SB)) != 0 or sp.simplify(
            (after.diff(t) - before.diff(t)).subs(t, t_SB)) != 0:
        raise AssertionError("the twist is not C¹ at t_SB")
    rel = sp.Piecewise((c * before / M_st, t < t_SB), (c * after / M_st, True))
    d.add("Fig. 9, no backlash", sp.Eq(M_rel, rel),
          "Steady lowering (u = M_L/c, equal speeds) at t = 0, each interval solved as a "
          "constant-forcing oscillator, joined C¹ at t_SB; M_G = c·u over M_st.")
    return rel
