"""Many designs of one piecewise-linear model at once: the largest of an
affine output over each design's run, every phase in closed form.

:func:`crane_sym.mechanics.piecewise_linear.simulate` runs one design; a
design sweep of a hybrid model ran it once per design in a Python loop.
:func:`largest_batched` runs an array of designs together. Each design keeps
its own mode, state, clock and schedule. A round takes every design still
running through one phase: the designs are grouped by mode, each group's
closed forms come from batched eigen-decompositions
(:func:`crane_sym.mechanics.batched_forms.batch_forms`), the guards of all
its designs are searched together by the certified no-skip step and refined
by bracketing on arrays (:mod:`crane_sym.mechanics.batched_events`), the
output's stationary points of the phase are found the same way, and the
model's vectorised rule switches the designs that fired each event. Designs
that reach their end leave the work.

What the per-design solver does, this does: the phase ends at the earliest
guard crossing strictly before the next scheduled instant (the first guard
on a tie), the scheduled event otherwise; the largest |output| is taken over
each phase's ends and stationary points (:func:`crane_sym.mechanics.phase_table.largest`).
A design whose eigen-decomposition the batched route refuses (ill-conditioned,
a repeated eigenvalue) is run by the per-design route instead
(:meth:`BatchedSystem.run`, :func:`simulate`), and counted
(:attr:`BatchedLargest.fallback`). A design with more than ``max_events``
phases is stopped there and marked (:attr:`BatchedLargest.capped`, value NaN),
never silently cut short.

The model describes itself to the solver by :class:`BatchedSystem`: modes as
integer codes, and its matrices, guards, switching rule and output for an
array of designs in one mode.
"""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import Protocol, Sequence

import numpy as np

from crane_sym.mechanics.batched_events import all_crossings, first_crossings
from crane_sym.mechanics.batched_forms import BatchForm, Signals, batch_forms
from crane_sym.mechanics.phase_table import HybridRun, largest

__all__ = ["BatchedGuard", "BatchedLargest", "BatchedSystem", "largest_batched"]

#: Code of the event "end" (the run reached t_end).
END = -1


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
    seconds: dict[str, float] = field(default_factory=dict)

    @property
    def summary(self) -> dict[str, int]:
        """Designs in all, by the batched route, by the per-design route, capped."""
        n = self.value.size
        fell, cap = int(self.fallback.sum()), int(self.capped.sum())
        return {"designs": n, "batched": n - fell - cap, "fallback": fell, "capped": cap,
                "rounds": self.rounds}


@dataclass
class _State:
    """Every design's mode, state, clock, schedule pointer and best so far."""

    mode: np.ndarray
    x: np.ndarray
    t: np.ndarray
    t_end: np.ndarray
    times: np.ndarray            # (N, S) scheduled instants, sorted, inf when none
    names: np.ndarray            # (N, S) their name codes
    ptr: np.ndarray
    count: np.ndarray
    best: np.ndarray
    best_t: np.ndarray
    done: np.ndarray
    fell: np.ndarray
    capped: np.ndarray


def largest_batched(system: BatchedSystem, modes: np.ndarray, x0: np.ndarray,
                    t_end: np.ndarray | float, schedule_names: Sequence[str] = (),
                    schedule_times: np.ndarray | None = None, *, h_min: float = 1e-10,
                    max_events: int = 10_000) -> BatchedLargest:
    """The largest |output| over each design's run from t = 0 to ``t_end``.

    Parameters
    ----------
    system : BatchedSystem
        The family; design i is ``system.run(i)`` for the per-design route.
    modes : (N,) int
        Each design's first mode.
    x0 : (N, n)
        Each design's state at t = 0.
    t_end : float or (N,)
        Each design's end.
    schedule_names, schedule_times : (S,) names and (N, S) instants
        Events known in advance, per design (those outside [0, t_end) ignored,
        ties taken in the names' order, as :func:`simulate` sorts them).
    """
    x0 = np.atleast_2d(np.asarray(x0, dtype=float))
    N = x0.shape[0]
    names = list(schedule_names)
    times = (np.zeros((N, 0)) if schedule_times is None
             else np.broadcast_to(np.asarray(schedule_times, float), (N, len(names))))
    t_end = np.broadcast_to(np.asarray(t_end, dtype=float), (N,)).copy()
    code = np.broadcast_to(np.argsort(np.argsort(names, kind="stable")), times.shape)
    times = np.where((times >= 0) & (times < t_end[:, None]), times, np.inf)
    order = np.lexsort((code, times), axis=-1)
    s = _State(np.asarray(modes, dtype=np.int64).copy(), x0.copy(), np.zeros(N), t_end,
               np.take_along_axis(times, order, axis=1),
               np.take_along_axis(np.broadcast_to(np.arange(len(names)), times.shape), order,
                                  axis=1),
               np.zeros(N, dtype=np.intp), np.zeros(N, dtype=np.intp), np.full(N, np.nan),
               np.zeros(N), np.zeros(N, dtype=bool), np.zeros(N, dtype=bool),
               np.zeros(N, dtype=bool))
    best_key = np.full(N, -np.inf)
    rounds = 0
    while True:
        act = np.flatnonzero(~(s.done | s.fell | s.capped))
        if not act.size:
            break
        rounds += 1
        for mode in np.unique(s.mode[act]):
            idx = act[s.mode[act] == mode]
            A, b = system.matrices(int(mode), idx)
            parts, refused = batch_forms(A, b)
            s.fell[idx[refused]] = True
            for where, form in parts:
                _phase(system, int(mode), idx[where], form, s, best_key, names, h_min)
        over = ~(s.done | s.fell) & (s.count >= max_events)
        s.capped |= over
    for i in np.flatnonzero(s.fell):                 # the per-design route
        run = system.run(int(i))
        s.best_t[i], s.best[i] = largest(run.solve(), run.system, run.output, magnitude=True)
    s.best[s.capped] = np.nan
    return BatchedLargest(s.best, s.best_t, s.count, s.fell, s.capped, rounds)


