"""Verdicts on published formulas, from checks that can fail.

For each published formula the audit runs the symbolic, numeric and dimension
checks on the print as transcribed and keeps that literal result in the record.
Only when the literal print fails does it try the formula's readings, and only
the kinds the reading policy allows (``published.READINGS``). The verdict
names the check that decided, the basis it rests on and, for a finding, its
cause. The verdicts' names and the record they fill are
:mod:`crane_sym.audit.records` (imported here too).
"""
from __future__ import annotations

from dataclasses import dataclass, replace

import sympy as sp

from crane_sym import progress
from crane_sym.audit.checks import (FAIL, INCONCLUSIVE, PASS, CheckOutcome, difference,
                                    dimension_consistency, numeric_equivalence,
                                    symbolic_equivalence)
from crane_sym.derivation import Derivation
from crane_sym.audit.fits import fit_of
from crane_sym.latex import latex
from crane_sym.audit.machine_read import DIFFERS, machine_read
from crane_sym.audit.records import (
    AGREEMENTS, AS_PRINTED, AS_RECONSTRUCTED, CONFIRMATIONS, CONFIRMED,
    CONFIRMED_WITH_CONVENTION, CONSISTENT, DIMENSION_ERROR, DISCREPANCY, NOT_CHECKABLE,
    NOT_THE_PRINT, ON_MODEL, ON_PAPER, ON_READING, ON_RECONSTRUCTION, REJECTED, REMARK,
    RESTATED, RESTS_ON, UNEXPLAINED, VERDICTS, Attempt, AuditRecord)
from crane_sym.published import (ASSUMPTION, CHOSEN, DEFINITION, Cause, Convention,
                                 PublishedFormula)
from crane_sym.audit.sampling import physical_definitions
from crane_sym.sensitivity import Sensitivity


@dataclass(frozen=True)
class _Comparison:
    """Symbolic then numeric comparison of one reading with the derivation."""

    same: bool
    method: str
    outcomes: tuple[CheckOutcome, ...]


#: id(derivation) -> (number of steps, definitions): the definitions of its defined
#: symbols in its data, found once per built derivation.
_DEFINITIONS: dict[int, tuple[int, dict]] = {}


def definitions(d: Derivation) -> dict[sp.Symbol, sp.Expr]:
    """The defined symbols of ``d`` in its data (``sampling.physical_definitions``),
    computed once per derivation (again if steps were added since)."""
    cached = _DEFINITIONS.get(id(d))
    if cached is None or cached[0] != len(d.steps):
        cached = (len(d.steps), physical_definitions(d.steps, d.symbols))
        _DEFINITIONS[id(d)] = cached
    return cached[1]


def _compare(reading: sp.Eq, derived: sp.Eq, d: Derivation,
             tolerance: float = 0.0) -> _Comparison:
    num = numeric_equivalence(reading, derived, d.symbols, tol=max(tolerance, 1e-20),
                              names=d.latex_names, definitions=definitions(d))
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


def _convention_note(d: Derivation, f: PublishedFormula, conv: Convention) -> str:
    """The reading's note; for a fitted value, with the fit shown."""
    if conv.fit is None:
        return conv.note
    return f"{conv.note} ({fit_of(d, conv.fit, f).text(f.label)})"


#: The slips a band must tell from the print to be evidence: a factor 2 either way
#: and a decimal point shifted either way.
SLIPS = ((2.0, "twice"), (0.5, "half"), (10.0, "ten times"), (0.1, "a tenth"))


def _undiscriminated(value: float, inside) -> list[str]:
    """The slips of ``value`` that would still lie inside the band (``inside``)."""
    return [f"{name} it ({factor * value:.4g})" for factor, name in SLIPS
            if inside(factor * value)]


