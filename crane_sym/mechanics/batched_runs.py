"""Any piecewise-linear model through the batched solver: an array of
per-design runs (:class:`crane_sym.mechanics.phase_table.HybridRun`) seen as
one :class:`crane_sym.mechanics.batched.BatchedSystem`.

A model written for one design (a paper's, or one assembled from components)
describes each mode by Python code per design. :class:`RunFamily` asks each
design's system for its matrices, guards and output, stacks them for the
designs in a mode, and calls each design's switching rule on the designs
that fired an event; the closed forms, the event search and the extrema are
the batched solver's. Where the runs' systems know themselves as one family
(their class's ``family(systems)``: designs of one component template,
:class:`crane_sym.components.design_family.DesignFamily`), a mode's matrices,
guards, the switches its rules allow and the runs' outputs (its
``outputs(outputs)``, where it offers them) come from it for all the designs
in the mode at once. Elsewhere the Python calls cost per design and phase
what a model written for arrays (a paper's own family of designs) saves;
the closed forms and the search are shared. The designs' guards in a mode must agree in number, names and
directions (they do for designs of one model).

Designs that need no run of their own to be solved together (a block of a
component template whose designs differ only in values the family holds as
arrays) give the family and their starts instead
(:func:`largest_of_starts`); a design's own run is then built only where the
per-design route takes it (``runs[i]`` of a sequence that builds on demand).
"""
from __future__ import annotations

from typing import Hashable, Sequence

import numpy as np

from crane_sym.mechanics.batched import BatchedGuard, BatchedLargest, largest_batched
from crane_sym.mechanics.phase_table import HybridRun

__all__ = ["RunFamily", "largest_of_runs", "largest_of_starts"]


