"""What the toolkit generates code from for paper 003: a gear designer's
functions (Form 1, Fig. 10), the largest support load (3)–(4), the closed-form
pieces of the start-up model (the drive at the rim, the stepped start), and
the start-up's curves, which a scene tabulates (``tabulated``).

Arc cosines whose argument can leave [−1, 1] are ``acos_checked`` (an
impossible mesh or tip raises an error naming the parameter), the involute
is ``involute`` (a stable kernel at small angles), and the tip-thickness shift
is ``tip_shift`` (a bracketed solve): the derived expressions, with each such
function evaluating to the derived one in mpmath.
"""
from __future__ import annotations

from functools import partial

import sympy as sp

from crane_sym.derivation import Derivation, Output, TabulatedOutput
from crane_sym.mechanics.involute import acos_checked, involute, tip_half_angle, tip_shift

from .hybrid import scene_runs
from .model import (G_g, G_pch, G_vs, J_r, L_max, M_v, P_m, P_nom, W_f, W_w, a_w, alpha,
                    alpha_a1, alpha_a2, alpha_tw, c_arm, c_l, d_a1, d_a2, dy, dy1, dy2, ha,
                    lam, m, m_d, m_k, n_m, omega_0, omega_n, phi_b, psi, sigma, v_0, v_n, x,
                    t_s, x1, x2, x_o, x_sum, z, z1, z2, zeta)


def _stable(expr: sp.Expr) -> sp.Expr:
    """tan a − a of the derived form as ``involute(a)``."""
    return expr.replace(lambda e: isinstance(e, sp.Add) and any(
        isinstance(t, sp.tan) and -t.args[0] in e.args for t in e.args),
        lambda e: _fold(e))


def _fold(add: sp.Add) -> sp.Expr:
    terms = list(add.args)
    for t in list(terms):
        if isinstance(t, sp.tan) and -t.args[0] in terms:
            terms.remove(t)
            terms.remove(-t.args[0])
            terms.append(involute(t.args[0]))
    return sp.Add(*terms)


def outputs(d: Derivation) -> list[Output]:
    """Generated functions: the gear pair of Form 1, Fig. 10's limits, (3)–(4)."""
    def rhs(label: str) -> sp.Expr:
        return d.step(label).statement.rhs

    cos_w = sp.cos(rhs("Form 1, alpha_tw"))   # acos's argument, recovered exactly
    angle_w = acos_checked(cos_w, 1)
    shift_sum = (involute(angle_w) - involute(alpha)) * (z1 + z2) / (2 * sp.tan(alpha))
    tips = {d_a1: rhs("Form 1, d_a1"), d_a2: rhs("Form 1, d_a2")}
    a1 = acos_checked(sp.cos(rhs("Form 1, alpha_a1")).subs(tips), 2)
    a2 = acos_checked(sp.cos(rhs("Form 1, alpha_a2")).subs(tips), 3)
    eps = rhs("Form 1, epsilon_alpha").subs({alpha_a1: a1, alpha_a2: a2, alpha_tw: angle_w})
    d_a = (m * z + 2 * (ha + x - dy) * m)
    thickness = d_a * tip_half_angle(x, z, alpha, ha, dy, 4)
    load = rhs("(3)").subs(M_v, rhs("(4)"))
    gear = (m, z1, z2, a_w, alpha)
    return [
        Output("operating_pressure_angle", angle_w, gear, ("Form 1, alpha_tw",),
               "Operating pressure angle alpha_tw of the pair at centre distance a_w.",
               "rad"),
        Output("shift_sum", _stable(shift_sum), gear, ("Form 1, x_sum",),
               "Sum of shift coefficients x1 + x2 from the meshing equation.", "1"),
        Output("centre_distance", _stable(rhs("centre distance from the shifts")),
               (m, z1, z2, x_sum, alpha), ("Form 1, x_sum", "Form 1, alpha_tw"),
               "Centre distance a_w at which the pair meshes without backlash with "
               "the sum of shifts x_sum (inverse involute).", "m"),
        Output("tip_diameter", d_a, (m, z, x, ha, dy), ("Form 1, d_a1",),
               "Tip diameter m*z + 2*(h_a + x - dy)*m.", "m"),
        Output("tip_thickness", thickness, (m, z, x, alpha, ha, dy), ("Form 1, s_a1",),
               "Tooth thickness on the tip circle (negative: the tooth is pointed "
               "below the tip).", "m"),
        Output("contact_ratio", eps, (m, z1, z2, x1, x2, a_w, alpha, ha, dy1, dy2),
               ("Form 1, epsilon_alpha",), "Transverse contact ratio epsilon_alpha.", "1"),
        Output("tip_thickness_shift", tip_shift(z, alpha, ha, dy, sigma),
               (z, alpha, ha, dy, sigma), ("pointed tip",),
               "Shift coefficient at which the tip thickness is sigma*m (Fig. 10, "
               "curves 2-3).", "1"),
        Output("pointed_tip_shift", tip_shift(z, alpha, ha, dy, 0), (z, alpha, ha, dy),
               ("pointed tip",), "Shift coefficient at which the tooth tip is pointed "
               "(Fig. 10, curve 1).", "1"),
        Output("undercut_limit", rhs("undercut limit"), (z, alpha, ha), ("undercut limit",),
               "Least shift coefficient free of undercut (Fig. 10, curve 4).", "1"),
        *startup_outputs(rhs),
        Output("max_support_load", load, (psi, G_g, G_pch, G_vs, L_max, x_o, c_arm),
               ("(3)", "(4)"), "Largest vertical load on one portal leg, load case 2v "
               "(reconstructed portal: see the derivation).", "N"),
    ]


