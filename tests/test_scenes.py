"""Tests for crane_sym.scenes.reading and travel_braking.scene_report."""
import math
import os
from pathlib import Path

import numpy as np
import pytest

from crane_sym.scenes.reading import (Scene, SceneError, SceneReport, format_quantity,
                                      list_scenes, load_scene, scenes_directory)
from crane_sym.scenes.run import run_scene

PNG_MAGIC = b"\x89PNG\r\n\x1a\n"

HEAD = """\
[scene]
name = "probe"
derivation = "travel_braking"
title = "probe"
outputs = ["elastic_force"]
"""
PARAMETERS = {"m1": '"4.4 t"', "m2": '"110 t"', "c": '"3.0e6 N/m"',
              "P_t": '"24 kN"', "W": '"11 kN"', "v0": '"80 m/min"'}
OPTIONS = '[options]\nduration = "1.5 s"\npoints = 301\n'


def _write(tmp_path: Path, head: str = HEAD, options: str = OPTIONS,
           **changes: str | None) -> Path:
    """A scene file: the 50 t parameters with ``changes`` (None drops one)."""
    params = {**PARAMETERS, **changes}
    body = "".join(f"{k} = {v}\n" for k, v in params.items() if v is not None)
    path = tmp_path / "probe.toml"
    path.write_text(f"{head}[parameters]\n{body}{options}", encoding="utf-8")
    return path


@pytest.fixture(scope="module")
def crane() -> Scene:
    return load_scene("overhead_crane_50t")


def test_shipped_scene_is_listed():
    assert "overhead_crane_50t" in list_scenes()
    assert (scenes_directory("travel_braking") / "overhead_crane_50t.toml").is_file()


def test_50t_scene_loads_in_si(crane):
    assert crane.name == "overhead_crane_50t"
    assert crane.derivation == "travel_braking"
    assert crane.outputs == ("elastic_force", "velocity_m1", "velocity_m2")
    p = crane.parameters
    assert list(p) == ["m1", "m2", "c", "P_t", "W", "v0"]  # symbol-table order
    assert p["m1"] == 4400.0
    assert p["m2"] == 110000.0
    assert p["c"] == 3.0e6
    assert p["P_t"] == 24000.0
    assert p["W"] == 11000.0
    assert p["v0"] == pytest.approx(80 / 60, rel=1e-15)
    assert crane.options["duration"] == 1.5
    assert crane.options["points"] == 1501


def test_load_by_path_equals_load_by_name(crane):
    by_path = load_scene(scenes_directory("travel_braking") / "overhead_crane_50t.toml")
    assert by_path.parameters == crane.parameters
    assert by_path.options == crane.options


def test_run_scene_writes_png_and_peak_is_twice_rigid_force(crane, tmp_path):
    report, (png,) = run_scene(crane, tmp_path / "out")
    assert isinstance(report, SceneReport)
    assert png == tmp_path / "out" / "overhead_crane_50t.png"
    data = png.read_bytes()
    assert len(data) > 1000 and data[:8] == PNG_MAGIC

    p = crane.parameters
    m1, m2, c, P_t, W, v0 = (p[k] for k in ("m1", "m2", "c", "P_t", "W", "v0"))
    F_r = (P_t * m2 - W * m1) / (m1 + m2)
    omega = math.sqrt(c * (m1 + m2) / (m1 * m2))
    v = report.values
    assert v["F_r"] == pytest.approx(F_r, rel=1e-12)
    assert v["F_max"] == pytest.approx(2 * F_r, rel=1e-12)
    assert v["t_max"] == pytest.approx(math.pi / omega, rel=1e-12)
    assert v["p"] == pytest.approx(omega, rel=1e-12)
    assert v["dynamic_factor"] == pytest.approx(2.0, rel=1e-12)
    assert v["F_max_over_P_t"] == pytest.approx(2 * F_r / P_t, rel=1e-12)
    assert v["t_stop_rigid"] == pytest.approx(v0 * (m1 + m2) / (P_t + W), rel=1e-12)
    # This brake keeps slipping and the crane keeps moving for the 1.5 s shown.
    assert math.isnan(v["t_slip_end"]) and v["v1_min"] > 0
    assert math.isnan(v["t_v2_zero"]) and v["v2_min"] > 0

    # Curves: the force panel reaches the peak on the 1 ms grid; v1 from the formula.
    force, speeds = report.panels
    assert force.title == "Elastic link force" and "kN" in force.ylabel
    _, t, F_kN = force.curves[0]
    assert t[0] == 0.0 and t[-1] == 1.5 and len(t) == 1501
    assert F_kN.max() == pytest.approx(2 * F_r / 1e3, rel=1e-3)
    _, t1, v1 = speeds.curves[0]
    expected = v0 - (P_t + W) * t1 / (m1 + m2) - F_r * np.sin(omega * t1) / (m1 * omega)
    np.testing.assert_allclose(v1, expected, rtol=1e-12)
    assert any("45.31 kN" in line for line in report.lines)


