"""The vocabulary of an audit's verdicts and the record of one (:class:`AuditRecord`):
the verdicts, what a confirmation rests on, one reading of the print
(:class:`Attempt`) and their JSON-ready forms.
:mod:`crane_sym.audit.verdicts` decides them.
"""
from __future__ import annotations

from dataclasses import dataclass, field

from crane_sym.audit.checks import CheckOutcome
from crane_sym.audit.machine_read import MachineRead
from crane_sym.published import INTERNAL, READINGS, RECONSTRUCTED, Cause
from crane_sym.sensitivity import Sensitivity

CONFIRMED = "confirmed"
CONFIRMED_WITH_CONVENTION = "confirmed_with_convention"
RESTATED = "restated"
CONSISTENT = "consistent"
DISCREPANCY = "discrepancy"
DIMENSION_ERROR = "dimension_error"
NOT_CHECKABLE = "not_checkable"
REMARK = "remark"
#: The print read by machine differs from the transcription checked, unexplained.
NOT_THE_PRINT = "not_the_print"
VERDICTS = (CONFIRMED, CONFIRMED_WITH_CONVENTION, RESTATED, CONSISTENT, DISCREPANCY,
            DIMENSION_ERROR, NOT_CHECKABLE, REMARK, NOT_THE_PRINT)
#: Verdicts that hold nothing to report: no cause.
AGREEMENTS = (CONFIRMED, RESTATED)
#: Verdicts that count as confirmations (never a ``definition`` record, never a
#: number reproduced only through chosen parameters: that is ``consistent``).
CONFIRMATIONS = (CONFIRMED, CONFIRMED_WITH_CONVENTION)
#: What a confirmation rests on, as the summary counts them (``AuditRecord.rests_on``).
ON_MODEL = "on the model"
ON_PAPER = "on the paper itself"
ON_RECONSTRUCTION = "on a reconstruction"
ON_READING = "on a reading"
RESTS_ON = (ON_MODEL, ON_PAPER, ON_RECONSTRUCTION, ON_READING)
#: The cause given to a finding whose formula names none (a test forbids it).
UNEXPLAINED = "unexplained"
#: How a record's transcription is described: a reconstruction is never "as printed".
AS_PRINTED, AS_RECONSTRUCTED = "as printed", "as reconstructed"
#: The attempt of a record's rejected reading (``PublishedFormula.rejected_target``).
REJECTED = "rejected reading"


@dataclass(frozen=True)
class Attempt:
    """One reading of the print (the literal one first) against the derivation."""

    reading: str            # "literal" or the policy's reading kind
    note: str               # what the reading is
    matches: bool           # same relation and consistent dimensions
    summary: str            # one sentence on how it came out
    derived: str            # LaTeX of the derived relation it was compared with
    difference: str         # LaTeX of the simplified difference ("" if none or too big)
    checks: tuple[CheckOutcome, ...]

    def as_dict(self) -> dict:
        """JSON-ready form."""
        return {"reading": self.reading, "note": self.note, "matches": self.matches,
                "summary": self.summary, "derived": self.derived,
                "difference": self.difference,
                "checks": [_check_dict(c) for c in self.checks]}


