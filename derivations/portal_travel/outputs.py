"""What the toolkit generates code from for paper 003: a gear designer's
functions (Form 1, Fig. 10) and the largest support load (3)–(4).

Arc cosines whose argument can leave [−1, 1] are ``acos_checked`` (an
impossible mesh or tip raises an error naming the parameter), the involute
is ``involute`` (a stable kernel at small angles), and the tip-thickness shift
is ``tip_shift`` (a bracketed solve): the derived expressions, with each such
function evaluating to the derived one in mpmath.
"""
from __future__ import annotations

import sympy as sp

from crane_sym.derivation import Derivation, Output
from crane_sym.involute import acos_checked, involute, tip_half_angle, tip_shift

from .model import (G_g, G_pch, G_vs, L_max, M_v, a_w, alpha, alpha_a1, alpha_a2,
                    alpha_tw, c_arm, d_a1, d_a2, dy, dy1, dy2, ha, m, psi, sigma, x, x1,
                    x2, x_o, x_sum, z, z1, z2)


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
        Output("max_support_load", load, (psi, G_g, G_pch, G_vs, L_max, x_o, c_arm),
               ("(3)", "(4)"), "Largest vertical load on one portal leg, load case 2v "
               "(reconstructed portal: see the derivation).", "N"),
    ]
