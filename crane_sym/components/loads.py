"""What acts on one body of a drive train: brakes, motors (constant, steady or
a speed characteristic), gravity and constant resistances (a law in time:
:mod:`crane_sym.components.laws`); a body's given state at t = 0
(:class:`Initial`, applied by :mod:`crane_sym.components.initial`); and a
one-sided contact of a body with the ground (:class:`GroundContact`, a mode
of :mod:`crane_sym.components.hybrid`).

Values are text with a unit or numbers in SI (:func:`crane_sym.components.parts.value`);
a torque on a rotating body is a force on a translating one, checked when the
model is assembled.
"""
from __future__ import annotations

from dataclasses import dataclass

from sympy.physics.units import current, force, length, time

from crane_sym.components.laws import MotorLaw
from crane_sym.components.parts import (Component, ComponentError, Given, Value, _at_least,
                                        _name, value)

__all__ = ["BUILD_UPS", "Brake", "Characteristic", "DCMotor", "Gravity", "GroundContact",
           "Initial", "Motor", "Resistance", "STEADY", "SpeedController"]

#: Dimensions of an armature's resistance (V/A) and inductance (V·s/A).
OHM = force * length / (time * current**2)
HENRY = force * length / current**2

#: A motor torque that holds the drive in its steady motion at the start.
STEADY = "steady"
#: How a brake's torque builds up after its delay.
BUILD_UPS = ("step", "ramp", "exponential")


@dataclass(frozen=True)
class Brake(Component):
    """A brake on ``body``: after ``delay`` its torque (a force on a translating
    body) builds up to ``load`` as a step, a linear ``ramp`` over ``time``, or
    an ``exponential`` 1 − e^(−τ/time); it opposes the motion while the body
    slides and holds the body once it comes to rest while the rest of the load
    stays within what it can hold; it releases for good at ``fails_at`` (s,
    after its delay; None: never)."""

    name: str
    body: str
    load: Value
    delay: float = 0.0
    build_up: str = "step"
    time: float = 0.0
    fails_at: float | None = None
    kind = "brake"

    def __init__(self, name: str, body: str, load: Given, delay: Given = 0.0,
                 build_up: str = "step", time_: Given = 0.0,
                 fails_at: Given | None = None) -> None:
        name = _name("brake", name)
        owner = f"brake {name!r}"
        m = value(owner, "torque", load)
        _at_least(owner, "torque", m, 0.0, True)
        dt = value(owner, "delay", delay, time)
        _at_least(owner, "delay", dt, 0.0, False)
        if build_up not in BUILD_UPS:
            raise ComponentError(f"{owner}: build_up must be one of {', '.join(BUILD_UPS)}, "
                                 f"got {build_up!r}")
        tt = value(owner, "time", time_, time)
        if build_up == "step":
            _at_least(owner, "time", tt, 0.0, False)
        else:
            _at_least(owner, f"time of its {build_up}", tt, 0.0, True)
        broken = None if fails_at is None else value(owner, "fails_at", fails_at, time)
        if broken is not None and broken.si <= dt.si:
            raise ComponentError(f"{owner}: fails_at must be > its delay {dt.si:g} s (it "
                                 f"releases once engaged), got {broken.text!r}")
        for key, v in (("name", name), ("body", body), ("load", m), ("delay", dt.si),
                       ("build_up", build_up), ("time", tt.si),
                       ("fails_at", None if broken is None else broken.si)):
            object.__setattr__(self, key, v)


@dataclass(frozen=True)
class Motor(Component):
    """A constant torque (a force on a translating body) along the body's
    coordinate, or :data:`STEADY`: the torque that holds the drive in its steady
    motion at the start; switched off at ``off_at`` (None: never)."""

    name: str
    body: str
    load: Value | None
    off_at: float | None = None
    kind = "motor"

    def __init__(self, name: str, body: str, load: Given, off_at: Given | None = None) -> None:
        name = _name("motor", name)
        owner = f"motor {name!r}"
        m = None if load == STEADY else value(owner, "torque", load)
        off = None
        if off_at is not None:
            off = value(owner, "off_at", off_at, time)
            _at_least(owner, "off_at", off, 0.0, False)
        for key, v in (("name", name), ("body", body), ("load", m),
                       ("off_at", None if off is None else off.si)):
            object.__setattr__(self, key, v)


