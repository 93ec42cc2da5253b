"""Verdicts on published formulas, from checks that can fail.

For each published formula the audit runs the symbolic, numeric and dimension
checks on the print as transcribed; only when the print does not match does
it try the formula's conventions. The verdict names the check that decided.
"""
from __future__ import annotations

from dataclasses import dataclass, field

import sympy as sp

from . import progress
from .checks import (FAIL, INCONCLUSIVE, PASS, CheckOutcome,
                     dimension_consistency, numeric_equivalence,
                     symbolic_equivalence)
from .derivation import Derivation
from .published import ASSUMPTION, PublishedFormula

CONFIRMED = "confirmed"
CONFIRMED_WITH_CONVENTION = "confirmed_with_convention"
DISCREPANCY = "discrepancy"
DIMENSION_ERROR = "dimension_error"
NOT_CHECKABLE = "not_checkable"
REMARK = "remark"
VERDICTS = (CONFIRMED, CONFIRMED_WITH_CONVENTION, DISCREPANCY, DIMENSION_ERROR,
            NOT_CHECKABLE, REMARK)


@dataclass(frozen=True)
class AuditRecord:
    """The verdict on one published formula."""

    derivation: str
    label: str
    verdict: str
    method: str
    detail: str
    checks: tuple[CheckOutcome, ...] = field(default=())

    def as_dict(self) -> dict:
        """JSON-ready form."""
        return {"derivation": self.derivation, "label": self.label,
                "verdict": self.verdict, "method": self.method,
                "detail": self.detail,
                "checks": [{"method": c.method, "status": c.status,
                            "detail": c.detail} for c in self.checks]}


@dataclass(frozen=True)
class _Comparison:
    """Symbolic then numeric comparison of one reading with the derivation."""

    same: bool
    method: str
    outcomes: tuple[CheckOutcome, ...]


def _compare(reading: sp.Eq, derived: sp.Eq, d: Derivation,
             tolerance: float = 0.0) -> _Comparison:
    num = numeric_equivalence(reading, derived, d.symbols, tol=max(tolerance, 1e-20))
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


def _latex(expr: sp.Basic) -> str:
    return sp.latex(expr)


def audit_formula(d: Derivation, f: PublishedFormula) -> AuditRecord:
    """The verdict on one published formula of derivation ``d``."""
    def record(verdict: str, method: str, detail: str,
               checks: tuple[CheckOutcome, ...] = ()) -> AuditRecord:
        return AuditRecord(d.id, f.label, verdict, method, detail, checks)

    if f.printed is None:
        return record(NOT_CHECKABLE, "none", f.not_checkable)
    derived = d.step(f.target).statement
    as_printed = _compare(f.printed, derived, d, f.tolerance)
    dim = dimension_consistency(f.printed, d.symbols)
    checks = as_printed.outcomes + (dim,)
    if as_printed.same and dim.status == PASS:
        return record(CONFIRMED, as_printed.method,
                      f"matches derived step {f.target}: "
                      f"{as_printed.outcomes[0 if as_printed.method == 'symbolic' else 1].detail}; "
                      f"{dim.detail}", checks)
    why_not = _why_not(as_printed, dim)
    for conv in f.conventions:
        again = _compare(conv.reading, derived, d, f.tolerance)
        dim_again = dimension_consistency(conv.reading, d.symbols)
        if again.same and dim_again.status == PASS:
            return record(
                CONFIRMED_WITH_CONVENTION, again.method,
                f"as printed: {why_not}. Read with the convention '{conv.note}', "
                f"it matches derived step {f.target} ({again.method}).",
                checks + again.outcomes + (dim_again,))
    corrected = f"derived form: ${_latex(derived)}$"
    if f.kind == ASSUMPTION:
        return record(REMARK, as_printed.method if not as_printed.same else "dimension",
                      f"stated assumption ({f.provenance}); {why_not}; {corrected}",
                      checks)
    if dim.status == FAIL:
        follows = (f"it does follow from step {f.target}, which carries the same error"
                   if as_printed.same else why_not)
        return record(DIMENSION_ERROR, "dimension", f"{dim.detail}; {follows}; {corrected}",
                      checks)
    if not as_printed.same and as_printed.outcomes[1].status == FAIL:
        return record(DISCREPANCY, "numeric", f"{why_not}; {corrected}", checks)
    return record(NOT_CHECKABLE, "none",
                  "neither check could decide: " + "; ".join(c.detail for c in checks),
                  checks)


def _why_not(comp: _Comparison, dim: CheckOutcome) -> str:
    parts = []
    if not comp.same:
        num = comp.outcomes[1]
        parts.append(num.detail if num.status == FAIL else
                     "the comparison was inconclusive")
    if dim.status == FAIL:
        parts.append("dimension check: " + dim.detail)
    return "; ".join(parts) or "matches"


def audit(d: Derivation) -> list[AuditRecord]:
    """Verdicts on every published formula of ``d``, in the paper's order."""
    records = []
    for f in d.published:
        progress.current().step(f"{d.id}: checking printed formula {f.label}")
        records.append(audit_formula(d, f))
    return records
