"""The audit's policy, pinned on every paper: bases, readings, causes, mutations.

- a ``definition`` record is never counted as a confirmation;
- a reading always leaves the literal check in the record, and is named there;
- every finding has a cause the transcriber gave, one sentence per cause id;
- a transcription mutated by scaling one term flips to a finding;
- every format shows what a record rests on (reconstruction, basis note);
- a result of chosen parameters is decided by their band, never confirmed, and
  only by a band that discriminates (README, "Labels by rule", rule 4);
- ``consistent`` is a band's or one reading's of two (rule 3), never else;
- every print is read by machine, a difference explained, coverage in the README.
"""
from __future__ import annotations

import json
from dataclasses import replace

import pytest
import sympy as sp

from crane_sym import registry
from crane_sym.audit.verdicts import (AGREEMENTS, CONFIRMATIONS, CONFIRMED_WITH_CONVENTION,
                                      CONSISTENT, RESTATED, UNEXPLAINED, audit, audit_formula)
from crane_sym.published import (BASES, CHOSEN, DEFINITION, MODEL, READINGS,
                                 PublishedFormula)
from crane_sym.audit.formats import as_json, as_markdown, as_table, by_cause, findings, summary

PAPERS = registry.ids()


@pytest.fixture(scope="module", params=PAPERS)
def paper(request):
    d = registry.get(request.param)
    return d, audit(d)


def test_every_record_has_a_basis_and_a_cause_key(paper):
    _, records = paper
    for item in json.loads(as_json(records)):
        assert item["basis"] in BASES, item["label"]
        assert "cause" in item, item["label"]
        assert item["basis"] == MODEL or item["basis_note"], item["label"]


def test_a_definition_is_never_a_confirmation(paper):
    _, records = paper
    for r in records:
        if r.basis == DEFINITION:
            assert r.verdict not in CONFIRMATIONS, r.label
        if r.verdict == RESTATED:
            assert r.basis == DEFINITION, r.label
    restated = sum(r.verdict == RESTATED for r in records)
    confirmations = sum(r.verdict in CONFIRMATIONS and not r.duplicate_of for r in records)
    assert f"{confirmations} confirmations" in summary(records)
    assert f"{restated} restated definitions (not counted" in summary(records)


def test_a_reading_keeps_the_literal_check(paper):
    _, records = paper
    for r in records:
        if r.reading is None:
            assert r.verdict != CONFIRMED_WITH_CONVENTION, r.label
            continue
        assert r.literal.reading == "literal" and not r.literal.matches, r.label
        assert r.reading is not None and r.reading.reading in READINGS, r.label
        assert set(r.literal.checks) <= set(r.checks), r.label
        assert r.detail.startswith(("as printed: ", "as reconstructed: ")), r.label
        assert f"Read with the {r.reading.reading}" in r.detail, r.label


def test_every_finding_has_a_cause(paper):
    _, records = paper
    for r in findings(records):
        assert r.cause is not None and r.cause.id != UNEXPLAINED, (r.label, r.verdict)
        assert r.cause.sentence.strip(), r.label
    for cause_id, group in by_cause(records).items():
        assert len({r.cause.sentence for r in group}) == 1, cause_id


def test_no_cause_is_declared_where_nothing_is_found(paper):
    d, records = paper
    for f, r in zip(d.published, records):
        if r.verdict in AGREEMENTS and r.reading is None:
            assert f.cause is None, f"{f.label}: declares {f.cause} but is {r.verdict}"
        if r.reading is not None:       # a reading is always a finding with its cause
            assert r.cause is not None and r.cause.id != UNEXPLAINED, f.label


def test_markdown_groups_findings_by_cause(paper):
    _, records = paper
    text = as_markdown(records)
    for cause_id, group in by_cause(records).items():
        assert f"### {cause_id} ({len(group)} record" in text
    for r in findings(records):
        if r.printed:
            shown = "the OCR kept: " if r.reconstructed else "printed: "
            assert f"{shown}${r.printed}$" in text, r.label


def test_every_format_shows_what_a_record_rests_on(paper):
    """A reconstruction is flagged with its OCR, and a basis note is shown for a
    confirmation as for a finding, in the table, the Markdown and the JSON; a
    reconstructed transcription is never described as "as printed"."""
    _, records = paper
    table, markdown = as_table(records), as_markdown(records)
    rows = {line for line in markdown.splitlines() if line.startswith("| ")}
    for r in records:
        label = r.label.replace("|", "\\|")
        row = next(line for line in rows if line.startswith(f"| {r.derivation} | {label} |"))
        if r.reconstructed:
            assert "reconstructed from OCR damage; the OCR kept" in row, r.label
            assert not r.detail.startswith("as printed"), r.label
            assert all(a.note != "the print as printed" for a in r.attempts), r.label
        if r.basis_note:
            assert " ".join(r.basis_note.split())[:60] in row, r.label
        assert r.as_dict()["transcription"] == r.transcription
    for r in records:
        if r.reconstructed:
            assert f"the OCR kept: «{' '.join(r.printed.split())}»" in table, r.label
        if r.basis_note:
            assert f"rests on the {r.basis}: {' '.join(r.basis_note.split())}"[:80] in table


