"""The verdicts of a walkthrough in a teacher's words.

A walkthrough shows, under each print, what the audit found: the verdict, the
check that decided, what it rests on, the reading that made it follow, the
value under that reading, the cause of a finding. The audit's records keep the
reviewer's wording (paper files, module names, cause ids, the parser's
messages); here the same facts are said once each, in the paper's words: a
paper's ``HANDOUT_WORDS`` replaces the code names of its notes, a cause is
lettered (A, B, …) and stated in full where it first occurs, the paper's
declared reading of its data likewise.
"""
from __future__ import annotations

import re
from dataclasses import dataclass, field

import sympy as sp

from crane_sym.audit.verdicts import (CONFIRMED, CONFIRMED_WITH_CONVENTION, CONSISTENT, DIMENSION_ERROR,
                                      DISCREPANCY, NOT_CHECKABLE, NOT_THE_PRINT, REMARK, RESTATED,
                                      AuditRecord)
from crane_sym.derivation import Derivation
from crane_sym.docs.numbers import LIMIT, decimal, is_value, printed_digits
from crane_sym.markdown import markdown_table
from crane_sym.published import PublishedFormula

__all__ = ["Voice", "verdict_name"]

_SAYS = {
    CONFIRMED: "the print, as printed, follows from the derivation",
    CONFIRMED_WITH_CONVENTION: "as printed it does not follow; with the reading below, it "
                               "does",
    RESTATED: "the step restates the printed definition, so nothing could fail",
    CONSISTENT: "the reconstruction reproduces it only through parameters the paper does "
                "not state; the printed number lies in the band they span (not a "
                "confirmation)",
    DISCREPANCY: "the print does not follow from the derivation",
    DIMENSION_ERROR: "a term of the print has the wrong dimension",
    NOT_CHECKABLE: "nothing checkable was printed",
    REMARK: "a modelling choice the paper states that differs from what the model implies",
    NOT_THE_PRINT: "the transcription checked is not the print: read by machine, the "
                   "printed formula differs from it",
}
#: What a verdict says of a transcription reconstructed from OCR damage.
_SAYS_RECONSTRUCTED = {
    CONFIRMED: "the print as reconstructed from OCR damage follows from the derivation",
    CONFIRMED_WITH_CONVENTION: "as reconstructed it does not follow; with the reading "
                               "below, it does",
    DISCREPANCY: "the print as reconstructed does not follow from the derivation",
}
#: How each check decides, in words.
_DECIDED = {"symbolic": "decided by the symbolic check", "numeric": "decided by the "
            "numeric check", "dimension": "decided by the dimension check",
            "none": "no check could decide", "machine reading": "decided by the print "
            "read by machine"}
_TOKEN = re.compile(r"\s*Token\([^)]*\)")
#: A quote of the paper in a note: 'ZJ7', 'Form 1 value'.
_QUOTE = re.compile(r"((?<![\w'])'[^'\n]*'(?![\w']))")


def verdict_name(verdict: str) -> str:
    """A verdict as words: ``confirmed with convention``, ``dimension error``."""
    return verdict.replace("_", " ")


def _letters():
    k = 0
    while True:
        k += 1
        n, name = k, ""
        while n:
            n, r = divmod(n - 1, 26)
            name = chr(65 + r) + name
        yield name


