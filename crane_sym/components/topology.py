"""From a list of components to independent coordinates: bodies joined by
gears and drums merged into rigid groups, each with one coordinate.

Within a group every body's coordinate is a fixed multiple κ of the group's
coordinate, the coordinate of its first body in the order the components were
given (κ = 1 there); a rigid link is a part whose kind declares ``rigid`` (its
κ in its symbols). Elastic links join groups, or a group and the fixed
ground (``"ground"`` as one end of ``between``: x ≡ 0, no group, κ = 0, which
:meth:`Assembly.ends` gives in this one place), and so do spans (a part whose
kind ``couples`` several coordinates by its own energies:
``Assembly.couplings``); brakes, motors and loads (a part whose kind ``acts``)
act on a body and reach its group through κ, each checked by its kind's
``check``; what else the assembly asks of a part (it holds a group, sets a
speed, is steady) its kind's ``roles`` say.

What cannot be a drive train is refused here, in one line naming the
component: two components of one name, a link or a load on an unknown body,
a link between bodies of the wrong kinds, a value of the wrong dimension, a
body connected to nothing, parts of the drive not connected to each other, a
loop of gears and drums whose ratios disagree, an elastic link inside a rigid
group (it could never twist), and a body without inertia whose rigid group has
none (between two rigid links, or two elastic ones, it has no equation of
motion).
"""
from __future__ import annotations

import difflib
from dataclasses import dataclass
from typing import Sequence

import sympy as sp

from crane_sym.components import kinds
from crane_sym.components.acting import Load
from crane_sym.components.parts import (DIMENSIONS, GROUND, ROTATING, Body, Component,
                                        ComponentError, ElasticLink)

__all__ = ["Assembly", "Contact", "End", "Group", "Link", "Load", "assemble", "elastic_link",
           "rigid_groups"]

#: Relative tolerance of a loop of rigid ratios.
LOOP_TOLERANCE = 1e-12


@dataclass(frozen=True)
class Group:
    """Bodies joined rigidly: ``members`` are (body, κ), the first with κ = 1;
    ``inertia`` is Σ J κ², the group's inertia referred to its coordinate."""

    members: tuple[tuple[Body, float], ...]
    links: tuple[str, ...]
    factors: tuple[sp.Expr, ...] = ()

    @property
    def name(self) -> str:
        return self.members[0][0].name

    @property
    def motion(self) -> str:
        return self.members[0][0].motion

    @property
    def inertia(self) -> float:
        return sum(b.inertia * k * k for b, k in self.members)


@dataclass(frozen=True)
class Link:
    """An elastic link with its values in SI, checked against its bodies' kind."""

    part: ElasticLink
    stiffness: float
    damping: float
    backlash: float
    reference: float | None

    @property
    def gapped(self) -> bool:
        """Whether it has a gap (a backlash, or a slack link's): its contact
        switches."""
        return self.part.gapped


@dataclass(frozen=True)
class Contact:
    """A body's one-sided contact with the ground: its rigid group and κ."""

    part: GroundContact
    group: int
    kappa: float


@dataclass(frozen=True)
class End:
    """Where an end of a link sits: its rigid group (None at the ground), and
    κ, its coordinate per unit of the group's, as a number and in the parts'
    symbols (0 at the ground, whose coordinate is 0 whatever the groups do)."""

    group: int | None
    kappa: float
    factor: sp.Expr


#: The fixed end: no group, κ = 0.
_FIXED = End(None, 0.0, sp.Integer(0))


