"""Verdicts on published formulas, from checks that can fail.

For each published formula the audit runs the symbolic, numeric and dimension
checks on the print as transcribed and keeps that literal result in the record.
Only when the literal print fails does it try the formula's readings, and only
the kinds the reading policy allows (``published.READINGS``). The verdict
names the check that decided, the basis it rests on and, for a finding, its
cause.
"""
from __future__ import annotations

from dataclasses import dataclass, field

import sympy as sp

from . import progress
from .checks import (FAIL, INCONCLUSIVE, PASS, CheckOutcome, difference,
                     dimension_consistency, numeric_equivalence,
                     symbolic_equivalence)
from .derivation import Derivation
from .latex import latex
from .published import (ASSUMPTION, DEFINITION, Cause, Convention,
                        PublishedFormula)

CONFIRMED = "confirmed"
CONFIRMED_WITH_CONVENTION = "confirmed_with_convention"
RESTATED = "restated"
DISCREPANCY = "discrepancy"
DIMENSION_ERROR = "dimension_error"
NOT_CHECKABLE = "not_checkable"
REMARK = "remark"
VERDICTS = (CONFIRMED, CONFIRMED_WITH_CONVENTION, RESTATED, DISCREPANCY,
            DIMENSION_ERROR, NOT_CHECKABLE, REMARK)
#: Verdicts that hold nothing to report: no cause.
AGREEMENTS = (CONFIRMED, RESTATED)
#: Verdicts that count as confirmations (never a ``definition`` record).
CONFIRMATIONS = (CONFIRMED, CONFIRMED_WITH_CONVENTION)
#: The cause given to a finding whose formula names none (a test forbids it).
UNEXPLAINED = "unexplained"


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

    @property
    def literal(self) -> Attempt | None:
        """How the print as printed came out (kept even when a reading decides)."""
        return self.attempts[0] if self.attempts else None

    @property
    def reading(self) -> Attempt | None:
        """The reading that decided a ``confirmed_with_convention`` verdict."""
        return next((a for a in self.attempts[1:] if a.matches), None)

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
                "transcription": ("reconstructed from OCR damage" if self.reconstructed
                                  else "as printed"),
                "note": self.note,
                "literal": self.literal.as_dict() if self.literal else None,
                "readings": [a.as_dict() for a in self.attempts[1:]],
                "point": dict(self.point),
                "checks": [_check_dict(c) for c in self.checks]}


def _check_dict(c: CheckOutcome) -> dict:
    out = {"method": c.method, "status": c.status, "detail": c.detail}
    if c.point:
        out["point"] = dict(c.point)
    return out


@dataclass(frozen=True)
class _Comparison:
    """Symbolic then numeric comparison of one reading with the derivation."""

    same: bool
    method: str
    outcomes: tuple[CheckOutcome, ...]


def _compare(reading: sp.Eq, derived: sp.Eq, d: Derivation,
             tolerance: float = 0.0) -> _Comparison:
    num = numeric_equivalence(reading, derived, d.symbols, tol=max(tolerance, 1e-20),
                              names=d.latex_names)
    if tolerance > 0:  # a rounded printed number: only numbers can decide
        skipped = CheckOutcome("symbolic", INCONCLUSIVE,
                               f"not tried: the print is rounded (tolerance {tolerance:g})")
        return _Comparison(num.status == PASS, "numeric", (skipped, num))
    if num.status == FAIL:  # a refuted relation cannot simplify to the derived one
        skipped = CheckOutcome("symbolic", INCONCLUSIVE,
                               "not tried: the numeric check refuted the relation")
        return _Comparison(False, "numeric", (skipped, num))
    sym = symbolic_equivalence(reading, derived, d.symbols)
    if sym.status == PASS:
        return _Comparison(True, "symbolic", (sym, num))
    return _Comparison(num.status == PASS, "numeric", (sym, num))


def _attempt(d: Derivation, f: PublishedFormula, reading: str, note: str,
             relation: sp.Eq, target: str) -> tuple[Attempt, _Comparison, CheckOutcome]:
    derived = d.step(target).statement
    comp = _compare(relation, derived, d, f.tolerance)
    dim = dimension_consistency(relation, d.symbols, d.latex_names)
    matches = comp.same and dim.status == PASS
    diff = "" if comp.same else _difference_latex(relation, derived, d.latex_names)
    summary = (f"matches derived step {target} ({comp.method})" if matches
               else _why_not(comp, dim))
    attempt = Attempt(reading, note, matches, summary,
                      latex(derived, symbol_names=d.latex_names), diff,
                      comp.outcomes + (dim,))
    return attempt, comp, dim


