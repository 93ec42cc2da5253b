"""``[[brake]]``: a brake on a body, its torque (a force on a translating body)
built up after a delay as a step, a ramp or an exponential.

Its modes: ``engaged`` (from its delay on, until it is released at
``fails_at``) and ``ramping`` (a ramp under way); a ramp's or an
exponential's build-up 0 ≤ β ≤ 1 is a state of its own. Engaged, it holds
its group by friction up to |κ| M β (``friction_capacity``; so it plays the
role ``holds at rest`` undeclared): the system's groups slide against it,
and rest or slip again where their load says so.
"""
import numpy as np
import sympy as sp
from sympy.physics.units import time

from crane_sym.components.acting import force_load
from crane_sym.components.kinds.base import Acting, Key, Kind, failure, load_key, run_end
from crane_sym.components.kinds.events import BACKWARD, FORWARD, FREE, HELD, Events
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


# --- its modes and events ---------------------------------------------------------
TABLE = "brake"


def _at_once(part: Brake) -> bool:
    """Whether it acts from t = 0: a step without delay."""
    return part.delay == 0 and part.build_up == "step"


def _start(part: Brake, rest: bool) -> dict:
    """Engaged at a start at rest if it acts at once (the start decides its
    group's motion); never ramping."""
    return {"engaged": rest and _at_once(part), "ramping": False}


def _names(part: Brake) -> tuple:
    return ((f"{part.name} engages", "engage"), (f"{part.name} ramp done", "ramped"),
            (f"{part.name} releases", "let go"))


def _schedule(part: Brake, rest: bool) -> tuple:
    """Engaging at its delay (but at a start at rest, where it acts at once
    and the start engaged it), released at ``fails_at``, its ramp done."""
    out = [] if rest and _at_once(part) else [(part.delay, f"{part.name} engages")]
    if part.fails_at is not None:
        out.append((part.fails_at, f"{part.name} releases"))
    if part.build_up == "ramp":
        out.append((part.delay + part.time, f"{part.name} ramp done"))
    return tuple(out)


def _column(system, i: int) -> int | None:
    """The column of brake i's build-up β in the state (None for a step)."""
    return system.columns.get((TABLE, i))


def _friction_capacity(designs, mode, i: int):
    """(group, β's column or None, |κ| M per design): what brake i holds while engaged."""
    if not mode.engaged[i]:
        return None
    system = designs.model
    grip = designs.gather((TABLE, i, "grip"), lambda s: abs(s.place(s.of_kind[TABLE][i])[1])
                          * s.of_kind[TABLE][i].load)
    return system.place(system.of_kind[TABLE][i])[0], _column(system, i), grip


def _rates(designs, mode, i: int, A, b) -> None:
    """β' = 1/T on a ramp under way, β' = (1 − β)/T for an exponential
    (A, b: (designs, size, size) and (designs, size))."""
    system = designs.model
    col, part = _column(system, i), system.of_kind[TABLE][i].part
    if col is None or not mode.engaged[i]:
        return
    rate = 1.0 / designs.gather((TABLE, i, "time"), lambda s: s.of_kind[TABLE][i].part.time)
    if part.build_up == "ramp" and mode.ramping[i]:
        b[:, col] = rate
    elif part.build_up == "exponential":
        A[:, col, col], b[:, col] = -rate, rate


def _set(values: tuple, i: int, value) -> list:
    out = list(values)
    out[i] = value
    return out


def _engaged(system, mode, i: int):
    """``mode`` with brake i engaged (ramping if a ramp), and its group."""
    part = system.of_kind[TABLE][i].part
    mode = mode.setting(engaged=_set(mode.engaged, i, True),
                        ramping=_set(mode.ramping, i, part.build_up == "ramp"))
    return mode, system.place(system.of_kind[TABLE][i])[0]


def _engage(system, mode, i: int, x):
    """Engaged (ramping if a ramp): a free group then slides the way it
    moves, or, at rest, is held while its load is within the capacity."""
    mode, g = _engaged(system, mode, i)
    if mode.motion[g] != FREE:
        return mode, x
    speed = x[system.v(g)]
    if speed:
        return mode.moving(g, FORWARD if speed > 0 else BACKWARD), x
    return system.rests(mode, g, x)


def _engage_designs(designs, mode, i: int, x):
    """:func:`_engage` for the designs of one template at once (x: (k, size)):
    the groups at rest settled together (``DesignArray.settled``)."""
    system = designs.model
    mode, g = _engaged(system, mode, i)
    if mode.motion[g] != FREE:
        return [mode] * designs.k, x
    speed = x[:, system.v(g)]
    sliding = {FORWARD: mode.moving(g, FORWARD), BACKWARD: mode.moving(g, BACKWARD)}
    modes = [sliding[FORWARD if s > 0 else BACKWARD] if s else None for s in speed]
    still = np.flatnonzero(speed == 0)
    if still.size:
        x[still, system.v(g)] = 0.0
        for d, motion in zip(still, designs.take(still).settled(mode, g, x[still])):
            modes[d] = mode.moving(g, motion)
    return modes, x


def _ramped(system, mode, i: int, x):
    """Its ramp done: β = 1 from here on."""
    x[_column(system, i)] = 1.0
    return _ramp_done(mode, i), x


def _ramped_designs(designs, mode, i: int, x):
    """:func:`_ramped` for the designs of one template at once (x: (k, size))."""
    x[:, _column(designs.model, i)] = 1.0
    return [_ramp_done(mode, i)] * designs.k, x


def _ramp_done(mode, i: int):
    return mode.setting(ramping=_set(mode.ramping, i, False))


def _let_go(system, mode, i: int, x):
    """Released for good: its group free if no other brake is engaged on it,
    else held only while the rest still hold its load."""
    mode = mode.setting(engaged=_set(mode.engaged, i, False),
                        ramping=_set(mode.ramping, i, False))
    g = system.place(system.of_kind[TABLE][i])[0]
    if not any(on and system.place(system.of_kind[TABLE][k])[0] == g
               for k, on in enumerate(mode.engaged)):
        return mode.moving(g, FREE), x
    if mode.motion[g] == HELD:
        return mode.moving(g, system.settled(mode, g, x)), x
    return mode, x


EVENTS = Events(("engaged", "ramping"), _start, _names,
                {"engage": _engage, "ramped": _ramped, "let go": _let_go},
                together={"engage": _engage_designs, "ramped": _ramped_designs},
                schedule=_schedule, friction_capacity=_friction_capacity,
                states=lambda part: 0 if part.build_up == "step" else 1, rates=_rates)


KIND = Kind(TABLE, (Key("name", "word"), Key("body", "body"),
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
            roles=lambda part: frozenset({"slides"}), counted="brakes", events=EVENTS)