@dataclass(frozen=True)
class Assembly:
    """The checked model: bodies in order, rigid groups, where each body sits
    (group index, κ), the elastic links and the loads."""

    bodies: dict[str, Body]
    groups: tuple[Group, ...]
    place: dict[str, tuple[int, float, sp.Expr]]
    links: tuple[Link, ...]
    loads: tuple[Load, ...]
    rigid: tuple[Component, ...] = ()
    contacts: tuple[Contact, ...] = ()
    #: The parts that join several coordinates by their own energies (spans:
    #: ``Kind.couples``), in the order given.
    couplings: tuple[Component, ...] = ()

    def ends(self, link: Link) -> tuple[End, End]:
        """The two ends of ``link`` in the order of ``between``; the ground
        is the fixed end (no group, κ = 0), so every sum over a link's ends
        that skips ``group is None`` reads the ground as x ≡ 0."""
        return tuple(_FIXED if e == GROUND else End(*self.place[e])
                     for e in link.part.ends)  # type: ignore[return-value]

    def weights(self, link: Link) -> list[tuple[int, float]]:
        """The twist u = x(second) − x(first) as (group, weight) pairs, u =
        Σ weight·q_group, the ground left out."""
        first, second = self.ends(link)
        return [(e.group, sign * e.kappa) for e, sign in ((first, -1.0), (second, 1.0))
                if e.group is not None]

    def twist(self, link: Link, coordinates: Sequence[sp.Expr]) -> sp.Expr:
        """The twist u = κ_second q_second − κ_first q_first in the parts'
        symbols (the ground's term 0)."""
        first, second = self.ends(link)
        at = lambda e: 0 if e.group is None else e.factor * coordinates[e.group]  # noqa: E731
        return at(second) - at(first)

    @property
    def grounded(self) -> bool:
        """Whether a link holds the drive to the ground (its positions then
        absolute, none free to be set at 0)."""
        return any(GROUND in l.part.ends for l in self.links)

    def motion(self, link: Link) -> str:
        """The motion (rotating or translating) of the bodies ``link`` joins."""
        return next(self.bodies[e].motion for e in link.part.ends if e != GROUND)


def _unknown(owner: str, name: object, known: Sequence[str]) -> ComponentError:
    close = difflib.get_close_matches(str(name), list(known), n=2, cutoff=0.6)
    hint = f"; did you mean {' or '.join(map(repr, close))}?" if close else \
        f"; bodies: {', '.join(known)}"
    return ComponentError(f"{owner} names unknown body {name!r}{hint}")


def assemble(components: Sequence[Component]) -> Assembly:
    """Check the components and merge the rigid groups (see the module docstring).

    Parameters
    ----------
    components : sequence of Component
        Bodies, rigid and elastic links, and what acts on the bodies.

    Raises
    ------
    ComponentError
        One line naming the component at fault.
    """
    seen: dict[str, Component] = {}
    for part in components:
        if not isinstance(part, Component):
            raise ComponentError(f"not a component: {part!r}")
        if part.name in seen:
            raise ComponentError(f"{part.label}: the name is taken by {seen[part.name].label}")
        seen[part.name] = part
    # Bodies and elastic links are the parts' two base types (a pendulum is an
    # ElasticLink), not kinds: the assembly is built of them.
    bodies = {p.name: p for p in components if isinstance(p, Body)}
    if not bodies:
        raise ComponentError("the model has no body (inertia or mass)")
    rigid = [p for p in components if kinds.of(p).rigid is not None]
    elastic = [p for p in components if isinstance(p, ElasticLink)]
    acting = [p for p in components if kinds.of(p).acts is not None]
    for part, ends in [*((p, p.ends) for p in [*rigid, *elastic]),
                       *((p, (p.body,)) for p in acting)]:
        for end in ends:
            if end not in bodies and not (end == GROUND and isinstance(part, ElasticLink)):
                raise _unknown(part.label, end, list(bodies))
    couplings = [p for p in components if kinds.of(p).couples is not None]
    joined = []
    for part in couplings:
        couples = kinds.of(part).couples
        names = couples.bodies(part)
        for end in names:
            if end not in bodies:
                raise _unknown(part.label, end, list(bodies))
        couples.check(part, bodies)
        joined.append(names)
    _kinds(bodies, rigid, elastic)
    _connected(bodies, rigid, elastic, joined)
    groups, place = rigid_groups(bodies, rigid)
    links = tuple(elastic_link(p, bodies, place) for p in elastic)
    loads = tuple(kinds.of(p).check(p, bodies, components) for p in acting)
    steady = [l.part.label for l in loads if kinds.plays(l.part, "steady")]
    if len(steady) > 1:
        raise ComponentError(f"{steady[1]}: only one motor may be 'steady' ({steady[0]} is)")
    _speed_laws(loads, groups, place)
    contacts = _contacts([p for p in components if kinds.plays(p, "rests")], bodies,
                         place, loads)
    balancing = steady + [l.part.label for l in loads if kinds.plays(l.part, "balances")]
    if len(balancing) > 1:
        raise ComponentError(f"{balancing[1]}: only one motor may balance the others "
                             f"({balancing[0]} does: a 'steady' torque or an acceleration law)")
    return Assembly(bodies, groups, place, links, loads, tuple(rigid), contacts,
                    tuple(couplings))


