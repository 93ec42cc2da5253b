"""``[[dc_motor]]``: a DC motor's armature on a body, its current a first-order
state driven by a voltage law in time (written as a motor law's table)."""
import sympy as sp
from sympy.physics.units import time

from crane_sym import units
from crane_sym.components.acting import Load, body_of, same_unit
from crane_sym.components.kinds.base import Acting, Key, Kind, PartQuantity, Symbolic
from crane_sym.components.laws import MotorLaw
from crane_sym.components.loads import HENRY, OHM, DCMotor
from crane_sym.components.parts import DIMENSIONS

RESISTANCE = Symbolic("resistance", "R", "positive", lambda load: load.values[0],
                      "armature resistance of the DC motor {name}")
INDUCTANCE = Symbolic("inductance", "L", "positive", lambda load: load.values[1],
                      "armature inductance of the DC motor {name}")
CONSTANT = Symbolic("constant", "k", "positive", lambda load: load.values[2],
                    "torque (back-emf) constant of the DC motor {name}")


def _acts(part: DCMotor, kappa: sp.Expr, q: sp.Expr) -> Acting:
    """k i on the body; L di/dt = V − R i − k ω, ω = κ q̇ the body's speed."""
    i, V = sp.Symbol(f"i_{part.name}", real=True), sp.Symbol(f"V_{part.name}", real=True)
    R, L, k = (s.symbol(part.name) for s in (RESISTANCE, INDUCTANCE, CONSTANT))
    omega = kappa * q.diff(q.args[0])
    return Acting(k * i, (("signals", V),), states=((i, (V - R * i - k * omega) / L),),
                  outputs=(("current", "A", i), ("torque", "load", k * i),
                           ("speed", "speed", omega)))


def _check(part: DCMotor, bodies: dict, components: tuple) -> Load:
    """Its voltage's unit, and R, L and k in SI (k by its body's motion)."""
    body, where = body_of(part, bodies)
    same_unit(where, "voltage", part.voltage.unit, part.voltage.dimension,
              units.UNITS["V"][1], "a voltage (e.g. V)")
    k = part.constant.check(where, "constant", DIMENSIONS["motor constant"][body.motion])
    return Load(part, None, (part.resistance.si, part.inductance.si, k))


def _time_constant(part: DCMotor, kappa: sp.Expr, q: sp.Expr, inertia: sp.Expr) -> sp.Expr:
    """τ = J_red / (−∂F/∂ω), F = k i with its current where L di/dt = 0."""
    acts = _acts(part, kappa, q)
    (current, rate), = acts.states
    speed = sp.Dummy("omega")
    force = acts.force.subs(current, sp.solve(rate, current)[0])
    force = force.subs(q.diff(q.args[0]), speed / kappa)
    return inertia / -sp.diff(force, speed)


TIME_CONSTANT = PartQuantity(
    "time_constant", "its mechanical time constant: the reduced inertia over the slope of its "
    "torque against speed, the armature's inductance neglected", time, "s",
    "the reduced inertia of its body over −∂F/∂ω, F = k i with L di/dt = 0 "
    "(i = (V − k ω)/R)", _time_constant)


def _build(g: dict, entry: dict, where: str) -> DCMotor:
    voltage = MotorLaw(g["name"], g["body"], g["breakpoints"], g["coefficients"], g["unit"],
                       "voltage", g["time_unit"])
    return DCMotor(g["name"], g["body"], g["resistance"], g["inductance"], g["constant"],
                   voltage)


KIND = Kind("dc_motor", (Key("name", "word"), Key("body", "body"),
                         Key("resistance", value=OHM, sign="positive"),
                         Key("inductance", value=HENRY, sign="positive"),
                         Key("constant", value="motor constant", sign="positive"),
                         Key("breakpoints", "law"), Key("coefficients", "law"),
                         Key("unit", "word", required=False, default="V"),
                         Key("time_unit", "word", required=False, default="s")),
            _build, "a DC motor's armature on a body, its voltage a law in time", "dc motor",
            symbols=(RESISTANCE, INDUCTANCE, CONSTANT), acts=_acts, check=_check,
            quantities=(TIME_CONSTANT,))
