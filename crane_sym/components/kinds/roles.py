"""What the assembly and the reports ask of a kind beyond its keys and its
share of the equations (the fields :class:`crane_sym.components.kinds.base.Kind`
declares for them): the type of its ``check``, the roles a part may play
(:data:`ROLE_FLAGS`), the quantities its parts report
(:class:`PartQuantity`), and the check of a rigid link's ends.
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Any, Callable, Sequence

import sympy as sp
from sympy.physics.units import Dimension

from crane_sym.components.parts import Component, ComponentError

__all__ = ["ROLE_FLAGS", "Check", "PartQuantity", "ends_moving", "has_role"]

#: A kind's check of a part against the bodies by name and all the components
#: (a speed controller looks up its DC motor): see ``Kind.check``.
Check = Callable[[Component, dict, Sequence[Component]], Any]

#: What a part may declare of itself (``Kind.roles``), and what the assembly
#: then asks (:mod:`crane_sym.components.topology`,
#: :mod:`crane_sym.components.vibration`).
ROLE_FLAGS = {
    "holds at rest": "it may hold its body's rigid group at rest (a brake, a speed law): a "
                     "ground contact takes no such group; a kind whose ``Events`` give a "
                     "``friction_capacity`` plays it without declaring it",
    "sets speed": "it sets its body's speed (a speed law): one to a rigid group, and a mode "
                  "holds that group out of its vibration",
    "slides": "it acts while its body slides (a brake): never where a speed law sets the speed",
    "steady": "its load is solved at the start (a steady motor): one at most",
    "balances": "it balances the other loads at the start (an acceleration law): one at "
                "most, a steady motor counted",
    "rests": "it rests its body's rigid group on the ground (a ground contact)",
}


@dataclass(frozen=True)
class PartQuantity:
    """A quantity a kind's parts report, ``<part>.<name>`` in a [[formula]]:
    what it is (``text``), its dimension and SI unit, how it is derived
    (``how``) and ``derive(part, κ, q, inertia)``, its expression in the
    parts' symbols given its body's κ, its group's coordinate q(t) and the
    inertia of that group referred to the body."""

    name: str
    text: str
    dimension: Dimension
    unit: str
    how: str
    derive: Callable[[Component, sp.Expr, sp.Expr, sp.Expr], sp.Expr]


def has_role(kind: Any, part: Component, role: str) -> bool:
    """Whether ``part`` (of ``kind``) plays ``role`` (a key of :data:`ROLE_FLAGS`):
    it declares it, or, for ``holds at rest``, its kind holds by friction
    (its ``Events`` give a ``friction_capacity``)."""
    if role not in ROLE_FLAGS:
        raise KeyError(f"no role {role!r}; roles: {', '.join(ROLE_FLAGS)}")
    if role == "holds at rest" and kind.events is not None \
            and kind.events.friction_capacity is not None:
        return True
    return kind.roles is not None and role in kind.roles(part)


def ends_moving(part: Component, bodies: dict, want: tuple[str, str], what: str) -> None:
    """Refuse a rigid link whose two ends do not move as ``want`` (rotating,
    translating), in one line saying ``what`` it does.

    Parameters
    ----------
    part : Component
        A rigid link (its ``ends``).
    bodies : dict
        The model's bodies by name.
    want : (str, str)
        The motions of its first and second end.
    what : str
        What it does, as the message says (``joins two rotating bodies``).
    """
    a, b = (bodies[e] for e in part.ends)
    if (a.motion, b.motion) != want:
        raise ComponentError(f"{part.label} {what}; {a.label} is {a.motion}, "
                             f"{b.label} is {b.motion}")
