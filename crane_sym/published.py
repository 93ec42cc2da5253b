"""Published formulas: the paper's text as printed, beside its transcription.

The transcription is a SymPy expression built in code (never parsed from the
LaTeX), faithful to the print *including its errors*. Readings the print
allows but does not spell out (a symbol used for another, an ambiguous
operator) are ``Convention``s: the audit tries the print first and a
convention only after, and says which one it needed.
"""
from __future__ import annotations

from dataclasses import dataclass

import sympy as sp

EQUATION = "equation"      # a claim that must follow from the model
ASSUMPTION = "assumption"  # a stated modelling choice; a difference is a remark


@dataclass(frozen=True)
class Convention:
    """A reading of the print under a stated convention.

    Parameters
    ----------
    note : str
        What the convention is, e.g. "P in (6) is the frequency p of (5)".
    reading : sympy.Eq
        The printed formula read under the convention.
    """

    note: str
    reading: sp.Eq


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

    def __post_init__(self) -> None:
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
