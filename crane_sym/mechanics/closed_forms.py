"""One phase of a piecewise-linear system in closed form: x' = A x + b.

Closed form of one phase
------------------------
With z = (x, 1), z' = M z and M = [[A, b], [0, 0]], so z(t) = exp(M t) z(0).
exp(M t) as a sum of terms t^j e^{λt} C, exact where that is cheap (each
entry of A and b taken as the exact rational of its shortest decimal): from
exact spectral projectors where M's characteristic polynomial has linear and
simple quadratic factors only (:mod:`crane_sym.mechanics.rational_projectors`),
else from SymPy's Jordan decomposition M = P J P⁻¹ (P evaluated to 30 digits,
then inverted in floating point); elsewhere from the spectral clusters of M
(:mod:`crane_sym.mechanics.spectral_clusters`: O(n³), exact where
eigenvalues coincide or nearly do):

.. math::

    e^{Mt} = \\sum_{\\text{blocks}} \\sum_j C_{\\lambda, j}\\, \\frac{t^j}{j!} e^{\\lambda t},

and a pair λ = σ ± iω folds into real terms t^j e^{σt} cos ωt and t^j e^{σt} sin ωt
(:class:`ClosedForm`). Rigid-body modes (λ = 0, Jordan blocks) give the
polynomial part (:func:`closed_form`, ``exact``). Evaluation is NumPy.
"""
from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache
from typing import Iterator, Sequence

import numpy as np
import sympy as sp
from sympy.matrices.exceptions import MatrixError

from crane_sym.mechanics.rational_projectors import projector_terms
from crane_sym.mechanics.spectral_clusters import numpy_terms

__all__ = ["ClosedForm", "JordanFormError", "clear_cache", "closed_form", "exact_is_cheap",
           "fold", "jordan", "jordan_blocks"]


class JordanFormError(ValueError):
    """SymPy's exact Jordan form of a phase failed (a ``MatrixError``): one
    line saying so and what to do; the run names the phase
    (:meth:`in_phase`)."""

    def in_phase(self, k: int, t: float) -> "JordanFormError":
        """The same error, naming phase ``k`` of the run, which starts at ``t`` [s]."""
        return JordanFormError(f"phase {k} of the run (from t = {float(t):.6g} s): {self}")


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

    def residual(self, t: float, x0: np.ndarray, A: np.ndarray, b: np.ndarray) -> float:
        """The largest t·|x'(t) − (A x(t) + b)| of the form, each row relative to
        |x_i(t)| + t (Σ_j |A_ij x_j(t)| + |b_i|) (what the row moves over the
        phase): ~eps where the form solves its equations, large where rounding
        grown with t^k (a kernel's series beside a mode 1e7 times faster) has
        spoilt it."""
        z0 = np.append(np.asarray(x0, dtype=float), 1.0)
        vectors = (self.coefficients @ z0)[:, : self.n]
        p, s, w = self.powers, self.sigmas, self.omegas
        tp = t ** p
        low = np.where(p > 0, p * t ** np.maximum(p - 1, 0), 0.0)
        grow = np.exp(s * t)
        wave = np.where(self.sine, np.sin(w * t), np.cos(w * t))
        turn = np.where(self.sine, w * np.cos(w * t), -w * np.sin(w * t))
        beta = tp * grow * wave
        rate = (low + s * tp) * grow * wave + tp * grow * turn
        x, dx = beta @ vectors, rate @ vectors
        A, b = np.asarray(A, float), np.asarray(b, float)
        scale = np.abs(x) + t * (np.abs(A) @ np.abs(x) + np.abs(b))
        # a row that stays ~0 (a held body's speed) is measured against the
        # rows that move: its rounding is no residual
        floor = 1e-6 * float((np.abs(x) + t * np.abs(dx)).max(initial=0.0))
        miss = t * np.abs(dx - (A @ x + b))
        scale = np.maximum(scale, floor)
        with np.errstate(divide="ignore", invalid="ignore"):
            ratio = np.where(scale > 0, miss / scale, np.where(miss > 0, np.inf, 0.0))
        return float(ratio.max(initial=0.0))

    def start_miss(self, t: float, x0: np.ndarray, A: np.ndarray, b: np.ndarray) -> float:
        """The largest |x(0) − x0| of the form, each row relative to what it
        moves over a phase of length ``t``, |x0_i| + t (Σ_j |A_ij x0_j| + |b_i|):
        a form can solve its equations (a small :meth:`residual`) from another
        start, where a term's coefficients ~1/λ of an eigenvalue that is the
        rounding of a zero cancel to nothing in x(0)."""
        x0 = np.asarray(x0, dtype=float)
        A, b = np.asarray(A, float), np.asarray(b, float)
        miss = np.abs(self.state(0.0, x0) - x0)
        scale = np.abs(x0) + t * (np.abs(A) @ np.abs(x0) + np.abs(b))
        scale = np.maximum(scale, 1e-6 * float(scale.max(initial=0.0)))
        with np.errstate(divide="ignore", invalid="ignore"):
            ratio = np.where(scale > 0, miss / scale, np.where(miss > 0, np.inf, 0.0))
        return float(ratio.max(initial=0.0))

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
def jordan(a_key: tuple, b_key: tuple) -> tuple[sp.Matrix, sp.Matrix]:
    """SymPy's exact Jordan decomposition M = P J P⁻¹ of M = [[A, b], [0, 0]],
    each entry taken as the exact rational of the float's shortest decimal
    (cached; the float and the mpmath closed forms share it)."""
    n = len(b_key)
    exact = lambda v: sp.Rational(repr(v))  # noqa: E731  (the float's shortest decimal)
    aug = sp.zeros(n + 1, n + 1)
    aug[:n, :n] = sp.Matrix(n, n, [exact(v) for v in a_key])
    aug[:n, n] = sp.Matrix([exact(v) for v in b_key])
    try:
        return aug.jordan_form()
    except MatrixError as exc:
        said = " ".join(str(exc).split()) or "no reason given"
        raise JordanFormError(f"SymPy's exact Jordan form of its x' = A x + b failed "
                              f"(MatrixError: {said}), so it has no closed form here: "
                              "change a value of the model by a small fraction (its "
                              "eigenvalues nearly coincide), or report the model") from None


