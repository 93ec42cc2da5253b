"""A derivation as a Markdown walkthrough a student can follow.

The walkthrough goes from the mechanical model, through every step in the
paper's order (with what was done, why, and the formula as the paper printed
it beside its verdict), to a summary of the verdicts. Formulas are LaTeX:
``$...$`` inline and ``$$...$$`` on lines of their own for displays.

Both functions are pure: they return text and neither print nor write files.
"""
from __future__ import annotations

import re

import sympy as sp

from .audit import (CONFIRMED, CONFIRMED_WITH_CONVENTION, CONSISTENT, DIMENSION_ERROR,
                    DISCREPANCY, NOT_CHECKABLE, REMARK, RESTATED, AuditRecord, audit)
from .derivation import Derivation, Step
from .latex import cyrillic_as_text, latex
from .report import rests_on_lines
from .symbols import COORDINATE, DEFINED, PARAMETER, TIME

#: Roles whose symbols are always listed; DEFINED ones only when a step uses them.
_LISTED_ROLES = (PARAMETER, TIME, COORDINATE)


def _tex(expr: sp.Basic, latex_names: dict) -> str:
    """LaTeX of ``expr`` as a mechanics text writes it, with the paper's names."""
    return latex(expr, symbol_names=latex_names)


def _statement_tex(statement: sp.Basic, latex_names: dict) -> str:
    """``lhs = rhs`` for an equation; the plain LaTeX of anything else."""
    if isinstance(statement, sp.Equality):
        return (_tex(statement.lhs, latex_names) + " = "
                + _tex(statement.rhs, latex_names))
    return _tex(statement, latex_names)


def _display(tex: str) -> str:
    """A display formula with ``$$`` on lines of their own."""
    return f"$$\n{cyrillic_as_text(tex.strip())}\n$$"


def _cell(text: str) -> str:
    """Text safe inside a Markdown table cell."""
    return " ".join(str(text).split()).replace("|", r"\|")


def _math_cell(tex: str) -> str:
    """Inline math safe inside a table cell (``|`` written as ``\\vert``)."""
    return "$" + " ".join(cyrillic_as_text(tex).split()).replace("|", r"\vert ") + "$"


def _fenced(text: str) -> str:
    """``text`` verbatim in a code fence longer than any backtick run in it."""
    longest = max((len(run) for run in re.findall(r"`+", text)), default=0)
    fence = "`" * max(3, longest + 1)
    return f"{fence}text\n{text}\n{fence}"


def _model(model: str) -> str:
    """The model: prose paragraphs as text, indented paragraphs (the diagram)
    verbatim in a code block."""
    blocks = []
    for para in re.split(r"\n[ \t]*\n", model.strip("\n")):
        lines = [line.rstrip() for line in para.split("\n")]
        if not any(lines):
            continue
        if all(line[:1] in (" ", "\t") for line in lines if line):
            blocks.append(_fenced("\n".join(lines)))
        else:
            blocks.append(" ".join(line.strip() for line in lines if line.strip()))
    return "\n\n".join(blocks)


def _symbols(d: Derivation, latex_names: dict) -> str:
    """Table of the symbols the student meets (unused defined ones skipped)."""
    rows = ["| Symbol | Meaning | Unit |", "| --- | --- | --- |"]
    for entry in d.symbols:
        used = entry.role in _LISTED_ROLES or (
            entry.role == DEFINED and any(s.statement.has(entry.expr) for s in d.steps))
        if used:
            tex = _tex(entry.expr, latex_names)
            if isinstance(entry.expr, sp.core.function.AppliedUndef):
                tex += r"(" + ", ".join(latex(a) for a in entry.expr.args) + ")"
            rows.append(f"| {_math_cell(tex)} "
                        f"| {_cell(entry.description)} | {_cell(entry.unit)} |")
    return "\n".join(rows)


_SAYS = {
    CONFIRMED: "the print, as printed, follows from the derivation",
    CONFIRMED_WITH_CONVENTION: "as printed it does not follow; read as below, it does",
    RESTATED: "the step restates the printed definition, so nothing could fail",
    CONSISTENT: "the reconstruction reproduces it only through parameters the paper does "
                "not state; the printed number lies in the band they span (not a "
                "confirmation)",
    DISCREPANCY: "the print does not follow from the derivation",
    DIMENSION_ERROR: "a term of the print has the wrong dimension",
    NOT_CHECKABLE: "nothing checkable was printed",
    REMARK: "a modelling choice the paper states that differs from what the model implies",
}
#: What a verdict says of a transcription reconstructed from OCR damage.
_SAYS_RECONSTRUCTED = {
    CONFIRMED: "the print as reconstructed from OCR damage follows from the derivation",
    CONFIRMED_WITH_CONVENTION: "as reconstructed it does not follow; read as below, it does",
    DISCREPANCY: "the print as reconstructed does not follow from the derivation",
}


