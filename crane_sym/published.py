"""Published formulas: the paper's text as printed, beside its transcription.

The transcription is a SymPy expression built in code (never parsed from the
LaTeX), faithful to the print *including its errors*. Each formula says what
its verdict can rest on (``BASES``) and, when it is a finding, why (``Cause``).

The reading policy
------------------
A reading is a way of taking the print that it does not spell out. The audit
applies only the kinds in ``READINGS``, and always in this order: the literal
print is checked first and its result is kept in the record; only when it fails
is a reading tried, and a reading that matches makes the verdict
``confirmed_with_convention``, with the reading named in that record.
"""
from __future__ import annotations

from dataclasses import dataclass

import sympy as sp

from crane_sym.readings import Reinterpretation

EQUATION = "equation"      # a claim that must follow from the model
ASSUMPTION = "assumption"  # a modelling choice the paper states; a difference is a remark
#: A number a reconstructed model gives only through parameters the paper does not
#: state: decided against the band those parameters span (``crane_sym.sensitivity``).
CHOSEN = "result of chosen parameters"
KINDS = (EQUATION, ASSUMPTION, CHOSEN)

# --- What a verdict rests on -------------------------------------------------------
MODEL = "model"
RECONSTRUCTED = "reconstructed model"
INTERNAL = "internal"
DEFINITION = "definition"
#: Basis -> what it means; every basis but ``model`` needs a note naming what.
BASES = {
    MODEL: "the derivation from the physics the paper states",
    RECONSTRUCTED: "a model the paper does not fully state (the note names what was "
                   "reconstructed)",
    INTERNAL: "the paper against itself: dimensions, one equation against another, a "
              "table against its own formula",
    DEFINITION: "the record restates a definition or adopts the print, so nothing "
                "could fail; never counted as a confirmation",
}

# --- The reading policy ----------------------------------------------------------
LOST_MARK = "lost mark"
SYMBOL_FOR_ANOTHER = "symbol for another"
OPERATOR_SCOPE = "operator scope"
FITTED_VALUE = "fitted value"
LINE_BREAK_SIGN = "line-break sign"
#: The only readings the audit may apply, and when.
READINGS = {
    LOST_MARK: "a dot, prime, sign or bracket lost in print or OCR",
    SYMBOL_FOR_ANOTHER: "a symbol printed for another one (a wrong case or subscript, "
                        "one name for two quantities, an undefined symbol given the "
                        "meaning the text implies)",
    OPERATOR_SCOPE: "an operator whose scope the print leaves open (÷ before a product)",
    FITTED_VALUE: "an instant or parameter the paper does not state, fitted to its "
                  "printed numbers",
    LINE_BREAK_SIGN: "an operator repeated at a line break, as Russian and Ukrainian "
                     "typesetting does, read once",
}


@dataclass(frozen=True)
class Cause:
    """Why a record is a finding, shared by every record that fails for it.

    Parameters
    ----------
    id : str
        Short, stable id: the paper's number, then a slug (``"<paper>-table2-plus-one"``).
    sentence : str
        One sentence a reviewer can check.
    """

    id: str
    sentence: str


@dataclass(frozen=True)
class PaperReading:
    """How a paper's data are read where the print allows two readings, declared
    once per paper with the evidence for it; every record that depends on it
    names it, and a printed number that only the rejected reading reproduces is
    a finding that says so.

    Parameters
    ----------
    subject : str
        What is read, e.g. "Table 1's J1, J2 and M_SB".
    reading : str
        The reading taken, e.g. "values of the whole drive (both trains)".
    evidence : str
        Why: the printed numbers that decide between the readings.
    rejected : str
        The other reading, e.g. "values of each train (counted twice)".
    fixed_by : tuple of str
        Labels of the records whose prints are that evidence. Such a record
        matches under the reading it chose and fails under the other, so it is
        ``consistent`` with the reading, never a confirmation of it.
    """

    subject: str
    reading: str
    evidence: str
    rejected: str
    fixed_by: tuple[str, ...] = ()

    @property
    def text(self) -> str:
        """``"<subject> read as <reading>"``."""
        return f"{self.subject} read as {self.reading}"


@dataclass(frozen=True)
class Fit:
    """A parameter the paper does not state, fitted to several printed numbers.

    Each printed number that a ``fitted value`` reading with this fit checks
    allows an interval of the parameter (its derived step is a function of
    it, the print has its rounding); the audit shows that interval, the one
    all of them share, and the value the reading takes, which must lie in it.

    Parameters
    ----------
    symbol : sympy.Symbol
        The parameter, free in the derived step of each record.
    name : str
        What it is, e.g. "the braking time Δt".
    unit : str
        Its unit as written.
    value : sympy.Rational
        The value the reading takes.
    bracket : (float, float)
        Where the fit looks for it.
    """

    symbol: sp.Symbol
    name: str
    unit: str
    value: sp.Expr
    bracket: tuple[float, float]


