"""Prints read by machine: each pre-pass rule on its own, the parse of a dynamics
print, and a quiet fix of a transcription caught as an unexplained difference."""
from __future__ import annotations

import os
from dataclasses import replace

import pytest
import sympy as sp

pytest.importorskip("lark")

from crane_sym import registry  # noqa: E402
from crane_sym.audit.latex_parse import (bound_variables, candidates, layout, parse,  # noqa: E402
                                         placeholder, split, wrap_calls)
from crane_sym.audit.machine_read import AGREES, DIFFERS, UNREADABLE, machine_read  # noqa: E402
from crane_sym.audit.verdicts import NOT_THE_PRINT, audit_formula, tied_to_print  # noqa: E402


def _formula(paper: str, label: str):
    d = registry.get(paper)
    return d, next(f for f in d.published if f.label == label)


def test_layout_drops_numbers_and_reads_commas_percent_and_mathcad():
    assert layout(r"F = c(x_2 - x_1) \quad (3)") == "F = c(x_2 - x_1)"
    assert layout("2,4") == "2.4"
    assert layout("5%") == r"5 \cdot 10^{-2}"
    assert layout("z1:=25") == "z1=25"
    assert layout(r"\left\{ a \right\}") == "( a )"


def test_split_gives_each_relation_of_a_chain_and_a_line():
    assert split(r"a = b = c") == ["a = b", "b = c", "a = c"]
    assert split(r"a = 1 \quad b = 2") == ["a = 1", "b = 2"]
    assert split(r"x &= y \\ &= z") == ["x = y", "y = z", "x = z"]


def test_a_call_is_its_own_factor():
    """Without the wrap the parser reads sin(x t)/(x t) as sin(1)."""
    assert wrap_calls(r"1 - \sin(x t) / (x t)") == r"1 - (\sin(x t)) / (x t)"
    parsed = parse(wrap_calls(r"1 - \sin(x t) / (x t)"))
    x, t = sp.symbols("x t")
    assert sp.simplify(parsed.rhs - (1 - sp.sin(x * t) / (x * t))) == 0


def test_a_bound_variable_becomes_a_letter():
    renamed = bound_variables(r"\int_0^t S(\theta) d\theta")
    assert " ".join(renamed.split()) == r"\int_0^t S(w) dw"


def test_placeholders_are_single_symbols_to_the_parser():
    assert placeholder(0) == "V_{pqa}" and placeholder(26) == "V_{pqaa}"
    assert len({placeholder(k) for k in range(800)}) == 800
    parsed = parse(f"{placeholder(3)} + 1")
    assert len(parsed.rhs.free_symbols) == 1


def test_a_dot_is_a_time_derivative_not_a_product():
    """ẍ_1 of paper 000's (1) is read as d²x1/dt², not as dot·x."""
    d, f = _formula("travel_braking", "(1)")
    read = machine_read(d, f)
    assert read.status == AGREES, read.detail
    x1 = d.symbols["x1"].expr
    assert "\\ddot{x}_{1}" in read.parsed and x1.diff(x1.args[0], 2) in f.printed.atoms(
        sp.Derivative)


def test_a_quiet_fix_is_an_unexplained_difference():
    """A transcription that swaps m1 and m2 against its print differs, and nothing
    the record names explains it: the defect the tests forbid."""
    d, f = _formula("travel_braking", "(13)")
    m1, m2 = d.symbols["m1"].expr, d.symbols["m2"].expr
    fixed = replace(f, printed=f.printed.xreplace({m1: m2, m2: m1}))
    read = machine_read(d, fixed)
    assert read.status == DIFFERS and read.explained_by == ""
    assert machine_read(d, f).status == AGREES


def test_a_partly_read_print_compares_every_part_it_reads():
    """(28) prints P(t), P(0) and Q(t) in one system, P(0) not read by the parser:
    a sign slipped into the transcription of P(t) differs from the part read, the
    part not read is named, and the record is the finding."""
    d, f = _formula("hoist_startup", "(28)")
    assert machine_read(d, f).status == AGREES
    slip = replace(f, printed=sp.Eq(f.printed.lhs, -f.printed.rhs, evaluate=False))
    read = machine_read(d, slip)
    assert read.status == DIFFERS and read.explained_by == "", read.detail
    assert "the parts not read" in read.detail and "P(0)" in read.detail
    judged = tied_to_print(replace(audit_formula(d, slip), machine_read=read))
    assert judged.verdict == NOT_THE_PRINT


@pytest.mark.parametrize("label", ["(8), middle", "(23)"])
def test_a_part_read_that_is_not_this_records_stays_unread(label):
    """Another record's part of the same print ((8)'s outer members beside its
    middle member), or a member written in names the transcription writes out
    ((23)'s x_*(t)), is no difference: this record's own part is not read."""
    d, f = _formula("hoist_startup", label)
    read = machine_read(d, f)
    assert read.status == UNREADABLE and read.detail.startswith("part of the print"), label


