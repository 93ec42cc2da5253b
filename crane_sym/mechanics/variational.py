"""Extremals of functionals with higher derivatives (Chovnyuk et al., eqs (58)–(61)).

For :math:`J[u] = \\int L(t, u, \\dot u, \\dots, u^{(n)})\\,dt` the
Euler–Poisson equation is

.. math::

    \\sum_{k=0}^{n} (-1)^k \\frac{d^k}{dt^k}
    \\frac{\\partial L}{\\partial u^{(k)}} = 0 .

``euler_poisson`` builds it from this formula (the tests cross-check it with
``sympy.calculus.euler.euler_equations``); ``solve_boundary_value`` solves
the linear constant-coefficient equations that result, with conditions at
several points, e.g. :math:`u^{(IV)} = 0` with the drive's start and end states.
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Mapping

import sympy as sp

from crane_sym.mechanics.loads import as_expression


def _derivatives(expr: sp.Expr, u: sp.Expr, t: sp.Symbol) -> dict[int, sp.Expr]:
    """``{k: u^(k)}`` for every derivative of ``u`` in ``expr``, and ``{0: u}``."""
    found = {0: u}
    for d in expr.atoms(sp.Derivative):
        if d.expr == u and set(d.variables) == {t}:
            found[len(d.variables)] = d
    return found


def _check_unknown(u: sp.Expr, t: sp.Symbol) -> None:
    if not (isinstance(u, sp.core.function.AppliedUndef) and u.args == (t,)):
        raise TypeError(f"u must be an undefined function applied to {t}, e.g. "
                        f"Function('u')({t}); got {u}")


def euler_poisson(L: sp.Expr, u: sp.Expr, t: sp.Symbol) -> sp.Eq:
    """Euler–Poisson equation of :math:`\\int L\\,dt` for one function ``u(t)``.

    .. math::

        \\sum_{k=0}^{n} (-1)^k \\frac{d^k}{dt^k}
        \\frac{\\partial L}{\\partial u^{(k)}} = 0

    The partial derivatives treat :math:`u, \\dot u, \\dots, u^{(n)}` as
    independent variables; the total derivatives act on everything,
    including given functions of time such as :math:`Q(t)` (Chovnyuk et al.,
    (58) -> (59)).

    Parameters
    ----------
    L : sympy.Expr
        The Lagrangian, in ``t``, ``u(t)`` and its derivatives.
    u : applied function
        The unknown, e.g. ``Function('u')(t)``.
    t : Symbol
        The independent variable.

    Returns
    -------
    sympy.Eq
        ``Eq(expanded left-hand side, 0)``.
    """
    _check_unknown(u, t)
    derivs = _derivatives(L, u, t)
    # Freeze u^(k) as plain symbols, highest order first, so that d/du does not
    # see u inside u'.
    frozen = {k: sp.Dummy(f"u{k}") for k in derivs}
    plain = L
    for k in sorted(derivs, reverse=True):
        plain = plain.subs(derivs[k], frozen[k])
    if plain.has(u):
        raise ValueError(f"L contains {u} in a form other than its derivatives in {t}")
    thaw = {frozen[k]: derivs[k] for k in derivs}
    total = sp.Integer(0)
    for k in sorted(derivs):
        partial = sp.diff(plain, frozen[k]).xreplace(thaw)
        total += (-1) ** k * sp.diff(partial, t, k)
    return sp.Eq(sp.expand(total), 0)


def _check_linear(equation: sp.Eq, u: sp.Expr, t: sp.Symbol) -> int:
    """Order of ``equation``; raises unless it is linear in ``u`` and its
    derivatives with coefficients free of ``t``."""
    residual = equation.lhs - equation.rhs
    derivs = _derivatives(residual, u, t)
    frozen = {k: sp.Dummy(f"u{k}") for k in derivs}
    plain = residual
    for k in sorted(derivs, reverse=True):
        plain = plain.subs(derivs[k], frozen[k])
    variables = list(frozen.values())
    poly = sp.Poly(sp.expand(plain), *variables) if variables else None
    if poly is None or poly.total_degree() > 1:
        raise ValueError(f"the equation is not linear in {u} and its derivatives")
    for k, var in frozen.items():
        if t in poly.coeff_monomial(var).free_symbols:
            raise ValueError(f"the coefficient of the derivative of order {k} depends on {t}")
    order = max((k for k, var in frozen.items() if poly.coeff_monomial(var) != 0),
                default=0)
    if order == 0:
        raise ValueError(f"the equation contains no derivative of {u}")
    return order


@dataclass(frozen=True)
class BoundaryValueSolution:
    """Solution of a linear ODE with conditions at several points.

    Attributes
    ----------
    equation : sympy.Eq
    u : applied function
    t : Symbol
    conditions : mapping ``(order, point) -> value``
    general : sympy.Expr
        The general solution with the integration constants ``constants``.
    constants : tuple of Symbol
    values : mapping constant -> expression
        The constants fixed by the conditions.
    """

    equation: sp.Eq
    u: sp.Expr
    t: sp.Symbol
    conditions: Mapping[tuple[int, sp.Expr], sp.Expr]
    general: sp.Expr
    constants: tuple[sp.Symbol, ...]
    values: Mapping[sp.Symbol, sp.Expr]

    @property
    def solution(self) -> sp.Expr:
        """The general solution with the constants fixed."""
        return self.general.xreplace(dict(self.values))

    def residuals(self) -> dict[str, sp.Expr]:
        """Simplified residuals of the equation and of each condition (all 0)."""
        def simplified(expr: sp.Expr) -> sp.Expr:
            once = sp.simplify(expr)
            return once if once == 0 else sp.simplify(once.rewrite(sp.exp))

        eq = self.equation.lhs - self.equation.rhs
        out = {"equation": simplified(eq.subs(self.u, self.solution).doit())}
        for (order, point), value in self.conditions.items():
            got = self.solution.diff(self.t, order).subs(self.t, point)
            out[f"u^({order})({point})"] = simplified(got - value)
        return out


def solve_boundary_value(equation: sp.Eq, u: sp.Expr, t: sp.Symbol,
                         conditions: Mapping[tuple[int, object], object]
                         ) -> BoundaryValueSolution:
    """Solve a linear constant-coefficient ODE of order :math:`n` with
    :math:`n` conditions :math:`u^{(k)}(t_j) = c_{kj}`.

    Parameters
    ----------
    equation : sympy.Eq
        Linear in ``u`` and its derivatives with constant coefficients (the
        right-hand side may depend on ``t``), e.g. :math:`u^{(IV)} = 0`.
    u : applied function
    t : Symbol
    conditions : mapping ``(order, point) -> value``
        E.g. ``{(0, 0): 0, (1, 0): 0, (1, T): v, (2, T): 0}``;
        ``0 <= order < n``, exactly ``n`` entries.

    Raises
    ------
    ValueError
        When the equation is not linear with constant coefficients, the
        number of conditions is not its order, or the conditions do not fix
        the constants.
    """
    _check_unknown(u, t)
    order = _check_linear(equation, u, t)
    fixed = {}
    for key, value in conditions.items():
        if not (isinstance(key, tuple) and len(key) == 2 and isinstance(key[0], int)
                and not isinstance(key[0], bool)):
            raise TypeError(f"condition keys are (order, point) pairs, got {key!r}")
        k, point = key
        if not 0 <= k < order:
            raise ValueError(f"condition order {k} is outside 0..{order - 1}")
        fixed[(k, as_expression(point, "point"))] = as_expression(value, f"u^({k})")
    if len(fixed) != order:
        raise ValueError(f"an equation of order {order} needs {order} conditions, "
                         f"got {len(fixed)}")
    general = sp.dsolve(equation, u).rhs
    known = equation.free_symbols | {t}
    for key, value in fixed.items():
        known |= key[1].free_symbols | value.free_symbols
    constants = tuple(sorted(general.free_symbols - known, key=str))
    if len(constants) != order:
        raise ValueError(f"dsolve gave constants {constants}, expected {order}")
    system = [general.diff(t, k).subs(t, point) - value
              for (k, point), value in fixed.items()]
    solutions = sp.linsolve(system, constants)
    if len(solutions) != 1:
        raise ValueError("the conditions do not fix the constants: no solution")
    (values,) = solutions
    free = set().union(*(v.free_symbols for v in values)) & set(constants)
    if free:
        raise ValueError(f"the conditions do not fix the constants {sorted(map(str, free))}")
    return BoundaryValueSolution(equation, u, t, fixed, general, constants,
                                 {c: sp.simplify(v) for c, v in zip(constants, values)})
