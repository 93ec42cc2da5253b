"""``[[characteristic]]``: a motor's β (v0 − v), its slope stepped at the hold times."""
import sympy as sp

from crane_sym.components.acting import Load, body_of
from crane_sym.components.kinds.base import Acting, Key, Kind, Symbolic
from crane_sym.components.loads import Characteristic
from crane_sym.components.parts import DIMENSIONS

SPEED = Symbolic("speed", "v0", "real", lambda load: load.values[0],
                 "no-load speed of the characteristic {name}")


def _acts(part: Characteristic, kappa: sp.Expr, q: sp.Expr) -> Acting:
    """β (v0 − v), v = κ q̇ the body's speed; β is the mode's step."""
    beta = sp.Symbol(f"beta_{part.name}", positive=True)
    v = kappa * q.diff(q.args[0])
    return Acting(beta * (SPEED.symbol(part.name) - v), (("slopes", beta),))


def _check(part: Characteristic, bodies: dict, components: tuple) -> Load:
    """Its no-load speed, then its slopes (a damping each), in SI."""
    body, where = body_of(part, bodies)
    speed = part.speed.check(where, "speed", DIMENSIONS["speed"][body.motion])
    return Load(part, None, (speed, *(k.check(where, "slope", DIMENSIONS["damping"][body.motion])
                                      for k in part.slopes)))


KIND = Kind("characteristic", (Key("name", "word"), Key("body", "body"),
                               Key("speed", value="speed"), Key("slopes", "list"),
                               Key("holds", "list", required=False, default=[])),
            lambda g, entry, where: Characteristic(g["name"], g["body"], g["speed"], g["slopes"],
                                                   g["holds"]),
            "a motor's speed characteristic on a body",
            symbols=(SPEED,), acts=_acts,
            shape=lambda part: len(part.holds), check=_check,
            steps=lambda load: load.values[1:])
