"""A user's piecewise-polynomial drive law (paper 002, a scene load): the generated
module against direct integration of the two-mass hoist and against quadrature
of Duhamel's integral; continuity at the breakpoints; scene validation."""
import importlib.util
from pathlib import Path

import numpy as np
import pytest
import sympy as sp

from crane_sym.derivations.hoist_startup import drive_law as dl
from crane_sym.derivations.hoist_startup import drive_law_scene as dls
from crane_sym.scenes.run import run_scene
from crane_sym.scenes.reading import SceneError, load_scene, scenes_directory
from crane_sym.scenes.specialize import render_scene_module, scene_files

integrate = pytest.importorskip("scipy.integrate")

EXAMPLE = "hoist_user_drive_law"
HEAD = """\
[scene]
name = "probe"
derivation = "hoist_startup"
title = "probe"
[parameters]
m1 = "2 t"
m2 = "8 t"
C = "1.0e6 N/m"
g = "9.81 m/s^2"
"""
LAW = """\
[drive_law]
lifting = "{lifting}"
breakpoints = [0.0, 0.25, 1.0, 1.25]
coefficients = [[0.0, 2.0], [0.5], [0.5, -2.0]]
"""
OPTIONS = '[options]\nduration = "2.5 s"\npoints = 501\n'


def _write(tmp_path: Path, text: str, name: str = "probe.toml") -> Path:
    path = tmp_path / name
    path.write_text(text, encoding="utf-8")
    return path


