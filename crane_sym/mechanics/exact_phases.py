"""A piecewise-linear run solved in mpmath, so that what a module prints of it
is the same on every machine.

The double-precision run (:func:`crane_sym.mechanics.piecewise_linear.simulate`) takes
its last bits from the machine: libm's sines and exponentials, NumPy's SIMD
loops, LAPACK's inverse. Thirty phases carry those bits from event to event,
and a table printed to 13 digits from it changes in its last digits from one
machine to another; where a guard grazes its surface (a speed that starts
from rest with zero acceleration) rounding noise even decides whether an
event fires. :func:`simulate_exact` runs the same model at :data:`DPS` digits:

- each phase's exp(Mt) in mpmath (:class:`ExactForm`,
  :mod:`crane_sym.mechanics.exact_forms`);
- each event by the same certified search, stepping in double, but every sign
  it acts on is the double's only where the double is farther from 0 than its
  rounding bound, and mpmath's elsewhere; the step where the sign changes is
  refined in mpmath (:func:`crossing`, :func:`illinois`);
- the state carried in mpmath, and the model's own switch rule applied to it.

The step sizes may differ in their last bits between machines; the signs, the
event times and the states do not (short of two crossings closer together
than ``h_min``, which the search does not resolve on any machine). Numbers
rounded to double once, from 40 digits, are the same bytes everywhere
(:func:`exact_table`).
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Callable, Hashable, Sequence

import mpmath
import numpy as np

from crane_sym.mechanics.closed_forms import ClosedForm, JordanFormError
from crane_sym.mechanics.exact_forms import DPS, ExactForm, exact_form
from crane_sym.mechanics.phase_table import HybridRun, PhaseTable
from crane_sym.mechanics.event_search import sign_change, signal
from crane_sym.mechanics.piecewise_linear import MAX_PHASES, Guard, HybridSystem, PhaseLimitError

__all__ = ["DPS", "ExactForm", "ExactRun", "ExactSegment", "crossing", "exact_form",
           "exact_table", "illinois", "simulate_exact", "tabulate_exact"]

EPS = float(np.finfo(float).eps)


def _noise(form: ClosedForm, amps: np.ndarray, k: float, t: float) -> float:
    """A bound of the rounding error of :func:`crane_sym.mechanics.event_search.signal`'s
    g at t, whatever libm: each term's size times its arguments' rounding, the
    amplitudes' own rounding and the sum's."""
    total = abs(k)
    for a, p, s, w in zip(amps, form.powers, form.sigmas, form.omegas):
        if a:
            total += abs(a) * t ** p * math.exp(s * t) * (2 + p + (w + abs(s)) * t)
    return (16 + 2 * len(amps)) * EPS * total


def illinois(g: Callable[[mpmath.mpf], mpmath.mpf], lo: mpmath.mpf,
             hi: mpmath.mpf) -> mpmath.mpf:
    """The root of ``g`` in [lo, hi] (g changes sign there) to the working
    precision: regula falsi with the Illinois weighting, bisection as a guard."""
    g_lo, g_hi = g(lo), g(hi)
    tol = mpmath.mpf(2) ** (8 - mpmath.mp.prec) * (1 + abs(hi))
    side = 0
    while hi - lo > tol and g_hi != 0 and g_lo != 0:
        mid = hi - g_hi * (hi - lo) / (g_hi - g_lo)
        if not lo < mid < hi:
            mid = (lo + hi) / 2
        g_mid = g(mid)
        if g_mid == 0:
            return mid
        if mpmath.sign(g_mid) == mpmath.sign(g_hi):
            hi, g_hi = mid, g_mid
            g_lo = g_lo / 2 if side == 1 else g_lo
            side = 1
        else:
            lo, g_lo = mid, g_mid
            g_hi = g_hi / 2 if side == -1 else g_hi
            side = -1
    if g_lo == 0:
        return lo
    return hi if abs(g_hi) <= abs(g_lo) else lo


def crossing(form: ExactForm, z0: Sequence[mpmath.mpf], guard: Guard,
             t_end: mpmath.mpf, h_min: float) -> mpmath.mpf | None:
    """The first τ in (0, t_end] where the guard changes sign along the phase,
    or None: the certified search of :mod:`crane_sym.mechanics.piecewise_linear` steps in
    double, each sign it acts on is the double's where the double is farther
    from 0 than its rounding bound and mpmath's elsewhere, and the step where
    the sign changes is refined in mpmath (:func:`illinois`)."""
    weights = [mpmath.mpf(w) for w in guard.weights]
    amps_mp = form.amplitudes(z0, weights)
    k_mp = mpmath.mpf(guard.constant)
    size = mpmath.fsum(abs(a) for a in amps_mp) + abs(k_mp)
    parts = mpmath.fsum(abs(w * x) for v in form.vectors(z0) for w, x in zip(weights, v))
    if size <= mpmath.mpf(10) ** (10 - mpmath.mp.dps) * parts:
        return None            # g ≡ 0 to the working digits: the state rides the surface
    amps, k = np.array([float(a) for a in amps_mp]), float(k_mp)
    double = form.double
    g_double, slope = signal(double, amps, k)

    def g_mp(tau: mpmath.mpf) -> mpmath.mpf:
        return mpmath.fdot(amps_mp, form.basis(tau)) + k_mp

    def decided(t: float) -> float:
        value = g_double(t)
        return value if abs(value) > _noise(double, amps, k, t) else float(g_mp(mpmath.mpf(t)))

    on_surface = abs(g_mp(mpmath.mpf(0))) <= mpmath.mpf(10) ** (10 - mpmath.mp.dps) * size
    bracket = sign_change(double, amps, decided, slope, float(t_end), guard.direction,
                          on_surface, h_min)
    if bracket is None:
        return None
    lo, hi, _ = bracket                 # no band: the signs are decided, level 0
    return mpmath.mpf(hi) if lo == hi else illinois(g_mp, mpmath.mpf(lo), mpmath.mpf(hi))


@dataclass(frozen=True)
class ExactSegment:
    """One phase in mpmath: mode, start and end, the state at its start, its form."""

    mode: Hashable
    t0: mpmath.mpf
    t1: mpmath.mpf
    z0: tuple[mpmath.mpf, ...]
    form: ExactForm
    event: str


@dataclass(frozen=True)
class ExactRun:
    """The phases of a run at ``dps`` digits."""

    segments: tuple[ExactSegment, ...]
    dps: int


def simulate_exact(system: HybridSystem, mode: Hashable, x0: Sequence[float], t_end: float,
                   schedule: Sequence[tuple[float, str]] = (), *, h_min: float = 1e-10,
                   max_events: int = MAX_PHASES, dps: int = DPS) -> ExactRun:
    """:func:`crane_sym.mechanics.piecewise_linear.simulate` with every phase, event time,
    state and switching decision in mpmath at ``dps`` digits (the search for
    the events steps in double, see :func:`crossing`)."""
    with mpmath.workdps(dps):
        z = tuple(mpmath.mpf(float(v)) for v in x0)
        pending = sorted((float(s), name) for s, name in schedule if 0 <= s < t_end)
        t, segments, event = mpmath.mpf(0), [], "start"
        for _ in range(max_events):
            try:
                form = exact_form(*system.matrices(mode))
            except JordanFormError as exc:
                raise exc.in_phase(len(segments) + 1, t) from None
            horizon = mpmath.mpf(pending[0][0] if pending else t_end) - t
            end, event = horizon, (pending[0][1] if pending else "end")
            for guard in system.guards(mode):
                hit = crossing(form, z, guard, end, h_min)
                if hit is not None and hit < end:
                    end, event = hit, guard.name
            segments.append(ExactSegment(mode, t, t + end, z, form, event))
            t += end
            if event == "end":
                return ExactRun(tuple(segments), dps)
            if pending and event == pending[0][1] and end == horizon:
                pending.pop(0)
            x = np.empty(form.n, dtype=object)
            x[:] = form.state(end, z)
            mode, x = system.switch(mode, event, t, x)
            z = tuple(mpmath.mpf(v) for v in x)
    raise PhaseLimitError(max_events, float(t), t_end, event)


def tabulate_exact(run: ExactRun, output: Callable[[Hashable], tuple[np.ndarray, float]],
                   scale: float = 1.0) -> PhaseTable:
    """The table of (w·x + k)/``scale`` over the phases of ``run``, as
    :func:`crane_sym.mechanics.phase_table.tabulate` builds it, each number rounded once
    to double from the replay's digits."""
    with mpmath.workdps(run.dps):
        segments = [s for s in run.segments if s.t1 > s.t0] or list(run.segments[-1:])
        edges = [run.segments[0].t0] + [s.t1 for s in segments]
        first, consts, rows = [0], [], []
        for seg in segments:
            w, k = output(seg.mode)
            weights = [mpmath.mpf(float(v)) / mpmath.mpf(scale) for v in np.ravel(w)]
            form = seg.form
            merged: dict[tuple, list] = {}
            for a, p, s, o, sine in zip(form.amplitudes(seg.z0, weights), form.powers,
                                        form.sigmas, form.omegas, form.sine):
                merged.setdefault((p, s, o), [mpmath.mpf(0), mpmath.mpf(0)])[int(sine)] += a
            size = mpmath.fsum(abs(a) for pair in merged.values() for a in pair)
            const = mpmath.mpf(float(k)) / mpmath.mpf(scale)
            for (p, s, o), (a, b) in sorted(merged.items()):
                if p == 0 and s == 0 and o == 0:
                    const += a                # the phase's constant part
                elif abs(a) + abs(b) > mpmath.mpf("1e-15") * size:
                    rows.append((p, s, o, a, b))
            consts.append(const)
            first.append(len(rows))
        cols = np.array([[float(v) for v in row] for row in rows], dtype=float).reshape(-1, 5).T
        return PhaseTable(np.array([float(e) for e in edges]), np.array(first, dtype=np.intp),
                          *cols, np.array([float(c) for c in consts]),
                          tuple(s.event for s in segments))


def exact_table(run: HybridRun, dps: int = DPS) -> PhaseTable:
    """The table a scene's module prints: ``run`` solved in mpmath
    (:func:`simulate_exact`), each number rounded once to double.

    Parameters
    ----------
    run : HybridRun
        The system, its start and the output a scene wants.
    dps : int, optional
        Decimal digits of the mpmath solution.
    """
    exact = simulate_exact(run.system, run.mode, run.x0, run.t_end, run.schedule, dps=dps)
    return tabulate_exact(exact, run.output, run.scale)
