"""Audit records as a table, JSON or Markdown, with counts by verdict, basis and cause.

Every format shows what a record rests on: a transcription reconstructed from
OCR damage (and the OCR that survived), the basis note of a confirmation as of
a finding, the paper's declared reading, the sensitivity of a result of chosen
parameters, a check that repeats another record's, and the machine reading of
the print.
"""
from __future__ import annotations

import json
from collections import Counter
from typing import Sequence

from crane_sym.audit.verdicts import (AGREEMENTS, CONFIRMATIONS, CONSISTENT, RESTS_ON, VERDICTS,
                                      AuditRecord)
from crane_sym.markdown import markdown_table
from crane_sym.published import BASES, READINGS


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


def confirmations(records: Sequence[AuditRecord]) -> dict[str, int]:
    """What the confirmations rest on (``AuditRecord.rests_on``) -> how many, each
    check counted once (a record that repeats another's check is left out)."""
    found = Counter(r.rests_on for r in records
                    if r.verdict in CONFIRMATIONS and not r.duplicate_of)
    return {k: found.get(k, 0) for k in RESTS_ON}


def machine_read_coverage(records: Sequence[AuditRecord],
                          subject: str | None = None) -> dict[str, int]:
    """Machine reading -> number of records (agrees, differs, unreadable), of
    every record or of those whose transcription is ``subject`` (``number`` or
    ``formula``: a bare number read is no evidence that a formula was)."""
    found = Counter(r.machine_read.status for r in records if r.machine_read is not None
                    and subject in (None, r.machine_read.subject))
    return {k: found.get(k, 0) for k in ("agrees", "differs", "unreadable")}


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
    """One paragraph: verdict counts, confirmations by what they rest on,
    findings against causes, machine-read coverage."""
    c = counts(records)
    found = findings(records)
    causes = by_cause(records)
    on = confirmations(records)
    repeats = sum(1 for r in records if r.duplicate_of)
    parts = ["  ".join(f"{v}: {n}" for v, n in c.items()),
             f"{len(records)} records ({repeats} repeat an earlier record's check and are "
             f"counted once): {sum(on.values())} confirmations ("
             + ", ".join(f"{n} {k}" for k, n in on.items()) + "; "
             f"{c['confirmed_with_convention']} records under a named reading), "
             f"{c[CONSISTENT]} consistent (with a reconstruction only through chosen "
             f"parameters, or under one of two readings; not counted as confirmations), "
             f"{c['restated']} restated definitions (not counted as confirmations), "
             f"{len(found)} findings from {len(causes)} causes"]
    for verdict in VERDICTS:
        rs = [r for r in found if r.verdict == verdict]
        if rs:
            n = len({r.cause.id for r in rs})
            extra = " (definitions whose print needed a reading)" if verdict in AGREEMENTS else ""
            parts.append(f"{len(rs)} {verdict} record{'s' if len(rs) > 1 else ''}{extra} "
                         f"from {n} cause{'s' if n > 1 else ''}")
    for subject in ("formula", "number"):
        read = machine_read_coverage(records, subject)
        if sum(read.values()):
            parts.append(f"machine-read prints of {subject}s: "
                         + ", ".join(f"{n} {k}" for k, n in read.items()))
    return "\n".join(parts)


def as_json(records: Sequence[AuditRecord]) -> str:
    """A JSON list of records; each has derivation, label, verdict, method, basis,
    basis_note, cause (id and sentence, or null when nothing is found), detail,
    printed (LaTeX), transcription, note, target, paper_reading, sensitivity,
    duplicate_of, rests_on (of a confirmation), machine_read, literal (the print
    as printed), readings (tried after it), point (of a numeric failure) and checks."""
    return json.dumps([r.as_dict() for r in records], indent=2, ensure_ascii=False)


def _flat(text: str) -> str:
    return " ".join(str(text).split())


def rests_on_lines(r: AuditRecord) -> list[str]:
    """What the record rests on beyond its verdict, one phrase each: the OCR a
    reconstruction was read from, the basis note, the paper's reading, the
    sensitivity, a repeated check, the machine reading."""
    lines = []
    if r.reconstructed:
        lines.append(f"transcription reconstructed from OCR damage; the OCR kept: "
                     f"«{_flat(r.printed)}»")
    if r.basis_note:
        lines.append(f"rests on the {r.basis}: {_flat(r.basis_note)}")
    if r.paper_reading:
        lines.append(f"uses the paper's declared reading: {r.paper_reading}")
    if r.sensitivity is not None:
        lines.append(f"sensitivity to the chosen parameters: {r.sensitivity.text()}")
    if r.duplicate_of:
        lines.append(f"the same check as {r.duplicate_of} (counted once)")
    if r.machine_read is not None:
        lines.append(f"machine-read: {r.machine_read.text()}")
    return lines