@dataclass(frozen=True)
class Convention:
    """A reading of the print under a stated convention.

    Parameters
    ----------
    note : str
        What the convention is, e.g. "P in (6) is the frequency p of (5)".
    reading : sympy.Eq or Reinterpretation
        The printed formula read under the convention: best the operation
        (``crane_sym.readings``) that makes it from the transcription, so the
        reading checks what is transcribed; a relation typed beside the
        transcription only where no operation states the reading.
    kind : str
        Which reading of the policy (a key of ``READINGS``).
    compare_to : str
        The derived step the reading is checked against, when the reading
        changes the derived side (a fitted instant); default: the formula's.
    fit : Fit or None
        For a ``fitted value``: the parameter fitted and the numbers it is
        fitted to; the audit shows the fit in the record.
    """

    note: str
    reading: sp.Eq | Reinterpretation
    kind: str
    compare_to: str = ""
    fit: Fit | None = None

    def __post_init__(self) -> None:
        if self.kind not in READINGS:
            raise ValueError(f"reading kind {self.kind!r} is not in the policy: "
                             f"{sorted(READINGS)}")
        if self.fit is not None and self.kind != FITTED_VALUE:
            raise ValueError(f"{self.note!r}: only a {FITTED_VALUE!r} reading carries a "
                             "Fit")


@dataclass(frozen=True)
class PublishedFormula:
    """One formula of the paper.

    Parameters
    ----------
    label : str
        The paper's equation number as printed, e.g. ``"(6)"``.
    latex : str
        The printed LaTeX, verbatim from the paper's text.
    printed : sympy.Eq or None
        The transcription as printed; ``None`` when nothing checkable was
        printed (then ``not_checkable`` says why).
    provenance : str
        Where it stands (file, equation) and any OCR reconstruction.
    compare_to : str
        Label of the derived step it is checked against (default: ``label``).
    conventions : tuple of Convention
        Readings tried when the print as such does not match.
    kind : str
        ``equation``; ``assumption`` (a modelling choice the paper states:
        ``stated`` quotes where); or ``result of chosen parameters`` (a number a
        reconstructed model gives only through values the paper does not
        state: its derived step carries their sensitivity, whose band decides).
    reconstructed : bool
        True when OCR damage forced a reconstruction from the text.
    not_checkable : str
        Reason, when ``printed`` is None.
    tolerance : float
        Relative tolerance of the numeric comparison. 0 (the default) means
        exact; a number printed to a few digits takes half a unit of its last
        digit relative to its value, and is then decided numerically only.
    basis : str
        What the verdict rests on (a key of ``BASES``).
    basis_note : str
        What was reconstructed, restated or compared, for every basis but
        ``model``.
    cause : Cause or None
        The transcriber's diagnosis, for a formula whose record is a finding.
    verbatim : bool
        True when ``latex`` holds the OCR'd text of the print (a Mathcad form,
        a table cell) rather than LaTeX; the walkthrough shows it as text,
        beside the transcription typeset.
    stated : str
        For an ``assumption``: where the paper states it, quoted.
    paper_reading : PaperReading or None
        The paper's declared reading of its data that the derived step uses.
    rejected_target : str
        The derived step under the rejected reading of ``paper_reading``,
        tried when the record fails, so a finding says whether only that
        reading reproduces the print.
    read_as : str
        A named reading of the print's names that its text, not its LaTeX,
        fixes (the instant "at t = 0" of a sentence, one name the paper uses
        for two quantities): where the machine reading of the print differs
        from the transcription, this is what explains it, shown in the record.
    """

    label: str
    latex: str
    printed: sp.Eq | None
    provenance: str
    compare_to: str = ""
    conventions: tuple[Convention, ...] = ()
    kind: str = EQUATION
    reconstructed: bool = False
    not_checkable: str = ""
    tolerance: float = 0.0
    basis: str = MODEL
    basis_note: str = ""
    cause: Cause | None = None
    verbatim: bool = False
    stated: str = ""
    paper_reading: PaperReading | None = None
    rejected_target: str = ""
    read_as: str = ""

    def __post_init__(self) -> None:
        if self.basis not in BASES:
            raise ValueError(f"{self.label}: basis must be one of {sorted(BASES)}")
        if self.basis != MODEL and not self.basis_note:
            raise ValueError(f"{self.label}: a {self.basis!r} basis must say what "
                             "(basis_note)")
        if self.kind not in KINDS:
            raise ValueError(f"{self.label}: kind must be one of {KINDS}")
        if self.kind == ASSUMPTION and not self.stated.strip():
            raise ValueError(f"{self.label}: an assumption is a remark only where the "
                             "paper states it: quote where (stated)")
        if self.kind == CHOSEN and self.basis != RECONSTRUCTED:
            raise ValueError(f"{self.label}: a result of chosen parameters rests on a "
                             f"{RECONSTRUCTED!r} basis")
        if self.rejected_target and self.paper_reading is None:
            raise ValueError(f"{self.label}: a rejected reading needs the paper's "
                             "reading it is rejected for (paper_reading)")
        if not 0 <= self.tolerance < 1:
            raise ValueError(f"{self.label}: tolerance must be in [0, 1)")
        if self.printed is None and not self.not_checkable:
            raise ValueError(f"{self.label}: no transcription and no reason why")
        for relation in [self.printed] + [self.reading(c) for c in self.conventions]:
            if relation is not None and not isinstance(relation, sp.Equality):
                raise TypeError(
                    f"{self.label}: a transcription must be a sympy.Eq built in "
                    f"code, got {type(relation).__name__}")

    @property
    def target(self) -> str:
        """Label of the derived step this formula is checked against."""
        return self.compare_to or self.label

    def reading(self, conv: Convention) -> sp.Basic:
        """``conv``'s relation, made from the transcription where ``conv`` names
        the operation (``crane_sym.readings``), else as typed; a ``symbol for
        another`` reading of a number takes the transcription's number (the
        reading of ``k̃_дин3 = 2.0736`` as ``k̃_дин4 = 2.0736``), so the number
        transcribed, not a second copy typed beside it, is what is checked."""
        reading = conv.reading
        if isinstance(reading, Reinterpretation):
            return reading.applied(self.printed) if self.printed is not None else None
        if (conv.kind == SYMBOL_FOR_ANOTHER and isinstance(reading, sp.Equality)
                and self.printed is not None and reading.rhs.is_number
                and self.printed.rhs.is_number):
            return sp.Eq(reading.lhs, self.printed.rhs, evaluate=False)
        return reading


