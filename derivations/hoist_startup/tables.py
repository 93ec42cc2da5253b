"""Tables 1–2 of paper 002: the cells derived from (65) and (66), and as printed.

``derive_tables(d)`` adds the derived cells as steps (after (66)); ``PUBLISHED``
holds the printed cells (Table 1, from (65); Table 2, from (66)) and the two
readings of Table 2 its numbers need. Importing this module builds the records
of ``published`` (it uses their helpers); ``build()`` imports it when it runs.
"""
from __future__ import annotations

from dataclasses import replace
from decimal import Decimal

import sympy as sp

from crane_sym.derivation import Derivation
from crane_sym.published import FITTED_VALUE, Cause, Convention, PublishedFormula

from .model import K_cell, col, g, t, t_a, t_n, tau0, v0
from .published import _cell
from .steps import rhs


# --- The tables derived -----------------------------------------------------------
#: Table 2 as the numbers show it was computed (see ``derive_tables``).
TABLE2_G = sp.Rational(981, 100)
TABLE2_T_A = sp.Rational(1, 1000)
#: The literal reading: the instant the header gives, standard gravity.
STANDARD_G = sp.Rational(980665, 100000)
AS_HEADED = ", as headed"


def derive_tables(d: Derivation) -> None:
    """Table 1 from (65); Table 2 from (66) as its numbers show it was computed."""
    for i in (2, 3, 4):
        law = rhs(d, f"(65), i = {i}")
        for frac in TABLE_COLUMNS:
            d.add(table1_label(i, frac), sp.Eq(K_cell, law.subs(t, frac * t_n)),
                  f"(65), i = {i} at t/t_п = {frac}.", title="Table 1" if (
                      i, frac) == (2, TABLE_COLUMNS[0]) else "")
    d.add("Table 2, columns", sp.Eq(col, t / tau0),
          "The g term of (66) reproduces the printed numbers only with the column "
          "read as t/τ_0, the range the caption gives (t ∈ [0, τ_0]).", title="Table 2")
    d.add("Table 2, a_i term", sp.Eq(t_a, TABLE2_T_A),
          "The a_i term reproduces the printed k̃_дин2 = 0.999 (t_п = 1 s) and 0.9995 "
          "(t_п = 2 s) in every column only at t = 1 ms.")
    for i in TABLE2_ROWS:
        law = rhs(d, f"(66), i = {i}")
        a_part, g_part = law.as_independent(g)
        for speed, duration in TABLE2_BLOCKS:
            for frac in TABLE_COLUMNS:
                fixed = {v0: speed, t_n: duration}
                value = (a_part.subs(fixed).subs(t, TABLE2_T_A)
                         + g_part.subs(fixed).subs({g: TABLE2_G, t: frac * tau0}))
                headed = law.subs(fixed).subs({g: STANDARD_G, t: frac * duration})
                d.add(table2_label(i, speed, duration, frac) + AS_HEADED,
                      sp.Eq(K_cell, headed),
                      f"(66), i = {i} at t = {frac}·t_п in both terms, as the header "
                      "t/t_п says, with standard gravity; τ_0 is not given.")
                d.add(table2_label(i, speed, duration, frac), sp.Eq(K_cell, value),
                      f"(66), i = {i} with g = 9.81, t/τ_0 = {frac} in the g term, "
                      "t = 1 ms in the a_i term.")


TABLE_COLUMNS = tuple(sp.Rational(n, 4) for n in range(5))
TABLE2_ROWS = (1, 3, 2, 4)                       # the printed order
TABLE2_BLOCKS = tuple((sp.Rational(v), sp.Integer(tp)) for v in ("1/4", "1/2")
                      for tp in (1, 2))


def _dec(x: sp.Rational) -> str:
    return str(Decimal(int(x.p)) / Decimal(int(x.q))).rstrip("0").rstrip(".") or "0"


def table1_label(i: int, frac: sp.Rational) -> str:
    """Label of a Table 1 cell, e.g. ``Table 1, k3, t/tn=0.25``.

    Parameters
    ----------
    i : int
        Row: the law a_i of k̃_дин,i^(opt).
    frac : sympy.Rational
        Column t/t_п.
    """
    return f"Table 1, k{i}, t/tn={_dec(frac)}"


def table2_label(i: int, speed: sp.Rational, duration: sp.Integer,
                 frac: sp.Rational) -> str:
    """Label of a Table 2 cell, e.g. ``Table 2, k1, v0=0.25, tn=1, col=0.5``.

    Parameters
    ----------
    i : int
        Row: the law a_i.
    speed, duration : sympy.Rational
        The block: v0 [m/s] and t_п [s].
    frac : sympy.Rational
        The printed column (see step ``Table 2, columns`` for its reading).
    """
    return f"Table 2, k{i}, v0={_dec(speed)}, tn={duration}, col={_dec(frac)}"


