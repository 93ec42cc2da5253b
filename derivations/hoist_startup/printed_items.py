"""The inventory of paper 002's print (``002_f8509f3826f601de.txt``): what the
audit owes a verdict, listed from the print, not from the records.

Equations (1)–(66); the unnumbered formulas of its text between them; the 15
cells of Table 1 and the 80 of Table 2 (``tables.py``, as printed).
"""
from __future__ import annotations

from crane_sym.published import PrintedItem, numbered

from .tables import (TABLE1, TABLE2, TABLE2_BLOCKS, TABLE_COLUMNS, table1_label,
                     table2_label)

#: The unnumbered formulas of the text, where each stands, and the records of each
#: (a print judged two ways has two).
_UNNUMBERED = {"S(t) after (31)": (), "Y in (33)–(49)": (), "m Ω² = C (after (35))": (),
               "x_ст (after (35))": (), "x_ст (before (45))": (),
               "half period (before (47))": (),
               "x_max for θ ≥ π/Ω (before (47))": ("x_max for θ ≥ π/Ω, in x_ст",),
               "K_дин normalisations": (),
               "Q̈ ≡ 0 (before (60))": ("Q̈ ≡ 0 at τ_0",), "t3* (after (66))": (),
               "max k̃3 (after (66))": (), "t4* (after (66))": (),
               "max k̃4 (after (66))": ()}

PRINTED_ITEMS = numbered(1, 66) + [
    PrintedItem(text, "unnumbered formula", (text, *more))
    for text, more in _UNNUMBERED.items()] + [
    PrintedItem(table1_label(i, frac) + f": {cell}", "table cell",
                (table1_label(i, frac),))
    for i, row in TABLE1.items() for frac, cell in zip(TABLE_COLUMNS, row)] + [
    PrintedItem(table2_label(i, v, tn, frac) + f": {cell}", "table cell",
                (table2_label(i, v, tn, frac),))
    for i, blocks in TABLE2.items() for (v, tn), row in zip(TABLE2_BLOCKS, blocks)
    for frac, cell in zip(TABLE_COLUMNS, row)]
