"""Tests for crane_sym.docs.walkthrough against the real travel_braking derivation."""
import copy
import dataclasses
import re

import pytest
import sympy as sp

from crane_sym import registry
from crane_sym.audit.verdicts import NOT_CHECKABLE, AuditRecord, audit
from crane_sym.docs.verdicts import verdict_name
from crane_sym.published import PublishedFormula
from crane_sym.docs.walkthrough import render, walkthrough

ID = "travel_braking"


@pytest.fixture(scope="module")
def built():
    """The derivation, its audit and its walkthrough, built once."""
    d = registry.get(ID)
    records = audit(d)
    names = getattr(registry.module(ID), "LATEX_NAMES", {})
    return d, records, names, render(d, records, names)


def _section(text: str, heading: str) -> str:
    """The text of one ``## heading`` section."""
    start = text.index(f"## {heading}\n")
    end = text.find("\n## ", start + 1)
    return text[start:] if end < 0 else text[start:end]


def test_step_headings_in_order(built):
    d, _, _, text = built
    positions = []
    for k, step in enumerate(d.steps, start=1):
        match = re.search(rf"^### Step {k} — {re.escape(step.label)}( · .*)?$",
                          text, re.MULTILINE)
        assert match, f"no heading for step {k} {step.label!r}"
        if step.title:
            assert match.group(0).endswith(f" · {step.title}")
        positions.append(match.start())
    assert positions == sorted(positions)
    assert len(d.steps) == len(re.findall(r"^### Step \d+ — ", text, re.MULTILINE))


def test_sections_in_order(built):
    text = built[3]
    d = built[0]
    assert text.startswith(f"# {d.title}\n")
    assert d.citation in text.splitlines()[2] and d.paper not in text   # no file names
    order = [text.index(f"## {h}\n") for h in
             ("The model", "Symbols", "Derivation", "Verdicts")]
    assert order == sorted(order)


def test_every_numbered_label_printed(built):
    text = built[3]
    for n in range(1, 15):
        assert f"**As printed in the paper** ({n}):" in text


def test_every_how_and_why_appears(built):
    d, _, _, text = built
    for step in d.steps:
        assert f"**What was done.** {step.how}" in text
        if step.why:
            assert f"**Why.** {step.why}" in text


def test_printed_latex_verbatim(built):
    d, _, _, text = built
    latex6 = next(f.latex for f in d.published if f.label == "(6)")
    assert f"$$\n{latex6}\n$$" in text
    for f in d.published:
        assert f.latex.strip() in text


def test_statements_use_latex_names(built):
    _, _, names, text = built
    for tex in names.values():
        if tex in ("(x_2 - x_1)^*", r"F_{\max}", r"t_{\max}"):
            assert tex in _section(text, "Derivation")


def test_diagram_kept_verbatim(built):
    d, _, _, text = built
    model = _section(text, "The model")
    diagram = [line for line in d.model.splitlines() if line.startswith("  ")]
    assert diagram
    block = re.search(r"```text\n(.*?)\n```", model, re.DOTALL).group(1)
    assert block.splitlines() == diagram


def test_symbols_table(built):
    d, _, names, text = built
    table = _section(text, "Symbols")
    assert "$m_{1}$" in table and r"$x_{1}(t)$" in table
    assert "$(x_2 - x_1)^*$" in table
    assert "$P$" not in table  # defined, used only by the print, not by a step
    for entry in d.symbols.with_role("parameter", "time", "coordinate"):
        assert entry.description in table


def test_verdicts_in_summary_and_steps(built):
    _, records, _, text = built
    summary = _section(text, "Verdicts")
    for r in records:
        assert f"| {r.label} | {verdict_name(r.verdict)} | {r.method} | {r.transcription} " \
            f"| {r.basis} |" in summary
        assert f"Verdict: **{verdict_name(r.verdict)}** — " in text
        assert f"(decided by the {r.method} check; rests on: {r.basis}" in text
        if r.cause:       # stated in full once, then named by its letter
            assert text.count(f": {r.cause.sentence}") == 1
            assert re.search(rf"- Cause [A-Z]: {re.escape(r.cause.sentence)}", text)


def test_deterministic(built):
    d, records, names, text = built
    assert render(d, records, names) == text


def test_walkthrough_matches_render(built):
    assert walkthrough(ID) == built[3]
    assert walkthrough("000") == built[3]


def test_balanced_display_math_and_no_none(built):
    text = built[3]
    assert text.count("$$") % 2 == 0
    assert text.count("$$\n") == text.count("\n$$")
    assert "None" not in text


def test_without_records(built):
    d, _, _, _ = built
    text = render(d)
    assert "Verdict:" not in text
    assert "| (6) | not audited | — |" in text
    assert "None" not in text and text.count("$$") % 2 == 0


def test_published_without_step_is_listed():
    d = copy.copy(registry.get(ID))
    orphan = PublishedFormula("(99)", r"Q = 0", None, "nowhere",
                              not_checkable="no such step")
    d.published = list(d.published) + [orphan]
    records = [AuditRecord(d.id, "(99)", NOT_CHECKABLE, "none", "no such step")]
    text = render(d, records, {})
    assert "| (99) | not checkable | none |" in _section(text, "Verdicts")
    # with nothing to check, it is a row of the table of such items, its print beside it
    assert "| (99) | $Q = 0$ | — |" in _section(text, "Printed items with nothing to check")
    assert len(registry.get(ID).published) == len(d.published) - 1


def test_non_equation_statement_renders():
    d = copy.copy(registry.get(ID))
    d.steps = [dataclasses.replace(d.steps[0], statement=sp.true)]
    d.published = []
    text = render(d)
    assert "$$\n\\text{True}\n$$" in text
