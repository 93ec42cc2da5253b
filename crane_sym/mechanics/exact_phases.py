"""A piecewise-linear run solved in mpmath, so that what a module prints of it
is the same on every machine.

The double-precision run (:func:`crane_sym.mechanics.piecewise_linear.simulate`) takes
its last bits from the machine: libm's sines and exponentials, NumPy's SIMD
loops, LAPACK's inverse. Thirty phases carry those bits from event to event,
and a table printed to 13 digits from it changes in its last digits from one
machine to another; where a guard grazes its surface (a speed that starts
from rest with zero acceleration) rounding noise even decides whether an
event fires. :func:`simulate_exact` runs the same model at :data:`DPS` digits:

- each phase's exp(Mt) from SymPy's exact Jordan form where that is cheap
  (n ≤ 4, no clusters, factors at most quadratic, as the double run takes it)
  or from its spectral clusters in mpmath (:class:`ExactForm`);
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
from functools import lru_cache
from typing import Callable, Hashable, Sequence

import mpmath
import numpy as np
import sympy as sp

from crane_sym.mechanics.closed_forms import ClosedForm, exact_is_cheap, jordan, jordan_blocks
from crane_sym.mechanics.phase_table import HybridRun, PhaseTable
from crane_sym.mechanics.spectral_clusters import Algebra, cluster_terms, group
from crane_sym.mechanics.piecewise_linear import (MAX_PHASES, Guard, HybridSystem, PhaseLimitError,
                                                  sign_change, signal, use_precise_forms)

__all__ = ["DPS", "ExactForm", "ExactRun", "ExactSegment", "crossing", "exact_form",
           "exact_table", "illinois", "simulate_exact", "tabulate_exact"]

#: Working digits of the exact run.
DPS = 40
EPS = float(np.finfo(float).eps)


def _mp(value: sp.Expr) -> mpmath.mpf | mpmath.mpc:
    """An exact SymPy number at the working precision."""
    return sp.sympify(value)._to_mpmath(mpmath.mp.prec)


@dataclass(frozen=True, eq=False)
class ExactForm:
    """exp(M τ) of one phase as Σ_j C_j β_j(τ), β_j = τ^k e^{στ} {cos, sin}(ωτ),
    in mpmath (the same terms as :class:`crane_sym.mechanics.closed_forms.ClosedForm`)."""

    n: int
    powers: tuple[int, ...]
    sigmas: tuple[mpmath.mpf, ...]
    omegas: tuple[mpmath.mpf, ...]
    sine: tuple[bool, ...]
    coefficients: tuple[mpmath.matrix, ...]

    @property
    def double(self) -> ClosedForm:
        """The same terms rounded to double (what the event search steps with)."""
        return _double(self)

    def basis(self, tau: mpmath.mpf) -> list[mpmath.mpf]:
        """β_j(τ) for every term."""
        out = []
        for k, s, w, sine in zip(self.powers, self.sigmas, self.omegas, self.sine):
            wave = mpmath.sin(w * tau) if sine else mpmath.cos(w * tau)
            out.append(tau ** k * mpmath.exp(s * tau) * wave)
        return out

    def vectors(self, z0: Sequence[mpmath.mpf]) -> list[list[mpmath.mpf]]:
        """C_j (x0, 1) for every term, the state part only."""
        z = mpmath.matrix(list(z0) + [1])
        return [list((C * z)[: self.n]) for C in self.coefficients]

    def state(self, tau: mpmath.mpf, z0: Sequence[mpmath.mpf]) -> list[mpmath.mpf]:
        """x(τ) from x(0) = ``z0``."""
        beta = self.basis(tau)
        vectors = self.vectors(z0)
        return [mpmath.fsum(b * v[i] for b, v in zip(beta, vectors)) for i in range(self.n)]

    def amplitudes(self, z0: Sequence[mpmath.mpf],
                   weights: Sequence[mpmath.mpf]) -> list[mpmath.mpf]:
        """a_j of w·x(τ) = Σ a_j β_j(τ)."""
        return [mpmath.fdot(weights, v) for v in self.vectors(z0)]


@lru_cache(maxsize=256)
def _double(form: ExactForm) -> ClosedForm:
    coefs = np.array([[[float(C[i, j]) for j in range(C.cols)] for i in range(C.rows)]
                      for C in form.coefficients], dtype=float)
    return ClosedForm(form.n, np.array(form.powers, dtype=float),
                      np.array([float(v) for v in form.sigmas]),
                      np.array([float(v) for v in form.omegas]),
                      np.array(form.sine, dtype=bool), coefs)


def _real_terms(terms: list[tuple[int, mpmath.mpc, mpmath.matrix]], n: int) -> ExactForm:
    """Fold each pair λ = σ ± iω into the real terms cos ωτ and sin ωτ."""
    tiny = mpmath.mpf(10) ** (10 - mpmath.mp.dps)
    powers, sigmas, omegas, sine, coefs = [], [], [], [], []
    for j, lam, C in sorted(terms, key=lambda t: (t[0], mpmath.re(t[1]), mpmath.im(t[1]))):
        re, im = mpmath.re(lam), mpmath.im(lam)
        if abs(im) <= tiny * (1 + abs(lam)):          # a real root printed with radicals
            im = mpmath.mpf(0)
        if abs(re) <= tiny * (1 + abs(lam)):
            re = mpmath.mpf(0)
        if im < 0:
            continue                                  # folded into its conjugate
        pair = 2 if im > 0 else 1
        for is_sine in (False, True):
            if im == 0 and is_sine:
                continue
            part = C.apply(mpmath.im) * (-pair) if is_sine else C.apply(mpmath.re) * pair
            powers.append(j), sigmas.append(re), omegas.append(abs(im))
            sine.append(is_sine), coefs.append(part)
    return ExactForm(n, tuple(powers), tuple(sigmas), tuple(omegas), tuple(sine), tuple(coefs))


def _augmented(a_key: tuple, b_key: tuple) -> mpmath.matrix:
    """M = [[A, b], [0, 0]], each entry the float's shortest decimal (as the
    exact Jordan form takes it, :func:`crane_sym.mechanics.closed_forms.jordan`)."""
    n = len(b_key)
    M = mpmath.zeros(n + 1, n + 1)
    for i in range(n):
        for j in range(n):
            M[i, j] = mpmath.mpf(repr(a_key[i * n + j]))
        M[i, n] = mpmath.mpf(repr(b_key[i]))
    return M


def _form_jordan(a_key: tuple, b_key: tuple) -> ExactForm:
    """The terms from SymPy's exact Jordan form, P evaluated in mpmath."""
    P, J = jordan(a_key, b_key)
    size = P.rows
    Pm = mpmath.matrix([[_mp(e) for e in P.row(r)] for r in range(size)])
    Pinv = mpmath.inverse(Pm)
    terms: dict[tuple, list] = {}
    for i, k in jordan_blocks(J):
        for j in range(k):                            # τ^j/j! on the j-th superdiagonal
            E = mpmath.zeros(size, size)
            for r in range(k - j):
                E[i + r, i + r + j] = 1 / mpmath.factorial(j)
            entry = terms.setdefault((j, J[i, i]), [j, _mp(J[i, i]), mpmath.zeros(size, size)])
            entry[2] = entry[2] + Pm * E * Pinv
    return _real_terms([tuple(v) for v in terms.values()], size - 1)


