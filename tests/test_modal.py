"""crane_sym.mechanics.modal: the chain's relative dynamic matrix and stable 2×2 eigenvalues."""
import mpmath
import numpy as np
import pytest
import sympy as sp

from crane_sym.mechanics.modal import eigenvalues_2x2, relative_dynamic_matrix

I1, I2, I3, C1, C2, lam = sp.symbols("I1 I2 I3 C1 C2 lambda", positive=True)
K = sp.Matrix([[C1, -C1, 0], [-C1, C1 + C2, -C2], [0, -C2, C2]])
M = sp.diag(I1, I2, I3)


def test_eigenvalues_are_the_elastic_roots_of_the_chain():
    A = relative_dynamic_matrix(M, K)
    char = (K - lam * M).det()
    for root in eigenvalues_2x2(A):
        assert sp.simplify(char.subs(lam, root)) == 0


def test_a_held_chain_is_refused():
    with pytest.raises(ValueError, match="free chain"):
        relative_dynamic_matrix(M, K + sp.diag(1, 0, 0))
    with pytest.raises(ValueError, match="2x2"):
        eigenvalues_2x2(sp.eye(3))


def test_nearly_equal_roots_stay_real_where_the_textbook_form_fails():
    """C1/I1 = C2/I3 and a heavy I2: b² − 4c rounds to a negative number."""
    small, large = eigenvalues_2x2(relative_dynamic_matrix(M, K))
    args = (I1, I2, I3, C1, C2)
    stable = sp.lambdify(args, [small, large], "numpy")
    b = sp.factor(small + large)
    c = sp.factor(small * large)
    naive = sp.lambdify(args, [(b - sp.sqrt(b**2 - 4 * c)) / 2,
                               (b + sp.sqrt(b**2 - 4 * c)) / 2], "numpy")
    exact = [sp.lambdify(args, e, "mpmath") for e in (small, large)]
    naive_worst = 0.0
    for heavy in (1e9, 1e10, 1e11, 1e12):
        x = (3.0, heavy, 7.0, 5.0, 5.0 * 7.0 / 3.0)
        with mpmath.workdps(50):
            refs = [f(*(mpmath.mpf(v) for v in x)) for f in exact]
            for value, ref in zip(stable(*x), refs):
                assert abs((value - ref) / ref) < 4e-16
            with np.errstate(invalid="ignore"):
                for value, ref in zip(naive(*x), refs):
                    error = abs((value - ref) / ref) if np.isfinite(value) else mpmath.inf
                    naive_worst = max(naive_worst, error)
    assert naive_worst > 1e-9       # the case is hard: the textbook form fails it

