"""``[[dc_motor]]``: a DC motor's armature on a body, its current a first-order
state driven by a voltage law in time (written as a motor law's table)."""
import sympy as sp

from crane_sym.components.kinds.base import Acting, Key, Kind, Symbolic
from crane_sym.components.laws import MotorLaw
from crane_sym.components.loads import HENRY, OHM, DCMotor

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
            symbols=(RESISTANCE, INDUCTANCE, CONSTANT), acts=_acts)
