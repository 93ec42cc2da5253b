"""Elimination of a two-mass system to its relative coordinate (Komarov).

Each equation of motion is solved for its mass's acceleration; their
difference, written in ``u = x2 - x1``, must no longer contain ``x1``. The
result is the single equation

.. math:: \\ddot u + 2n\\dot u + \\Omega^2 u = S(t).
"""
from __future__ import annotations

from dataclasses import dataclass

import sympy as sp


@dataclass(frozen=True)
class RelativeEquation:
    """``u'' + damping*u' + omega2*u = forcing`` in ``u = x2 - x1``."""

    u: sp.Expr
    omega2: sp.Expr
    damping: sp.Expr
    forcing: sp.Expr

    @property
    def n(self) -> sp.Expr:
        """Half the coefficient of u' (the ``damping`` of ``crane_sym.mechanics.duhamel``)."""
        return self.damping / 2

    @property
    def equation(self) -> sp.Eq:
        t = self.u.args[0]
        return sp.Eq(self.u.diff(t, 2) + self.damping * self.u.diff(t)
                     + self.omega2 * self.u, self.forcing)

    def in_coordinates(self, x1: sp.Expr, x2: sp.Expr) -> sp.Eq:
        """The equation with ``u`` written out as ``x2 - x1``."""
        return self.equation.subs(self.u, x2 - x1).doit()


def relative_coordinate(eq1: sp.Eq, eq2: sp.Eq, x1: sp.Expr, x2: sp.Expr,
                        u: sp.Expr) -> RelativeEquation:
    """Reduce the equations of motion of two masses to one equation in ``u``.

    Raises ``ValueError`` when the difference of the accelerations still
    depends on the absolute coordinates (the system does not decouple).

    Parameters
    ----------
    eq1, eq2 : sympy.Eq
        The equations of motion of the two masses.
    x1, x2 : applied functions of t
        Their coordinates.
    u : applied function of t
        The relative coordinate to introduce.
    """
    t = x1.args[0]
    a1 = sp.solve(eq1, x1.diff(t, 2), dict=True)
    a2 = sp.solve(eq2, x2.diff(t, 2), dict=True)
    if len(a1) != 1 or len(a2) != 1:
        raise ValueError("each equation must be linear in its own acceleration")
    rel = a2[0][x2.diff(t, 2)] - a1[0][x1.diff(t, 2)]
    rel = sp.expand(rel.subs(x2, x1 + u).doit())
    if rel.has(x1):
        raise ValueError(f"x1 does not cancel from the relative equation: {rel}")
    ud, uu = sp.Dummy("ud"), sp.Dummy("u")
    frozen = rel.subs(u.diff(t), ud).subs(u, uu)
    damping = -frozen.coeff(ud)
    omega2 = -frozen.coeff(uu)
    forcing = sp.expand(frozen + damping * ud + omega2 * uu)
    if forcing.has(ud, uu):
        raise ValueError("the relative equation is not linear in u")
    return RelativeEquation(u, sp.factor(omega2), sp.factor(damping),
                            sp.simplify(forcing))
