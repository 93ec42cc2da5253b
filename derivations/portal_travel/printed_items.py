"""The inventory of paper 003's print (``003_5e8a923a75d2f7ba.txt``): what the
audit owes a verdict, listed from the print, not from the records.

Equations (1)–(4) ((1)–(2) lost in the OCR); the lines of the Mathcad Form 1
and of its appendix, each a formula or a number it computes; the z = 10 value
read off Fig. 10; the 24 cells of Table 1 (its F_ср = 150 kN is the heading of
a column, not a cell); the two dynamic coefficients the text states before
Table 1; the 18 cells of Table 2 and the 8 of Table 3 (``tables.py``, as
printed). The text's other numbers (30 and 60 kN of resistance, the motor's
13 kW and 935 min⁻¹) are inputs, not results.
"""
from __future__ import annotations

from crane_sym.published import PrintedItem, numbered

from .tables import TABLE1, TABLE2, TABLE3

#: Form 1 and its appendix, line by line as printed (a number it computes is a
#: line of its own).
_FORM1 = ("m", "z1", "z2", "a_w", "h_a", "alpha", "alpha_tw", "alpha_tw = 22.2 deg",
          "x_sum", "x_sum = 0.527", "x1", "x2", "k1", "k2", "d_a1", "d_a1 = 280.536",
          "d_a2", "d_a2 = 440", "alpha_a1", "alpha_a2", "0.4m = 4 mm", "s_a1",
          "s_a1 = 5.231", "s_a1/m = 0.523", "s_a1/m >= 0.4", "epsilon_alpha",
          "epsilon_alpha > 1.2", "epsilon_alpha = 1.54")
_APPENDIX = ("c", "t", "b", "k", "z", "a", "starting guess", "Fo", "equation",
             "Find(x1) = 0.7")


def _table1() -> list[PrintedItem]:
    items = []
    for row in TABLE1:
        gap = row["backlash"]
        items += [PrintedItem(f"Table 1, backlash {gap}, hold time {k}: {cell}",
                              "table cell", (f"Table 1, hold times, backlash {gap}",))
                  for k, cell in enumerate(row["hold_s"], 1)]
        items += [PrintedItem(f"Table 1, backlash {gap}, acceleration {k}: {cell}",
                              "table cell", (f"Table 1, acceleration {k}, backlash {gap}",))
                  for k, cell in enumerate(row["accel"], 1)]
        items.append(PrintedItem(f"Table 1, backlash {gap}, F_max: {row['F_max_kN']}",
                                 "table cell", (f"Table 1, F_max, backlash {gap}",)))
        items.append(PrintedItem(f"Table 1, backlash {gap}, psi: {row['psi']}", "table cell",
                                 (f"Table 1, psi, backlash {gap}",
                                  f"Table 1, psi against the model, backlash {gap}")))
    return items


PRINTED_ITEMS = numbered(1, 4) + [
    PrintedItem(f"Form 1, {line}", "unnumbered formula", (f"Form 1, {line}",))
    for line in _FORM1] + [
    PrintedItem(f"Form 1 appendix, {line}", "unnumbered formula",
                (f"Form 1 appendix, {line}",)) for line in _APPENDIX] + [
    PrintedItem("the text after Form 1: the shift at z = 10 is 0,7 (Fig. 10, curve 1)",
                "number in the text", ("Fig. 10, curve 1, z = 10",))] + _table1() + [
    PrintedItem(f"the text before Table 1: ψ = {text}", "number in the text", (label,))
    for text, label in (("1,6", "text, psi = 1,6 (the start-up value of [2], no backlash)"),
                        ("2,6", "text, psi = 2,6 (backlash of one turn of the fast shaft)"))
] + [
    PrintedItem(f"Table 2, {case}, {unit}: {cell}", "table cell",
                (f"Table 2, {case}, {unit}",))
    for case, cells in TABLE2.items()
    for unit, cell in zip(("vertical pressure, %", "transverse force, kN"), cells)] + [
    PrintedItem(f"Table 3, {load}, {variant}, {stat}: {cell}", "table cell",
                (f"Table 3, {load}, {variant}, {stat}",))
    for (load, variant), cells in TABLE3.items() for stat, cell in zip(("m_R", "σ_R"), cells)]
