"""Sway (``[[pendulum]]``): a load hanging from a trolley, linearized about the
vertical, run against the closed forms of a trolley stopped abruptly and of one
braked at constant deceleration (the residual sway, zero after a whole number
of periods); its sway angle swept, audited and shown in the walkthrough."""
from __future__ import annotations

import json
import math
from pathlib import Path

import numpy as np
import pytest

from crane_sym.cli.main import main
from crane_sym.components.component_file import read_component_file
from component_commands import swept, walkthrough

EXAMPLE = Path(__file__).resolve().parents[1] / "examples" / "drive_trains" / "trolley_sway.toml"
V, L, G, M = 1.0, 10.0, 9.81, 10e3             # m/s, m, m/s^2, kg (the example's)
OMEGA = math.sqrt(G / L)                       # rad/s
PERIOD = 2 * math.pi / OMEGA


def _residual(v: float, ramp: float, g: float = G, length: float = L) -> float:
    """The sway left after braking from v to rest at a = v/T over T: with
    u = y − x, u'' + ω² u = a from u = u' = 0 gives u = (a/ω²)(1 − cos ωt); at
    t = T its amplitude √(u² + (u'/ω)²) = (a/ω²)√(2 − 2 cos ωT) =
    (2a/ω²)|sin(ωT/2)|, so θ = (2 v/(g T))|sin(ωT/2)| (ω² L = g)."""
    omega = math.sqrt(g / length)
    return 2 * v / (g * ramp) * abs(math.sin(omega * ramp / 2))


def _run(text: str, tmp_path: Path):
    path = tmp_path / "model.toml"
    path.write_text(text, encoding="utf-8")
    read = read_component_file(path)
    return read.model.run(read.duration, read.body, read.speed, rest=read.rest)


def _amplitude(run, t: float) -> float:
    """The free sway's angle amplitude √(u² + (u̇/ω)²)/L at t (after the ramp)."""
    link = run.system.assembly.links[0]
    twist = run.system.twist(link)
    rate = np.roll(twist, 1)
    segment = next(s for s in run.result.segments if s.t0 <= t <= s.t1)
    x = segment.state(np.array(t))
    return math.hypot(float(twist @ x), float(rate @ x) / OMEGA) / L


def _ramp(ramp: float, duration: float) -> str:
    """The example braked over ``ramp`` seconds instead, run for ``duration``."""
    text = EXAMPLE.read_text(encoding="utf-8")
    for old, new in (("breakpoints = [0.0, 2.0, 30.0]",
                      f"breakpoints = [0.0, {ramp!r}, {duration!r}]"),
                     ("[1.0, -0.5],", f"[1.0, {-V / ramp!r}],"),
                     ('duration = "30 s"', f'duration = "{duration!r} s"')):
        assert old in text
        text = text.replace(old, new)
    return text


def test_a_trolley_stopped_abruptly_leaves_the_sway_v_over_omega(tmp_path):
    """Stopped at once from v, the trolley is fixed and the load keeps v: u(0) =
    0, u̇(0) = v, so u = (v/ω) sin ωt and θ peaks at v/(ωL) at t = π/(2ω)."""
    run = _run(f"""
[model]
name = "stopped"

[[mass]]
name = "load"
mass = "{M} kg"

[[pendulum]]
name = "sway"
between = ["ground", "load"]
length = "{L} m"

[[initial]]
name = "moving"
body = "load"
velocity = "{V} m/s"

[run]
duration = "{PERIOD} s"
start = "rest"
""", tmp_path)
    peak, expected = run.peaks[0], V / (OMEGA * L)
    print(f"peak angle {peak.factor!r} rad at {peak.time!r} s; v/(omega L) = {expected!r} rad "
          f"at pi/(2 omega) = {math.pi / (2 * OMEGA)!r} s")
    assert peak.angle
    assert abs(abs(peak.factor) - expected) <= 1e-9 * expected
    assert abs(peak.time - math.pi / (2 * OMEGA)) <= 1e-6 * PERIOD
    assert abs(abs(peak.value) - M * G * expected) <= 1e-9 * M * G * expected


