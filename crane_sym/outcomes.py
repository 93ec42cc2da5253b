"""How a check comes out: ``pass``, ``fail`` or ``inconclusive``, with what it saw.

Shared by the audit's checks (``checks``) and the self-checks of a solution
(``verification``), so neither has to import the other's layer.
"""
from __future__ import annotations

from dataclasses import dataclass

__all__ = ["FAIL", "INCONCLUSIVE", "PASS", "CheckOutcome"]

PASS, FAIL, INCONCLUSIVE = "pass", "fail", "inconclusive"


@dataclass(frozen=True)
class CheckOutcome:
    """Result of one check: which, how it came out, and what it saw."""

    method: str
    status: str
    detail: str
    #: For a failed numeric check: every symbol's value at the failing point
    #: (LaTeX name, value to 12 digits), so a reviewer can recompute by hand.
    point: tuple[tuple[str, str], ...] = ()
