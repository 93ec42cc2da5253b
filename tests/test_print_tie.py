"""The print and its transcription tied, and the recall of the print.

- a change made in the printed LaTeX only (the transcription untouched) turns
  the record's verdict into a ``not_the_print`` finding, in every format;
- every paper lists the items of its print, and each has a record;
- the recall counts the inventory, not the records: a record taken away leaves
  its item without one;
- the machine reading's coverage is counted apart for formulas and numbers.
"""
from __future__ import annotations

import json
from dataclasses import replace

import pytest

pytest.importorskip("lark")

from crane_sym import registry  # noqa: E402
from crane_sym.audit.formats import as_json, as_markdown, as_table, machine_read_coverage  # noqa: E402
from crane_sym.audit.machine_read import machine_read  # noqa: E402
from crane_sym.audit.recall import recall  # noqa: E402
from crane_sym.audit.verdicts import (NOT_THE_PRINT, audit, audit_formula,  # noqa: E402
                                      tied_to_print)

#: (paper, record, printed text, changed to, the verdict before the change)
MUTATIONS = [("000", "(13)", r"(1 - \cos pt)", r"(2 - \cos pt)", "confirmed"),
             ("001", "conclusions 890 %", "890 %", "980 %", "consistent"),
             ("003", "Form 1, d_a1 = 280.536", "280.536", "280.563", "confirmed")]


def _judged(d, f):
    return tied_to_print(replace(audit_formula(d, f), machine_read=machine_read(d, f)))


@pytest.mark.parametrize("paper, label, old, new, before", MUTATIONS)
def test_a_change_of_the_print_alone_is_a_finding(paper, label, old, new, before):
    d = registry.get(paper)
    f = next(f for f in d.published if f.label == label)
    assert old in f.latex
    assert _judged(d, f).verdict == before
    changed = _judged(d, replace(f, latex=f.latex.replace(old, new)))
    assert changed.verdict == NOT_THE_PRINT and changed.machine_read.status == "differs"
    assert changed.cause.id == "transcription-not-the-print"
    assert "the transcription checked is not the print" in changed.detail
    assert f"on the transcription the audit gave {before}" in changed.detail
    assert json.loads(as_json([changed]))[0]["verdict"] == NOT_THE_PRINT
    assert "transcription-not-the-print" in as_table([changed])
    assert "### transcription-not-the-print" in as_markdown([changed])


def test_an_explained_difference_keeps_its_verdict():
    d = registry.get("000")
    f = next(f for f in d.published if f.label == "initial stretch")
    r = _judged(d, f)
    assert r.machine_read.status == "differs" and r.machine_read.explained_by
    assert r.verdict != NOT_THE_PRINT


@pytest.fixture(scope="module", params=registry.ids())
def paper(request):
    d = registry.get(request.param)
    return d, audit(d)


def test_every_printed_item_has_a_record(paper):
    d, records = paper
    found = recall(d, records)
    assert found.items == len(d.printed_items) > 0
    assert found.with_record == found.items, found.missing
    assert not found.unlisted, found.unlisted
    assert found.text().startswith(f"{d.id}: printed items: {found.items}, with a record: "
                                   f"{found.items}")


def test_the_recall_counts_the_print_not_the_records(paper):
    d, records = paper
    item = d.printed_items[0]
    kept = [r for r in records if not item.judged_by(r.label)]
    found = recall(d, kept)
    assert found.items == len(d.printed_items)
    assert item.item in found.missing and found.with_record == found.items - 1


def test_coverage_is_counted_for_formulas_and_numbers_apart(paper):
    _, records = paper
    every = machine_read_coverage(records)
    formulas = machine_read_coverage(records, "formula")
    numbers = machine_read_coverage(records, "number")
    nothing = sum(r.machine_read.subject == "nothing transcribed" for r in records)
    assert sum(every.values()) == sum(formulas.values()) + sum(numbers.values()) + nothing
    assert all(r.machine_read.as_dict()["subject"] == r.machine_read.subject for r in records)


@pytest.mark.parametrize("paper, label, subject", [
    ("000", "(13)", "formula"), ("003", "Form 1, d_a1 = 280.536", "number"),
    ("001", "conclusions 890 %", "number"), ("003", "Table 2, wind load, vertical pressure, %",
                                             "nothing transcribed")])
def test_what_a_record_transcribes(paper, label, subject):
    d = registry.get(paper)
    f = next(f for f in d.published if f.label == label)
    assert machine_read(d, f).subject == subject


def test_003s_lost_equations_and_tables_2_3_have_records():
    d = registry.get("003")
    records = {r.label: r for r in audit(d)}
    for label in ("(1)", "(2)"):
        assert records[label].reconstructed and records[label].verdict == "confirmed"
        assert records[label].rests_on == "on a reconstruction"
    tables = [r for k, r in records.items() if k.startswith(("Table 2,", "Table 3,"))]
    assert len(tables) == 26
    assert all(r.verdict == "not_checkable" and r.cause for r in tables)