def _import(source: str, path: Path):
    path.write_text(source, encoding="utf-8")
    spec = importlib.util.spec_from_file_location(path.stem, path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


@pytest.fixture(scope="module", params=[dl.FROM_WEIGHT, dl.PICKUP])
def case(request, tmp_path_factory):
    """(scene, response, generated module) for the example law in both lifting cases."""
    tmp = tmp_path_factory.mktemp(request.param)
    if request.param == dl.FROM_WEIGHT:
        scene = load_scene(EXAMPLE)
    else:
        scene = load_scene(_write(tmp, HEAD + LAW.format(lifting="pickup") + OPTIONS))
    module = _import(render_scene_module(scene), tmp / "scene_module.py")
    return scene, dls.response(scene), module


def _numbers(scene):
    return tuple(float(scene.parameters[k]) for k in ("m1", "m2", "C", "g"))


def _acceleration(t: float) -> float:
    """The example law, written out by hand: 2 t, 0.5, 0.5 - 2 (t - 1), then 0."""
    if t < 0.25:
        return 2.0 * t
    if t < 1.0:
        return 0.5
    if t < 1.25:
        return 0.5 - 2.0 * (t - 1.0)
    return 0.0


def _resistance(t: float, scene, tau0: float | None) -> float:
    weight = float(scene.parameters["m2"] * scene.parameters["g"])
    return weight if tau0 is None else weight * min(t / tau0, 1.0)


def test_example_scene_reads_in_si():
    scene = load_scene(EXAMPLE)
    r = dls.response(scene)
    assert (r.m1, r.m2, r.C, r.g) == (2000, 8000, 10**6, sp.Rational(981, 100))
    assert scene.load.breakpoints == (0, sp.Rational(1, 4), 1, sp.Rational(5, 4))
    assert scene.load.coefficients == ((0, 2), (sp.Rational(1, 2),), (sp.Rational(1, 2), -2))
    assert len(scene.load.coefficients) == 3                     # a 3-piece law
    assert scene.load.lifting == dl.FROM_WEIGHT and scene.options["duration"] == 2.5
    assert scene.load_table == "drive_law"
    assert load_scene("overhead_crane_50t").load_table == ""


def test_generated_functions_take_time_only_and_validate(case):
    scene, response, module = case
    assert module.__all__ == ["drive_acceleration", "drive_speed", "relative_forcing",
                              "rope_stretch", "rope_stretch_rate", "rope_force",
                              "dynamic_coefficient", "load_acceleration"]
    with pytest.raises(ValueError, match="t must be >= 0"):
        module.rope_stretch(-1.0)
    t = np.linspace(0.0, 2.5, 11)
    for name in module.__all__:
        assert getattr(module, name)(t).shape == t.shape
    assert response.final_speed == sp.Rational(1, 2)
    assert module.drive_speed(2.0) == pytest.approx(0.5, rel=1e-14)
    assert np.allclose(module.drive_acceleration(t), [_acceleration(x) for x in t],
                       rtol=0, atol=1e-15)


def test_against_direct_integration_of_the_two_mass_system(case):
    """(1): m1 x1'' + C (x1 - x2) = P(t), m2 x2'' - C (x1 - x2) = -Q(t),
    P = (m1 + m2) a + m2 g, by DOP853 at rtol 1e-12, piece by piece."""
    scene, response, module = case
    m1, m2, C, g = _numbers(scene)
    tau0 = None if response.contact_time is None else float(response.contact_time)

    def rhs(t, y):
        x1, x2, v1, v2 = y
        rope = C * (x1 - x2)
        return [v1, v2, ((m1 + m2) * _acceleration(t) + m2 * g - rope) / m1,
                (rope - _resistance(t, scene, tau0)) / m2]

    cuts = sorted({0.0, 0.25, 1.0, 1.25, 2.5} | ({tau0} if tau0 else set()))
    y = [0.0 if tau0 else m2 * g / C, 0.0, 0.0, 0.0]
    times, stretch, rate = [], [], []
    for lo, hi in zip(cuts[:-1], cuts[1:]):
        grid = np.linspace(lo, hi, 60)
        sol = integrate.solve_ivp(rhs, (lo, hi), y, method="DOP853", t_eval=grid,
                                  rtol=1e-12, atol=1e-16)
        assert sol.success
        y = sol.y[:, -1]
        times.append(grid)
        stretch.append(sol.y[0] - sol.y[1])
        rate.append(sol.y[2] - sol.y[3])
    t = np.concatenate(times)
    x, v = np.concatenate(stretch), np.concatenate(rate)
    assert np.max(np.abs(module.rope_stretch(t) - x)) <= 1e-9 * np.max(np.abs(x))
    assert np.max(np.abs(module.rope_stretch_rate(t) - v)) <= 1e-8 * np.max(np.abs(v))
    force = C * x
    assert np.max(np.abs(module.rope_force(t) - force)) <= 1e-9 * np.max(force)
    ref = float(response.reference)
    assert np.max(np.abs(module.dynamic_coefficient(t) - force / ref)) <= 1e-9 * np.max(
        force / ref)
    load = (force - np.array([_resistance(s, scene, tau0) for s in t])) / m2
    assert np.max(np.abs(module.load_acceleration(t) - load)) <= 1e-8 * np.max(np.abs(load))


@pytest.mark.filterwarnings("ignore::scipy.integrate.IntegrationWarning")
def test_against_quadrature_of_the_duhamel_integral(case):
    """(21), (23): x = x0 cos Ωt + (1/Ω) ∫_0^t S(θ) sin Ω(t - θ) dθ, by quadrature."""
    scene, response, module = case
    m1, m2, C, g = _numbers(scene)
    omega = float(response.omega)
    tau0 = None if response.contact_time is None else float(response.contact_time)
    x0 = 0.0 if tau0 else m2 * g / C

    def forcing(s):
        return ((m1 + m2) * _acceleration(s) + m2 * g) / m1 + _resistance(s, scene, tau0) / m2

    rng = np.random.default_rng(20261121)
    cuts = [0.25, 1.0, 1.25] + ([tau0] if tau0 else [])
    for t in np.concatenate([rng.uniform(0.0, 2.5, 12), cuts]):
        inside = [c for c in cuts if c < t]
        value, error = integrate.quad(lambda s: forcing(s) * np.sin(omega * (t - s)), 0.0, t,
                                      points=inside or None, epsabs=0.0, epsrel=1e-12,
                                      limit=200)
        x = x0 * np.cos(omega * t) + value / omega
        assert module.rope_stretch(t) == pytest.approx(x, rel=1e-10, abs=1e-14)
        assert module.relative_forcing(t) == pytest.approx(forcing(t), rel=1e-13)


def test_stretch_and_rate_are_continuous_at_every_breakpoint(case):
    scene, response, module = case
    pieces, t = response.stretch.pieces, response.t
    assert len(pieces) == (5 if scene.load.lifting == dl.PICKUP else 4)
    for left, right in zip(pieces[:-1], pieces[1:]):
        b = left.end
        assert b == right.start
        for order in (0, 1):
            jump = (left.expr.diff(t, order) - right.expr.diff(t, order)).subs(t, b)
            assert abs(sp.N(jump, 50)) < 1e-40
        below, above = np.nextafter(float(b), 0.0), np.nextafter(float(b), 9.0)
        for func in (module.rope_stretch, module.rope_stretch_rate):
            scale = np.max(np.abs(func(np.linspace(0.0, 2.5, 501))))
            assert abs(func(above) - func(below)) <= 1e-13 * scale


def test_strings_in_the_law_are_refused_without_evaluation(tmp_path):
    marker = tmp_path / "evaluated"
    payload = f"__import__('pathlib').Path({str(marker)!r}).touch() or 1"
    for breakpoints, coefficients in (
            ("[0.0, 0.25, 1.0, 1.25]", f'[[0.0, "{payload}"], [0.5], [0.5, -2.0]]'),
            ("[0.0, 0.25, 1.0, 1.25]", '[[0.0, 2.0], "[0.5]", [0.5, -2.0]]'),
            (f'[0.0, "{payload}", 1.0, 1.25]', "[[0.0, 2.0], [0.5], [0.5, -2.0]]")):
        law = (f'[drive_law]\nlifting = "from_weight"\nbreakpoints = {breakpoints}\n'
               f"coefficients = {coefficients}\n")
        path = _write(tmp_path, HEAD + law + OPTIONS)
        with pytest.raises(SceneError, match="string|not strings|sequence of numbers"):
            load_scene(path)
    with pytest.raises(TypeError, match="never evaluated"):
        dl.drive_law([0, 1], [["1 + 1"]])
    assert not marker.exists()


@pytest.mark.parametrize("law, message", [
    (LAW.format(lifting="sideways"), "lifting must be"),
    (LAW.format(lifting="pickup").replace("[0.5], ", ""), "coefficients needs 3 rows"),
    (LAW.format(lifting="pickup").replace("1.0, 1.25]", "0.2, 1.25]"), "must increase"),
    (LAW.format(lifting="pickup") + 'time_unit = "m"\n', "time_unit"),
    (LAW.format(lifting="pickup") + "shape = 3\n", r"unknown keys \['shape'\]"),
])
def test_bad_laws_name_what_is_wrong(tmp_path, law, message):
    with pytest.raises(SceneError, match=message):
        load_scene(_write(tmp_path, HEAD + law + OPTIONS))


def test_bad_system_data_and_tables_are_named(tmp_path):
    law = LAW.format(lifting="from_weight")
    with pytest.raises(SceneError, match="parameter 'g' .* is missing"):
        load_scene(_write(tmp_path, HEAD.replace('g = "9.81 m/s^2"\n', "")
                                       + law + OPTIONS))
    with pytest.raises(SceneError, match="parameter 'C'"):
        load_scene(_write(tmp_path, HEAD.replace("N/m", "N") + law + OPTIONS))
    with pytest.raises(SceneError, match=r"unknown table 'extra'; expected scene, "
                                         r"parameters, options, drive_law$"):
        load_scene(_write(tmp_path, HEAD + law + OPTIONS + "[extra]\n"))
    with pytest.raises(SceneError, match=r"unknown table 'drive_law'"):
        load_scene(_write(tmp_path, HEAD.replace(
            '"hoist_startup"', '"travel_braking"') + law + OPTIONS))


def test_units_of_the_law_are_converted(tmp_path):
    """The same law in ms and mm/s²: c_kj in mm/s² per ms^j."""
    law = ('[drive_law]\nlifting = "from_weight"\ntime_unit = "ms"\n'
           'acceleration_unit = "mm/s^2"\nbreakpoints = [0, 250, 1000, 1250]\n'
           "coefficients = [[0, 2.0], [500], [500, -2.0]]\n")
    scene = load_scene(_write(tmp_path, HEAD + law + OPTIONS))
    example = load_scene(EXAMPLE)
    assert scene.load.breakpoints == example.load.breakpoints
    assert scene.load.coefficients == example.load.coefficients


def test_pickup_needs_a_law_that_ends_at_a_speed():
    law = dl.drive_law([0, 1], [[-1]])           # ends at v = -1 m/s
    with pytest.raises(ValueError, match="tau_0"):
        dl.respond(law, 2000, 8000, 10**6, 9.81, dl.PICKUP)
    with pytest.raises(ValueError, match="lifting must be"):
        dl.respond(law, 2000, 8000, 10**6, 9.81, "hanging")


def test_paper_law_a3_matches_the_general_generated_function():
    """a_3 of (30) given as a user law: the same K as the derivation's function."""
    import crane_sym.generated.hoist_startup as gen
    v0, t_n, m1, m2, C, g = (sp.Rational(1, 4), 1, 2000, 8000, 10**6, sp.Rational(981, 100))
    law = dl.drive_law([0, t_n], [[0, 12 * v0, -24 * v0, 12 * v0]])
    tau0 = m2 * g / (C * v0)
    for lifting in (dl.PICKUP, dl.FROM_WEIGHT):
        response = dl.respond(law, m1, m2, C, g, lifting, contact_time=tau0)
        k = sp.lambdify(response.t, response.dynamic_coefficient(), "numpy")
        t = np.linspace(0.0, 2.0, 801)
        args = (25.0,) + ((float(tau0),) if lifting == dl.PICKUP else ())
        ref = getattr(gen, f"dynamic_coefficient_{lifting}_a3")(t, *args, 2000.0, 8000.0,
                                                                 9.81, 0.25, 1.0)
        assert np.max(np.abs(k(t) - ref)) <= 1e-12 * np.max(np.abs(ref))


def test_cli_files_are_deterministic_and_named_by_the_scene(tmp_path):
    files = scene_files(EXAMPLE)
    assert list(files) == ["scene_hoist_user_drive_law.py"]
    assert files == scene_files(scenes_directory("hoist_startup") / f"{EXAMPLE}.toml")
    text = files["scene_hoist_user_drive_law.py"]
    assert "Drive law of scene 'hoist_user_drive_law'" in text
    assert "def rope_stretch(t, *, out=None):" in text and "eval(" not in text
    from crane_sym.scenes import specialize
    shipped = specialize.shipped_scene_modules()
    assert shipped["scene_hoist_user_drive_law.py"] == text


def test_run_writes_the_module_and_a_plot_and_bounds_the_samples(tmp_path):
    """`crane-sym run` on a drive-law scene: the module it writes is the one
    `generate --scene` gives, and the guaranteed K_max bounds every sample."""
    law = ('[drive_law]\nlifting = "from_weight"\nbreakpoints = [0.0, 0.3]\n'
           "coefficients = [[1.0]]\n")
    path = _write(tmp_path, HEAD + law + '[options]\nduration = "0.6 s"\npoints = 301\n')
    report, figures = run_scene(path, tmp_path / "out")
    assert [f.name for f in figures] == ["probe_1.png", "probe_2.png"]   # a and v apart
    assert all(f.is_file() and f.stat().st_size > 0 for f in figures)
    written = (tmp_path / "out" / "scene_probe.py").read_text(encoding="utf-8")
    assert written == scene_files(path)["scene_probe.py"]
    module = _import(written, tmp_path / "again.py")
    t = np.linspace(0.0, 0.6, 301)
    k = module.dynamic_coefficient(t)
    assert report.values["certified"] == 1.0
    assert np.max(k) <= report.values["K_max"] * (1 + 1e-12)
    # a step a = 1 m/s² from weight: rope force m2 (g + a (1 - cos Ωt)) over the
    # rigid load's m2 (g + a) (27) peaks at (g + 2a)/(g + a)
    assert report.values["K_max"] == pytest.approx((9.81 + 2.0) / (9.81 + 1.0), rel=1e-9)
