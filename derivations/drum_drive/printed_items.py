"""The inventory of paper 004's print (``004_f118c513e0426caf.txt``): what the
audit owes a verdict, listed from the print, not from the records.

Equations (1)–(21) are numbered; the example's initial state is an unnumbered
formula; the example's one result is the amplitude read off Fig. 3 ("does not
exceed 10 mm"). The example's inputs (I_1 = 13 kg·m², …, t_i = 10 s) are
inputs, not results, and the paper has no table.
"""
from __future__ import annotations

from crane_sym.published import PrintedItem, numbered

PRINTED_ITEMS = numbered(1, 21) + [
    PrintedItem("example, z(0) = 0; y(0) = 0; … (the initial state)", "unnumbered formula",
                ("initial state",)),
    PrintedItem("Fig. 3, the drum shaft's amplitude does not exceed 10 mm",
                "number in the text", ("Fig. 3, amplitude at most 10 mm",)),
]
