"""``[[elastic]]``: a spring and a viscous damper between two bodies of one kind,
with an optional backlash gap: F = c (u − flank) + d u̇, u = x(second) − x(first);
or, with ``slack`` h instead, a rope that only pulls: F = c (u − h) + d u̇ while
u ≥ h, 0 below (a key of this kind, not a kind of its own: a slack rope is an
elastic link whose gap runs from −∞ to h, so its load, peak, dynamic factor,
sweep and walkthrough are the elastic link's).

Its modes: a gapped link (a backlash, a slack, or ``fails_at``) is on its
upper flank (+1), in its gap (0) or on its lower flank (−1), ``Mode.contacts``
by its place among the gapped links; it opens where its twist returns to the
flank and closes where the twist reaches the other end of the gap; cut at
``fails_at``, it stays in its gap for good (``Mode.cut``)."""
import numpy as np
from sympy.physics.units import time

from crane_sym.components.kinds.base import Key, Kind, Symbolic, failure
from crane_sym.components.kinds.events import Events
from crane_sym.components.parts import DIMENSIONS, UNITS, ComponentError, ElasticLink


def _build(g: dict, entry: dict, where: str) -> ElasticLink:
    first, second = g["between"]
    if "slack" in entry and ("backlash" in entry or "contact" in entry):
        given = "backlash" if "backlash" in entry else "contact"
        raise ComponentError(f"{where}: slack {entry['slack']!r} makes a rope that only pulls; "
                             f"it takes no {given} (got {given} = {entry[given]!r})")
    return ElasticLink(g["name"], first, second, g["stiffness"], g["damping"], g["backlash"],
                       g["contact"], g["reference"], g["positive"], g["slack"], g["fails_at"])


def _switching(part: ElasticLink, motion: str) -> tuple:
    gap = (("slack", part.slack.si, "slack") if part.slack is not None else
           ("backlash", part.backlash.si, "backlash (gap)"))
    return ((gap[0], gap[1], DIMENSIONS["backlash"][motion], UNITS["backlash"][motion],
             f"{gap[2]} of the elastic link {part.name}"),
            *failure(part, f"the elastic link {part.name}"))


# --- its modes and events ---------------------------------------------------------
def _names(part: ElasticLink) -> dict[str, str]:
    """Its contact events by rule: a backlash link ``opens`` and ``closes
    +``/``-``; a slack rope ``snaps taut`` and ``goes slack`` (it has no
    lower flank); a link that fails ``breaks``."""
    if part.slack is not None:
        out = {"open": f"{part.name} goes slack", "close+": f"{part.name} snaps taut"}
    else:
        out = {"open": f"{part.name} opens", "close+": f"{part.name} closes +",
               "close-": f"{part.name} closes -"}
    return {**out, "break": f"{part.name} breaks"}


def _gapped(system, i: int) -> int | None:
    """Link i's place among the gapped links (None: it has no gap)."""
    link = system.of_kind["elastic"][i]
    return next((j for j, l in enumerate(system.backlash) if l is link), None)


def _guards(designs, mode, i: int) -> tuple:
    """Opening from its flank, closing on either end of its gap (not once cut,
    nor for a gap of width 0), for each design: its twist's weights and its
    flanks its own."""
    system = designs.model
    j = _gapped(system, i)
    if j is None or j in mode.cut:
        return ()
    lo, hi = designs.flanks[:, j, 0], designs.flanks[:, j, 1]
    opens = lo < hi
    if not opens.all():
        if opens.any():
            raise ValueError(f"designs differ in the guards of mode {mode!r}: the gap of "
                             f"{system.backlash[j].part.name} is 0 in some of them")
        return ()
    link = system.backlash[j]
    u = designs.gather(("twist", j), lambda s: s.twist(s.backlash[j]))
    name, c = _names(link.part), mode.contacts[j]
    if c > 0:
        return ((name["open"], u, -hi, -1),)
    if c < 0:
        return ((name["open"], u, -lo, 1),)
    closing = ((name["close+"], u, -hi, 1),)
    if np.isfinite(lo).all():           # a slack link has no lower flank
        closing += ((name["close-"], u, -lo, -1),)
    return closing


def _contact(rule: str):
    """The rule that puts a gapped link in contact ``rule`` names (cut for good
    at a break)."""
    def switch(system, mode, i: int, x):
        j = _gapped(system, i)
        contacts = list(mode.contacts)
        contacts[j] = {"open": 0, "close+": 1, "close-": -1, "break": 0}[rule]
        cut = tuple(sorted({*mode.cut, j})) if rule == "break" else mode.cut
        return mode.setting(contacts=contacts, cut=cut), x
    return switch


EVENTS = Events((), lambda part, rest: {},
                lambda part: tuple((name, rule) for rule, name in _names(part).items())
                if part.gapped else (),
                {rule: _contact(rule) for rule in ("open", "close+", "close-", "break")},
                plain=frozenset({"open", "close+", "close-", "break"}),
                schedule=lambda part, rest: (() if part.fails_at is None else
                                             ((part.fails_at, f"{part.name} breaks"),)),
                guards=_guards)


KIND = Kind("elastic", (Key("name", "word"), Key("between", "ends"),
                        Key("stiffness", value="stiffness", sign="positive"),
                        Key("damping", value="damping", sign="nonnegative", required=False,
                            default=0.0),
                        Key("backlash", value="backlash", sign="nonnegative", required=False,
                            default=0.0),
                        Key("contact", "word", required=False, default="positive"),
                        Key("reference", value="load", sign="nonzero", required=False),
                        Key("positive", "word", required=False),
                        Key("slack", value="backlash", sign="nonnegative", required=False),
                        Key("fails_at", value=time, sign="positive", required=False)),
            _build, "a spring and damper between two bodies, with an optional backlash, "
            "or a rope that only pulls (slack)",
            "elastic link",
            symbols=(Symbolic("stiffness", "c", "positive", lambda link: link.stiffness,
                              "stiffness of the elastic link {name}", equations_only=True),
                     Symbolic("damping", "d", "nonnegative", lambda link: link.damping,
                              "damping of the elastic link {name}", equations_only=True)),
            shape=lambda link: link.gapped, switching=_switching, counted="links", events=EVENTS)
