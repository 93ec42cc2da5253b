"""``[[motor]]``: a constant (or ``steady``) torque on a body, optionally switched off.

Its mode: ``driven``, on from the start until ``off_at``; its switch ``on``
is 1 while driven, else 0.
"""
import sympy as sp
from sympy.physics.units import time

from crane_sym.components.acting import Load, force_load
from crane_sym.components.kinds.base import Acting, Key, Kind, Symbolic, load_key
from crane_sym.components.kinds.events import Events
from crane_sym.components.loads import Motor


def _idle(part: Motor, duration: float, rest: bool) -> str | None:
    if part.load is not None:
        if part.load.si == 0:
            return "its torque is 0"
        if rest and part.off_at == 0:
            return "it is switched off at t = 0 and the run starts at rest"
    return None


TORQUE = Symbolic("torque", "M", "real", lambda load: load.load,
                  "{key} of the motor {name} on {body}")


def _acts(part: Motor, kappa: sp.Expr, q: sp.Expr) -> Acting:
    """on·M: its torque while switched on."""
    on, M = sp.Symbol(f"on_{part.name}", real=True), TORQUE.symbol(part.name)
    return Acting(on * M, (("switches", on), ("motor_loads", M)), constant=True)


def _check(part: Motor, bodies: dict, components: tuple) -> Load:
    """Its torque in SI; a steady motor's is solved at the start."""
    return Load(part, None) if part.load is None else force_load(part, bodies)


def _off(system, mode, i: int, x):
    """Switched off for good."""
    driven = list(mode.driven)
    driven[i] = False
    return mode.setting(driven=driven), x


EVENTS = Events(("driven",), lambda part, rest: {"driven": True},
                lambda part: ((f"{part.name} off", "off"),), {"off": _off}, plain=frozenset({"off"}),
                schedule=lambda part, rest: (() if part.off_at is None else
                                             ((part.off_at, f"{part.name} off"),)),
                role="switches", value=lambda designs, mode, i: 1.0 if mode.driven[i] else 0.0)


KIND = Kind("motor", (Key("name", "word"), Key("body", "body"),
                      Key("torque", value="load", sign="positive", required=False),
                      Key("force", value="load", sign="positive", required=False),
                      Key("off_at", value=time, sign="nonnegative", required=False)),
            lambda g, entry, where: Motor(g["name"], g["body"], g[load_key(entry, where)],
                                          g["off_at"]),
            "a motor's constant or steady torque on a body", idle=_idle,
            symbols=(TORQUE,), acts=_acts, check=_check,
            roles=lambda part: frozenset({"steady"} if part.load is None else ()), events=EVENTS)