def test_ocr_debris_is_unreadable_with_its_reason():
    d, f = _formula("hoist_brakes", "(6), hoisting")
    read = machine_read(d, f)
    assert read.status == UNREADABLE and read.detail.startswith("OCR debris")


def test_a_divide_leaves_its_scope_open():
    d, f = _formula("travel_braking", "(7)")
    assert machine_read(d, f).status == UNREADABLE
    assert "\\div" in machine_read(d, f).detail


def test_a_reconstruction_explains_a_difference():
    d, f = _formula("portal_travel", "Form 1, epsilon_alpha = 1.54")
    read = machine_read(d, f)
    assert read.status == DIFFERS and "reconstruction" in read.explained_by


def test_candidates_hold_every_relation_of_a_print():
    assert len(candidates(r"\Omega^2 = a, \quad S(t) = b.")) == 2


def test_an_unreadable_print_gives_one_message_whatever_the_hash_seed():
    """Which unknown name a message names does not depend on set order, so the
    audit JSON is the same bytes in every process."""
    import subprocess
    import sys
    code = ("import sympy as sp\n"
            "from crane_sym.audit.print_names import map_symbols, Unreadable\n"
            "t = sp.Symbol('t')\n"
            "e = sp.Function('f')(t) + sp.Function('g')(t) + sp.Symbol('a') * sp.Symbol('b')\n"
            "try:\n    map_symbols(e, {}, {'t': t})\n"
            "except Unreadable as exc:\n    print(exc)\n")
    messages = {subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                               env={**os.environ, "PYTHONHASHSEED": str(seed)},
                               check=True).stdout for seed in range(6)}
    assert messages == {"no symbol of the derivation is printed 'f'\n"}


def test_a_structural_form_rebuilds_its_expression_without_eval():
    """The table's forms: numbers, functions, integrals, relations and the
    undefined functions the lark transformer builds, rebuilt from an allow-list."""
    from crane_sym.audit.parse_table import expression, form
    x, t = sp.symbols("x t")
    f = sp.Function("Y_{2}", commutative=True)
    for e in (sp.Float("2.5", 30) * x + sp.Rational(3, 7), sp.exp(-x) * sp.cos(sp.pi * t),
              sp.Integral(f(x), (x, 0, t)), sp.Eq(sp.Abs(x), 2), x < 1, sp.I * x):
        assert expression(form(e)) == e and form(expression(form(e))) == form(e)
    with pytest.raises(ValueError, match="unknown form"):
        expression(["__import__", ["Symbol", "os", {}]])
    with pytest.raises(ValueError, match="no structural form"):
        form(sp.Matrix([x]))


def test_the_committed_table_is_this_parsers_and_holds_fresh_parses():
    """The table's fingerprint is this parser's, every key is its side's, and a
    seeded sample of its entries parsed afresh gives the stored forms."""
    import json
    import random
    from crane_sym.audit.latex_parse import Unreadable, _parse_live, parse_table, parser
    from crane_sym.audit.parse_table import entry_for, key
    table = parse_table()
    assert table.path is not None and table.entries, "generated/machine_reading.json"
    data = json.loads(table.path.read_text(encoding="utf-8"))
    assert data["parser"] == parser()
    for k, entry in table.entries.items():
        assert k == key(entry["side"], frozenset(entry["functions"]))
    for k in random.Random(39).sample(sorted(table.entries), 8):
        entry = table.entries[k]
        functions = frozenset(entry["functions"])
        try:
            fresh = entry_for(entry["side"], functions, _parse_live(entry["side"], functions))
        except Unreadable as why:
            fresh = entry_for(entry["side"], functions, None, str(why))
        assert fresh == entry


def test_a_side_not_in_the_table_is_parsed_afresh_and_counted():
    from crane_sym.audit.latex_parse import parse_side, parse_table
    table = parse_table()
    before = table.fresh
    side = r"\frac{a}{b} + 3.5 x + 39"
    parse_side.cache_clear()
    first = parse_side(side, frozenset())
    assert table.fresh == before + 1
    a, b, x = sp.symbols("a b x")
    assert sp.simplify(first - (a / b + sp.Float("3.5") * x + 39)) == 0
    assert all(type(s.name) is str for s in first.free_symbols)   # not lark's tokens


def test_a_side_missing_from_the_table_makes_generate_check_stale(monkeypatch):
    """A side the table lacks is parsed afresh, counted, and put back in the text
    `generate` writes, so that text differs from a table without it."""
    from crane_sym.audit.latex_parse import parse_table
    from crane_sym.audit.machine_read import parse_table_text, table_entries
    d = registry.get("travel_braking")
    table = parse_table()
    whole = table_entries(d)
    dropped = sorted(whole)[0]
    monkeypatch.setattr(table, "entries", {k: e for k, e in table.entries.items()
                                           if k != dropped})
    before = table.fresh
    again = table_entries(d)
    assert table.fresh == before + 1 and again == whole
    without = {k: e for k, e in whole.items() if k != dropped}
    assert parse_table_text(again) != parse_table_text(without)
