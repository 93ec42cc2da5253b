"""Events of many signals at once: the certified no-skip search and a
bracketed refinement, both on arrays.

:func:`first_crossings` is :func:`crane_sym.mechanics.event_search.sign_change`
for m signals together (:class:`crane_sym.mechanics.batched_signals.Signals`),
with the same guarantee: from t, g cannot reach 0 before t + |g(t)|/L (L
bounds |g'| over the current window) nor before the root of
|g(t)| − |g'(t)| h − M₂h²/2 (of |g(t)| + |g'(t)| h − M₂h²/2 where g moves
away from 0), so each row steps by the larger certified distance, by
``h_min`` where it is smaller, checking the sign at each step; where g heads
for 0 and stays monotone over twice Newton's distance, that step is
certified too (at most one zero on it) and brackets a simple root at once.
A quadratic signal (a free side's speed or angle) is not stepped: its root
comes from its monotone pieces. Every row keeps its own clock, window and
bounds; a row leaves the loop once it has bracketed a sign change or
reached its end (or passed an earlier crossing of its design), so the loop
runs as many rounds as the slowest row needs and each round costs as much as
the rows still searching. :func:`refine` narrows every bracket together by
Newton's method kept in the bracket, from the values the search knows, to
``xtol`` (as ``brentq`` does for one design).
"""
from __future__ import annotations

from typing import Callable

import numpy as np

from crane_sym.mechanics.batched_signals import ALL, Signals

__all__ = ["all_crossings", "first_crossings", "refine"]


def first_crossings(sig: Signals, start: np.ndarray, t_end: np.ndarray, direction: np.ndarray,
                    h_min: float = 1e-10, xtol: float = 1e-14,
                    owner: np.ndarray | None = None) -> np.ndarray:
    """The first t in (start, t_end] where each g changes sign, NaN where none.

    ``direction`` (+1, −1 or 0 per row) says on which side a start on the
    surface lies, as for :func:`crane_sym.mechanics.event_search.first_crossing`.
    ``owner`` (one integer ≥ 0 per row, the rows of one design's guards
    sharing one; an array as long as the largest is made) asks for
    the earliest crossing of each owner only: a row stops searching, NaN, once
    it is past a bracket another row of its owner has found (its crossing,
    if any, comes later).
    """
    m = start.shape[0]
    out = np.full(m, np.nan)
    span = t_end - start
    if np.all(start == 0):
        slope, size, spread = sig.scales(np.minimum(h_min, span), t_end)
        band = np.maximum(slope * h_min, 1e-12 * size)
        # a signal whose constant outweighs everything else it holds over the
        # search (and by more than the surface band) keeps its sign: no search
        live = np.abs(sig.poly[:, 0]) - spread <= 2 * band
    else:
        rows = np.arange(m)
        near = sig.bounds(rows, start, start + np.minimum(h_min, span))[0] * h_min
        band = np.maximum(near, 1e-12 * sig.size(rows))
        live = np.ones(m, dtype=bool)
    return _searched(sig, live, start, t_end, direction, band, h_min, xtol, owner, out)


def _searched(sig: Signals, live: np.ndarray, start: np.ndarray, t_end: np.ndarray,
              direction: np.ndarray, band: np.ndarray, h_min: float, xtol: float,
              owner: np.ndarray | None, out: np.ndarray) -> np.ndarray:
    """:func:`first_crossings` of the rows ``live`` (a mask), ``band`` given:
    the quadratics solved from their coefficients, the others stepped (the
    signals they need taken once)."""
    g0, d0 = sig.both(ALL, start)
    on_surface = np.abs(g0) <= band
    # a quadratic off the surface (a free side's speed or angle): its crossing
    # from its monotone pieces, no stepping
    quad = live & sig.quadratic() & ~on_surface
    limit = None
    if quad.any():
        q = np.flatnonzero(quad)
        out[q] = _quadratic_crossings(sig.polynomial(), q, start[q], t_end[q], g0[q], xtol)
        if owner is not None:                   # the others stop past their owner's
            first = np.full(int(owner.max()) + 1, np.inf)
            np.minimum.at(first, owner[q], np.where(np.isnan(out[q]), np.inf, out[q]))
            limit = first[owner]
    rest = np.flatnonzero(live & ~quad)
    if not rest.size:
        return out
    if rest.size < live.size:
        sig, start, t_end, direction = sig.take(rest), start[rest], t_end[rest], direction[rest]
        g0, d0, band, on_surface = g0[rest], d0[rest], band[rest], on_surface[rest]
        owner = None if owner is None else owner[rest]
        limit = None if limit is None else limit[rest]
    # a start on the surface with a side: the search watches g + side·band until g
    # leaves the band, so rounding noise about 0 is not taken for a crossing
    level = np.where(on_surface & (direction != 0), -direction * band, 0.0)
    lo, hi, flo, fhi, level, M2, dlo, dhi = _brackets(sig, start, t_end, direction, on_surface,
                                                     g0, d0,
                                        h_min, level=level, band=band, owner=owner,
                                        limit=limit)
    found = ~np.isnan(lo)
    same = found & (lo == hi)
    out[rest[same]] = hi[same]
    open_ = np.flatnonzero(found & (lo < hi))
    if open_.size:
        out[rest[open_]] = refine(sig, open_, lo[open_], hi[open_], xtol, level[open_],
                                  flo[open_], fhi[open_], curvature=M2[open_],
                                  slopes=(dlo[open_], dhi[open_]))
    return out


