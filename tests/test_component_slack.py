"""A slack rope (``slack`` of ``[[elastic]]``): a rope that only pulls, run
against the energy balance of a load falling through its slack, the free fall's
time, and the closed form of its rebound; swept and audited like any link."""
from __future__ import annotations

import math
import re
from pathlib import Path

import numpy as np
import pytest

from crane_sym.cli.main import main
from crane_sym.components.component_file import read_component_file
from component_commands import swept, walkthrough

EXAMPLE = Path(__file__).resolve().parents[1] / "examples" / "drive_trains" / "slack_rope.toml"
M, C, H, G = 2000.0, 2e6, 0.2, 9.81           # kg, N/m, m, m/s^2 (the example's)


def _shock(m: float, c: float, h: float, g: float) -> float:
    """The peak of a rope that catches a load falling through its slack h:
    m g (h + s) = c s²/2 gives F = c s = m g (1 + √(1 + 2 c h/(m g)))."""
    return m * g * (1 + math.sqrt(1 + 2 * c * h / (m * g)))


def _on_the_rope(m: float, c: float, h: float, g: float) -> float:
    """How long the rope stays taut: with s = u − h from the instant it snaps
    taut at speed v = √(2 g h), s = (m g/c)(1 − cos ωt) + (v/ω) sin ωt, which is
    0 again where tan(ωt/2) = −v ω/g: t = 2 (π − atan(v ω/g))/ω."""
    omega, v = math.sqrt(c / m), math.sqrt(2 * g * h)
    return 2 * (math.pi - math.atan(v * omega / g)) / omega


def _run(path: Path = EXAMPLE):
    read = read_component_file(path)
    return read.model.run(read.duration, read.body, read.speed, rest=read.rest)


def test_the_shock_load_is_the_energy_balance():
    run = _run()
    peak, expected = run.peaks[0], _shock(M, C, H, G)
    print(f"peak {peak.value!r} N at {peak.time!r} s; energy balance {expected!r} N")
    assert abs(peak.value - expected) <= 1e-9 * expected
    assert abs(peak.factor - expected / (M * G)) <= 1e-9 * expected / (M * G)


def test_the_rope_snaps_taut_after_the_free_fall_and_goes_slack_after_the_rebound():
    run = _run()
    taut, on = math.sqrt(2 * H / G), _on_the_rope(M, C, H, G)
    up = 2 * math.sqrt(2 * G * H) / G                   # up and down again at the same speed
    expected = [(taut, "rope snaps taut"), (taut + on, "rope goes slack"),
                (taut + on + up, "rope snaps taut"), (2 * (taut + on) + up - taut,
                                                      "rope goes slack")]
    print(f"events {run.events!r}; closed forms {expected!r}")
    assert [e for _, e in run.events] == [e for _, e in expected]
    for (t, _), (t_ref, _) in zip(run.events, expected):
        assert abs(t - t_ref) <= 1e-9 * t_ref


def test_a_slack_rope_never_pushes():
    """Below its slack the rope's load is 0, whatever the twist: sampled over
    the whole run, the load is never negative and is 0 wherever u < h."""
    run = _run()
    load = run.system.link_load(0)
    u = run.system.twist(run.system.assembly.links[0])
    for segment in run.result.segments:
        w, k = load(segment.mode)
        times = np.linspace(segment.t0, segment.t1, 50)
        for t in times:
            x = segment.state(np.array(t))
            force, twist = float(np.asarray(w) @ x + k), float(u @ x)
            assert force >= -1e-9 * M * G
            if twist < H * (1 - 1e-9):
                assert force == 0.0


def test_a_sweep_of_the_slack_follows_the_energy_balance(tmp_path, capsys):
    data, slacks, peaks = swept(EXAMPLE, "rope.slack=0.05:0.4:4", "rope.peak", tmp_path / "out",
                                capsys)
    assert data["outputs"]["rope.peak"]["unit"] == "kN"
    assert np.allclose(slacks, np.linspace(0.05, 0.4, 4), rtol=1e-15)
    for h, peak in zip(slacks, peaks):
        expected = _shock(M, C, float(h), G)
        print(f"slack {h!r} m: swept peak {peak!r} N, energy balance {expected!r} N")
        assert abs(peak - expected) <= 1e-9 * expected


def test_the_example_audits_its_shock_formula(capsys):
    assert main(["audit", str(EXAMPLE), "--format", "json"]) == 0
    text = capsys.readouterr().out
    assert re.search(r'"verdict": "confirmed"', text), text


def test_the_walkthrough_names_the_slack_and_the_contacts(tmp_path):
    text = walkthrough(EXAMPLE, tmp_path)
    assert "slack = 0.2 m" in text
    assert "rope: taut, slack" in text
    assert "rope snaps taut" in text and "rope goes slack" in text
