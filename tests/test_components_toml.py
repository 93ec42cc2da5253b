"""Component files: the shipped Fig. 9 and start-up examples against papers 001's
and 003's hybrid models (``hybrid.py``: the same physics through the Python API), `crane-sym run FILE` writing only into --out, and bad files refused in
one line naming the table, the key and the closest known one."""
from __future__ import annotations

import json
from pathlib import Path

import pytest

from crane_sym.cli.main import main
from crane_sym.components import ComponentError
from crane_sym.components.reading import is_component_file
from crane_sym.components.component_file import read_component_file

EXAMPLE = Path(__file__).resolve().parents[1] / "examples" / "drive_trains" / "hoist_fig9.toml"


def test_fig9_example_agrees_with_paper_001s_model():
    """The file's data are Table 1's: its run is ``hybrid.EMERGENCY_STOP``'s
    (whose run is checked against the paper's equations integrated in
    ``test_components.py``)."""
    from crane_sym.derivations.hoist_brakes.drive_train import table1_values
    from crane_sym.derivations.hoist_brakes.hybrid import EMERGENCY_STOP
    paper = EMERGENCY_STOP.solve(table1_values(52e3), {"duration": 1.0})
    when, relative = paper.peak("relative_torque")
    M_st = paper.system.assembly.links[0].reference
    read = read_component_file(EXAMPLE)
    run = read.model.run(read.duration, read.body, read.speed)
    peak = run.peaks[0]
    assert peak.value == pytest.approx(relative * M_st, rel=1e-9)
    # the payload is the rated one: the load at the start is M_st, the factor M_G/M_st
    assert peak.factor == pytest.approx(relative, rel=1e-9)
    assert peak.time == pytest.approx(when, abs=1e-9)


def test_run_writes_the_numbers_and_the_plot_into_out_only(tmp_path, capsys):
    out = tmp_path / "out"
    assert main(["run", str(EXAMPLE), "--out", str(out), "--quiet"]) == 0
    printed = capsys.readouterr().out
    # kN·m where the load is that large; the sign convention said once above
    assert "peak load of gearbox_mesh: -16.82 kN·m at t = 0.1597 s" in printed
    assert printed.count("signs: a link's load is c·u + d·u'") == 1
    assert "dynamic factor -5.796" in printed
    assert "event at t = 0.100000 s: safety_brakes engages" in printed
    assert sorted(p.name for p in tmp_path.rglob("*")) == \
        ["hoist_fig9.json", "hoist_fig9_loads.png", "model_hoist_fig9.py", "out"]
    data = json.loads((out / "hoist_fig9.json").read_text())
    assert data["peaks"][0]["unit"] == "N*m"           # the JSON stays in SI
    assert data["peaks"][0]["value"] == pytest.approx(-1.682e4, rel=1e-3)
    assert [e["event"] for e in data["events"]][:2] == ["drive off", "safety_brakes engages"]


def test_a_scene_is_not_a_component_file():
    scene = (Path(__file__).resolve().parents[1] / "derivations" / "hoist_brakes" / "scenes"
             / "hoist_table1.toml")
    assert not is_component_file(scene) and is_component_file(EXAMPLE)


GOOD = """
[model]
name = "flywheel"
[[inertia]]
name = "wheel"
inertia = "12 kg*m^2"
[[brake]]
name = "b"
body = "wheel"
torque = "400 N*m"
delay = "0.05 s"
[run]
duration = "2 s"
speed = "30 rad/s"
"""

BAD = {
    "an unknown table": (GOOD + "[[inertias]]\nname = 'x'\n", ["table 'inertias'",
                                                               "did you mean 'inertia'"]),
    "an unknown key": (GOOD.replace('delay = "0.05 s"', 'dealy = "0.05 s"'),
                       ["[[brake]] 'b'", "unknown key 'dealy'", "did you mean 'delay'"]),
    "a bare number with a dimension": (GOOD.replace('"400 N*m"', "400"),
                                       ["[[brake]] 'b'", "torque needs a value with its unit"]),
    "a wrong unit": (GOOD.replace('"12 kg*m^2"', '"12 kg"'), ["inertia 'wheel'", "'12 kg'"]),
    "a missing key": (GOOD.replace('body = "wheel"\n', ""), ["[[brake]] 'b'", "lacks 'body'"]),
    "a table where an array is due": (GOOD.replace("[[brake]]", "[brake]"),
                                      ["[[brake]] must be an array of tables"]),
    "no duration": (GOOD.replace('duration = "2 s"\n', ""), ["[run] lacks 'duration'"]),
    "a topology error": (GOOD.replace('body = "wheel"', 'body = "whel"'),
                         ["component model 'flywheel'", "brake 'b' names unknown body 'whel'"]),
    "text that is code": (GOOD.replace('"400 N*m"', '"__import__(\'os\').system(\'x\')"'),
                          ["brake 'b': torque", "must start with a number"]),
    "not TOML": ("[model\n", ["not valid TOML"]),
}