@dataclass(frozen=True)
class PrintedItem:
    """One item of a paper's print that the audit owes a verdict: a numbered
    equation, a table cell, a number its text states as a result, or an
    unnumbered formula of its text. A paper lists its items from the print
    (``PRINTED_ITEMS`` beside its records), so the audit's recall counts the
    print, not the records.

    Parameters
    ----------
    item : str
        The item as the paper places it: ``"(13)"``, ``"Table 2, wind load, %"``.
    kind : str
        One of ``ITEM_KINDS``.
    records : tuple of str
        Labels of the records that judge it; a label judges the item when it is
        the label or begins with it and a comma (``"(28), P(0)"`` judges ``"(28)"``).
    """

    item: str
    kind: str
    records: tuple[str, ...]

    def __post_init__(self) -> None:
        if self.kind not in ITEM_KINDS:
            raise ValueError(f"printed item {self.item}: kind must be one of {ITEM_KINDS}")
        if not self.records:
            raise ValueError(f"printed item {self.item}: name the records that judge it")

    def judged_by(self, label: str) -> bool:
        """True when the record labelled ``label`` judges this item."""
        return any(label == r or label.startswith(r + ", ") for r in self.records)


#: What a printed item is.
ITEM_KINDS = ("numbered equation", "table cell", "number in the text", "unnumbered formula")


def numbered(first: int, last: int) -> list[PrintedItem]:
    """Items ``(first)`` … ``(last)`` of the print, each judged by the records of
    its number (an equation the OCR lost is still an item: the print had it).

    Parameters
    ----------
    first, last : int
        The first and last equation number printed.
    """
    return [PrintedItem(f"({n})", "numbered equation", (f"({n})",))
            for n in range(first, last + 1)]


def printed(paper: str, label: str, latex: str, relation: sp.Eq | None,
            note: str = "", **kwargs) -> PublishedFormula:
    """A formula of ``paper`` with its provenance written the same way everywhere:
    ``"<paper>, eq (n); <note>"`` for a numbered equation, else ``"<paper>, <label>"``.

    Parameters
    ----------
    paper : str
        The paper's source file name.
    label : str
        The equation number as printed, ``"(n)"``, or another label.
    latex : str
        The printed LaTeX.
    relation : sympy.Eq or None
        The transcription (None: nothing to check).
    note : str, optional
        The transcriber's note.
    **kwargs
        Further fields of :class:`PublishedFormula`.
    """
    where = f"{paper}, eq {label}" if label.startswith("(") else f"{paper}, {label}"
    return PublishedFormula(label, latex, relation, where + (f"; {note}" if note else ""),
                            **kwargs)
