"""The certified search for a phase's events: where an affine function of the
state, g(t) = w·x(t) + k along a phase's closed form, first changes sign.

Events without a skipped crossing
---------------------------------
An event is an affine function g(x) = w·x + k of the state (a contact angle,
a speed, a torque against a brake's limit). Along a phase g(t) = Σ_j a_j β_j(t)
with the real terms β_j of :class:`ClosedForm`, so |g'| and |g''| on [t, t + H] are bounded by
Σ |a_j| max|β_j'| and Σ |a_j| max|β_j''| (:meth:`ClosedForm.derivative_bound`,
:meth:`ClosedForm.second_derivative_bound`). From t, g cannot reach 0 before
t + |g(t)|/L, nor before the root h* of |g(t)| − |g'(t)| h − M₂h²/2 (a
Newton-like step, since g'(t) is exact): :func:`first_crossing` steps by the
larger certified distance, and by ``h_min`` where it is smaller, checking the sign at each
step; a sign change is refined by ``scipy.optimize.brentq``. No crossing is
skipped except a pair of crossings closer together than ``h_min`` (a touch);
the first crossing is found to ``xtol``.

:func:`signal` gives g and g' in double, :func:`exact_zeros` drops the terms
a guard weighs to zero in exact arithmetic, :func:`sign_change` brackets the
first crossing and :func:`first_crossing` refines it. The double run
(:mod:`crane_sym.mechanics.piecewise_linear`) and the exact one
(:mod:`crane_sym.mechanics.exact_phases`) search with them;
:mod:`crane_sym.mechanics.batched_events` is the same search on arrays.
"""
from __future__ import annotations

import math
from typing import Callable

import numpy as np

from crane_sym.mechanics.closed_forms import ClosedForm

__all__ = ["exact_zeros", "first_crossing", "sign_change", "signal"]


def first_crossing(form: ClosedForm, x0: np.ndarray, weights: np.ndarray,
                   constant: float, t_end: float, *, direction: int = 0,
                   h_min: float = 1e-10, xtol: float = 1e-14,
                   window: float | None = None, clean: bool = False) -> float | None:
    """The first t in (0, t_end] where g = w·x(t) + k changes sign, or None.

    Steps by the certified distance |g|/L (L bounds |g'| over the current
    window, at most ``window`` long), never below ``h_min``; see the module
    docstring for the guarantee. ``direction`` (+1: g rises through 0, −1:
    falls, 0: either) says on which side a start on the surface lies: a phase
    that begins where the previous event left g = 0 up to rounding takes g on
    the side opposite to ``direction``, so the surface it starts on does not
    fire again at once. ``clean``: g's terms that are rounding noise of an exact
    zero dropped first (:func:`exact_zeros`), so a rate that is zero in exact
    arithmetic (a load held constant, a rigid mode's share of a relative
    load) has no crossings of noise.
    """
    amps, k = (exact_zeros(form, weights, constant, x0) if clean
               else form.scalar_terms(weights, constant, x0))
    if not np.any(amps) and k == 0.0:
        return None             # g ≡ 0: the state rides the surface, never crosses
    g, slope = signal(form, amps, k)
    size = float(np.sum(np.abs(amps)) + abs(k))
    band = max(form.derivative_bound(amps, 0.0, min(h_min, t_end)) * h_min, 1e-12 * size)
    on_surface = abs(g(0.0)) <= band
    bracket = sign_change(form, amps, g, slope, t_end, direction, on_surface, h_min, window,
                          band=band)
    if bracket is None:
        return None
    lo, hi, level = bracket
    if lo == hi:
        return hi
    if level and np.sign(g(0.0)) * np.sign(g(hi)) < 0:
        # g itself went from its side across the surface beyond the band: a
        # real crossing (a gap of 1e-9 closing from rest, backlash -> 0), at
        # its own root, not where g passes the band
        lo, level = 0.0, 0.0
    from scipy.optimize import brentq      # on use: SciPy's import costs ~0.5 s
    return brentq(lambda t: g(t) + level, lo, hi, xtol=xtol, rtol=4 * np.finfo(float).eps)


def exact_zeros(form: ClosedForm, weights: np.ndarray, constant: float,
                x0: np.ndarray) -> tuple[np.ndarray, float]:
    """The amplitudes a_j of g = w·x + k (:meth:`ClosedForm.scalar_terms`) with each
    a_j that is within 64 ulps of the sum it comes from (Σ_i |w_i (C_j z0)_i|) set
    to 0, and the constant merged into the constant term, likewise."""
    w = np.asarray(weights, float)
    z0 = np.append(np.asarray(x0, dtype=float), 1.0)
    parts = (form.coefficients @ z0)[:, : form.n] * w
    amps = parts.sum(axis=1)
    noise = 64 * np.finfo(float).eps * np.abs(parts).sum(axis=1)
    const = np.flatnonzero((form.powers == 0) & (form.sigmas == 0) & (form.omegas == 0))
    k = float(constant)
    if const.size:
        j = const[0]
        amps[j] += k
        noise[j] += 64 * np.finfo(float).eps * abs(k)
        k = 0.0
    amps[np.abs(amps) <= noise] = 0.0
    return amps, k


