"""``[[gravity]]``: the weight of a translating body along its coordinate."""
import sympy as sp
from sympy.physics.units import length, time

from crane_sym.components.acting import Load
from crane_sym.components.kinds.base import Acting, Key, Kind, Symbolic
from crane_sym.components.loads import Gravity
from crane_sym.components.parts import TRANSLATING, ComponentError

G = Symbolic("g", "g", "positive", lambda load: load.part.g,
             "acceleration of the gravity {name} on {body}")


def _acts(part: Gravity, kappa: sp.Expr, q: sp.Expr) -> Acting:
    """± m g along the body's coordinate."""
    m = sp.Symbol(f"m_{part.body}", positive=True)
    return Acting(m * G.symbol(part.name) * (1 if part.direction == "+" else -1), constant=True)


def _check(part: Gravity, bodies: dict, components: tuple) -> Load:
    """± m g on a mass; a rotating body takes no weight."""
    body = bodies[part.body]
    if body.motion != TRANSLATING:
        raise ComponentError(f"{part.label} acts on {body.label}, which rotates; gravity "
                             "acts on a mass")
    return Load(part, body.inertia * part.g * (1.0 if part.direction == "+" else -1.0))


KIND = Kind("gravity", (Key("name", "word"), Key("body", "body"),
                        Key("g", value=length / time**2, sign="nonnegative", required=False,
                            default="9.81 m/s^2"),
                        Key("direction", "word", required=False, default="+")),
            lambda g, entry, where: Gravity(g["name"], g["body"], g["g"], g["direction"]),
            "the weight of a translating body",
            idle=lambda part, duration, rest: "g is 0" if part.g == 0 else None,
            symbols=(G,), acts=_acts, check=_check)
