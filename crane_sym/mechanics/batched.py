"""Many designs of one piecewise-linear model at once: the largest of an
affine output over each design's run, every phase in closed form.

:func:`crane_sym.mechanics.piecewise_linear.simulate` runs one design; a
design sweep of a hybrid model ran it once per design in a Python loop.
:func:`largest_batched` runs an array of designs together. Each design keeps
its own mode, state, clock and schedule. A round takes every design still
running through one phase: the designs are grouped by mode, each group's
closed forms come from batched eigen-decompositions
(:func:`crane_sym.mechanics.batched_forms.batch_forms`, kept per mode by
:class:`crane_sym.mechanics.batched_cache.FormCache`, each distinct A
decomposed once for all the modes it appears in:
:class:`crane_sym.mechanics.batched_spectra.SpectraMemo`), the guards of every
design of every mode are searched together by the certified no-skip step
and refined by bracketing on arrays
(:mod:`crane_sym.mechanics.batched_events`), the output's stationary points
of the phase are found the same way (skipped where a bound of the output
over the phase cannot pass the design's best so far), and the model's
vectorised rule switches the designs that fired each event. Designs that
reach their end leave the work; with ``tail``, the last designs still running
go on from where they are by the per-design route (:func:`simulate`).

What the per-design solver does, this does: the phase ends at the earliest
guard crossing strictly before the next scheduled instant (the first guard
on a tie), the scheduled event otherwise; the largest |output| is taken over
each phase's ends and stationary points (:func:`crane_sym.mechanics.phase_table.largest`).
A design whose eigen-decomposition the batched route refuses (ill-conditioned:
a defective eigenvalue, a pair nearly real) is run by the per-design route instead
(:meth:`BatchedSystem.run`, :func:`simulate`), and counted
(:attr:`BatchedLargest.fallback`). A design with more than ``max_events``
phases is stopped there and marked (:attr:`BatchedLargest.capped`, value NaN),
never silently cut short.

The model describes itself to the solver by :class:`BatchedSystem`
(:mod:`crane_sym.mechanics.batched_system`, re-exported here): modes as
integer codes, and its matrices, guards, switching rule and output for an
array of designs in one mode.
"""
from __future__ import annotations

import functools
import time
from dataclasses import dataclass
from typing import Sequence

import numpy as np

from crane_sym.mechanics.batched_events import all_crossings, first_crossings
from crane_sym.mechanics.batched_cache import FormCache
from crane_sym.mechanics.batched_forms import COND_LIMIT, BatchForm
from crane_sym.mechanics.batched_signals import Signals
from crane_sym.mechanics.batched_spectra import SpectraMemo
from crane_sym.mechanics.batched_system import BatchedGuard, BatchedLargest, BatchedSystem
from crane_sym.mechanics.phase_table import PEAK_TIE, largest
from crane_sym.mechanics.piecewise_linear import simulate

__all__ = ["BatchedGuard", "BatchedLargest", "BatchedSystem", "largest_batched"]

#: Code of the event "end" (the run reached t_end).
END = -1


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
    tail: np.ndarray = None
    magnitude: bool = True


