"""Failures (``fails_at``): a link cut and a brake released at an instant, run
against closed forms: two reeves from the ground, one breaking (the step on a
single mass: peak = static + 2 jump), a reeve breaking under a jib on its own
stiffness (the two-mass modes), and a load dropped onto its rope by a brake
that releases (twice its weight)."""
from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest
from scipy.linalg import eigh
from scipy.optimize import minimize_scalar

from component_commands import swept, walkthrough
from crane_sym.components.parameters import parameters
from crane_sym.components.component_file import read_component_file

EXAMPLE = (Path(__file__).resolve().parents[1] / "examples" / "drive_trains"
           / "jib_reeve_failure.toml")
G = 9.81
M_TIP, M_LOAD, K_JIB, C_REEVE, T_BREAK = 4e3, 20e3, 4e6, 3e6, 0.5     # the example's
TWO_REEVES = """
[model]
name = "two_reeves"

[[mass]]
name = "load"
mass = "{m} kg"

[[elastic]]
name = "reeve_a"
between = ["ground", "load"]
stiffness = "{ca} N/m"

[[elastic]]
name = "reeve_b"
between = ["ground", "load"]
stiffness = "{cb} N/m"
fails_at = "{t0} s"

[[gravity]]
name = "weight"
body = "load"

[run]
duration = "{t1} s"
"""


def _run(path: Path):
    read = read_component_file(path)
    return read.model.run(read.duration, read.body, read.speed, rest=read.rest)


def _peak(run, link: str):
    return next(p for p in run.peaks if p.link == link)


def test_the_remaining_reeve_takes_static_plus_twice_the_jump(tmp_path):
    """One mass on two ropes from the ground: before the break x0 = m g/(ca +
    cb), after it m ẍ = m g − ca x from x0 at rest, so x swings about m g/ca
    with amplitude m g/ca − x0 and reeve a peaks at ca (2 m g/ca − x0) = 2 m g −
    ca x0 at t0 + π/ω: its static load ca x0 plus twice the jump m g − ca x0."""
    m, ca, cb, t0 = 8e3, 2e6, 1e6, 0.3
    omega = math.sqrt(ca / m)
    path = tmp_path / "two_reeves.toml"
    path.write_text(TWO_REEVES.format(m=m, ca=ca, cb=cb, t0=t0, t1=t0 + 1.5 * math.pi / omega))
    run = _run(path)
    share = ca * m * G / (ca + cb)
    expected = share + 2 * (m * G - share)
    a, b = _peak(run, "reeve_a"), _peak(run, "reeve_b")
    print(f"reeve_a {a.value!r} N at {a.time!r} s; static + 2 jump {expected!r} N at "
          f"{t0 + math.pi / omega!r} s; events {run.events!r}")
    assert run.events == [(t0, "reeve_b breaks")]
    assert abs(a.value - expected) <= 1e-9 * expected
    assert abs(a.time - (t0 + math.pi / omega)) <= 1e-6 / omega
    assert abs(a.static - share) <= 1e-9 * share
    assert abs(b.value - (m * G - share)) <= 1e-9 * m * G       # its load until it broke


def test_a_link_that_only_fails_carries_its_load_from_a_start_at_rest(tmp_path):
    """From rest at the ropes' unstretched length both reeves pull before the
    break: the load swings about m g/(ca + cb), reeve b peaks at twice its
    share, 2 cb m g/(ca + cb), at π/ω, ω² = (ca + cb)/m (the run ends before
    the break)."""
    m, ca, cb = 8e3, 2e6, 1e6
    omega = math.sqrt((ca + cb) / m)
    path = tmp_path / "two_reeves.toml"
    path.write_text(TWO_REEVES.format(m=m, ca=ca, cb=cb, t0=10.0, t1=1.5 * math.pi / omega)
                    + 'start = "rest"\n')
    b = _peak(_run(path), "reeve_b")
    expected = 2 * cb * m * G / (ca + cb)
    print(f"reeve_b {b.value!r} N at {b.time!r} s; twice its share {expected!r} N")
    assert abs(b.value - expected) <= 1e-9 * expected
    assert abs(b.time - math.pi / omega) <= 1e-6 / omega


