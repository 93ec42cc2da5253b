"""Every paper's walkthrough reads as a handout: words and LaTeX, no SymPy code
and no code names, tables as tables, one row per symbol, Cyrillic set as text,
sums as a person writes them, steps numbered without gaps, numbers beside the
printed numbers to their digits, no line of math over ``LIMIT`` characters, and
every formula typesets (``handout_math.math_errors``: TeX's specials, pairs,
and the MathML conversion the printable page uses)."""
from __future__ import annotations

import re

import pytest
import sympy as sp

from handout_metrics import code_names, metrics

from crane_sym import registry
from crane_sym.docs.page import math_pieces
from crane_sym.docs.numbers import LIMIT, math_errors
from crane_sym.latex import cyrillic_as_text, latex
from crane_sym.docs.walkthrough import walkthrough

#: What SymPy's str() or its default LaTeX leaves in a text, and internal names.
LEAKS = ("Derivative(", "Integral(", "Piecewise(", "sqrt(", r"{\left(t \right)}",
         "_at0", "vartheta(", "Eq(", "Symbol(")
POWER = re.compile(r"[\w)]\*\*\d")                    # Python's power, not Markdown bold
MATH = re.compile(r"\$\$(.+?)\$\$|\$([^$\n]+)\$", re.S)
TEXT = re.compile(r"\\(?:text|mathrm)\{[^{}]*\}")
CYRILLIC = re.compile(r"[А-Яа-яЁёІіЇїЄєҐґ]")


@pytest.fixture(scope="module", params=registry.ids())
def text(request):
    return request.param, walkthrough(request.param)


def _verdict_and_step_lines(text: str) -> list[str]:
    """The lines the toolkit writes (not the paper's printed LaTeX, kept verbatim)."""
    lines, verbatim = [], False
    for line in text.splitlines():
        if line.startswith("**As printed in the paper**"):
            verbatim = True
            continue
        if verbatim and line == "$$":
            continue
        if verbatim and not line.startswith("Verdict:"):
            continue
        verbatim = False
        lines.append(line)
    return lines


def test_no_sympy_code_or_internal_names(text):
    paper, md = text
    for line in _verdict_and_step_lines(md):
        for leak in LEAKS:
            assert leak not in line, f"{paper}: {leak!r} in {line[:160]!r}"
        assert not POWER.search(line), f"{paper}: {line[:160]!r}"


def test_cyrillic_is_set_as_text_in_the_toolkit_math(text):
    paper, md = text
    for line in _verdict_and_step_lines(md):
        for m in MATH.finditer(line):
            body = TEXT.sub("", m.group(1) or m.group(2))
            assert not CYRILLIC.search(body), f"{paper}: {body[:120]!r}"


def test_one_row_per_symbol(text):
    paper, md = text
    table = md[md.index("## Symbols"):md.index("## Derivation")]
    symbols = [row.split("|")[1].strip() for row in table.splitlines()
               if row.startswith("| $")]
    assert len(symbols) == len(set(symbols)), \
        f"{paper}: {[s for s in symbols if symbols.count(s) > 1]}"


def test_sums_lead_with_a_positive_term(text):
    paper, md = text
    assert r"- x_{1} + x_{2}" not in md and r"- c \left(x_{1} - x_{2}\right)" not in md


def test_tables_are_tables():
    md = walkthrough("002")
    assert md.count("### Table 1\n") == 1 and md.count("### Table 2\n") == 1
    assert not re.search(r"^### Step \d+ — Table [12], k", md, re.M)
    table2 = md[md.index("### Table 2\n"):]
    assert table2.count("| k3, ") == 20 and "the table adds 1 to both rows" in table2
    assert len(md.splitlines()) < 3000