def largest_batched(system: BatchedSystem, modes: np.ndarray, x0: np.ndarray,
                    t_end: np.ndarray | float, schedule_names: Sequence[str] = (),
                    schedule_times: np.ndarray | None = None, *, h_min: float = 1e-10,
                    max_events: int = 10_000, cond_limit: float = COND_LIMIT,
                    tail: int = 0, magnitude: bool = True) -> BatchedLargest:
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
    h_min, max_events : as for :func:`simulate`; a design past ``max_events``
        phases is marked capped.
    cond_limit : float
        Largest eigenvalue condition number the batched closed forms accept
        (:func:`crane_sym.mechanics.batched_forms.batch_forms`); a design above
        it, in any mode it reaches, takes the per-design route.
    tail : int
        When this many designs or fewer are still running, each goes on from
        its current mode and state by the per-design route. Default 0: a
        round of a few designs costs NumPy's per-call overhead (~1 ms), less
        than the per-design route's run (measured on 001's grid: the last 8
        designs 0.36 s by the per-design route, 3 ms in rounds).
    magnitude : bool
        The largest |output| (True), or the largest output (False), as
        :func:`crane_sym.mechanics.phase_table.largest` takes it.
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
               np.zeros(N, dtype=bool), np.zeros(N, dtype=bool), magnitude)
    best_key = np.full(N, -np.inf)
    forms: dict[int, FormCache] = {}
    memo = SpectraMemo()                 # modes that differ in b only share A's spectra
    clock = dict.fromkeys(("forms", "events", "extrema", "switching", "tail", "fallback"),
                          0.0)
    rounds = 0
    while True:
        act = np.flatnonzero(~(s.done | s.fell | s.capped))
        if act.size <= tail:
            tick = time.process_time()
            for i in act:
                _finish(system, int(i), s, best_key, names, max_events)
            clock["tail"] += time.process_time() - tick
            break
        rounds += 1
        tick = time.process_time()
        groups = []
        for mode in np.unique(s.mode[act]):
            idx = act[s.mode[act] == mode]
            if int(mode) not in forms:
                forms[int(mode)] = FormCache(N, cond_limit, memo)
            cache = forms[int(mode)]
            # (A, b) asked for only where a design meets the mode first
            for where, form in cache.forms(idx, functools.partial(system.matrices, int(mode))):
                if form is None:
                    s.fell[idx[where]] = True
                else:
                    groups.append(_Group(int(mode), idx[where], form))
        clock["forms"] += time.process_time() - tick
        if groups:
            _round(system, groups, s, best_key, names, h_min, clock)
        over = ~(s.done | s.fell) & (s.count >= max_events)
        s.capped |= over
    tick = time.process_time()
    for i in np.flatnonzero(s.fell):                 # the per-design route
        run = system.run(int(i))
        try:
            result = simulate(run.system, run.mode, run.x0, run.t_end, run.schedule,
                              max_events=max_events, exact=run.exact)
        except RuntimeError:                          # past max_events
            s.fell[i], s.capped[i] = False, True
            continue
        s.best_t[i], s.best[i] = largest(result, run.system, run.output, magnitude=magnitude)
    clock["fallback"] = time.process_time() - tick
    s.best[s.capped] = np.nan
    return BatchedLargest(s.best, s.best_t, s.count, s.fell, s.capped, rounds, clock,
                          s.tail)


def _finish(system: BatchedSystem, i: int, s: _State, best_key: np.ndarray, names: list[str],
            max_events: int) -> None:
    """Design ``i`` from its current mode and state to its end by the
    per-design route (:func:`simulate`), its largest joined to the batched part's."""
    run = system.run(i)
    t = s.t[i]
    pending = [(float(s.times[i, j]) - t, names[s.names[i, j]])
               for j in range(s.ptr[i], s.times.shape[1]) if np.isfinite(s.times[i, j])]
    try:
        result = simulate(run.system, system.mode(int(s.mode[i]), i), s.x[i], s.t_end[i] - t,
                          pending, max_events=max(max_events - int(s.count[i]), 1),
                          exact=False)
    except RuntimeError:                              # past max_events
        s.capped[i] = True
        return
    when, value = largest(result, run.system, run.output, magnitude=s.magnitude)
    key = abs(value) if s.magnitude else value
    if key > _beyond(best_key[i]):
        s.best[i], s.best_t[i], best_key[i] = value, t + when, key
    s.count[i] += len(result.segments)
    s.tail[i] = True
    s.done[i] = True


def _beyond(best):
    """What a later peak must pass to replace ``best``: of peaks within
    ``PEAK_TIE`` (1e-9) the first is kept, as ``phase_table.largest`` keeps
    it (-inf stays)."""
    return best + PEAK_TIE * np.abs(np.where(np.isfinite(best), best, 0.0))


def _signals(form: BatchForm, vectors: np.ndarray, weights: np.ndarray,
             const: np.ndarray) -> Signals:
    """g = w·x + k of each design over the phase, as a :class:`Signals`; a
    term within 64 ulps of the sum it comes from is rounding noise of an exact
    zero (the rigid mode's powers of t of a load that only the springs set) and
    is 0, as on the per-design route (``event_search.exact_zeros``)."""
    parts = vectors[:, :, : form.n] * weights[:, None, :]
    amps = parts.sum(axis=2)
    amps[np.abs(amps) <= 64 * np.finfo(float).eps * np.abs(parts).sum(axis=2)] = 0.0
    return Signals.of(form, amps, np.asarray(const, float))


