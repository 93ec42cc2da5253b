"""Initial states (``[[initial]]``): a run started from a displaced or moving
body, against the closed form of a free two-mass system, and a file that gives
one wrongly refused in one line, exit 2."""
from __future__ import annotations

import math
import re
from pathlib import Path

import numpy as np
import pytest

from crane_sym.cli.main import main
from crane_sym.components.component_file import read_component_file

EXAMPLE = Path(__file__).resolve().parents[1] / "examples" / "drive_trains" / "hook_released.toml"
M1, M2, C = 1200.0, 800.0, 3.0e5              # kg, kg, N/m
OMEGA = math.sqrt(C * (M1 + M2) / (M1 * M2))   # rad/s, the relative mode
FREE = """
[model]
name = "free_pair"

[[mass]]
name = "left"
mass = "{m1} kg"

[[mass]]
name = "right"
mass = "{m2} kg"

[[elastic]]
name = "spring"
between = ["left", "right"]
stiffness = "{c} N/m"

[[initial]]
name = "pushed"
body = "right"
{initial}

[run]
duration = "{duration} s"
{start}
"""


def _run(tmp_path: Path, initial: str, start: str = "", duration: float = 0.0):
    """The free pair with ``initial`` keys on the right mass, run over 2.5
    relative periods (the run and its link's load as a function of time)."""
    path = tmp_path / "free_pair.toml"
    path.write_text(FREE.format(m1=M1, m2=M2, c=C, initial=initial, start=start,
                                duration=duration or 5 * math.pi / OMEGA))
    read = read_component_file(path)
    run = read.model.run(read.duration, read.body, read.speed, rest=read.rest)
    assert len(run.result.segments) == 1                # one phase: nothing switches

    def load(t: float) -> float:
        w, k = run.system.link_load(0)(run.result.segments[0].mode)
        return float(np.asarray(w) @ run.result.state(np.array(t)) + k)
    return run, load


@pytest.mark.parametrize("start", ['start = "rest"', 'start = "steady"', ""])
def test_displacement_gives_c_u0_cos_omega_t(tmp_path, start):
    u0 = 0.02
    run, load = _run(tmp_path, f'displacement = "{u0} m"', start)
    peak = run.peaks[0]
    print(f"{start or 'default start'}: peak {peak.value!r} N at {peak.time!r} s, "
          f"c u0 = {C * u0!r} N; F(2 pi/w) = {load(2 * math.pi / OMEGA)!r} N")
    assert abs(peak.value - C * u0) <= 1e-9 * C * u0
    assert peak.time == 0.0
    assert abs(load(2 * math.pi / OMEGA) - C * u0) <= 1e-9 * C * u0
    assert abs(load(math.pi / OMEGA) + C * u0) <= 1e-9 * C * u0
    times = np.linspace(0, 5 * math.pi / OMEGA, 301)
    error = max(abs(load(t) - C * u0 * math.cos(OMEGA * t)) for t in times)
    assert error <= 1e-9 * C * u0


def test_velocity_gives_c_v0_over_omega_sin_omega_t(tmp_path):
    v0 = 1.5
    run, load = _run(tmp_path, f'velocity = "{v0} m/s"', 'start = "rest"')
    peak, amplitude = run.peaks[0], C * v0 / OMEGA
    print(f"peak {peak.value!r} N at {peak.time!r} s, c v0/w = {amplitude!r} N "
          f"at pi/(2 w) = {math.pi / (2 * OMEGA)!r} s")
    assert abs(peak.value - amplitude) <= 1e-9 * amplitude
    assert abs(peak.time - math.pi / (2 * OMEGA)) <= 1e-4 / OMEGA
    times = np.linspace(0, 5 * math.pi / OMEGA, 301)
    error = max(abs(load(t) - amplitude * math.sin(OMEGA * t)) for t in times)
    assert error <= 1e-9 * amplitude
    # the centre of mass moves at m2 v0 / (m1 + m2) throughout
    x = run.result.state(np.array([0.0, 1.0]))
    drift = (M1 * (x[1, 0] - x[0, 0]) + M2 * (x[1, 2] - x[0, 2])) / (M1 + M2)
    assert abs(drift - M2 * v0 / (M1 + M2)) <= 1e-9 * v0


def test_both_at_once_superpose(tmp_path):
    u0, v0 = 0.01, -0.4
    _, load = _run(tmp_path, f'displacement = "{u0} m"\nvelocity = "{v0} m/s"')
    times = np.linspace(0, 5 * math.pi / OMEGA, 101)
    closed = [C * (u0 * math.cos(OMEGA * t) + v0 / OMEGA * math.sin(OMEGA * t)) for t in times]
    scale = C * math.hypot(u0, v0 / OMEGA)
    assert max(abs(load(t) - f) for t, f in zip(times, closed)) <= 1e-9 * scale