@pytest.mark.parametrize("case", sorted(BAD))
def test_a_bad_component_file_is_one_line_naming_what(case, tmp_path):
    text, phrases = BAD[case]
    path = tmp_path / "model.toml"
    path.write_text(text)
    with pytest.raises(ComponentError) as info:
        read_component_file(path)
    message = str(info.value)
    assert "\n" not in message
    for phrase in phrases:
        assert phrase in message, (case, message)


def test_a_good_small_file_runs(tmp_path):
    path = tmp_path / "model.toml"
    path.write_text(GOOD)
    read = read_component_file(path)
    run = read.model.run(read.duration, read.body, read.speed)
    assert dict((e, t) for t, e in run.events)["wheel rests"] == \
        pytest.approx(0.05 + 12 * 30 / 400, rel=1e-12)


def test_cli_error_is_one_line(tmp_path, capsys):
    path = tmp_path / "model.toml"
    path.write_text(GOOD.replace('delay = "0.05 s"', 'dealy = "0.05 s"'))
    assert main(["run", str(path), "--out", str(tmp_path / "out"), "--quiet"]) == 2
    err = capsys.readouterr().err.strip()
    assert err.startswith("crane-sym: error:") and "\n" not in err
    assert not (tmp_path / "out").exists()


def _load_module(path):
    import importlib.util
    spec = importlib.util.spec_from_file_location(path.stem, path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def test_generated_module_agrees_with_the_run_and_keeps_text_as_data(tmp_path):
    """The module (tables from the mpmath replay) against the double run, to
    1e-9 of the peak; a title that could close a docstring stays a literal."""
    import numpy as np

    from crane_sym.components.generate import render_component_module
    from crane_sym.mechanics.phase_table import values
    title = 'x""" + __import__("os").system("echo hi") + """ \\N{BULLET}'
    path = tmp_path / "model.toml"
    path.write_text(EXAMPLE.read_text().replace(
        'title = "Table 1 hoist: emergency stop while lowering 52 t (Fig. 9)"',
        f"title = {json.dumps(title)}"))
    read = read_component_file(path)
    assert read.model.title == title
    run = read.model.run(read.duration, read.body, read.speed)
    target = tmp_path / "model_hoist_fig9.py"
    target.write_text(render_component_module(run))
    module = _load_module(target)
    assert module.MODEL_TITLE == title
    times = np.linspace(0.0, 1.0, 4001)
    expected = values(run.result, times, run.system.link_load(0))
    peak = abs(run.peaks[0].value)
    assert np.max(np.abs(module.load_gearbox_mesh(times) - expected)) <= 1e-9 * peak
    with pytest.raises(ValueError, match="t must be <="):
        module.load_gearbox_mesh(1.5)


def test_portal_startup_example_agrees_with_paper_003s_model():
    """The file's data are Table 1's drive at the rim (backlash π rad): its run is
    ``hybrid.STARTUP``'s."""
    import numpy as np

    from crane_sym.derivations.portal_travel.hybrid import STARTUP, rim_values
    from crane_sym.derivations.portal_travel.startup import CHOSEN, HOLDS
    when, peak = STARTUP.solve(rim_values(CHOSEN, np.pi),
                               {"holds": HOLDS, "end": 4.0}).peak("load")
    read = read_component_file(EXAMPLE.with_name("portal_startup.toml"))
    assert read.rest
    run = read.model.run(read.duration, read.body, read.speed, rest=read.rest)
    assert sum(p.value for p in run.peaks) == pytest.approx(peak, rel=1e-9)
    assert run.peaks[0].time == pytest.approx(when, abs=1e-9)


def test_a_start_at_rest_takes_no_speed(tmp_path):
    path = tmp_path / "model.toml"
    path.write_text(GOOD.replace('speed = "30 rad/s"', 'start = "rest"\nspeed = "1 rad/s"'))
    with pytest.raises(ComponentError, match="a start at rest takes no body or speed"):
        read_component_file(path)


def test_model_show_prints_groups_equations_and_modes(capsys):
    assert main(["model", "show", str(EXAMPLE)]) == 0
    text = capsys.readouterr().out
    assert "theta_shaft: shaft = 1, drum = 1/i_gearbox, hook = r_rope/(i_gearbox*n_rope)" in text
    assert "equations of motion (Lagrange, with Rayleigh dissipation):" in text
    assert "elastic link 'gearbox_mesh': upper flank, gap, lower flank" in text
    assert "group shaft: free, sliding +/-, held" in text


@pytest.mark.parametrize("name", ["hoist_fig9", "bridge_travel"])
def test_a_group_that_slips_does_not_rest_on_rounding_noise(name):
    """A held group slips where its load reaches the brakes' capacity, with
    zero acceleration: it must not be logged as resting again ~1e-10 s later
    (the search's rounding band, event_search.sign_change)."""
    read = read_component_file(EXAMPLE.with_name(f"{name}.toml"))
    run = read.model.run(read.duration, read.body, read.speed, rest=read.rest)
    slips = [(t, e) for t, e in run.events if " slips " in e]
    assert slips
    for (t1, e1), (t2, e2) in zip(run.events, run.events[1:]):
        if " slips " in e1:
            assert not (e2 == e1.split()[0] + " rests" and t2 - t1 < 1e-6), (t1, e1, t2, e2)
