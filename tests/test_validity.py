"""Physical validity is stated, never silently crossed.

A scene whose load or duration takes a model outside the range it holds for
gets a ``warning:`` line, panels greyed where the model does not hold, and
maxima taken over the valid part only: a user's drive law lifting with
pick-up (paper 002), a 12 t travel-braking scene run past the instant the
brake stops slipping (paper 000), a drum whose element slips (paper 004).
The mechanism is the machinery's (``panels``, ``plots``, ``crossings``);
the instants are each paper's.
"""
from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest
import sympy as sp

from crane_sym.scenes import plots
from crane_sym.mechanics.crossings import first_reaching
from crane_sym.scenes.panels import Panel, SceneReport, Span, outside, valid_mask
from crane_sym.scenes.run import import_module_file, run_scene
from crane_sym.scenes.reading import SceneError, load_scene, scenes_directory

pytest.importorskip("scipy")

t = sp.Symbol("t", real=True)
HOIST = """\
[scene]
name = "user_pickup"
derivation = "hoist_startup"
title = "A user's jerk-limited law, lifting with pick-up"
[parameters]
m1 = "2 t"
m2 = "8 t"
C = "1.0e6 N/m"
g = "9.81 m/s^2"
[drive_law]
lifting = "pickup"
breakpoints = [0.0, 0.25, 1.0, 1.25]
coefficients = [[0.0, 2.0], [0.5], [0.5, -2.0]]
[options]
duration = "{duration}"
points = {points}
"""


def _write(tmp_path: Path, text: str, name: str) -> Path:
    path = tmp_path / f"{name}.toml"
    path.write_text(text, encoding="utf-8")
    return path


# --- the machinery -------------------------------------------------------------------
def test_first_reaching_finds_the_first_root_with_proof():
    found = first_reaching(sp.sin(t), t, 0, 3, sp.Rational(1, 2))
    assert found.certified and found.location == pytest.approx(math.pi / 6, rel=1e-14)
    down = first_reaching(sp.cos(t), t, 0, 4, 0, above=False)
    assert down.location == pytest.approx(math.pi / 2, rel=1e-14)
    assert first_reaching(sp.sin(t) - 2, t, 0, 10).location is None       # never
    assert first_reaching(t ** 2, t, 0, 1).location == 0.0                # holds at a
    pieces = sp.Piecewise((t, t < 1), (2 - t, True))                     # a roof at t = 1
    assert first_reaching(pieces, t, 0, 3, 0, above=False).location == pytest.approx(0.0)
    assert first_reaching(pieces, t, sp.Rational(1, 2), 3, 0,
                          above=False).location == pytest.approx(2.0, rel=1e-14)
    with pytest.raises(ValueError, match="give numbers"):
        first_reaching(sp.sin(t) + sp.Symbol("k"), t, 0, 1)


def test_spans_outside_the_valid_interval_and_their_mask():
    spans = outside(0.5, 2.0, before="on the ground", after="slack")
    assert [(s.start, s.end, s.reason) for s in spans] == [
        (-math.inf, 0.5, "on the ground"), (2.0, math.inf, "slack")]
    x = np.array([0.0, 0.5, 1.0, 2.0, 2.5])
    assert valid_mask(x, spans).tolist() == [False, True, True, True, False]
    assert outside(0.0, math.inf, after="never") == []
    with pytest.raises(ValueError, match="reason"):
        Span(0.0, 1.0, "")


def test_a_greyed_panel_is_drawn_faint_with_its_reason_and_valid_y_limits():
    x = np.linspace(0.0, 5.0, 501)
    panel = Panel("speed", "$v$", [("$v$", x, 1.0 - x / 2)],
                  invalid=outside(0.0, 2.0, after="crane stopped"))
    fig = plots.figures([panel], "scene")[0]
    ax = fig.get_axes()[0]
    labels = [text.get_text() for text in ax.get_legend().get_texts()]
    assert labels == ["$v$", "crane stopped"]
    bottom, top = ax.get_ylim()
    assert bottom > -0.1 and top < 1.1         # the valid part 1 ... 0, not down to -1.5
    full, faint = ax.get_lines()
    assert np.isnan(full.get_ydata()[x > 2.0]).all()
    assert faint.get_alpha() < 1 and not np.isnan(faint.get_ydata()[x > 2.0]).any()
    grey = [p for p in ax.patches if p.get_label() == "crane stopped"]
    assert len(grey) == 1 and grey[0].get_x() == pytest.approx(2.0)


