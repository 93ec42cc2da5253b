"""Linear ordinary differential equations with constant coefficients.

``solve_constant_coefficient`` returns the general solution with integration
constants named by the caller (the paper's ``A``, ``B``), the particular
solution and the constants fixed by initial conditions.
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Mapping, Sequence

import sympy as sp


@dataclass(frozen=True)
class ODESolution:
    """Solution of ``L[u] = f`` with named constants."""

    u: sp.Expr
    basis: tuple[sp.Expr, ...]
    constants: tuple[sp.Symbol, ...]
    particular: sp.Expr
    constant_values: Mapping[sp.Symbol, sp.Expr]

    @property
    def general(self) -> sp.Expr:
        """``Σ C_k basis_k + particular``."""
        return sum((c * b for c, b in zip(self.constants, self.basis)),
                   sp.Integer(0)) + self.particular

    @property
    def solution(self) -> sp.Expr:
        """The general solution with the initial conditions applied."""
        return self.general.xreplace(dict(self.constant_values))


def solve_constant_coefficient(equation: sp.Eq, u: sp.Expr,
                               constants: Sequence[sp.Symbol],
                               initial: Mapping[int, sp.Expr] | None = None,
                               t0: sp.Expr = sp.Integer(0)) -> ODESolution:
    """Solve a linear constant-coefficient ODE for ``u(t)``.

    Parameters
    ----------
    equation : sympy.Eq
        Linear in ``u`` and its derivatives, constant coefficients.
    u : applied function of ``t``
    constants : sequence of Symbol
        Names for the integration constants, matched to the basis functions
        in a fixed order: the one equal to 1 at ``t0`` (cos, cosh) first.
    initial : mapping derivative order -> value at ``t0``, optional
        E.g. ``{0: 0, 1: 0}`` for ``u(t0) = 0, u'(t0) = 0``.
    t0 : sympy.Expr, optional
        The instant the initial values hold at.
    """
    t = u.args[0]
    general = sp.dsolve(equation, u).rhs
    raw = sorted(general.free_symbols - equation.free_symbols - {t}, key=str)
    if len(raw) != len(constants):
        raise ValueError(f"expected {len(constants)} constants, dsolve gave {raw}")
    particular = sp.simplify(general.subs({c: 0 for c in raw}))
    basis = [sp.simplify(general.diff(c)) for c in raw]
    basis.sort(key=lambda b: (sp.simplify(b.subs(t, t0) - 1) != 0, sp.srepr(b)))
    solution = ODESolution(u, tuple(basis), tuple(constants), particular, {})
    if not initial:
        return solution
    conditions = [sp.Eq(solution.general.diff(t, k).subs(t, t0), v)
                  for k, v in sorted(initial.items())]
    values = sp.solve(conditions, list(constants), dict=True)
    if len(values) != 1:
        raise ValueError(f"initial conditions do not fix the constants: {values}")
    fixed = {c: sp.simplify(v) for c, v in values[0].items()}
    return ODESolution(u, tuple(basis), tuple(constants), particular, fixed)