def jordan_blocks(J: sp.Matrix) -> Iterator[tuple[int, int]]:
    """(first row, size) of each Jordan block of ``J``."""
    i, size = 0, J.rows
    while i < size:
        k = 1
        while i + k < size and J[i + k - 1, i + k] == 1 and J[i + k, i + k] == J[i, i]:
            k += 1
        yield i, k
        i += k


@lru_cache(maxsize=256)
def _closed_form_cached(a_key: tuple, b_key: tuple) -> ClosedForm:
    n = len(b_key)
    terms = projector_terms(a_key, b_key)
    return _folded(n, _jordan_terms(a_key, b_key) if terms is None else terms)


def _jordan_terms(a_key: tuple, b_key: tuple) -> dict[tuple[int, complex], np.ndarray]:
    """{(j, λ): C} from SymPy's exact Jordan form, P to 30 digits inverted in floats."""
    n = len(b_key)
    P, J = jordan(a_key, b_key)
    Pn = np.array(P.evalf(30).tolist(), dtype=complex)
    Pinv = np.linalg.inv(Pn)
    terms: dict[tuple, np.ndarray] = {}
    size = n + 1
    for i, k in jordan_blocks(J):
        lam = complex(sp.N(J[i, i], 30))
        if abs(lam.imag) <= 1e-20 * (1 + abs(lam)):     # a real root printed with radicals
            lam = complex(lam.real, 0.0)
        if abs(lam.real) <= 1e-20 * (1 + abs(lam)):
            lam = complex(0.0, lam.imag)
        for j in range(k):                            # t^j/j! on the j-th superdiagonal
            E = np.zeros((size, size), dtype=complex)
            for r in range(k - j):
                E[i + r, i + r + j] = 1.0 / float(sp.factorial(j))
            C = Pn @ E @ Pinv
            key = (j, lam)
            terms[key] = terms.get(key, 0) + C
    return terms


