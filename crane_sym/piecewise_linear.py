"""Piecewise-linear systems: x' = A x + b between events, each phase in closed form.

A drive with backlash, brakes that stick and forces switched on at given
instants is linear between the instants at which a contact changes; this
module solves each phase exactly and finds the switching instants by root
finding on those closed forms, never by a time-stepping integrator.

Closed form of one phase
------------------------
With z = (x, 1), z' = M z and M = [[A, b], [0, 0]], so z(t) = exp(M t) z(0).
SymPy's exact Jordan decomposition M = P J P⁻¹ (each entry of A and b taken
as the exact rational of its shortest decimal; P evaluated to 30 digits, then
inverted in floating point, which is stable where a symbolic inverse of
nested radicals is not) gives

.. math::

    e^{Mt} = \\sum_{\\text{blocks}} \\sum_j C_{\\lambda, j}\\, \\frac{t^j}{j!} e^{\\lambda t},

and a pair λ = σ ± iω folds into real terms t^j e^{σt} cos ωt and t^j e^{σt} sin ωt
(:class:`ClosedForm`). Rigid-body modes (λ = 0, Jordan blocks) give the
polynomial part. Above n = 4 (where exact eigenvalues of arbitrary data become
costly radicals) the same terms come from numeric eigenvectors of the nonzero,
simple eigenvalues and the exact nilpotent series on the generalized kernel
(:func:`closed_form`, ``exact``). Evaluation is NumPy.

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
a speed to zero). Paper 001's two-mass hoist with coupling backlash and paper
003's three-mass travel drive with backlash in two stages are such systems.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field
from functools import lru_cache
from typing import Hashable, Iterator, Protocol, Sequence

import numpy as np
import sympy as sp
from scipy.optimize import brentq

__all__ = ["ClosedForm", "Guard", "HybridSystem", "PiecewiseResult", "Segment", "by_phase",
           "closed_form", "first_crossing", "simulate"]


@dataclass(frozen=True)
class ClosedForm:
    """exp(M t) of one phase as Σ_j C_j β_j(t), β_j = t^k e^{σt} {cos, sin}(ωt).

    Attributes
    ----------
    n : int
        Dimension of the state x.
    powers, sigmas, omegas : ndarray
        k, σ and ω of each term β_j.
    sine : ndarray of bool
        True where β_j carries sin(ωt), False for cos(ωt) (ω = 0: cos).
    coefficients : ndarray, shape (terms, n + 1, n + 1)
        The real matrices C_j.
    """

    n: int
    powers: np.ndarray
    sigmas: np.ndarray
    omegas: np.ndarray
    sine: np.ndarray
    coefficients: np.ndarray

    def basis(self, t: np.ndarray) -> np.ndarray:
        """β_j(t) for every term, shape (terms,) + shape of ``t``."""
        t = np.asarray(t, dtype=float)[..., None]
        wave = np.where(self.sine, np.sin(self.omegas * t), np.cos(self.omegas * t))
        return np.moveaxis(t ** self.powers * np.exp(self.sigmas * t) * wave, -1, 0)

    def state(self, t: np.ndarray | float, x0: np.ndarray) -> np.ndarray:
        """x(t) from x(0) = ``x0``; shape ``t.shape + (n,)``."""
        z0 = np.append(np.asarray(x0, dtype=float), 1.0)
        vectors = self.coefficients @ z0                       # (terms, n + 1)
        out = np.tensordot(self.basis(t), vectors, axes=(0, 0))
        return out[..., : self.n]

    def scalar_terms(self, weights: np.ndarray, constant: float,
                     x0: np.ndarray) -> tuple[np.ndarray, float]:
        """Coefficients a_j of g(t) = w·x(t) + k = Σ a_j β_j(t) + k."""
        z0 = np.append(np.asarray(x0, dtype=float), 1.0)
        return (self.coefficients @ z0)[:, : self.n] @ np.asarray(weights, float), constant

    def derivative_bound(self, amplitudes: np.ndarray, t0: float, t1: float) -> float:
        """An upper bound of |d/dt Σ a_j β_j| on [t0, t1] (0 ≤ t0 ≤ t1)."""
        k, s, w = self.powers, self.sigmas, self.omegas
        grow = np.exp(np.maximum(s * t0, s * t1))
        poly = np.where(k > 0, k * t1 ** np.maximum(k - 1, 0), 0.0)
        bound = grow * (poly + (np.abs(s) + w) * t1 ** k)
        return float(np.sum(np.abs(amplitudes) * bound))

    def second_derivative_bound(self, amplitudes: np.ndarray, t0: float, t1: float) -> float:
        """An upper bound of |d²/dt² Σ a_j β_j| on [t0, t1] (0 ≤ t0 ≤ t1)."""
        k, s, w = self.powers, self.sigmas, self.omegas
        grow = np.exp(np.maximum(s * t0, s * t1))
        rate = np.abs(s) + w
        p2 = np.where(k > 1, k * (k - 1) * t1 ** np.maximum(k - 2, 0), 0.0)
        p1 = np.where(k > 0, 2 * k * rate * t1 ** np.maximum(k - 1, 0), 0.0)
        bound = grow * (p2 + p1 + rate ** 2 * t1 ** k)
        return float(np.sum(np.abs(amplitudes) * bound))


@lru_cache(maxsize=256)
def _closed_form_cached(a_key: tuple, b_key: tuple) -> ClosedForm:
    n = len(b_key)
    exact = lambda v: sp.Rational(repr(v))  # noqa: E731  (the float's shortest decimal)
    aug = sp.zeros(n + 1, n + 1)
    aug[:n, :n] = sp.Matrix(n, n, [exact(v) for v in a_key])
    aug[:n, n] = sp.Matrix([exact(v) for v in b_key])
    P, J = aug.jordan_form()
    Pn = np.array(P.evalf(30).tolist(), dtype=complex)
    Pinv = np.linalg.inv(Pn)
    terms: dict[tuple, np.ndarray] = {}
    i = 0
    size = n + 1
    while i < size:                                   # walk the Jordan blocks
        lam = complex(sp.N(J[i, i], 30))
        if abs(lam.imag) <= 1e-20 * (1 + abs(lam)):     # a real root printed with radicals
            lam = complex(lam.real, 0.0)
        if abs(lam.real) <= 1e-20 * (1 + abs(lam)):
            lam = complex(0.0, lam.imag)
        k = 1
        while i + k < size and J[i + k - 1, i + k] == 1 and J[i + k, i + k] == J[i, i]:
            k += 1
        for j in range(k):                            # t^j/j! on the j-th superdiagonal
            E = np.zeros((size, size), dtype=complex)
            for r in range(k - j):
                E[i + r, i + r + j] = 1.0 / float(sp.factorial(j))
            C = Pn @ E @ Pinv
            key = (j, lam)
            terms[key] = terms.get(key, 0) + C
        i += k
    powers, sigmas, omegas, sine, coefs = [], [], [], [], []
    for (j, lam), C in sorted(terms.items(), key=lambda kv: (kv[0][0], kv[0][1].real,
                                                             kv[0][1].imag)):
        if lam.imag < 0:
            continue                                  # folded into its conjugate
        pair = 2.0 if lam.imag > 0 else 1.0
        for is_sine, part in ((False, pair * C.real), (True, -pair * C.imag)):
            if lam.imag == 0 and is_sine:
                continue
            powers.append(j), sigmas.append(lam.real), omegas.append(abs(lam.imag))
            sine.append(is_sine), coefs.append(part)
    return ClosedForm(n, np.array(powers, float), np.array(sigmas), np.array(omegas),
                      np.array(sine), np.array(coefs))


def closed_form(A: Sequence, b: Sequence, exact: bool | None = None) -> ClosedForm:
    """The closed form of x' = A x + b (cached).

    Parameters
    ----------
    A : (n, n) array-like of numbers
    b : (n,) array-like of numbers
    exact : bool, optional
        True: SymPy's exact Jordan form (entries as exact decimals); cheap for
        n ≤ 4 (two masses: quadratic eigenvalues), slow for larger systems with
        arbitrary data. False: numeric eigenvectors of the nonzero eigenvalues
        (simple, or repeated with a full set of eigenvectors) and the exact
        nilpotent series on the rest
        (rigid modes). Default: exact for n ≤ 4, numeric above.
    """
    A = np.asarray(A, dtype=float)
    key = (tuple(map(float, A.ravel())), tuple(map(float, np.ravel(b))))
    if exact if exact is not None else len(key[1]) <= 4:
        return _closed_form_cached(*key)
    return _closed_form_numeric(*key)


@lru_cache(maxsize=256)
def _closed_form_numeric(a_key: tuple, b_key: tuple) -> ClosedForm:
    """exp(M t) = Σ e^{λt} C_λ over the nonzero eigenvalues, plus Σ_j (N t)^j / j! · Q
    on the generalized kernel (Q = I − Σ C_λ, N = M Q). C_λ = R (Lᴴ R)⁻¹ Lᴴ from the
    right and left eigenvectors of λ: a repeated eigenvalue with a full set of
    eigenvectors (two equal drives) stays numeric; a defective one goes exact."""
    from scipy.linalg import eig

    n = len(b_key)
    M = np.zeros((n + 1, n + 1))
    M[:n, :n] = np.reshape(a_key, (n, n))
    M[:n, n] = b_key
    lam, vl, vr = eig(M, left=True, right=True)
    scale = max(np.abs(lam).max(), 1.0)
    live = np.flatnonzero(np.abs(lam) > 1e-6 * scale)
    clusters: list[list[int]] = []                 # equal eigenvalues (symmetric sides)
    for i in live:
        near = [c for c in clusters if abs(lam[c[0]] - lam[i]) < 1e-6 * scale]
        if near:
            near[0].append(i)
        else:
            clusters.append([i])
    projector = np.zeros((n + 1, n + 1), dtype=complex)
    powers, sigmas, omegas, sine, coefs = [], [], [], [], []
    for cluster in clusters:     # projector R (L^H R)^-1 L^H: semisimple clusters only
        R, L = vr[:, cluster], vl[:, cluster].conj().T
        gram = L @ R
        if np.linalg.cond(gram) > 1e8:
            return _closed_form_cached(a_key, b_key)   # a defective nonzero eigenvalue
        C = R @ np.linalg.solve(gram, L)
        projector += C
        value = np.mean(lam[cluster])
        if abs(value.imag) < 1e-6 * scale:             # real, or a pair too close to part
            value = complex(value.real, 0.0)
        if value.imag < 0:
            continue
        pair = 2.0 if value.imag > 0 else 1.0
        for is_sine, part in ((False, pair * C.real), (True, -pair * C.imag)):
            if value.imag == 0 and is_sine:
                continue
            powers.append(0), sigmas.append(value.real), omegas.append(abs(value.imag))
            sine.append(is_sine), coefs.append(part)
    Q = np.eye(n + 1) - projector.real
    N = M @ Q
    term = Q.copy()
    for j in range(n + 1 - live.size):
        if j:
            term = N @ term / j
        powers.append(j), sigmas.append(0.0), omegas.append(0.0)
        sine.append(False), coefs.append(term.copy())
    return ClosedForm(n, np.array(powers, float), np.array(sigmas), np.array(omegas),
                      np.array(sine), np.array(coefs))


def first_crossing(form: ClosedForm, x0: np.ndarray, weights: np.ndarray,
                   constant: float, t_end: float, *, direction: int = 0,
                   h_min: float = 1e-10, xtol: float = 1e-14,
                   window: float | None = None) -> float | None:
    """The first t in (0, t_end] where g = w·x(t) + k changes sign, or None.

    Steps by the certified distance |g|/L (L bounds |g'| over the current
    window, at most ``window`` long), never below ``h_min``; see the module
    docstring for the guarantee. ``direction`` (+1: g rises through 0, −1:
    falls, 0: either) says on which side a start on the surface lies: a phase
    that begins where the previous event left g = 0 up to rounding takes g on
    the side opposite to ``direction``, so the surface it starts on does not
    fire again at once.
    """
    amps, k = form.scalar_terms(weights, constant, x0)
    p, s, w, sine = form.powers, form.sigmas, form.omegas, form.sine

    # g and g' in plain floats: a phase has a handful of terms, and these run
    # thousands of times per run, where NumPy's per-call cost dominates.
    terms = [(float(a), int(pp), float(ss), float(ww), bool(sn))
             for a, pp, ss, ww, sn in zip(amps, p, s, w, sine) if a != 0.0]

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

    window = window or _window(form, max(t_end, h_min))
    t, gt = 0.0, g(0.0)
    size = float(np.sum(np.abs(amps)) + abs(k))
    on_surface = abs(gt) <= max(form.derivative_bound(amps, 0.0, min(h_min, t_end)) * h_min,
                                1e-12 * size)
    side = -direction if (on_surface and direction) else np.sign(gt)
    if side == 0:                                      # on the surface, either way
        t = min(h_min, t_end)
        gt = g(t)
        side = np.sign(gt)
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
            gn = g(nxt)
            if gn == 0.0 or np.sign(gn) != side:
                if gn == 0.0 or np.sign(gt) != side:
                    return nxt
                return brentq(g, t, nxt, xtol=xtol, rtol=4 * np.finfo(float).eps)
            t, gt = nxt, gn
    return None


def _window(form: ClosedForm, scale: float) -> float:
    """A window length over which the derivative bound stays tight: a quarter of
    the shortest period, and no longer than the e-folding time of a growing term."""
    limits = [scale]
    if np.any(form.omegas > 0):
        limits.append(0.25 * 2 * np.pi / form.omegas.max())
    if np.any(form.sigmas > 0):
        limits.append(1.0 / form.sigmas.max())
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
    holds some of ``times``; a time before the first start goes to phase 0."""
    which = np.clip(np.searchsorted(starts, times, side="right") - 1, 0, None)
    for i in range(len(starts)):
        mask = which == i
        if np.any(mask):
            yield i, mask