def startup_outputs(rhs) -> list[Output]:
    """The start-up's closed-form pieces in the scene's own parameters (the rim
    quantities substituted), each checked equal to its step."""
    rim = {m_d: rhs("start-up, motor mass at the rim"), P_nom: rhs("start-up, rated force"),
           v_0: rhs("start-up, no-load speed")}
    ratio = (omega_0 / (lam * (omega_0 - omega_n))) ** sp.Rational(1, 3)
    if sp.simplify(ratio - rhs("start-up, slope ratio").subs(rim)) != 0:
        raise AssertionError("the slope ratio does not follow from its step")
    drive = (J_r, n_m, omega_n, v_n)
    slope = rhs("start-up, first characteristic").subs(rim)
    gap = sp.simplify(rhs("start-up, motor speed in the gap").subs(
        {sp.Symbol("beta_1", real=True): slope}).subs(rim))
    return [
        Output("startup_gap_motor_speed", gap, (t_s, lam, P_m, J_r, v_n, omega_0, omega_n),
               ("start-up, motor speed in the gap",), "Motor speed at the rim in the first "
               "stage while the gap is open (from rest, first characteristic).", "m/s"),
        Output("startup_motor_mass", rim[m_d], drive, ("start-up, motor mass at the rim",),
               "Motor rotors of one side reduced to the wheel rim.", "kg"),
        Output("startup_rated_force", rim[P_nom], (P_m, n_m, v_n), ("start-up, rated force",),
               "Rated force of one side at the rim.", "N"),
        Output("startup_no_load_speed", rim[v_0], (v_n, omega_0, omega_n),
               ("start-up, no-load speed",), "No-load speed at the rim.", "m/s"),
        Output("startup_backlash_at_rim", rhs("start-up, backlash at the rim"),
               (phi_b, v_n, omega_n), ("start-up, backlash at the rim",),
               "Backlash phi_b of the fast shaft as a gap at the rim.", "m"),
        Output("startup_first_slope", sp.simplify(rhs("start-up, first characteristic")
                                                  .subs(rim)),
               (lam, P_m, n_m, v_n, omega_0, omega_n), ("start-up, first characteristic",),
               "Slope beta_1 of the first start characteristic of one side.", "N*s/m"),
        Output("startup_slope_ratio", ratio, (lam, omega_0, omega_n),
               ("start-up, slope ratio",), "Ratio q of the slopes of consecutive "
               "characteristics (three steps to the natural one).", "1",
               ((omega_0 - omega_n, "omega_0 > omega_n (the no-load speed above the rated "
                                    "one)"),)),
        Output("startup_link_damping", rhs("start-up, link damping").subs(rim),
               (zeta, c_l) + drive, ("start-up, link damping",),
               "Damping coefficient b of a link.", "N*s/m"),
        Output("startup_rigid_breakaway", rhs("start-up, rigid break-away").subs(rim),
               (lam, P_m, n_m, v_n, m_k, J_r, omega_n, W_f, W_w),
               ("start-up, rigid break-away",), "Acceleration of the rigid drive at "
               "break-away on the first characteristic.", "m/s^2"),
    ]


#: The start-up's curves a scene tabulates: hybrid.STARTUP's output, name, unit, summary.
_CURVES = (("load", "startup_load", "N", "Force F1 + F2 of both links on the crane"),
           ("left_link_load", "startup_link_load", "N", "Force F1 of one link (one side)"),
           ("motor_speed", "startup_motor_speed", "m/s",
            "Speed v1 of one side's motors at the wheel rim"),
           ("crane_speed", "startup_crane_speed", "m/s", "Speed v_k of the crane"))


def tabulated() -> list[TabulatedOutput]:
    """The start-up with backlash of Fig. 12: its phases depend on the data, so a
    start-up scene's module carries each curve as a table, one per backlash of
    the scene's setting ``backlash`` (``<name>_<k>``), the runs of
    ``hybrid.STARTUP`` (``hybrid.scene_runs``)."""
    drive = (P_m, omega_n, omega_0, J_r, n_m, v_n, lam, c_l, zeta, m_k, W_f, W_w)
    return [TabulatedOutput(name, drive, ("Fig. 12",),
                            f"{summary} during the start-up from rest on the stepped "
                            "rheostat start (start steps held for the setting holds), "
                            "backlash in both drives.", unit, partial(scene_runs, output))
            for output, name, unit, summary in _CURVES]
