"""Audit records as a table, JSON or Markdown, with counts by verdict, basis and cause."""
from __future__ import annotations

import json
from collections import Counter
from typing import Sequence

from .audit import AGREEMENTS, CONFIRMATIONS, VERDICTS, AuditRecord
from .published import BASES, READINGS


def counts(records: Sequence[AuditRecord]) -> dict[str, int]:
    """Verdict -> number of records, every verdict kind listed."""
    found = Counter(r.verdict for r in records)
    return {v: found.get(v, 0) for v in VERDICTS}


def counts_by_basis(records: Sequence[AuditRecord]) -> dict[str, dict[str, int]]:
    """Verdict -> basis -> number of records (only the pairs that occur)."""
    table: dict[str, dict[str, int]] = {}
    for r in records:
        table.setdefault(r.verdict, {}).setdefault(r.basis, 0)
        table[r.verdict][r.basis] += 1
    return {v: table[v] for v in VERDICTS if v in table}


def findings(records: Sequence[AuditRecord]) -> list[AuditRecord]:
    """Records with something to report: every verdict but confirmed and
    restated, and a restated definition whose print needed a reading."""
    return [r for r in records if r.cause is not None]


def by_cause(records: Sequence[AuditRecord]) -> dict[str, list[AuditRecord]]:
    """Cause id -> its findings, in the order the causes first occur."""
    groups: dict[str, list[AuditRecord]] = {}
    for r in findings(records):
        groups.setdefault(r.cause.id, []).append(r)
    return groups


def summary(records: Sequence[AuditRecord]) -> str:
    """One paragraph: verdict counts, confirmations, findings against causes."""
    c = counts(records)
    found = findings(records)
    causes = by_cause(records)
    confirmations = sum(c[v] for v in CONFIRMATIONS)
    parts = ["  ".join(f"{v}: {n}" for v, n in c.items()),
             f"{len(records)} records: {confirmations} confirmations "
             f"({c['confirmed_with_convention']} of them under a named reading), "
             f"{c['restated']} restated definitions (not counted as confirmations), "
             f"{len(found)} findings from {len(causes)} causes"]
    for verdict in VERDICTS:
        rs = [r for r in found if r.verdict == verdict]
        if rs:
            n = len({r.cause.id for r in rs})
            extra = " (definitions whose print needed a reading)" if verdict in AGREEMENTS else ""
            parts.append(f"{len(rs)} {verdict} record{'s' if len(rs) > 1 else ''}{extra} "
                         f"from {n} cause{'s' if n > 1 else ''}")
    return "\n".join(parts)


def as_json(records: Sequence[AuditRecord]) -> str:
    """A JSON list of records; each has derivation, label, verdict, method, basis,
    basis_note, cause (id and sentence, or null when nothing is found), detail,
    printed (LaTeX), note, literal (the print as printed), readings (tried
    after it), point (of a numeric failure) and checks."""
    return json.dumps([r.as_dict() for r in records], indent=2, ensure_ascii=False)


def as_table(records: Sequence[AuditRecord], width: int = 90) -> str:
    """Fixed-width text table, detail cut to fit, then the counts."""
    head = (f"{'derivation':<15} {'label':<26} {'verdict':<26} {'basis':<20} "
            f"{'cause':<24} {'method':<9} detail")
    lines = [head, "-" * len(head)]
    for r in records:
        detail = r.detail if len(r.detail) <= width else r.detail[:width - 1] + "…"
        cause = r.cause.id if r.cause else "—"
        lines.append(f"{r.derivation:<15} {r.label:<26} {r.verdict:<26} {r.basis:<20} "
                     f"{cause:<24} {r.method:<9} {detail}")
    lines += ["", summary(records)]
    return "\n".join(lines)


def _md(text: str) -> str:
    return text.replace("|", "\\|").replace("\n", " ")


def _finding_details(r: AuditRecord) -> list[str]:
    lines = [f"- **{r.derivation} {r.label}**: **{r.verdict}** (decided by {r.method}; "
             f"basis: {r.basis}" + (f" — {r.basis_note}" if r.basis_note else "") + ")",
             f"  - printed: ${r.printed}$" if r.printed else "  - printed: —",
             f"  - transcriber's note: {r.note}"]
    for a in r.attempts:
        head = "as printed" if a.reading == "literal" else f"read with the {a.reading} '{a.note}'"
        lines.append(f"  - {head}: {a.summary}")
        lines.append(f"    - derived: ${a.derived}$")
        if a.difference:
            lines.append(f"    - difference (printed − derived): ${a.difference}$")
    if not r.attempts:
        lines.append(f"  - {r.detail}")
    return lines


def as_markdown(records: Sequence[AuditRecord]) -> str:
    """Findings grouped by cause, each with what a reviewer needs to recompute
    it; then the table of every record; then the counts."""
    lines = ["# Audit", "", "## Counts", "", "```", summary(records), "```", "",
             "| verdict | " + " | ".join(BASES) + " |",
             "| --- |" + " --- |" * len(BASES)]
    for verdict, row in counts_by_basis(records).items():
        lines.append(f"| {verdict} | " + " | ".join(str(row.get(b, 0)) for b in BASES) + " |")
    lines += ["", "## Findings by cause", ""]
    for cause_id, group in by_cause(records).items():
        lines += [f"### {cause_id} ({len(group)} record{'s' if len(group) > 1 else ''})", "",
                  group[0].cause.sentence, ""]
        for r in group:
            lines += _finding_details(r)
        lines.append("")
    lines += ["## Every record", "",
              "| derivation | label | verdict | basis | cause | decided by | detail |",
              "| --- | --- | --- | --- | --- | --- | --- |"]
    for r in records:
        lines.append(f"| {r.derivation} | {_md(r.label)} | **{r.verdict}** | {r.basis} | "
                     f"{r.cause.id if r.cause else '—'} | {r.method} | {_md(r.detail)} |")
    lines += ["", "## The reading policy", ""]
    lines += [f"- **{kind}**: {what}" for kind, what in READINGS.items()]
    return "\n".join(lines)


FORMATS = {"table": as_table, "json": as_json, "markdown": as_markdown}