def signal(form: ClosedForm, amps: np.ndarray,
           k: float) -> tuple[Callable[[float], float], Callable[[float], float]]:
    """g(t) = Σ a_j β_j(t) + k and g'(t) in plain floats: a phase has a handful
    of terms, and these run thousands of times per run, where NumPy's per-call
    cost dominates."""
    terms = [(float(a), int(pp), float(ss), float(ww), bool(sn))
             for a, pp, ss, ww, sn in zip(amps, form.powers, form.sigmas, form.omegas,
                                          form.sine) if a != 0.0]

    def g(t: float) -> float:
        total = k
        for a, pp, ss, ww, sn in terms:
            v = a * (math.sin(ww * t) if sn else math.cos(ww * t))
            if ss:
                v *= math.exp(ss * t)
            if pp:
                v *= t ** pp
            total += v
        return float(total)

    def slope(t: float) -> float:
        total = 0.0
        for a, pp, ss, ww, sn in terms:
            c, sw = math.cos(ww * t), math.sin(ww * t)
            wave, dwave = (sw, ww * c) if sn else (c, -ww * sw)
            tp = t ** pp
            dtp = pp * t ** (pp - 1) if pp else 0.0
            total += a * math.exp(ss * t) * ((dtp + ss * tp) * wave + tp * dwave)
        return total
    return g, slope


def sign_change(form: ClosedForm, amps: np.ndarray, g: Callable[[float], float],
                slope: Callable[[float], float], t_end: float, direction: int,
                on_surface: bool, h_min: float, window: float | None = None,
                band: float = 0.0) -> tuple[float, float, float] | None:
    """The first step (lo, hi, level) of the certified search over which
    ``g`` + level leaves its starting side, (hi, hi, level) where it is on the
    other side or 0 at hi already, or None when it does not by ``t_end``.
    ``g`` gives the value whose sign is trusted (the double, or a decided value
    in :mod:`crane_sym.mechanics.exact_phases`); ``slope`` and the bounds of ``form``
    only size the steps.

    ``band`` (with ``on_surface`` and a ``direction``): g's rounding bound at
    the start. The search then watches g − direction·band until g leaves the
    band on its side (level 0 from there), as
    :mod:`crane_sym.mechanics.batched_events` does: a guard that starts on its
    surface with zero slope (a speed from rest at zero acceleration) does not
    fire on the rounding noise of g about 0. Where g's slope at the start is
    beyond its own rounding bound, its sign decides at once (away from the
    surface, or across it: two gaps that close at one instant): no band."""
    window = window or _window(form, max(t_end, h_min))
    side = -direction if (on_surface and direction) else 0
    level = side * band
    if level and abs(slope(0.0)) > 1e-12 * form.derivative_bound(amps, 0.0, min(h_min, t_end)):
        level = 0.0
    t, gt = 0.0, g(0.0) + level
    side = side or np.sign(gt)
    if side == 0:                                      # on the surface, either way
        t = min(h_min, t_end)
        gt = g(t)
        side = np.sign(gt)

    def watched(t: float) -> float:
        nonlocal level
        value = g(t)
        if level and side * value > band:              # out of the band on its side
            level = 0.0
        return value + level
    while t < t_end:
        w_end = min(t + window, t_end)
        L = form.derivative_bound(amps, t, w_end)
        M2 = form.second_derivative_bound(amps, t, w_end)
        while t < w_end:
            if np.sign(gt) != side:
                step = 0.0
            elif L <= 0:                               # g constant on the window: skip it
                step = w_end - t
            else:   # |g(t+h)| >= |g| - |g'(t)| h - M2 h²/2 > 0 below the larger root
                d1 = abs(slope(t))
                step = max(abs(gt) / L, 2 * abs(gt) / (d1 + np.sqrt(d1 * d1 + 2 * M2 * abs(gt))))
            nxt = min(t + max(step, h_min), w_end)
            gn = watched(nxt)
            if gn == 0.0 or np.sign(gn) != side:
                if gn == 0.0 or np.sign(gt) != side:
                    return nxt, nxt, level
                return t, nxt, level
            t, gt = nxt, gn
    return None


def _window(form: ClosedForm, scale: float) -> float:
    """A window length over which the derivative bound stays tight: a quarter of
    the shortest period, and no longer than the e-folding time of the fastest
    growing or decaying term (a bound taken at a window's start is otherwise
    stale once the terms it holds have decayed, and the steps |g|/L shrink
    with g)."""
    limits = [scale]
    if np.any(form.omegas > 0):
        limits.append(0.25 * 2 * np.pi / form.omegas.max())
    if np.any(form.sigmas != 0):
        limits.append(1.0 / np.abs(form.sigmas).max())
    return min(limits)
