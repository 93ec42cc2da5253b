"""Paper 003's equations (1)–(2), lost in the OCR, and its Tables 2–3, as printed.

(1)–(2) (``003_5e8a923a75d2f7ba.txt``, "движение системы описывается
уравнениями: … (1)" and "… записываются в следующем виде: (2)"): the OCR keeps
only debris («Щ md \\mdi тк J тк ' тк W8»); each is reconstructed from the
text's definitions (F, P_d, C_пр, α of the first stage; F1, F2, P_p1, v_d,
v_0, λ, P_c of the second) and labelled so. Tables 2–3 are measurements of two
cranes' support loads: the paper derives nothing from them, so each cell's
record says so (``tables.py`` holds the cells, as printed).
"""
from __future__ import annotations

import sympy as sp

from crane_sym.published import RECONSTRUCTED, Cause, PublishedFormula

from .model import F_1, W_f, W_w, b_l, beta_k, c_l, m_d, m_k, s_b, t, v_0, x_1, x_2, x_k
from .published import _printed
from .tables import TABLE2, TABLE3

_LOST = ("the system its text defines, rebuilt (startup.py, model text) because the OCR "
         "lost the print; the reconstruction is checked against the model built from the "
         "same definitions, so it shows the two agree, not that the print was this")


def _link(x_i: sp.Expr) -> sp.Expr:
    """F_i: the link's stiffness and damping once its flank is closed."""
    return c_l * (x_i - x_k - s_b) + b_l * (x_i - x_k).diff(t)


LOST = [
    _printed("(1)", r"(1)", sp.Eq(m_d * x_1.diff(t, 2), beta_k * (v_0 - x_1.diff(t)) - F_1),
             "reconstructed: the first stage, m_d·dv_d/dt = P_d − F with the motor force "
             "P_d = β(v_0 − v_d) linear in the speed ('Тяговая сила двигателя линейно "
             "зависит от скорости'); the OCR kept only the number",
             compare_to="start-up, first stage", reconstructed=True,
             basis=RECONSTRUCTED, basis_note=_LOST),
    _printed("(2)", r"Щ md \mdi тк J тк ' тк W8 (2) V",
             sp.Eq(m_k * x_k.diff(t, 2), _link(x_1) + _link(x_2) - W_w - W_f),
             "reconstructed: the second stage's crane equation, m_к·dv_к/dt = F1 + F2 − "
             "P_c, with F_i = C_пр(x_i − x_к − s) + α(ẋ_i − ẋ_к) and P_c = W_w + W_f; the "
             "OCR kept «md», «тк» (m_к) and «W8»", compare_to="start-up, crane",
             reconstructed=True, basis=RECONSTRUCTED, basis_note=_LOST),
]

TABLE2_MEASURED = Cause(
    "003-table2-measurements", "Table 2's cells are the largest changes of the support "
    "loads measured in the programme tests of the crane КПП-10/30; the paper gives no model "
    "of those load cases, so nothing derives or checks them")
TABLE3_MEASURED = Cause(
    "003-table3-measurements", "Table 3's cells are the mean and standard deviation of the "
    "support loads measured in the service tests of the crane КПП-10/32; the paper fits the "
    "normal law to them without printing the histograms, so nothing checks them")
_UNITS = ("vertical pressure, %", "transverse force, kN")
_STATS = ("m_R", "σ_R")


def _measured() -> list[PublishedFormula]:
    records = []
    for case, cells in TABLE2.items():
        for unit, cell in zip(_UNITS, cells):
            records.append(_printed(
                f"Table 2, {case}, {unit}", cell, None,
                f"Table 2 (programme tests of the КПП-10/30), {case}: {unit}",
                not_checkable="a measurement: nothing in the paper derives it",
                cause=TABLE2_MEASURED))
    for (load, variant), cells in TABLE3.items():
        for stat, cell in zip(_STATS, cells):
            records.append(_printed(
                f"Table 3, {load}, {variant}, {stat}", cell, None,
                f"Table 3 (service tests of the КПП-10/32), {load}, {variant}: {stat}",
                not_checkable="a statistic of measurements: nothing in the paper derives "
                "it", cause=TABLE3_MEASURED))
    return records


PUBLISHED_MEASURED = LOST + _measured()