@dataclass(frozen=True)
class AuditRecord:
    """The verdict on one published formula, with what it rests on."""

    derivation: str
    label: str
    verdict: str
    method: str
    detail: str
    checks: tuple[CheckOutcome, ...] = field(default=())
    basis: str = "model"
    basis_note: str = ""
    cause: Cause | None = None
    printed: str = ""                       # LaTeX as printed
    note: str = ""                          # the transcriber's note (provenance)
    attempts: tuple[Attempt, ...] = ()      # literal first, then readings tried
    reconstructed: bool = False             # the print was rebuilt from OCR damage
    sensitivity: Sensitivity | None = None  # of a result of chosen parameters
    paper_reading: str = ""                 # the paper's declared reading it uses
    duplicate_of: str = ""                  # label of an earlier record, same check
    target: str = ""                        # the derived step it is checked against
    machine_read: MachineRead | None = None  # the print read by machine

    @property
    def transcription(self) -> str:
        """``"reconstructed from OCR damage"`` or ``"as printed"``."""
        return "reconstructed from OCR damage" if self.reconstructed else AS_PRINTED

    @property
    def literal(self) -> Attempt | None:
        """How the print as printed came out (kept even when a reading decides)."""
        return self.attempts[0] if self.attempts else None

    @property
    def reading(self) -> Attempt | None:
        """The reading of the policy that decided a ``confirmed_with_convention``
        verdict (never the rejected reading of the paper's declared one)."""
        return next((a for a in self.attempts[1:] if a.matches and a.reading in READINGS),
                    None)

    @property
    def rests_on(self) -> str:
        """What a confirmation rests on: a reconstruction (of the print or of the
        model) before a reading (of the policy, or the paper's declared one),
        before the paper against itself, before the model."""
        if self.reconstructed or self.basis == RECONSTRUCTED:
            return ON_RECONSTRUCTION
        if self.verdict == CONFIRMED_WITH_CONVENTION or self.paper_reading:
            return ON_READING
        return ON_PAPER if self.basis == INTERNAL else ON_MODEL

    @property
    def point(self) -> tuple[tuple[str, str], ...]:
        """The sampled point at which the literal print fails numerically."""
        lit = self.literal
        return next((c.point for c in lit.checks if c.point), ()) if lit else ()

    def as_dict(self) -> dict:
        """JSON-ready form."""
        return {"derivation": self.derivation, "label": self.label,
                "verdict": self.verdict, "method": self.method,
                "basis": self.basis, "basis_note": self.basis_note,
                "cause": ({"id": self.cause.id, "sentence": self.cause.sentence}
                          if self.cause else None),
                "detail": self.detail, "printed": self.printed,
                "transcription": self.transcription,
                "note": self.note, "target": self.target,
                "paper_reading": self.paper_reading or None,
                "sensitivity": _sensitivity_dict(self.sensitivity),
                "duplicate_of": self.duplicate_of or None,
                "rests_on": self.rests_on if self.verdict in CONFIRMATIONS else None,
                "machine_read": (self.machine_read.as_dict()
                                 if self.machine_read is not None else None),
                "literal": self.literal.as_dict() if self.literal else None,
                "readings": [a.as_dict() for a in self.attempts[1:]],
                "point": dict(self.point),
                "checks": [_check_dict(c) for c in self.checks]}


def _sensitivity_dict(s: Sensitivity | None) -> dict | None:
    if s is None:
        return None
    low, high = s.band
    ends = {f"{end}_at": {"value": e.value, "by": e.by,
                          "parameters": {p.key: v for p, v in zip(s.parameters, e.at)}}
            for end, e in zip(("lowest", "highest"), s.extremes)}
    return {"value": s.value, "band": [low, high], "tolerance": s.spread, "how": s.how,
            "parameters": [{"name": p.name, "key": p.key, "unit": p.unit,
                            "chosen": p.chosen, "plausible": [p.low, p.high], "why": p.why}
                           for p in s.parameters], **ends}


def _check_dict(c: CheckOutcome) -> dict:
    out = {"method": c.method, "status": c.status, "detail": c.detail}
    if c.point:
        out["point"] = dict(c.point)
    return out


__all__ = ["AGREEMENTS", "AS_PRINTED", "AS_RECONSTRUCTED", "CONFIRMATIONS", "CONFIRMED",
           "CONFIRMED_WITH_CONVENTION", "CONSISTENT", "DIMENSION_ERROR", "DISCREPANCY",
           "NOT_CHECKABLE", "NOT_THE_PRINT", "ON_MODEL", "ON_PAPER", "ON_READING",
           "ON_RECONSTRUCTION", "REJECTED", "REMARK", "RESTATED", "RESTS_ON", "UNEXPLAINED",
           "VERDICTS", "Attempt", "AuditRecord"]
