"""`crane-sym audit FILE` gives every formula a verdict: a formula the model
cannot check is not_checkable with the reason and the others are checked
(exit 0); a static load is given wherever equilibrium fixes it (a link outside
a loop of elastic links); a switching value (a backlash, a brake's torque and
delay, a law's values) is a symbol a formula may name; a print the parser
stops on names the construct and the spelling that reads."""
from __future__ import annotations

import json
from pathlib import Path

from crane_sym.cli.main import main
from crane_sym.components.parameters import parameters
from crane_sym.components.quantities import static_loads
from crane_sym.components.component_file import read_component_file

#: A gantry hoist no paper has: motor, coupling with backlash, drum, a block on
#: the drum's rope and the hook below it on two ropes in parallel (a loop of
#: elastic links), a steady motor holding the weight.
GANTRY = r'''
[model]
name = "gantry_hoist"

[[inertia]]
name = "motor"
inertia = "20 kg*m^2"

[[inertia]]
name = "drum"
inertia = "500 kg*m^2"

[[mass]]
name = "block"
mass = "2 t"

[[mass]]
name = "hook"
mass = "30 t"

[[drum]]
name = "reel"
drum = "drum"
load = "block"
radius = "0.5 m"
reeving = 2

[[elastic]]
name = "coupling"
between = ["motor", "drum"]
stiffness = "4e5 N*m/rad"
backlash = "2 deg"

[[elastic]]
name = "rope_a"
between = ["block", "hook"]
stiffness = "2e7 N/m"

[[elastic]]
name = "rope_b"
between = ["block", "hook"]
stiffness = "2e7 N/m"

[[gravity]]
name = "weight"
body = "hook"
g = "9.81 m/s^2"

[[motor]]
name = "drive"
body = "motor"
torque = "steady"

[[brake]]
name = "stop"
body = "motor"
torque = "3 kN*m"
delay = "0.2 s"

[run]
duration = "1 s"
body = "motor"
speed = "0 rpm"

[[formula]]
name = "parallel rope"
latex = "F = \\frac{m g}{2}"
quantity = "rope_a.static"
symbols = { m = "hook.mass", g = "weight.g" }

[[formula]]
name = "coupling, wrong"
latex = "M = \\frac{2 m g r}{n}"
quantity = "coupling.static"
symbols = { m = "hook.mass", g = "weight.g", r = "reel.radius", n = "reel.reeving" }

[[formula]]
name = "coupling, with backlash"
latex = "M = \\frac{m g r}{n} + c s"
quantity = "coupling.static"
symbols = { m = "hook.mass", g = "weight.g", r = "reel.radius", n = "reel.reeving", c = "coupling.stiffness", s = "coupling.backlash" }
'''


#: A static-load formula with a term in the run's speed over a brake's delay.
SPEED_TERM = r'''
[[formula]]
name = "{name}"
latex = "M = \\frac{{m g r}}{{n}} + \\frac{{J v}}{{\\tau}}"
quantity = "coupling.static"
symbols = {{ m = "hook.mass", g = "weight.g", r = "reel.radius", n = "reel.reeving", J = "motor.inertia", v = "run.speed", "\\tau" = "stop.delay" }}
'''


def _gantry(tmp_path: Path, extra: str = "") -> Path:
    path = tmp_path / "gantry.toml"
    path.write_text(GANTRY + extra, encoding="utf-8")
    return path


def test_three_formulas_three_verdicts_and_exit_0(tmp_path, capsys):
    assert main(["audit", str(_gantry(tmp_path)), "--format", "json", "-q"]) == 0
    records = {r["label"]: r for r in json.loads(capsys.readouterr().out)}
    assert [records[k]["verdict"] for k in records] == ["not_checkable", "discrepancy",
                                                         "discrepancy"]
    assert "rope_a lies in a loop of elastic links" in records["parallel rope"]["detail"]
    assert "Printed / derived: $2$" in records["coupling, wrong"]["detail"]
    assert "Printed − derived: $c s$" in records["coupling, with backlash"]["detail"]


def test_a_link_outside_the_loop_has_its_static_load(tmp_path):
    model = read_component_file(_gantry(tmp_path)).model
    loads = static_loads(model)
    assert loads["rope_a"] is None and loads["rope_b"] is None
    held = float(abs(loads["coupling"]).xreplace(model.equations.values))
    assert abs(held / (30e3 * 9.81 * 0.5 / 2) - 1) < 1e-12      # m g r / n at the motor


