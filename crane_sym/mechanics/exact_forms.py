"""exp(M t) of one phase in mpmath: the closed forms the exact run steps
through, and the precise fallback of a double phase.

A phase x' = A x + b is z' = M z with z = (x, 1) and M = [[A, b], [0, 0]];
exp(M t) = Σ_j C_j β_j(t), β_j = t^k e^{σt} {cos, sin}(ωt), the terms of
:class:`crane_sym.mechanics.closed_forms.ClosedForm` (:class:`ExactForm`):

- from SymPy's exact Jordan form where that is cheap (n ≤ 4, no clusters,
  factors at most quadratic, as the double run takes it);
- else from the spectral clusters of M (:mod:`crane_sym.mechanics.spectral_clusters`),
  their projectors from mpmath's eigenvectors.

The precise fallback (:func:`precise_closed_form`, registered with
:func:`crane_sym.mechanics.piecewise_linear.use_precise_forms`) resolves the
small eigenvalues its rounding bound resolves as modes, and sums those slow
beside the phase (|λ| T ≤ :data:`SLOW` over its horizon T) with the kernel as
one series Σ_j (N t)^j / j!: a rigid-body mode's zero, rounded in A's doubles
to 4.6e-13 beside the constant input's exact 0, is an eigenvalue pair so
nearly defective that split into e^{λt} C_λ + C_0 its coefficients are
~1e13 and cancel to O(1), which rounding to double destroys; the series'
coefficients are those of the sum.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from functools import cached_property, lru_cache
from typing import Sequence

import mpmath
import numpy as np
import sympy as sp

from crane_sym.mechanics.closed_forms import ClosedForm, exact_is_cheap, jordan, jordan_blocks
from crane_sym.mechanics.piecewise_linear import use_precise_forms
from crane_sym.mechanics.spectral_clusters import KERNEL, Algebra, cluster_terms, group

__all__ = ["DPS", "ExactForm", "SLOW", "exact_form", "precise_closed_form"]

#: Working digits of the exact run.
DPS = 40
#: Largest |λ| T of a small resolved eigenvalue summed with the kernel over a
#: horizon T (its share of the series then falls as (|λ| T)^j / j!: below
#: 1e-40 by j = 35).
SLOW = 1.0
#: Most terms of the kernel's series.
SERIES_TERMS = 80


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

    @cached_property
    def _rows(self) -> tuple[list[list[mpmath.mpf]], ...]:
        """The state rows of each C_j as lists (mpmath's matrix product, less
        its bookkeeping: the same dot products in the same order)."""
        return tuple([[C[i, k] for k in range(C.cols)] for i in range(self.n)]
                     for C in self.coefficients)

    def vectors(self, z0: Sequence[mpmath.mpf]) -> list[list[mpmath.mpf]]:
        """C_j (x0, 1) for every term, the state part only."""
        z = [mpmath.mpmathify(v) for v in z0] + [mpmath.mpf(1)]
        return [[mpmath.fdot(zip(row, z)) for row in rows] for rows in self._rows]

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


def _form_eig(a_key: tuple, b_key: tuple, horizon: float | None = None) -> ExactForm | None:
    """The terms from the spectral clusters of M
    (:mod:`crane_sym.mechanics.spectral_clusters`), their projectors from
    mpmath's left and right eigenvectors, at twice the working digits where
    eigenvalues cluster (a defective pair's eigenvectors lose half the digits
    they are computed with); None where even those are not enough (the exact
    route then). With a ``horizon`` (the precise fallback of a double phase) a
    small eigenvalue its rounding bound resolves is a mode, not the kernel's (a
    slow mode beside one 1e7 times faster), and one slow over the horizon is
    summed with the kernel (:func:`_slow_series`); without, every eigenvalue
    below KERNEL of the scale is the kernel's (a double's rounding in A leaves
    a rigid mode's zeros at ±3e-7i, exactly as the doubles say)."""
    algebra = _mp_algebra()
    M = _augmented(a_key, b_key)
    size = M.rows
    digits = mpmath.mp.dps
    lam, left, right = mpmath.eig(M, left=True, right=True)
    scale = max(max(abs(v) for v in lam), 1)
    resolve = horizon is not None
    errors = _errors(M, left, right) if resolve else None
    kernel, clusters = group(list(lam), float(scale), errors=errors)
    if any(len(c) > 1 for c in clusters):      # their vectors at twice the digits
        digits = 2 * mpmath.mp.dps
        with mpmath.workdps(digits):
            lam, left, right = mpmath.eig(M, left=True, right=True)
            errors = _errors(M, left, right) if resolve else None
        kernel, clusters = group(list(lam), float(scale), errors=errors)
    slow = [c for c in clusters if resolve and all(
        abs(lam[i]) <= KERNEL * scale and abs(lam[i]) * horizon <= SLOW for i in c)]
    terms, projector = [], mpmath.zeros(size, size)
    for cluster in (c for c in clusters if c not in slow):
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
    extra = _slow_series(M * Q, Q, len(kernel), horizon if slow else None)
    return ExactForm(form.n, form.powers + tuple(range(len(extra))),
                     form.sigmas + (mpmath.mpf(0),) * len(extra),
                     form.omegas + (mpmath.mpf(0),) * len(extra),
                     form.sine + (False,) * len(extra), form.coefficients + tuple(extra))


