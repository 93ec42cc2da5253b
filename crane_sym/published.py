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

EQUATION = "equation"      # a claim that must follow from the model
ASSUMPTION = "assumption"  # a stated modelling choice; a difference is a remark

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
        Short, stable id, e.g. ``"002-table2-plus-one"``.
    sentence : str
        One sentence a reviewer can check.
    """

    id: str
    sentence: str


@dataclass(frozen=True)
class Convention:
    """A reading of the print under a stated convention.

    Parameters
    ----------
    note : str
        What the convention is, e.g. "P in (6) is the frequency p of (5)".
    reading : sympy.Eq
        The printed formula read under the convention.
    kind : str
        Which reading of the policy (a key of ``READINGS``).
    compare_to : str
        The derived step the reading is checked against, when the reading
        changes the derived side (a fitted instant); default: the formula's.
    """

    note: str
    reading: sp.Eq
    kind: str
    compare_to: str = ""

    def __post_init__(self) -> None:
        if self.kind not in READINGS:
            raise ValueError(f"reading kind {self.kind!r} is not in the policy: "
                             f"{sorted(READINGS)}")


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
        ``equation`` or ``assumption``.
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

    def __post_init__(self) -> None:
        if self.basis not in BASES:
            raise ValueError(f"{self.label}: basis must be one of {sorted(BASES)}")
        if self.basis != MODEL and not self.basis_note:
            raise ValueError(f"{self.label}: a {self.basis!r} basis must say what "
                             "(basis_note)")
        if self.kind not in (EQUATION, ASSUMPTION):
            raise ValueError(f"kind must be {EQUATION!r} or {ASSUMPTION!r}")
        if not 0 <= self.tolerance < 1:
            raise ValueError(f"{self.label}: tolerance must be in [0, 1)")
        if self.printed is None and not self.not_checkable:
            raise ValueError(f"{self.label}: no transcription and no reason why")
        for relation in [self.printed] + [c.reading for c in self.conventions]:
            if relation is not None and not isinstance(relation, sp.Equality):
                raise TypeError(
                    f"{self.label}: a transcription must be a sympy.Eq built in "
                    f"code, got {type(relation).__name__}")

    @property
    def target(self) -> str:
        """Label of the derived step this formula is checked against."""
        return self.compare_to or self.label


def printed(paper: str, label: str, latex: str, relation: sp.Eq | None,
            note: str = "", **kwargs) -> PublishedFormula:
    """A formula of ``paper`` with its provenance written the same way everywhere:
    ``"<paper>, eq (n); <note>"`` for a numbered equation, else ``"<paper>, <label>"``."""
    where = f"{paper}, eq {label}" if label.startswith("(") else f"{paper}, {label}"
    return PublishedFormula(label, latex, relation, where + (f"; {note}" if note else ""),
                            **kwargs)
