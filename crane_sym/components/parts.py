"""The components of a drive train, as data: bodies, rigid and elastic links
(what acts on one body, brakes, motors and loads, is in
:mod:`crane_sym.components.loads`).

Every value is given either as text with its unit (``"20 kg*m^2"``, read by
:func:`crane_sym.units.parse_quantity`, never evaluated) or as a number in SI.
A value whose dimension depends on the body it acts on (the stiffness of a
link between rotating shafts is a torque per radian, between translating
bodies a force per metre) is kept as a :class:`Value` and checked when the
model is assembled (:mod:`crane_sym.components.topology`), where the body's
kind is known.

Sign conventions: every body has one coordinate (an angle of a rotating body,
a displacement of a translating one) and its own positive direction. A gear
turns its ``output`` ``1/ratio`` as far as its ``input``; a drum moves its
``load`` ``radius/reeving`` metres per radian of the ``drum``. An elastic link
twists by u = (coordinate of its second body) − (of its first) and pushes the
second body back with F = c·(u − u_flank) + d·u̇ on a flank, 0 in its gap.
"""
from __future__ import annotations

import math
import numbers
import re
from dataclasses import dataclass
from typing import Union

from sympy.physics.units import Dimension, current, force, length, mass, time

from crane_sym import units

__all__ = ["Body", "Component", "ComponentError", "DIMENSIONS", "Drum", "ElasticLink", "GROUND",
           "Gear", "Given", "Inertia", "Mass", "ROTATING", "TRANSLATING", "UNITS", "VALUE_KINDS",
           "Value", "value"]

ROTATING, TRANSLATING = "rotating", "translating"
_NAME = re.compile(r"[A-Za-z][A-Za-z0-9_]{0,39}")
_ONE = Dimension(1)
_VOLT = force * length / (time * current)

#: Each kind of value a component holds: its dimension and SI unit by the kind
#: of body it acts on. The one table of them: :data:`DIMENSIONS` and
#: :data:`UNITS` are its two columns, and a kind's keys
#: (:mod:`crane_sym.components.kinds`) name its rows.
VALUE_KINDS: dict[str, dict[str, tuple[Dimension, str]]] = {
    "inertia": {ROTATING: (mass * length**2, "kg*m^2")},
    "mass": {TRANSLATING: (mass, "kg")},
    # an element's own mass along its stretch: kg along a length, kg·m² along an angle
    "own inertia": {ROTATING: (mass * length**2, "kg*m^2"), TRANSLATING: (mass, "kg")},
    "stiffness": {ROTATING: (force * length, "N*m/rad"), TRANSLATING: (force / length, "N/m")},
    "damping": {ROTATING: (force * length * time, "N*m*s/rad"),
                TRANSLATING: (force * time / length, "N*s/m")},
    "backlash": {ROTATING: (_ONE, "rad"), TRANSLATING: (length, "m")},
    "displacement": {ROTATING: (_ONE, "rad"), TRANSLATING: (length, "m")},
    "load": {ROTATING: (force * length, "N*m"), TRANSLATING: (force, "N")},
    "speed": {ROTATING: (1 / time, "rad/s"), TRANSLATING: (length / time, "m/s")},
    "acceleration": {ROTATING: (1 / time**2, "rad/s^2"), TRANSLATING: (length / time**2, "m/s^2")},
    # a DC motor's torque per ampere (= its back-emf per unit of speed)
    "motor constant": {ROTATING: (force * length / current, "N*m/A"),
                       TRANSLATING: (force / current, "N/A")},
    # a speed controller's gains, its output an armature voltage
    "voltage per speed": {ROTATING: (_VOLT * time, "V*s/rad"),
                          TRANSLATING: (_VOLT * time / length, "V*s/m")},
    "voltage per displacement": {ROTATING: (_VOLT, "V/rad"), TRANSLATING: (_VOLT / length, "V/m")},
}
#: Dimension of each kind of value, by the kind of body it acts on.
DIMENSIONS = {k: {motion: d for motion, (d, _) in by.items()} for k, by in VALUE_KINDS.items()}
#: SI unit of each kind of value, by the kind of body it acts on.
UNITS = {k: {motion: u for motion, (_, u) in by.items()} for k, by in VALUE_KINDS.items()}


