"""Scene-specialized modules: values folded in, only the requested outputs,
time the only argument, the same numbers as the general module."""
import importlib.util

import numpy as np
import pytest

from crane_sym import registry
from crane_sym.scenes import reading as scenes
from crane_sym.scenes import specialize
from crane_sym.cli.main import main


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
    # The scene folds the phase rate exactly, the general module rounds it from
    # m1, m2, c (a few ulp): the two agree to the phase's conditioning.
    phase = general.natural_frequency(p["m1"], p["m2"], p["c"]) * t[-1] / 2
    assert np.max(np.abs(special.elastic_force(t) - F)) <= \
        8 * 2.0**-53 * (1 + phase) * np.max(np.abs(F))
    v1 = general.velocity_m1(t, p["m1"], p["m2"], p["c"], p["P_t"], p["W"], p["v0"])
    assert np.max(np.abs(special.velocity_m1(t) - v1)) <= 8 * 2.0**-53 * (1 + phase) * p["v0"]
    with pytest.raises(ValueError, match="t must be >= 0"):
        special.elastic_force(-1.0)


def test_scene_module_is_smaller_and_takes_time_only(scene):
    d = registry.get(scene.derivation)
    small = specialize.specialize(d, scene)
    assert [str(a) for o in small for a in o.args] == ["t"] * len(small)
    assert specialize.operation_count(small) < specialize.operation_count(
        [d.output(n) for n in scene.outputs])
    text = specialize.render_scene_module(scene)
    assert "def natural_frequency" not in text and "_diff_of_products" not in text
    assert "m2 = 110000.0 kg" in text


def test_shipped_scene_modules_are_generated_and_fresh(scene):
    files = specialize.shipped_scene_modules()
    assert "scene_overhead_crane_50t.py" in files
    from crane_sym.codegen import files as module_files
    on_disk = module_files.default_directory() / "scene_overhead_crane_50t.py"
    assert on_disk.read_text() == files["scene_overhead_crane_50t.py"]


# --- switches and inputs (paper 004: damping off, the load W left as an argument)
UNDAMPED = "drum_drive_undamped"


def test_switched_off_damping_leaves_no_damping_code(tmp_path):
    scene = scenes.load_scene(UNDAMPED)
    assert scene.switched_off == ("damping",) and scene.inputs == ("W",)
    assert main(["generate", "--scene", UNDAMPED, "--out", str(tmp_path)]) == 0
    path = tmp_path / f"scene_{UNDAMPED}.py"
    code = path.read_text().split('"""', 2)[2]          # after the module docstring
    assert not any(f"nu{x}" in code for x in ("1", "2", "_y", "_z", "_t"))
    special = _load(path)
    d = registry.get(scene.derivation)
    small = specialize.specialize(d, scene)
    assert specialize.operation_count(small) < specialize.operation_count(
        [d.output(n) for n in scene.outputs]) / 5
    import crane_sym.generated.drum_drive as general
    p = {**scene.parameters, **{n: 0.0 for n in ("nu1", "nu2", "nu_y", "nu_z", "nu_t")}}
    order = [str(a) for a in d.output("state_derivative").args]
    rng = np.random.default_rng(3)
    for _ in range(5):
        state = dict(zip([f"s{i}" for i in range(1, 11)], rng.normal(size=10) * 1e-3))
        W = float(rng.uniform(1e3, 1e4))
        expected = general.state_derivative(*[{**p, **state, "W": W}[a] for a in order])
        got = special.state_derivative(W, *state.values())
        assert np.allclose(got, expected, rtol=1e-13, atol=1e-13 * np.max(np.abs(expected)))
    jac_order = [str(a) for a in d.output("state_jacobian").args]
    assert np.allclose(special.state_jacobian(),
                       general.state_jacobian(*[p[a] for a in jac_order]), rtol=1e-14)


def _scene_text(options: str, extra_parameters: str = "", inputs: str = '["W"]') -> str:
    text = (scenes.scenes_directory("drum_drive") / f"{UNDAMPED}.toml").read_text()
    text = text.replace('inputs = ["W"]', f"inputs = {inputs}")
    text = text.replace("damping = false", options)
    return text.replace("[parameters]\n", "[parameters]\n" + extra_parameters)


@pytest.mark.parametrize("options, extra, inputs, message", [
    ('damping = "off"', "", '["W"]', r"\[options\] damping \(.*\) must be true or false, "
     "got 'off'"),
    ("damping = false", 'nu1 = "20 N*m*s/rad"\n', '["W"]', "'nu1' is fixed by a switch"),
    ("damping = false", 'W = "1 kN"\n', '["W"]', "'W' is an input of the scene"),
    ("damping = false", "", '["mu"]', "input 'mu' is not a parameter"),
    ("damping = true", "", '["W"]', "parameter 'nu1'.*is missing"),
])
def test_switch_and_input_errors_name_the_key(tmp_path, options, extra, inputs, message):
    path = tmp_path / "scene.toml"
    path.write_text(_scene_text(options, extra, inputs))
    with pytest.raises(scenes.SceneError, match=message):
        scenes.load_scene(path)


def test_scene_module_header_names_the_command_that_regenerates_it(tmp_path, monkeypatch):
    """A shipped scene by its name; a user's scene by its file's name (no
    absolute path, so the shipped modules read the same on every machine),
    and that command writes the same module again."""
    shipped = specialize.render_scene_module(scenes.load_scene("overhead_crane_50t"))
    assert ("regenerate with `crane-sym generate --scene overhead_crane_50t --out <folder>`."
            in shipped)
    source = scenes.scene_path("overhead_crane_50t").read_text(encoding="utf-8")
    mine = tmp_path / "my_crane.toml"
    mine.write_text(source.replace('name = "overhead_crane_50t"', 'name = "my_crane"'),
                    encoding="utf-8")
    text = specialize.render_scene_module(scenes.load_scene(mine))
    assert "regenerate with `crane-sym generate --scene my_crane.toml --out <folder>`." in text
    assert str(tmp_path) not in text and "regenerate with `crane-sym generate`." not in text
    same_name = tmp_path / "copy.toml"          # a copy keeps the name, not the file
    same_name.write_text(source, encoding="utf-8")
    assert "--scene copy.toml " in specialize.render_scene_module(scenes.load_scene(same_name))
    monkeypatch.chdir(tmp_path)
    assert main(["generate", "--scene", "my_crane.toml", "--out", "again"]) == 0
    assert (tmp_path / "again" / "scene_my_crane.py").read_text(encoding="utf-8") == text
    import crane_sym.generated.travel_braking as general   # the paper's module: unchanged
    assert "regenerate with `crane-sym generate`." in (general.__doc__ or "")