def test_a_report_that_greys_without_a_warning_is_refused(tmp_path, monkeypatch):
    from crane_sym import registry
    x = np.linspace(0.0, 1.0, 11)
    quiet = SceneReport(["no word of it"], {"v": 1.0},
                        [Panel("p", "y", [("y", x, x)], invalid=outside(0, 0.5, after="x"))])
    monkeypatch.setattr(registry.module("travel_braking"), "scene_report",
                        lambda scene, module: quiet)
    with pytest.raises(SceneError, match="warning:"):
        run_scene("overhead_crane_50t", tmp_path)


# --- paper 002: a user's drive law lifting with pick-up ------------------------------------
@pytest.fixture(scope="module")
def pickup(tmp_path_factory):
    """(scene, report, pngs, module) of the pick-up law over 0.3 s: the model's K
    peaks before lift-off, at 0.13 s, above anything after it."""
    tmp = tmp_path_factory.mktemp("pickup")
    scene = load_scene(_write(tmp, HOIST.format(duration="0.3 s", points=3001), "user_pickup"))
    report, pngs = run_scene(scene, tmp / "out")
    return scene, report, pngs, import_module_file(tmp / "out" / "scene_user_pickup.py")


def test_pickup_is_warned_and_valid_only_after_lift_off(pickup):
    scene, report, _, _ = pickup
    tau0 = 8000 * 9.81 / (1e6 * 0.5)                    # (29), v0 = 0.5 m/s
    assert report.values["valid_from"] == pytest.approx(tau0, rel=1e-12)
    assert report.values["valid_to"] == pytest.approx(0.3)
    warnings = report.warnings
    assert len(warnings) == 2
    assert "rests on the ground" in warnings[0] and "not 0" in warnings[0]
    assert "only after lift-off, t >= 0.1570 s" in warnings[1]
    for panel in report.panels[2:]:                     # K, rope force, load acceleration
        assert [(s.start, s.end) for s in panel.invalid] == [(-math.inf, pytest.approx(tau0))]
        assert "load on the ground" in panel.invalid[0].reason
    assert report.panels[0].invalid == report.panels[1].invalid == []   # the law: data


def test_pickup_k_max_is_certified_over_the_valid_part_only(pickup):
    scene, report, _, module = pickup
    v = report.values
    t_all = np.linspace(0.0, 0.3, 300_001)
    k = module.dynamic_coefficient(t_all)
    valid = t_all >= v["valid_from"]
    assert k.max() > v["K_max"] * 1.05              # the model's peak on the ground, refused
    assert v["t_max"] >= v["valid_from"] and v["certified"] == 1.0
    assert k[valid].max() <= v["K_max"] * (1 + 1e-12)
    assert k[valid].max() == pytest.approx(v["K_max"], rel=1e-9)
    line = [ln for ln in report.lines if ln.startswith("K_max")][0]
    assert "over the valid part [0.1570 s, 0.3000 s] only" in line


