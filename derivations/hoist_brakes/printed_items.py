"""The inventory of paper 001's print (``001_544065b666a6bc39.txt``): what the
audit owes a verdict, listed from the print, not from the records.

Equations (1)–(7) (the OCR keeps the numbers (2)–(7); (1) is the unnumbered
α1 = ΣM_i/J_red that the text calls the first); the fifteen cells of Table 1,
as printed; the numbers the text states after (5), in its conclusions and under
Figs 8, 9, 11 and 12.
"""
from __future__ import annotations

from crane_sym.published import PrintedItem, numbered

#: Table 1 (Технические характеристики подъемника), cell name -> the cell as the
#: OCR prints it (value and unit).
TABLE1_CELLS = {
    "n1": "п,= 1500 мин1", "v": "V =45 * верт м/мин", "J1": "•1, = 20 кг'М2",
    "J2": "}2= 500 кг'М2", "m_GM": "тгм= 10 т", "m_L": "шг= 52 т", "r": "г = 0,5 м",
    "i_g": "[р = 26,2", "i_t": "1п = 4", "M_BB": "Мрт = 5,8 кН м",
    "t_BB": "1здрт= 0,4 с", "M_SB": "Мтб= 130 кН м", "t_SB": "*здтб = 0,1 С",
    "c": "с = 4* 104 Нм/рад", "delta": "8 = 3°"}


def table1_label(name: str) -> str:
    """The record label of Table 1's cell ``name``: ``Table 1, n1`` (the hoist
    speed's record keeps its value, ``Table 1, v = 45 m/min``)."""
    return "Table 1, v = 45 m/min" if name == "v" else f"Table 1, {name}"


_TEXT = (("after (5), BF_SB = 1.7", "after (5), «для FBt6 = 1,7»"),
         ("after (5), BF_SB = 3.3", "after (5), «для FBt6 = 3,3»"),
         ("after (5), 2.4", "after (5), «2,4 ... 4,2», lower end"),
         ("after (5), 4.2", "after (5), «2,4 ... 4,2», upper end"),
         ("after (5), 3.9", "after (5), «3,9 ... 7,2», lower end"),
         ("after (5), 7.2", "after (5), «3,9 ... 7,2», upper end"),
         ("typical 2.6", "rigid body, «типичным значением … 2,6»"),
         ("in some cases 4.4", "rigid body, «в некоторых случаях … 4,4»"),
         ("Fig. 9 peak 8.9", "Fig. 9, M_rel,max = 8,9"),
         ("conclusions 890 %", "conclusions, «Мр охн макс = 890%»"),
         ("Fig. 8 legend, MF = 0.90", "Fig. 8 legend, «MF = 0,90...0,95», lower end"),
         ("Fig. 8 legend, MF = 0.95", "Fig. 8 legend, «MF = 0,90...0,95», upper end"))
_FIGS = tuple((f"Fig. {fig}, {factor}, {end} (text)",
               f"under Fig. {fig}, «{factor} = {text}», payload {end}")
              for fig, factor, end, text in (
                  (11, "BF_SB", "0 t", "5%"), (11, "BF_SB", "52 t", "12%"),
                  (11, "BF_BB", "0 t", "92%"), (11, "BF_BB", "52 t", "8%"),
                  (12, "BF_SB", "0 t", "5%"), (12, "BF_SB", "52 t", "12%"),
                  (12, "BF_BB", "0 t", "124%"), (12, "BF_BB", "52 t", "208%")))

PRINTED_ITEMS = numbered(1, 7) + [
    PrintedItem(f"Table 1, {name}: {cell}", "table cell", (table1_label(name),))
    for name, cell in TABLE1_CELLS.items()] + [
    PrintedItem(where, "number in the text", (label,)) for label, where in _TEXT + _FIGS]
