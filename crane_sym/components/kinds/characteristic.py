"""``[[characteristic]]``: a motor's β (v0 − v), its slope stepped at the hold times.

Its mode: ``steps``, the step it is on (0 at the start, one more at the end
of each hold time); its slope β the step's, the last one's from there on.
"""
from itertools import accumulate

import numpy as np
import sympy as sp

from crane_sym.components.acting import Load, body_of
from crane_sym.components.kinds.base import Acting, Key, Kind, Symbolic
from crane_sym.components.kinds.events import Events
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


def _next(system, mode, i: int, x):
    """On to the next step."""
    steps = list(mode.steps)
    steps[i] += 1
    return mode.setting(steps=steps), x


def _slope(designs, mode, i: int) -> np.ndarray:
    """Each design's slope on the step it is on (the first where the mode has no steps)."""
    values = designs.gather(("characteristic", i),
                            lambda s: s.of_kind["characteristic"][i].values)
    k = mode.steps[i] if mode.steps else 0
    return values[:, 1 + min(k, values.shape[1] - 2)]


EVENTS = Events(("steps",), lambda part, rest: {"steps": 0},
                lambda part: ((f"{part.name} next step", "step"),), {"step": _next}, plain=frozenset({"step"}),
                schedule=lambda part, rest: tuple((float(t), f"{part.name} next step")
                                                  for t in accumulate(part.holds)),
                role="slopes", value=_slope)


KIND = Kind("characteristic", (Key("name", "word"), Key("body", "body"),
                               Key("speed", value="speed"), Key("slopes", "list"),
                               Key("holds", "list", required=False, default=[])),
            lambda g, entry, where: Characteristic(g["name"], g["body"], g["speed"], g["slopes"],
                                                   g["holds"]),
            "a motor's speed characteristic on a body",
            symbols=(SPEED,), acts=_acts,
            shape=lambda part: len(part.holds), check=_check,
            steps=lambda load: load.values[1:], events=EVENTS)