def _difference_latex(relation: sp.Eq, derived: sp.Eq, names: dict) -> str:
    diff = difference(relation, derived)
    return "" if diff is None else latex(diff, symbol_names=names)


def audit_formula(d: Derivation, f: PublishedFormula) -> AuditRecord:
    """The verdict on one published formula of derivation ``d``."""
    def record(verdict: str, method: str, detail: str,
               attempts: tuple[Attempt, ...] = ()) -> AuditRecord:
        cause = None
        read = any(a.matches for a in attempts[1:])  # the literal print needed a reading
        if verdict not in AGREEMENTS or read:
            cause = f.cause or Cause(UNEXPLAINED, f"{d.id} {f.label}: the transcriber "
                                                  "gave no cause for this finding")
        checks = tuple(c for a in attempts for c in a.checks)
        return AuditRecord(d.id, f.label, verdict, method, detail, checks, f.basis,
                           f.basis_note, cause, f.latex, f.provenance, attempts,
                           f.reconstructed)

    if f.printed is None:
        return record(NOT_CHECKABLE, "none", f.not_checkable)
    literal, comp, dim = _attempt(d, f, "literal", "the print as printed", f.printed,
                                  f.target)
    if literal.matches:
        verdict = RESTATED if f.basis == DEFINITION else CONFIRMED
        return record(verdict, comp.method, f"as printed, {literal.summary}; "
                      f"{dim.detail}", (literal,))
    attempts = [literal]
    for conv in f.conventions:
        again, comp_r, _ = _attempt(d, f, conv.kind, conv.note, conv.reading,
                                    conv.compare_to or f.target)
        attempts.append(again)
        if again.matches:
            verdict = RESTATED if f.basis == DEFINITION else CONFIRMED_WITH_CONVENTION
            return record(verdict, comp_r.method,
                          f"as printed: {literal.summary}. Read with the {conv.kind} "
                          f"'{conv.note}', it {again.summary}.", tuple(attempts))
    tried = "".join(f" Read with the {a.reading} '{a.note}': {a.summary}."
                    for a in attempts[1:])
    tried += f" Derived form: ${literal.derived}$." + (
        f" Printed − derived: ${literal.difference}$." if literal.difference else "")
    if f.kind == ASSUMPTION:
        return record(REMARK, comp.method if not comp.same else "dimension",
                      f"stated assumption; as printed: {literal.summary}.{tried}",
                      tuple(attempts))
    if dim.status == FAIL:
        follows = (f"; the relation does follow from step {f.target}, which carries "
                   "the same error" if comp.same else "")
        return record(DIMENSION_ERROR, "dimension",
                      f"as printed: {literal.summary}{follows}.{tried}", tuple(attempts))
    if comp.outcomes[1].status == FAIL:
        return record(DISCREPANCY, "numeric", f"as printed: {literal.summary}.{tried}",
                      tuple(attempts))
    return record(NOT_CHECKABLE, "none",
                  "neither check could decide: "
                  + "; ".join(c.detail for c in literal.checks), tuple(attempts))


def _why_not(comp: _Comparison, dim: CheckOutcome) -> str:
    parts = []
    if not comp.same:
        num = comp.outcomes[1]
        parts.append(num.detail if num.status == FAIL else
                     "the comparison was inconclusive")
    if dim.status == FAIL:
        parts.append("dimensions: " + dim.detail)
    return "; ".join(parts) or "matches"


def audit(d: Derivation) -> list[AuditRecord]:
    """Verdicts on every published formula of ``d``, in the paper's order."""
    records = []
    for f in d.published:
        progress.current().step(f"{d.id}: checking printed formula {f.label}")
        records.append(audit_formula(d, f))
    return records


__all__ = ["AGREEMENTS", "CONFIRMATIONS", "CONFIRMED", "CONFIRMED_WITH_CONVENTION",
           "DIMENSION_ERROR", "DISCREPANCY", "NOT_CHECKABLE", "REMARK", "RESTATED",
           "UNEXPLAINED", "VERDICTS", "Attempt", "AuditRecord", "Convention",
           "audit", "audit_formula"]