def _scaled(relation: sp.Eq) -> sp.Eq:
    """The relation with one term scaled by 3/2 (``X = 0`` becomes ``X = 1``)."""
    for side in ("rhs", "lhs"):
        terms = sp.Add.make_args(getattr(relation, side))
        if len(terms) > 1:
            new = sp.Add(terms[0] * sp.Rational(3, 2), *terms[1:])
            return (sp.Eq(relation.lhs, new, evaluate=False) if side == "rhs"
                    else sp.Eq(new, relation.rhs, evaluate=False))
    if relation.rhs == 0:
        return sp.Eq(relation.lhs, 1, evaluate=False)
    return sp.Eq(relation.lhs, relation.rhs * sp.Rational(3, 2), evaluate=False)


def test_a_mutated_transcription_flips_to_a_finding(paper):
    d, records = paper
    checked = 0
    for f, r in zip(d.published, records):
        if r.verdict not in AGREEMENTS + (CONFIRMED_WITH_CONVENTION,):
            continue
        bad = replace(f, printed=_scaled(f.printed), conventions=tuple(
            replace(c, reading=_scaled(c.reading)) if isinstance(c.reading, sp.Equality)
            else c for c in f.conventions))
        again = audit_formula(d, bad)
        assert again.verdict not in AGREEMENTS + (CONFIRMED_WITH_CONVENTION,), f.label
        checked += 1
    assert checked > 0


def test_a_toy_definition_is_restated_and_its_mutation_is_found():
    d = registry.get(PAPERS[0])
    f = next(f for f in d.published if f.printed is not None and f.basis == MODEL
             and audit_formula(d, f).verdict == "confirmed")
    as_definition = replace(f, basis=DEFINITION, basis_note="toy: adopted")
    assert audit_formula(d, as_definition).verdict == RESTATED
    with pytest.raises(ValueError, match="basis_note"):
        PublishedFormula("(x)", "", f.printed, "toy", basis=DEFINITION)


def test_every_record_is_read_by_machine(paper):
    """Every record carries its machine reading; a difference from the hand
    transcription is explained by a labelled reconstruction or a named reading."""
    _, records = paper
    for r in records:
        read = r.machine_read
        assert read is not None and read.status in ("agrees", "differs", "unreadable"), r.label
        assert read.detail, r.label
        if read.status == "differs":
            assert read.explained_by, f"{r.label}: unexplained difference: {read.detail}"
        assert r.as_dict()["machine_read"]["status"] == read.status


def _readme_coverage() -> dict[str, dict[str, int]]:
    """The machine-read coverage table of the README, paper id -> counts."""
    from pathlib import Path
    text = (Path(__file__).resolve().parents[1] / "README.md").read_text(encoding="utf-8")
    rows = {}
    for line in text.splitlines():
        cells = [c.strip(" `") for c in line.strip().strip("|").split("|")]
        if len(cells) == 6 and cells[1] in registry.ids():
            rows[cells[1]] = dict(zip(("agrees", "differs", "unreadable"),
                                      map(int, cells[2:5])))
    return rows


def test_readme_states_the_machine_read_coverage(paper):
    from crane_sym.audit.formats import machine_read_coverage
    d, records = paper
    assert _readme_coverage().get(d.id) == machine_read_coverage(records)


def test_chosen_parameters_never_confirm(paper):
    """A number that only a model with chosen parameters gives is decided by the
    band those parameters span, stated in the record: consistent or a discrepancy,
    never a confirmation and never a remark."""
    d, records = paper
    for f, r in zip(d.published, records):
        chosen = f.printed is not None and d.step(f.target).sensitivity is not None
        assert chosen == (f.kind == CHOSEN), f.label
        if chosen:
            assert r.verdict in (CONSISTENT, "discrepancy", "not_checkable"), f.label
            low, high = r.sensitivity.band
            assert f"band {low:.4g}–{high:.4g}" in r.detail and "Sensitivity:" in r.detail
            assert r.as_dict()["sensitivity"]["parameters"], f.label
            slips = [k * float(f.printed.rhs) for k in (2, 0.5, 10, 0.1)]
            wide = any(low - f.tolerance * abs(low) <= x <= high + f.tolerance * abs(high)
                       for x in slips)
            assert (r.verdict == "not_checkable") == wide, f.label
        if r.verdict == CONSISTENT:
            one_reading = f.paper_reading is not None and f.label in f.paper_reading.fixed_by
            assert (chosen or one_reading) and r.verdict not in CONFIRMATIONS, f.label