def test_hook_released_example_peaks_at_weight_plus_c_lift():
    read = read_component_file(EXAMPLE)
    run = read.model.run(read.duration, read.body, read.speed, rest=read.rest)
    m, c, lift, g = 10e3, 5e5, 0.1, 9.81
    m_red = 500.0 * (2 / 0.4) ** 2
    omega = math.sqrt(c * (m_red + m) / (m_red * m))
    peak = run.peaks[0]
    print(f"peak {peak.value!r} N at {peak.time!r} s; m g + c lift = {m * g + c * lift!r} N "
          f"at pi/w = {math.pi / omega!r} s; start {peak.static!r} N")
    assert abs(peak.value - (m * g + c * lift)) <= 1e-9 * (m * g + c * lift)
    assert abs(peak.time - math.pi / omega) <= 1e-4 / omega
    assert abs(peak.static - (m * g - c * lift)) <= 1e-9 * m * g
    assert abs(peak.factor - (m * g + c * lift) / 98.1e3) <= 1e-9


def test_a_displaced_start_gives_no_dynamic_factor_without_a_reference(tmp_path):
    """The load at a displaced start is no static load: without a given
    reference the factor is left out, not peak over that load (3.08 here)."""
    text = EXAMPLE.read_text().replace('reference = "98.1 kN"', "")
    (tmp_path / "hook.toml").write_text(text)
    read = read_component_file(tmp_path / "hook.toml")
    peak = read.model.run(read.duration, read.body, read.speed, rest=read.rest).peaks[0]
    assert peak.reference is None and peak.factor is None
    assert abs(peak.static - (10e3 * 9.81 - 5e5 * 0.1)) <= 1e-9 * 10e3 * 9.81


#: What replaces the right mass's initial keys (and the [run] start), and the
#: line expected after "crane-sym: error: ".
FAULTS = {
    "wrong unit": ('displacement = "0.1 s"', "",
                   r"component model 'free_pair': initial state 'pushed' on mass 'right': "
                   r"displacement '0\.1 s' is time, expected .*length.*"),
    "velocity in N": ('velocity = "2 N"', "",
                      r"component model 'free_pair': initial state 'pushed' on mass 'right': "
                      r"velocity '2 N' is .*, expected .*"),
    "neither": ("", "", r"component model 'free_pair': \[\[initial\]\] 'pushed': give a "
                        r"displacement, a velocity or both"),
    "velocity with a steady speed": (
        'velocity = "1 m/s"', 'body = "left"\nspeed = "2 m/s"',
        r"initial state 'pushed': a velocity and the steady start's \[run\] speed 2 \(SI\) both "
        r"set the speed of 'right'; give one \(or start = \"rest\"\)"),
    "a number without a unit": ("displacement = 0.1", "",
                                r"component model 'free_pair': \[\[initial\]\] 'pushed': "
                                r"displacement needs a value with its unit as text, .*"),
}


@pytest.mark.parametrize("case", FAULTS)
def test_a_bad_initial_state_is_one_line(case, tmp_path, capsys):
    initial, start, line = FAULTS[case]
    path = tmp_path / "free_pair.toml"
    path.write_text(FREE.format(m1=M1, m2=M2, c=C, initial=initial, start=start, duration=1))
    code = main(["run", str(path), "--out", str(tmp_path / "out"), "-q"])
    err = capsys.readouterr().err
    assert code == 2, err
    assert re.fullmatch(rf"crane-sym: error: {line}\n", err), err


def test_two_displacements_of_one_rigid_group_are_refused(tmp_path, capsys):
    path = tmp_path / "free_pair.toml"
    text = FREE.format(m1=M1, m2=M2, c=C, initial='displacement = "1 mm"', start="",
                       duration=1)
    path.write_text(text.replace("[run]", '[[initial]]\nname = "again"\nbody = "right"\n'
                                          'displacement = "2 mm"\n\n[run]'))
    assert main(["run", str(path), "--out", str(tmp_path / "out"), "-q"]) == 2
    assert capsys.readouterr().err == (
        "crane-sym: error: component model 'free_pair': initial state 'again' on mass 'right': "
        "initial state 'pushed' gives the displacement of its rigid group (right) already\n")


