"""How a kind switches the model: the mode values its parts own, the events
they name, their guards and the rule each event switches by
(:class:`Events`, ``Kind.events``).

The piecewise-linear system (:class:`crane_sym.components.hybrid.ComponentSystem`)
is the generic machinery: it keeps the groups' motion (free, sliding, held)
and loops over the kinds, asking each part's :class:`Events` for its share.
A rule (``rules``) gets the system of one design, the mode, the part's place
among its kind's parts and the state; it reads the mode through
:meth:`Mode.of` and writes it through :meth:`Mode.setting` (a field of
``Mode`` where the kind owns one, else a value of ``Mode.own``), so a new
kind switches without a new field. The hooks the solver asks in every phase
(``guards``, ``friction_capacity``, ``rates``, ``value``) get the designs of
one template at once instead
(:class:`~crane_sym.components.design_arrays.DesignArray`: ``designs.model``
the structure they share, ``designs.gather`` a number of each design) and
answer with a leading axis of designs; one design alone is an array of one.

A guard is ``(event, weights, constant, direction)``: the event happens
where ``weights·x + constant`` crosses 0 the way ``direction`` says (weights
(designs, size) or (size,), constant (designs,) or a number)
(:class:`crane_sym.mechanics.piecewise_linear.Guard`, which the system
builds from it).
"""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any, Callable, Mapping

from crane_sym.components.parts import Component

__all__ = ["BACKWARD", "Events", "FORWARD", "FREE", "GuardSpec", "HELD"]

#: A group's motion: free, sliding forwards or backwards against its brakes, held.
FREE, FORWARD, BACKWARD, HELD = "free", "+", "-", "0"

#: (event, weights over the state, constant, direction): a guard of a mode.
GuardSpec = tuple[str, Any, float, int]

#: An event's rule: (system, mode, the part's place, state) -> (mode, state).
Handler = Callable[[Any, Any, int, Any], tuple[Any, Any]]


def _none(*args) -> tuple:
    return ()


@dataclass(frozen=True)
class Events:
    """The modes and events of a kind's parts.

    ``fields``: the mode's values it owns, one a part each;
    ``start(part, rest)``: each field it owns with the part's value at the
    start (steady, or at ``rest``); ``names(part)``: each event the part
    names with the key of its rule in ``rules``; ``schedule(part, rest)``:
    its events known in advance, (time, event) each (but those a start at
    ``rest`` has already taken); ``guards(designs, mode, i)``:
    its guards in a mode (:data:`GuardSpec`); ``rules``: the handler of each
    event key; ``plain``: the keys of the rules that set the mode from the
    mode alone and leave the state as it is (designs that fire such an event
    in one mode go to one new mode together); ``together``: for a key of
    ``rules``, the same rule for the designs of one template at once,
    ``(designs, mode, i, x (k, size)) -> (modes, x)``, where the new mode
    rests on the state (a brake engaging on a group at rest). The rest are what the generic
    machinery asks of a kind that acts through it:
    ``friction_capacity(designs, mode, i)``, what the part
    can hold of its group's load by friction, (group, column of its own
    state or None, size per design: the capacity is size·x[column], or size
    itself), or None (a kind that gives it plays the role ``holds at rest``);
    ``fixes(system, mode, i)``,
    the group the part itself keeps still (no friction guard for it) or
    None; ``states(part)``, how many states of its own (a brake's build-up)
    and ``rates(designs, mode, i, A, b)``, their rows; ``role`` and
    ``value(designs, mode, i)``, the number its symbol of that role
    (:data:`~crane_sym.components.kinds.base.ROLES`) takes in a mode (a
    motor's switch, a characteristic's slope)."""

    fields: tuple[str, ...]
    start: Callable[[Component, bool], Mapping[str, Any]]
    names: Callable[[Component], tuple[tuple[str, str], ...]]
    rules: Mapping[str, Handler] = field(default_factory=dict)
    plain: frozenset[str] = frozenset()
    together: Mapping[str, Callable] = field(default_factory=dict)
    schedule: Callable[[Component, bool], tuple[tuple[float, str], ...]] = _none
    guards: Callable[[Any, Any, int], tuple[GuardSpec, ...]] = _none
    friction_capacity: Callable[[Any, Any, int], Any] | None = None
    fixes: Callable[[Any, Any, int], int | None] | None = None
    states: Callable[[Component], int] = lambda part: 0
    rates: Callable[[Any, Any, int, Any, Any], None] | None = None
    role: str = ""
    value: Callable[[Any, Any, int], float] | None = None
