"""Faults of a component file that were tracebacks: each is one line naming
the part, the value and the bound, exit 2, nothing written (a table, as
tests/test_fault_table.py is for scenes)."""
from __future__ import annotations

import json
import os
import re
import subprocess
import sys
from pathlib import Path
from typing import NamedTuple

import pytest

from crane_sym.cli.main import main

EXAMPLES = Path(__file__).parents[1] / "examples" / "drive_trains"
TRAVEL, HOIST = "travel_braking_000.toml", "hoist_rope_stretch.toml"
FIG9 = "hoist_fig9.toml"
SLACK = "slack_rope.toml"
SWAY = "trolley_sway.toml"
JIB = "jib_reeve_failure.toml"
GIRDER, LIFT = "girder_hoist.toml", "lift_off.toml"
DC = "dc_hoist_pi.toml"
MODEL_DC = r"component model 'dc_hoist_pi': "
DRUM = "drum_drive_004.toml"
MAGNITUDE = r"must be 0 or of magnitude 1e-30 to 1e\+30 in SI units, got "
PERIODS = r"run: duration {} s spans {} periods of the slowest mode \({} s\), at most 10000; "


def _tables(kind: str, n: int, body: str) -> str:
    """``n`` tables of ``kind`` (brake, inertia chained by gears, backlash
    link), each joined to the example's ``body``."""
    if kind == "brake":
        return "".join(f'[[brake]]\nname = "b{i}"\nbody = "{body}"\ntorque = "2 kN*m"\n'
                       f'delay = "{0.01 * i:.2f} s"\nbuild_up = "ramp"\ntime = "0.2 s"\n\n'
                       for i in range(n))
    if kind == "geared":
        ends = [body] + [f"j{i}" for i in range(n)]
        return "".join(f'[[inertia]]\nname = "j{i}"\ninertia = "1 kg*m^2"\n\n'
                       f'[[gear]]\nname = "g{i}"\ninput = "{ends[i]}"\noutput = "j{i}"\n'
                       f'ratio = 1.01\n\n' for i in range(n))
    ends = [body] + [f"j{i}" for i in range(n)]
    return "".join(f'[[mass]]\nname = "j{i}"\nmass = "100 kg"\n\n'
                   f'[[elastic]]\nname = "k{i}"\nbetween = ["{ends[i]}", "j{i}"]\n'
                   f'stiffness = "1e6 N/m"\ndamping = "1e3 N*s/m"\nbacklash = "1 mm"\n\n'
                   for i in range(n))


class Fault(NamedTuple):
    example: str
    old: str
    new: str
    line: str                      # what follows "crane-sym: error: ", a regex