def _folded(n: int, terms: dict[tuple[int, complex], np.ndarray]) -> ClosedForm:
    """The real :class:`ClosedForm` of complex terms {(j, λ): C}, a conjugate
    pair folded into cos and sin terms."""
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
        True: the exact form (entries as exact decimals): rational spectral
        projectors where the characteristic polynomial's factors are linear or
        simple quadratics (:mod:`crane_sym.mechanics.rational_projectors`), else
        SymPy's Jordan form, whose cost grows without bound with n and
        near-coinciding eigenvalues (radicals).
        False: the spectral clusters (:mod:`crane_sym.mechanics.spectral_clusters`),
        O(n³), exact where eigenvalues coincide or nearly do. None (the
        default): the exact form where it is cheap (:func:`exact_is_cheap`:
        n ≤ 4, no clusters, factors at most quadratic), the clusters elsewhere.
    """
    A = np.asarray(A, dtype=float)
    key = (tuple(map(float, A.ravel())), tuple(map(float, np.ravel(b))))
    if exact or (exact is None and exact_is_cheap(*key)):
        return _closed_form_cached(*key)
    return _closed_form_numeric(*key)


@lru_cache(maxsize=256)
def exact_is_cheap(a_key: tuple, b_key: tuple) -> bool:
    """Whether the exact form is cheap and adds accuracy: n ≤ 4, no two
    nonzero eigenvalues within a cluster of each other (where exact radicals
    of nearly equal roots grow without bound), and a characteristic
    polynomial whose factors over the rationals are at most quadratic."""
    from crane_sym.mechanics.spectral_clusters import group

    n = len(b_key)
    if n > 4:
        return False
    A = np.reshape(a_key, (n, n))
    lam = np.linalg.eigvals(A)
    _, clusters = group(list(lam), max(float(np.abs(lam).max(initial=0.0)), 1.0))
    if any(len(c) > 1 for c in clusters):
        return False
    exact = sp.Matrix(n, n, [sp.Rational(repr(float(v))) for v in a_key])
    _, factors = sp.factor_list(exact.charpoly().as_expr())
    return all(sp.degree(f) <= 2 for f, _ in factors)


@lru_cache(maxsize=256)
def _closed_form_numeric(a_key: tuple, b_key: tuple) -> ClosedForm:
    """exp(M t) from its spectral clusters (:mod:`crane_sym.mechanics.spectral_clusters`):
    single eigenvalues from their eigenvectors, the kernel's nilpotent series, and
    coinciding or nearly coinciding eigenvalues (critical damping, equal
    subsystems) in closed form from an ordered Schur form's projector."""
    n = len(b_key)
    M = np.zeros((n + 1, n + 1))
    M[:n, :n] = np.reshape(a_key, (n, n))
    M[:n, n] = b_key
    return fold(n, numpy_terms(M))


def fold(n: int, terms: list[tuple[int, complex, np.ndarray]]) -> ClosedForm:
    """The real ClosedForm of Σ t^j e^{λt} C: a pair λ = σ ± iω into cos ωt and
    sin ωt terms (the terms of λ with ω < 0 are their conjugates' and dropped);
    terms of one (j, λ) summed."""
    merged: dict[tuple, np.ndarray] = {}
    for j, lam, C in terms:
        lam = complex(lam)
        if lam.imag < 0:
            continue
        key = (int(j), lam.real, lam.imag)
        merged[key] = merged.get(key, 0) + np.asarray(C, dtype=complex)
    powers, sigmas, omegas, sine, coefs = [], [], [], [], []
    for (j, re, im), C in sorted(merged.items(), key=lambda kv: kv[0]):
        pair = 2.0 if im > 0 else 1.0
        for is_sine, part in ((False, pair * C.real), (True, -pair * C.imag)):
            if im == 0 and is_sine:
                continue
            powers.append(j), sigmas.append(re), omegas.append(im)
            sine.append(is_sine), coefs.append(part)
    return ClosedForm(n, np.array(powers, float), np.array(sigmas), np.array(omegas),
                      np.array(sine, dtype=bool), np.array(coefs))


def clear_cache() -> None:
    """Forget every closed form computed so far (a bench's cold start)."""
    jordan.cache_clear()
    _closed_form_cached.cache_clear()
    _closed_form_numeric.cache_clear()
