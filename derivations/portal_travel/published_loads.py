"""Paper 003 beyond Form 1, as printed: the z = 10 value of Fig. 10, the support
loads (3)–(4), and Table 1 (its own arithmetic; the start-up cells, which need
the three-mass model of issue 14 item 3, are recorded as not yet checkable).
"""
from __future__ import annotations

import sympy as sp

from crane_sym.published import INTERNAL, RECONSTRUCTED, Cause, PublishedFormula

from .model import G_g, G_pch, G_vs, L_max, M_v, R_max, V_xp, c_arm, psi, psi_cell, x_o
from .published import _number, _printed, _value
from .tables import TABLE1

PORTAL = ("a four-legged portal carrying the vertical load in quarters and the slewing "
          "part's moment as a couple ±M_в/c on the circular rail, each force shared by "
          "two legs (the paper draws no portal and defines neither ψ nor the leg layout)")
HALF_TWICE = Cause("003-moment-halved-twice", "(4) halves the moment ψG_гL_max − G_пчx_o "
                   "that (3) already shares between two legs with 0.5·M_в/c, so together "
                   "they give a leg a quarter of the couple force M_в/c; the reconstructed "
                   "portal gives a half")
INPUTS = Cause("003-table1-inputs", "the hold times per start step are settings of "
               "the 'Dinamo' start panel, inputs of the start-up model rather than results")
STARTUP = Cause("003-startup-not-built", "the cell is an output of the three-mass "
                "start-up model with backlash (issue 14, item 3), which waits for the "
                "piecewise-linear machinery; only the table's own arithmetic is checked")

FIG10 = [
    _value("Fig. 10, curve 1, z = 10", "Коэффициент смещения, реализующий заострение зуба "
           "на диаметре вершин, при z=10, равен 0,7 (см. также кривую 1 на рис.10)",
           V_xp, "0,7", "the text after Form 1, read off curve 1 of Fig. 10"),
]

LOADS = [
    _printed("(3)", r"= 0,25(v,/Gr + Ст + Сж) + 0,5^. с (3)",
             sp.Eq(R_max, sp.Rational(1, 4) * (psi * G_g + G_pch + G_vs)
                   + sp.Rational(1, 2) * M_v / c_arm),
             "rebuilt from the text's definitions: R_max = 0.25(ψG_г + G_пч + G_вс) + "
             "0.5·M_в/c; the OCR lost the left side and reads ψ as 'v,/'",
             reconstructed=True, basis=RECONSTRUCTED, basis_note=PORTAL),
    _printed("(4)", r"М = 0,5(yGrL - G x ), (4) в ’ VY Г max ПЧ oy’ v '",
             sp.Eq(M_v, sp.Rational(1, 2) * (psi * G_g * L_max - G_pch * x_o)),
             "rebuilt: M_в = 0.5(ψ·G_г·L_max − G_пч·x_o); the OCR reads ψ as 'y' and "
             "puts the subscripts on the next line", reconstructed=True,
             basis=RECONSTRUCTED, basis_note=PORTAL, cause=HALF_TWICE),
]


def _table1() -> list[PublishedFormula]:
    records = []
    for row in TABLE1:
        gap = row["backlash"]
        value, tol = _number(row["psi"])
        records.append(_printed(
            f"Table 1, psi, backlash {gap}", row["psi"], sp.Eq(psi_cell, value),
            f"dynamic coefficient of the row with backlash {gap} rad, F_ср = 150 kN",
            compare_to=f"Table 1, psi, backlash {gap}", tolerance=tol, basis=INTERNAL,
            basis_note="the table's F_max over its F_ср = 150 kN"))
        records.append(_printed(
            f"Table 1, hold times, backlash {gap}", " ".join(row["hold_s"]), None,
            f"Table 1, row with backlash {gap} rad [s]",
            not_checkable="inputs of the start-up model (the start panel's settings)",
            basis=INTERNAL, basis_note="the table's inputs, nothing derived",
            cause=INPUTS))
        for what, cells in (("accelerations", row["accel"]), ("F_max", (row["F_max_kN"],))):
            records.append(_printed(
                f"Table 1, {what}, backlash {gap}", " ".join(cells), None,
                f"Table 1, row with backlash {gap} rad",
                not_checkable="needs the three-mass start-up model with backlash, not "
                "built yet (issue 14, item 3)", basis=INTERNAL,
                basis_note="the start-up model is not built yet", cause=STARTUP))
    return records


TEXT = [
    _printed(f"text, psi = {text} ({where})", f"коэффициент динамичности у = {text}",
             sp.Eq(psi_cell, _number(text)[0]), f"the text before Table 1 ({where})",
             compare_to=f"Table 1, psi, backlash {gap}", tolerance=_number(text)[1],
             basis=INTERNAL, basis_note="the text against Table 1's F_max/F_ср")
    for text, gap, where in (("1,6", "0", "the start-up value of [2], no backlash"),
                             ("2,6", "2pi", "backlash of one turn of the fast shaft"))]

PUBLISHED_LOADS = FIG10 + LOADS + _table1() + TEXT