def test_a_braked_wheel_given_a_speed_slides_to_rest(tmp_path):
    """A wheel (J) turning at ω0 under a brake (M) engaged from t = 0 at rest
    stops at J ω0 / M, turned by J ω0² / (2 M) from where it was put."""
    J, M, w0 = 2.0, 50.0, 300 * 2 * math.pi / 60
    path = tmp_path / "wheel.toml"
    path.write_text('[model]\nname = "wheel"\n\n[[inertia]]\nname = "wheel"\n'
                    f'inertia = "{J} kg*m^2"\n\n[[brake]]\nname = "hold"\nbody = "wheel"\n'
                    f'torque = "{M} N*m"\n\n[[initial]]\nname = "spun"\nbody = "wheel"\n'
                    'displacement = "90 deg"\nvelocity = "300 rpm"\n\n'
                    '[run]\nduration = "2 s"\nstart = "rest"\n')
    read = read_component_file(path)
    run = read.model.run(read.duration, read.body, read.speed, rest=read.rest)
    (t_rest, event), = run.events
    angle = run.result.state(np.array(2.0))[0]
    print(f"{event} at {t_rest!r} s (J w0/M = {J * w0 / M!r}); angle {angle!r} rad "
          f"(pi/2 + J w0^2/(2M) = {math.pi / 2 + J * w0 ** 2 / (2 * M)!r})")
    assert event == "wheel rests"
    assert abs(t_rest - J * w0 / M) <= 1e-12 * J * w0 / M
    assert abs(angle - (math.pi / 2 + J * w0 ** 2 / (2 * M))) <= 1e-12 * angle


def test_a_sweep_varies_the_initial_displacement():
    """``lifted.displacement`` is a field of a sweep (by its declaration): the
    designs, solved together, peak at m g + c |lift|."""
    from crane_sym.components.designs import Designs
    designs = Designs(EXAMPLE)
    lifts = np.array([-0.2, -0.1, -0.05])
    assert designs.fields["lifted.displacement"].key == "displacement"
    peaks = designs.largest("rope.peak", {"lifted.displacement": lifts})
    closed = 10e3 * 9.81 + 5e5 * np.abs(lifts)
    print(f"peaks {peaks!r} N, m g + c |lift| = {closed!r} N")
    assert np.all(np.abs(peaks - closed) <= 1e-9 * closed)


def test_the_walkthrough_names_the_initial_state(tmp_path):
    page = tmp_path / "page.md"
    assert main(["walkthrough", str(EXAMPLE), "-o", str(page)]) == 0
    assert "then given its initial states (hook displacement -0.1 m)" in page.read_text()


def test_a_displacement_past_a_flank_closes_the_gap(tmp_path):
    """With a gap −s < u < 0, a start at u0 > 0 is on the upper flank: the
    load c u0 cos ωt until u = 0 at π/(2ω), where the gap opens; the bodies
    then part at u0 ω and close on the lower flank s/(u0 ω) later."""
    u0, s = 0.004, 0.001
    path = tmp_path / "free_pair.toml"
    text = FREE.format(m1=M1, m2=M2, c=C, initial=f'displacement = "{u0} m"',
                       start='start = "rest"', duration=1)
    path.write_text(text.replace(f'stiffness = "{C} N/m"',
                                 f'stiffness = "{C} N/m"\nbacklash = "{s} m"'))
    read = read_component_file(path)
    run = read.model.run(read.duration, read.body, read.speed, rest=read.rest)
    opened, closed = run.events[:2]
    expected = (math.pi / (2 * OMEGA), math.pi / (2 * OMEGA) + s / (u0 * OMEGA))
    print(f"events {opened}, {closed}; expected at {expected}; peak {run.peaks[0].value!r} N")
    assert (opened[1], closed[1]) == ("spring opens", "spring closes -")
    assert abs(opened[0] - expected[0]) <= 1e-12 * expected[1]
    assert abs(closed[0] - expected[1]) <= 1e-12 * expected[1]
    assert abs(run.peaks[0].value - C * u0) <= 1e-9 * C * u0 and run.peaks[0].time == 0.0


def test_a_velocity_of_a_body_a_speed_law_moves_is_refused(tmp_path, capsys):
    path = tmp_path / "free_pair.toml"
    text = FREE.format(m1=M1, m2=M2, c=C, initial='velocity = "1 m/s"',
                       start='start = "rest"', duration=1)
    path.write_text(text.replace("[run]", '[[motor_law]]\nname = "control"\nbody = "right"\n'
                                          'law = "speed"\nunit = "m/s"\n'
                                          'breakpoints = [0.0, 5.0]\ncoefficients = [[0.5]]\n\n'
                                          '[run]'))
    assert main(["run", str(path), "--out", str(tmp_path / "out"), "-q"]) == 2
    assert capsys.readouterr().err == (
        "crane-sym: error: initial state 'pushed': motor law 'control' sets the speed of "
        "'right'; give no velocity\n")
