"""What the toolkit generates code from for paper 001: the relative gearbox
torque of the rigid drive (with φ5), the coordinated brake factors over the
payload, and the rigid drive's speed and stopping time in an emergency stop.
"""
from __future__ import annotations

import sympy as sp

from crane_sym.derivation import Derivation, Output, TabulatedOutput

from . import model as _model
from .hybrid import EMERGENCY_STOP

from .model import (BF_SB, LF, MF, J, J1, J2, M_BB, M_L, M_M, M_SB, M_st, d_omega, d_t, g,
                    i_g, i_t, m_h, m_p, m_r, omega1, phi5, r, t, t_BB, t_SB, c, delta)

#: Arguments of the payload functions, the most used first.
HOIST = (m_p, J1, J2, m_h, m_r, r, i_g, i_t, g, omega1)
BRAKES = (M_SB, M_BB, t_SB, t_BB)


def physical(d: Derivation, expr: sp.Expr) -> sp.Expr:
    """``expr`` with MF, LF, J, M_L and M_st written in Table 1's quantities."""
    expr = expr.subs({MF: d.step("MF").statement.rhs, LF: d.step("LF").statement.rhs})
    return expr.subs({J: d.step("reduced inertia").statement.rhs,
                      M_L: d.step("static torque").statement.rhs,
                      M_st: d.step("rated static torque").statement.rhs})


def _speed_law(d: Derivation, mode: str) -> tuple[sp.Expr, sp.Expr, sp.Expr]:
    """Hook speed (m/s, in the direction of travel) of the rigid drive after an
    emergency stop at t = 0 (motor torque lost), the time it comes to rest, and
    the drive's deceleration with every brake on (> 0: it comes to rest).

    The accelerations of (1) in the three intervals (no brake, safety brakes,
    all brakes) are constant, so ω is piecewise linear; the brakes hold it at 0.
    """
    # (1) takes hoisting as +; the speed here is along the direction of travel.
    sign = 1 if mode == "hoisting" else -1
    step = sign * d.step(f"(1), {mode}").statement.rhs.subs(M_M, 0)
    a0 = physical(d, step.subs({M_SB: 0, M_BB: 0}))
    a1 = physical(d, step.subs(M_BB, 0))
    a2 = physical(d, step)
    w_sb = omega1 + a0 * t_SB
    w_bb = w_sb + a1 * (t_BB - t_SB)
    free = sp.Piecewise((omega1 + a0 * t, t <= t_SB),
                        (w_sb + a1 * (t - t_SB), t <= t_BB),
                        (w_bb + a2 * (t - t_BB), True))
    gear = r / (i_g * i_t)
    speed = sp.Piecewise((gear * free, free > 0), (0, True))
    stop = sp.Piecewise((-omega1 / a0, w_sb <= 0), (t_SB - w_sb / a1, w_bb <= 0),
                        (t_BB - w_bb / a2, True))
    return speed, stop, -a2


def _one_phase_after(rel: sp.Piecewise) -> sp.Piecewise:
    """Fig. 9 without backlash with its after-t_SB piece on the phases Ω(t − t_SB)
    and Ω·t_SB only (exactly equal to the derived form).

    As derived, that piece is ``u0 − (u0 − ue)(1 − cos Ωt) − B(1 − cos Ω(t − t_SB))``:
    two large phases rounded on their own, whose errors do not cancel where the
    two oscillations do (near a turning point of the torque, at long times) —
    1.2e-13 against a 2.4e-14 bound in 001's payload-from-1e-12-kg case. With
    Ωt = Ωτ + h (τ = t − t_SB, h = Ω·t_SB) it is
    ``u0 − (u0 − ue + B)·2sin²(Ωτ/2) − (u0 − ue)(2cos(Ωτ)·sin²(h/2) + sin(Ωτ)·sin h)``:
    a rounding of Ωτ errs like a rounding of t, one of h like one of t_SB
    (t_SB ≤ t), and at small τ every term keeps its sign (no cancellation).
    """
    from .model import J_d, c
    (before, early), (after, _) = rel.args
    omega2 = c * (J1 + J_d) / (J1 * J_d)
    W = sp.sqrt(omega2)
    u0, ue, B = M_L / c, M_L / (J_d * omega2), (M_SB / i_g) / (J_d * omega2)
    x, h = W * (t - t_SB), W * t_SB
    stable = c / M_st * (u0 - (u0 - ue + B) * 2 * sp.sin(x / 2) ** 2
                         - (u0 - ue) * (2 * sp.cos(x) * sp.sin(h / 2) ** 2
                                        + sp.sin(x) * sp.sin(h)))
    a, b = sp.symbols("a b", real=True)        # Ωτ and h
    gap = (stable - after).subs({t: (a + b) / W, t_SB: b / W}).replace(
        lambda e: isinstance(e, (sp.sin, sp.cos)), lambda e: e.func(sp.expand(e.args[0])))
    gap = gap.subs({sp.sin(a / 2) ** 2: (1 - sp.cos(a)) / 2, sp.sin(b / 2) ** 2: (1 - sp.cos(b)) / 2})
    if sp.simplify(sp.expand_trig(gap)) != 0:
        raise AssertionError("the one-phase form is not the derived after-t_SB piece")
    return sp.Piecewise((before, early), (stable, True))


