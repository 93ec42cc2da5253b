"""Form 1 of paper 003 as printed: every Mathcad line, its OCR text verbatim as
``latex``, its transcription, and the form's printed numbers.

The OCR flattened the Mathcad layout (fractions split over lines, subscripts
lost); a line rebuilt from the text around it is marked ``reconstructed``.
"""
from __future__ import annotations

from decimal import Decimal

import sympy as sp

from crane_sym.readings import Meaning, Scaled

from crane_sym.published import (DEFINITION, INTERNAL, LOST_MARK, SYMBOL_FOR_ANOTHER,
                                 Cause, Convention, PublishedFormula, printed)

from .model import (C_eps, C_sa, F_alpha, F_aw, F_ha, F_k, F_k1, F_k2, F_m, F_x1, F_x2,
                    F_x0, F_z, F_z1, F_z2, Fo, V_atw, V_da1, V_da2, V_eps, V_sa1, V_sa1m,
                    V_samin, V_xp, V_xsum, PAPER, a_w, alpha, alpha_a1, alpha_a2,
                    alpha_tw, b_ap, c_ap, d_a1, d_a2, dy, dy1, dy2, eps_a, ha, half_pi, k,
                    k1, k2, m, s_a1, t_ap, x1, x2, x_p, x_sum, z, z1, z2)

FORM = "Form 1"


def _printed(label: str, latex: str, relation: sp.Eq | None, note: str = "",
             **kwargs) -> PublishedFormula:
    """A record whose ``latex`` is the OCR'd text of the print (Mathcad, tables)."""
    return printed(PAPER, label, latex, relation, note, verbatim=True, **kwargs)


def _number(text: str) -> tuple[sp.Rational, float]:
    """A printed number and half a unit of its last digit, relative to it."""
    value = Decimal(text.replace(",", "."))
    half = Decimal(5).scaleb(value.as_tuple().exponent - 1)
    return sp.Rational(*value.as_integer_ratio()), float(half / abs(value))


def _value(label: str, latex: str, symbol: sp.Symbol, text: str, note: str,
           **kwargs) -> PublishedFormula:
    """A number the form prints, against the value derived from its data."""
    value, tolerance = _number(text)
    step = {V_atw: "atw", V_xsum: "xsum", V_da1: "da1", V_da2: "da2", V_sa1: "sa1",
            V_sa1m: "sa1m", V_eps: "eps", V_xp: "xp", V_samin: "0.4m"}[symbol]
    return _printed(label, latex, sp.Eq(symbol, value), note, tolerance=tolerance,
                    compare_to=f"Form 1 value, {step}", **kwargs)


def _appendix(name: str, latex: str, relation: sp.Eq, note: str = "",
              **kwargs) -> PublishedFormula:
    """A definition line of the form's appendix, against its step."""
    return _printed(f"{FORM} appendix, {name}", latex, relation, note,
                    compare_to=f"appendix, {name}", **kwargs)


def _data(label: str, latex: str, symbol: sp.Symbol, value: int, note: str = "",
          **kwargs) -> PublishedFormula:
    """An input line of the form: restated, it is the data."""
    name = label.split(", ", 1)[1].replace("alpha", "α")
    step = f"Form 1 data, {'appendix ' if 'appendix' in label else ''}{name}"
    return _printed(label, latex, sp.Eq(symbol, value), note or "an input of the form",
                    basis=DEFINITION, basis_note="an input of Form 1", compare_to=step,
                    **kwargs)


K_SIGN = Cause("003-shortening-sign", "Form 1 adds its tooth 'shortening coefficient' k "
               "to the tip height (+k in d_a and in the appendix's Fo), so a shortened "
               "tooth needs k < 0, where GOST 16532 subtracts Δy >= 0; with k = 0, as "
               "used, no printed value changes")
