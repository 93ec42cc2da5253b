"""The derivation steps of paper 003's gear geometry (Form 1, Fig. 10), from the
involute and the generating rack, in the order of Form 1; then the form's own
numbers derived from its data.

Each function adds one section's steps to the ``Derivation`` and returns what
the later sections need; ``build()`` in ``__init__`` calls them in order.
"""
from __future__ import annotations

import mpmath
import sympy as sp

from crane_sym.derivation import Derivation
from crane_sym.mechanics.involute import (inverse_involute_fn, involute_point, rack_space_width, thickness_at_radius,
                                          tip_shift_mp)

from .model import (C_eps, C_sa, F_alpha, F_aw, F_ha, F_k, F_k1, F_k2, F_m, F_x1, F_x2,
                    F_x0, F_z, F_z1, F_z2, Fo, V_atw, V_da1, V_da2, V_eps, V_sa1, V_sa1m,
                    V_samin, V_xp, V_xsum, a_w, alpha, alpha_a1, alpha_a2, alpha_tw,
                    alpha_y, b_ap, c_ap, d_a1, d_a2, dy, dy1, dy2, eps_a, ha, half_pi, m,
                    phi, r, r_b, r_y, s, s_a1, s_y, t_ap, theta, x1, x2, x_min,
                    x_p, x_sum, z, z1, z2)

#: Form 1's data (mm, degrees), copied from 003_5e8a923a75d2f7ba.txt, Form 1, part 1.
FORM1 = {"m": sp.Integer(10), "z1": sp.Integer(25), "z2": sp.Integer(42),
         "a_w": sp.Integer(340), "h_a": sp.Integer(1), "alpha_deg": sp.Integer(20),
         "x2": sp.Integer(0), "k": sp.Integer(0), "z_appendix": sp.Integer(10)}


def inv(a: sp.Expr) -> sp.Expr:
    """tan a − a, the involute function in the form the print uses."""
    return sp.tan(a) - a


def involute_and_rack(d: Derivation) -> None:
    """The involute function, the rack-cut thickness and the thickness at any radius."""
    x, y = involute_point(r_b, phi)
    polar = phi - sp.atan(phi)
    if sp.simplify(sp.tan(polar) - y / x) != 0 or \
            sp.simplify(x ** 2 + y ** 2 - r_b ** 2 * (1 + phi ** 2)) != 0:
        raise ArithmeticError("involute: the polar angle phi - atan(phi) does not hold")
    d.add("involute polar angle", sp.Eq(theta, polar),
          "The involute point (r_b(cos φ + φ sin φ), r_b(sin φ − φ cos φ)) has "
          "tan θ = (tan φ − φ)/(1 + φ tan φ) = tan(φ − atan φ) and radius r_b√(1 + φ²); "
          "both checked by simplification.",
          "The tooth flank is this curve; its polar angle gives the tooth thickness.",
          "The involute")
    d.add("involute function", sp.Eq(theta, inv(alpha_y)),
          "At radius r_y the pressure angle α_y has cos α_y = r_b/r_y = 1/√(1 + φ²), "
          "so φ = tan α_y and θ = tan α_y − α_y = inv α_y.")
    d.add("rack-cut thickness", sp.Eq(s, sp.factor_terms(rack_space_width(m, alpha, x1 * m))),
          "The gear rolls without slip on the rack line x·m above the rack's datum; its "
          "reference thickness equals the rack's space width there, πm/2 widened by "
          "x·m·tan α at each flank.", "Generating by a rack fixes the thickness.",
          "Cutting by a rack")
    d.add("thickness at a radius", sp.Eq(s_y, thickness_at_radius(s, r, r_y, alpha, alpha_y)),
          "The half angle of the tooth at r_y is s/(2r) + inv α − inv α_y, because each "
          "flank's polar angle is inv of its pressure angle.")


def mesh(d: Derivation) -> None:
    """Form 1, part 2: the operating pressure angle and the sum of the shifts."""
    cos_w = m * (z1 + z2) * sp.cos(alpha) / (2 * a_w)
    d.add("Form 1, alpha_tw", sp.Eq(alpha_tw, sp.acos(cos_w)),
          "The line of action is tangent to both base circles, so a_w·cos α_tw = "
          "r_b1 + r_b2 = m(z1 + z2)cos α/2.",
          "The centre distance is given; the angle follows.", "Operating pressure angle")
    w = sp.Symbol("w", positive=True)  # the operating pressure angle in the mesh
    thick = []
    for zi, xi in ((z1, x1), (z2, x2)):
        ri = m * zi / 2
        si = rack_space_width(m, alpha, xi * m)
        thick.append(thickness_at_radius(si, ri, ri * sp.cos(alpha) / sp.cos(w), alpha, w))
    pitch = 2 * sp.pi * (m * z1 / 2 * sp.cos(alpha) / sp.cos(w)) / z1
    solved = sp.solve(sp.Eq(thick[0] + thick[1], pitch), x2)[0]
    total = sp.simplify(x1 + solved)
    expected = (inv(w) - inv(alpha)) * (z1 + z2) / (2 * sp.tan(alpha))
    if sp.simplify(total - expected) != 0:
        raise ArithmeticError("meshing equation: unexpected sum of shifts")
    d.add("Form 1, x_sum", sp.Eq(x_sum, expected.subs(w, alpha_tw)),
          "No backlash: s_w1 + s_w2 equals the operating pitch πd_w1/z1, with "
          "d_wi = m z_i cos α/cos α_tw and s_wi from 'thickness at a radius'; solved "
          "for x1 + x2 and checked against inv α_tw = inv α + 2x_Σ tan α/(z1 + z2).",
          "The meshing equation ties the shifts to the centre distance.", "Sum of shifts")
    inv_w = inv(alpha) + 2 * x_sum * sp.tan(alpha) / (z1 + z2)
    d.add("centre distance from the shifts",
          sp.Eq(a_w, m * (z1 + z2) * sp.cos(alpha) / (2 * sp.cos(inverse_involute_fn(inv_w, 5)))),
          "'Form 1, x_sum' solved for inv α_tw = inv α + 2x_Σ tan α/(z1 + z2), inverted by "
          "the inverse involute, and put into 'Form 1, alpha_tw'.",
          "The designer's inverse problem: the centre distance a chosen pair of shifts needs.")


