"""Tests for crane_sym.mechanics.variational.

``euler_poisson`` implements the Euler–Poisson sum itself; SymPy's
``euler_equations`` is the independent route it is checked against.
"""
import pytest
import sympy as sp
from sympy.calculus.euler import euler_equations

from crane_sym.mechanics.variational import euler_poisson, solve_boundary_value

t = sp.Symbol("t", real=True)
u = sp.Function("u")(t)
Q = sp.Function("Q")(t)
k, m2, v0, t_n, Omega, a = sp.symbols("k m2 v0 t_n Omega a", positive=True)
D = {j: u.diff(t, j) for j in range(1, 7)}


def _same_equation(left: sp.Eq, right: sp.Eq) -> bool:
    """Two equations ``expr = 0`` are the same up to a constant nonzero factor."""
    ratio = sp.simplify(left.lhs / right.lhs)
    return ratio != 0 and not ratio.has(u, Q) and t not in ratio.free_symbols


def test_second_derivative_squared_gives_fourth_derivative_zero():
    eq = euler_poisson(D[2] ** 2, u, t)
    assert sp.solve(eq, D[4]) == [0]
    assert eq.lhs.atoms(sp.Derivative) == {D[4]}


@pytest.mark.parametrize("L", [
    D[2] ** 2 + k ** 2 * D[1] ** 2,
    D[2] ** 2 + k ** 2 * D[1] ** 2 + t * u ** 2 + sp.sin(t) * u,
    (D[2] - k * D[1]) ** 2 + u * D[1] * t,
    D[3] ** 2 + Q * D[2] ** 2 + sp.exp(-t) * u * D[1],
    sp.cos(u) * D[1] ** 2 + D[2] * D[1] * u,
])
def test_matches_sympy_euler_equations(L):
    mine = euler_poisson(L, u, t)
    (theirs,) = euler_equations(L, u, t)
    assert sp.simplify(mine.lhs - (theirs.lhs - theirs.rhs)) == 0


def test_third_derivative_squared_gives_sixth_derivative_zero():
    assert sp.solve(euler_poisson(D[3] ** 2, u, t), D[6]) == [0]


def test_paper_002_integral_of_squared_dynamic_coefficient():
    # (57)-(58): J = ∫ k_din^2 dt with k_din = (m2 x'' + Q(t)) / (m2 v0 / t_n);
    # the Euler–Poisson equation is (59), m2 x'''' + Q'' = 0.
    k_din = (m2 * D[2] + Q) / (m2 * v0 / t_n)
    eq = euler_poisson(k_din ** 2, u, t)
    printed_59 = sp.Eq(D[4] * m2 + Q.diff(t, 2), 0)
    assert _same_equation(eq, printed_59)
    # With Q'' = 0 it reduces to (60), x'''' = 0.
    assert sp.solve(eq.subs(Q, a * t + 1).doit(), D[4]) == [0]


def test_refuses_non_function_unknown():
    with pytest.raises(TypeError, match="undefined function"):
        euler_poisson(k ** 2, k, t)


def test_boundary_value_solution_satisfies_its_conditions():
    T, v = sp.symbols("T v", positive=True)
    conditions = {(0, 0): 0, (1, 0): 0, (1, T): v, (2, T): 0}
    bv = solve_boundary_value(euler_poisson(D[2] ** 2, u, t), u, t, conditions)
    assert all(r == 0 for r in bv.residuals().values())
    # and independently of residuals(): substitute by hand
    x = bv.solution
    assert sp.simplify(x.diff(t, 4)) == 0
    for (order, point), value in conditions.items():
        assert sp.simplify(x.diff(t, order).subs(t, point) - value) == 0


def test_boundary_value_with_forcing_and_exponentials():
    # (56): x'''' + Ω² x'' = Ω² a, a constant drive acceleration.
    eq = sp.Eq(D[4] + Omega ** 2 * D[2], Omega ** 2 * a)
    bv = solve_boundary_value(eq, u, t, {(0, 0): 0, (1, 0): 0, (2, 0): 0, (3, 0): 0})
    assert all(r == 0 for r in bv.residuals().values())
    eq = sp.Eq(D[4] - k ** 2 * D[2], 0)
    bv = solve_boundary_value(eq, u, t, {(0, 0): 0, (1, 0): 0, (1, 1): 1, (2, 1): 0})
    assert all(r == 0 for r in bv.residuals().values())
    assert len(bv.constants) == 4


def test_boundary_value_validation():
    with pytest.raises(ValueError, match="needs 4 conditions, got 3"):
        solve_boundary_value(sp.Eq(D[4], 0), u, t, {(0, 0): 0, (1, 0): 0, (0, 1): 1})
    with pytest.raises(ValueError, match="order 4 is outside 0..3"):
        solve_boundary_value(sp.Eq(D[4], 0), u, t,
                             {(0, 0): 0, (1, 0): 0, (0, 1): 1, (4, 1): 1})
    with pytest.raises(ValueError, match="not linear"):
        solve_boundary_value(sp.Eq(D[2] + u ** 2, 0), u, t, {(0, 0): 0, (0, 1): 1})
    with pytest.raises(ValueError, match="depends on t"):
        solve_boundary_value(sp.Eq(D[2] + t * u, 0), u, t, {(0, 0): 0, (0, 1): 1})
    with pytest.raises(ValueError, match="do not fix"):
        # u'' = 0 with u'(0) = 0, u'(1) = 1 has no solution
        solve_boundary_value(sp.Eq(D[2], 0), u, t, {(1, 0): 0, (1, 1): 1})
    with pytest.raises(ValueError, match="do not fix"):
        # u'' + π² u = 0 with u(0) = 0, u(1) = 0: a whole family
        solve_boundary_value(sp.Eq(D[2] + sp.pi ** 2 * u, 0), u, t, {(0, 0): 0, (0, 1): 0})
    with pytest.raises(TypeError):
        solve_boundary_value(sp.Eq(D[2], 0), u, t, {(0, 0): 0, (0, 1): "1"})
