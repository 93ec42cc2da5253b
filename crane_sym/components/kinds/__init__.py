"""The kinds of component, each declared once in its own module: its TOML
table, its keys (form, kind of value, sign, default), how its part is built,
its check against its bodies' motion, its roles and its share of the
equations. Reading a component file, the assembly, the equations, the fields
a design sweep varies, the quantities and the walkthrough's table of
components loop over :data:`KINDS`.

May import: the rest of ``components`` below the reader (``parts``,
``loads``, ``laws``, ``acting``) and the top-level vocabulary; never
``reading``, ``designs`` or what imports them.
"""
from crane_sym.components.kinds import (brake, characteristic, dc_motor, drum, elastic, gear,
                                        gravity, ground_contact, inertia, initial, mass, motor,
                                        motor_law, pendulum, resistance, span, speed_controller)
from crane_sym.components.kinds.base import Key, Kind, has_role

from crane_sym.components.parts import Component

__all__ = ["KINDS", "Key", "Kind", "by_table", "of", "plays"]

#: Every kind, in the order a component file's tables are read.
KINDS: list[Kind] = [k.KIND for k in (inertia, mass, gear, drum, elastic, pendulum, brake,
                                      motor, characteristic, motor_law, dc_motor,
                                      speed_controller, gravity, resistance, initial,
                                      ground_contact, span)]


def by_table() -> dict[str, Kind]:
    """Each kind by its table name, from :data:`KINDS` as it is now."""
    return {k.table: k for k in KINDS}


#: (the list :data:`KINDS` was, its length, each part kind's first kind in
#: it): :func:`of` looks a part's kind up, built anew when KINDS is another list.
_INDEX: tuple[list, int, dict[str, Kind]] = ([], 0, {})


def of(part: Component) -> Kind:
    """The kind of ``part`` (by its ``kind``: ``gear``, ``elastic link``): the
    first of :data:`KINDS` that declares it.

    Parameters
    ----------
    part : Component
        A part of a model.
    """
    global _INDEX
    if _INDEX[0] is not KINDS or _INDEX[1] != len(KINDS):
        _INDEX = (KINDS, len(KINDS), {k.part_kind: k for k in reversed(KINDS)})
    kind = _INDEX[2].get(part.kind)
    if kind is None:
        raise KeyError(f"no kind declares parts of kind {part.kind!r}")
    return kind


def plays(part: Component, role: str) -> bool:
    """Whether ``part`` plays ``role`` (``Kind.roles``: a key of
    :data:`crane_sym.components.kinds.base.ROLE_FLAGS`, e.g. ``holds at rest``).

    Parameters
    ----------
    part : Component
        A part of a model.
    role : str
        The role asked for.
    """
    return has_role(of(part), part, role)