@dataclass
class _Group:
    """Designs of one mode and one spectral structure in a round."""

    mode: int
    idx: np.ndarray
    form: BatchForm
    vectors: np.ndarray = None
    end: np.ndarray = None
    event: np.ndarray = None
    guards: list = None


def _round(system: BatchedSystem, groups: list[_Group], s: _State, best_key: np.ndarray,
           names: list[str], h_min: float, clock: dict[str, float]) -> None:
    """One phase of every design in ``groups``: the guards of all of them
    searched together, then the output's extrema, then the switches."""
    tick = time.process_time()
    S = s.times.shape[1]
    sigs, spans, dirs, owner = [], [], [], []
    for gi, grp in enumerate(groups):
        idx, form = grp.idx, grp.form
        k = idx.size
        grp.vectors = form.vectors(s.x[idx])
        slot = np.minimum(s.ptr[idx], max(S - 1, 0))
        nxt = np.where(s.ptr[idx] < S, s.times[idx, slot], np.inf) if S else np.full(k, np.inf)
        scheduled = np.isfinite(nxt)
        horizon = np.where(scheduled, nxt, s.t_end[idx]) - s.t[idx]
        grp.event = np.where(scheduled, s.names[idx, slot] if S else END, END)
        grp.end = horizon
        grp.guards = system.guards(grp.mode, idx)
        G = len(grp.guards)
        if not G:
            continue
        # every guard of the group in one product: row r·G + j is guard j of design r
        W = np.stack([np.broadcast_to(g.weights, (k, form.n)) for g in grp.guards], axis=1)
        K = np.stack([np.broadcast_to(np.asarray(g.constant, float), (k,))
                      for g in grp.guards], axis=1)
        amps = np.matmul(grp.vectors[:, :, : form.n], W.transpose(0, 2, 1))   # (k, T, G)
        amps = amps.transpose(0, 2, 1).reshape(k * G, -1)
        # a constant g (a guard of a side the mode does not move) cannot cross:
        # every term but the kernel's power 0 is 0
        moves = np.zeros(k * G, dtype=bool)
        for col in range(amps.shape[1]):
            if col != form.real + 2 * form.pairs:
                moves |= amps[:, col] != 0
        keep = np.flatnonzero(moves & np.repeat(horizon > 0, G))
        if keep.size:
            r, j = np.divmod(keep, G)
            sigs.append(Signals.of(form, amps[keep], K.ravel()[keep], owner=r))
            spans.append(horizon[r])
            dirs.append(np.array([float(g.direction) for g in grp.guards])[j])
            owner.append(np.stack([np.full(keep.size, gi), j, r]))
    if sigs:
        gi_, j_, r_ = np.concatenate(owner, axis=1)
        base = np.cumsum([0] + [grp.idx.size for grp in groups])
        pos = base[gi_] + r_
        # one design's guards race: only the earliest of them matters
        hits = first_crossings(Signals.concat(sigs), np.zeros(sum(a.size for a in spans)),
                               np.concatenate(spans), np.concatenate(dirs), h_min, owner=pos)
        end, event = np.concatenate([g.end for g in groups]), np.concatenate(
            [g.event for g in groups])
        for j in range(int(j_.max()) + 1):            # earliest; the first guard on a tie
            sel = np.flatnonzero((j_ == j) & (hits < end[pos]))
            end[pos[sel]] = hits[sel]
            event[pos[sel]] = len(names) + j
        for gi, grp in enumerate(groups):
            grp.end, grp.event = end[base[gi]:base[gi + 1]], event[base[gi]:base[gi + 1]]
    clock["events"] += time.process_time() - tick
    tick = time.process_time()
    _extrema(system, groups, s, best_key, h_min)
    clock["extrema"] += time.process_time() - tick
    tick = time.process_time()
    for grp in groups:
        _advance(system, grp, s, names)
    clock["switching"] += time.process_time() - tick