def outputs(d: Derivation) -> list[Output]:
    """Generated functions: the paper's factors, then Table 1's quantities."""
    rhs = lambda label: d.step(label).statement.rhs  # noqa: E731
    out = [
        Output("relative_gearbox_torque_hoisting", rhs("rigid jump, hoisting"),
               (MF, LF, BF_SB), ("(2)", "(4)"),
               "Rigid drive, hoisting: gearbox-input torque over the rated static torque "
               "after the safety brakes act (motor torque lost).", "1"),
        Output("relative_gearbox_torque_lowering", rhs("rigid jump, lowering"),
               (MF, LF, BF_SB), ("(2)",),
               "Rigid drive, lowering: the same (negative when the brakes reverse it).",
               "1"),
        Output("peak_relative_gearbox_torque_hoisting", rhs("(2), hoisting"),
               (phi5, MF, LF, BF_SB), ("(2)", "(3)"),
               "Peak relative gearbox torque, hoisting, with the dynamic factor phi5.", "1"),
        Output("peak_relative_gearbox_torque_lowering", rhs("(2), lowering"),
               (phi5, MF, LF, BF_SB), ("(2)",),
               "Peak relative gearbox torque, lowering, with the dynamic factor phi5.", "1"),
    ]
    for n, mode, name in ((6, "hoisting", "service_brake_factor_hoisting"),
                          (6, "lowering", "service_brake_factor_lowering"),
                          (7, "hoisting", "safety_brake_factor")):
        expr = sp.factor(sp.cancel(physical(d, rhs(f"({n}), {mode}").subs(d_omega, omega1))))
        out.append(Output(name, expr, HOIST + (d_t,), (f"({n})",),
                          f"Coordinated brake factor ({n}) over the payload m_p, stopping "
                          f"from omega1 in d_t ({mode}).", "1"))
    J_d = d.step("inertia beyond the cut").statement.rhs
    torque = physical(d, _one_phase_after(rhs("Fig. 9, no backlash")).subs(_model.J_d, J_d))
    out.append(Output("elastic_gearbox_torque_no_backlash", torque,
                      (t, J1, J2, m_h, m_p, m_r, r, i_g, i_t, g, c, M_SB, t_SB), ("Fig. 9",),
                      "Relative gearbox torque M_G/M_st of the elastic drive without backlash, "
                      "lowering, motor torque lost at t = 0, safety brakes from t_SB; valid "
                      "while the drum slides and the service brakes are off.", "1"))
    out.append(Output("elastic_natural_frequency", sp.sqrt(c * (1 / J1 + 1 / J_d)),
                      (J1, J2, m_h, m_p, r, i_g, i_t, c), ("Fig. 9",),
                      "Natural frequency of the two-mass drive in contact (motor shafts J1 "
                      "against everything beyond the gearbox input, stiffness c).", "rad/s"))
    out.append(Output("backlash_at_motor_shaft", delta * i_g, (delta, i_g), ("Fig. 9",),
                      "The drum-coupling backlash seen at the motor shaft.", "rad"))
    for mode in ("hoisting", "lowering"):
        speed, stop, braking = _speed_law(d, mode)
        out.append(Output(f"rigid_hook_speed_{mode}", speed, (t,) + HOIST[:4] + HOIST[5:]
                          + BRAKES, ("(1)",),
                          f"Hook speed of the rigid drive, {mode}, after an emergency stop "
                          "at t = 0: motor torque lost, brakes after their delays (Fig. 5).",
                          "m/s"))
        out.append(Output(f"rigid_stopping_time_{mode}", stop, HOIST[:4] + HOIST[5:] + BRAKES,
                          ("(1)",), f"Time the rigid drive takes to stop, {mode}.", "s",
                          ((braking, "the brakes together decelerate the drive "
                                     "(M_BB + M_SB/i_g above the load torque): else it "
                                     "never stops"),)))
    return out


def tabulated() -> list[TabulatedOutput]:
    """The elasto-kinetic response of Fig. 9 with backlash: its phases depend on
    the data, so a scene's module carries it as a table (``crane_sym.mechanics.phase_table``),
    the run of ``hybrid.EMERGENCY_STOP``."""
    return [TabulatedOutput(
        "elastic_gearbox_torque",
        (J1, J2, m_h, m_p, m_r, r, i_g, i_t, g, c, delta, M_SB, M_BB, t_SB, t_BB, omega1),
        ("Fig. 9",),
        "Relative gearbox torque M_G/M_st of the elastic drive with the coupling backlash, "
        "emergency stop while lowering the payload m_p: motor torque lost at t = 0, safety "
        "brakes after t_SB, service brakes after t_BB, brakes that stick at zero speed.",
        "1", EMERGENCY_STOP.runner("relative_torque"))]
