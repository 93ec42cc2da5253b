"""The largest value of an output over one phase, by certified bounds.

On a phase the output is g(τ) = Σ a_j β_j(τ) + k (:class:`ClosedForm`), its
rate g' likewise (the rate's own amplitudes). Only the largest |g| (or g)
and the first instant within :data:`~crane_sym.mechanics.phase_table.PEAK_TIE`
of it matter, not every extremum: a grid no coarser than a quarter of the
fastest period (and the fastest e-folding time) gives a first best; on each
interval [a, b], |g| ≤ max(|g(a)|, |g(b)|) + M₂ (b − a)²/8 with M₂ a bound of
|g''| there (the rate's certified derivative bound), so an interval whose bound
can neither raise the best past the tie nor reach the tie before its ends
do is dropped, as is one that cannot add a tenth of the tie to what its ends
know; the others are halved, and solved at the root of g' where g' changes
sign over them and they may raise the best, until none is left. The tie is
relative to the best, or to a millionth of g's terms where the best is
smaller (an output held at zero). The cost
follows the number of crests near the top, not every extremum of a
many-mode signal (a chain of 20 bodies).
"""
from __future__ import annotations

import numpy as np

from crane_sym.mechanics.closed_forms import ClosedForm

__all__ = ["peak_candidates"]

#: Most intervals of the first grid.
GRID = 20_000
#: An interval this much shorter than the phase is not halved again.
SHORTEST = 1e-13
#: Most intervals open at once (a search that needs more is refused by name).
MOST = 1_000_000


def _values(form: ClosedForm, amps: np.ndarray, k: float, tau: np.ndarray) -> np.ndarray:
    return amps @ form.basis(tau) + k


def _curvature(form: ClosedForm, rate: np.ndarray, a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """A bound of |g''| = |d/dτ (rate)| on each [a, b] (0 ≤ a ≤ b), as
    :meth:`ClosedForm.derivative_bound` of the rate, interval by interval."""
    p, s, w = form.powers[:, None], form.sigmas[:, None], form.omegas[:, None]
    grow = np.exp(np.maximum(s * a, s * b))
    poly = np.where(p > 0, p * b ** np.maximum(p - 1, 0), 0.0)
    return np.abs(rate) @ (grow * (poly + (np.abs(s) + w) * b ** p))


def peak_candidates(form: ClosedForm, amps: np.ndarray, k: float, rate: np.ndarray,
                    rate_k: float, length: float, magnitude: bool,
                    tie: float) -> tuple[np.ndarray, np.ndarray]:
    """(τ, g(τ)) of the instants where g may come within ``tie`` of its largest
    over [0, ``length``]: the phase's ends and the crests (roots of g') of every
    interval that could come within the tie (in time order).

    Parameters
    ----------
    form : ClosedForm
        The phase's closed form.
    amps, k : ndarray, float
        g = Σ a_j β_j + k.
    rate, rate_k : ndarray, float
        g' = Σ r_j β_j + r_k.
    length : float
        The phase's length.
    magnitude : bool
        The largest |g| instead of g.
    tie : float
        The relative tie of peaks.
    """
    key = np.abs if magnitude else (lambda v: v)
    if not length > 0:                                 # an instant: its one value
        return np.zeros(1), _values(form, amps, k, np.zeros(1))
    span = [length]
    if np.any(form.omegas > 0):
        span.append(0.25 * 2 * np.pi / form.omegas.max())
    if np.any(form.sigmas != 0):
        span.append(1.0 / np.abs(form.sigmas).max())
    count = int(min(GRID, max(2, np.ceil(length / min(span)))))
    grid = np.linspace(0.0, length, count + 1)
    values = _values(form, amps, k, grid)
    best = float(key(values).max())
    times, found = [np.array([0.0, length])], [values[[0, -1]]]
    a, b, va, vb = grid[:-1], grid[1:], values[:-1], values[1:]
    floor = SHORTEST * max(length, 1.0)
    # g's own size: a tie below it is none (an output held at 0)
    size = 1e-6 * (float(np.abs(amps).sum()) + abs(k))
    while a.size:
        if a.size > MOST:
            raise RuntimeError(f"the peak search of a phase of {length:g} s holds {a.size}"
                               f" intervals (at most {MOST})")
        scale = max(abs(best), size)
        M2 = _curvature(form, rate, a, b)
        known = np.maximum(key(va), key(vb))
        slack = M2 * (b - a) ** 2 / 8                  # what the interval may add
        live = ((known + slack >= best - tie * scale) & (slack > 0.1 * tie * scale)
                & (b - a > floor))
        a, b, va, vb = a[live], b[live], va[live], vb[live]
        if not a.size:
            break
        ra = _values(form, rate, rate_k, a)
        rb = _values(form, rate, rate_k, b)
        for ends, rates, vals in ((a, ra, va), (b, rb, vb)):    # g' = 0 on an end
            flat = rates == 0
            times.append(ends[flat]), found.append(vals[flat])
        split = 0.5 * (a + b)              # halved, or cut at its crest (g' = 0)
        turns = np.flatnonzero(np.sign(ra) * np.sign(rb) < 0)
        def slope(x: float) -> float:
            return float(_values(form, rate, rate_k, np.array([x]))[0])
        if turns.size:
            from scipy.optimize import brentq  # on use: SciPy's import costs ~0.5 s
        for i in turns:
            sa, sb = slope(a[i]), slope(b[i])
            if sa * sb < 0:                        # the same signs evaluated alone
                split[i] = brentq(slope, a[i], b[i], xtol=1e-15,
                                  rtol=4 * np.finfo(float).eps)
            else:   # g' is rounding at an end (a crest found before, a grid point):
                # its sign differs evaluated alone. That end is the crest, not the
                # midpoint (a point within the tie of the top, taken as its time)
                split[i] = a[i] if abs(sa) <= abs(sb) else b[i]
        inside = (split[turns] - a[turns] > floor) & (b[turns] - split[turns] > floor)
        # a crest on an end of its interval (a grid point, a half) is that end
        edge = turns[~inside]
        at_a = split[edge] - a[edge] <= floor
        times.append(np.where(at_a, a[edge], b[edge]))
        found.append(np.where(at_a, va[edge], vb[edge]))
        split[edge] = 0.5 * (a + b)[edge]
        turns = turns[inside]
        vm = _values(form, amps, k, split)
        times.append(split[turns]), found.append(vm[turns])
        best = max(best, float(key(vm).max()))
        a, b = np.concatenate([a, split]), np.concatenate([split, b])
        va, vb = np.concatenate([va, vm]), np.concatenate([vm, vb])
    times, found = np.concatenate(times), np.concatenate(found)
    order = np.argsort(times, kind="stable")
    return times[order], found[order]
