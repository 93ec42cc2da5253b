"""Lagrange's equations of the second kind, with Rayleigh dissipation.

SymPy's ``LagrangesMethod`` takes no dissipation function; this builder does:

.. math::

    \\frac{d}{dt}\\frac{\\partial T}{\\partial \\dot q_i}
    - \\frac{\\partial T}{\\partial q_i} + \\frac{\\partial \\Pi}{\\partial q_i}
    + \\frac{\\partial \\Phi}{\\partial \\dot q_i} = Q_i
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Mapping, Sequence

import sympy as sp


@dataclass(frozen=True)
class LagrangeEquations:
    """Equations of motion, one per generalized coordinate.

    ``equations[i]`` reads ``(inertia + elastic + dissipative terms) = Q_i``.
    """

    coordinates: tuple[sp.Expr, ...]
    equations: tuple[sp.Eq, ...]

    def mass_matrix(self) -> sp.Matrix:
        """Coefficients of the second derivatives."""
        t = self.coordinates[0].args[0]
        acc = [q.diff(t, 2) for q in self.coordinates]
        return sp.Matrix([[sp.expand(e.lhs).coeff(a) for a in acc]
                          for e in self.equations])


def lagrange_equations(T: sp.Expr, V: sp.Expr, coordinates: Sequence[sp.Expr],
                       t: sp.Symbol, forces: Mapping[sp.Expr, sp.Expr] | None = None,
                       dissipation: sp.Expr = sp.Integer(0)) -> LagrangeEquations:
    """Equations of motion from kinetic energy ``T``, potential energy ``V``,
    Rayleigh function ``dissipation`` and generalized forces ``forces``.

    Parameters
    ----------
    T, V, dissipation : sympy.Expr
        Energies and the dissipation function, in the coordinates and their
        first derivatives.
    coordinates : sequence of applied functions of ``t``
        The generalized coordinates ``q_i(t)``.
    t : Symbol
        Time.
    forces : mapping coordinate -> expression, optional
        Generalized non-conservative forces ``Q_i`` (virtual work
        ``δA = Σ Q_i δq_i``); missing coordinates get 0.

    Returns
    -------
    LagrangeEquations
    """
    forces = dict(forces or {})
    unknown = set(forces) - set(coordinates)
    if unknown:
        raise ValueError(f"forces given for non-coordinates {sorted(map(str, unknown))}")
    equations = []
    for q in coordinates:
        qd = q.diff(t)
        lhs = (sp.diff(T, qd).diff(t) - sp.diff(T, q) + sp.diff(V, q)
               + sp.diff(dissipation, qd))
        equations.append(sp.Eq(sp.expand(lhs), forces.get(q, sp.Integer(0))))
    return LagrangeEquations(tuple(coordinates), tuple(equations))