class ComponentError(ValueError):
    """A component or a model that cannot be built; one line naming the component."""


@dataclass(frozen=True)
class Value:
    """A value in SI with the dimension it was written in (None: a bare number,
    taken as SI) and the text it came from."""

    si: float
    dimension: Dimension | None
    text: str

    def check(self, owner: str, what: str, expected: Dimension) -> float:
        """The SI value, or ComponentError if it was written in another dimension."""
        if self.dimension is not None and not units.same_dimension(self.dimension, expected):
            raise ComponentError(f"{owner}: {what} {self.text!r} is "
                                 f"{units.format_dimension(self.dimension)}, expected "
                                 f"{units.describe_dimension(expected)}")
        return self.si


Given = Union[str, float, int, Value]


#: The magnitudes a value may have in SI units, besides 0: past them a run's
#: linear algebra is singular (1e308 kg, 1e-300 N/m) or overflows to inf
#: (1e-320 kg). A backlash of 1e-6 deg is 1.7e-8 rad.
MAGNITUDES = (1e-30, 1e30)


def value(owner: str, what: str, given: Given, expected: Dimension | None = None) -> Value:
    """``given`` (text with a unit, or a number in SI) as a :class:`Value`; with
    ``expected``, its dimension checked at once; 0 or a magnitude within
    :data:`MAGNITUDES`, else :class:`ComponentError`."""
    if type(given) in (float, int) or (   # a float first: every design of a sweep gives them
            not isinstance(given, (bool, Value)) and isinstance(given, numbers.Real)):
        if not math.isfinite(float(given)):
            raise ComponentError(f"{owner}: {what} must be finite, got {given!r}")
        result = Value(float(given), None, repr(given))
    elif isinstance(given, Value):
        result = given
    elif isinstance(given, bool):
        raise ComponentError(f"{owner}: {what} expects a quantity, got {given!r}")
    elif isinstance(given, str):
        try:
            q = units.parse_quantity(given)
        except units.UnitError as exc:
            raise ComponentError(f"{owner}: {what}: {exc}") from None
        result = Value(q.value, q.dimension, given)
    else:
        raise ComponentError(f"{owner}: {what} expects text like '20 kg*m^2' or a number, "
                             f"got {type(given).__name__}")
    if expected is not None:
        result.check(owner, what, expected)
    low, high = MAGNITUDES
    if result.si != 0 and not low <= abs(result.si) <= high:
        raise ComponentError(f"{owner}: {what} must be 0 or of magnitude {low:g} to {high:g} "
                             f"in SI units, got {result.text!r}")
    return result


def _name(kind: str, name: object) -> str:
    if not isinstance(name, str) or not _NAME.fullmatch(name):
        raise ComponentError(f"{kind} name must be a letter then letters, digits or '_' "
                             f"(at most 40), got {name!r}")
    return name


#: The fixed end a link may name in ``between``: the ground or the structure,
#: its coordinate ≡ 0; no body may take the name.
GROUND = "ground"


def _body_name(kind: str, name: object) -> str:
    name = _name(kind, name)
    if name == GROUND:
        raise ComponentError(f"{kind} name {GROUND!r} is reserved for the fixed end a link "
                             "may name in 'between'; call the body something else")
    return name


def _at_least(owner: str, what: str, v: Value, low: float, strict: bool) -> None:
    if (v.si <= low) if strict else (v.si < low):
        raise ComponentError(f"{owner}: {what} must be {'>' if strict else '>='} {low:g}, "
                             f"got {v.text!r}")


class Component:
    """Base of every component: a ``name`` unique in its model."""

    kind = "component"
    name: str

    @property
    def label(self) -> str:
        """How messages name it: ``gear 'gearbox'``."""
        return f"{self.kind} {self.name!r}"


@dataclass(frozen=True)
class Body(Component):
    """A rigid body with one coordinate: rotating (``inertia`` in kg·m²) or
    translating (``inertia`` holds its mass in kg). Zero is allowed for a shaft
    end joined rigidly to bodies that have inertia."""

    name: str
    inertia: float
    motion: str

    @property
    def kind(self) -> str:            # type: ignore[override]
        return "inertia" if self.motion == ROTATING else "mass"


