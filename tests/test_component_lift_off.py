"""A load lifted off the ground and set down again
(examples/drive_trains/lift_off.toml: [[ground_contact]]): the hoisting factor
ψ = 1 + (v/g)√(c/m) and the lift-off time m g/(c v) against their closed forms,
derived here with SymPy, and the whole run (events, rope force, the ground's
reaction) against solve_ivp with events."""
from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest
import sympy as sp

from crane_sym.cli.main import main
from crane_sym.components.component_file import read_component_file
from hybrid_references import lift_off_reference

EXAMPLE = Path(__file__).resolve().parents[1] / "examples" / "drive_trains" / "lift_off.toml"
M, C, G = 10000.0, 2.0e6, 9.81                           # the example's values
SPEEDS, BREAKS = (-0.2, 0.15, 0.0), (0.0, 0.6895382938, 1.6089226855)
V, DURATION = -SPEEDS[0], 2.5                             # the hoisting speed, up


@pytest.fixture(scope="module")
def run():
    read = read_component_file(EXAMPLE)
    return read.model.run(read.duration, read.body, read.speed, rest=read.rest)


def _lift():
    """The lift in the parts' symbols, y up from the ground, the drive's end at
    v t, F = c (v t − y): resting, the ground carries m g − c v t until t1 =
    m g/(c v); then m ÿ = F − m g from y = ẏ = 0 at t1. Returns (t1, F(t))."""
    m, c, g, v, t = sp.symbols("m c g v t", positive=True)
    t1 = sp.solve(sp.Eq(c * v * t, m * g), t)[0]
    y = sp.Function("y")
    motion = sp.dsolve(sp.Eq(m * y(t).diff(t, 2), c * (v * t - y(t)) - m * g), y(t),
                       ics={y(t1): 0, y(t).diff(t).subs(t, t1): 0}).rhs
    return (m, c, g, v, t), t1, sp.simplify(c * (v * t - motion))


def test_the_example_holds_the_values_the_test_derives_with(run):
    a = run.system.assembly
    assert a.bodies["load"].inertia == M and a.links[0].stiffness == C
    law = next(l.part for l in a.loads if l.part.name == "hoist")
    assert [law.value_at(t + 1e-9) for t in BREAKS] == pytest.approx(SPEEDS, abs=1e-12)


def test_psi_and_the_lift_off_time_against_their_closed_forms(run):
    """The exact condition: ψ is the run's peak when the drive still hoists at
    v at the first maximum after lift-off (t1 + π/(2ω) before it turns) and
    the lowering's swing about m g, w √(c m), stays below the lift's."""
    (m, c, g, v, t), t1, force = _lift()
    omega = sp.sqrt(c / m)
    swing = sp.simplify(force - m * g)
    assert sp.simplify(swing - v * sp.sqrt(c * m) * sp.sin(omega * (t - t1))) == 0
    psi = 1 + swing.subs(t, t1 + sp.pi / (2 * omega)) / (m * g)
    assert sp.simplify(psi - (1 + v / g * sp.sqrt(c / m))) == 0
    values = {m: M, c: C, g: G, v: V}
    lifted, peak_at = float(t1.subs(values)), float((t1 + sp.pi / (2 * omega)).subs(values))
    assert peak_at < BREAKS[1] and SPEEDS[1] < V              # the exact condition holds
    rope = run.peaks[0]
    assert rope.factor == pytest.approx(float(psi.subs(values)), rel=1e-9)
    assert rope.factor == pytest.approx(1 + V / G * math.sqrt(C / M), rel=1e-9)
    assert rope.time == pytest.approx(peak_at, rel=1e-9)
    assert run.events[0] == (pytest.approx(M * G / (C * V), rel=1e-9), "ground_support lifts off")
    assert lifted == pytest.approx(M * G / (C * V), rel=1e-12)


def test_the_run_against_solve_ivp_with_events(run):
    found, state, drive = lift_off_reference(M, C, G, SPEEDS, BREAKS, DURATION)
    contacts = [(t, e.removeprefix("ground_support ")) for t, e in run.events
                if e.startswith("ground_support")]
    assert [e for _, e in contacts] == [e for _, e in found] == ["lifts off", "sets down"]
    for (t, _), (t_ref, _) in zip(contacts, found):
        assert t == pytest.approx(t_ref, abs=1e-9)
    times = np.linspace(0.0, DURATION, 2001)
    ref = C * (state(times) - np.array([drive(t) for t in times]))
    got = np.array([_at(run, run.system.link_load(0), t) for t in times])
    assert np.abs(got - ref).max() < 1e-9 * M * G
    reaction = np.array([_at(run, run.system.contact_load(0), t) for t in times])
    resting = (times <= found[0][0]) | (times >= found[1][0])
    assert np.abs(reaction - np.where(resting, M * G - ref, 0.0)).max() < 1e-9 * M * G
    assert (reaction >= -1e-9 * M * G).all() and (ref >= -1e-9 * M * G).all()  # rope taut
    (peak,) = run.reactions
    assert peak.start == pytest.approx(M * G, rel=1e-12)
    assert peak.value == pytest.approx(max(reaction.max(), M * G), rel=1e-9)


def _at(run, affine, t: float) -> float:
    """An output w·x + k of the run at time t, from the phase that holds t."""
    seg = next(s for s in run.result.segments if s.t0 <= t <= s.t1)
    w, k = affine(seg.mode)
    return float(np.asarray(w) @ run.result.state(np.array(t)) + k)


def test_the_walkthrough_shows_the_contact(tmp_path):
    page = tmp_path / "page.md"
    assert main(["walkthrough", str(EXAMPLE), "--out", str(page), "-q"]) == 0
    text = page.read_text(encoding="utf-8")
    assert "| ground_support | ground_contact | load | direction = + |" in text
    assert "ground_support lifts off" in text and "ground_support sets down" in text
    assert "| ground_support | 98100.0 N | 0.00000 s | 98100.0 N |" in text