def _contacts(parts: list[Component], bodies: dict[str, Body],
              place: dict[str, tuple[int, float, sp.Expr]],
              loads: tuple[Load, ...]) -> tuple[Contact, ...]:
    """Each ground contact on a known body, one a rigid group, on a group that
    no brake holds and no speed law moves (the contact alone holds it)."""
    out: list[Contact] = []
    for part in parts:
        if part.body not in bodies:
            raise _unknown(part.label, part.body, list(bodies))
        g, kappa, _ = place[part.body]
        for other in out:
            if other.group == g:
                raise ComponentError(f"{part.label}: {other.part.label} rests the same rigid "
                                     "group on the ground already")
        for load in loads:
            if kinds.plays(load.part, "holds at rest") and place[load.part.body][0] == g:
                raise ComponentError(f"{part.label}: {load.part.label} acts on the rigid group "
                                     f"of {bodies[part.body].label}, which the ground holds "
                                     "while it rests; a contact takes a group without brakes "
                                     "or speed laws")
        out.append(Contact(part, g, kappa))
    return tuple(out)


def _speed_laws(loads: tuple[Load, ...], groups: tuple[Group, ...],
                place: dict[str, tuple[int, float, sp.Expr]]) -> None:
    """A group that a speed law moves takes no brake and no second speed law."""
    moved: dict[int, Component] = {}
    for load in loads:
        if kinds.plays(load.part, "sets speed"):
            g = place[load.part.body][0]
            if g in moved:
                raise ComponentError(f"{load.part.label}: {moved[g].label} sets the speed of "
                                     f"{groups[g].members[0][0].label} already")
            moved[g] = load.part
    for load in loads:
        g = place[load.part.body][0]
        if kinds.plays(load.part, "slides") and g in moved:
            raise ComponentError(f"{load.part.label} acts on a body whose speed "
                                 f"{moved[g].label} sets: it could never slide")


def _kinds(bodies: dict[str, Body], rigid: list, elastic: list) -> None:
    for part in rigid:
        kinds.of(part).check(part, bodies, ())     # its ends' motions, as its kind says
    for part in elastic:
        if part.ends == (GROUND, GROUND):
            raise ComponentError(f"{part.label} joins the ground to itself")
        named = [bodies[e] for e in part.ends if e != GROUND]
        a, b = named * (3 - len(named))          # a link to the ground: its one body
        if a.motion != b.motion:
            raise ComponentError(f"{part.label} joins {a.label} ({a.motion}) and {b.label} "
                                 f"({b.motion}); a link joins bodies of one kind (through a "
                                 "drum between them)")
        if a.name == b.name and len(named) == 2:
            raise ComponentError(f"{part.label} joins {a.label} to itself")
        if part.positive is not None and a.motion == ROTATING:
            raise ComponentError(f"{part.label}: positive = {part.positive!r} is for a "
                                 "translating link (a rope, a buffer); a shaft's torque "
                                 "keeps its sign")


def _connected(bodies: dict[str, Body], rigid: list, elastic: list,
               joined: list[tuple[str, ...]]) -> None:
    """Every body in a link, and all of them one connected drive (a span joins
    the bodies it names, ``joined``)."""
    edges = [p.ends for p in [*rigid, *elastic] if GROUND not in p.ends]
    edges += [pair for names in joined for pair in zip(names, names[1:])]
    touched = {e for p in [*rigid, *elastic] for e in p.ends} | {e for names in joined
                                                                  for e in names}
    if len(bodies) > 1:
        for name, body in bodies.items():
            if name not in touched:
                raise ComponentError(f"{body.label} is connected to nothing (no gear, drum, "
                                     "elastic link or span names it)")
    first = next(iter(bodies))
    reached, todo = {first}, [first]
    while todo:
        here = todo.pop()
        for a, b in edges:
            for x, y in ((a, b), (b, a)):
                if x == here and y not in reached:
                    reached.add(y)
                    todo.append(y)
    for name, body in bodies.items():
        if name not in reached:
            raise ComponentError(f"{body.label} is not connected to {bodies[first].label}: "
                                 "no chain of gears, drums, elastic links and spans joins "
                                 "them")


