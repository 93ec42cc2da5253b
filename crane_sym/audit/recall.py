"""Recall of the print: how many of a paper's printed items have a record.

A paper lists the items of its print (``Derivation.printed_items``: every
numbered equation, table cell and number its text states as a result), each
naming the records that judge it. The recall counts those items, not the
records, so an item the audit forgot shows as missing; a record that judges no
item of the inventory shows too (the inventory is then incomplete).
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Sequence

from crane_sym.derivation import Derivation
from crane_sym.audit.verdicts import AuditRecord

__all__ = ["Recall", "recall"]


@dataclass(frozen=True)
class Recall:
    """One paper's printed items against its records."""

    paper: str
    items: int
    with_record: int
    missing: tuple[str, ...]      # items no record judges
    unlisted: tuple[str, ...]     # records that judge no item of the inventory

    def text(self) -> str:
        """One line: ``<paper>: printed items: N, with a record: M`` and what is off."""
        line = f"{self.paper}: printed items: {self.items}, with a record: {self.with_record}"
        if self.missing:
            line += "; without a record: " + ", ".join(self.missing)
        if self.unlisted:
            line += "; records of no listed item: " + ", ".join(self.unlisted)
        return line

    def as_dict(self) -> dict:
        """JSON-ready form."""
        return {"paper": self.paper, "printed_items": self.items,
                "with_a_record": self.with_record, "missing": list(self.missing),
                "unlisted": list(self.unlisted)}


def recall(d: Derivation, records: Sequence[AuditRecord]) -> Recall:
    """The recall of ``d``'s print by ``records``.

    Parameters
    ----------
    d : Derivation
        The built paper, its ``printed_items`` the inventory of its print.
    records : sequence of AuditRecord
        Its audit's records.

    Examples
    --------
    >>> from crane_sym import registry
    >>> from crane_sym.audit.verdicts import audit
    >>> d = registry.get("travel_braking")
    >>> recall(d, audit(d)).text()
    'travel_braking: printed items: 16, with a record: 16'
    """
    labels = [r.label for r in records if r.derivation == d.id]
    missing = tuple(i.item for i in d.printed_items
                    if not any(i.judged_by(label) for label in labels))
    unlisted = tuple(label for label in labels
                     if not any(i.judged_by(label) for i in d.printed_items))
    return Recall(d.id, len(d.printed_items), len(d.printed_items) - len(missing),
                  missing, unlisted)