def test_the_example_peaks_at_its_residual_sway():
    """Braked over T_r = 2 s (< π/ω: the sway during the ramp stays below the
    residual), the run's largest angle is the residual's closed form."""
    read = read_component_file(EXAMPLE)
    run = read.model.run(read.duration, read.body, read.speed, rest=read.rest)
    peak, expected = run.peaks[0], _residual(V, 2.0)
    print(f"peak angle {peak.factor!r} rad; residual {expected!r} rad; after the ramp "
          f"{_amplitude(run, 10.0)!r} rad")
    assert abs(abs(peak.factor) - expected) <= 1e-9 * expected
    assert abs(_amplitude(run, 10.0) - expected) <= 1e-9 * expected


@pytest.mark.parametrize("periods", [0.37, 1.0, 1.5, 2.0])
def test_the_residual_sway_of_a_ramp(periods, tmp_path):
    """After a ramp of T_r the load swings at (2 v/(g T_r))|sin(ωT_r/2)|:
    none when T_r is a whole number of periods."""
    ramp = periods * PERIOD
    run = _run(_ramp(ramp, ramp + PERIOD), tmp_path)
    after, expected = _amplitude(run, ramp + PERIOD / 3), _residual(V, ramp)
    scale = 2 * V / (G * ramp)                        # the sway's size during the ramp
    print(f"T_r = {periods} periods: residual {after!r} rad, closed form {expected!r} rad")
    assert abs(after - expected) <= 1e-9 * scale
    if periods == int(periods):
        assert expected < 1e-15 and after <= 1e-9 * scale


def test_a_sweep_of_the_rope_length_gives_the_residual(tmp_path, capsys):
    data, lengths, angles = swept(EXAMPLE, "sway.length=5:20:4", "sway.angle", tmp_path / "out",
                                  capsys)
    assert data["outputs"]["sway.angle"]["unit"] == "rad"
    assert np.allclose(lengths, [5.0, 10.0, 15.0, 20.0], rtol=1e-15)
    for length, angle in zip(lengths, angles):
        expected = _residual(V, 2.0, length=float(length))
        print(f"L = {length!r} m: swept {angle!r} rad, residual {expected!r} rad")
        assert abs(angle - expected) <= 1e-9 * expected


def test_the_run_reports_the_angle_and_the_audit_confirms_the_residual(tmp_path, capsys):
    assert main(["run", str(EXAMPLE), "--out", str(tmp_path / "run"), "--format", "json",
                 "-q"]) == 0
    found = json.loads(capsys.readouterr().out)["results"]
    assert found["sway.angle"]["unit"] == "rad"
    assert abs(found["sway.angle"]["value"] - _residual(V, 2.0)) <= 1e-9 * _residual(V, 2.0)
    assert main(["audit", str(EXAMPLE), "--format", "json"]) == 0
    assert '"verdict": "confirmed"' in capsys.readouterr().out


def test_the_walkthrough_derives_the_pendulums_energy(tmp_path):
    text = walkthrough(EXAMPLE, tmp_path)
    assert "| sway | pendulum | trolley – load | length = 10 m; g = 9.81 m/s^2 |" in text
    assert (r"\Pi = \frac{g_{\mathrm{sway}} m_{\mathrm{load}} \left(x_{\mathrm{load}} - "
            r"x_{\mathrm{trolley}}\right)^{2}}{2 L_{\mathrm{sway}}}") in text


def test_the_run_line_gives_the_angle_once_not_as_a_dynamic_factor(tmp_path, capsys):
    assert main(["run", str(EXAMPLE), "--out", str(tmp_path / "run")]) == 0
    out = capsys.readouterr().out
    load = next(line for line in out.splitlines() if "peak load of sway" in line)
    assert "dynamic factor" not in load
    assert "peak sway angle of sway: 0.08525 rad (4.884 deg)" in out

