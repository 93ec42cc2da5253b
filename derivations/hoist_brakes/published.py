"""The published formulas and numbers of paper 001, as printed.

The OCR of (1)–(7) is badly damaged: each record keeps the OCR text verbatim
as its ``latex`` and transcribes the formula the surrounding text defines
(``reconstructed=True``, the note says how each damaged token was read).
Every printed number is its own record, checked against Table 1 read one way
for the whole paper (``TABLE1_COUNTING``, declared once with its evidence); a
number only the rejected reading reproduces is a finding that says so.
"""
from __future__ import annotations

from dataclasses import replace
from decimal import Decimal

import sympy as sp

from crane_sym.published import (CHOSEN, DEFINITION, FITTED_VALUE, INTERNAL, RECONSTRUCTED,
                                 Cause, Convention, Fit, PaperReading, PublishedFormula,
                                 printed)

from .model import (BF_BB, BF_SB, LF, MF, PAPER, J, M_BB, M_L, M_M, M_SB, M_rel, M_rel_max,
                    M_st, N, alpha, d_omega, d_t, i_g, phi5)
from .printed_items import TABLE1_CELLS, table1_label

#: The one reading of Table 1 every record of this paper uses.
TABLE1_COUNTING = PaperReading(
    "Table 1's J1, J2 and M_SB (printed once for a hoist with two motors and two drums)",
    "values of the whole drive (both trains together)",
    "Fig. 8's legend prints 'MF = 0,90...0,95', the inertia factor over the payload: "
    "0.903…0.954 with J1 and J2 as totals, 0.933…0.960 counted per train; the text's "
    "'BF_SB = 1,7' is 130 kN·m as the total (1.71), 3.42 per drum",
    "values of each train (J1, J2 and M_SB counted once per motor and once per drum)",
    ("Fig. 8 legend, MF = 0.90", "Fig. 8 legend, MF = 0.95", "after (5), BF_SB = 1.7"))
ONE_READING = Cause("001-one-reading-evidence", "Fig. 8's MF = 0,90...0,95 and the text's "
                    "BF_SB = 1,7 are the prints that fix the reading of Table 1 (totals); "
                    "each matches under that reading and fails under the other, so it is "
                    "consistent with the reading, not a confirmation of it")
BF33 = Cause("001-bf-3.3", "the second brake factor BF_SB = 3.3 after (5) is an input "
             "the text puts into (5) («для FBt6 = 3,3 получаем …») without its source; it "
             "follows from neither reading of Table 1 (1.71 with 130 kN·m in total, 3.42 on "
             "each drum), so it is not a result to check")
CASE44 = Cause("001-4.4-case", "the 4.4 'in some cases' is a claim about hoists in "
               "general («в некоторых случаях»), not about Table 1's hoist, so one example "
               "cannot decide it (for the record: (4) at the text's BF_SB = 3.3 gives 4.10 "
               "with Table 1's MF; (5) with 130 kN·m on each drum gives 4.42)")
TABLE1_INPUTS = Cause("001-table1-inputs", "Table 1's cells other than the hoist speed are "
                      "the reference hoist's data: inputs of every check, not results")
BRAKING_TIME = Cause("001-unstated-braking-time", "(6)–(7) need the braking time Δt, which "
                     "the paper never states; fitted to the eight percentages of Figs 11–12 "
                     "it lies in [0.999, 1.005] s, and Δt = 1 s reproduces all of them")
FIG9 = Cause("001-fig9-model", "Fig. 9's elastic model is stated only through Table 1; the "
             "reconstruction (stiffness at the motor shaft, 3° backlash at the drum, brakes as "
             "steps that hold, lowering the hook alone) peaks at 9.13 undamped with the motor "
             "torque lost at once; the paper states neither the mesh damping nor the motor's "
             "delay, and over their plausible ranges the peak spans 8.47–9.13, which holds "
             "the printed 8.9; the rated load gives 5.80")
PHI5_NOTE = ("how φ5 enters: the paper applies φ5 of EN 13001-2 without writing how; the "
             "standard multiplies the change of the load (the jump from LF) by φ5")
RANGE_NOTE = ("(3) reconstructed from OCR damage (with " + PHI5_NOTE + "), at φ5 from 1 (the "
              "text's special case 'φ5 = 1,0', the rigid body) to 2 (Fig. 8's legend 'φ5 = "
              "2,0 ... MF = 0,90...0,95') and Table 1's MF range")
OCR2 = r"^g rei шах = ф5 {MF (LF ± BFSB ) - ZJ7) + LF, (2)"
OCR6 = r"BFm= + ... Мя А t / Kes Асо / м: А t (6)"
OCR7 = r"BFSB=+(l-MF) ... Kes Асо / м: А t (7)"
#: The braking time of (6)–(7), fitted to the percentages of Figs 11–12.
BRAKING_FIT = Fit(d_t, "the braking time Δt", "s", sp.Integer(1), (0.5, 2.0))


def _printed(label: str, latex: str, relation: sp.Eq | None, note: str = "",
             **kwargs) -> PublishedFormula:
    return printed(PAPER, label, latex, relation, note, **kwargs)


