"""Outputs of a run of a piecewise-linear system: values, the largest value,
and the table of closed forms, one per phase, that a scene's module carries.

:func:`crane_sym.mechanics.piecewise_linear.simulate` finds the phases of one run (a
scene's data); an output g = w·x + k of the state is then, on phase i,

.. math::

    g(t) = c_i + \\sum_j \\tau^{k_j} e^{\\sigma_j \\tau}
           (a_j \\cos \\omega_j \\tau + b_j \\sin \\omega_j \\tau),
    \\qquad \\tau = t - t_i,

with the terms of the phase's closed form merged by (k, σ, ω). The table is
what a scene's generated module carries (``crane_sym.codegen.tabulated`` prints it):
the response as arithmetic only, no event search at run time. The same kernel
(``kernels.arithmetic._phase_sum``) evaluates it here and in the generated code.
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Callable, Hashable, Sequence

import numpy as np

from crane_sym.kernels.arithmetic import _phase_sum
from crane_sym.mechanics.phase_peaks import peak_candidates
from crane_sym.mechanics.event_search import exact_zeros
from crane_sym.mechanics.piecewise_linear import (HybridSystem, PiecewiseResult, Segment, by_phase,
                                                  simulate)

__all__ = ["PEAK_TIE", "HybridRun", "PhaseTable", "first_of_largest", "largest", "phase_candidates",
           "tabulate", "values"]

#: An affine output of the state per mode: mode -> (w, k), the output w·x + k.
Affine = Callable[[Hashable], tuple[np.ndarray, float]]


@dataclass(frozen=True)
class PhaseTable:
    """Phase starts and the run's end (``edges``), each phase's terms
    (``first[i]:first[i + 1]``) and constant, the event that ended each phase."""

    edges: np.ndarray
    first: np.ndarray
    powers: np.ndarray
    sigmas: np.ndarray
    omegas: np.ndarray
    cos_amps: np.ndarray
    sin_amps: np.ndarray
    consts: np.ndarray
    events: tuple[str, ...]

    def arrays(self) -> tuple[np.ndarray, ...]:
        """The arrays in the order ``kernels.arithmetic._phase_sum`` takes them."""
        return (self.edges, self.first, self.powers, self.sigmas, self.omegas,
                self.cos_amps, self.sin_amps, self.consts)

    def __call__(self, t: np.ndarray | float) -> np.ndarray:
        """The output at times ``t`` (inside [edges[0], edges[-1]])."""
        return _phase_sum(np.asarray(t, dtype=float), *self.arrays())


def tabulate(result: PiecewiseResult,
             output: Callable[[Hashable], tuple[np.ndarray, float]],
             scale: float = 1.0) -> PhaseTable:
    """The table of g = (w·x + k)/``scale`` over the phases of ``result``;
    ``output(mode)`` gives (w, k) of each phase's mode (a contact changes them).
    Phases of zero length (an event at the instant another ends) are left out."""
    segments = [s for s in result.segments if s.t1 > s.t0] or result.segments[-1:]
    edges = [result.segments[0].t0] + [s.t1 for s in segments]
    first, consts, rows = [0], [], []
    for seg in segments:
        w, k = output(seg.mode)
        form = seg.form
        amps, _ = form.scalar_terms(np.asarray(w, float) / scale, 0.0, seg.x0)
        merged: dict[tuple[float, float, float], list[float]] = {}
        for a, p, s, o, sine in zip(amps, form.powers, form.sigmas, form.omegas, form.sine):
            merged.setdefault((p, s, o), [0.0, 0.0])[int(bool(sine))] += a
        size = sum(abs(a) for pair in merged.values() for a in pair)
        const = k / scale
        for (p, s, o), (a, b) in sorted(merged.items()):
            if p == 0 and s == 0 and o == 0:
                const += a               # the phase's constant part
            elif abs(a) + abs(b) > 1e-15 * size:
                rows.append((p, s, o, a, b))
        consts.append(const)
        first.append(len(rows))
    cols = np.array(rows, dtype=float).reshape(-1, 5).T
    return PhaseTable(np.array(edges), np.array(first, dtype=np.intp), *cols,
                      np.array(consts), tuple(s.event for s in segments))


@dataclass(frozen=True)
class HybridRun:
    """One run of a piecewise-linear system and the output a scene wants of it:
    what a ``derivation.TabulatedOutput`` returns for the scene's data, what the
    bench hands to SciPy's integrators as the alternative."""

    system: HybridSystem
    mode: Hashable
    x0: np.ndarray
    t_end: float
    schedule: Sequence[tuple[float, str]]
    output: Callable[[Hashable], tuple[np.ndarray, float]]
    scale: float = 1.0
    exact: bool | None = None

    def solve(self) -> PiecewiseResult:
        """The phases in closed form (:func:`crane_sym.mechanics.piecewise_linear.simulate`)."""
        return simulate(self.system, self.mode, self.x0, self.t_end, self.schedule,
                        exact=self.exact)

    def table(self, result: PiecewiseResult | None = None) -> PhaseTable:
        """The output's table over the phases of ``result`` (solved if not given)."""
        return tabulate(self.solve() if result is None else result, self.output, self.scale)