EPS_COMMA = Cause("003-eps-decimal-comma", "the printed ε_α = 154 has lost its decimal "
                  "comma (1,54): the form itself requires ε_α > 1,2")


def _tip(zi, xi, kk) -> sp.Expr:
    return m * zi + 2 * (ha + xi + kk) * m


_cos_w = m * (z1 + z2) * sp.cos(alpha) / (2 * a_w)
_inv = lambda a: sp.tan(a) - a  # noqa: E731
_Fo = z * sp.cos(alpha) / (z + 2 * (1 + x_p + k))
_root_eq = ((sp.pi / 2 + 2 * x_p * sp.tan(alpha)) / z + (sp.tan(alpha) - alpha)
             + sp.acos(_Fo) - sp.tan(sp.acos(_Fo)))

def _form_x_sum() -> sp.Expr:
    """x_Σ by the form's own two lines (α_tw, x_Σ) at the form's data."""
    data = {m: 10, z1: 25, z2: 42, a_w: 340, alpha: sp.pi / 9}
    atw = sp.acos(_cos_w.subs(data))
    return ((sp.tan(atw) - atw - sp.tan(alpha) + alpha) * (z1 + z2)
            / (2 * sp.tan(alpha))).subs(data)


DATA = [
    _data(f"{FORM}, m", "Модуль зуба, мм m:=10", F_m, 10),
    _data(f"{FORM}, z1", "Число зубьев шестерни z1:=25", F_z1, 25),
    _data(f"{FORM}, z2", "Число зубьев колеса z2:=42", F_z2, 42),
    _data(f"{FORM}, a_w", "Межосевое расстояние, мм aw:=340", F_aw, 340),
    _data(f"{FORM}, h_a", "Коэффициент высоты делительной головки зуба исходного ha:=1 "
          "контура", F_ha, 1),
    _data(f"{FORM}, alpha", "Угол исходного контура a := 20-", F_alpha, 20,
          "the OCR reads α as 'a' and the degree unit as '-': α := 20·deg",
          reconstructed=True),
]

PART2 = [
    _printed(f"{FORM}, alpha_tw", "-(1 + z2^-cos( а) / atw := acos / 2-a„",
             sp.Eq(alpha_tw, sp.acos(_cos_w)),
             "rebuilt from the three OCR fragments of the Mathcad fraction: "
             "α_tw := acos(m·(z1 + z2)·cos(α)/(2·a_w))", reconstructed=True),
    _value(f"{FORM}, alpha_tw = 22.2 deg", "180 „„ „ atw' “22'2", V_atw, "22.2",
           "read as α_tw·180/π = 22.2 (the OCR lost the operators)", reconstructed=True),
    _printed(f"{FORM}, x_sum", "Коэффициент суммы смещений x£ := (tan(atw) - atw - "
             "tan(a) + a)' (z1 + z2) 2-tan( a)",
             sp.Eq(x_sum, (sp.tan(alpha_tw) - alpha_tw - sp.tan(alpha) + alpha)
                   * (z1 + z2) / (2 * sp.tan(alpha))),
             "the fraction's denominator 2·tan(α) stands on the next OCR line",
             reconstructed=True),
    _value(f"{FORM}, x_sum = 0.527", "xs = 0.527", V_xsum, "0.527",
           "x_Σ as printed; the OCR reads x_Σ as 'xs'", reconstructed=True),
    _data(f"{FORM}, x1", "Коэффициент смещения у шестерни по опыту конструирования "
          "x1 := x^", F_x1, _form_x_sum(),
          "x1 := x_Σ by design experience (the whole shift on the pinion); the OCR "
          "reads x_Σ as 'x^'; transcribed as the form's own x_Σ line at its data",
          reconstructed=True),
    _data(f"{FORM}, x2", "Коэффициент смещения у колеса x2 := С", F_x2, 0,
          "the OCR reads 0 as 'С'; d_a2 = 440 = m·z2 + 2·h_a·m confirms x2 = 0",
          reconstructed=True),
    _data(f"{FORM}, k1", "шестерни: k1:=0", F_k1, 0),
    _data(f"{FORM}, k2", "колеса k2:=0", F_k2, 0),
    _printed(f"{FORM}, d_a1", "da1 := m z^ + 2 (ha + x1 + ki) m",
             sp.Eq(d_a1, _tip(z1, x1, k1)), "the OCR reads z1 as 'z^' and k1 as 'ki'",
             reconstructed=True, conventions=(Convention(
                 "k1 is the signed change of the tip height, −Δy1",
                 Meaning(((k1, -dy1),)), SYMBOL_FOR_ANOTHER),), cause=K_SIGN),
    _value(f"{FORM}, d_a1 = 280.536", "da1 = 280.536", V_da1, "280.536", "mm"),
    _printed(f"{FORM}, d_a2", "da2 := mz2 + 2-(ha + x2 + k2)-m",
             sp.Eq(d_a2, _tip(z2, x2, k2)), "'-' is the OCR's multiplication dot",
             conventions=(Convention("k2 is the signed change of the tip height, −Δy2",
                                     Meaning(((k2, -dy2),)), SYMBOL_FOR_ANOTHER),),
             cause=K_SIGN, reconstructed=True),
    _value(f"{FORM}, d_a2 = 440", "da2 = 440", V_da2, "440", "mm"),
]