#: The example, the text replaced, its replacement, the line expected.
ROWS = {
    "mass 1e308 kg": Fault(TRAVEL, 'mass = "4.4 t"', 'mass = "1e308 kg"',
                           rf"mass 'drive': mass {MAGNITUDE}'1e308 kg'"),
    "mass 1e-320 kg": Fault(TRAVEL, 'mass = "4.4 t"', 'mass = "1e-320 kg"',
                            rf"mass 'drive': mass {MAGNITUDE}'1e-320 kg'"),
    "stiffness 1e-300 N/m": Fault(TRAVEL, 'stiffness = "3.0e6 N/m"', 'stiffness = "1e-300 N/m"',
                                  rf"elastic link 'transmission': stiffness {MAGNITUDE}"
                                  r"'1e-300 N/m'"),
    "stiffness 1e40 N/m": Fault(TRAVEL, 'stiffness = "3.0e6 N/m"', 'stiffness = "1e40 N/m"',
                                rf"elastic link 'transmission': stiffness {MAGNITUDE}"
                                r"'1e40 N/m'"),
    "force 1e300 N": Fault(TRAVEL, 'force = "24 kN"', 'force = "1e300 N"',
                           rf"resistance 'brake': \w+ {MAGNITUDE}'1e300 N'"),
    "speed 1e308 rpm": Fault(HOIST, 'speed = "1500 rpm"', 'speed = "1e308 rpm"',
                             rf"run: speed {MAGNITUDE}'1e308 rpm'"),
    "reeving 1e300": Fault(HOIST, "reeving = 4", "reeving = 1e300",
                           rf"drum 'tackle': reeving {MAGNITUDE}'1e\+300'"),
    "ratio 1e-320": Fault(HOIST, "ratio = 26.2", "ratio = 1e-320",
                          rf"gear 'gearbox': ratio {MAGNITUDE}'1e-320'"),
    "reeving 1e-320": Fault(HOIST, "reeving = 4", "reeving = 1e-320",
                            rf"drum 'tackle': reeving {MAGNITUDE}'1e-320'"),
    "radius 1e308 m": Fault(HOIST, 'radius = "0.5 m"', 'radius = "1e308 m"',
                            rf"drum 'tackle': radius {MAGNITUDE}'1e308 m'"),
    "g 1e308 m/s^2": Fault(FIG9, 'g = "9.81 m/s^2"', 'g = "1e308 m/s^2"',
                           rf"gravity 'weight': g {MAGNITUDE}'1e308 m/s\^2'"),
    "TOML nested 5000 deep": Fault(TRAVEL, "[run]", "[deep]\nx = " + "[" * 5000 + "]" * 5000
                                   + "\n\n[run]",
                                   r"(\S+/)?x\.toml: not valid TOML: arrays or tables nested too "
                                   r"deep \(the reader's limit is below \d+\)"),
    "slack -0.2 m": Fault(SLACK, 'slack = "0.2 m"', 'slack = "-0.2 m"',
                          r"elastic link 'rope': slack must be >= 0, got '-0\.2 m'"),
    "slack 3 deg": Fault(SLACK, 'slack = "0.2 m"', 'slack = "3 deg"',
                         r"component model 'slack_rope': elastic link 'rope': slack '3 deg' is "
                         r"dimensionless, expected length \(e\.g\. m\)"),
    "slack and backlash": Fault(SLACK, 'slack = "0.2 m"', 'slack = "0.2 m"\nbacklash = "1 mm"',
                                r"component model 'slack_rope': \[\[elastic\]\] 'rope': slack "
                                r"'0\.2 m' makes a rope that only pulls; it takes no backlash "
                                r"\(got backlash = '1 mm'\)"),
    "pendulum length -10 m": Fault(SWAY, 'length = "10 m"', 'length = "-10 m"',
                                   r"pendulum 'sway': length must be > 0, got '-10 m'"),
    "pendulum length 10 s": Fault(SWAY, 'length = "10 m"', 'length = "10 s"',
                                  r"pendulum 'sway': length '10 s' is time, expected length "
                                  r"\(e\.g\. m\)"),
    "pendulum from the ground up": Fault(SWAY, 'between = ["trolley", "load"]',
                                         'between = ["trolley", "ground"]',
                                         r"pendulum 'sway': the load hangs at the second end "
                                         r"of between; it cannot be the ground"),
    "pendulum stiffness": Fault(SWAY, 'length = "10 m"', 'length = "10 m"\nstiffness = "1 N/m"',
                                r"component model 'trolley_sway': \[\[pendulum\]\] 'sway': "
                                r"unknown key 'stiffness'; expected name, between, length, g, "
                                r"damping"),
    "fails_at -1 s": Fault(JIB, 'fails_at = "0.5 s"', 'fails_at = "-1 s"',
                           r"elastic link 'reeve_b': fails_at must be > 0, got '-1 s'"),
    "fails_at 0.5 m": Fault(JIB, 'fails_at = "0.5 s"', 'fails_at = "0.5 m"',
                            r"elastic link 'reeve_b': fails_at '0\.5 m' is length, expected "
                            r"time \(e\.g\. s\)"),
    "brake fails before it engages": Fault(FIG9, 'delay = "0.4 s"',
                                           'delay = "0.4 s"\nfails_at = "0.2 s"',
                                           r"brake 'service_brakes': fails_at must be > its "
                                           r"delay 0\.4 s \(it releases once engaged\), got "
                                           r"'0\.2 s'"),
    # the fixed ground as a link's end, and a body's contact with it
    "ground to itself": Fault(GIRDER, 'between = ["ground", "girder"]',
                              'between = ["ground", "ground"]',
                              r"component model 'girder_hoist': elastic link 'structure' joins "
                              r"the ground to itself"),
    "a body named ground": Fault(GIRDER, 'name = "girder"', 'name = "ground"',
                                 r"mass name 'ground' is reserved for the fixed end a link may "
                                 r"name in 'between'; call the body something else"),
    "contact direction up": Fault(LIFT, 'direction = "+"', 'direction = "up"',
                                  r"ground contact 'ground_support': direction must be '\+' or "
                                  r"'-', got 'up'"),
    "contact on an unknown body": Fault(LIFT, 'body = "load"\ndirection',
                                        'body = "lode"\ndirection',
                                        r"component model 'lift_off': ground contact "
                                        r"'ground_support' names unknown body 'lode'; did you "
                                        r"mean 'load'\?"),
    "contact with a steady start": Fault(LIFT, 'start = "rest"\n', 'start = "steady"\n',
                                         r"(component model 'lift_off': )?ground contact "
                                         r"'ground_support': a body on the ground starts at "
                                         r"rest; give \[run\] start = \"rest\""),
    "two contacts on one body": Fault(LIFT, "[run]",
                                      '[[ground_contact]]\nname = "floor"\nbody = "load"\n\n'
                                      "[run]",
                                      r"component model 'lift_off': ground contact 'floor': "
                                      r"ground contact 'ground_support' rests the same rigid "
                                      r"group on the ground already"),
    # a brake holds at rest by its friction capacity, undeclared: no contact's group
    "brake on a resting group": Fault(LIFT, "[run]",
                                      '[[brake]]\nname = "catch"\nbody = "load"\n'
                                      'force = "1 kN"\n\n[run]',
                                      r"component model 'lift_off': ground contact "
                                      r"'ground_support': brake 'catch' acts on the rigid group "
                                      r"of mass 'load', which the ground holds while it rests; "
                                      r"a contact takes a group without brakes or speed laws"),
    # a DC motor's armature and its speed loop
    "armature resistance < 0": Fault(DC, 'resistance = "0.1 ohm"', 'resistance = "-0.1 ohm"',
                                     r"dc motor 'armature': resistance must be > 0, "
                                     r"got '-0.1 ohm'"),
    "armature inductance in s": Fault(DC, 'inductance = "5 mH"', 'inductance = "5 ms"',
                                      r"dc motor 'armature': inductance '5 ms' is time, "
                                      r"expected mass\*length\*\*2/\(time\*\*2\*current\*\*2\)"),
    "motor constant in N*m": Fault(DC, 'constant = "4 N*m/A"', 'constant = "4 N*m"',
                                   MODEL_DC + r"dc motor 'armature' on inertia 'motor': constant "
                                   r"'4 N\*m' is mass\*length\*\*2/time\*\*2, expected "
                                   r"mass\*length\*\*2/\(time\*\*2\*current\)"),
    "voltage law in A": Fault(DC, 'unit = "V"', 'unit = "A"',
                              MODEL_DC + r"dc motor 'armature' on inertia 'motor': its voltage "
                              r"unit 'A' is current, expected a voltage \(e\.g\. V\)"),
    "voltage 1e20 V": Fault(DC, "coefficients = [[0.0]]", "coefficients = [[1e20]]",
                            r"motor law 'armature': coefficients\[0\]\[0\] = 1e\+20 \(SI\) is "
                            r"too large: \|c\| = 1e\+20 SI, more than 1e\+12 SI"),
    "controller of no motor": Fault(DC, 'motor = "armature"', 'motor = "armatur"',
                                    MODEL_DC + r"speed controller 'speed_loop' on inertia 'motor': "
                                    r"motor 'armatur' is no dc_motor; dc motors: armature"),
    "torque limit 0": Fault(DC, 'limit = "1000 N*m"', 'limit = "0 N*m"',
                            r"speed controller 'speed_loop': limit must be > 0, got '0 N\*m'"),
    "limit without integral": Fault(DC, 'integral = "200 V/rad"', 'integral = "0 V/rad"',
                                    r"speed controller 'speed_loop': integral \(a limit's "
                                    r"integral tracks it\) must be > 0, got '0 V/rad'"),
    "limit below the load": Fault(DC, 'limit = "1000 N*m"', 'limit = "600 N*m"',
                                  r"start: speed_loop's limit holds i_armature within ±150 A; "
                                  r"the steady start needs 163\.5 A: the limit cannot hold "
                                  r"the load"),
    "gain in V/rad": Fault(DC, 'proportional = "20 V*s/rad"', 'proportional = "20 V/rad"',
                           MODEL_DC + r"speed controller 'speed_loop' on inertia 'motor': "
                           r"proportional '20 V/rad' is mass\*length\*\*2/\(time\*\*3\*current\), "
                           r"expected mass\*length\*\*2/\(time\*\*2\*current\)"),
    "reference in m/s": Fault(DC, 'unit = "rad/s"', 'unit = "m/s"',
                              MODEL_DC + r"speed controller 'speed_loop' on inertia 'motor': its "
                              r"reference unit 'm/s' is length/time, expected 1/time \(e\.g\. "
                              r"rad/s, rpm or Hz\)"),
    # a span's points and values (crane_sym.components.kinds.span)
    "span on an unknown body": Fault(DRUM, "start = { run = 1 }", "start = { rum = 1 }",
                                     r"component model 'drum_drive_004': span 'tight' names "
                                     r"unknown body 'rum'; did you mean 'drum' or 'run'\?"),
    "span factor in N": Fault(DRUM, 'end = { drum = "250 mm", centre = -1 }',
                              'end = { drum = "250 N", centre = -1 }',
                              r"component model 'drum_drive_004': span 'tight': end factor of "
                              r"'drum' '250 N' is mass\*length/time\*\*2, expected length "
                              r"\(e\.g\. m\)"),
    "span factor 0": Fault(DRUM, "end = { centre = 1 }", "end = { centre = 0 }",
                           r"span 'bending': end factor of 'centre' is 0; leave the body out"),
    "span point as text": Fault(DRUM, "end = { centre = 1 }", 'end = "centre"',
                                r"component model 'drum_drive_004': \[\[span\]\] 'bending': "
                                r"end must be a table of body names and factors, e\.g\. end = "
                                r"\{ drum = \"250 mm\", hub = -1 \}, got 'centre'"),
    "span between frame and frame": Fault(DRUM, "end = { centre = 1 }", "end = {}",
                                          r"span 'bending': both its start and its end are the "
                                          r"frame; name a body in start or end"),
    "span mass -5 kg": Fault(DRUM, 'mass = "1440 kg"', 'mass = "-5 kg"',
                             r"span 'tight': mass must be >= 0, got '-5 kg'"),
    # the model's bounds (crane_sym.components.model_limits), before it is derived
    "duration 1e5 s": Fault(TRAVEL, 'duration = "1.5 s"', 'duration = "1e5 s"',
                            r"component model 'travel_braking_000': "
                            + PERIODS.format("100000", r"4\.24e\+05", "0.236") + ".*"),
    "stiffness 1e20 N/m": Fault(TRAVEL, 'stiffness = "3.0e6 N/m"', 'stiffness = "1e20 N/m"',
                                r"component model 'travel_braking_000': "
                                + PERIODS.format(r"1\.5", r"3\.67e\+07", r"4\.09e-08") + ".*"),
    "20 backlash links": Fault(TRAVEL, "[run]", _tables("backlash", 20, "drive") + "[run]",
                               r"component model 'travel_braking_000': 20 elastic links with "
                               r"backlash, at most 8"),
    "25 elastic links": Fault(TRAVEL, "[run]", "".join(
        f'[[elastic]]\nname = "p{i}"\nbetween = ["bridge", "drive"]\nstiffness = "1e5 N/m"\n\n'
        for i in range(24)) + "[run]",
        r"component model 'travel_braking_000': 25 elastic links, at most 24"),
    "50 ramp brakes": Fault(FIG9, "[run]", _tables("brake", 50, "drum") + "[run]",
                            r"component model 'hoist_fig9': 52 brakes, at most 8"),
    "200 geared inertias": Fault(FIG9, "[run]", _tables("geared", 200, "drum") + "[run]",
                                 r"component model 'hoist_fig9': 204 bodies \(inertias and "
                                 r"masses\), at most 24"),
}
COMMANDS = {"run": ["run", "{file}", "--out", "{out}"],
            "walkthrough": ["walkthrough", "{file}", "-o", "{out}/page.md"],
            "model show": ["model", "show", "{file}"]}