def _signals(form: BatchForm, vectors: np.ndarray, weights: np.ndarray,
             const: np.ndarray) -> Signals:
    """g = w·x + k of each design over the phase, as a :class:`Signals`."""
    amps = np.einsum("kti,ki->kt", vectors[:, :, : form.n], weights)
    return Signals.of(form, amps, np.asarray(const, float))


def _phase(system: BatchedSystem, mode: int, idx: np.ndarray, form: BatchForm, s: _State,
           best_key: np.ndarray, names: list[str], h_min: float) -> None:
    """One phase of the designs ``idx`` (all in ``mode``): its end and event,
    the output's largest over it, the switch."""
    k = idx.size
    vec = form.vectors(s.x[idx])
    rows_k = np.arange(k)
    pending = s.ptr[idx] < s.times.shape[1]
    slot = np.minimum(s.ptr[idx], max(s.times.shape[1] - 1, 0))
    nxt = s.times[idx, slot] if s.times.shape[1] else np.full(k, np.inf)
    nxt = np.where(pending, nxt, np.inf)
    scheduled = np.isfinite(nxt)
    horizon = np.where(scheduled, nxt, s.t_end[idx]) - s.t[idx]
    event = np.where(scheduled, s.names[idx, slot] if s.times.shape[1] else END, END)
    end = horizon.copy()
    guards = system.guards(mode, idx)
    if guards and np.any(horizon > 0):
        G = len(guards)
        amps = np.concatenate([np.einsum("kti,ki->kt", vec[:, :, : form.n], g.weights)
                               for g in guards])
        sig = Signals.of(form, amps,
                         np.concatenate([np.broadcast_to(g.constant, (k,)) for g in guards]),
                         np.tile(rows_k, G))
        direction = np.repeat([g.direction for g in guards], k).astype(float)
        span = np.tile(horizon, G)
        # a constant g (a guard of a side the mode does not move) cannot cross
        search = np.flatnonzero(~sig.constant() & (span > 0))
        hits = np.full(G * k, np.nan)
        hits[search] = first_crossings(sig.take(search), np.zeros(search.size), span[search],
                                       direction[search], h_min)
        hits = hits.reshape(G, k)
        for j in range(G):                            # earliest; the first guard on a tie
            better = hits[j] < end
            end = np.where(better, hits[j], end)
            event = np.where(better, len(names) + j, event)
    # the output over [0, end]: its ends and stationary points
    w, c = system.output(mode, idx)
    out = _signals(form, vec, w, c)
    A, b = system.matrices(mode, idx)
    rate = _signals(form, vec, np.einsum("ki,kij->kj", w, A), np.einsum("ki,ki->k", w, b))
    cand_rows = [rows_k, rows_k]
    cand_t = [np.zeros(k), end]
    moving = np.flatnonzero(np.any(w != 0, axis=1) & (end > 1e-12))
    if moving.size:
        sub = rate.take(moving)
        which, when = all_crossings(sub, np.zeros(moving.size), end[moving], h_min)
        cand_rows.append(moving[which])
        cand_t.append(when)
    rows, when = np.concatenate(cand_rows), np.concatenate(cand_t)
    vals = out.value(rows, when)
    keys = np.abs(vals)
    order = np.lexsort((-keys, rows))                 # per design, its largest first
    first = order[np.r_[True, rows[order][1:] != rows[order][:-1]]]
    r, v, key = rows[first], vals[first], keys[first]
    gi = idx[r]
    up = key > best_key[gi]
    s.best[gi[up]], s.best_t[gi[up]] = v[up], s.t[gi[up]] + when[first][up]
    best_key[gi[up]] = key[up]
    # the state at the end, the clock, the switch
    x_end = form.state(end, vec)
    s.t[idx] += end
    s.count[idx] += 1
    fin = event == END
    s.done[idx[fin]] = True
    sched = (event >= 0) & (event < len(names))
    s.ptr[idx[sched]] += 1
    for e in np.unique(event[~fin]):
        sel = np.flatnonzero(event == e)
        name = names[e] if e < len(names) else guards[e - len(names)].name
        new_mode, new_x = system.switch(mode, name, idx[sel], s.t[idx[sel]], x_end[sel])
        s.mode[idx[sel]] = new_mode
        s.x[idx[sel]] = new_x
    s.x[idx[fin]] = x_end[fin]