def test_run_scene_png_is_deterministic(crane, tmp_path):
    first = run_scene(crane, tmp_path / "a")[1][0].read_bytes()
    second = run_scene(crane, tmp_path / "b")[1][0].read_bytes()
    assert first == second


def test_brake_stop_is_reported(tmp_path):
    # Slow travel, strong brake: v1 reaches 0 well within the duration.
    scene = load_scene(_write(tmp_path, v0='"0.05 m/s"', P_t='"200 kN"'))
    report, _ = run_scene(scene, tmp_path)
    t_end = report.values["t_slip_end"]
    assert 0 < t_end < 1.5
    assert any("stops slipping" in line for line in report.lines)


def test_missing_parameter_names_it(tmp_path):
    with pytest.raises(SceneError, match=r"parameter 'c' \(.*N/m\) is missing"):
        load_scene(_write(tmp_path, c=None))


def test_wrong_dimension_names_parameter(tmp_path):
    with pytest.raises(ValueError, match="'c'") as info:
        load_scene(_write(tmp_path, c='"3 kN*m/rad"'))
    assert isinstance(info.value, SceneError)


def test_unknown_parameter(tmp_path):
    with pytest.raises(SceneError, match="unknown parameter 'P_T'"):
        load_scene(_write(tmp_path, P_T='"24 kN"'))


def test_unknown_output(tmp_path):
    head = HEAD.replace('["elastic_force"]', '["elastic_force", "max_stress"]')
    with pytest.raises(SceneError, match="unknown output 'max_stress'"):
        load_scene(_write(tmp_path, head=head))


def test_unknown_derivation(tmp_path):
    head = HEAD.replace('"travel_braking"', '"hoist_lifting"')
    with pytest.raises(SceneError, match="hoist_lifting"):
        load_scene(_write(tmp_path, head=head))


def test_missing_scene_key(tmp_path):
    head = HEAD.replace('title = "probe"\n', "")
    with pytest.raises(SceneError, match="title"):
        load_scene(_write(tmp_path, head=head))


def test_bad_duration(tmp_path):
    with pytest.raises(SceneError, match="duration"):
        load_scene(_write(tmp_path, options='[options]\nduration = "1.5 m"\n'))


def test_unknown_scene_name():
    with pytest.raises(SceneError, match="unknown scene"):
        load_scene("no_such_scene")


def test_malicious_value_is_not_evaluated(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    payload = "\"__import__('os').system('touch HACKED')\""
    with pytest.raises(SceneError, match="'c'"):
        load_scene(_write(tmp_path, c=payload))
    assert not (tmp_path / "HACKED").exists()
    assert not Path(os.getcwd(), "HACKED").exists()


def test_format_quantity():
    assert format_quantity(45307.69 / 1e3, "kN") == "45.31 kN"
    assert format_quantity(0.1179774, "s") == "0.1180 s"
    assert format_quantity(2.0) == "2.000"
    assert format_quantity(1000.0, "N") == "1000 N"