#: The rows that bound a model's size and its run before it is derived; the
#: others are values that were tracebacks, warnings or anonymous messages.
BOUNDS = {"duration 1e5 s", "stiffness 1e20 N/m", "20 backlash links", "25 elastic links",
          "50 ramp brakes", "200 geared inertias"}
#: `model show` reads no [run] table: the run's speed and start are not its
#: input, and it solves no run.
PAIRS = [pytest.param(case, command, marks=pytest.mark.harm(
             "bounds" if case in BOUNDS else "one-line"))
         for case in ROWS for command in COMMANDS
         if command != "model show" or case not in ("speed 1e308 rpm",
                                                    "contact with a steady start",
                                                    "limit below the load")]


@pytest.mark.parametrize("case,command", PAIRS)
def test_one_line(case, command, tmp_path, capsys):
    row = ROWS[case]
    text = (EXAMPLES / row.example).read_text(encoding="utf-8")
    assert row.old in text
    source = tmp_path / "x.toml"
    source.write_text(text.replace(row.old, row.new, 1), encoding="utf-8")
    out = tmp_path / "out"
    argv = [a.format(file=source, out=out) for a in COMMANDS[command]]
    if command == "walkthrough":
        out.mkdir()
    code = main(argv + ([] if command == "model show" else ["-q"]))
    captured = capsys.readouterr()
    assert code == 2, captured.err
    assert re.fullmatch(rf"crane-sym: error: {row.line}\n", captured.err), captured.err
    assert captured.out == ""
    assert not out.exists() or list(out.iterdir()) == []


