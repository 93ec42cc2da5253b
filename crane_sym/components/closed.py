"""The closed-form response of a component model that never switches, in its
symbols: two rigid groups joined by one elastic link without backlash, loaded
by constant forces (no brake, no motor switched, no characteristic, no law in
time: a run's phases give those in closed form, numerically).

As the papers do by hand (Komarov's elimination): each equation of motion
solved for its acceleration, their difference written in the link's twist
u = κ_b q_b − κ_a q_a (:func:`crane_sym.mechanics.elimination.relative_coordinate`),

.. math:: \\ddot u + 2n\\dot u + \\Omega^2 u = S,

solved with u(0) = u0, u̇(0) = 0 (:func:`crane_sym.mechanics.odes.solve_constant_coefficient`),
and the link's force F = c u + d u̇. A part whose value is zero (an undamped
link) is dropped before the derivation.
"""
from __future__ import annotations

from dataclasses import dataclass

import sympy as sp

from crane_sym.components import kinds
from crane_sym.components.kinds.base import Acting
from crane_sym.components.model import Model
from crane_sym.components.parts import Component, ComponentError
from crane_sym.mechanics.elimination import RelativeEquation, relative_coordinate
from crane_sym.mechanics.odes import solve_constant_coefficient

__all__ = ["LinkResponse", "acting_parts", "link_response"]


@dataclass(frozen=True)
class LinkResponse:
    """The relative equation of the link, the twist u(t) and the force F(t)."""

    relative: RelativeEquation
    twist: sp.Expr
    force: sp.Expr


def acting_parts(model: Model) -> list[tuple[Component, Acting]]:
    """Each part acting on one body with what its kind says it adds to Q
    (``Kind.acts``), in the assembly's order.

    Parameters
    ----------
    model : Model
        The assembled and derived model.
    """
    a, eq = model.assembly, model.equations
    out = []
    for load in a.loads:
        g, _, kappa = a.place[load.part.body]
        out.append((load.part, kinds.of(load.part).acts(load.part, kappa, eq.coordinates[g])))
    return out


def link_response(model: Model, u0: sp.Expr = sp.Integer(0)) -> LinkResponse:
    """F(t) of the model's one elastic link from twist ``u0`` at rest relative
    to each other (u̇(0) = 0); ComponentError for a model that switches."""
    a, eq = model.assembly, model.equations
    if len(a.groups) != 2 or len(a.links) != 1 or a.links[0].gapped or a.couplings:
        raise ComponentError("a closed form in the symbols needs two rigid groups joined "
                             "by one elastic link without backlash (and no span)")
    # a load that switches (it joins a mode's symbols) or is no constant, but
    # not a part of first order (its states are refused next, by name)
    switching = [part.label for part, acts in acting_parts(model)
                 if (acts.joins or not acts.constant) and not acts.states]
    if switching:
        raise ComponentError(f"a closed form in the symbols needs constant loads; "
                             f"{switching[0]} switches or depends on the speed")
    if eq.states:
        raise ComponentError("a closed form in the symbols needs constant loads; the "
                             f"state {eq.states[0]} of a part is of first order")
    t = eq.t
    link = a.links[0]
    (_, _, ka), (_, _, kb) = (a.place[e] for e in link.part.ends)
    ga, gb = (a.place[e][0] for e in link.part.ends)
    xa, xb = sp.Function("X_a", real=True)(t), sp.Function("X_b", real=True)(t)
    back = {eq.coordinates[ga]: xa / ka, eq.coordinates[gb]: xb / kb}
    # a part given as zero (an undamped link, a shaft without inertia) drops out
    zero = {s: 0 for s, v in eq.values.items() if v == 0}
    eqs = [sp.Eq(e.lhs.xreplace(zero).subs(back).doit(), e.rhs.xreplace(zero))
           for e in eq.lagrange.equations]
    u = sp.Function("u", real=True)(t)
    rel = relative_coordinate(eqs[ga], eqs[gb], xa, xb, u)
    A, B = sp.symbols("A B")
    solved = solve_constant_coefficient(rel.equation, u, (A, B), initial={0: u0, 1: 0})
    c = sp.Symbol(f"c_{link.part.name}", positive=True)
    d = sp.Symbol(f"d_{link.part.name}", nonnegative=True)
    twist = solved.solution
    force = c * twist + d.xreplace(zero) * twist.diff(t)
    return LinkResponse(rel, twist, sp.simplify(force))