@dataclass
class Voice:
    """What a walkthrough has said so far: causes lettered, readings stated.

    Parameters
    ----------
    d : Derivation
        The derivation the records are of.
    words : dict of str to str
        The paper's ``HANDOUT_WORDS``: a code name in its notes -> the words a
        reader gets (``"of elastic.py"`` -> ``"of the model text"``).
    """

    d: Derivation
    words: dict[str, str] = field(default_factory=dict)
    causes: dict[str, str] = field(default_factory=dict)        # id -> letter
    cause_first: dict[str, str] = field(default_factory=dict)   # id -> first label
    readings: dict[str, str] = field(default_factory=dict)      # reading -> first label
    notes: dict[str, str] = field(default_factory=dict)         # basis note -> first label

    def __post_init__(self) -> None:
        self._next = _letters()
        keys = sorted(self.words, key=len, reverse=True)
        self._pattern = (re.compile("|".join(
            (r"(?<![\w\\])" if k[0].isalnum() else "") + re.escape(k)
            + (r"(?!\w)" if k[-1].isalnum() else "") for k in keys)) if keys else None)

    def say(self, text: str) -> str:
        """``text`` with the paper's code names in words (never inside a quote of
        the paper, ``'…'``), and the paper's file name left out."""
        text = text.replace(f"{self.d.paper}, ", "").replace(self.d.paper, "the paper")
        if self._pattern is None:
            return text
        pieces = _QUOTE.split(text)     # odd pieces are quotes, kept as they are
        return "".join(piece if i % 2 else
                       self._pattern.sub(lambda m: self.words[m.group(0)], piece)
                       for i, piece in enumerate(pieces))

    def letter(self, record: AuditRecord) -> str:
        """The cause's letter, given at its first occurrence."""
        cid = record.cause.id
        if cid not in self.causes:
            self.causes[cid] = next(self._next)
            self.cause_first[cid] = record.label
        return self.causes[cid]

    # --- the lines under a print ------------------------------------------------
    def verdict_lines(self, record: AuditRecord, f: PublishedFormula) -> list[str]:
        """The verdict in words, then what it rests on, the reading, the value, the
        cause and, for a symbolic finding, the difference."""
        rests = record.basis
        if record.basis_note:
            first = self.notes.setdefault(record.basis_note, record.label)
            rests += (f" ({self.say(record.basis_note)})" if first == record.label else
                      f", as under {self.say(first)}")
        says = (_SAYS_RECONSTRUCTED if record.reconstructed else _SAYS).get(
            record.verdict, _SAYS[record.verdict])
        lines = [f"Verdict: **{verdict_name(record.verdict)}** — {says} "
                 f"({_DECIDED.get(record.method, record.method)}; rests on: {rests})."]
        if record.paper_reading:
            first = self.readings.setdefault(record.paper_reading, record.label)
            lines.append(f"- On the paper's reading: {self.say(record.paper_reading)}."
                         if first == record.label else
                         f"- On the paper's reading, as stated under {self.say(first)}.")
        if record.sensitivity is not None:
            lines.append(f"- Sensitivity to the chosen parameters: "
                         f"{self.say(record.sensitivity.text())}.")
        if record.duplicate_of:
            lines.append(f"- The same check as {self.say(record.duplicate_of)} "
                         "(counted once).")
        reading = record.reading
        if reading is not None:
            lines.append(f"- Read with the {reading.reading}: {self.say(reading.note)}.")
        lines += self.numbers(record, f)
        if record.cause:
            letter = self.letter(record)
            first = self.cause_first[record.cause.id]
            lines.append(f"- Cause {letter}: {self.say(record.cause.sentence)}"
                         if first == record.label else
                         f"- Cause {letter}, as under {self.say(first)}.")
        lines += self._difference(record, f)
        if record.machine_read is not None:
            lines.append(f"- Read by machine: {self._machine(record)}.")
        return lines

    def numbers(self, record: AuditRecord, f: PublishedFormula) -> list[str]:
        """The derived value beside a printed number, to the print's digits, and
        under the reading that decided, with the reading."""
        if not is_value(f.printed) or record.verdict == RESTATED:
            return []       # a restated input derives nothing to compare
        percent = "%" in f.latex
        out = []

        def value_of(label: str, relation: sp.Eq, tolerance: float) -> str | None:
            statement = self.d.step(label).statement
            if not is_value(statement) or not is_value(relation):
                return None
            rhs = statement.rhs
            places = printed_digits(relation.rhs, tolerance) - (2 if percent else 0)
            shown = decimal(rhs, places, percent)
            more = decimal(rhs, places + 2, percent)
            exact = sp.nsimplify(rhs) * 10 ** (places + (2 if percent else 0))
            return f"${shown}$" + ("" if exact.is_integer else f" (${more}$)")

        literal = value_of(f.target, f.printed, f.tolerance)
        if literal:
            out.append(f"- Derived, to the print's digits: {literal}.")
        for conv in f.conventions:
            if record.reading is not None and conv.note in record.reading.note:
                under = value_of(conv.compare_to or f.target, f.reading(conv), f.tolerance)
                if under and (conv.compare_to or under != literal):
                    out.append(f"- Derived with the reading ({self.say(conv.note)}): "
                               f"{under}.")
        return out

    def _difference(self, record: AuditRecord, f: PublishedFormula) -> list[str]:
        literal = record.literal
        if (record.verdict in (CONFIRMED, RESTATED) or literal is None
                or record.reading is not None
                or is_value(f.printed)):
            return []
        dim = next((c for c in literal.checks
                    if c.method == "dimension" and c.status == "fail"), None)
        if dim is not None:
            return [f"- Dimensions: {self.say(dim.detail)}."]
        if literal.difference and len(literal.difference) <= LIMIT:
            return [f"- Printed − derived: ${literal.difference}$."]
        return []

    def _machine(self, record: AuditRecord) -> str:
        m = record.machine_read
        if m.status == "agrees":
            return "the print parses to the transcription"
        if m.status == "differs":
            return ("it differs from the transcription, as " + self.say(m.explained_by)
                    if m.explained_by else "it differs from the transcription")
        reason = m.detail.split(":")[0]
        if reason.startswith("the parser cannot read"):
            reason = "the LaTeX grammar cannot parse it"
        return f"not read ({self.say(_TOKEN.sub('', reason))})"

    # --- the summary ------------------------------------------------------------
    def table(self, records: list[AuditRecord] | None) -> list[str]:
        """One row per printed formula, then the causes by letter."""
        header = ["Formula", "Verdict", "Decided by", "Transcription", "Rests on", "Cause"]
        if records is None:
            return [markdown_table(header, [[_cell(self.say(f.label)), "not audited", "—", "—",
                                             "—", "—"] for f in self.d.published])]
        out = [markdown_table(header, [
            [_cell(self.say(r.label)), verdict_name(r.verdict), r.method, r.transcription,
             r.basis, self.letter(r) if r.cause else "—"] for r in records])]
        sentences = {r.cause.id: r.cause.sentence for r in records if r.cause}
        if sentences:
            out.append("Causes of the findings:")
            out.append("\n".join(f"- **{self.causes[cid]}.** {self.say(s)}"
                                 for cid, s in sentences.items()))
        return out


def _cell(text: str) -> str:
    """Text safe inside a Markdown table cell."""
    return " ".join(str(text).split()).replace("|", r"\|")