@dataclass(frozen=True)
class Gravity(Component):
    """The weight of a translating body: its mass times ``g``, along its
    coordinate (``direction`` "+") or against it ("-")."""

    name: str
    body: str
    g: float = 9.81
    direction: str = "+"
    kind = "gravity"

    def __init__(self, name: str, body: str, g: Given = "9.81 m/s^2",
                 direction: str = "+") -> None:
        name = _name("gravity", name)
        owner = f"gravity {name!r}"
        v = value(owner, "g", g, length / time**2)
        _at_least(owner, "g", v, 0.0, False)
        if direction not in ("+", "-"):
            raise ComponentError(f"{owner}: direction must be '+' or '-', got {direction!r}")
        for key, val in (("name", name), ("body", body), ("g", v.si), ("direction", direction)):
            object.__setattr__(self, key, val)


@dataclass(frozen=True)
class Resistance(Component):
    """A constant torque or force on a body along its coordinate (negative:
    against it), e.g. a travel resistance during a run of known direction."""

    name: str
    body: str
    load: Value
    kind = "resistance"

    def __init__(self, name: str, body: str, load: Given) -> None:
        name = _name("resistance", name)
        for key, v in (("name", name), ("body", body),
                       ("load", value(f"resistance {name!r}", "torque", load))):
            object.__setattr__(self, key, v)


@dataclass(frozen=True)
class Characteristic(Component):
    """A motor whose torque (force) falls linearly with the body's speed,
    β_k (v0 − v): lines through the no-load speed ``speed``, the slope of a
    stepped start (a rheostat) moving to the next of ``slopes`` at each of the
    ``holds`` in turn (one fewer hold than slopes; the last slope stays)."""

    name: str
    body: str
    speed: Value
    slopes: tuple[Value, ...]
    holds: tuple[float, ...]
    kind = "characteristic"

    def __init__(self, name: str, body: str, speed: Given, slopes, holds=()) -> None:
        name = _name("characteristic", name)
        owner = f"characteristic {name!r}"
        if not isinstance(slopes, (list, tuple)) or not slopes:
            raise ComponentError(f"{owner}: slopes must be a non-empty list")
        if not isinstance(holds, (list, tuple)) or len(holds) != len(slopes) - 1:
            raise ComponentError(f"{owner}: give one hold time fewer than slopes "
                                 f"({len(slopes) - 1}), got {holds!r}")
        k = tuple(value(owner, "slope", x) for x in slopes)
        for x in k:
            _at_least(owner, "slope", x, 0.0, True)
        h = tuple(value(owner, "hold", x, time) for x in holds)
        for x in h:
            _at_least(owner, "hold", x, 0.0, True)
        for key, v in (("name", name), ("body", body), ("speed", value(owner, "speed", speed)),
                       ("slopes", k), ("holds", tuple(x.si for x in h))):
            object.__setattr__(self, key, v)


@dataclass(frozen=True)
class Initial(Component):
    """The state of ``body`` at t = 0 beside the run's start: moved by
    ``displacement`` along its coordinate from where the start puts it, and
    moving at ``velocity`` (None: as the start has it). No force: its kind
    declares no ``acts``."""

    name: str
    body: str
    displacement: Value | None = None
    velocity: Value | None = None
    kind = "initial state"

    def __init__(self, name: str, body: str, displacement: Given | None = None,
                 velocity: Given | None = None) -> None:
        name = _name("initial state", name)
        owner = f"initial state {name!r}"
        if displacement is None and velocity is None:
            raise ComponentError(f"{owner}: give a displacement, a velocity or both")
        for key, v in (("name", name), ("body", body),
                       ("displacement", None if displacement is None else
                        value(owner, "displacement", displacement)),
                       ("velocity", None if velocity is None else
                        value(owner, "velocity", velocity))):
            object.__setattr__(self, key, v)


