"""The published formulas of paper 000, as printed: eqs (1)–(14) and the
initial conditions, each with its printed LaTeX and any reading convention.
"""
from __future__ import annotations

import sympy as sp

from crane_sym.readings import Meaning, Scaled

from crane_sym.published import (ASSUMPTION, DEFINITION, OPERATOR_SCOPE, SYMBOL_FOR_ANOTHER, Cause,
                                 Convention, PublishedFormula, printed)

from .model import (PAPER, A, B, F, P, P_t, W, c, m1, m2, p, t, u0, u0_dot, x1,
                    x2, x_p)


# LaTeX copied verbatim from 000_4ef6efc8a81a3b06.txt; Russian words in it:
# "где" = "where", "или" = "or". The OCR of this paper is clean.
def _printed(label: str, latex: str, relation: sp.Eq | None, note: str = "",
             **kwargs) -> PublishedFormula:
    return printed(PAPER, label, latex, relation, note, **kwargs)


_stretch = x2 - x1
_x_star = (P_t * m2 - W * m1) / (c * (m1 + m2))

#: The instant the text gives the two initial conditions, which their print omits.
AT_START = ("x_2 − x_1 (and its rate) of the print taken at t = 0, the instant the "
            "sentence before it names ('при t = 0')")
#: Where the paper states its initial conditions (quoted for the assumption records).
INITIAL = ('"Начальные условия при t = 0 примем следующие:" ("we take the following '
           'initial conditions at t = 0"), before (10)')

PUBLISHED = [
    _printed("(1)", r"m_1 \ddot{x}_1 - c(x_2 - x_1) = -P_t; \quad (1)",
             sp.Eq(m1 * x1.diff(t, 2) - c * _stretch, -P_t)),
    _printed("(2)", r"m_2 \ddot{x}_2 + c(x_2 - x_1) = -W; \quad (2)",
             sp.Eq(m2 * x2.diff(t, 2) + c * _stretch, -W)),
    _printed("(3)", r"F = c(x_2 - x_1) \quad (3)", sp.Eq(F, c * _stretch)),
    _printed("(4)", r"(\ddot{x}_2 - \ddot{x}_1) + c \cdot \frac{m_1 + m_2}{m_1 \cdot m_2}"
             r" (x_2 - x_1) = \frac{P_t}{m_1} - \frac{W}{m_2}; \quad (4)",
             sp.Eq(_stretch.diff(t, 2) + c * (m1 + m2) / (m1 * m2) * _stretch,
                   P_t / m1 - W / m2)),
    _printed("(5)", r"(x_2 - x_1) = A \cos pt + B \sin pt + (x_2 - x_1)^*, \quad (5)",
             sp.Eq(_stretch, A * sp.cos(p * t) + B * sp.sin(p * t) + x_p)),
    _printed("(6)", r"\text{где, } P = \sqrt{\frac{m_1 + m_2}{m_1 \cdot m_2} \cdot c}, \quad (6)",
             sp.Eq(P, sp.sqrt((m1 + m2) / (m1 * m2) * c)),
             "printed with a capital P, while (5), (9), (10), (13), (14) use p",
             conventions=(Convention(
                 "P in (6) is the frequency p of (5); it is not the braking force P_t",
                 Meaning(((P, p),)), SYMBOL_FOR_ANOTHER),),
             cause=Cause("000-capital-P", "(6) prints the frequency p of (5) as a capital P, "
                         "the letter of no quantity in the paper")),
    _printed("(7)", r"(x_2 - x_1)^* = \left( \frac{P_t}{m_1} - \frac{W}{m_2} \right) "
             r"\div \frac{m_1 + m_2}{m_1 \cdot m_2} c, \quad (7)",
             # Read as printed: ÷ and the product after it at equal precedence,
             # left to right, i.e. (P_t/m1 - W/m2) / ((m1+m2)/(m1*m2)) * c.
             sp.Eq(x_p, (P_t / m1 - W / m2) / ((m1 + m2) / (m1 * m2)) * c),
             "the divisor after ÷ is a fraction followed by the factor c",
             conventions=(Convention(
                 "÷ divides by the whole product (m1 + m2)/(m1·m2)·c that follows it",
                 # read left to right c multiplies; over the whole product it divides
                 Scaled(c ** -2), OPERATOR_SCOPE),),
             cause=Cause("000-divide-scope", "(7) writes ÷ before a product; taken left "
                         "to right, c multiplies instead of divides")),
    _printed("(8)", r"\text{или } (x_2 - x_1)^* = \frac{P_t m_2 - W m_1}{c(m_1 + m_2)}, \quad (8)",
             sp.Eq(x_p, _x_star)),
    _printed("(9)", r"(x_2 - x_1) = A \cos pt + B \sin pt + \frac{P_t m_2 - W m_1}"
             r"{c(m_1 + m_2)}, \quad (9)",
             sp.Eq(_stretch, A * sp.cos(p * t) + B * sp.sin(p * t) + _x_star)),
    _printed("initial stretch", r"x_2 - x_1 = 0;", sp.Eq(u0, 0),
             "initial conditions at t = 0, printed between (9) and (10); the "
             "step 'preloaded start' gives F(t) from the preloaded state",
             read_as=AT_START, compare_to="steady travel", kind=ASSUMPTION, stated=INITIAL,
             cause=Cause(
                 "000-unstretched-start", "the print starts braking from an unstretched "
                 "link, while steady travel against the resistance W stretches it by "
                 "−W/c")),
    _printed("initial relative velocity", r"\dot{x}_2 - \dot{x}_1 = 0.", sp.Eq(u0_dot, 0),
             "initial conditions at t = 0, printed between (9) and (10)",
             read_as=AT_START, kind=ASSUMPTION, stated=INITIAL, basis=DEFINITION,
             basis_note="the model adopts the equal speeds of steady travel"),
    _printed("(10)", r"(\dot{x}_2 - \dot{x}_1) = -pA \sin pt + pB \cos pt, \quad (10)",
             sp.Eq(_stretch.diff(t), -p * A * sp.sin(p * t) + p * B * sp.cos(p * t))),
    _printed("(11)", r"A = -\frac{P_t m_2 - W m_1}{c(m_1 + m_2)}, \quad (11)",
             sp.Eq(A, -_x_star), "printed on one line with (12)"),
    _printed("(12)", r"B = 0. \quad (12)", sp.Eq(B, 0), "printed on one line with (11)"),
    _printed("(13)", r"(x_2 - x_1) = \frac{P_t m_2 - W m_1}{c(m_1 + m_2)} (1 - \cos pt), \quad (13)",
             sp.Eq(_stretch, _x_star * (1 - sp.cos(p * t)))),
    _printed("(14)", r"F = c(x_2 - x_1) = \frac{P_t m_2 - W m_1}{(m_1 + m_2)} (1 - \cos pt), \quad (14)",
             sp.Eq(F, (P_t * m2 - W * m1) / (m1 + m2) * (1 - sp.cos(p * t))),
             "a chain; its middle member c(x2 − x1) restates (3), so the "
             "transcription keeps the outer equality F = ..."),
]
