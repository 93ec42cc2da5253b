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

from .audit import AuditRecord, audit
from .derivation import Derivation
from .symbols import COORDINATE, DEFINED, PARAMETER, TIME

#: Roles whose symbols are always listed; DEFINED ones only when a step uses them.
_LISTED_ROLES = (PARAMETER, TIME, COORDINATE)


def _tex(expr: sp.Basic, latex_names: dict) -> str:
    """LaTeX of ``expr`` with the derivation's own symbol names."""
    return sp.latex(expr, symbol_names=latex_names)


def _statement_tex(statement: sp.Basic, latex_names: dict) -> str:
    """``lhs = rhs`` for an equation; the plain LaTeX of anything else."""
    if isinstance(statement, sp.Equality):
        return (_tex(statement.lhs, latex_names) + " = "
                + _tex(statement.rhs, latex_names))
    return _tex(statement, latex_names)


def _display(tex: str) -> str:
    """A display formula with ``$$`` on lines of their own."""
    return f"$$\n{tex.strip()}\n$$"


def _cell(text: str) -> str:
    """Text safe inside a Markdown table cell."""
    return " ".join(str(text).split()).replace("|", r"\|")


def _math_cell(tex: str) -> str:
    """Inline math safe inside a table cell (``|`` written as ``\\vert``)."""
    return "$" + " ".join(tex.split()).replace("|", r"\vert ") + "$"


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
            rows.append(f"| {_math_cell(_tex(entry.expr, latex_names))} "
                        f"| {_cell(entry.description)} | {_cell(entry.unit)} |")
    return "\n".join(rows)


def _verdict_line(record: AuditRecord) -> str:
    """One sentence: the verdict, the check that decided it, and why."""
    line = (f"Verdict: **{record.verdict}** (decided by {record.method}; rests on: "
            f"{record.basis}" + (f", {record.basis_note}" if record.basis_note else "") + ")")
    if record.cause:
        line += f". Cause `{record.cause.id}`: {record.cause.sentence}"
    return line + (f" — {record.detail}" if record.detail else "")


def _printed_blocks(formulas: list, by_label: dict[str, AuditRecord],
                    latex_names: dict | None = None) -> list[str]:
    """The paper's print of each formula, verbatim, with its verdict; a print
    rebuilt from OCR damage shows the OCR as text, then the reconstruction and why."""
    blocks = []
    for f in formulas:
        label = f.label if f.label.startswith("(") else f"({f.label})"
        if f.reconstructed and f.printed is not None:
            blocks.append(f"**As printed in the paper** {label}, the OCR verbatim:")
            blocks.append(f"```text\n{f.latex.strip()}\n```")
            blocks.append(f"**Read as** (a reconstruction; {f.provenance}):")
            blocks.append(_display(_statement_tex(f.printed, latex_names or {})))
        else:
            blocks.append(f"**As printed in the paper** {label}:")
            blocks.append(_display(f.latex))
        if f.label in by_label:
            blocks.append(_verdict_line(by_label[f.label]))
    return blocks


def _verdicts(d: Derivation, records: list[AuditRecord] | None) -> str:
    """Summary table: one row per audited (or, without records, published) formula."""
    rows = ["| Formula | Verdict | Decided by | Rests on | Cause |",
            "| --- | --- | --- | --- | --- |"]
    if records is None:
        rows += [f"| {_cell(f.label)} | not audited | — | — | — |" for f in d.published]
    else:
        rows += [f"| {_cell(r.label)} | {_cell(r.verdict)} | {_cell(r.method)} | "
                 f"{_cell(r.basis)} | {_cell(r.cause.id) if r.cause else '—'} |"
                 for r in records]
    return "\n".join(rows)


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
    names = dict(latex_names or {})
    by_label = {r.label: r for r in records or []}
    parts = [f"# {d.title}", f"Paper: `{d.paper}` — {d.citation}",
             "## The model", _model(d.model),
             "## Symbols", _symbols(d, names),
             "## Derivation"]
    for k, step in enumerate(d.steps, start=1):
        heading = f"### Step {k} — {step.label}"
        parts.append(heading + (f" · {step.title}" if step.title else ""))
        parts.append(f"**What was done.** {step.how}")
        if step.why:
            parts.append(f"**Why.** {step.why}")
        parts.append(_display(_statement_tex(step.statement, names)))
        parts += _printed_blocks([f for f in d.published if f.target == step.label],
                                 by_label, names)
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