def _verdict_line(record: AuditRecord) -> str:
    """The verdict in words: what it says, what decided it, what it rests on, and
    for a finding its cause, the reading, the difference and the offending terms."""
    rests = record.basis + (f" ({record.basis_note})" if record.basis_note else "")
    says = (_SAYS_RECONSTRUCTED if record.reconstructed else _SAYS).get(
        record.verdict, _SAYS[record.verdict])
    lines = [f"Verdict: **{record.verdict}** — {says} "
             f"(decided by the {record.method} check; rests on: {rests})."]
    lines += [f"- {line[0].upper()}{line[1:]}." for line in rests_on_lines(record)
              if not line.startswith("rests on the ")]     # the basis is said above
    reading = record.reading
    if reading is not None:
        lines.append(f"- Read with the {reading.reading}: {reading.note}.")
    if record.cause:
        lines.append(f"- Cause `{record.cause.id}`: {record.cause.sentence}")
    literal = record.literal
    if record.verdict in (CONFIRMED, RESTATED) or literal is None or reading is not None:
        return "\n".join(lines)
    dim = next((c for c in literal.checks
                if c.method == "dimension" and c.status == "fail"), None)
    if dim is not None:
        lines.append(f"- Dimensions: {dim.detail}.")
    elif literal.difference and len(literal.difference) <= _SHORT:
        lines.append(f"- Printed − derived: ${literal.difference}$.")
    return "\n".join(lines)


#: A difference longer than this (LaTeX characters) is left to ``crane-sym audit``.
_SHORT = 300


def _printed_blocks(formulas: list, by_label: dict[str, AuditRecord],
                    latex_names: dict | None = None) -> list[str]:
    """The paper's print of each formula, verbatim, with its verdict; a print
    rebuilt from OCR damage shows the OCR as text, then the reconstruction and why."""
    blocks = []
    latex_names = latex_names or {}
    for f in formulas:
        label = f.label if f.label.startswith("(") else f"({f.label})"
        if f.verbatim or (f.reconstructed and f.printed is not None):
            # OCR'd text of the print, then what it is read as, and why
            blocks.append(f"**As printed in the paper** {label}"
                          + (", the OCR verbatim:" if f.reconstructed else ":"))
            blocks.append(_fenced(f.latex.strip()))
            if f.printed is not None:
                blocks.append(f"**Read as** (a reconstruction; {f.provenance}):"
                              if f.reconstructed else "Transcribed:")
                blocks.append(_display(_statement_tex(f.printed, latex_names)))
        else:
            blocks.append(f"**As printed in the paper** {label}:")
            blocks.append(_display(f.latex))
        if f.label in by_label:
            blocks.append(_verdict_line(by_label[f.label]))
    return blocks


def _verdicts(d: Derivation, records: list[AuditRecord] | None) -> str:
    """Summary table: one row per audited (or, without records, published) formula."""
    rows = ["| Formula | Verdict | Decided by | Transcription | Rests on | Cause |",
            "| --- | --- | --- | --- | --- | --- |"]
    if records is None:
        rows += [f"| {_cell(f.label)} | not audited | — | — | — | — |" for f in d.published]
    else:
        rows += [f"| {_cell(r.label)} | {_cell(r.verdict)} | {_cell(r.method)} | "
                 f"{_cell(r.transcription)} | "
                 f"{_cell(r.basis + (': ' + r.basis_note if r.basis_note else ''))} | "
                 f"{_cell(r.cause.id) if r.cause else '—'} |"
                 for r in records]
    return "\n".join(rows)


def _step_head(k: int, step: Step) -> list[str]:
    """Heading, what was done and why, of step ``k`` (walkthrough and notebook)."""
    head = [f"### Step {k} — {step.label}" + (f" · {step.title}" if step.title else ""),
            f"**What was done.** {step.how}"]
    return head + ([f"**Why.** {step.why}"] if step.why else [])


_TABLE_STEP = re.compile(r"^(Table \d+), ")