class RunFamily:
    """The runs as one family: mode codes are given to modes as they appear.
    ``family`` and ``output`` given (designs that are one family without a
    run each, :func:`largest_of_starts`), ``runs`` is asked only for the
    designs the per-design route takes."""

    def __init__(self, runs: Sequence[HybridRun], family=None, output=None) -> None:
        if family is not None:
            self.runs, self.family, self._output = runs, family, output
        else:
            self.runs = list(runs)
            made = getattr(self.runs[0].system, "family", None)
            #: The systems as one family, or None (each asked in turn).
            self.family = made([r.system for r in self.runs]) if made else None
            #: The runs' outputs for designs at once where the family offers it, else None.
            self._output = (self.family.outputs([r.output for r in self.runs])
                            if self.family is not None else None)
        self._modes: list[Hashable] = []
        self._codes: dict[Hashable, int] = {}

    def code(self, mode: Hashable) -> int:
        """The code of ``mode`` (a new one on its first appearance)."""
        if mode not in self._codes:
            self._codes[mode] = len(self._modes)
            self._modes.append(mode)
        return self._codes[mode]

    def codes(self, modes: Sequence[Hashable]) -> np.ndarray:
        """The code of each of ``modes``; most designs share a few mode objects,
        each hashed once."""
        seen: dict[int, int] = {}
        return np.array([seen[id(m)] if id(m) in seen else seen.setdefault(id(m), self.code(m))
                         for m in modes], dtype=np.int64)

    def mode(self, code: int, i: int | None = None) -> Hashable:
        """The mode of a code (the same for every design ``i``)."""
        return self._modes[code]

    def matrices(self, mode: int, index: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Each design's (A, b) in the mode, stacked."""
        if self.family is not None:
            return self.family.matrices(self._modes[mode], index)
        pairs = [self.runs[i].system.matrices(self._modes[mode]) for i in index]
        return (np.array([np.asarray(A, float) for A, _ in pairs]),
                np.array([np.asarray(b, float) for _, b in pairs]))

    def guards(self, mode: int, index: np.ndarray) -> list[BatchedGuard]:
        """Each design's guards in the mode, stacked guard by guard."""
        if self.family is not None:
            return [BatchedGuard(name, w, k, d)
                    for name, w, k, d in self.family.guards(self._modes[mode], index)]
        lists = [self.runs[i].system.guards(self._modes[mode]) for i in index]
        first = lists[0]
        if any([(g.name, g.direction) for g in gs] != [(g.name, g.direction) for g in first]
               for gs in lists):
            raise ValueError(f"designs differ in the guards of mode {self._modes[mode]!r}")
        return [BatchedGuard(g.name, np.array([gs[j].weights for gs in lists], dtype=float),
                             np.array([gs[j].constant for gs in lists], dtype=float),
                             g.direction) for j, g in enumerate(first)]

    def switch(self, mode: int, event: str, index: np.ndarray, t: np.ndarray,
               x: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Each design's own rule, on the designs that fired ``event`` (the
        family's, for all of them at once, where it has one)."""
        both = None if self.family is None else \
            self.family.switch(self._modes[mode], event, index, x)
        if both is not None:
            return self.codes(both[0]), both[1]
        codes, out = np.empty(index.size, dtype=np.int64), np.empty_like(x)
        for k, i in enumerate(index):
            new, out[k] = self.runs[i].system.switch(self._modes[mode], event, float(t[k]),
                                                     x[k].copy())
            codes[k] = self.code(new)
        return codes, out

    def output(self, mode: int, index: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Each run's output in the mode, stacked (as :func:`largest` takes it:
        the run's ``scale`` is its table's, not applied here)."""
        if self._output is not None:
            return self._output(self._modes[mode], index)
        pairs = [self.runs[i].output(self._modes[mode]) for i in index]
        return (np.array([np.asarray(w, float) for w, _ in pairs]),
                np.array([float(k) for _, k in pairs]))

    def run(self, i: int) -> HybridRun:
        """Design ``i`` itself."""
        return self.runs[i]


def largest_of_runs(runs: Sequence[HybridRun], **options) -> BatchedLargest:
    """The largest |output| (or, with ``magnitude=False``, output) of each
    run, the runs solved together
    (:func:`crane_sym.mechanics.batched.largest_batched`). Scheduled events
    a run lacks are taken as never happening.

    Parameters
    ----------
    runs : sequence of HybridRun
        One run a design: system, initial mode and state, end, schedule.
    **options
        Passed on to :func:`crane_sym.mechanics.batched.largest_batched`
        (``magnitude`` and the solver's tolerances).
    """
    family = RunFamily(runs)
    columns = sorted({key for r in runs for _, key in _numbered(r.schedule)})
    times = np.full((len(runs), len(columns)), np.inf)
    for i, r in enumerate(runs):
        for t, key in _numbered(r.schedule):
            times[i, columns.index(key)] = t
    modes = np.array([family.code(r.mode) for r in runs])
    x0 = np.array([np.asarray(r.x0, float) for r in runs])
    t_end = np.array([r.t_end for r in runs], dtype=float)
    return largest_batched(family, modes, x0, t_end, [name for name, _ in columns], times,
                           **options)


def largest_of_starts(family: RunFamily, modes: Sequence[Hashable], x0: np.ndarray,
                      t_end: float, schedule: Sequence, **options) -> BatchedLargest:
    """:func:`largest_of_runs` of designs given as one family and their starts:
    each design's first mode and state, one end and one schedule for all.
    What it returns is what :func:`largest_of_runs` returns for the designs'
    runs (``family.runs[i]``, asked only where the per-design route takes
    design i).

    Parameters
    ----------
    family : RunFamily
        The designs, made with their family and output.
    modes : sequence
        Each design's first mode.
    x0 : (N, n)
        Each design's state at t = 0.
    t_end : float
        The runs' end.
    schedule : sequence of (time, name)
        Events known in advance, the same for every design.
    **options
        As for :func:`largest_of_runs`.
    """
    columns = [key for _, key in _numbered(schedule)]
    order = sorted(range(len(columns)), key=lambda j: columns[j])
    given = [t for t, _ in _numbered(schedule)]
    times = np.broadcast_to(np.array([given[j] for j in order], dtype=float),
                            (len(modes), len(columns)))
    return largest_batched(family, family.codes(modes), np.asarray(x0, float), float(t_end),
                           [columns[j][0] for j in order], times, **options)


def _numbered(schedule) -> list[tuple[float, tuple[str, int]]]:
    """(time, (name, occurrence)) of each scheduled event: a name scheduled
    several times (the steps of a start panel) keeps each instant."""
    seen: dict[str, int] = {}
    out = []
    for t, name in schedule:
        k = seen.get(name, 0)
        seen[name] = k + 1
        out.append((float(t), (name, k)))
    return out
