"""The tables of a :class:`~crane_sym.components.hybrid.ComponentSystem` that
rest on its model's structure alone (:class:`Layout`): which parts are of
which kind, which kinds switch, the columns of the parts' own states, the
events of the groups and the rule of each part's event.

The designs of a sweep share their template's equations
(:meth:`~crane_sym.components.equations.Equations.for_design`), and with
them its layouts (``Equations.layouts``): a design's system looks its
layout up by what the tables are built from (the parts' kinds, the groups,
each switching part's event names and count of own states) and builds
only what rests on its values (the laws, κ, the numbers of its modes).
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Callable

from crane_sym.components import kinds
from crane_sym.components.equations import Equations
from crane_sym.components.kinds.events import Events
from crane_sym.components.topology import Assembly

__all__ = ["Layout", "layout"]


@dataclass(frozen=True)
class Layout:
    """What a system's tables are, by structure.

    ``of_kind``: each kind's table -> the places of its parts among the
    assembly's (loads, contacts, links), in the order given; ``switching``:
    (events, table) of each kind that switches, in the order of
    :data:`~crane_sym.components.kinds.KINDS`; ``columns``: (table, place)
    -> the column of a part's own state after the groups' 2 n;
    ``events``: each group's event -> (kind, group); ``rules``: each part's
    event -> (its rule, the part's place among its kind's parts); ``plain``:
    the events whose rule sets the mode from the mode alone
    (``Events.plain``); ``together``: each part's event whose rule has a form
    for k designs at once (``Events.together``) -> (that form, the part's
    place); ``kinds``:
    the kinds it was built from (:data:`~crane_sym.components.kinds.KINDS`
    then, kept so that the ids its key holds stay theirs)."""

    kinds: tuple
    of_kind: dict[str, tuple[int, ...]]
    switching: tuple[tuple[Events, str], ...]
    columns: dict[tuple[str, int], int]
    events: dict[str, tuple[str, int]]
    rules: dict[str, tuple[Callable, int]]
    plain: frozenset[str]
    together: dict[str, tuple[Callable, int]]


#: Each group's events: (suffix of its name, kind).
_GROUP_EVENTS = ((" rests", "rest"), (" slips +", "slip+"), (" slips -", "slip-"))


def layout(equations: Equations) -> Layout:
    """The :class:`Layout` of ``equations``' system, built once per structure
    and kept in ``equations.layouts`` (shared by a template and its designs).

    Parameters
    ----------
    equations : Equations
        A model's (or a design's) equations, with their assembly.
    """
    own = equations.__dict__.get("_layout")      # a design's system and schedule both ask
    if own is not None and own.kinds == tuple(kinds.KINDS):
        return own
    a = equations.assembly
    items = (*a.loads, *a.contacts, *a.links)
    switches = {k.part_kind: k.events for k in kinds.KINDS if k.events is not None}
    signature = (tuple(map(id, kinds.KINDS)), tuple(item.part.kind for item in items),
                 tuple(g.name for g in a.groups),
                 tuple((tuple(switches[item.part.kind].names(item.part)),
                        switches[item.part.kind].states(item.part))
                       for item in items if item.part.kind in switches))
    if signature not in equations.layouts:
        equations.layouts[signature] = _built(a)
    equations.__dict__["_layout"] = equations.layouts[signature]
    return equations.layouts[signature]


def _built(assembly: Assembly) -> Layout:
    """The tables of :class:`Layout` for ``assembly``."""
    items = (*assembly.loads, *assembly.contacts, *assembly.links)
    of_kind = {kind.table: tuple(j for j, item in enumerate(items)
                                 if item.part.kind == kind.part_kind)
               for kind in kinds.KINDS}
    switching = tuple((kind.events, kind.table) for kind in kinds.KINDS
                      if kind.events is not None)
    columns: dict[tuple[str, int], int] = {}
    rules: dict[str, tuple[Callable, int]] = {}
    plain: set[str] = set()
    together: dict[str, tuple[Callable, int]] = {}
    for events, table in switching:
        for i, j in enumerate(of_kind[table]):
            for _ in range(events.states(items[j].part)):
                columns[table, i] = len(columns)
            for name, key in events.names(items[j].part):
                rules[name] = (events.rules[key], i)
                if key in events.plain:
                    plain.add(name)
                if key in events.together:
                    together[name] = (events.together[key], i)
    events = {group.name + suffix: (kind, g) for g, group in enumerate(assembly.groups)
              for suffix, kind in _GROUP_EVENTS}
    return Layout(tuple(kinds.KINDS), of_kind, switching, columns, events, rules,
                  frozenset(plain), together)