def values(result: PiecewiseResult, times: np.ndarray, affine: Affine) -> np.ndarray:
    """w·x + k at ``times`` (inside the run), (w, k) = ``affine(mode)`` of each phase.

    Parameters
    ----------
    result : PiecewiseResult
        The run.
    times : ndarray
        Times inside the run.
    affine : callable
        Mode -> (w, k) of the output w·x + k.
    """
    times = np.asarray(times, dtype=float)
    out = np.empty(times.shape)
    for i, mask in by_phase([s.t0 for s in result.segments], times):
        seg = result.segments[i]
        w, k = affine(seg.mode)
        out[mask] = seg.state(times[mask]) @ np.asarray(w, float) + k
    return out


#: A peak's time is the first instant the output comes within this fraction of
#: the peak (equal crests of an undamped ring differ by rounding: the first is
#: where an engineer reads "the peak occurs").
PEAK_TIE = 1e-9


def first_of_largest(times: Sequence[float], found: Sequence[float],
                     magnitude: bool = False) -> tuple[float, float]:
    """(time, value) of the earliest candidate within :data:`PEAK_TIE` of the
    largest value (of |value| with ``magnitude``; the value keeps its sign)."""
    times, found = np.asarray(times, float), np.asarray(found, float)
    if not times.size:
        return 0.0, float("nan")
    order = np.argsort(times, kind="stable")
    times, found = times[order], found[order]
    keys = np.abs(found) if magnitude else found
    top = keys.max()
    i = int(np.flatnonzero(keys >= top - PEAK_TIE * abs(top))[0])
    return float(times[i]), float(found[i])


def largest(result: PiecewiseResult, system: HybridSystem, affine: Affine,
            magnitude: bool = False) -> tuple[float, float]:
    """(time, value) of the largest w·x + k over the run (of |w·x + k| with
    ``magnitude``; the value keeps its sign): each phase's ends and stationary
    points are the only candidates; the time is the first at which the output
    comes within :data:`PEAK_TIE` of it (:func:`first_of_largest`).

    Parameters
    ----------
    result : PiecewiseResult
        The run.
    system : HybridSystem
        The system it is a run of.
    affine : callable
        Mode -> (w, k) of the output w·x + k.
    magnitude : bool, optional
        The largest absolute value instead.
    """
    times, found = [], []
    for seg in result.segments:
        when, value = phase_candidates(seg, system, affine, magnitude)
        times.append(when), found.append(value)
    return first_of_largest(np.concatenate(times), np.concatenate(found), magnitude)


def phase_candidates(segment: Segment, system: HybridSystem, affine: Affine,
                     magnitude: bool) -> tuple[np.ndarray, np.ndarray]:
    """(t, value) of the instants of one phase where its output w·x + k may come
    within :data:`PEAK_TIE` of its largest (:func:`crane_sym.mechanics.phase_peaks.peak_candidates`:
    its ends, its best grid points, its stationary points near the top; the
    rate's terms that are rounding noise of an exact zero dropped)."""
    w, k = affine(segment.mode)
    w = np.asarray(w, float)
    ends = np.array([segment.t0, segment.t1])
    if not w.any():
        return ends, np.full(2, float(k))
    A, b = system.matrices(segment.mode)
    amps, k0 = segment.form.scalar_terms(w, float(k), segment.x0)
    rate, rate_k = exact_zeros(segment.form, w @ A, float(w @ b), segment.x0)
    tau, value = peak_candidates(segment.form, amps, k0, rate, rate_k,
                                 segment.t1 - segment.t0, magnitude, PEAK_TIE)
    return segment.t0 + tau, value