def _mp_algebra() -> Algebra:
    return Algebra(matmul=lambda X, Y: X * Y, norm=lambda X: mpmath.mnorm(X, "F"),
                   sqrt=mpmath.sqrt, trace=lambda X: mpmath.fsum(X[i, i] for i in range(X.rows)),
                   eps=float(mpmath.mpf(10) ** (-mpmath.mp.dps)))


def _errors(M: mpmath.matrix, left: mpmath.matrix, right: mpmath.matrix) -> list[float]:
    """Rounding bounds eps·κ_i·‖M‖ of the eigenvalues at the working digits
    (:func:`crane_sym.mechanics.spectral_clusters.resolution`, in mpmath)."""
    eps, norm, out = mpmath.mpf(10) ** (-mpmath.mp.dps), mpmath.mnorm(M, "F"), []
    for i in range(M.rows):
        r = [right[k, i] for k in range(M.rows)]
        l = [left[i, k] for k in range(M.rows)]
        dot = abs(mpmath.fsum(a * c for a, c in zip(l, r)))
        size = mpmath.sqrt(mpmath.fsum(abs(a) ** 2 for a in l) * mpmath.fsum(abs(c) ** 2 for c in r))
        out.append(float(eps * norm * size / dot) if dot else math.inf)
    return out