def tips(d: Derivation) -> None:
    """Form 1, parts 2–3: tip diameters, tip pressure angles, tip thickness, contact ratio."""
    for zi, xi, dyi, da, n in ((z1, x1, dy1, d_a1, "1"), (z2, x2, dy2, d_a2, "2")):
        d.add(f"Form 1, d_a{n}", sp.Eq(da, m * zi + 2 * (ha + xi - dyi) * m),
              "The rack's datum line runs at r + x·m from the centre while cutting; the "
              "full-depth tip lies h_a·m beyond it, less a tip shortening Δy·m.",
              title="Tip diameters" if n == "1" else "")
    for zi, da, aa, n in ((z1, d_a1, alpha_a1, "1"), (z2, d_a2, alpha_a2, "2")):
        d.add(f"Form 1, alpha_a{n}", sp.Eq(aa, sp.acos(m * zi * sp.cos(alpha) / da)),
              "cos α_a = r_b/r_a on the tip circle.",
              title="Tip pressure angles" if n == "1" else "")
    s1 = m * (sp.pi / 2 + 2 * x1 * sp.tan(alpha))
    tip = thickness_at_radius(s1, m * z1 / 2, d_a1 / 2, alpha, alpha_a1)
    form = d_a1 * ((sp.pi / 2 + 2 * x1 * sp.tan(alpha)) / z1 + inv(alpha) - inv(alpha_a1))
    if sp.simplify(tip - form) != 0:
        raise ArithmeticError("tip thickness: the rearranged form does not follow")
    d.add("Form 1, s_a1", sp.Eq(s_a1, form),
          "'thickness at a radius' with s = m(π/2 + 2x1 tan α), r = mz1/2, r_y = d_a1/2, "
          "rearranged; the two forms checked equal by simplification.",
          "A pointed or thin tip breaks; surface-hardened teeth need s_a >= 0.4m.",
          "Tip thickness")
    rb1, rb2 = m * z1 * sp.cos(alpha) / 2, m * z2 * sp.cos(alpha) / 2
    path = rb1 * sp.tan(alpha_a1) + rb2 * sp.tan(alpha_a2) - (rb1 + rb2) * sp.tan(alpha_tw)
    d.add("Form 1, epsilon_alpha", sp.Eq(eps_a, sp.simplify(path / (sp.pi * m * sp.cos(alpha)))),
          "Path of contact √(r_a1² − r_b1²) + √(r_a2² − r_b2²) − a_w sin α_tw, with "
          "√(r_a² − r_b²) = r_b tan α_a and a_w sin α_tw = (r_b1 + r_b2) tan α_tw, over the "
          "base pitch π m cos α.", "At least 1.2 pairs of teeth should share the load.",
          "Transverse contact ratio")


def tooth_limits(d: Derivation) -> None:
    """Form 1's appendix and Fig. 10: the pointed-tip shift and the undercut limit."""
    d_a = z + 2 * (ha + x_p - dy)
    cos_a = z * sp.cos(alpha) / d_a
    condition = (sp.pi / 2 + 2 * x_p * sp.tan(alpha)) / z + inv(alpha) - inv(sp.acos(cos_a))
    d.add("pointed tip", sp.Eq(condition, 0),
          "The tip thickness of 'Form 1, s_a1' for a gear of z teeth and shift x is "
          "d_a times this half angle; it vanishes at the pointed tip.",
          "The largest shift a tooth can take.", "Pointed tip (Form 1 appendix)")
    d.add("pointed tip, h_a = 1", sp.Eq(condition.subs(ha, 1), 0),
          "'pointed tip' for the standard rack h_a = 1, as the appendix writes it.")
    d.add("appendix, c", sp.Eq(c_ap, sp.cos(alpha)), "A name for cos α.")
    d.add("appendix, t", sp.Eq(t_ap, sp.tan(alpha)), "A name for tan α.")
    d.add("appendix, b", sp.Eq(b_ap, inv(alpha)), "'involute function' at the profile angle.")
    d.add("appendix, a", sp.Eq(half_pi, sp.pi / 2), "Half the angular pitch times z.")
    d.add("appendix, Fo", sp.Eq(Fo, cos_a.subs(ha, 1)),
          "cos α_a = r_b/r_a = z cos α/(z + 2(1 + x − Δy)), from 'Form 1, d_a1'.")
    d.add("undercut limit", sp.Eq(x_min, ha - z * sp.sin(alpha) ** 2 / 2),
          "The rack's tip line, (h_a − x)m inside the rolling line, must not pass the "
          "end of the line of action, (mz/2) sin²α inside the reference circle.",
          "Fig. 10's curve 4.", "Undercut")