def simulate(system: HybridSystem, mode: Hashable, x0: Sequence[float], t_end: float,
             schedule: Sequence[tuple[float, str]] = (), *, h_min: float = 1e-10,
             max_events: int = 10_000, exact: bool | None = None) -> PiecewiseResult:
    """Run ``system`` from ``mode`` and ``x0`` at t = 0 to ``t_end``.

    ``schedule`` lists (time, name) events known in advance (a brake that
    engages after its delay); ``system.switch`` handles them like guards.
    Each phase is the closed form of its (A, b); its end is the earliest of its
    guards' first crossings (:func:`first_crossing`) and the next scheduled time.
    ``exact`` chooses the closed forms' route (:func:`closed_form`); False, the
    numeric eigenvectors, is what a sweep over many designs wants (each design
    has new matrices, and SymPy's Jordan form costs ~0.2 s a run).
    """
    x = np.asarray(x0, dtype=float)
    pending = sorted((float(t), name) for t, name in schedule if 0 <= t < t_end)
    result, t = PiecewiseResult(), 0.0
    for _ in range(max_events):
        A, b = system.matrices(mode)
        form = closed_form(A, b, exact)
        horizon = (pending[0][0] if pending else t_end) - t
        end, event = horizon, (pending[0][1] if pending else "end")
        for guard in system.guards(mode):
            hit = first_crossing(form, x, np.array(guard.weights), guard.constant,
                                 end, direction=guard.direction, h_min=h_min)
            if hit is not None and hit < end:
                end, event = hit, guard.name
        result.segments.append(Segment(mode, t, t + end, x, form, event))
        x_end = form.state(end, x)
        t += end
        if event == "end":
            return result
        if pending and event == pending[0][1] and end == horizon:
            pending.pop(0)
        mode, x = system.switch(mode, event, t, x_end)
    raise RuntimeError(f"more than {max_events} events before t = {t_end}")

