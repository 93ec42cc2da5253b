"""The numeric witness that spares ``simplify``: it says an expression is not 0
only where it truly is not, at a point its symbols' assumptions allow, and
stays silent on every identity, whatever functions and integrals it holds."""
from __future__ import annotations

import sympy as sp

from crane_sym.audit.checks import numerically_nonzero

t, omega = sp.symbols("t Omega", positive=True)
a = sp.Symbol("a")                                  # no assumption: complex
theta = sp.Dummy("theta")
S, Y = sp.Function("S"), sp.Function("Y")
X = sp.Function("X", positive=True)


def _duhamel(f: sp.Expr) -> sp.Integral:
    return sp.Integral(f, (theta, 0, t))


def test_identities_are_never_called_nonzero():
    identities = [
        sp.sin(t)**2 + sp.cos(t)**2 - 1,
        sp.exp(60) * (t + 1) - sp.exp(60) * t - sp.exp(60),        # cancellation at 1e26
        sp.sqrt(X(t)**2) - X(t),                                    # X declared positive
        _duhamel(S(theta) * sp.sin(omega * (t - theta)))           # θ -> t - θ
        - _duhamel(S(t - theta) * sp.sin(omega * theta)),
        sp.Derivative(Y(t), t) - sp.Derivative(Y(t), t),
    ]
    assert [numerically_nonzero(e) for e in identities] == [False] * len(identities)


def test_differences_are_found():
    found = [
        t - omega,
        sp.sqrt(a**2) - a,                  # not 0 for a negative a, which a may be
        2 * _duhamel(S(theta) * sp.sin(omega * (t - theta)))
        - _duhamel(S(t - theta) * sp.sin(omega * theta)),
        sp.Derivative(Y(t), t) - 2 * sp.Derivative(Y(t), t),
    ]
    assert [numerically_nonzero(e) for e in found] == [True] * len(found)


def test_what_numbers_cannot_tell_is_left_to_simplify():
    n = sp.Symbol("n", integer=True)
    unknowable = [
        sp.Derivative(Y(t)**2, t) - 2 * Y(t) * sp.Derivative(Y(t), t),   # not a bare function
        sp.cos(sp.pi * n) - 1,                                          # n an integer
        sp.Sum(t**n, (n, 0, 3)) - 1,
    ]
    assert [numerically_nonzero(e) for e in unknowable] == [False] * len(unknowable)
