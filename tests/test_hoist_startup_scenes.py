"""Scenes of paper 002: Figs 3 and 5 and the drive laws a_i from the generated
code; guaranteed maxima of K(t) against a dense sample and against the paper."""
import importlib
import math

import numpy as np
import pytest

from crane_sym import registry
from crane_sym.derivations.hoist_startup import report as hss
from crane_sym.scenes.run import run_scene
from crane_sym.scenes.reading import SceneError, SceneReport, load_scene, scenes_directory

PNG_MAGIC = b"\x89PNG\r\n\x1a\n"
SCENES = ("hoist_fig3", "hoist_fig5", "hoist_drive_laws")


@pytest.fixture(scope="module")
def laws():
    """(scene, report) of the drive-law scene, computed once (about 30 s)."""
    scene = load_scene("hoist_drive_laws")
    return scene, hss.scene_report(scene)


@pytest.mark.parametrize("name", SCENES)
def test_each_scene_runs_and_writes_a_png(name, tmp_path, laws, monkeypatch):
    scene = load_scene(name)
    if name == "hoist_drive_laws":          # the report computed once, by the fixture
        monkeypatch.setattr(registry.module("hoist_startup"), "scene_report",
                            lambda s, m=None: laws[1], raising=False)
    report, pngs = run_scene(scene, tmp_path)
    assert isinstance(report, SceneReport) and report.panels and report.lines
    # nine panels of the drive laws: pick-up, from weight, Table 1
    assert pngs == ([tmp_path / f"{name}_{k}.png" for k in (1, 2, 3)]
                    if name == "hoist_drive_laws" else [tmp_path / f"{name}.png"])
    for png in pngs:
        data = png.read_bytes()
        assert len(data) > 1000 and data[:8] == PNG_MAGIC
    assert report.values["Omega"] == pytest.approx(25.0, rel=1e-12)


def test_scene_files_are_shipped():
    for name in SCENES:
        assert (scenes_directory("hoist_startup") / f"{name}.toml").is_file()
        assert load_scene(name).options["figure"] in hss.FIGURES


def test_fig3_largest_displacement_is_twice_the_static_one():
    report = hss.scene_report(load_scene("hoist_fig3"))
    v = report.values
    assert v["K_at_half_period"] == pytest.approx(2.0, rel=1e-14)
    assert abs(v["K_at_period"]) < 1e-14
    assert v["K_max_sampled"] <= 2.0 + 1e-14
    assert v["K_max_sampled"] == pytest.approx(2.0, rel=1e-6)
    assert [c[0] for c in report.panels[0].curves][0] == r"$x(t)/x_\mathrm{ст}$ (38)"


def test_fig5_trails_the_static_line_by_one_over_omega_tn():
    v = hss.scene_report(load_scene("hoist_fig5")).values
    assert v["lag_amplitude"] == pytest.approx(1 / 25.0, rel=1e-14)
    assert v["lag_max_sampled"] <= v["lag_amplitude"] * (1 + 1e-12)
    assert v["lag_max_sampled"] == pytest.approx(v["lag_amplitude"], rel=1e-5)
    assert v["K_at_t_n"] == pytest.approx(1 - math.sin(25.0) / 25.0, rel=1e-14)


@pytest.mark.parametrize("case", hss.CASES)
@pytest.mark.parametrize("i", [1, 2, 3, 4])
def test_guaranteed_maxima_bound_and_match_a_dense_sample(laws, case, i):
    scene, report = laws
    v, q = report.values, scene.parameters
    assert v["certified"] == 1.0
    gen = importlib.import_module(hss.GENERATED)
    t = np.linspace(v[f"valid_from_{case}_a{i}"], v[f"valid_to_{case}_a{i}"], 400_001)
    dense = hss._k(gen, case, i, t, q)
    top = v[f"K_max_{case}_a{i}"]
    assert dense.max() <= top * (1 + 1e-12)
    assert dense.max() == pytest.approx(top, rel=1e-6)
    at = hss._k(gen, case, i, np.array([v[f"t_K_max_{case}_a{i}"]]), q)[0]
    assert at == pytest.approx(top, rel=1e-12)
    assert v[f"K_max_sampled_{case}_a{i}"] <= top * (1 + 1e-12)