def _number(label: str, text: str, target: str, note: str, scale: int = 1,
            symbol: sp.Symbol = N, **kwargs) -> PublishedFormula:
    """A printed number (decimal comma) against step ``target``, within half a unit
    of its last digit; ``scale`` converts the printed unit (percent: 100)."""
    value = Decimal(text.replace(",", "."))
    half = float(Decimal(5).scaleb(value.as_tuple().exponent - 1) / abs(value))
    exact = sp.Rational(*value.as_integer_ratio()) / scale
    return _printed(label, text, sp.Eq(symbol, exact), note, compare_to=target,
                    tolerance=half, **kwargs)


def _counted(label: str, text: str, step: str, note: str,
             **kwargs) -> PublishedFormula:
    """A printed number against step ``<step>, totals`` (the paper's reading of Table
    1), with ``<step>, per train`` tried as the rejected reading when it fails."""
    kwargs.setdefault("basis", INTERNAL)
    kwargs.setdefault("basis_note", "a printed number against Table 1's data")
    return _number(label, text, f"{step}, totals", note, paper_reading=TABLE1_COUNTING,
                   rejected_target=f"{step}, per train", **kwargs)


def _percent(fig: int, factor: str, end: str, text: str, mode: str) -> PublishedFormula:
    label = f"Fig. {fig}, {factor}, {end}"
    f = _number(label + " (text)", text, label,
                f"the text under Fig. {fig} ({mode}), payload {end}, in percent",
                scale=100, basis=INTERNAL, basis_note="a printed number against (6)–(7) "
                "with Table 1's data", cause=BRAKING_TIME, paper_reading=TABLE1_COUNTING)
    return replace(f, latex=text + "%", conventions=(Convention(
        "the unstated braking time is Δt = 1 s", f.printed, FITTED_VALUE,
        compare_to=label + ", Δt = 1 s", fit=BRAKING_FIT),))


_M_sum = M_M - M_BB - M_SB / i_g - M_L
_grad = J * d_omega / (M_st * d_t)