def Inertia(name: str, inertia: Given) -> Body:
    """A rotating body of moment of inertia ``inertia`` (kg·m²).

    Parameters
    ----------
    name : str
        The body's name (a letter, then letters, digits, ``_``).
    inertia : str or float
        Its moment of inertia, text with a unit or kg·m²; zero for a shaft
        end joined rigidly to bodies that have inertia.
    """
    name = _body_name("inertia", name)
    v = value(f"inertia {name!r}", "inertia", inertia, DIMENSIONS["inertia"][ROTATING])
    _at_least(f"inertia {name!r}", "inertia", v, 0.0, False)
    return Body(name, v.si, ROTATING)


def Mass(name: str, mass_: Given) -> Body:
    """A translating body of mass ``mass_`` (kg).

    Parameters
    ----------
    name : str
        The body's name (a letter, then letters, digits, ``_``).
    mass_ : str or float
        Its mass, text with a unit or kg.
    """
    name = _body_name("mass", name)
    v = value(f"mass {name!r}", "mass", mass_, DIMENSIONS["mass"][TRANSLATING])
    _at_least(f"mass {name!r}", "mass", v, 0.0, False)
    return Body(name, v.si, TRANSLATING)


@dataclass(frozen=True)
class Gear(Component):
    """An ideal gear: ``input`` turns ``ratio`` times as far as ``output``
    (both rotating)."""

    name: str
    input: str
    output: str
    ratio: float
    kind = "gear"

    def __init__(self, name: str, input: str, output: str, ratio: Given) -> None:
        name = _name("gear", name)
        v = value(f"gear {name!r}", "ratio", ratio, _ONE)
        if v.si == 0:
            raise ComponentError(f"gear {name!r}: ratio must not be 0")
        object.__setattr__(self, "name", name)
        object.__setattr__(self, "input", input)
        object.__setattr__(self, "output", output)
        object.__setattr__(self, "ratio", v.si)

    @property
    def ends(self) -> tuple[str, str]:
        return self.input, self.output

    @property
    def factor(self) -> float:
        """Coordinate of the second end per unit of the first."""
        return 1.0 / self.ratio


@dataclass(frozen=True)
class Drum(Component):
    """A rope drum: the translating ``load`` moves ``radius/reeving`` per radian
    of the rotating ``drum`` (``reeving``: rope falls of the tackle, e.g. 8/2 = 4)."""

    name: str
    drum: str
    load: str
    radius: float
    reeving: float
    kind = "drum"

    def __init__(self, name: str, drum: str, load: str, radius: Given,
                 reeving: Given = 1) -> None:
        name = _name("drum", name)
        r = value(f"drum {name!r}", "radius", radius, length)
        n = value(f"drum {name!r}", "reeving", reeving, _ONE)
        _at_least(f"drum {name!r}", "radius", r, 0.0, True)
        _at_least(f"drum {name!r}", "reeving", n, 0.0, True)
        for key, v in (("name", name), ("drum", drum), ("load", load), ("radius", r.si),
                       ("reeving", n.si)):
            object.__setattr__(self, key, v)

    @property
    def ends(self) -> tuple[str, str]:
        return self.drum, self.load

    @property
    def factor(self) -> float:
        return self.radius / self.reeving


#: What a translating link's positive load may be declared to be, and its opposite.
SENSES = {"tension": "compression", "compression": "tension"}