def _slow_series(N: mpmath.matrix, Q: mpmath.matrix, kernel: int,
                 horizon: float | None) -> list[mpmath.matrix]:
    """The coefficients (N t)^j / j! Q of exp(N t) Q on the kernel and the
    modes slow beside the phase (N = M Q): the kernel's ``kernel`` terms
    (N nilpotent there), or with slow modes in it (``horizon`` given) as many
    as bring ‖N^j/j! Q‖ T^j below the working digits of the largest, at most
    :data:`SERIES_TERMS` (the phase's residual check judges what is left)."""
    extra, term = [], Q
    if horizon is None:
        for j in range(kernel):
            if j:
                term = N * term / j
            extra.append(term)
        return extra
    tol, peak = mpmath.mpf(10) ** (-mpmath.mp.dps), mpmath.mpf(0)
    for j in range(SERIES_TERMS):
        if j:
            term = N * term / j
        size = mpmath.mnorm(term, "F") * mpmath.mpf(horizon) ** j
        if j >= kernel and size <= tol * peak:
            break
        peak = max(peak, size)
        extra.append(term)
    return extra


@lru_cache(maxsize=256)
def _exact_form_cached(a_key: tuple, b_key: tuple, dps: int,
                       horizon: float | None = None) -> ExactForm:
    with mpmath.workdps(dps):
        if exact_is_cheap(a_key, b_key):            # as the double run takes it
            return _form_jordan(a_key, b_key)
        return _form_eig(a_key, b_key, horizon) or _form_jordan(a_key, b_key)


def precise_closed_form(A: np.ndarray, b: np.ndarray, horizon: float) -> ClosedForm:
    """exp(Mt) at :data:`DPS` digits rounded to double, for a phase at most
    ``horizon`` long: what a double run takes where its own form does not
    solve its equations (time scales 1e7 apart, a free drive beside a stiff
    shaft). The horizon is rounded up to a power of two, so that phases of
    one mode share their form.

    >>> import numpy as np
    >>> form = precise_closed_form(np.array([[0.0, 1.0], [0.0, 0.0]]), np.zeros(2), 1.0)
    >>> [float(v) for v in form.state(2.0, np.array([1.0, 3.0]))]
    [7.0, 3.0]
    """
    A = np.asarray(A, dtype=float)
    bound = 2.0 ** math.ceil(math.log2(max(float(horizon), 2.0 ** -60)))
    return _exact_form_cached(tuple(map(float, A.ravel())), tuple(map(float, np.ravel(b))),
                              DPS, bound).double


use_precise_forms(precise_closed_form)


def exact_form(A: Sequence, b: Sequence) -> ExactForm:
    """exp(Mt) of x' = A x + b in mpmath at the working precision (cached).
    The entries of A and b are taken exactly, as the doubles they are."""
    A = np.asarray(A, dtype=float)
    return _exact_form_cached(tuple(map(float, A.ravel())), tuple(map(float, np.ravel(b))),
                              mpmath.mp.dps)
