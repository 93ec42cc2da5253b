"""``[[brake]]``: a brake on a body, its torque (a force on a translating body)
built up after a delay as a step, a ramp or an exponential."""
import sympy as sp
from sympy.physics.units import time

from crane_sym.components.acting import force_load
from crane_sym.components.kinds.base import Acting, Key, Kind, failure, load_key, run_end
from crane_sym.components.loads import Brake
from crane_sym.components.parts import DIMENSIONS, ROTATING, UNITS


def _idle(part: Brake, duration: float, rest: bool) -> str | None:
    if part.delay >= duration:
        return f"it engages at t = {part.delay:g} s, and {run_end(duration)}"
    return None


def _acts(part: Brake, kappa: sp.Expr, q: sp.Expr) -> Acting:
    """B: its signed friction, which the mode sets."""
    B = sp.Symbol(f"B_{part.name}", real=True)
    return Acting(B, (("friction", B),))


def _switching(part: Brake, motion: str) -> tuple:
    word = "torque" if motion == ROTATING else "force"
    return ((word, part.load.si, DIMENSIONS["load"][motion], UNITS["load"][motion],
             f"{word} of the brake {part.name}"),
            ("delay", part.delay, time, "s", f"delay of the brake {part.name}"),
            *failure(part, f"the brake {part.name}"))


KIND = Kind("brake", (Key("name", "word"), Key("body", "body"),
                      Key("torque", value="load", sign="positive", required=False),
                      Key("force", value="load", sign="positive", required=False),
                      Key("delay", value=time, sign="nonnegative", required=False, default=0.0),
                      Key("build_up", "word", required=False, default="step"),
                      Key("time", value=time, sign="positive", required=False, default=0.0,
                          when=lambda entry: entry.get("build_up", "step") != "step"),
                      Key("fails_at", value=time, sign="positive", required=False)),
            lambda g, entry, where: Brake(g["name"], g["body"], g[load_key(entry, where)],
                                          g["delay"], g["build_up"], g["time"], g["fails_at"]),
            "a brake on a body", idle=_idle, acts=_acts, switching=_switching,
            check=lambda part, bodies, components: force_load(part, bodies),
            roles=lambda part: frozenset({"holds", "slides"}), counted="brakes")