PUBLISHED = [
    _printed("(1)", r"IX, а'=ТеТ\" L^i red m", sp.Eq(alpha, _M_sum / J),
             "unnumbered; OCR of α1 = ΣM_i / J_red,m; the text lists the moments (motor, "
             "service brake, safety brake, load) and the inertias (J1, J2, m_h, m_p)",
             compare_to="(1), hoisting", reconstructed=True, basis=DEFINITION,
             basis_note="Newton's law at the motor shaft; the print gives no terms, the "
             "transcription takes the model's (hoisting)"),
    _printed("(2), hoisting", OCR2, sp.Eq(M_rel_max, phi5 * (MF * (LF + BF_SB) - LF) + LF),
             "the + of ±; 'ZJ7' read as LF (the bracket closes MF(LF ± BF_SB) − LF), '{' "
             "as '('", reconstructed=True, basis=RECONSTRUCTED, basis_note=PHI5_NOTE),
    _printed("(2), lowering", OCR2, sp.Eq(M_rel_max, phi5 * (MF * (LF - BF_SB) - LF) + LF),
             "the − of ±, as above", reconstructed=True, basis=RECONSTRUCTED,
             basis_note=PHI5_NOTE),
    _printed("(3)", r"Маге, тах = ФАмр(ВР!Ш +1)-1]+1 (3)",
             sp.Eq(M_rel_max, phi5 * (MF * (BF_SB + 1) - 1) + 1),
             "'ФАмр(' read as φ5[MF(, 'ВР!Ш' as BF_SB: (2), hoisting, at LF = 1",
             reconstructed=True, basis=RECONSTRUCTED, basis_note=PHI5_NOTE),
    _printed("(4)", r"Моы=Ш(ВРя +1) (4)", sp.Eq(M_rel, MF * (BF_SB + 1)),
             "'Ш' read as MF, 'ВРя' as BF_SB; the text calls it the 'static' torque at the "
             "gearbox input, i.e. without φ5", reconstructed=True),
    _printed("(5)", r"Мсге,=ВРзв+ 1 (5)", sp.Eq(M_rel, BF_SB + 1),
             "'ВРзв' read as BF_SB; (4) with MF = 1 as the text says", reconstructed=True),
    _printed("(6), hoisting", OCR6, sp.Eq(BF_BB, -LF + MF * _grad),
             "only 'BF_BB = +' and the pieces M_st*, Δt, J_ges*, Δω of a fraction survive; "
             "the terms are the ones the text defines below (LF, MF, J_ges*, M_st*, Δω, "
             "Δt), the sign the text's 'hoisting (−)'", reconstructed=True),
    _printed("(6), lowering", OCR6, sp.Eq(BF_BB, LF + MF * _grad),
             "as above, with the text's 'lowering (+)'", reconstructed=True),
    _printed("(7), hoisting", OCR7, sp.Eq(BF_SB, (1 - MF) * _grad),
             "'l-MF' read as 1 − MF; the fraction J_ges*·Δω/(M_st*·Δt) as in (6)",
             reconstructed=True),
    _printed("(7), lowering", OCR7, sp.Eq(BF_SB, (1 - MF) * _grad),
             "as above: the print's + holds for both directions", reconstructed=True),
    _number("Table 1, v = 45 m/min", "45", "Table 1, hoist speed",
            "Table 1's hoist speed (m/min) against n1, r, i_g, i_t",
            basis=INTERNAL, basis_note="Table 1 against itself (kinematics)"),
    _counted("Fig. 8 legend, MF = 0.90", "0,90", "MF rated load",
             "the lower end of Fig. 8's 'MF = 0,90...0,95'", cause=ONE_READING),
    _counted("Fig. 8 legend, MF = 0.95", "0,95", "MF hook only",
             "the upper end of Fig. 8's 'MF = 0,90...0,95'", cause=ONE_READING),
    _counted("after (5), BF_SB = 1.7", "1,7", "BF_SB of Table 1",
             "the text's first brake factor against Table 1", cause=ONE_READING),
    _printed("after (5), BF_SB = 3.3", "3,3", None, "the text's second brake factor, "
             "an input of (5) («для FBt6 = 3,3 получаем»)",
             not_checkable="an input, not a result: the text puts it into (5) without "
             "saying where it comes from", basis=INTERNAL,
             basis_note="the text's input, nothing derived", cause=BF33),
    _counted("after (5), 2.4", "2,4", "after (5), BF_SB = 17/10, lower",
             "'2,4 ... 4,2' for BF_SB = 1.7: (3) at φ5 = 1 and the smallest MF",
             basis=RECONSTRUCTED, basis_note=RANGE_NOTE),
    _counted("after (5), 4.2", "4,2", "after (5), BF_SB = 17/10, upper",
             "upper end of '2,4 ... 4,2': (3) at φ5 = 2 and the largest MF",
             basis=RECONSTRUCTED, basis_note=RANGE_NOTE),
    _counted("after (5), 3.9", "3,9", "after (5), BF_SB = 33/10, lower",
             "'3,9 ... 7,2' for BF_SB = 3.3", basis=RECONSTRUCTED, basis_note=RANGE_NOTE),
    _counted("after (5), 7.2", "7,2", "after (5), BF_SB = 33/10, upper",
             "upper end of '3,9 ... 7,2'", basis=RECONSTRUCTED, basis_note=RANGE_NOTE),
    _counted("typical 2.6", "2,6", "rigid, (4), BF_SB = 17/10",
             "'typical for all hoists': the rigid body (4) without φ5",
             basis_note="a printed number against (4) with Table 1's MF"),
    _printed("in some cases 4.4", "4,4", None, "'may reach 4,4' «в некоторых случаях»: "
             "a claim about hoists in general",
             not_checkable="a general claim is not checked against one example (Table 1's "
             "hoist)", basis=INTERNAL, basis_note="a claim about hoists in general",
             cause=CASE44),
]
PUBLISHED += [_printed(
    table1_label(name), cell, None, f"Table 1's cell {name}, as the OCR prints it",
    not_checkable="an input: Table 1 gives the reference hoist's data, which the model "
    "takes as given and nothing in the paper derives", basis=INTERNAL,
    basis_note="the table's inputs, nothing derived", cause=TABLE1_INPUTS, verbatim=True)
    for name, cell in TABLE1_CELLS.items() if name != "v"]
PUBLISHED.append(_number(
    "Fig. 9 peak 8.9", "8,9", "Fig. 9 peak, hook only", "the text: 'M_rel,max = 8,9 (Fig. 9)' "
    "while lowering the hook ('спуск грузозахватного механизма'), and '890 %' in the "
    "conclusions; compared as a magnitude (Fig. 9 plots it negative)", kind=CHOSEN,
    basis=RECONSTRUCTED, basis_note="the two-mass hoist with backlash of elastic.py: where c "
    "and the backlash act and the brake law are argued in the model text; the mesh damping "
    "and the motor's delay are not stated and are moved over their plausible ranges "
    "(elastic.FIG9_CHOSEN)", cause=FIG9, paper_reading=TABLE1_COUNTING))
PUBLISHED.append(replace(_number(
    "conclusions 890 %", "890", "Fig. 9 peak, hook only", "the conclusions: "
    "'M_rel,max = 890 %', the peak of Fig. 9 in percent", scale=100, kind=CHOSEN,
    basis=RECONSTRUCTED, basis_note=PUBLISHED[-1].basis_note, cause=FIG9,
    paper_reading=TABLE1_COUNTING), latex="890 %"))
PUBLISHED += [_percent(11, "BF_SB", "0 t", "5", "hoisting"),
              _percent(11, "BF_SB", "52 t", "12", "hoisting"),
              _percent(11, "BF_BB", "0 t", "92", "hoisting"),
              _percent(11, "BF_BB", "52 t", "8", "hoisting"),
              _percent(12, "BF_SB", "0 t", "5", "lowering"),
              _percent(12, "BF_SB", "52 t", "12", "lowering"),
              _percent(12, "BF_BB", "0 t", "124", "lowering"),
              _percent(12, "BF_BB", "52 t", "208", "lowering")]
