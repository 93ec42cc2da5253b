"""What a family of piecewise-linear models tells the batched solver, and
what it gets back.

A model describes itself to :func:`crane_sym.mechanics.batched.largest_batched`
by :class:`BatchedSystem`: modes as integer codes, and its matrices, guards
(:class:`BatchedGuard`), switching rule and output for an array of designs in
one mode. The solver answers with :class:`BatchedLargest`: each design's
largest output, when, its phases, and which designs took the per-design
route or stopped at the cap.
"""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import Hashable, Protocol

import numpy as np

from crane_sym.mechanics.phase_table import HybridRun

__all__ = ["BatchedGuard", "BatchedLargest", "BatchedSystem"]


@dataclass(frozen=True)
class BatchedGuard:
    """A guard of k designs in one mode: g = weights·x + constant, per design."""

    name: str
    weights: np.ndarray          # (k, n)
    constant: np.ndarray         # (k,)
    direction: int = 0


class BatchedSystem(Protocol):
    """What :func:`largest_batched` needs from a family of piecewise-linear models.

    Every method gets a mode code and ``index``, the designs (positions in the
    family) that are in that mode, and answers for all of them at once.
    """

    n: int

    def matrices(self, mode: int, index: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """(A, b) of each design, shapes (k, n, n) and (k, n)."""

    def guards(self, mode: int, index: np.ndarray) -> list[BatchedGuard]:
        """The events that end the mode, in the per-design model's order."""

    def switch(self, mode: int, event: str, index: np.ndarray, t: np.ndarray,
               x: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Next mode codes (k,) and states (k, n) after ``event``."""

    def output(self, mode: int, index: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """The output as weights (k, n) and constants (k,)."""

    def run(self, i: int) -> HybridRun:
        """Design ``i`` for the per-design route (its output the same)."""

    def mode(self, code: int, i: int) -> Hashable:
        """The per-design model's mode of a mode code, for design ``i``."""


@dataclass
class BatchedLargest:
    """The largest |output| of each design's run (``value`` keeps its sign)
    and when; ``phases`` per design; which designs took the per-design route
    (``fallback``) and which stopped at the cap (``capped``, value NaN)."""

    value: np.ndarray
    time: np.ndarray
    phases: np.ndarray
    fallback: np.ndarray
    capped: np.ndarray
    rounds: int = 0
    #: Where the time went: closed forms, event search, the output's extrema,
    #: switching and bookkeeping, the per-design route [CPU s of this process].
    seconds: dict[str, float] = field(default_factory=dict)
    #: Designs the batched route took part of the way, the per-design route
    #: the rest (the last ``tail`` still running).
    finished_alone: np.ndarray = None

    @property
    def summary(self) -> dict[str, int]:
        """Designs in all, by the batched route (some finished alone), by the
        per-design route from the start (fallback), capped."""
        n = self.value.size
        fell, cap = int(self.fallback.sum()), int(self.capped.sum())
        alone = 0 if self.finished_alone is None else int(self.finished_alone.sum())
        return {"designs": n, "batched": n - fell - cap, "finished_alone": alone,
                "fallback": fell, "capped": cap, "rounds": self.rounds}