# --- The tables as printed -------------------------------------------------------
TABLE1 = {2: ("1,0", "0,75", "0,5", "0,25", "0"),
          3: ("0", "1,6875", "1,500", "0,5625", "0"),
          4: ("0", "1,5820", "1,8750", "0,5273", "0")}

# Rows in printed order k1, k3, k2, k4; blocks (v0, t_п) = (0.25, 1), (0.25, 2),
# (0.50, 1), (0.50, 2); columns 0, 0.25, 0.5, 0.75, 1.0.
TABLE2 = {
    1: (("1,000", "10,810", "20,620", "30,430", "40,240"),
        ("1,000", "20,620", "40,240", "59,860", "79,480"),
        ("1,000", "5,905", "10,810", "15,715", "20,620"),
        ("1,000", "10,810", "20,620", "30,430", "40,240")),
    3: (("1,012", "10,822", "20,632", "30,442", "40,252"),
        ("1,006", "20,626", "40,246", "59,8662", "79,486"),
        ("1,012", "5,917", "10,822", "15,727", "20,632"),
        ("1,006", "10,816", "20,626", "30,436", "40,246")),
    2: (("0,999", "10,809", "20,619", "30,429", "40,239"),
        ("0,9995", "20,6195", "40,2395", "59,8595", "79,4795"),
        ("0,999", "5,904", "10,809", "15,714", "20,619"),
        ("0,9995", "10,8095", "20,6195", "30,4295", "40,2395")),
    4: (("1,000", "10,810", "20,620", "30,430", "40,240"),
        ("1,000", "20,620", "40,240", "59,860", "79,480"),
        ("1,000", "5,905", "10,810", "15,715", "20,620"),
        ("1,000", "10,81", "20,620", "30,430", "40,240")),
}
#: Table 2 cells that (66) misses, and what they are instead.
TABLE2_NOTES = {
    3: "k̃_дин3 and k̃_дин4 of Table 2 are 1 + (66): the table adds 1 to both rows",
    4: "k̃_дин3 and k̃_дин4 of Table 2 are 1 + (66): the table adds 1 to both rows",
}

PUBLISHED = [_cell(table1_label(i, frac), text, "Table 1, from (65)")
              for i, row in TABLE1.items() for frac, text in zip(TABLE_COLUMNS, row)]
#: The reading Table 2's numbers need (the literal one is its header, t/t_п).
FITTED_INSTANTS = ("the instants fitted to the printed numbers: the column is t/τ_0 in "
                   "the g term (the caption's t ∈ [0, τ_0]), the a_i term is taken at "
                   "t = 1 ms, g = 9.81 m/s²")
UNSTATED_INSTANTS = Cause(
    "002-table2-instants", "Table 2's header gives the column as t/t_п and no τ_0; its "
    "numbers follow from (66) only at instants fitted to them (t/τ_0 in the g term, "
    "t = 1 ms in the a_i term, g = 9.81)")
PLUS_ONE = Cause(
    "002-table2-plus-one", "the rows k̃_дин3 and k̃_дин4 of Table 2 are 1 + (66) even "
    "at the fitted instants: the table adds 1 to both rows")


def _table2_cell(i: int, speed: sp.Rational, duration: sp.Integer, frac: sp.Rational,
                 text: str) -> PublishedFormula:
    label = table2_label(i, speed, duration, frac)
    cell = _cell(label, text, "Table 2, from (66)"
                 + (f"; {TABLE2_NOTES[i]}" if i in TABLE2_NOTES else "")
                 + ("; the printed 59,8662 has one digit too many: 1 + (66) is 59.865994"
                    if text == "59,8662" else ""),
                 compare_to=label + AS_HEADED,
                 cause=(PLUS_ONE if i in TABLE2_NOTES
                        else None if (i, frac) == (1, 0)  # 1 at t = 0 under any reading
                        else UNSTATED_INSTANTS))
    fitted = Convention(FITTED_INSTANTS, cell.printed, FITTED_VALUE, compare_to=label)
    return replace(cell, conventions=(fitted,))


PUBLISHED += [_table2_cell(i, speed, duration, frac, text)
              for i in TABLE2_ROWS
              for (speed, duration), row in zip(TABLE2_BLOCKS, TABLE2[i])
              for frac, text in zip(TABLE_COLUMNS, row)]
