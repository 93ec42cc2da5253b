"""Loads as an engineer reads them: a link that declares ``positive =
"tension"`` has its load printed as tension or compression, every link's load
in kN or kN·m where it is that large, the plot's axis in words and those
units; the JSON keeps SI values and their signs and adds what positive means."""
from __future__ import annotations

import json
from pathlib import Path

import pytest

from crane_sym.cli.main import main
from crane_sym.components.model import LinkPeak
from crane_sym.components.parts import ComponentError
from crane_sym.components.component_file import read_component_file
from crane_sym.components.report import load_figures, load_text, part_peaks, report_lines
from crane_sym.scenes.panels import engineering

GANTRY = Path(__file__).resolve().parents[1] / "examples" / "drive_trains" / "gantry_hoist.toml"


@pytest.fixture(scope="module")
def run():
    read = read_component_file(GANTRY)
    return read.model.run(read.duration, read.body, read.speed, rest=read.rest)


def test_engineering_units():
    assert engineering(-152100.0, "N") == (1e3, "kN")
    assert engineering(4610.0, "N*m") == (1e3, "kN·m")
    assert engineering(2.5e6, "N") == (1e6, "MN")
    assert engineering(950.0, "N") == (1.0, "N")
    assert engineering(3.0, "s") == (1.0, "s")



def _lines(run) -> list[str]:
    """The lines ``run`` prints for ``run``."""
    return report_lines(run, part_peaks(run))

def test_a_load_in_words_turns_with_its_sign():
    scale = engineering(152100.0, "N")
    assert load_text(152100.0, "N", "tension", *scale) == "152.1 kN tension"
    assert load_text(-152100.0, "N", "tension", *scale) == "152.1 kN compression"
    assert load_text(-152100.0, "N", "compression", *scale) == "152.1 kN tension"
    assert load_text(-152100.0, "N", None, *scale) == "-152.1 kN"


def test_run_says_tension_in_kn_and_the_sign_once(run):
    lines = _lines(run)
    ropes = [l for l in lines if l.startswith("peak load of rope_")]
    assert len(ropes) == 4 and all(" kN tension at t = " in l and "(at the start "
                                   in l and " kN tension, dynamic factor " in l
                                   for l in ropes)
    (coupling,) = [l for l in lines if l.startswith("peak load of coupling")]
    assert " kN·m at t = " in coupling and "tension" not in coupling
    assert sum(l.startswith("signs: ") for l in lines) == 1     # the shafts say no word


def test_a_reversed_rope_reads_compression_where_its_sign_turns(tmp_path):
    text = GANTRY.read_text(encoding="utf-8").replace(
        'between = ["top_a", "rope_a"]', 'between = ["rope_a", "top_a"]')
    path = tmp_path / "reversed.toml"
    path.write_text(text, encoding="utf-8")
    read = read_component_file(path)
    run = read.model.run(read.duration, read.body, read.speed, rest=read.rest)
    (line,) = [l for l in _lines(run) if l.startswith("peak load of rope_a_top")]
    assert " kN compression at t = " in line       # its positive = "tension" now lies
    path.write_text(text.replace('between = ["rope_a", "top_a"]\nstiffness = "3e7 N/m"\n'
                                 'damping = "1e4 N*s/m"\npositive = "tension"',
                                 'between = ["rope_a", "top_a"]\nstiffness = "3e7 N/m"\n'
                                 'damping = "1e4 N*s/m"\npositive = "compression"'),
                    encoding="utf-8")
    read = read_component_file(path)
    run = read.model.run(read.duration, read.body, read.speed, rest=read.rest)
    (line,) = [l for l in _lines(run) if l.startswith("peak load of rope_a_top")]
    assert " kN tension at t = " in line


@pytest.mark.parametrize("change, message", [
    ('positive = "tension"          #', "positive must be 'tension' or 'compression', got 'pull'"),
    ('damping = "20 N*m*s/rad"', "positive = 'tension' is for a translating link"),
])
def test_a_wrong_positive_is_one_line(tmp_path, change, message):
    text = GANTRY.read_text(encoding="utf-8")
    if change.startswith("positive"):
        text = text.replace('positive = "tension"', 'positive = "pull"', 1)
    else:
        text = text.replace(change, change + '\npositive = "tension"', 1)
    path = tmp_path / "bad.toml"
    path.write_text(text, encoding="utf-8")
    with pytest.raises(ComponentError, match=message.replace("(", r"\(")):
        read_component_file(path)


def test_the_plot_axis_in_words_and_kn(run):
    figs = load_figures(run, "gantry")
    labels = [ax.get_ylabel() for f in figs for ax in f.get_axes()]
    assert labels[:3] == ["torque [kN·m]"] * 3 and labels[3:] == ["tension [kN]"] * 4
    assert all(ax.get_xlabel() == "time [s]" for f in figs for ax in f.get_axes())
    rope = figs[0].get_axes()[3].get_lines()[0].get_ydata()
    peak = next(p for p in run.peaks if p.link == "rope_a_top")
    assert max(rope) == pytest.approx(peak.value / 1e3, rel=1e-3)   # drawn in kN


def test_json_stays_si_and_says_what_positive_is(capsys):
    assert main(["run", str(GANTRY), "--format", "json", "-q"]) == 0
    data = json.loads(capsys.readouterr().out)
    assert data["results"]["rope_a_top.peak"]["unit"] == "N"
    assert data["results"]["rope_a_top.peak"]["value"] > 1e5            # N, not kN
    assert data["positive"] == {f"rope_{s}_{e}": "tension" for s in "ab"
                                for e in ("top", "bottom")}
    assert data["sign_convention"].startswith("a link's load is c·u + d·u'")


def test_linkpeak_keeps_its_old_fields():
    p = LinkPeak("rope", 0.1, 2.0, "N", 1.0, None)
    assert p.positive is None and p.factor is None


def test_a_brake_at_the_steady_starts_instant_is_said(tmp_path):
    """A brake without delay on a steady start engages at t = 0, after the steady
    motion it starts from: the run says so, rather than leave it to be guessed."""
    fig9 = GANTRY.parent / "hoist_fig9.toml"
    path = tmp_path / "at_once.toml"
    path.write_text(fig9.read_text(encoding="utf-8").replace('delay = "0.1 s"',
                                                              'delay = "0 s"'),
                    encoding="utf-8")
    read = read_component_file(path)
    at_once = read.model.run(read.duration, read.body, read.speed, rest=read.rest)
    assert any(l.startswith("note: brake 'safety_brakes' engages at t = 0") and
               "computed without it" in l for l in _lines(at_once))
    read = read_component_file(fig9)
    later = read.model.run(read.duration, read.body, read.speed, rest=read.rest)
    assert not any(l.startswith("note: brake") for l in _lines(later))