def _jib_after_break():
    """The tip and the load after the break, x = (x_tip, x_load) from the
    unloaded ropes: M ẍ + K x = f, from the old balance at rest; modes by
    eigh(K, M). Returns the forces of reeve a and the jib as functions of τ."""
    Mm = np.diag([M_TIP, M_LOAD])
    f = np.array([M_TIP * G, M_LOAD * G])

    def stiffness(c):
        return np.array([[K_JIB + c, -c], [-c, c]])
    before, after = np.linalg.solve(stiffness(2 * C_REEVE), f), np.linalg.solve(
        stiffness(C_REEVE), f)
    w2, phi = eigh(stiffness(C_REEVE), Mm)           # phi.T M phi = 1
    amplitudes = phi.T @ Mm @ (before - after)
    omegas = np.sqrt(w2)

    def x(tau):
        return after + phi @ (amplitudes * np.cos(omegas * tau))
    return (lambda tau: C_REEVE * (x(tau)[1] - x(tau)[0]), lambda tau: K_JIB * x(tau)[0])


@pytest.mark.parametrize("link,which", [("reeve_a", 0), ("jib", 1)])
def test_a_reeve_breaking_under_the_jib_peaks_as_the_two_mass_modes(link, which):
    run = _run(EXAMPLE)
    force = _jib_after_break()[which]
    peak = _peak(run, link)
    tau = peak.time - T_BREAK
    best = minimize_scalar(lambda s: -force(s), bounds=(tau - 0.02, tau + 0.02),
                           method="bounded", options={"xatol": 1e-12})
    print(f"{link}: run {peak.value!r} N at {peak.time!r} s; modes {-best.fun!r} N at "
          f"{T_BREAK + best.x!r} s")
    assert abs(peak.value + best.fun) <= 1e-9 * abs(best.fun)
    assert abs(tau - best.x) <= 1e-6
    for t in (0.6, 0.9, 1.3, 1.9):                   # the loads along the run
        segment = next(s for s in run.result.segments if s.t0 <= t <= s.t1)
        w, k = run.system.link_load([l.part.name for l in run.system.assembly.links]
                                    .index(link))(segment.mode)
        value = float(np.asarray(w) @ segment.state(np.array(t)) + k)
        assert abs(value - force(t - T_BREAK)) <= 1e-9 * abs(best.fun)


def test_a_brake_that_releases_drops_the_load_onto_its_rope(tmp_path):
    """A load held by a brake at its rope's unstretched length (start at rest)
    is let go at t0: F = m g (1 − cos ω (t − t0)), peak 2 m g at t0 + π/ω."""
    m, c, t0 = 5e3, 1e6, 0.2
    omega = math.sqrt(c / m)
    path = tmp_path / "dropped.toml"
    path.write_text(f"""
[model]
name = "dropped"

[[mass]]
name = "load"
mass = "{m} kg"

[[elastic]]
name = "rope"
between = ["ground", "load"]
stiffness = "{c} N/m"
reference = "{m * G} N"

[[gravity]]
name = "weight"
body = "load"

[[brake]]
name = "holding"
body = "load"
force = "100 kN"
fails_at = "{t0} s"

[run]
duration = "{t0 + 1.5 * math.pi / omega} s"
start = "rest"
""")
    run = _run(path)
    peak = run.peaks[0]
    print(f"peak {peak.value!r} N at {peak.time!r} s (factor {peak.factor!r}); events "
          f"{run.events!r}")
    assert [e for _, e in run.events] == ["holding releases"]
    assert abs(peak.value - 2 * m * G) <= 1e-9 * m * G
    assert abs(peak.factor - 2) <= 1e-9
    assert abs(peak.time - (t0 + math.pi / omega)) <= 1e-6 / omega


def test_the_instant_of_a_failure_is_a_value_a_formula_names_and_a_sweep_varies(tmp_path,
                                                                                  capsys):
    model = read_component_file(EXAMPLE).model
    found = parameters(model)["reeve_b.fails_at"]
    assert (found.value, found.unit) == (T_BREAK, "s")
    _, instants, peaks = swept(EXAMPLE, "reeve_b.fails_at=0.3:0.7:3", "reeve_a.peak",
                               tmp_path / "out", capsys)
    expected = _peak(_run(EXAMPLE), "reeve_a").value     # from the same steady state
    print(f"fails_at {instants!r} s: reeve_a peaks {peaks!r} N; the file's {expected!r} N")
    assert np.allclose(instants, [0.3, 0.5, 0.7], rtol=1e-15)
    assert np.all(np.abs(peaks - expected) <= 1e-9 * expected)


def test_the_walkthrough_names_the_break(tmp_path):
    text = walkthrough(EXAMPLE, tmp_path)
    assert "fails_at = 0.5 s" in text
    assert "reeve_b: intact, cut" in text
    assert "reeve_b breaks" in text
