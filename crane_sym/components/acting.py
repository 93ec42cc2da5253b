"""What acts on one body, checked against the body's motion: each brake,
motor, law in time, gravity, resistance, characteristic, DC motor and speed
controller as a :class:`Load` with its values in SI (a torque on a shaft, a
force on a mass), or a one-line ComponentError naming the part, its unit and
the one expected. :func:`crane_sym.components.topology.assemble` calls it for
each such part.

May import: ``parts``, ``loads``, ``laws`` and the top-level vocabulary.
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Sequence

from crane_sym import units
from crane_sym.components.laws import MotorLaw
from crane_sym.components.loads import (Characteristic, DCMotor, Gravity, Motor,
                                        SpeedController)
from crane_sym.components.parts import (DIMENSIONS, ROTATING, TRANSLATING, Body, Component,
                                        ComponentError)

__all__ = ["Load", "checked_load"]


@dataclass(frozen=True)
class Load:
    """A brake, motor, gravity or resistance with its torque or force in SI
    (None: a steady motor, solved at the start)."""

    part: Component
    load: float | None
    values: tuple[float, ...] = ()



def checked_load(part: Component, bodies: dict[str, Body],
                 components: Sequence[Component]) -> Load:
    """``part`` (a brake, motor, law, gravity, resistance, characteristic, DC
    motor or speed controller) as a :class:`Load`: its values in SI, each
    checked against the motion of the body it acts on."""
    body = bodies[part.body]
    if isinstance(part, Gravity):
        if body.motion != TRANSLATING:
            raise ComponentError(f"{part.label} acts on {body.label}, which rotates; gravity "
                                 "acts on a mass")
        return Load(part, body.inertia * part.g * (1.0 if part.direction == "+" else -1.0))
    if isinstance(part, Motor) and part.load is None:
        return Load(part, None)
    if isinstance(part, MotorLaw):
        what = ("load" if part.law == "torque" else part.law)
        expected = DIMENSIONS[what][body.motion]
        if not units.same_dimension(part.dimension, expected):
            raise ComponentError(f"{part.label} on {body.label}: its unit {part.unit!r} is "
                                 f"{units.format_dimension(part.dimension)}, expected "
                                 f"{units.describe_dimension(expected)}")
        return Load(part, None)
    if isinstance(part, DCMotor):
        where = f"{part.label} on {body.label}"
        if not units.same_dimension(part.voltage.dimension, units.UNITS["V"][1]):
            raise ComponentError(f"{where}: its voltage unit {part.voltage.unit!r} is "
                                 f"{units.format_dimension(part.voltage.dimension)}, expected "
                                 f"a voltage (e.g. V)")
        k = part.constant.check(where, "constant", DIMENSIONS["motor constant"][body.motion])
        return Load(part, None, (part.resistance.si, part.inductance.si, k))
    if isinstance(part, SpeedController):
        return _controller(part, bodies, components)
    if isinstance(part, Characteristic):
        where = f"{part.label} on {body.label}"
        speed = part.speed.check(where, "speed", DIMENSIONS["speed"][body.motion])
        return Load(part, None, (speed, *(k.check(where, "slope", DIMENSIONS["damping"][body.motion])
                                          for k in part.slopes)))
    word = "torque" if body.motion == ROTATING else "force"
    return Load(part, part.load.check(f"{part.label} on {body.label}", word,
                                      DIMENSIONS["load"][body.motion]))


def _controller(part: SpeedController, bodies: dict[str, Body],
                components: Sequence[Component]) -> Load:
    """A speed controller's gains (volts per speed, per displacement) and torque
    limit in SI, checked by the motion of its body and of its DC motor's."""
    body = bodies[part.body]
    where = f"{part.label} on {body.label}"
    motors = {p.name: p for p in components if isinstance(p, DCMotor)}
    if part.motor not in motors:
        raise ComponentError(f"{where}: motor {part.motor!r} is no dc_motor; dc motors: "
                             f"{', '.join(motors) or 'none'}")
    if not units.same_dimension(part.reference.dimension, DIMENSIONS["speed"][body.motion]):
        raise ComponentError(f"{where}: its reference unit {part.reference.unit!r} is "
                             f"{units.format_dimension(part.reference.dimension)}, expected "
                             f"{units.describe_dimension(DIMENSIONS['speed'][body.motion])}")
    gains = (part.proportional.check(where, "proportional",
                                     DIMENSIONS["voltage per speed"][body.motion]),
             part.integral.check(where, "integral",
                                 DIMENSIONS["voltage per displacement"][body.motion]))
    if part.limit is None:
        return Load(part, None, (*gains, None))
    motion = bodies[motors[part.motor].body].motion
    return Load(part, None, (*gains, part.limit.check(where, "limit",
                                                      DIMENSIONS["load"][motion])))
