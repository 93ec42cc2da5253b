"""``[[speed_controller]]``: a PI loop on a body's speed setting a DC motor's
armature voltage, its integral a first-order state, with an optional torque
limit as a mode (conditional integration while at the limit)."""
import sympy as sp

from crane_sym.components.acting import Load, body_of, same_unit
from crane_sym.components.kinds.base import Acting, Key, Kind, Symbolic
from crane_sym.components.laws import MotorLaw
from crane_sym.components.loads import DCMotor, SpeedController
from crane_sym.components.parts import DIMENSIONS, ComponentError

PROPORTIONAL = Symbolic("proportional", "kp", "nonnegative", lambda load: load.values[0],
                        "proportional gain of the speed controller {name}")
INTEGRAL = Symbolic("integral", "ki", "nonnegative", lambda load: load.values[1],
                    "integral gain of the speed controller {name}")
LIMIT = Symbolic("limit", "Tmax", "positive", lambda load: load.values[2],
                 "torque limit of the speed controller {name}")


def _acts(part: SpeedController, kappa: sp.Expr, q: sp.Expr) -> Acting:
    """No force of its own: z' = ω_ref − ω, and k_p (ω_ref − ω) + k_i z added to
    its motor's L di/dt; the limit keeps k i within ±T_max, z tracking."""
    z, ref = sp.Symbol(f"z_{part.name}", real=True), sp.Symbol(f"ref_{part.name}", real=True)
    i = sp.Symbol(f"i_{part.motor}", real=True)
    L, k = (sp.Symbol(f"{x}_{part.motor}", positive=True) for x in "Lk")
    kp, ki = PROPORTIONAL.symbol(part.name), INTEGRAL.symbol(part.name)
    error = ref - kappa * q.diff(q.args[0])
    limits = () if part.limit is None else ((i, LIMIT.symbol(part.name) / k, z),)
    return Acting(sp.Integer(0), (("signals", ref),),
                  states=((z, error), (i, (kp * error + ki * z) / L)), limits=limits)


def _check(part: SpeedController, bodies: dict, components: tuple) -> Load:
    """Its gains (volts per speed, per displacement) and torque limit in SI,
    checked by the motion of its body and of its DC motor's."""
    body, where = body_of(part, bodies)
    motors = {p.name: p for p in components if isinstance(p, DCMotor)}
    if part.motor not in motors:
        raise ComponentError(f"{where}: motor {part.motor!r} is no dc_motor; dc motors: "
                             f"{', '.join(motors) or 'none'}")
    same_unit(where, "reference", part.reference.unit, part.reference.dimension,
              DIMENSIONS["speed"][body.motion])
    gains = (part.proportional.check(where, "proportional",
                                     DIMENSIONS["voltage per speed"][body.motion]),
             part.integral.check(where, "integral",
                                 DIMENSIONS["voltage per displacement"][body.motion]))
    if part.limit is None:
        return Load(part, None, (*gains, None))
    motion = bodies[motors[part.motor].body].motion
    return Load(part, None, (*gains, part.limit.check(where, "limit",
                                                      DIMENSIONS["load"][motion])))


def _build(g: dict, entry: dict, where: str) -> SpeedController:
    reference = MotorLaw(g["name"], g["body"], g["breakpoints"], g["coefficients"], g["unit"],
                         "reference", g["time_unit"])
    return SpeedController(g["name"], g["body"], g["motor"], g["proportional"], g["integral"],
                           reference, g["limit"])


KIND = Kind("speed_controller",
            (Key("name", "word"), Key("body", "body"), Key("motor", "word"),
             Key("proportional", value="voltage per speed", sign="nonnegative"),
             Key("integral", value="voltage per displacement", sign="nonnegative"),
             Key("breakpoints", "law"), Key("coefficients", "law"), Key("unit", "word"),
             Key("time_unit", "word", required=False, default="s"),
             Key("limit", value="load", sign="positive", required=False)),
            _build, "a PI speed loop setting a DC motor's voltage, with a torque limit",
            "speed controller", symbols=(PROPORTIONAL, INTEGRAL, LIMIT), acts=_acts,
            check=_check)