def _band(d: Derivation, f: PublishedFormula, literal: Attempt,
          how: str) -> tuple[str, Attempt, str]:
    """A result of chosen parameters against the band they span: ``consistent``
    inside it, ``discrepancy`` outside; the band's half-width is the tolerance.
    A band is evidence only if it discriminates: when a print off by a factor 2
    or by a shifted decimal point would lie inside it too, the verdict is
    ``not_checkable`` (the band is stated, and says which slips it holds)."""
    sens = d.step(f.target).sensitivity
    if sens is None or f.printed is None or not f.printed.rhs.is_number:
        raise ValueError(f"{d.id} {f.label}: a result of chosen parameters is a printed "
                         f"number whose derived step ({f.target}) carries a sensitivity")
    value, (low, high) = float(f.printed.rhs), sens.band
    slack = f.tolerance

    def holds(x: float) -> bool:
        return low - slack * abs(low) <= x <= high + slack * abs(high)
    inside = holds(value)
    check = CheckOutcome(
        "numeric", PASS if inside else FAIL,
        f"the printed {value:g} is {'inside' if inside else 'outside'} the band "
        f"{low:.4g}–{high:.4g} that the chosen parameters span (tolerance ±"
        f"{100 * sens.spread:.2g} % about {sens.value:.4g}, from their plausible ranges, "
        f"widened by the print's rounding ±{100 * slack:.2g} %)")
    attempt = Attempt("sensitivity band", sens.text(), inside, check.detail,
                      f"{low:.4g} \\ldots {high:.4g}", "", (check,))
    detail = (f"{how}: {literal.summary} at the chosen parameters; {check.detail}. "
              f"Sensitivity: {sens.text()}.")
    slips = _undiscriminated(value, holds)
    if slips:
        return NOT_CHECKABLE, attempt, (
            f"the band does not discriminate: a print of {', '.join(slips)} would lie "
            f"inside it too, so it is no evidence either way. {detail}")
    return (CONSISTENT if inside else DISCREPANCY), attempt, detail


def audit_formula(d: Derivation, f: PublishedFormula) -> AuditRecord:
    """The verdict on one published formula of derivation ``d``.

    Parameters
    ----------
    d : Derivation
        The built derivation, whose step ``f.target`` the formula is checked against.
    f : PublishedFormula
        The formula, one of ``d.published`` (or built for ``d`` alone).
    """
    sensitivity = d.step(f.target).sensitivity if f.kind == CHOSEN else None

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
                           f.reconstructed, sensitivity,
                           f.paper_reading.text if f.paper_reading else "", "", f.target)

    if f.printed is None:
        return record(NOT_CHECKABLE, "none", f.not_checkable)
    how = AS_RECONSTRUCTED if f.reconstructed else AS_PRINTED
    literal, comp, dim = _attempt(
        d, f, "literal", "the reconstruction of the damaged print" if f.reconstructed
        else "the print as printed", f.printed, f.target)
    if f.kind == CHOSEN:
        verdict, band, detail = _band(d, f, literal, how)
        return record(verdict, "numeric" if verdict != NOT_CHECKABLE else "none", detail,
                      (literal, band))
    on = f" (on the paper's reading: {f.paper_reading.text})" if f.paper_reading else ""
    if literal.matches:
        verdict = RESTATED if f.basis == DEFINITION else CONFIRMED
        if verdict == CONFIRMED and _evidence_of_its_reading(f):
            other, _, _ = _attempt(d, f, REJECTED, f.paper_reading.rejected, f.printed,
                                   f.rejected_target)
            if not other.matches:
                return record(CONSISTENT, comp.method, f"{how}, {literal.summary}{on}; "
                              f"{dim.detail}. Under the other reading ("
                              f"{f.paper_reading.rejected}): {other.summary}. A match "
                              "under one of two readings, the one this print is evidence "
                              "for, is consistent with it, not a confirmation",
                              (literal, other))
        return record(verdict, comp.method, f"{how}, {literal.summary}{on}; "
                      f"{dim.detail}", (literal,))
    attempts = [literal]
    for conv in f.conventions:
        again, comp_r, _ = _attempt(d, f, conv.kind, _convention_note(d, f, conv),
                                    f.reading(conv), conv.compare_to or f.target)
        attempts.append(again)
        if again.matches:
            verdict = RESTATED if f.basis == DEFINITION else CONFIRMED_WITH_CONVENTION
            return record(verdict, comp_r.method,
                          f"{how}: {literal.summary}. Read with the {conv.kind} "
                          f"'{again.note}', it {again.summary}.", tuple(attempts))
    if f.rejected_target:
        other, _, _ = _attempt(d, f, REJECTED, f.paper_reading.rejected, f.printed,
                               f.rejected_target)
        attempts.append(other)
    tried = "".join(f" Read with the {a.reading} '{a.note}': {a.summary}."
                    for a in attempts[1:])
    if f.rejected_target and attempts[-1].matches:
        tried += (f" Only the reading this paper rejects ({f.paper_reading.rejected}) "
                  f"reproduces it; the paper's reading is {f.paper_reading.reading}.")
    tried += f" Derived form: ${literal.derived}$." + (
        f" Printed − derived: ${literal.difference}$." if literal.difference else "")
    if f.kind == ASSUMPTION:
        return record(REMARK, comp.method if not comp.same else "dimension",
                      f"a modelling choice the paper states ({f.stated}); {how}: "
                      f"{literal.summary}.{tried}", tuple(attempts))
    if dim.status == FAIL:
        follows = (f"; the relation does follow from step {f.target}, which carries "
                   "the same error" if comp.same else "")
        return record(DIMENSION_ERROR, "dimension",
                      f"{how}: {literal.summary}{follows}.{tried}", tuple(attempts))
    if comp.outcomes[1].status == FAIL:
        return record(DISCREPANCY, "numeric", f"{how}: {literal.summary}{on}.{tried}",
                      tuple(attempts))
    return record(NOT_CHECKABLE, "none",
                  "neither check could decide: "
                  + "; ".join(c.detail for c in literal.checks), tuple(attempts))


