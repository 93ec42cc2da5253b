"""exp(M t)'s terms from exact spectral projectors (crane_sym.mechanics.rational_projectors)
against mpmath's matrix exponential at 50 digits, on the hard cases a phase meets:
a critically damped pair (a repeated eigenvalue), free bodies (a Jordan block at 0),
an undamped and an overdamped pair, and the route's limits (equal subsystems)."""
from fractions import Fraction

import mpmath
import numpy as np
import pytest

from crane_sym.mechanics import closed_forms
from crane_sym.mechanics.rational_projectors import projector_terms


def _two_masses(k: float, m1: float, m2: float, c: float) -> np.ndarray:
    """Two free masses joined by a spring and a damper: a rigid mode (Jordan block at 0)."""
    return np.array([[0, 0, 1, 0], [0, 0, 0, 1],
                     [-k / m1, k / m1, -c / m1, c / m1], [k / m2, -k / m2, c / m2, -c / m2]])


CASES = {
    "critical damping": (np.array([[0.0, 1.0], [-49.0, -14.0]]), [0.0, 1.0]),
    "undamped pair": (np.array([[0.0, 1.0], [-43840.0, 0.0]]), [0.0, -9.81]),
    "overdamped pair": (np.array([[0.0, 1.0], [-2.0, -7.3]]), [0.5, 0.0]),
    "free bodies, damped": (_two_masses(4.0e6, 12.5, 310.0, 850.0), [0.0, 0.0, 3.1, -0.2]),
    "free bodies, undamped": (_two_masses(4.0e6, 12.5, 310.0, 0.0), [0.0, 0.0, 3.1, -0.2]),
    "one body sliding": (np.array([[0.0, 1.0], [0.0, 0.0]]), [0.0, -2.5]),
    "at rest": (np.zeros((3, 3)), [0.0, 0.0, 0.0]),
}
EQUAL_SUBSYSTEMS = (np.array([[0.0, 1.0, 0.0, 0.0], [-4.0, 0.0, 0.0, 0.0],
                              [0.0, 0.0, 0.0, 1.0], [0.0, 0.0, -4.0, 0.0]]), [0.0, 1.0, 0.0, 1.0])


def _keys(A: np.ndarray, b) -> tuple[tuple, tuple]:
    return tuple(map(float, np.ravel(A))), tuple(map(float, b))


def _exact_exp(A: np.ndarray, b, t: float) -> mpmath.matrix:
    """exp(M t) at 50 digits, M from the floats' shortest decimals as the route reads them."""
    n = len(b)
    with mpmath.workdps(50):
        M = mpmath.zeros(n + 1, n + 1)
        for i in range(n):
            for j in range(n):
                r = Fraction(repr(float(A[i, j])))
                M[i, j] = mpmath.mpf(r.numerator) / r.denominator
            r = Fraction(repr(float(b[i])))
            M[i, n] = mpmath.mpf(r.numerator) / r.denominator
        return mpmath.expm(M * mpmath.mpf(t))


def _terms_at(terms: dict, t: float) -> np.ndarray:
    return sum(C * t ** j * np.exp(lam * t) for (j, lam), C in terms.items()
               if lam.imag >= 0) + sum(np.conj(C) * t ** j * np.exp(np.conj(lam) * t)
                                       for (j, lam), C in terms.items() if lam.imag > 0)


@pytest.mark.parametrize("case", list(CASES))
@pytest.mark.parametrize("t", [0.0, 1e-4, 0.05, 1.0])
def test_terms_are_the_exponential(case, t):
    """Σ C t^j e^{λt} (a conjugate added where a pair is folded) is exp(M t) to
    a few units of rounding, each entry against the largest of its row; the
    phase ωt of a double ω carries |λ|·t units of rounding more."""
    A, b = CASES[case]
    terms = projector_terms(*_keys(A, b))
    assert terms is not None
    got = _terms_at(terms, t).real
    want = np.array(_exact_exp(A, b, t).tolist(), dtype=float)
    scale = np.maximum(np.abs(want).max(axis=1, keepdims=True), 1e-300)
    phase = max(abs(lam) for _, lam in terms) * t
    assert np.max(np.abs(got - want) / scale) < 5e-15 + 2.3e-16 * phase, case


@pytest.mark.parametrize("case", list(CASES))
def test_the_closed_form_takes_it_and_agrees_with_the_jordan_route(case):
    """The double closed form (exact route) now comes from the projectors; SymPy's
    Jordan route, kept for the rest, gives the same exp(M t) to rounding."""
    A, b = CASES[case]
    keys = _keys(A, b)
    form = closed_forms._closed_form_cached(*keys)
    jordan = closed_forms._folded(len(b), closed_forms._jordan_terms(*keys))
    z0 = np.append(np.linspace(0.3, -0.7, len(b)), 1.0)
    for t in (0.0, 0.01, 0.7):
        a, c = form.state(t, z0[:-1]), jordan.state(t, z0[:-1])
        assert np.allclose(a, c, rtol=1e-13, atol=1e-13 * np.abs(c).max(initial=1.0))


def test_a_cubic_factor_is_left_to_the_jordan_route():
    """χ with an irreducible cubic factor (x³ − 2 here) is not this route's: None."""
    A = np.array([[0.0, 1.0, 0.0], [0.0, 0.0, 1.0], [2.0, 0.0, 0.0]])
    assert projector_terms(*_keys(A, [0.0, 0.0, 0.0])) is None


def test_a_repeated_quadratic_factor_is_left_to_the_jordan_route():
    """Equal undamped subsystems have (x² + 4)² in χ: not simple, None."""
    A, b = EQUAL_SUBSYSTEMS
    assert projector_terms(*_keys(A, b)) is None
