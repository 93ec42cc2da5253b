"""Paper 003 beyond Form 1, as printed: the z = 10 value of Fig. 10, the support
loads (3)–(4), and Table 1 (its own arithmetic, and its start-up cells against the
three-mass model with backlash of ``startup.py``).
"""
from __future__ import annotations

import sympy as sp

from crane_sym.published import (CHOSEN, DEFINITION, INTERNAL, RECONSTRUCTED, Cause,
                                 PublishedFormula)

from .model import (F_peak, G_g, G_pch, G_vs, L_max, M_v, R_max, V_xp, a_cell, c_arm, psi,
                    psi_cell, x_o)
from .published import _number, _printed, _value
from .tables import TABLE1

PORTAL = ("a four-legged portal carrying the vertical load in quarters and the slewing "
          "part's moment as a couple ±M_в/c on the circular rail, each force shared by "
          "two legs: a layout built to reproduce (3), since the paper draws no portal and "
          "defines neither ψ nor the leg layout; (3) is adopted, not checked")
MOMENT = ("(4) against the text's own definition of M_в, 'the moment of the loads acting in "
          "the vertical plane' (момент от нагрузок, действующих в вертикальной плоскости): "
          "about the slewing axis, ψG_г at the reach L_max against G_пч at x_o")
HALF_TWICE = Cause("003-moment-halved-twice", "(4) prints half of the moment ψG_гL_max − "
                   "G_пчx_o that the text defines M_в to be, and (3) shares M_в/c between two "
                   "legs with its own 0.5, so together they give a leg a quarter of the "
                   "couple force")
INPUTS = Cause("003-table1-inputs", "the hold times per start step are settings of "
               "the 'Dinamo' start panel, inputs of the start-up model rather than results")
STARTUP_MODEL = ("the three-mass start-up of startup.py (Fig. 11), built from the text's "
                 "definitions because (1)–(2) are lost in the OCR; the rotor inertia, travel "
                 "speed, λ, stiffness, damping and crane mass are not printed and were chosen, "
                 "not fitted (model text); the band they span over the whole box of their "
                 "plausible ranges (startup.PLAUSIBLE), every corner and an optimiser inside "
                 "it, decides")
STARTUP = Cause("003-startup-unstated-parameters", "the start-up model needs six parameters "
                "the paper does not state (rotor inertia, travel speed, λ, stiffness, damping, "
                "crane mass); with the chosen ones it gives F_max = 242, 269, 288 kN (ψ = "
                "1.62, 1.79, 1.92) for backlash 0, π, 2π, growing by 19 % where Table 1 prints "
                "62 %, so each printed load is judged against the band the six parameters "
                "span over their plausible ranges, not against the chosen values")
ACCEL = Cause("003-startup-accelerations", "the model's crane gains about 0.37, 0.37, 0.11 "
              "m/s² per start step whatever the backlash (the backlash changes the peak load, "
              "not the speed gained), where Table 1 prints 0.25, 0.32, 0.21 without backlash "
              "and a first step that grows with the backlash (0.45, 0.54); the paper states "
              "neither its start characteristics nor how it measures an acceleration per "
              "step, so each printed value is judged against the band the unstated "
              "parameters span")

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
             reconstructed=True, basis=DEFINITION, basis_note=PORTAL),
    _printed("(4)", r"М = 0,5(yGrL - G x ), (4) в ’ VY Г max ПЧ oy’ v '",
             sp.Eq(M_v, sp.Rational(1, 2) * (psi * G_g * L_max - G_pch * x_o)),
             "rebuilt: M_в = 0.5(ψ·G_г·L_max − G_пч·x_o); the OCR reads ψ as 'y' and "
             "puts the subscripts on the next line", reconstructed=True,
             basis=INTERNAL, basis_note=MOMENT, cause=HALF_TWICE),
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
        value, tol = _number(row["F_max_kN"])
        records.append(_printed(
            f"Table 1, F_max, backlash {gap}", row["F_max_kN"], sp.Eq(F_peak, value),
            f"Table 1, row with backlash {gap} rad: largest longitudinal load [kN]",
            compare_to=f"start-up model, F_max, backlash {gap}", tolerance=tol,
            kind=CHOSEN, basis=RECONSTRUCTED, basis_note=STARTUP_MODEL, cause=STARTUP))
        value, tol = _number(row["psi"])
        records.append(_printed(
            f"Table 1, psi against the model, backlash {gap}", row["psi"],
            sp.Eq(psi_cell, value), f"Table 1, row with backlash {gap} rad",
            compare_to=f"start-up model, psi, backlash {gap}", tolerance=tol,
            kind=CHOSEN, basis=RECONSTRUCTED, basis_note=STARTUP_MODEL, cause=STARTUP))
        for k, cell in enumerate(row["accel"], 1):
            value, tol = _number(cell)
            records.append(_printed(
                f"Table 1, acceleration {k}, backlash {gap}", cell, sp.Eq(a_cell, value),
                f"Table 1, row with backlash {gap} rad, start step {k} [m/s²]",
                compare_to=f"start-up model, acceleration {k}, backlash {gap}",
                tolerance=tol, kind=CHOSEN, basis=RECONSTRUCTED,
                basis_note=STARTUP_MODEL, cause=ACCEL))
    return records


TEXT = [
    _printed(f"text, psi = {text} ({where})", f"коэффициент динамичности у = {text}",
             sp.Eq(psi_cell, _number(text)[0]), f"the text before Table 1 ({where})",
             compare_to=f"Table 1, psi, backlash {gap}", tolerance=_number(text)[1],
             basis=INTERNAL, basis_note="the text against Table 1's F_max/F_ср")
    for text, gap, where in (("1,6", "0", "the start-up value of [2], no backlash"),
                             ("2,6", "2pi", "backlash of one turn of the fast shaft"))]

PUBLISHED_LOADS = FIG10 + LOADS + _table1() + TEXT
