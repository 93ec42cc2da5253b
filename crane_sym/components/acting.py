"""What acts on one body, checked against the body's motion: a part's values
in SI as a :class:`Load` (a torque on a shaft, a force on a mass), and the
checks its kind's ``check`` is made of (each kind of
:mod:`crane_sym.components.kinds` declares its own;
:func:`crane_sym.components.topology.assemble` calls it for each part that
acts on a body). A wrong unit is a one-line ComponentError naming the part,
its unit and the one expected.

May import: ``parts``, ``loads``, ``laws`` and the top-level vocabulary.
"""
from __future__ import annotations

from dataclasses import dataclass

from sympy.physics.units import Dimension

from crane_sym import units
from crane_sym.components.parts import DIMENSIONS, ROTATING, Body, Component, ComponentError

__all__ = ["Load", "body_of", "force_load", "same_unit"]


@dataclass(frozen=True)
class Load:
    """A part acting on one body with its torque or force in SI (None: a steady
    motor, solved at the start, or a part whose force is no constant) and its
    other values in SI (``values``, in the order its kind declares)."""

    part: Component
    load: float | None
    values: tuple[float, ...] = ()


def body_of(part: Component, bodies: dict[str, Body]) -> tuple[Body, str]:
    """The body ``part`` acts on, and how messages name the pair (``brake 'b'
    on inertia 'drum'``).

    Parameters
    ----------
    part : Component
        A part acting on one body (its ``body`` names it).
    bodies : dict
        The model's bodies by name.
    """
    body = bodies[part.body]
    return body, f"{part.label} on {body.label}"


def force_load(part: Component, bodies: dict[str, Body]) -> Load:
    """A part's ``load`` (a brake's, a motor's, a resistance's) as a torque on a
    rotating body or a force on a translating one, in SI.

    Parameters
    ----------
    part : Component
        A part with a ``load`` and the ``body`` it acts on.
    bodies : dict
        The model's bodies by name.
    """
    body, where = body_of(part, bodies)
    word = "torque" if body.motion == ROTATING else "force"
    return Load(part, part.load.check(where, word, DIMENSIONS["load"][body.motion]))


def same_unit(where: str, what: str, unit: str, dimension: Dimension,
              expected: Dimension, example: str = "") -> None:
    """Refuse a unit ``unit`` of ``dimension`` where ``expected`` is due, in
    one line (``<where>: its <what> unit 'kN' is force, expected a speed``);
    ``example`` names the expected dimension instead (``a voltage (e.g. V)``).

    Parameters
    ----------
    where : str
        The part on its body, as messages name it.
    what : str
        What the unit belongs to (``voltage``, ``reference``; "" for the part's own).
    unit : str
        The unit as the file gives it.
    dimension, expected : Dimension
        Its dimension and the one expected.
    example : str
        How the message names the expected dimension (default: described).
    """
    if not units.same_dimension(dimension, expected):
        own = f"its {what} unit" if what else "its unit"
        raise ComponentError(f"{where}: {own} {unit!r} is {units.format_dimension(dimension)}"
                             f", expected {example or units.describe_dimension(expected)}")