def _quadratic_crossings(sig: Signals, rows: np.ndarray, start: np.ndarray, t_end: np.ndarray,
                         g0: np.ndarray, xtol: float) -> np.ndarray:
    """The first sign change in (start, t_end] of each g = c₀ + c₁t + c₂t²
    (``g0`` = g(start) ≠ 0), NaN where none: g is monotone on [start, t_v]
    and [t_v, t_end] (t_v = −c₁/2c₂, its vertex, where inside), so the first
    of these pieces whose end is on the other side (or at 0) holds exactly
    one root, which :func:`refine` narrows from the quadratic formula's."""
    c = np.zeros((rows.size, 3))
    c[:, : sig.poly.shape[1]] = sig.poly[rows, :3]
    c0, c1, c2 = c.T
    with np.errstate(divide="ignore", invalid="ignore"):
        tv = np.where(c2 != 0, -c1 / (2 * c2), np.inf)
    inner = (tv > start) & (tv < t_end)
    mid = np.where(inner, tv, start)
    gv, ge = sig.value(rows, mid), sig.value(rows, t_end)
    side = np.sign(g0)
    first = inner & ((gv == 0) | (np.sign(gv) != side))
    second = ~first & ((ge == 0) | (np.sign(ge) != side))
    lo = np.where(first, start, mid)
    hi = np.where(first, mid, t_end)
    flo = np.where(first, g0, np.where(inner, gv, g0))
    fhi = np.where(first, gv, ge)
    out = np.full(rows.size, np.nan)
    at_hi = (first | second) & (fhi == 0)
    out[at_hi] = hi[at_hi]
    open_ = np.flatnonzero((first | second) & (fhi != 0))
    if open_.size:
        a, b, k = c2[open_], c1[open_], c0[open_]
        with np.errstate(divide="ignore", invalid="ignore"):
            disc = np.sqrt(np.maximum(b * b - 4 * a * k, 0.0))
            q = -0.5 * (b + np.where(b >= 0, disc, -disc))
            r1, r2 = q / a, k / q
            linear = -k / b
        guess = np.where(a == 0, linear, np.where((r1 >= lo[open_]) & (r1 <= hi[open_]), r1, r2))

        def horner(live: np.ndarray, x: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
            # g and g' as Signals.both gives them, from the three coefficients
            a_, b_ = a[live], b[live]
            return (a_ * x + b_) * x + k[live], 2 * a_ * x + b_
        out[open_] = refine(sig, rows[open_], lo[open_], hi[open_], xtol, 0.0, flo[open_],
                            fhi[open_], guess=guess, evaluate=horner, curvature=2 * np.abs(a))
    return out


def all_crossings(sig: Signals, start: np.ndarray, t_end: np.ndarray, h_min: float = 1e-10,
                  xtol: float = 1e-14) -> tuple[np.ndarray, np.ndarray]:
    """Every sign change of each g in (start, t_end], as (row, time) arrays:
    the certified search goes on past each bracket on the other side (the
    stationary points of a phase's output, all of them in one pass)."""
    m = start.shape[0]
    rows = np.arange(m)
    g0, d0 = sig.both(rows, start)
    found: list = []
    _brackets(sig, start, t_end, np.zeros(m), np.zeros(m, dtype=bool), g0, d0, h_min, found)
    if not found:
        return np.zeros(0, dtype=np.intp), np.zeros(0)
    which, lo, hi, flo, fhi, M2, dlo, dhi = (np.concatenate(parts) for parts in zip(*found))
    out = hi.copy()
    open_ = np.flatnonzero(lo < hi)
    if open_.size:
        out[open_] = refine(sig, which[open_], lo[open_], hi[open_], xtol, 0.0, flo[open_],
                            fhi[open_], curvature=M2[open_],
                            slopes=(dlo[open_], dhi[open_]))
    return which, out


def _brackets(sig: Signals, start: np.ndarray, t_end: np.ndarray, direction: np.ndarray,
              on_surface: np.ndarray, g0: np.ndarray, d0: np.ndarray, h_min: float,
              collect: list | None = None, level: np.ndarray | None = None,
              band: np.ndarray | None = None,
              owner: np.ndarray | None = None,
              limit: np.ndarray | None = None) -> tuple[np.ndarray, ...]:
    """(lo, hi) of the first step over which each g leaves its side, (hi, hi)
    where it is on the other side or 0 at hi already, NaN where it does not;
    the values watched at lo and hi, the level watched at the end, and the
    bound of |g''| over the window that holds the bracket.
    With ``collect`` (a list) every bracket is appended to it as (rows, lo,
    hi, value at lo, value at hi, bound of |g''|) arrays and the search goes on from hi on the
    other side. Where ``level`` is nonzero the row watches g + level
    (``level[i]`` turns 0 once g is past ``band[i]`` on its side); lo and hi
    bracket the value watched. With ``owner``, a row past the earliest ``hi``
    of its owner, or past its ``limit`` (a crossing of its owner found
    otherwise), stops.

    Each step is the longest of: the certified distances (|g|/L, the root of
    |g| − |g'| h − M₂h²/2, or, where g moves away from 0, of
    |g| + |g'| h − M₂h²/2), ``h_min``, and, where g heads for 0, a step
    over which g is monotone (h ≤ |g'|/(2M₂), so |g'| stays above |g'|/2),
    twice the Newton distance |g/g'| long: on it g has at most one zero and
    the sign at its end tells whether it has one, so the step is certified as
    well, and it brackets a simple root in one step once Newton's distance
    is accurate."""
    m = start.shape[0]
    lo, hi = np.full(m, np.nan), np.full(m, np.nan)
    flo, fhi = np.full(m, np.nan), np.full(m, np.nan)
    dlo, dhi = np.full(m, np.nan), np.full(m, np.nan)
    level = np.zeros(m) if level is None else level.copy()
    t, gt, dt = start.copy(), g0 + level, d0.copy()
    window = sig.window(ALL, np.maximum(t_end - start, h_min))
    decays = sig.decays()
    side = np.where(on_surface & (direction != 0), -direction, np.sign(gt))
    zero = np.flatnonzero(side == 0)                 # on the surface, either way
    if zero.size:
        t[zero] = start[zero] + np.minimum(h_min, t_end[zero] - start[zero])
        gt[zero], dt[zero] = sig.both(zero, t[zero])
        gt[zero] += level[zero]
        side[zero] = np.sign(gt[zero])
    w_end = t.copy()                                 # a window to open on the first round
    L, M2 = np.zeros(m), np.zeros(m)
    act = np.flatnonzero(t < t_end)
    if owner is not None:
        cap = np.full(int(owner.max()) + 1 if m else 0, np.inf)
    while act.size:
        renew = act[t[act] >= w_end[act]]            # the window passed: bounds of the next
        if renew.size:
            w_end[renew] = np.minimum(t[renew] + window[renew], t_end[renew])
            (L[renew], M2[renew]), (Lr, Mr) = sig.bounds_on(
                renew if renew.size < m else ALL, t[renew], w_end[renew], t_end[renew])
            # where the bounds over the whole rest are nearly those of the window
            # (an undamped oscillation, a rigid motion), the rest is the window;
            # not where a term decays: its bounds shrink window by window
            whole = (Lr <= 2 * L[renew]) & (Mr <= 4 * M2[renew]) & ~decays[renew]
            pick = renew[whole]
            w_end[pick], L[pick], M2[pick] = t_end[pick], Lr[whole], Mr[whole]
        ta, ga, sa, La, Ma = t[act], gt[act], side[act], L[act], M2[act]
        ag = np.abs(ga)
        d1 = np.abs(dt[act])
        with np.errstate(divide="ignore", invalid="ignore"):
            newton = 2 * ag / (d1 + np.sqrt(d1 * d1 + 2 * Ma * ag))
            step = np.maximum(ag / La, newton)
            # g heads for 0 and stays monotone over twice Newton's distance
            heading = dt[act] * sa
            mono = np.minimum(2 * ag / d1, 0.5 * d1 / Ma)
            step = np.where((heading < 0) & (mono > step), mono, step)
            # g moves away from 0 (a start on the surface): |g| + |g'|h − M₂h²/2
            # stays above 0 up to its positive root
            away = (d1 + np.sqrt(d1 * d1 + 2 * Ma * ag)) / Ma
            step = np.where((heading > 0) & (away > step), away, step)
        step = np.where(La <= 0, w_end[act] - ta, step)     # g constant on the window
        step = np.where(np.sign(ga) != sa, 0.0, step)
        step = np.where(np.isnan(step), 0.0, step)
        nxt = np.minimum(ta + np.maximum(step, h_min), w_end[act])
        gn, dn = sig.both(act if act.size < m else ALL, nxt)   # act: sorted, unique
        la = level[act]
        gn = gn + la
        banded = np.flatnonzero(la != 0)
        if banded.size:                              # out of the band on its side: plain g
            rows_b = act[banded]
            out = side[rows_b] * (gn[banded] - la[banded]) > band[rows_b]
            gn[banded[out]] -= la[banded[out]]
            level[rows_b[out]] = 0.0
        crossed = (gn == 0.0) | (np.sign(gn) != sa)
        at_hi = crossed & ((gn == 0.0) | (np.sign(ga) != sa))
        done = act[crossed]
        lo[done] = np.where(at_hi[crossed], nxt[crossed], ta[crossed])
        hi[done] = nxt[crossed]
        flo[done] = np.where(at_hi[crossed], gn[crossed], ga[crossed])
        fhi[done] = gn[crossed]
        dlo[done] = np.where(at_hi[crossed], dn[crossed], dt[done])
        dhi[done] = dn[crossed]
        t[act], gt[act], dt[act] = nxt, gn, dn
        if collect is None:
            keep = ~crossed & (nxt < t_end[act])
            if owner is not None:                    # past the owner's earliest bracket
                np.minimum.at(cap, owner[done], hi[done])
                keep &= nxt <= cap[owner[act]]
                if limit is not None:
                    keep &= nxt <= limit[act]
            act = act[keep]
            continue
        collect.append((done, lo[done], hi[done], flo[done], fhi[done], M2[done], dlo[done],
                        dhi[done]))
        side[done] = -side[done]
        flat = done[side[done] == 0]                     # began on the surface: g decides
        side[flat] = np.sign(gt[flat])
        act = act[nxt < t_end[act]]
    return lo, hi, flo, fhi, level, M2, dlo, dhi


def refine(sig: Signals, rows: np.ndarray, lo: np.ndarray, hi: np.ndarray,
           xtol: float = 1e-14, level: np.ndarray | float = 0.0,
           f_lo: np.ndarray | None = None, f_hi: np.ndarray | None = None,
           max_rounds: int = 200, guess: np.ndarray | None = None,
           evaluate: Callable[[np.ndarray, np.ndarray], tuple[np.ndarray, np.ndarray]]
           | None = None, curvature: np.ndarray | None = None,
           slopes: tuple[np.ndarray, np.ndarray] | None = None) -> np.ndarray:
    """The root of each g + ``level`` in its bracket [lo, hi] (values of opposite
    signs at the ends, or 0 at one; ``f_lo``, ``f_hi`` where the search knows
    them; a first point ``guess`` inside), to ``xtol`` plus 4 ulp of the root.
    ``evaluate(positions, t)`` (g and g' of those of ``rows``) may stand for
    :meth:`Signals.both` where the caller evaluates them more cheaply.
    ``curvature`` (a bound of |g''| on each bracket) lets a row stop one
    evaluation sooner: Newton's point x − c is within ``xtol`` of the root
    once 4M₂c² ≤ (|g'| − 2M₂|c|)·xtol (with |g'| > 4M₂|c|), its error being
    at most 2M₂c²/(|g'| − 2M₂|c|). ``slopes`` (g' at lo and hi) give the
    first point as the root of the cubic through both ends' values and
    slopes (:func:`_hermite_root`) instead of the secant's.

    Newton's method kept in the bracket: the first point is the secant of the
    ends, each evaluation gives g and g' (one pass over the terms) and
    narrows the bracket by its sign; a Newton point outside the bracket is
    replaced by its middle (so the bracket at least halves), and a row is
    done when Newton's correction is within the tolerance (the root is the
    corrected point; convergence is quadratic there), the bracket is, or
    Newton's correction at an end of it is (that end the root)."""
    rtol = 4 * np.finfo(float).eps
    a, b = lo.copy(), hi.copy()
    level = np.broadcast_to(np.asarray(level, dtype=float), a.shape)
    fa = sig.value(rows, a) + level if f_lo is None else f_lo.copy()
    fb = sig.value(rows, b) + level if f_hi is None else f_hi.copy()
    root = np.where(fa == 0.0, a, np.where(fb == 0.0, b, np.nan))
    live = np.flatnonzero(np.isnan(root))
    with np.errstate(divide="ignore", invalid="ignore"):
        x = b - fb * (b - a) / (fb - fa) if guess is None else guess.copy()
    if guess is None and slopes is not None:
        x = _hermite_root(a, b, fa, fb, *slopes, x)
    x = np.where((x > a) & (x < b), x, 0.5 * (a + b))
    for _ in range(max_rounds):
        if not live.size:
            break
        xl = x[live]
        g, d = sig.both(rows[live], xl) if evaluate is None else evaluate(live, xl)
        g = g + level[live]
        hit = g == 0.0
        left = np.sign(g) == np.sign(fa[live])              # the root is in [x, b]
        a[live] = np.where(left, xl, a[live])
        fa[live] = np.where(left, g, fa[live])
        b[live] = np.where(left, b[live], xl)
        fb[live] = np.where(left, fb[live], g)
        al, bl = a[live], b[live]
        with np.errstate(divide="ignore", invalid="ignore"):
            newton = xl - g / d
        inside = (newton > al) & (newton < bl)
        tol = xtol + rtol * np.abs(xl)
        # a correction within the tolerance: converged (it may point a hair out of
        # the bracket when g at x is rounding noise)
        done = ~hit & (np.abs(newton - xl) <= tol)
        if curvature is not None:                # the Newton point's error is bounded
            c, M, dd = np.abs(newton - xl), curvature[live], np.abs(d)
            with np.errstate(invalid="ignore", over="ignore"):
                done |= ~hit & inside & (dd > 4 * M * c) & (4 * M * c * c <= (dd - 2 * M * c) * tol)
        close = ~hit & ~done & (bl - al <= 2 * tol)
        # an end of the bracket whose Newton correction (by g' at x) is within
        # the tolerance is the root: Newton points a hair past it, and halving
        # toward it would take a round per bit
        fal, fbl = np.abs(fa[live]), np.abs(fb[live])
        with np.errstate(divide="ignore", invalid="ignore"):
            at_end = ~hit & ~done & ~close & ~inside & (np.minimum(fal, fbl) <= tol * np.abs(d))
        root[live[hit]] = xl[hit]
        root[live[done]] = np.clip(newton[done], al[done], bl[done])
        root[live[close]] = 0.5 * (al[close] + bl[close])
        root[live[at_end]] = np.where(fal[at_end] <= fbl[at_end], al[at_end], bl[at_end])
        x[live] = np.where(inside, newton, 0.5 * (al + bl))
        live = live[~(hit | done | close | at_end)]
    if live.size:
        root[live] = 0.5 * (a[live] + b[live])
    return root


def _hermite_root(a: np.ndarray, b: np.ndarray, fa: np.ndarray, fb: np.ndarray,
                  da: np.ndarray, db: np.ndarray, secant: np.ndarray) -> np.ndarray:
    """The root in [a, b] of the cubic with g's values and slopes at both ends
    (three Newton steps on it from the secant's point, kept in the bracket);
    the secant's point where the cubic gives none (a first point only:
    :func:`refine` narrows it on g itself)."""
    h = b - a
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        u = np.clip((secant - a) / h, 0.0, 1.0)
        for _ in range(3):
            u2, u3 = u * u, u * u * u
            p = ((2 * u3 - 3 * u2 + 1) * fa + (u3 - 2 * u2 + u) * h * da
                 + (3 * u2 - 2 * u3) * fb + (u3 - u2) * h * db)
            dp = ((6 * u2 - 6 * u) * (fa - fb) + (3 * u2 - 4 * u + 1) * h * da
                  + (3 * u2 - 2 * u) * h * db)
            u = np.clip(u - p / dp, 0.0, 1.0)
        x = a + u * h
    return np.where(np.isfinite(x), x, secant)
