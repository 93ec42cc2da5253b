"""A kind switches the model from its one module (``Kind.events``,
:mod:`crane_sym.components.kinds.events`): a toy ratchet, registered for the
test only, catches a body the instant it would move back and holds it there.
Its event time and the peak it locks in are checked against their closed
forms.

    ground --[ spring c, damper d ]-- mass m <-- force F, ratchet

From rest, x(t) = (F/c) (1 − e^(−σt) (cos ω_d t + σ/ω_d sin ω_d t)), σ = ζω;
its speed first returns to 0 at t* = π/ω_d, where x = (F/c)(1 + e^(−σπ/ω_d)).
The link's load c x + d ẋ = F (1 − e^(−σt) (cos ω_d t − σ/ω_d sin ω_d t))
peaks before that, at ω_d t_p = π − atan(2σω_d / (ω_d² − σ²)). The ratchet
catches the mass at t*: the link holds c x(t*) = F (1 + e^(−σπ/ω_d)) to the
end of the run, where without the ratchet the mass would swing back.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, replace
from pathlib import Path

import numpy as np
import pytest
import sympy as sp

from crane_sym.components import kinds
from crane_sym.components.acting import Load
from crane_sym.components.kinds import Key, Kind
from crane_sym.components.kinds.base import Acting
from crane_sym.components.kinds.events import HELD, Events
from crane_sym.components.loads import Resistance
from crane_sym.components.component_file import read_component_file


# --- the toy kind: one module's worth, as ARCHITECTURE.md "How to add a kind" shows ---
@dataclass(frozen=True, init=False)
class Ratchet(Resistance):
    """A one-way stop on a body: no force of its own; it catches the body the
    instant its speed returns to 0 and holds it there for good."""

    kind = "ratchet"


def _caught(mode, i: int) -> bool:
    values = mode.of("caught")
    return bool(values[i])


def _group(system, i: int) -> int:
    return system.place(system.of_kind["ratchet"][i])[0]


def _guards(designs, mode, i: int) -> tuple:
    """Free, its body moving forwards: caught where the speed falls through 0
    (the same guard for every design of ``designs``)."""
    if _caught(mode, i):
        return ()
    system = designs.model
    w = np.zeros(system.size)
    w[system.v(_group(system, i))] = 1.0
    name = system.of_kind["ratchet"][i].part.name
    return ((f"{name} catches", w, 0.0, -1),)


def _catch(system, mode, i: int, x):
    """Caught: its body's group held at rest for good."""
    g = _group(system, i)
    x[system.v(g)] = 0.0
    caught = list(mode.of("caught"))
    caught[i] = True
    return mode.setting(caught=caught).moving(g, HELD), x


RATCHET = Kind(
    "ratchet", (Key("name", "word"), Key("body", "body")),
    lambda g, entry, where: Ratchet(g["name"], g["body"], 0.0),
    "a one-way stop that catches a body when it would move back",
    acts=lambda part, kappa, q: Acting(sp.Integer(0)),
    check=lambda part, bodies, components: Load(part, None),
    events=Events(("caught",), lambda part, rest: {"caught": False},
                  lambda part: ((f"{part.name} catches", "catch"),), {"catch": _catch},
                  guards=_guards,
                  fixes=lambda system, mode, i: _group(system, i) if _caught(mode, i) else None))
# -------------------------------------------------------------------------------------

M, C, D, F = 200.0, 8.0e4, 400.0, 1.0e3          # kg, N/m, N·s/m, N

FILE = f"""
[model]
name = "ratchet"

[[mass]]
name = "slider"
mass = "{M} kg"

[[elastic]]
name = "spring"
between = ["ground", "slider"]
stiffness = "{C} N/m"
damping = "{D} N*s/m"

[[resistance]]
name = "push"
body = "slider"
force = "{F} N"

{{ratchet}}

[run]
duration = "0.5 s"
start = "rest"
"""
STOP = '[[ratchet]]\nname = "stop"\nbody = "slider"'


def _run(tmp_path: Path, ratchet: str):
    path = tmp_path / "ratchet.toml"
    path.write_text(FILE.format(ratchet=ratchet), encoding="utf-8")
    f = read_component_file(path)
    return f.model.run(f.duration, f.body, f.speed, rest=f.rest)


def test_a_kind_with_its_own_switching_runs_from_its_one_module(tmp_path, monkeypatch):
    monkeypatch.setattr(kinds, "KINDS", [*kinds.KINDS, RATCHET])
    omega = math.sqrt(C / M)
    sigma = D / (2 * M)
    omega_d = math.sqrt(omega**2 - sigma**2)
    t_catch = math.pi / omega_d
    locked = F * (1 + math.exp(-sigma * t_catch))
    t_peak = (math.pi - math.atan(2 * sigma * omega_d / (omega_d**2 - sigma**2))) / omega_d
    peak = F * (1 - math.exp(-sigma * t_peak) * (math.cos(omega_d * t_peak)
                                                 - sigma / omega_d * math.sin(omega_d * t_peak)))

    run = _run(tmp_path, STOP)
    assert [e for _, e in run.events] == ["stop catches"]
    t, _ = run.events[0]
    assert abs(t - t_catch) <= 1e-9 * t_catch
    assert abs(abs(run.peaks[0].value) - peak) <= 1e-9 * peak
    # caught: held at rest, the link at c x(t*) to the end of the run
    last = run.result.segments[-1]
    assert last.mode.motion == (HELD,) and last.mode.of("caught") == (True,)
    w, k = run.system.link_load(0)(last.mode)
    end = run.result.state(np.array([run.t_end]))[0]
    assert abs(abs(float(w @ end + k)) - locked) <= 1e-9 * locked

    # without it the spring swings back: its load at the end is far from the peak
    monkeypatch.setattr(kinds, "KINDS", [k for k in kinds.KINDS if k is not RATCHET])
    free = _run(tmp_path, "")
    assert free.events == [] and abs(abs(free.peaks[0].value) - peak) <= 1e-9 * peak
    w, k = free.system.link_load(0)(free.result.segments[-1].mode)
    swung = float(w @ free.result.state(np.array([free.t_end]))[0] + k)
    assert abs(abs(swung) - locked) > 0.05 * locked


def test_an_unregistered_switching_kind_is_an_unknown_table(tmp_path):
    from crane_sym.components import ComponentError
    with pytest.raises(ComponentError, match="unknown table 'ratchet'"):
        _run(tmp_path, STOP)


def test_holding_at_rest_follows_from_a_friction_capacity():
    """The role ``holds at rest`` is derived from ``Events.friction_capacity``:
    the brake declares only ``slides`` yet plays it; the ratchet, which keeps
    its group still itself (``fixes``), plays it once its events give a
    capacity; a speed law, which holds without friction, declares it."""
    from crane_sym.components.kinds import brake, motor_law
    from crane_sym.components.kinds.roles import has_role
    assert brake.KIND.roles(None) == frozenset({"slides"})
    assert has_role(brake.KIND, None, "holds at rest")
    assert not has_role(RATCHET, None, "holds at rest")
    gripping = replace(RATCHET, events=replace(RATCHET.events,
                                               friction_capacity=lambda system, mode, i: None))
    assert has_role(gripping, None, "holds at rest")
    speed = type("Law", (), {"law": "speed"})()
    assert has_role(motor_law.KIND, speed, "holds at rest")
    with pytest.raises(KeyError, match="no role 'holds'"):
        has_role(brake.KIND, None, "holds")
