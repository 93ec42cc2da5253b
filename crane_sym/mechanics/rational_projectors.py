"""exp(M t)'s terms from exact spectral projectors, where M's characteristic
polynomial factors over the rationals into linear and simple quadratic factors.

For χ(x) = Π f_k(x)^{m_k}, with the f_k coprime, the projector onto the
generalized eigenspace of f_k is a polynomial in M,

.. math::

    Π_k = (t_k g_k)(M),\\quad g_k = χ / f_k^{m_k},\\quad
    s_k f_k^{m_k} + t_k g_k = 1 \\ (\\text{Bézout over } \\mathbb{Q}),

exact in rationals and with no basis of eigenvectors. Then

- f_k = x − λ (any m_k): C_{λ,j} = (M − λ)^j Π_k / j! for j < m_k, while nonzero;
- f_k quadratic with m_k = 1, roots λ1 ≠ λ2: C_{λ1,0} = Π_k (M − λ2) / (λ1 − λ2).

Each entry is rounded once to a double: the rationals exactly, the quadratics'
roots through mpmath at 160 bits. No floating-point library takes part, so the
terms are the same on every machine, and far cheaper than SymPy's Jordan form
with radicals (:func:`crane_sym.mechanics.closed_forms.jordan`), which stays the
route for anything else.
"""
from __future__ import annotations

from fractions import Fraction
from math import factorial

import mpmath
import numpy as np
import sympy as sp

__all__ = ["projector_terms"]

Matrix = list[list[Fraction]]


def projector_terms(a_key: tuple, b_key: tuple) -> dict[tuple[int, complex], np.ndarray] | None:
    """{(j, λ): C_{λ,j}} of exp(M t) = Σ C_{λ,j} t^j e^{λt} for M = [[A, b], [0, 0]]
    (entries the exact rationals of the floats' shortest decimals), or None where
    χ(M) has a factor of degree above 2 or a repeated quadratic factor."""
    n = len(b_key)
    M = [[Fraction(repr(v)) for v in a_key[i * n:(i + 1) * n]] + [Fraction(repr(b_key[i]))]
         for i in range(n)] + [[Fraction(0)] * (n + 1)]
    x = sp.Symbol("x")
    chi = sp.Poly(sp.Matrix(M).charpoly(x).as_expr(), x, domain="QQ")
    _, factors = chi.factor_list()
    if any(f.degree() > 2 or (f.degree() == 2 and m > 1) for f, m in factors):
        return None
    terms: dict[tuple[int, complex], np.ndarray] = {}
    for f, m in factors:
        power = f ** m
        rest = sp.Poly(1, x, domain="QQ")
        for g, k in factors:
            if g != f:
                rest *= g ** k
        _, t, one = sp.gcdex(power, rest)
        assert one == 1                       # coprime factors
        Pi = _poly_at(t * rest, M)
        if f.degree() == 1:
            lam = -_fraction(f.monic().all_coeffs()[1])
            N = _shifted(M, lam)
            C, j = Pi, 0
            while j < m and any(any(row) for row in C):
                terms[(j, complex(float(lam)))] = _doubles(C, Fraction(1, factorial(j)))
                C, j = _matmul(N, C), j + 1
        else:
            terms.update(_pair_terms(f, Pi, M))
    return terms


def _pair_terms(f: sp.Poly, Pi: Matrix, M: Matrix) -> dict[tuple[int, complex], np.ndarray]:
    """C_{λ,0} of the roots of the irreducible quadratic ``f`` (the upper one of a
    complex pair only: its conjugate folds into it)."""
    _, p, q = (_fraction(c) for c in f.monic().all_coeffs())
    PiM = _matmul(Pi, M)
    with mpmath.workprec(160):
        mp = lambda r: mpmath.mpf(r.numerator) / r.denominator  # noqa: E731
        disc = mp(p * p - 4 * q)
        half = mp(-p) / 2
        if disc < 0:
            roots = [mpmath.mpc(half, mpmath.sqrt(-disc) / 2)]
            other = lambda lam: mpmath.conj(lam)  # noqa: E731
        else:
            roots = [half + mpmath.sqrt(disc) / 2, half - mpmath.sqrt(disc) / 2]
            other = lambda lam: roots[1] if lam == roots[0] else roots[0]  # noqa: E731
        out = {}
        for lam in roots:
            mu = other(lam)
            C = np.array([[complex((mp(a) - mu * mp(b)) / (lam - mu)) for a, b in zip(ra, rb)]
                          for ra, rb in zip(PiM, Pi)])
            out[(0, complex(lam))] = C
    return out


def _fraction(c) -> Fraction:
    return Fraction(int(c.numerator), int(c.denominator))


def _matmul(X: Matrix, Y: Matrix) -> Matrix:
    cols = list(zip(*Y))
    return [[sum((a * b for a, b in zip(row, col)), Fraction(0)) for col in cols] for row in X]


def _shifted(M: Matrix, lam: Fraction) -> Matrix:
    return [[v - lam if i == j else v for j, v in enumerate(row)] for i, row in enumerate(M)]


def _poly_at(poly: sp.Poly, M: Matrix) -> Matrix:
    """poly(M) by Horner's rule, in exact rationals."""
    size = len(M)
    out: Matrix = [[Fraction(0)] * size for _ in range(size)]
    for c in poly.all_coeffs():
        out = _matmul(out, M)
        c = _fraction(c)
        for i in range(size):
            out[i][i] += c
    return out


def _doubles(C: Matrix, scale: Fraction) -> np.ndarray:
    """The exact ``scale·C`` rounded once to doubles (complex, as the terms are)."""
    return np.array([[complex(float(v * scale)) for v in row] for row in C])