def as_table(records: Sequence[AuditRecord], width: int = 90) -> str:
    """Fixed-width text table, each column as wide as its widest entry, detail
    cut to fit, each row followed by what it rests on (indented), then the
    counts."""
    rows = [(r.derivation, r.label, r.verdict, r.basis, r.cause.id if r.cause else "—",
             r.method) for r in records]
    names = ("derivation", "label", "verdict", "basis", "cause", "method")
    widths = [max(len(text) for text in column) for column in zip(names, *rows)]

    def line(cells: Sequence[str], detail: str) -> str:
        return " ".join(f"{c:<{w}}" for c, w in zip(cells, widths)) + " " + detail
    head = line(names, "detail")
    lines = [head, "-" * len(head)]
    for r, cells in zip(records, rows):
        detail = r.detail if len(r.detail) <= width else r.detail[:width - 1] + "…"
        lines.append(line(cells, detail))
        lines += [f"{'':<{widths[0] + 2}}↳ {text}" for text in rests_on_lines(r)]
    lines += ["", summary(records)]
    return "\n".join(lines)


def _md(text: str) -> str:
    return text.replace("|", "\\|").replace("\n", " ")


def _finding_details(r: AuditRecord) -> list[str]:
    lines = [f"- **{r.derivation} {r.label}**: **{r.verdict}** (decided by {r.method}; "
             f"basis: {r.basis}" + (f" — {r.basis_note}" if r.basis_note else "") + ")",
             (f"  - reconstructed from OCR damage; the OCR kept: ${r.printed}$"
              if r.reconstructed else f"  - printed: ${r.printed}$") if r.printed
             else "  - printed: —",
             f"  - transcriber's note: {r.note}"]
    lines += [f"  - {line}" for line in rests_on_lines(r)[1 if r.reconstructed else 0:]
              if not line.startswith("rests on the ")]
    for a in r.attempts:
        head = ("as reconstructed" if r.reconstructed else "as printed") \
            if a.reading == "literal" else f"read with the {a.reading} '{a.note}'"
        lines.append(f"  - {head}: {a.summary}")
        lines.append(f"    - derived: ${a.derived}$")
        if a.difference:
            lines.append(f"    - difference (printed − derived): ${a.difference}$")
    if not r.attempts:
        lines.append(f"  - {r.detail}")
    return lines


def as_markdown(records: Sequence[AuditRecord]) -> str:
    """Findings grouped by cause, each with what a reviewer needs to recompute
    it; then the table of every record with what it rests on; then the counts."""
    on = confirmations(records)
    lines = ["# Audit", "", "## Counts", "", "```", summary(records), "```", "",
             markdown_table(["verdict", *BASES],
                            [[verdict, *(row.get(b, 0) for b in BASES)]
                             for verdict, row in counts_by_basis(records).items()])]
    lines += ["", "Confirmations, each check counted once: "
              + ", ".join(f"{n} {k}" for k, n in on.items()) + "."]
    lines += ["", "## Findings by cause", ""]
    for cause_id, group in by_cause(records).items():
        lines += [f"### {cause_id} ({len(group)} record{'s' if len(group) > 1 else ''})", "",
                  group[0].cause.sentence, ""]
        for r in group:
            lines += _finding_details(r)
        lines.append("")
    lines += ["## Every record", "", markdown_table(
        ["derivation", "label", "verdict", "basis", "cause", "decided by", "transcription",
         "rests on", "detail"],
        [[r.derivation, _md(r.label), f"**{r.verdict}**", r.basis,
          r.cause.id if r.cause else "—", r.method, r.transcription,
          _md("; ".join(rests_on_lines(r)) or "—"), _md(r.detail)] for r in records])]
    lines += ["", "## The reading policy", ""]
    lines += [f"- **{kind}**: {what}" for kind, what in READINGS.items()]
    return "\n".join(lines)


FORMATS = {"table": as_table, "json": as_json, "markdown": as_markdown}