def rigid_factor(part: Component) -> sp.Expr:
    """κ of a rigid link's second end per unit of its first, in its symbols, as
    its kind declares (``Kind.rigid``: 1/i for a gear, r/n for a drum)."""
    return kinds.of(part).rigid(part)


def rigid_groups(bodies: dict[str, Body], rigid: list
                 ) -> tuple[tuple[Group, ...], dict[str, tuple[int, float, sp.Expr]]]:
    """Rigid groups by a walk over gears and drums, κ multiplied along the way
    (as a number and in the links' symbols); a link that closes a loop must
    agree with the product around it."""
    place: dict[str, tuple[int, float, sp.Expr]] = {}
    groups: list[Group] = []
    for start in bodies:
        if start in place:
            continue
        index = len(groups)
        place[start] = (index, 1.0, sp.Integer(1))
        members, used, todo = [start], [], [start]
        while todo:
            here = todo.pop(0)
            for part in rigid:
                a, b = part.ends
                if here not in (a, b) or part.name in used:
                    continue
                used.append(part.name)
                factor, exact = part.factor, rigid_factor(part)
                other, factor, exact = ((b, factor, exact) if here == a else
                                        (a, 1.0 / factor, 1 / exact))
                kappa, kappa_sym = place[here][1] * factor, place[here][2] * exact
                if other in place:
                    have = place[other][1]
                    if abs(have - kappa) > LOOP_TOLERANCE * max(abs(have), abs(kappa)):
                        loop = ", ".join(p.name for p in rigid if p.name in used)
                        raise ComponentError(
                            f"{part.label} closes a loop of rigid links ({loop}) with ratios "
                            f"that disagree: it moves {bodies[other].label} {kappa:.12g} per "
                            f"unit of {bodies[start].label}, the rest of the loop {have:.12g}")
                    continue
                place[other] = (index, kappa, kappa_sym)
                members.append(other)
                todo.append(other)
        group = Group(tuple((bodies[m], place[m][1]) for m in members), tuple(used),
                      tuple(place[m][2] for m in members))
        if group.inertia <= 0:
            around = {m: [p.label for p in rigid if m in p.ends] for m in members}
            named = max(members, key=lambda m: len(around[m]))
            where = (f"between the rigid links {' and '.join(around[named])}"
                     if len(around[named]) > 1 else
                     f"at the rigid link {around[named][0]}" if around[named] else
                     "between elastic links")
            raise ComponentError(f"{bodies[named].label} has no inertia {where}, and no body "
                                 "joined rigidly to it has any: it has no equation of motion")
        groups.append(group)
    return tuple(groups), place


def elastic_link(part: ElasticLink, bodies: dict[str, Body],
                 place: dict[str, tuple[int, float]]) -> Link:
    """The link of ``part`` with its values in SI, checked against its bodies."""
    a, b = part.ends
    if GROUND not in part.ends and place[a][0] == place[b][0]:
        raise ComponentError(f"{part.label} joins {bodies[a].label} and {bodies[b].label}, "
                             "which gears and drums already join rigidly: it could never twist")
    motion = bodies[b if a == GROUND else a].motion
    check = lambda what, v: v.check(part.label, what, DIMENSIONS[what][motion])  # noqa: E731
    stiffness, given = part.assembled(bodies)
    reference = (None if given is None else
                 given.check(part.label, "reference", DIMENSIONS["load"][motion]))
    if part.slack is not None:
        part.slack.check(part.label, "slack", DIMENSIONS["backlash"][motion])  # m, or rad
    return Link(part, check("stiffness", stiffness), check("damping", part.damping),
                check("backlash", part.backlash), reference)
