"""``[[ground_contact]]``: a body resting on the ground, which pushes it but
never pulls: held at x = 0 by the reaction R ≥ 0, lifting off where R would
turn negative, set down where it comes back.

Its modes are its group's motion: held (on the ground) or free (lifted off);
the group is the contact's to hold, so no friction guard asks about it
(``fixes``). Its reaction R = s N/κ is what holds the group still
(:meth:`crane_sym.components.hybrid.ComponentSystem.reaction`).
"""
import numpy as np

from crane_sym.components.kinds.base import Key, Kind
from crane_sym.components.kinds.events import FREE, HELD, Events
from crane_sym.components.loads import GroundContact


def _guards(designs, mode, j: int) -> tuple:
    """On the ground: lifts off where R falls through 0; off it: set down
    where its body returns to x = 0 (for each design)."""
    system = designs.model
    contact = system.contacts[j]
    name, g = contact.part.name, contact.group
    if mode.motion[g] == HELD:
        w, k = designs.reaction(mode, j)
        if w.any():                     # a constant reaction never turns negative
            return ((f"{name} lifts off", w, k, -1),)
        return ()
    w = np.zeros((designs.k, system.size))     # the body's way towards the ground
    w[:, system.q(g)] = contact.part.sign * designs.gather(("contact kappa", j),
                                                           lambda s: s.contacts[j].kappa)
    return ((f"{name} sets down", w, 0.0, 1),)


def _lift(system, mode, j: int, x):
    return mode.moving(system.contacts[j].group, FREE), x


def _land(system, mode, j: int, x):
    """Set down at rest, exactly on the ground (an inelastic touch): held if
    the ground must push, else free."""
    g = system.contacts[j].group
    x[system.q(g)] = x[system.v(g)] = 0.0
    w, k = system.reaction(mode.moving(g, HELD), j)
    return mode.moving(g, HELD if float(w @ x + k) >= 0 else FREE), x


EVENTS = Events((), lambda part, rest: {},
                lambda part: ((f"{part.name} lifts off", "lift"),
                              (f"{part.name} sets down", "land")),
                {"lift": _lift, "land": _land}, guards=_guards, plain=frozenset({"lift"}),
                fixes=lambda system, mode, j: system.contacts[j].group)

KIND = Kind("ground_contact", (Key("name", "word"), Key("body", "body"),
                               Key("direction", "word", required=False, default="+")),
            lambda g, entry, where: GroundContact(g["name"], g["body"], g["direction"]),
            "a body resting on the ground: it lifts off and is set down again",
            "ground contact", roles=lambda part: frozenset({"rests"}), events=EVENTS)