def _evidence_of_its_reading(f: PublishedFormula) -> bool:
    """``f`` is among the prints that fix its paper's reading, and the other
    reading can be tried on it."""
    return bool(f.paper_reading and f.rejected_target
                and f.label in f.paper_reading.fixed_by)


def _why_not(comp: _Comparison, dim: CheckOutcome) -> str:
    parts = []
    if not comp.same:
        num = comp.outcomes[1]
        parts.append(num.detail if num.status == FAIL else
                     "the comparison was inconclusive")
    if dim.status == FAIL:
        parts.append("dimensions: " + dim.detail)
    return "; ".join(parts) or "matches"


def _check_key(f: PublishedFormula) -> tuple | None:
    """What makes two records one check: the same transcription against the same
    derived step, of the same kind (8.9 and 890 % are one number, printed to
    different digits)."""
    if f.printed is None:
        return None
    return (f.target, sp.srepr(f.printed), f.kind, f.rejected_target)


#: The cause of a record whose transcription is not what is printed.
NOT_THE_PRINT_CAUSE = Cause(
    "transcription-not-the-print", "the transcription checked is not the print: read by "
    "machine, the printed LaTeX differs from the transcription, and no labelled "
    "reconstruction or named reading explains the difference")


def tied_to_print(r: AuditRecord) -> AuditRecord:
    """``r`` unless its print, read by machine, differs from its transcription
    without a labelled reconstruction or a named reading to explain it: then a
    ``not_the_print`` finding, whatever the transcription's own check gave (a
    verdict rests on the print; the check of the transcription is kept in the
    detail and the attempts).

    Parameters
    ----------
    r : AuditRecord
        A record with its ``machine_read``.
    """
    read = r.machine_read
    if read is None or read.status != DIFFERS or read.explained_by:
        return r
    return replace(r, verdict=NOT_THE_PRINT, method="machine reading",
                   cause=NOT_THE_PRINT_CAUSE,
                   detail=f"the transcription checked is not the print ({read.detail}); "
                          f"on the transcription the audit gave {r.verdict}: {r.detail}")


def audit(d: Derivation) -> list[AuditRecord]:
    """Verdicts on every published formula of ``d``, in the paper's order, each with
    its print read by machine against the transcription (``machine_read``) and
    tied to it (``tied_to_print``); a record that repeats an earlier one's check (the same number printed twice, 8.9
    and 890 %) names that record in ``duplicate_of`` and is counted once.

    Parameters
    ----------
    d : Derivation
        The built derivation (``registry.get``), its ``published`` formulas to judge.
    """
    records, seen = [], {}
    for f in d.published:
        progress.current().step(f"{d.id}: checking printed formula {f.label}")
        r = tied_to_print(replace(audit_formula(d, f), machine_read=machine_read(d, f)))
        key = _check_key(f)
        if key is not None and key in seen:
            r = replace(r, duplicate_of=seen[key])
        elif key is not None:
            seen[key] = f.label
        records.append(r)
    return records


__all__ = ["AGREEMENTS", "CONFIRMATIONS", "CONFIRMED", "CONFIRMED_WITH_CONVENTION",
           "CONSISTENT", "DIMENSION_ERROR", "DISCREPANCY", "NOT_CHECKABLE", "NOT_THE_PRINT",
           "NOT_THE_PRINT_CAUSE", "ON_MODEL",
           "ON_PAPER", "ON_READING", "ON_RECONSTRUCTION", "REMARK", "RESTATED", "RESTS_ON",
           "UNEXPLAINED", "VERDICTS", "Attempt", "AuditRecord", "Convention",
           "audit", "audit_formula", "tied_to_print"]
