"""Scene-specialized modules: values folded in, only the requested outputs,
time the only argument, the same numbers as the general module."""
import importlib.util

import numpy as np
import pytest

from crane_sym import registry, scenes, specialize
from crane_sym.cli import main


@pytest.fixture(scope="module")
def scene():
    return scenes.load_scene("overhead_crane_50t")


def _load(path):
    spec = importlib.util.spec_from_file_location("scene_module", path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def test_scene_module_matches_general_module(scene, tmp_path):
    assert main(["generate", "--scene", "overhead_crane_50t", "--out", str(tmp_path)]) == 0
    special = _load(tmp_path / "scene_overhead_crane_50t.py")
    import crane_sym.generated.travel_braking as general
    assert special.__all__ == list(scene.outputs)
    p = scene.parameters
    t = np.linspace(0.0, 3.0, 2001)
    F = general.elastic_force(t, p["m1"], p["m2"], p["c"], p["P_t"], p["W"])
    assert np.max(np.abs(special.elastic_force(t) - F)) <= 1e-15 * np.max(np.abs(F))
    v1 = general.velocity_m1(t, p["m1"], p["m2"], p["c"], p["P_t"], p["W"], p["v0"])
    assert np.max(np.abs(special.velocity_m1(t) - v1)) <= 4e-16 * p["v0"]
    with pytest.raises(ValueError, match="t must be >= 0"):
        special.elastic_force(-1.0)


def test_scene_module_is_smaller_and_takes_time_only(scene):
    d = registry.get(scene.derivation)
    small = specialize.specialize(d, scene)
    assert [str(a) for o in small for a in o.args] == ["t"] * len(small)
    assert specialize.operation_count(small) < specialize.operation_count(
        [d.output(n) for n in scene.outputs])
    text = specialize.render_scene_module(d, scene)
    assert "def natural_frequency" not in text and "_diff_of_products" not in text
    assert "m2 = 110000.0 kg" in text


def test_shipped_scene_modules_are_generated_and_fresh(scene):
    files = specialize.shipped_scene_modules(registry.get)
    assert "scene_overhead_crane_50t.py" in files
    from crane_sym import codegen
    on_disk = codegen.default_directory() / "scene_overhead_crane_50t.py"
    assert on_disk.read_text() == files["scene_overhead_crane_50t.py"]