@dataclass(frozen=True)
class GroundContact(Component):
    """A body resting on the ground, which can push it but never pull: the
    ground lies on the ``direction`` side of the body ("+": along its
    coordinate, where a weight of direction "+" pushes it). Resting, the body
    is held at x = 0 by the reaction R ≥ 0; it lifts off where the R its rest
    needs would turn negative and is set down (at rest, an inelastic touch)
    where it comes back to x = 0. No force in Q: its kind declares no ``acts``."""

    name: str
    body: str
    direction: str = "+"
    kind = "ground contact"

    def __init__(self, name: str, body: str, direction: str = "+") -> None:
        name = _name("ground contact", name)
        if direction not in ("+", "-"):
            raise ComponentError(f"ground contact {name!r}: direction must be '+' or '-', "
                                 f"got {direction!r}")
        for key, val in (("name", name), ("body", body), ("direction", direction)):
            object.__setattr__(self, key, val)

    @property
    def sign(self) -> float:
        """+1 where the ground lies along the body's coordinate, else −1."""
        return 1.0 if self.direction == "+" else -1.0


@dataclass(frozen=True)
class DCMotor(Component):
    """A DC motor's armature on ``body``: resistance ``resistance`` (Ω),
    inductance ``inductance`` (H), torque constant ``constant`` (N·m/A; equal
    to its back-emf per rad/s; N/A on a translating body) and the voltage
    ``voltage``, a law in time (:class:`~crane_sym.components.laws.MotorLaw`
    of kind ``voltage``). Its current i is a first-order state,

    .. math:: L\\,\\frac{di}{dt} = V(t) - R\\,i - k\\,\\omega,

    ω the body's speed, and it pushes the body with k i along its coordinate
    (positive V drives the body the positive way)."""

    name: str
    body: str
    resistance: Value
    inductance: Value
    constant: Value
    voltage: MotorLaw
    kind = "dc motor"

    def __init__(self, name: str, body: str, resistance: Given, inductance: Given,
                 constant: Given, voltage: MotorLaw) -> None:
        name = _name("dc motor", name)
        owner = f"dc motor {name!r}"
        r = value(owner, "resistance", resistance, OHM)
        ell = value(owner, "inductance", inductance, HENRY)
        k = value(owner, "constant", constant)
        for what, v in (("resistance", r), ("inductance", ell), ("constant", k)):
            _at_least(owner, what, v, 0.0, True)
        for key, v in (("name", name), ("body", body), ("resistance", r), ("inductance", ell),
                       ("constant", k), ("voltage", voltage)):
            object.__setattr__(self, key, v)

    @property
    def laws(self) -> tuple[MotorLaw, ...]:
        """The laws in time it carries: its voltage."""
        return (self.voltage,)


@dataclass(frozen=True)
class SpeedController(Component):
    """A PI speed loop setting the armature voltage of the DC motor ``motor``
    from the speed ω of ``body`` and the reference ``reference`` (a law in
    time of kind ``reference``):

    .. math:: V_c = k_p\\,(\\omega_{ref} - \\omega) + k_i\\,z, \\qquad
              \\dot z = \\omega_{ref} - \\omega,

    added to the motor's own voltage law. ``limit`` (None: none) bounds the
    motor's torque k i: at ±limit the drive holds the current and z tracks
    the value at which the loop's demand just holds it (anti-windup by
    tracking, :mod:`crane_sym.components.first_order`) until the loop would
    lower the current."""

    name: str
    body: str
    motor: str
    proportional: Value
    integral: Value
    reference: MotorLaw
    limit: Value | None = None
    kind = "speed controller"

    def __init__(self, name: str, body: str, motor: str, proportional: Given,
                 integral: Given, reference: MotorLaw, limit: Given | None = None) -> None:
        name = _name("speed controller", name)
        owner = f"speed controller {name!r}"
        kp, ki = value(owner, "proportional", proportional), value(owner, "integral", integral)
        _at_least(owner, "proportional", kp, 0.0, False)
        _at_least(owner, "integral", ki, 0.0, False)
        cap = None if limit is None else value(owner, "limit", limit)
        if cap is not None:
            _at_least(owner, "limit", cap, 0.0, True)
            _at_least(owner, "integral (a limit's integral tracks it)", ki, 0.0, True)
        for key, v in (("name", name), ("body", body), ("motor", motor), ("proportional", kp),
                       ("integral", ki), ("reference", reference), ("limit", cap)):
            object.__setattr__(self, key, v)

    @property
    def laws(self) -> tuple[MotorLaw, ...]:
        """The laws in time it carries: its speed reference."""
        return (self.reference,)