@dataclass(frozen=True)
class ElasticLink(Component):
    """A spring and a viscous damper between two bodies of one kind, with an
    optional backlash gap.

    The twist is u = x_second − x_first. Without backlash the link pushes with
    F = c·u + d·u̇. With backlash s, ``contact = "positive"`` puts the gap at
    −s < u < 0 (the link rests on its positive flank at u = 0: F = c·u + d·u̇
    for u ≥ 0, c·(u + s) + d·u̇ for u ≤ −s), ``"negative"`` at 0 < u < s. In the
    gap F = 0. ``reference``, a load, divides the peak into the dynamic factor
    (default: the link's load at the start). ``positive`` (``"tension"`` or
    ``"compression"``, a translating link only) says what a positive F is,
    so that a report states the load in words: a rope listed from its upper
    end down, with x downwards, is in tension when F > 0. ``fails_at`` (s)
    cuts it at that instant (a reeve breaks): F = 0 from then on. ``slack`` h (≥ 0,
    instead of a backlash) makes it a rope that only pulls: F = c·(u − h) +
    d·u̇ while u ≥ h (taut), 0 below (slack), never a push; it snaps taut where
    u reaches h and goes slack where u falls back to h.
    """

    name: str
    first: str
    second: str
    stiffness: Value
    damping: Value
    backlash: Value
    contact: str = "positive"
    reference: Value | None = None
    positive: str | None = None
    slack: Value | None = None
    fails_at: float | None = None
    kind = "elastic link"
    #: Whether its dynamic factor is an angle in rad that a run reports (a
    #: pendulum's: its pull m g θ over the load's weight m g).
    reports_angle = False

    def __init__(self, name: str, first: str, second: str, stiffness: Given,
                 damping: Given = 0.0, backlash: Given = 0.0, contact: str = "positive",
                 reference: Given | None = None, positive: str | None = None,
                 slack: Given | None = None, fails_at: Given | None = None) -> None:
        name = _name("elastic link", name)
        owner = f"elastic link {name!r}"
        c, d = value(owner, "stiffness", stiffness), value(owner, "damping", damping)
        s = value(owner, "backlash", backlash)
        _at_least(owner, "stiffness", c, 0.0, True)
        _at_least(owner, "damping", d, 0.0, False)
        _at_least(owner, "backlash", s, 0.0, False)
        if contact not in ("positive", "negative"):
            raise ComponentError(f"{owner}: contact must be 'positive' or 'negative', "
                                 f"got {contact!r}")
        if positive not in (None, *SENSES):
            raise ComponentError(f"{owner}: positive must be 'tension' or 'compression', "
                                 f"got {positive!r}")
        h = None if slack is None else value(owner, "slack", slack)
        if h is not None:
            _at_least(owner, "slack", h, 0.0, False)
            if s.si != 0:
                raise ComponentError(f"{owner}: a slack link has no backlash (its gap is "
                                     f"below the slack), got backlash {s.text!r}")
        broken = None if fails_at is None else value(owner, "fails_at", fails_at, time)
        if broken is not None:
            _at_least(owner, "fails_at", broken, 0.0, True)
        ref = None if reference is None else value(owner, "reference", reference)
        if ref is not None and ref.si == 0:
            raise ComponentError(f"{owner}: reference must not be 0")
        for key, v in (("name", name), ("first", first), ("second", second),
                       ("stiffness", c), ("damping", d), ("backlash", s),
                       ("contact", contact), ("reference", ref), ("positive", positive),
                       ("slack", h), ("fails_at", None if broken is None else broken.si)):
            object.__setattr__(self, key, v)

    @property
    def ends(self) -> tuple[str, str]:
        return self.first, self.second

    def assembled(self, bodies: dict[str, Body]) -> tuple[Value, Value | None]:
        """Its stiffness and reference load, given the bodies it joins (as
        written; a pendulum's follow from its load's mass)."""
        return self.stiffness, self.reference

    @property
    def gapped(self) -> bool:
        """Whether its contact switches: a backlash, a slack (one-sided) link,
        or a link that fails (cut at ``fails_at``: its contact 0 from then on)."""
        return self.backlash.si > 0 or self.slack is not None or self.fails_at is not None

    @property
    def opens(self) -> bool:
        """Whether it opens and closes as it twists (a backlash or a slack; a
        link that only fails has a gap of width 0 and never opens)."""
        lo, hi = self.flanks
        return lo < hi

    @property
    def contacts(self) -> tuple[str, ...]:
        """Its contacts in words, from the upper flank down (then ``cut``,
        where it fails)."""
        words = (("taut", "slack") if self.slack is not None else
                 ("upper flank", "gap", "lower flank") if self.opens else ("intact",))
        return words + (("cut",) if self.fails_at is not None else ())

    @property
    def flanks(self) -> tuple[float, float]:
        """(lower, upper) ends of the gap in the twist u; a slack link's gap
        runs from −∞ to its slack (it pulls only, once u passes the slack)."""
        if self.slack is not None:
            return -math.inf, self.slack.si
        s = self.backlash.si
        return (-s, 0.0) if self.contact == "positive" else (0.0, s)