def _form_eig(a_key: tuple, b_key: tuple, resolve: bool = False) -> ExactForm | None:
    """The terms from the spectral clusters of M
    (:mod:`crane_sym.mechanics.spectral_clusters`), their projectors from
    mpmath's left and right eigenvectors, at twice the working digits where
    eigenvalues cluster (a defective pair's eigenvectors lose half the digits
    they are computed with); None where even those are not enough (the exact
    route then). With ``resolve`` a small eigenvalue its rounding bound resolves
    is a mode, not the kernel's (the precise fallback of a double phase: a slow
    mode beside one 1e7 times faster); without, every eigenvalue below
    KERNEL of the scale is the kernel's (a double's rounding in A leaves a rigid
    mode's zeros at ±3e-7i, exactly as the doubles say)."""
    algebra = _mp_algebra()
    M = _augmented(a_key, b_key)
    size = M.rows
    digits = mpmath.mp.dps
    lam, left, right = mpmath.eig(M, left=True, right=True)
    scale = max(max(abs(v) for v in lam), 1)
    errors = _errors(M, left, right) if resolve else None
    kernel, clusters = group(list(lam), float(scale), errors=errors)
    if any(len(c) > 1 for c in clusters):      # their vectors at twice the digits
        digits = 2 * mpmath.mp.dps
        with mpmath.workdps(digits):
            lam, left, right = mpmath.eig(M, left=True, right=True)
            errors = _errors(M, left, right) if resolve else None
        kernel, clusters = group(list(lam), float(scale), errors=errors)
    terms, projector = [], mpmath.zeros(size, size)
    for cluster in clusters:
        with mpmath.workdps(digits):
            R = mpmath.matrix([[right[r, c] for c in cluster] for r in range(size)])
            L = mpmath.matrix([[left[c, r] for r in range(size)] for c in cluster])
            gram = L * R
            if mpmath.cond(gram) > mpmath.mpf(10) ** (digits - 25):   # 25 digits kept
                return None
            P = R * mpmath.inverse(gram) * L
            mu = mpmath.fsum(lam[i] for i in cluster) / len(cluster)
        P = P * 1                                     # rounded to the working digits
        projector += P
        real = mpmath.mpf("1e-6") if len(cluster) > 1 else mpmath.mpf(10) ** (10 - mpmath.mp.dps)
        if abs(mpmath.im(mu)) <= real * abs(mu):     # a real eigenvalue, or a real
            mu = mpmath.mpc(mpmath.re(mu), 0)        # (conjugate-closed) cluster
        if mpmath.im(mu) < 0:
            continue
        N = (M - mu * mpmath.eye(size)) * P
        terms += cluster_terms(P, N, mu, len(cluster), algebra, float(scale))
    form = _real_terms(terms, size - 1)
    Q = mpmath.eye(size) - projector.apply(mpmath.re)
    N, term = M * Q, Q
    extra = []
    for j in range(len(kernel)):
        if j:
            term = N * term / j
        extra.append(term)
    return ExactForm(form.n, form.powers + tuple(range(len(extra))),
                     form.sigmas + (mpmath.mpf(0),) * len(extra),
                     form.omegas + (mpmath.mpf(0),) * len(extra),
                     form.sine + (False,) * len(extra), form.coefficients + tuple(extra))


@lru_cache(maxsize=256)
def _exact_form_cached(a_key: tuple, b_key: tuple, dps: int,
                       resolve: bool = False) -> ExactForm:
    with mpmath.workdps(dps):
        if exact_is_cheap(a_key, b_key):            # as the double run takes it
            return _form_jordan(a_key, b_key)
        return _form_eig(a_key, b_key, resolve) or _form_jordan(a_key, b_key)


def _precise(A: np.ndarray, b: np.ndarray) -> ClosedForm:
    """exp(Mt) at :data:`DPS` digits rounded to double: what a double run
    takes where its own form does not solve its equations (time scales 1e7
    apart)."""
    A = np.asarray(A, dtype=float)
    return _exact_form_cached(tuple(map(float, A.ravel())), tuple(map(float, np.ravel(b))),
                              DPS, True).double


use_precise_forms(_precise)


def exact_form(A: Sequence, b: Sequence) -> ExactForm:
    """exp(Mt) of x' = A x + b in mpmath at the working precision (cached).
    The entries of A and b are taken exactly, as the doubles they are."""
    A = np.asarray(A, dtype=float)
    return _exact_form_cached(tuple(map(float, A.ravel())), tuple(map(float, np.ravel(b))),
                              mpmath.mp.dps)


def _noise(form: ClosedForm, amps: np.ndarray, k: float, t: float) -> float:
    """A bound of the rounding error of :func:`crane_sym.mechanics.piecewise_linear.signal`'s
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
            form = exact_form(*system.matrices(mode))
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
