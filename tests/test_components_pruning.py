"""Model only what a run needs: components that cannot act over the run are
dropped before the derivation, the pruned model's link loads are the full
model's, the model refuses a run it was not built for, and `crane-sym run` /
`crane-sym model show` name each dropped part in one line."""
from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from crane_sym.cli.main import main
from crane_sym.components import (Brake, ComponentError, ElasticLink, Gravity, Mass, Model,
                                  Motor, MotorLaw, Resistance)
from crane_sym.components.component_file import read_component_file
from crane_sym.mechanics.phase_table import values

EXAMPLES = Path(__file__).resolve().parents[1] / "examples" / "drive_trains"
LINE = ("dropped brake 'service_brakes': it engages at t = 0.4 s, and the run ends at "
        "0.35 s")


def read_order(model: Model) -> list:
    """Every component of the file, the dropped ones too."""
    return [*model.components, *(d.part for d in model.dropped)]


def loads(run, times):
    return np.array([values(run.result, times, run.system.link_load(i))
                     for i in range(len(run.peaks))])


@pytest.mark.parametrize("file, size", [("hoist_fig9_safety_brakes.toml", 0),
                                        ("hoist_rope_stretch.toml", 1)])
def test_pruned_model_gives_the_full_models_link_loads(file, size, tmp_path):
    """The example drops the service brakes (a step brake: the same state; the
    rope-stretch hoist cut at 0.35 s drops an exponential one: one state less),
    and its links' loads, peaks and events are the full model's."""
    path = EXAMPLES / file
    if file == "hoist_rope_stretch.toml":
        text = path.read_text().replace('duration = "0.5 s"', 'duration = "0.35 s"')
        path = tmp_path / file
        path.write_text(text)
    read = read_component_file(path)
    pruned = read.model
    assert [d.part.name for d in pruned.dropped] == ["service_brakes"]
    assert "service_brakes" not in {p.name for p in pruned.components}
    assert {p.name for p in read.parts} == {p.name for p in read_order(pruned)}
    full = Model(read.parts)
    a = pruned.run(read.duration, read.body, read.speed)
    b = full.run(read.duration, read.body, read.speed)
    assert b.system.size - a.system.size == size
    times = np.linspace(0.0, 0.35, 3501)
    ours, theirs = loads(a, times), loads(b, times)
    scale = np.max(np.abs(theirs))
    if size == 0:
        assert np.array_equal(ours, theirs)
    assert np.max(np.abs(ours - theirs)) <= 1e-12 * scale
    assert [x for p in a.peaks for x in (p.time, p.value)] == pytest.approx(
        [x for p in b.peaks for x in (p.time, p.value)], rel=1e-12)
    assert [e for _, e in a.events] == [e for _, e in b.events]


def test_a_pruned_model_refuses_a_run_it_was_not_built_for():
    read = read_component_file(EXAMPLES / "hoist_fig9_safety_brakes.toml")
    with pytest.raises(ComponentError, match="built for a run of 0.35 s without brake "
                                             "'service_brakes'"):
        read.model.run("1 s", read.body, read.speed)
    rest = Model.for_run([Mass("a", 1.0), Mass("b", 1.0), ElasticLink("k", "a", "b", 1.0),
                          Motor("m", "a", 1.0, off_at=0.0)], 1.0, rest=True)
    assert [d.part.name for d in rest.dropped] == ["m"]
    with pytest.raises(ComponentError, match="from rest"):
        rest.run(1.0)


def test_what_is_dropped_and_what_is_kept():
    """Each rule, and the parts that look idle but act through the start."""
    parts = [Mass("a", 10.0), Mass("b", 20.0), ElasticLink("k", "a", "b", 1e4),
             Brake("late", "a", 1e3, delay=2.0), Brake("early", "b", 1e3, delay=0.5),
             Motor("idle", "a", 0.0), Motor("off", "b", 50.0, off_at=0.0),
             Resistance("none", "a", 0.0), Gravity("flat", "b", 0.0),
             MotorLaw("later", "a", [3.0, 4.0], [[1.0]], "N"),
             MotorLaw("zero", "b", [0.0, 1.0], [[0.0, 0.0]], "N"),
             MotorLaw("push", "b", [0.0, 1.0], [[5.0]], "N")]
    rest = Model.for_run(parts, 2.0, rest=True)
    assert {d.part.name: d.reason for d in rest.dropped} == {
        "late": "it engages at t = 2 s, and the run ends at 2 s",
        "idle": "its torque is 0",
        "off": "it is switched off at t = 0 and the run starts at rest",
        "none": "its load is 0", "flat": "g is 0",
        "later": "its law starts at t = 3 s, and the run ends at 2 s",
        "zero": "its law is 0 throughout"}
    assert [p.name for p in rest.components] == ["a", "b", "k", "early", "push"]
    full, pruned = Model(parts).run(2.0, rest=True), rest.run(2.0, rest=True)
    times = np.linspace(0.0, 2.0, 2001)
    assert np.max(np.abs(loads(pruned, times) - loads(full, times))) <= \
        1e-12 * np.max(np.abs(loads(full, times)))
    # in a steady start the motor off at 0 sets the balance, as does an
    # acceleration law before it starts: kept
    shaft = [Mass("a", 10.0), Mass("b", 20.0), ElasticLink("k", "a", "b", 1e4)]
    assert Model.for_run(shaft + [Motor("off", "b", 50.0, off_at=0.0),
                                  Motor("hold", "a", "steady")], 2.0).dropped == ()
    assert Model.for_run(shaft + [MotorLaw("acc", "a", [3.0, 4.0], [[1.0]], "m/s^2",
                                           law="acceleration")], 2.0, rest=True).dropped == ()


def test_run_and_model_show_print_one_line_per_dropped_part(tmp_path, capsys):
    file = str(EXAMPLES / "hoist_fig9_safety_brakes.toml")
    assert main(["run", file, "--out", str(tmp_path / "out")]) == 0
    assert f"  {LINE}\n" in capsys.readouterr().out
    assert main(["model", "show", file]) == 0
    assert f"  {LINE}\n" in capsys.readouterr().out
