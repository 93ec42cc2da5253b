"""Piecewise-linear systems: x' = A x + b between events, each phase in closed form.

A drive with backlash, brakes that stick and forces switched on at given
instants is linear between the instants at which a contact changes; this
module solves each phase exactly and finds the switching instants by root
finding on those closed forms, never by a time-stepping integrator.

Each phase's exp(Mt) comes from :mod:`crane_sym.mechanics.closed_forms`.

Events without a skipped crossing
---------------------------------
An event is an affine function g(x) = w·x + k of the state (a contact angle,
a speed, a torque against a brake's limit). Along a phase g(t) = Σ_j a_j β_j(t)
with the real terms β_j above, so |g'| and |g''| on [t, t + H] are bounded by
Σ |a_j| max|β_j'| and Σ |a_j| max|β_j''| (:meth:`ClosedForm.derivative_bound`,
:meth:`ClosedForm.second_derivative_bound`). From t, g cannot reach 0 before
t + |g(t)|/L, nor before the root h* of |g(t)| − |g'(t)| h − M₂h²/2 (a
Newton-like step, since g'(t) is exact): :func:`first_crossing` steps by the
larger certified distance, and by ``h_min`` where it is smaller, checking the sign at each
step; a sign change is refined by ``scipy.optimize.brentq``. No crossing is
skipped except a pair of crossings closer together than ``h_min`` (a touch);
the first crossing is found to ``xtol``.

Switching
---------
:func:`simulate` runs a :class:`HybridSystem`: a set of modes (any hashable
key), each with its (A, b), its guards, and a rule that maps a fired guard or
a scheduled instant to the next mode and state (e.g. a brake that sticks sets
a speed to zero). Vöth and Tyulenev's two-mass hoist with coupling backlash and
Andrianov and Ivanov's three-mass travel drive with backlash in two stages are
such systems.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Callable, Hashable, Iterator, Protocol, Sequence

import numpy as np
from scipy.optimize import brentq

from crane_sym.mechanics.closed_forms import ClosedForm, JordanFormError, closed_form

__all__ = ["ClosedForm", "Guard", "HybridSystem", "MAX_PHASES", "PhaseFormError",
           "PhaseLimitError", "PiecewiseResult", "Segment", "by_phase", "closed_form",
           "exact_zeros", "first_crossing", "sign_change", "signal", "simulate"]


#: Largest relative residual of a phase's closed form at the phase's end
#: (:meth:`ClosedForm.residual`) before it is taken from :func:`precise_form`.
RESIDUAL = 1e-8
#: The provider of precise closed forms (mpmath: ``exact_forms`` registers it).
_PRECISE: list[Callable[[np.ndarray, np.ndarray, float], ClosedForm]] = []


def use_precise_forms(provider: Callable[[np.ndarray, np.ndarray, float], ClosedForm]) -> None:
    """Register (A, b, the phase's longest) -> the form :func:`precise_form` takes."""
    _PRECISE[:] = [provider]


def precise_form(A: np.ndarray, b: np.ndarray, length: float, x0: np.ndarray,
                 horizon: float) -> ClosedForm:
    """The closed form, from the precise provider, of a phase at most ``horizon``
    long whose double one does not solve its equations to :data:`RESIDUAL` over
    ``length``; refused by name where none is registered or it does not either,
    or not from x0."""
    form = _PRECISE[0](A, b, horizon) if _PRECISE else None
    if form is None or max(form.residual(length, x0, A, b),
                           form.start_miss(length, x0, A, b)) > RESIDUAL:
        raise PhaseFormError(f"a phase of {length:g} s: its closed form does not solve its"
                             f" equations to {RESIDUAL:g} (time scales too far apart for"
                             " double precision)")
    return form


class PhaseFormError(RuntimeError):
    """A phase whose closed form neither route computes to :data:`RESIDUAL`."""


def _next_event(system: "HybridSystem", mode: Hashable, form: ClosedForm, x: np.ndarray,
                end: float, event: str, h_min: float) -> tuple[float, str]:
    """The phase's end: the first guard crossed before ``end``, else ``event``."""
    for guard in system.guards(mode):
        hit = first_crossing(form, x, np.array(guard.weights), guard.constant,
                             end, direction=guard.direction, h_min=h_min)
        if hit is not None and hit < end:
            end, event = hit, guard.name
    return end, event


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


@dataclass(frozen=True)
class Guard:
    """An affine event function g(x) = weights·x + constant of a mode; it fires
    when g changes sign."""

    name: str
    weights: tuple[float, ...]
    constant: float = 0.0
    direction: int = 0     # +1: fires as g rises through 0, -1: as it falls, 0: either


class HybridSystem(Protocol):
    """What :func:`simulate` needs from a piecewise-linear model."""

    def matrices(self, mode: Hashable) -> tuple[np.ndarray, np.ndarray]:
        """(A, b) of the mode."""

    def guards(self, mode: Hashable) -> list[Guard]:
        """The events that end the mode."""

    def switch(self, mode: Hashable, event: str, t: float,
               x: np.ndarray) -> tuple[Hashable, np.ndarray]:
        """The next mode and state after ``event`` (a guard's or a scheduled name)."""


@dataclass(frozen=True)
class Segment:
    """One phase: mode, start and end time, the state at its start, its closed form."""

    mode: Hashable
    t0: float
    t1: float
    x0: np.ndarray
    form: ClosedForm
    event: str

    def state(self, t: np.ndarray) -> np.ndarray:
        """x(t) for absolute times t in [t0, t1]."""
        return self.form.state(np.asarray(t, dtype=float) - self.t0, self.x0)


@dataclass
class PiecewiseResult:
    """The phases of a run, in order; :meth:`state` evaluates x at any times."""

    segments: list[Segment] = field(default_factory=list)

    @property
    def events(self) -> list[tuple[float, str, Hashable]]:
        """(time, event that ended the phase, mode of the phase)."""
        return [(s.t1, s.event, s.mode) for s in self.segments]

    def state(self, times: np.ndarray) -> np.ndarray:
        """x at ``times`` (inside [0, end]), shape ``times.shape + (n,)``."""
        times = np.asarray(times, dtype=float)
        out = np.empty(times.shape + (self.segments[0].form.n,))
        for i, mask in by_phase([s.t0 for s in self.segments], times):
            out[mask] = self.segments[i].state(times[mask])
        return out


def by_phase(starts: Sequence[float], times: np.ndarray) -> Iterator[tuple[int, np.ndarray]]:
    """(i, mask) for each phase i (phases start at ``starts``, in order) that
    holds some of ``times``; a time before the first start goes to phase 0.

    Parameters
    ----------
    starts : sequence of float
        The phases' start times, increasing.
    times : ndarray
        The times to sort.
    """
    which = np.clip(np.searchsorted(starts, times, side="right") - 1, 0, None)
    for i in range(len(starts)):
        mask = which == i
        if np.any(mask):
            yield i, mask


#: The most phases a run may take (a chattering contact, a brake that sticks
#: and slips at every step, would otherwise never end): past it the run stops
#: with :class:`PhaseLimitError`.
MAX_PHASES = 10_000


class PhaseLimitError(RuntimeError):
    """A run past its phase limit: the limit, the instant reached and the end."""

    def __init__(self, limit: int, t: float, t_end: float, last: str) -> None:
        super().__init__(f"more than {limit} phases (events) by t = {t:.6g} s of {t_end:g} s "
                         f"(the phase limit; the last event {last!r})")
        self.limit, self.t, self.t_end, self.last = limit, t, t_end, last


def _phase(system: HybridSystem, mode: Hashable, x: np.ndarray, first: tuple[float, str],
           h_min: float, exact: bool | None) -> tuple[ClosedForm, float, str]:
    """The phase from ``x`` in ``mode``: its closed form, its length and the
    event that ends it (``first``: the next scheduled one); the precise form
    where the double one's rounding grew past :data:`RESIDUAL` over it."""
    A, b = system.matrices(mode)
    form = closed_form(A, b, exact)
    end, event = _next_event(system, mode, form, x, *first, h_min)
    if form.residual(end, x, A, b) > RESIDUAL:      # rounding grown past the phase
        form = precise_form(A, b, end, x, first[0])
        end, event = _next_event(system, mode, form, x, *first, h_min)
        form = precise_form(A, b, end, x, first[0])   # checked where it ends too
    return form, end, event


def simulate(system: HybridSystem, mode: Hashable, x0: Sequence[float], t_end: float,
             schedule: Sequence[tuple[float, str]] = (), *, h_min: float = 1e-10,
             max_events: int = MAX_PHASES, exact: bool | None = None) -> PiecewiseResult:
    """Run ``system`` from ``mode`` and ``x0`` at t = 0 to ``t_end``.

    ``schedule`` lists (time, name) events known in advance (a brake that
    engages after its delay); ``system.switch`` handles them like guards.
    Each phase is the closed form of its (A, b); its end is the earliest of its
    guards' first crossings (:func:`first_crossing`) and the next scheduled time.
    ``exact`` chooses the closed forms' route (:func:`closed_form`); False, the
    numeric eigenvectors, is what a sweep over many designs wants (each design
    has new matrices, and SymPy's Jordan form costs ~0.2 s a run).

    Parameters
    ----------
    system : HybridSystem
        The modes, their (A, b), guards and switch rule.
    mode : hashable
        The mode at t = 0.
    x0 : sequence of float
        The state at t = 0.
    t_end : float
        End of the run.
    schedule : sequence of (float, str), optional
        Events known in advance.
    h_min : float, optional
        Shortest step of the event search.
    max_events : int, optional
        The run fails beyond this many phases (:class:`PhaseLimitError`).
    exact : bool, optional
        The closed forms' route (None: the system's choice).
    """
    x = np.asarray(x0, dtype=float)
    pending = sorted((float(t), name) for t, name in schedule if 0 <= t < t_end)
    result, t, event = PiecewiseResult(), 0.0, "start"
    for _ in range(max_events):
        horizon = (pending[0][0] if pending else t_end) - t
        first = (horizon, pending[0][1] if pending else "end")
        try:
            form, end, event = _phase(system, mode, x, first, h_min, exact)
        except JordanFormError as exc:
            raise exc.in_phase(len(result.segments) + 1, t) from None
        result.segments.append(Segment(mode, t, t + end, x, form, event))
        x_end = form.state(end, x)
        t += end
        if event == "end":
            return result
        if pending and event == pending[0][1] and end == horizon:
            pending.pop(0)
        mode, x = system.switch(mode, event, t, x_end)
    raise PhaseLimitError(max_events, t, t_end, event)