def _extrema(system: BatchedSystem, groups: list[_Group], s: _State, best_key: np.ndarray,
             h_min: float) -> None:
    """The output's largest |value| over each design's phase: its ends and its
    stationary points (zeros of its rate, all found in one search)."""
    outs, ends = [], []
    for grp in groups:
        w, c = system.output(grp.mode, grp.idx)
        outs.append(_signals(grp.form, grp.vectors, w, c))
        ends.append(grp.end)
    out, end = Signals.concat(outs), np.concatenate(ends)
    rate = out.rate()
    idx = np.concatenate([grp.idx for grp in groups])
    m = end.size
    rows = np.arange(m)
    # a phase whose output cannot pass the design's best so far needs no extrema
    reach = (np.abs(out.poly[:, 0]) if s.magnitude else out.poly[:, 0]) + out.spread(end)
    moving = np.flatnonzero(~rate.constant() & ~out.constant() & (end > 1e-12)
                            & (reach > best_key[idx]))
    v = out.value(rows, np.zeros(m))                 # at t = 0: no transcendental
    v_end = out.value(rows, end)
    key, key_end = (np.abs(v), np.abs(v_end)) if s.magnitude else (v, v_end)
    if moving.size:
        # crests only until the output has settled: past that instant none can
        # come within the tie of what is known, nor add a tenth of the tie
        # (a load settling to a constant: its rate's zeros are rounding noise)
        known = np.maximum(np.maximum(key, key_end), best_key[idx])[moving]
        g_c = out.poly[moving, 0]
        lower = known - PEAK_TIE * np.abs(known)
        room = lower - (np.abs(g_c) if s.magnitude else g_c)
        margin = np.maximum(room, 0.1 * PEAK_TIE * np.maximum(np.abs(g_c), np.abs(known)))
        margin = np.where(np.isfinite(margin), margin, 0.0)
        until = out.take(moving).settled_by(margin, end[moving])
        which, when = all_crossings(rate.take(moving), np.zeros(moving.size), until, h_min)
    # each phase's largest over its start, stationary points and end
    at = np.zeros(m)
    top = np.maximum(key, key_end)
    if moving.size and which.size:
        rows = moving[which]
        vs = out.value(rows, when)
        ks = np.abs(vs) if s.magnitude else vs
        np.maximum.at(top, rows, ks)
    # the first candidate (start, stationary points in time, end) within PEAK_TIE of top
    near = top - PEAK_TIE * np.abs(top)
    open_ = key < near                               # the start is not within the tie
    if moving.size and which.size:
        order = np.lexsort((when, rows))
        rows, vs, ks, when = rows[order], vs[order], ks[order], when[order]
        tops = np.flatnonzero(ks >= near[rows])
        _, first = np.unique(rows[tops], return_index=True)
        pick = tops[first]
        r = rows[pick]
        win = open_[r]
        v[r[win]], key[r[win]], at[r[win]] = vs[pick[win]], ks[pick[win]], when[pick[win]]
        open_[r[win]] = False
    later = open_ & (key_end >= near)
    v, key, at = np.where(later, v_end, v), np.where(later, key_end, key), np.where(later, end, at)
    up = key > _beyond(best_key[idx])
    gi = idx[up]
    s.best[gi], s.best_t[gi] = v[up], s.t[gi] + at[up]
    best_key[gi] = key[up]


def _advance(system: BatchedSystem, grp: _Group, s: _State, names: list[str]) -> None:
    """The state at the phase's end, the clock, the schedule, the switch."""
    idx, event = grp.idx, grp.event
    x_end = grp.form.state(grp.end, grp.vectors)
    s.t[idx] += grp.end
    s.count[idx] += 1
    fin = event == END
    s.done[idx[fin]] = True
    s.x[idx[fin]] = x_end[fin]
    s.ptr[idx[(event >= 0) & (event < len(names))]] += 1
    for e in np.unique(event[~fin]):
        sel = np.flatnonzero(event == e)
        name = names[e] if e < len(names) else grp.guards[e - len(names)].name
        new_mode, new_x = system.switch(grp.mode, name, idx[sel], s.t[idx[sel]], x_end[sel])
        s.mode[idx[sel]] = new_mode
        s.x[idx[sel]] = new_x