def test_the_printer_writes_as_a_person_does():
    t, c, a, b = sp.symbols("t c a b")
    x1, x2 = sp.Function("x_1")(t), sp.Function("x_2")(t)
    assert latex(-x1 + x2) == "x_{2} - x_{1}"
    assert latex(-c * (x1 - x2)) == r"c \left(x_{2} - x_{1}\right)"
    assert latex(c * (x1 - x2)) == r"c \left(x_{1} - x_{2}\right)"     # no sign to move
    assert latex(-c * (a + b)) == r"- c \left(a + b\right)"              # nothing to flip
    assert latex(x2.diff(t, 2) + x1.diff(t)) == r"\dot{x}_{1} + \ddot{x}_{2}"
    assert cyrillic_as_text(r"K_{дин} + \text{ст}") == r"K_{\text{дин}} + \text{ст}"


#: What each walkthrough may reach: lines, and the longest line (prose paragraphs
#: and table rows; a line of math is held to ``LIMIT`` apart). Before the handouts:
#: 000 436 / 331, 001 1030 / 1284, 002 2780 / 600, 003 1811 / 1842, 004 1113 / 1423.
#: Lines and longest line; hoist_brakes and portal_travel grew by the printed items
#: with nothing to check (issue 37), now one row each in their table and in the verdicts.
LIMITS = {"travel_braking": (450, 340), "hoist_brakes": (1000, 1250),
          "hoist_startup": (2900, 430), "portal_travel": (1680, 1150),
          "drum_drive": (1250, 1450)}


def _math_lines(md: str) -> list[str]:
    lines = []
    for tex, _ in math_pieces(md):
        lines += tex.splitlines()
    return lines


def test_no_code_names(text):
    """No file, module, function or check-internal name in the prose or headings."""
    paper, md = text
    assert code_names(md) == [], paper


def test_no_line_of_math_is_longer_than_the_limit(text):
    paper, md = text
    long = [line[:80] for line in _math_lines(md) if len(line) > LIMIT]
    assert not long, (paper, long)


def test_length_and_longest_line_within_limits(text):
    paper, md = text
    m = metrics(md)
    lines, longest = LIMITS[paper]
    assert m.lines <= lines and m.longest <= longest, (paper, m)


def test_every_formula_typesets(text):
    paper, md = text
    errors = [(tex[:80], e) for tex, _ in math_pieces(md) for e in math_errors(tex)]
    assert not errors, (paper, errors[:5])


def test_steps_are_numbered_without_gaps(text):
    paper, md = text
    numbers = [int(n) for n in re.findall(r"^### Step (\d+) — ", md, re.M)]
    assert numbers == list(range(1, len(numbers) + 1)), paper


def test_the_checker_fails_on_what_does_not_typeset():
    assert math_errors("5%") and math_errors(r"\frac{a}{b") and math_errors(r"\foo x")
    assert math_errors(r"\left( x") and math_errors(r"\begin{cases} a")
    assert not math_errors(r"5\,\% \approx \frac{a}{b}")


def test_derived_numbers_stand_beside_the_printed_ones():
    """001 and 003 show each derived value to the print's digits, and the value
    under the reading that decided with the reading."""
    md = walkthrough("001")
    mf = md[md.index("(Fig. 8 legend, MF = 0.90)"):]
    assert mf.index("- Derived, to the print's digits: $0.90$ ($0.9034$)") < 600
    fig11 = md[md.index("(Fig. 11, BF_SB, 0 t (text)): $5\\%$"):]
    assert "- Derived with the reading (the unstated braking time is Δt = 1 s): " \
        "$5\\,\\%$ ($5.18\\,\\%$)." in fig11[:1500]
    assert "$$\nN = \\frac{549152}{588527}\n$$" not in md          # decimals, not fractions
    md = walkthrough("003")
    for shown in ("$22.2$", "$0.527$", "$280.536$", "$5.231$", "$0.523$"):
        assert f"- Derived, to the print's digits: {shown}" in md, shown
    assert "- Derived with the reading (a decimal comma lost: ε_α = 1,54): $1.54$" in md
    assert max(len(line) for line in _math_lines(md)) <= LIMIT
