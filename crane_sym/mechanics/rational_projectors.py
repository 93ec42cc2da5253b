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
from math import factorial, gcd

import mpmath
import numpy as np
import sympy as sp

__all__ = ["projector_terms"]

#: A rational matrix as exact integers over one common denominator (object
#: arrays of Python ints: no gcd at each product, as Fractions would take).
Rational = tuple[np.ndarray, int]


def projector_terms(a_key: tuple, b_key: tuple) -> dict[tuple[int, complex], np.ndarray] | None:
    """{(j, λ): C_{λ,j}} of exp(M t) = Σ C_{λ,j} t^j e^{λt} for M = [[A, b], [0, 0]]
    (entries the exact rationals of the floats' shortest decimals), or None where
    χ(M) has a factor of degree above 2 or a repeated quadratic factor."""
    n = len(b_key)
    exact = [[Fraction(repr(v)) for v in a_key[i * n:(i + 1) * n]] + [Fraction(repr(b_key[i]))]
             for i in range(n)] + [[Fraction(0)] * (n + 1)]
    x = sp.Symbol("x")
    chi = sp.Poly(sp.Matrix(exact).charpoly(x).as_expr(), x, domain="QQ")
    _, factors = chi.factor_list()
    if any(f.degree() > 2 or (f.degree() == 2 and m > 1) for f, m in factors):
        return None
    M = _integers(exact)
    terms: dict[tuple[int, complex], np.ndarray] = {}
    for f, m in factors:
        rest = sp.Poly(1, x, domain="QQ")
        for g, k in factors:
            if g != f:
                rest *= g ** k
        _, t, one = sp.gcdex(f ** m, rest)
        assert one == 1                       # coprime factors
        Pi = _poly_at(t * rest, M)
        if f.degree() == 1:
            lam = -_fraction(f.monic().all_coeffs()[1])
            N = _plus_identity(M, -lam)
            C, j = Pi, 0
            while j < m and C[0].any():
                terms[(j, complex(float(lam)))] = _doubles(C, Fraction(1, factorial(j)))
                C, j = _matmul(N, C), j + 1
        else:
            terms.update(_pair_terms(f, Pi, M))
    return terms


def _pair_terms(f: sp.Poly, Pi: Rational, M: Rational) -> dict[tuple[int, complex], np.ndarray]:
    """C_{λ,0} of the roots of the irreducible quadratic ``f`` (the upper one of a
    complex pair only: its conjugate folds into it)."""
    _, p, q = (_fraction(c) for c in f.monic().all_coeffs())
    PiM = _matmul(Pi, M)
    with mpmath.workprec(160):
        mp = lambda num, den: mpmath.mpf(int(num)) / int(den)  # noqa: E731
        disc = mp((p * p - 4 * q).numerator, (p * p - 4 * q).denominator)
        half = mp(-p.numerator, 2 * p.denominator)
        if disc < 0:
            pairs = [(mpmath.mpc(half, mpmath.sqrt(-disc) / 2),
                      mpmath.mpc(half, -mpmath.sqrt(-disc) / 2))]
        else:
            r1, r2 = half + mpmath.sqrt(disc) / 2, half - mpmath.sqrt(disc) / 2
            pairs = [(r1, r2), (r2, r1)]
        out = {}
        for lam, mu in pairs:                 # Π (M − μ)/(λ − μ)
            C = [[complex((mp(a, PiM[1]) - mu * mp(b, Pi[1])) / (lam - mu))
                  for a, b in zip(ra, rb)] for ra, rb in zip(PiM[0], Pi[0])]
            out[(0, complex(lam))] = np.array(C)
    return out


def _fraction(c) -> Fraction:
    return Fraction(int(c.numerator), int(c.denominator))


def _integers(rows: list[list[Fraction]]) -> Rational:
    den = 1
    for v in (v for row in rows for v in row):
        den = den * v.denominator // gcd(den, v.denominator)
    return np.array([[int(v * den) for v in row] for row in rows], dtype=object), den


def _matmul(X: Rational, Y: Rational) -> Rational:
    return X[0].dot(Y[0]), X[1] * Y[1]


def _plus_identity(X: Rational, c: Fraction) -> Rational:
    """X + c·I."""
    out = X[0] * c.denominator
    for i in range(len(out)):
        out[i, i] += c.numerator * X[1]
    return out, X[1] * c.denominator


def _poly_at(poly: sp.Poly, M: Rational) -> Rational:
    """poly(M) by Horner's rule, in exact rationals."""
    size = len(M[0])
    out: Rational = (np.zeros((size, size), dtype=object), 1)
    for c in poly.all_coeffs():
        out = _plus_identity(_matmul(out, M), _fraction(c))
    return out


def _doubles(C: Rational, scale: Fraction) -> np.ndarray:
    """The exact ``scale·C`` rounded once to doubles (complex, as the terms are)."""
    return np.array([[complex(float(Fraction(int(v), C[1]) * scale)) for v in row]
                     for row in C[0]])
