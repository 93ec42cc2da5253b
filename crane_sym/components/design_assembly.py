"""A design's parts assembled on its template's assembly (:func:`reassemble`).

A design of a sweep has its template's parts with other values: the same
names, kinds, bodies and words (ends, contacts, build-ups). What the assembly
checks of those alone (names taken once, ends that exist, a connected drive,
links between bodies of one motion, one steady motor, speed laws and ground
contacts on groups of their own) held for the template, so a design takes
its template's lists of parts and builds only what rests on its values: the
rigid groups' κ and inertias (a loop's ratios, a group without inertia), the
links' and the loads' values in SI checked against their bodies. Parts that
differ in more than their values are assembled in full
(:func:`~crane_sym.components.topology.assemble`).
"""
from __future__ import annotations

from typing import Any, Sequence

from crane_sym.components import kinds
from crane_sym.components.parts import Component
from crane_sym.components.topology import (Assembly, Contact, assemble, elastic_link,
                                           rigid_groups)

__all__ = ["reassemble"]

#: The words of each template's parts (:func:`_words`), by the identity of its
#: list of parts (kept with it, so the key stays its own).
_TEMPLATE_WORDS: dict[int, tuple[Sequence[Component], tuple]] = {}


def reassemble(components: Sequence[Component], template: Sequence[Component],
               assembled: Assembly) -> Assembly:
    """``assemble(components)`` of a design whose parts are ``template``'s
    (assembled as ``assembled``) but for their values: the template's lists,
    the values' checks and κ anew; in full where the parts differ in more.

    Parameters
    ----------
    components : sequence of Component
        The design's parts.
    template, assembled
        The template's parts and its assembly.
    """
    if not _same_but_values(components, template):
        return assemble(components)
    by_name = {p.name: p for p in components}
    bodies = {name: by_name[name] for name in assembled.bodies}
    rigid = [by_name[p.name] for p in assembled.rigid]
    for part in rigid:
        kinds.of(part).check(part, bodies, ())           # a ratio against its ends' motion
    couplings = [by_name[p.name] for p in assembled.couplings]
    for part in couplings:
        kinds.of(part).couples.check(part, bodies)
    groups, place = rigid_groups(bodies, rigid)
    links = tuple(elastic_link(by_name[l.part.name], bodies, place) for l in assembled.links)
    acting = [by_name[l.part.name] for l in assembled.loads]
    loads = tuple(kinds.of(p).check(p, bodies, components) for p in acting)
    contacts = tuple(Contact(by_name[c.part.name], *place[c.part.body][:2])
                     for c in assembled.contacts)
    return Assembly(bodies, groups, place, links, loads, tuple(rigid), contacts,
                    tuple(couplings))


def _same_but_values(components: Sequence[Component], template: Sequence[Component]) -> bool:
    """Whether ``components`` are ``template``'s parts in order but for their
    values: the same classes and words (:func:`_words`); a part the design
    keeps as the template's is the same."""
    kept = _TEMPLATE_WORDS.get(id(template))
    if kept is None or kept[0] is not template:
        kept = _TEMPLATE_WORDS[id(template)] = (template, tuple(map(_words, template)))
    return len(components) == len(template) and \
        all(p is t or (type(p) is type(t) and _words(p) == w)
            for p, t, w in zip(components, template, kept[1]))


def _words(part: Component) -> tuple[tuple[str, Any], ...] | None:
    """What a part holds beside its values: each attribute that is a word, a
    flag, None or a tuple of words (its name, bodies, contact, build-up; a
    value given or not), and the bodies a span joins; None for a part
    without attributes of its own (never the same)."""
    try:
        own = vars(part)
    except TypeError:
        return None
    out = []
    for key, v in own.items():
        kind = type(v)
        if kind is str or kind is bool or v is None:
            out.append((key, v))
        elif (kind is tuple or kind is list) and all(type(e) is str for e in v):
            out.append((key, tuple(v)))
    couples = kinds.of(part).couples
    if couples is not None:
        out.append(("joins", tuple(couples.bodies(part))))
    return tuple(out)