def _table_groups(d: Derivation) -> dict[str, list]:
    """Table name -> the printed cells checked against its steps, in order."""
    groups: dict[str, list] = {}
    for f in d.published:
        m = _TABLE_STEP.match(f.target)
        if m and f.printed is not None:
            groups.setdefault(m.group(1), []).append(f)
    return groups


def _number(step: Step) -> str:
    value = step.statement.rhs
    return sp.sstr(sp.N(value, 6)) if value.is_number else f"${latex(value)}$"


def _table(name: str, cells: list, d: Derivation,
           by_label: dict[str, AuditRecord]) -> list[str]:
    """A printed table as one table: each cell beside its derived value and verdict."""
    readings = any(f.conventions for f in cells)
    head = "| cell | printed | derived" + (" | derived, read as noted" if readings else "")
    rows = [head + " | verdict | cause |",
            "| --- " * (5 + readings) + "|"]
    for f in cells:
        r = by_label.get(f.label)
        row = [_cell(f.label.removeprefix(name + ", ")), _cell(f.latex),
               _number(d.step(f.target))]
        if readings:
            row.append(_number(d.step(f.conventions[0].compare_to or f.target))
                       if f.conventions else "—")
        row += [_cell(r.verdict) if r else "not audited",
                f"`{r.cause.id}`" if r and r.cause else "—"]
        rows.append("| " + " | ".join(row) + " |")
    notes = {f.conventions[0].note for f in cells if f.conventions}
    causes = {r.cause.id: r.cause.sentence for f in cells
              if (r := by_label.get(f.label)) and r.cause}
    out = [f"### {name}", "\n".join(rows)]
    out += [f"*Read as noted:* {n}." for n in sorted(notes)]
    out += [f"*Cause* `{k}`: {v}" for k, v in causes.items()]
    return out


def render(d: Derivation, records: list[AuditRecord] | None = None,
           latex_names: dict | None = None) -> str:
    """The walkthrough of a derivation as Markdown with LaTeX.

    Parameters
    ----------
    d : Derivation
        The built derivation.
    records : list of AuditRecord, optional
        Verdicts from :func:`crane_sym.audit.audit`; without them the printed
        formulas are shown without verdicts and the summary says "not audited".
    latex_names : dict, optional
        Map from SymPy symbol to the LaTeX the paper uses for it.

    Returns
    -------
    str
        Markdown: title, model, symbols, every step in order, verdicts.
    """
    names = dict(d.latex_names) | dict(latex_names or {})
    by_label = {r.label: r for r in records or []}
    tables = _table_groups(d)
    in_table = {c.target: name for name, cells in tables.items() for c in cells}
    in_table |= {v.compare_to: name for name, cells in tables.items()
                 for c in cells for v in c.conventions if v.compare_to}
    shown: set[str] = set()
    parts = [f"# {d.title}", f"Paper: `{d.paper}` — {d.citation}",
             "## The model", _model(d.model),
             "## Symbols", _symbols(d, names),
             "## Derivation"]
    for k, step in enumerate(d.steps, start=1):
        if step.label in in_table:              # a table cell: one table for all
            name = in_table[step.label]
            if name not in shown:
                shown.add(name)
                parts += _table(name, tables[name], d, by_label)
            continue
        parts += _step_head(k, step)
        parts.append(_display(_statement_tex(step.statement, names)))
        parts += _printed_blocks([f for f in d.published if f.target == step.label
                                  and f.target not in in_table], by_label, names)
    labels = {s.label for s in d.steps}
    orphans = [f for f in d.published if f.target not in labels]
    if orphans:
        parts.append("### Printed formulas without a derived step")
        parts += _printed_blocks(orphans, by_label, names)
    parts += ["## Verdicts", _verdicts(d, records)]
    return "\n\n".join(parts) + "\n"


def walkthrough(name: str) -> str:
    """The walkthrough of a registered derivation, audited.

    Parameters
    ----------
    name : str
        A derivation id or paper number accepted by
        :func:`crane_sym.registry.resolve`.

    Returns
    -------
    str
        :func:`render` of the built derivation, with its audit records and
        the module's ``LATEX_NAMES`` (empty when the module defines none).
    """
    from . import registry

    key = registry.resolve(name)
    d = registry.get(key)
    latex_names = getattr(registry.module(key), "LATEX_NAMES", {})
    return render(d, audit(d), latex_names)