def test_switching_values_are_symbols_a_formula_may_name(tmp_path):
    known = parameters(read_component_file(_gantry(tmp_path)).model)
    for path, value in (("coupling.backlash", 2 * 3.141592653589793 / 180),
                        ("stop.torque", 3e3), ("stop.delay", 0.2)):
        assert abs(known[path].value - value) < 1e-12 * value, path
    law = read_component_file(Path(__file__).resolve().parents[1] / "examples"
                              / "drive_trains" / "hoist_drive_law.toml")
    known = parameters(law.model)
    assert (known["hoist.time_2"].value, known["hoist.value_2"].value) == (0.25, 0.5)
    assert known["hoist.value_2"].unit == "m/s^2"


def test_a_print_the_parser_stops_on_names_the_spelling_that_reads(tmp_path, capsys):
    extra = r'''
[[formula]]
name = "referred inertia"
latex = "J = \\frac{(J_a + J_b) n^2}{r^2}"
quantity = "motor.reduced_inertia"
symbols = { J_a = "motor.inertia", J_b = "drum.inertia", n = "reel.reeving", r = "reel.radius" }
'''
    assert main(["audit", str(_gantry(tmp_path, extra)), "--format", "json", "-q"]) == 0
    record = json.loads(capsys.readouterr().out)[-1]
    assert record["verdict"] == "not_checkable"
    assert ("a bracket times a power with no sign between them ('(J_a + J_b) n^2'): write "
            "the product out, '(J_a + J_b) \\cdot n^2'") in record["detail"]


def test_the_runs_speed_is_a_symbol_a_formula_may_name(tmp_path, capsys):
    """``run.speed`` (100 rpm at the motor) and a brake's delay: the static load
    depends on neither, so a print that adds ``J v / τ`` is found off by
    exactly that term."""
    extra = SPEED_TERM.format(name="coupling, with the run's speed")
    path = _gantry(tmp_path, extra)
    path.write_text(path.read_text(encoding="utf-8").replace('speed = "0 rpm"',
                                                             'speed = "100 rpm"'))
    read = read_component_file(path)
    speed = parameters(read.model, (read.body, read.speed))["run.speed"]
    assert abs(speed.value - 100 * 2 * 3.141592653589793 / 60) < 1e-12
    assert speed.unit == "rad/s"
    assert main(["audit", str(path), "--format", "json", "-q"]) == 0
    record = json.loads(capsys.readouterr().out)[-1]
    assert record["label"] == "coupling, with the run's speed"
    assert record["verdict"] == "discrepancy", record["detail"]
    assert r"Printed − derived: $\frac{J v}{\tau}$" in record["detail"]


def test_a_symbol_mapped_to_a_zero_value_is_read_and_put_to_zero(tmp_path, capsys):
    """The run's speed of 0 rpm, as any zero value, is put to zero as the
    derivation drops it: the print's ``J v / τ`` vanishes and the formula
    confirms (it was a name the parser could not find before)."""
    extra = SPEED_TERM.format(name="at rest")
    assert main(["audit", str(_gantry(tmp_path, extra)), "--format", "json", "-q"]) == 0
    record = json.loads(capsys.readouterr().out)[-1]
    assert (record["label"], record["verdict"]) == ("at rest", "confirmed"), record["detail"]


def test_the_table_keeps_its_columns_past_fourteen_characters(tmp_path, capsys):
    """Every column starts where its header does, whatever the length of a
    model's name or a formula's label (a fixed width of 15 broke both)."""
    path = _gantry(tmp_path)
    path.write_text(path.read_text(encoding="utf-8").replace(
        'name = "gantry_hoist"', 'name = "gantry_hoist_with_parallel_ropes"'), encoding="utf-8")
    assert main(["audit", str(path), "--format", "table", "-q"]) == 0
    head, _, *rows = capsys.readouterr().out.splitlines()
    starts = [head.index(name) for name in ("label", "verdict", "basis", "cause", "method")]
    records = [row for row in rows if row.startswith("gantry_hoist")]
    assert len(records) == 3
    for row in records:
        assert all(row[at - 1] == " " and row[at] != " " for at in starts), row