PART3 = [
    _printed(f"{FORM}, alpha_a1", "1 ( cos (а) ^ aa1 := acos I m-z^- ... da1 ) у",
             sp.Eq(alpha_a1, sp.acos(m * z1 * sp.cos(alpha) / d_a1)),
             "rebuilt: α_a1 := acos(m·z1·cos(α)/d_a1)", reconstructed=True),
    _printed(f"{FORM}, alpha_a2", "aa2 := acos I m^-- KO) ^ da2 ) у",
             sp.Eq(alpha_a2, sp.acos(m * z2 * sp.cos(alpha) / d_a2)),
             "rebuilt: α_a2 := acos(m·z2·cos(α)/d_a2)", reconstructed=True),
    _value(f"{FORM}, 0.4m = 4 mm", "Проверка толщины зуба на окружности вершин шестерни: "
           "Sa1>0.4m=4 мм", V_samin, "4", "the required least tip thickness",
           basis=INTERNAL, basis_note="the form's arithmetic 0.4·m with m = 10 mm"),
    _printed(f"{FORM}, s_a1", "sa1 := d a1' 0.5-тс + 2- x1- tan(a) z1 tan(a) - a - "
             "(tan(aa1) - aa1)",
             sp.Eq(s_a1, d_a1 * ((sp.pi / 2 + 2 * x1 * sp.tan(alpha)) / z1
                                 + sp.tan(alpha) - alpha - (sp.tan(alpha_a1) - alpha_a1))),
             "rebuilt: s_a1 := d_a1·((0.5π + 2·x1·tan(α))/z1 + tan(α) − α − "
             "(tan(α_a1) − α_a1))", reconstructed=True),
    _value(f"{FORM}, s_a1 = 5.231", "sa1 = 5.231", V_sa1, "5.231", "mm"),
    _value(f"{FORM}, s_a1/m = 0.523", "sa1 / m = 0.523", V_sa1m, "0.523",
           "the OCR splits 'sa1 / m' over two lines"),
    _printed(f"{FORM}, s_a1/m >= 0.4", "что соответствует требуемому нормативному "
             "значению 0,4 для поверхностной закалки", sp.Eq(C_sa, 1),
             "the claim s_a1/m = 0.523 >= 0.4, as 1 = true", basis=INTERNAL,
             compare_to="Form 1 check, s_a1/m >= 0.4",
             basis_note="the form's claim against its own derived s_a1/m"),
    _printed(f"{FORM}, epsilon_alpha", "zrtan(aa1) + z2-tan(aa2) - ( + z2)tan(atw) / 2-n",
             sp.Eq(eps_a, (z1 * sp.tan(alpha_a1) + z2 * sp.tan(alpha_a2)
                           - (z1 + z2) * sp.tan(alpha_tw)) / (2 * sp.pi)),
             "the OCR lost z1 in '( + z2)' and reads π as 'n'", reconstructed=True),
    _printed(f"{FORM}, epsilon_alpha > 1.2", "sa > 1,2", sp.Eq(C_eps, 1),
             "the requirement ε_α > 1.2, as 1 = true", basis=INTERNAL,
             compare_to="Form 1 check, epsilon_alpha > 1.2",
             basis_note="the form's requirement against its own derived ε_α"),
    _printed(f"{FORM}, epsilon_alpha = 1.54", "sa = 154", sp.Eq(V_eps, 154),
             "ε_α as printed (the OCR reads ε as 's')", tolerance=_number("154")[1],
             reconstructed=True,
             compare_to="Form 1 value, eps",
             conventions=(Convention("a decimal comma lost: ε_α = 1,54",
                                     Scaled(sp.Rational(1, 100)), LOST_MARK),),
             cause=EPS_COMMA),
]