@pytest.mark.parametrize("case", hss.CASES)
def test_load_acceleration_maxima_bound_a_dense_sample(laws, case):
    """The elastic counterpart of k̃ of (63)-(65), over Table 1's span."""
    scene, report = laws
    v, q = report.values, scene.parameters
    gen = importlib.import_module(hss.GENERATED)
    weight = q["m2"] * q["g"]
    for i in range(1, 5):
        t = np.linspace(v[f"valid_from_{case}_a{i}"], q["t_n"], 200_001)
        a0 = float(hss._law(gen, i, np.zeros(1), q)[0])
        force = hss._k(gen, case, i, t, q) * hss._reference(case, a0, q)
        load = (force - weight) / (q["m2"] * q["v0"] / q["t_n"])
        top = v[f"load_max_{case}_a{i}"]
        assert load.max() <= top * (1 + 1e-10)
        assert load.max() == pytest.approx(top, rel=1e-6)


def test_rigid_maxima_reproduce_the_numbers_printed_after_66(laws):
    _, report = laws
    v = report.values
    assert v["ktilde_opt_max_a3"] == pytest.approx(16 / 9, rel=1e-15)
    assert v["t_ktilde_opt_max_a3"] == pytest.approx(1 / 3, rel=1e-15)
    assert v["ktilde_opt_max_a4"] == pytest.approx(2.0736, rel=1e-15)
    assert v["t_ktilde_opt_max_a4"] == pytest.approx(0.4, rel=1e-15)
    assert v["paper_ktilde_max_a3"] == 1.7778                    # 16/9 to 4 decimals
    assert v["paper_ktilde_max_a4"] == 2.0736
    assert v["paper_ktilde_max_a2"] == v["ktilde_opt_max_a2"] == 1.0
    # A step in the acceleration (a_1) doubles the load's acceleration in the
    # elastic system; the smooth laws a_3, a_4 exceed the rigid optimum of (65).
    assert v["load_max_from_weight_a1"] == pytest.approx(2.0, rel=1e-12)
    for i in (3, 4):
        assert v[f"load_max_from_weight_a{i}"] > v[f"ktilde_opt_max_a{i}"]


def test_inconsistent_omega_is_refused(tmp_path):
    text = (scenes_directory("hoist_startup") / "hoist_fig3.toml").read_text(encoding="utf-8")
    path = tmp_path / "bad.toml"
    path.write_text(text.replace('Omega = "25 rad/s"', 'Omega = "26 rad/s"'),
                    encoding="utf-8")
    with pytest.raises(SceneError, match="parameter 'Omega' = 26.0 does not follow"):
        load_scene(path)                 # on load, before anything is written


def test_unknown_figure_is_refused(tmp_path):
    text = (scenes_directory("hoist_startup") / "hoist_fig3.toml").read_text(encoding="utf-8")
    path = tmp_path / "bad.toml"
    path.write_text(text.replace('figure = "fig3"', 'figure = "fig4"'), encoding="utf-8")
    with pytest.raises(SceneError, match=r"\[options\] figure \(.*\) must be one of"):
        load_scene(path)


def test_pickup_panels_are_greyed_until_the_load_lifts(laws):
    """With pick-up (28) leaves the resting load free to move: the model holds
    from lift-off (tau_0 over and the rope force at the weight) on; from
    weight it holds throughout."""
    scene, report = laws
    v, q = report.values, scene.parameters
    weight = q["m2"] * q["g"]
    gen = importlib.import_module(hss.GENERATED)
    for i in range(1, 5):
        start = v[f"valid_from_pickup_a{i}"]
        assert q["tau_0"] <= start < q["tau_0"] + 1e-3
        assert v[f"valid_from_from_weight_a{i}"] == 0.0
        assert v[f"valid_to_pickup_a{i}"] == v[f"valid_to_from_weight_a{i}"] == 2.0
        a0 = float(hss._law(gen, i, np.zeros(1), q)[0])
        force = hss._k(gen, "pickup", i, np.array([start]), q)[0] * hss._reference(
            "pickup", a0, q)
        assert force >= weight * (1 - 1e-9)          # the rope holds the load's weight
    pickup = [p for p in report.panels if p.invalid]
    assert len(pickup) == 4 and all("(26)" in p.group for p in pickup)
    assert all("load on the ground" in p.invalid[0].reason for p in pickup)
    assert len(report.warnings) == 3 and "after lift-off" in report.warnings[1]