def test_pickup_png_greys_the_contact_phase(pickup):
    _, _, pngs, _ = pickup
    # a and v of the drive law on axes of their own: five panels, two figures
    assert len(pngs) == 2 and all(p.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n" for p in pngs)
    axes = [ax for figure in plots.figures(pickup[1].panels, "x") for ax in figure.get_axes()]
    for ax in axes[2:]:                          # K, rope force, load acceleration
        texts = [tx.get_text() for tx in ax.get_legend().get_texts()]
        assert any("load on the ground" in tx for tx in texts)


def test_from_weight_example_holds_throughout_and_says_nothing_more():
    import importlib

    from crane_sym.registry import module
    scene = load_scene("hoist_user_drive_law")
    shipped = importlib.import_module(f"crane_sym.generated.scene_{scene.name}")
    report = module("hoist_startup").scene_report(scene, shipped)
    assert report.warnings == [] and all(not p.invalid for p in report.panels)
    assert report.values["valid_from"] == 0.0 and report.values["valid_to"] == 2.5
    assert "over [0, 2.500 s]" in [ln for ln in report.lines if ln.startswith("K_max")][0]


def test_a_rope_that_goes_slack_ends_the_valid_part(tmp_path):
    """From weight, a hard stop (a = -10 m/s² for 0.05 s): the rope goes slack."""
    text = HOIST.format(duration="1 s", points=1001).replace('"pickup"', '"from_weight"')
    text = text.replace("breakpoints = [0.0, 0.25, 1.0, 1.25]", "breakpoints = [0.0, 0.2, 0.25]")
    text = text.replace("coefficients = [[0.0, 2.0], [0.5], [0.5, -2.0]]",
                        "coefficients = [[2.0], [-10.0]]")
    scene = load_scene(_write(tmp_path, text, "slack"))
    report, _ = run_scene(scene, tmp_path / "out")
    v = report.values
    assert 0.2 < v["valid_to"] < 1.0
    assert any("rope goes slack" in w for w in report.warnings)
    module = import_module_file(tmp_path / "out" / f"scene_{scene.name}.py")
    x = module.rope_stretch(np.linspace(0.0, v["valid_to"], 20001))
    assert x.min() >= -1e-12 * x.max()                     # taut up to the end ...
    assert module.rope_stretch(v["valid_to"] + 1e-3) < 0     # ... and slack after it


# --- paper 000: a 12 t crane braked for 5 s -------------------------------------------------
def test_travel_braking_past_the_stop_is_warned_and_cut(tmp_path):
    text = (scenes_directory("travel_braking") / "overhead_crane_50t.toml").read_text(
        encoding="utf-8")
    for old, new in (('name = "overhead_crane_50t"', 'name = "crane_12t"'),
                     ('m2 = "110 t"', 'm2 = "12 t"'), ('duration = "1.5 s"', 'duration = "5 s"'),
                     ("points = 1501", "points = 5001")):
        assert old in text
        text = text.replace(old, new)
    report, (png,) = run_scene(load_scene(_write(tmp_path, text, "crane_12t")), tmp_path)
    v = report.values
    assert 0.5 < v["t_valid_end"] == v["t_slip_end"] < 1.0
    assert any("runs past the model's validity" in w for w in report.warnings)
    for panel in report.panels:
        (span,) = panel.invalid
        assert span.start == v["t_valid_end"] and span.end == math.inf
    assert v["v1_min"] >= -1e-3 and v["v2_min"] >= 0       # minima where the model holds
    fig = plots.figures(report.panels, "x")[0]
    velocities = fig.get_axes()[1]
    assert velocities.get_ylim()[0] > -0.1                 # not drawn down to -1.3 m/s
    assert png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def test_travel_braking_within_its_validity_is_unchanged(tmp_path):
    report, _ = run_scene("overhead_crane_50t", tmp_path)
    assert report.warnings == [] and all(not p.invalid for p in report.panels)
    assert report.values["t_valid_end"] == 1.5


# --- paper 004: an element that slips on the drum ------------------------------------------
def test_drum_slip_is_warned(tmp_path):
    text = (scenes_directory("drum_drive") / "drum_drive_example.toml").read_text(
        encoding="utf-8")
    text = text.replace('F0 = "20 kN"', 'F0 = "3 kN"').replace(
        'name = "drum_drive_example"', 'name = "drum_slip"')
    report, _ = run_scene(load_scene(_write(tmp_path, text, "drum_slip")), tmp_path)
    assert 0 < report.values["t_valid_end"] < 1.0
    assert any("slips on the drum" in w for w in report.warnings)
    greyed = [p.title for p in report.panels if p.invalid]
    assert "Load on the run, (21)" not in greyed and len(greyed) == 3
    shipped, _ = run_scene("drum_drive_example", tmp_path / "shipped")
    assert shipped.warnings == [] and shipped.values["t_valid_end"] == 10.0


def test_a_refused_law_leaves_no_folder(tmp_path):
    """Defect (b): a pick-up law that ends at a negative speed is refused on
    reading, so `crane-sym run` makes no folder."""
    from crane_sym.cli.main import main
    text = HOIST.format(duration="1 s", points=101).replace("[0.5, -2.0]", "[0.5, -20.0]")
    path = _write(tmp_path, text, "backwards")
    with pytest.raises(SceneError, match=r"\[drive_law\] .*v0 > 0, got -1/16"):
        load_scene(path)
    assert main(["run", str(path), "--out", str(tmp_path / "out")]) == 2
    assert not (tmp_path / "out").exists()