APPENDIX = [
    _appendix("c", "c := cos(a)", sp.Eq(c_ap, sp.cos(alpha)),
             basis=DEFINITION, basis_note="a name the appendix gives"),
    _appendix("t", "t := tan( a)", sp.Eq(t_ap, sp.tan(alpha)),
             basis=DEFINITION, basis_note="a name the appendix gives"),
    _appendix("b", "b := t - a", sp.Eq(b_ap, sp.tan(alpha) - alpha),
             "b = inv α, with t := tan α; the OCR reads α as 'a'", reconstructed=True),
    _data(f"{FORM} appendix, k", "k:=0", F_k, 0),
    _data(f"{FORM} appendix, z", "z:=10", F_z, 10),
    _appendix("a", "a := 0.5n", sp.Eq(half_pi, sp.pi / 2),
             "the OCR reads π as 'n'; the name is printed like α's 'a'",
             reconstructed=True, basis=DEFINITION, basis_note="a name the appendix gives"),
    _data(f"{FORM} appendix, starting guess", "Начальное значение переменной X:=0", F_x0, 0,
          "Mathcad's Find needs a starting value; the toolkit's bracketed solver of the "
          "pointed-tip shift needs none"),
    _appendix("Fo", "Fo(x) := ... z + 2- (1 + x + k)",
             sp.Eq(Fo, _Fo), "rebuilt: Fo(x) := z·c/(z + 2·(1 + x + k)), c := cos α",
             reconstructed=True, conventions=(Convention(
                 "k is the signed change of the tip height, −Δy",
                 Meaning(((k, -dy),)), SYMBOL_FOR_ANOTHER),), cause=K_SIGN),
    _printed(f"{FORM} appendix, equation", "Решаемое уравнение a + 2 x11 + b + "
             "acos(Fo(x1)) - tan(acos (Fo(x1))) = 0 z",
             sp.Eq(_root_eq, 0),
             "rebuilt: (a + 2·x1·t)/z + b + acos(Fo(x1)) − tan(acos(Fo(x1))) = 0 with "
             "a := 0.5π, t := tan α, b := t − α substituted as the appendix defines them",
             reconstructed=True,
             compare_to="pointed tip, h_a = 1", conventions=(Convention(
                 "k is the signed change of the tip height, −Δy",
                 Meaning(((k, -dy),)), SYMBOL_FOR_ANOTHER),), cause=K_SIGN),
    _value(f"{FORM} appendix, Find(x1) = 0.7", "Find(x1)=0.7", V_xp, "0.7",
           "the appendix's root at z = 10"),
]

PUBLISHED = DATA + PART2 + PART3 + APPENDIX
