"""Audit records as a table, JSON or Markdown."""
from __future__ import annotations

import json
from collections import Counter
from typing import Sequence

from .audit import VERDICTS, AuditRecord


def counts(records: Sequence[AuditRecord]) -> dict[str, int]:
    """Verdict -> number of records, every verdict kind listed."""
    found = Counter(r.verdict for r in records)
    return {v: found.get(v, 0) for v in VERDICTS}


def as_json(records: Sequence[AuditRecord]) -> str:
    """A JSON list of objects with keys derivation, label, verdict, method,
    detail (and the individual checks)."""
    return json.dumps([r.as_dict() for r in records], indent=2, ensure_ascii=False)


def as_table(records: Sequence[AuditRecord], width: int = 100) -> str:
    """Fixed-width text table, detail cut to fit, then the counts."""
    head = f"{'derivation':<16} {'label':<26} {'verdict':<26} {'method':<10} detail"
    lines = [head, "-" * len(head)]
    for r in records:
        detail = r.detail if len(r.detail) <= width else r.detail[:width - 1] + "…"
        lines.append(f"{r.derivation:<16} {r.label:<26} {r.verdict:<26} {r.method:<10} {detail}")
    lines.append("")
    lines.append("  ".join(f"{v}: {n}" for v, n in counts(records).items()))
    return "\n".join(lines)


def as_markdown(records: Sequence[AuditRecord]) -> str:
    """Markdown table with full details."""
    lines = ["| derivation | label | verdict | decided by | detail |",
             "| --- | --- | --- | --- | --- |"]
    for r in records:
        detail = r.detail.replace("|", "\\|").replace("\n", " ")
        lines.append(f"| {r.derivation} | {r.label} | **{r.verdict}** | {r.method} | {detail} |")
    lines.append("")
    lines.append(", ".join(f"{v}: {n}" for v, n in counts(records).items()))
    return "\n".join(lines)


FORMATS = {"table": as_table, "json": as_json, "markdown": as_markdown}
