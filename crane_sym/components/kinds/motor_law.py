"""``[[motor_law]]``: a torque, acceleration or speed law in time, piecewise polynomial
(paper 002's drive laws)."""
import sympy as sp
from sympy.physics.units import time

from crane_sym.components.acting import Load, body_of, same_unit
from crane_sym.components.kinds.base import Acting, Key, Kind, run_end
from crane_sym.components.laws import KINDS, SIGNALS, MotorLaw
from crane_sym.components.parts import DIMENSIONS, UNITS, ComponentError



def _idle(part: MotorLaw, duration: float, rest: bool) -> str | None:
    if part.law == "torque":
        if all(c == 0 for row in part.coefficients for c in row):
            return "its law is 0 throughout"
        if part.breakpoints[0] >= duration:
            return f"its law starts at t = {float(part.breakpoints[0]):g} s, and {run_end(duration)}"
    return None


#: The letter of a law's value by its kind: a torque L, an acceleration a, the
#: torque T a speed law takes.
LETTERS = {"torque": "L", "acceleration": "a", "speed": "T"}


def _acts(part: MotorLaw, kappa: sp.Expr, q: sp.Expr) -> Acting:
    """Its value at t (an acceleration law's drives the rigid drive instead)."""
    value = sp.Symbol(f"{LETTERS[part.law]}_{part.name}", real=True)
    return Acting(None if part.law == "acceleration" else value, (("signals", value),))


#: SI unit of a law's values, by its kind and the body's motion.
LAW_UNITS = {"torque": UNITS["load"], "speed": UNITS["speed"],
             "acceleration": UNITS["acceleration"]}


def _switching(part: MotorLaw, motion: str) -> tuple:
    """Breakpoint k (from 1) in s, and the law's value where piece k starts."""
    unit = LAW_UNITS[part.law][motion]
    times = tuple((f"time_{k}", float(b), time, "s",
                   f"breakpoint {k} of the motor law {part.name}")
                  for k, b in enumerate(part.breakpoints, start=1))
    return times + tuple((f"value_{k}", float(row[0]), part.dimension, unit,
                          f"value of the motor law {part.name} at its breakpoint {k}")
                         for k, row in enumerate(part.coefficients, start=1))


def _check(part: MotorLaw, bodies: dict, components: tuple) -> Load:
    """Its unit against its body's motion: a torque law's a load, an
    acceleration or speed law's its own."""
    body, where = body_of(part, bodies)
    expected = DIMENSIONS["load" if part.law == "torque" else part.law][body.motion]
    same_unit(where, "", part.unit, part.dimension, expected)
    return Load(part, None)


#: What a law of each kind is to the assembly (``Kind.roles``).
ROLES = {"speed": frozenset({"holds at rest", "sets speed"}), "acceleration": frozenset({"balances"}),
         "torque": frozenset()}


def _build(g: dict, entry: dict, where: str) -> MotorLaw:
    """The law; a law that gives no load (a voltage) belongs to its part's own table."""
    if g["law"] in SIGNALS:
        raise ComponentError(f"{where}: law must be one of {', '.join(KINDS)}, got {g['law']!r}")
    return MotorLaw(g["name"], g["body"], g["breakpoints"], g["coefficients"], g["unit"],
                    g["law"], g["time_unit"])


KIND = Kind("motor_law", (Key("name", "word"), Key("body", "body"), Key("law", "word"),
                          Key("unit", "word"), Key("breakpoints", "law"),
                          Key("coefficients", "law"),
                          Key("time_unit", "word", required=False, default="s")),
            _build, "a law in time on a body", "motor law", _idle, acts=_acts,
            switching=_switching, check=_check, roles=lambda part: ROLES[part.law])
