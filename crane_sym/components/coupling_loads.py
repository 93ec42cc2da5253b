"""The load of a part that joins several coordinates by its own energies (a
span, :mod:`crane_sym.components.kinds.span`), derived from those energies:

.. math:: F = \\frac{\\partial \\Pi}{\\partial u} + \\frac{\\partial \\Phi}{\\partial \\dot u},

u its stretch, linear in the coordinates. Π and Φ are the part's own share,
written in the coordinates q (and Φ in q̇); as they depend on q only through
u, the chain rule gives ∂Π/∂q_j = F_Π ∂u/∂q_j for every coordinate, so F_Π
is ∂Π/∂q_j over ∂u/∂q_j at any coordinate u moves with, and likewise F_Φ
from q̇_j. A share that does not depend on u alone (∂Π/∂q_k off that
multiple for some k) has no load of u, and is refused. The load is never
written a second time: a kind declares its energies and its stretch only.

>>> import sympy as sp
>>> t, c = sp.Symbol("t"), sp.Symbol("c", positive=True)
>>> a, b = (sp.Function(n)(t) for n in "ab")
>>> load_of((0, c * (b - 2 * a)**2 / 2, 0), b - 2 * a, [a, b], t)
c*(-2*a(t) + b(t))
"""
from __future__ import annotations

from typing import Sequence

import sympy as sp

from crane_sym.components.parts import ComponentError

__all__ = ["load_of"]


def _per_unit(energy: sp.Expr, u: sp.Expr, variables: Sequence[sp.Expr], what: str) -> sp.Expr:
    """∂energy/∂u, from its derivatives along ``variables`` (u's own rates)."""
    slopes = [sp.diff(u, v) for v in variables]
    j = next((k for k, a in enumerate(slopes) if a != 0), None)
    if j is None:
        raise ComponentError(f"{what}: its stretch moves with no coordinate")
    out = sp.factor_terms(sp.expand(sp.diff(energy, variables[j]) / slopes[j]))
    for v, a in zip(variables, slopes):
        if sp.expand(sp.diff(energy, v) - out * a) != 0:
            raise ComponentError(f"{what}: its energy depends on more than its stretch, so "
                                 "it has no load of it")
    return out


def load_of(shares: Sequence[sp.Expr], u: sp.Expr, coordinates: Sequence[sp.Expr],
            t: sp.Symbol, what: str = "coupling") -> sp.Expr:
    """F = ∂Π/∂u + ∂Φ/∂u̇ of a part's share (T, Π, Φ), its stretch ``u``
    (see the module docstring).

    Parameters
    ----------
    shares : (T, Π, Φ)
        The part's own energies in the coordinates.
    u : sympy expression
        Its stretch, linear in the coordinates.
    coordinates : sequence of sympy expressions
        q_g(t) of each group.
    t : Symbol
        Time.
    what : str
        How an error names the part.
    """
    speeds = [q.diff(t) for q in coordinates]
    return (_per_unit(sp.sympify(shares[1]), u, list(coordinates), what)
            + _per_unit(sp.sympify(shares[2]), u.diff(t), speeds, what))
