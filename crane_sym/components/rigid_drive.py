"""The force that drives a drive were it rigid: what an acceleration law
(``[[motor_law]] law = "acceleration"``) puts on its body, P = J_red a − Σ ρ F,
the drive's inertia and its constant loads referred to that body by virtual
work along the elastic links' chain (:func:`rigid_drive_force`), which
:func:`crane_sym.components.equations.derive` adds to the body's Q.
"""
from __future__ import annotations

import sympy as sp

from crane_sym.components.parts import Body
from crane_sym.components.topology import Assembly

__all__ = ["inertia_symbol", "rigid_drive_force"]


def inertia_symbol(body: Body) -> sp.Symbol:
    """A body's inertia symbol, J_<name> where it rotates and m_<name> where it
    moves along a line: the one name T and the rigid drive's J_red share."""
    return sp.Symbol(f"{'J' if body.motion == 'rotating' else 'm'}_{body.name}", positive=True)


def rigid_drive_force(assembly: Assembly, where: dict[str, tuple[sp.Expr, sp.Expr]],
                      body: str, a_law: sp.Symbol, acting: list[tuple[str, sp.Expr]]) -> sp.Expr:
    """P = J_red a − Σ ρ_b F_b: the force on ``body`` that drives the drive, were it
    rigid, at the acceleration ``a_law`` of ``body`` against the loads ``acting``
    (the weights, resistances and motors: the loads constant in time).

    Rigid, every elastic link keeps its twist: κ_b q̇_b = κ_a q̇_a, so group g
    moves ρ_g per unit of the body's coordinate y (ρ = 1/κ on its own group),
    body b moves κ_b ρ_g; virtual work refers its inertia and load to y."""
    place = assembly.place
    rho = {place[body][0]: 1 / where[body][0]}
    todo = [place[body][0]]
    while todo:
        here = todo.pop(0)
        for link in assembly.links:
            ends = assembly.ends(link)
            for near, far in (ends, ends[::-1]):
                if near.group == here and far.group is not None and far.group not in rho:
                    rho[far.group] = rho[here] * near.factor / far.factor
                    todo.append(far.group)
    J = sp.Integer(0)
    for g, group in enumerate(assembly.groups):
        for (member, _), kappa in zip(group.members, group.factors):
            J += inertia_symbol(member) * (kappa * rho[g]) ** 2
    held = sum((where[b][0] * rho[place[b][0]] * F for b, F in acting), sp.Integer(0))
    return sp.expand(J * a_law - held)