def _deg(e: sp.Expr) -> sp.Expr:
    return e * 180 / sp.pi


def form1_numbers(d: Derivation) -> dict[str, sp.Expr]:
    """Form 1's results derived from its data (mm), exact where closed, else 40 digits."""
    a = FORM1["alpha_deg"] * sp.pi / 180
    data = {m: FORM1["m"], z1: FORM1["z1"], z2: FORM1["z2"], a_w: FORM1["a_w"],
            ha: FORM1["h_a"], alpha: a, dy1: 0, dy2: 0}
    for sym, value, name in ((F_m, FORM1["m"], "m"), (F_z1, FORM1["z1"], "z1"),
                             (F_z2, FORM1["z2"], "z2"), (F_aw, FORM1["a_w"], "a_w"),
                             (F_ha, FORM1["h_a"], "h_a"), (F_alpha, FORM1["alpha_deg"], "α"),
                             (F_x2, FORM1["x2"], "x2"), (F_k1, FORM1["k"], "k1"),
                             (F_k2, FORM1["k"], "k2"), (F_k, FORM1["k"], "appendix k"),
                             (F_z, FORM1["z_appendix"], "appendix z"),
                             (F_x0, 0, "appendix starting guess")):
        d.add(f"Form 1 data, {name}", sp.Eq(sym, value), "The form's input.",
              title="Form 1's numbers" if name == "m" else "")

    def rhs(label: str) -> sp.Expr:
        return d.step(label).statement.rhs

    atw = rhs("Form 1, alpha_tw").subs(data)
    xs = rhs("Form 1, x_sum").subs(data).subs(alpha_tw, atw)
    d.add("Form 1 data, x1", sp.Eq(F_x1, xs), "The form takes x1 = x_Σ (and x2 = 0).")
    data1 = {**data, x1: xs, x2: 0}
    da1 = rhs("Form 1, d_a1").subs(data1)
    da2 = rhs("Form 1, d_a2").subs(data1)
    aa1 = rhs("Form 1, alpha_a1").subs(data1).subs(d_a1, da1)
    aa2 = rhs("Form 1, alpha_a2").subs(data1).subs(d_a2, da2)
    sa1 = rhs("Form 1, s_a1").subs(data1).subs({d_a1: da1, alpha_a1: aa1})
    eps = rhs("Form 1, epsilon_alpha").subs(data1).subs(
        {alpha_a1: aa1, alpha_a2: aa2, alpha_tw: atw})
    with mpmath.workdps(40):
        xp = sp.Float(tip_shift_mp(FORM1["z_appendix"], mpmath.pi / 9, 1, 0, 0), 40)
    values = {"atw": _deg(atw), "xsum": xs, "da1": da1, "da2": da2, "sa1": sa1,
              "sa1m": sa1 / FORM1["m"], "eps": eps, "xp": xp}
    for sym, key, how in (
            (V_atw, "atw", "'Form 1, alpha_tw' at the data, in degrees."),
            (V_xsum, "xsum", "'Form 1, x_sum' at the data."),
            (V_da1, "da1", "'Form 1, d_a1' at the data, x1 = x_Σ, Δy = 0 [mm]."),
            (V_da2, "da2", "'Form 1, d_a2' at the data, x2 = 0, Δy = 0 [mm]."),
            (V_sa1, "sa1", "'Form 1, s_a1' at the data [mm]."),
            (V_sa1m, "sa1m", "s_a1/m at the data."),
            (V_eps, "eps", "'Form 1, epsilon_alpha' at the data."),
            (V_xp, "xp", "'pointed tip' solved for x at z = 10, α = 20°, h_a = 1, Δy = 0 "
                         "(solved within a bracket to 40 digits).")):
        d.add(f"Form 1 value, {key}", sp.Eq(sym, values[key]), how)
    d.add("Form 1 value, 0.4m", sp.Eq(V_samin, sp.Rational(2, 5) * FORM1["m"]),
          "0.4·m with m = 10 mm.")
    d.add("Form 1 check, s_a1/m >= 0.4", sp.Eq(C_sa, 1 if sp.N(values["sa1m"]) >= 0.4 else 0),
          "1 when the derived s_a1/m reaches 0.4, else 0.")
    d.add("Form 1 check, epsilon_alpha > 1.2", sp.Eq(C_eps, 1 if sp.N(eps) > 1.2 else 0),
          "1 when the derived ε_α exceeds 1.2, else 0.")
    return values
