"""The inventory of paper 000's print (``000_4ef6efc8a81a3b06.txt``): what the
audit owes a verdict, listed from the print, not from the records.

Equations (1)–(14) are numbered; the two initial conditions printed between
(9) and (10) are unnumbered formulas. The paper has no table and states no
number as a result.
"""
from __future__ import annotations

from crane_sym.published import PrintedItem, numbered

PRINTED_ITEMS = numbered(1, 14) + [
    PrintedItem("initial conditions, x_2 - x_1 = 0 (between (9) and (10))",
                "unnumbered formula", ("initial stretch",)),
    PrintedItem("initial conditions, ẋ_2 - ẋ_1 = 0 (between (9) and (10))",
                "unnumbered formula", ("initial relative velocity",)),
]
