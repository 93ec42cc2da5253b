"""Every paper's walkthrough reads as a handout: words and LaTeX, no SymPy code,
tables as tables, one row per symbol, Cyrillic set as text, sums as a person
writes them."""
from __future__ import annotations

import re

import pytest
import sympy as sp

from crane_sym import registry
from crane_sym.latex import cyrillic_as_text, latex
from crane_sym.walkthrough import walkthrough

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
    assert table2.count("| k3, ") == 20 and "`002-table2-plus-one`" in table2
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