@pytest.mark.harm("one-line")
def test_the_fig9_hoist_without_gravity_runs(tmp_path, capsys):
    """g = 0 on the Fig. 9 hoist was a RuntimeError past 10⁴ events (the sweep at
    g = 0 gave 27.11 kN·m): it runs, exit 0, one peak for each link."""
    text = (EXAMPLES / FIG9).read_text(encoding="utf-8")
    source = tmp_path / "x.toml"
    source.write_text(text.replace('g = "9.81 m/s^2"', 'g = "0 m/s^2"', 1), encoding="utf-8")
    assert main(["run", str(source), "--format", "json", "-q"]) == 0
    results = json.loads(capsys.readouterr().out)["results"]
    assert "gearbox_mesh.peak" in results and abs(results["gearbox_mesh.peak"]["value"]) > 0


@pytest.mark.harm("bounds")
def test_a_chain_of_eight_masses_runs_within_its_bound(tmp_path):
    """A chain of 8 masses and 7 elastic links (6 took 31 s, 8 did not end):
    derived and run in a process of its own well inside the two minutes given
    (a hang fails the test; the time itself is the bench's to report)."""
    text = '[model]\nname = "chain8"\n\n'
    text += "".join(f'[[mass]]\nname = "m{i}"\nmass = "{i + 1} t"\n\n' for i in range(8))
    text += "".join(f'[[elastic]]\nname = "k{i}"\nbetween = ["m{i}", "m{i + 1}"]\n'
                    f'stiffness = "{i + 1}e6 N/m"\n\n' for i in range(7))
    text += ('[[resistance]]\nname = "brake"\nbody = "m0"\nforce = "24 kN"\n\n'
             '[run]\nduration = "1.5 s"\nstart = "rest"\n')
    source = tmp_path / "chain8.toml"
    source.write_text(text, encoding="utf-8")
    done = subprocess.run([sys.executable, "-m", "crane_sym", "run", str(source), "--format",
                           "json", "-q"], capture_output=True, text=True, timeout=120,
                          cwd=tmp_path, env={**os.environ, "PYTHONPATH": str(EXAMPLES.parents[1])})
    assert done.returncode == 0, done.stderr
    results = json.loads(done.stdout)["results"]
    assert all(f"k{i}.peak" in results for i in range(7))
    assert sorted(p.name for p in tmp_path.iterdir()) == ["chain8.toml"]
