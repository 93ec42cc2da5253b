"""One route for piecewise-linear models (crane_sym.mechanics.hybrid_models and
each paper's hybrid.py), one scene_report convention (crane_sym.scenes.kinds),
and a scene's time grid (Scene.times)."""
import pickle
from types import SimpleNamespace

import numpy as np
import pytest

from crane_sym import registry
from crane_sym.derivation import TabulatedOutput
from crane_sym.mechanics.hybrid_models import HybridModel, HybridSolution
from crane_sym.mechanics.phase_table import HybridRun, largest, values
from crane_sym.scenes.kinds import SceneKind, kind_of
from crane_sym.scenes.reading import list_scenes, load_scene

HYBRID_PAPERS = ("hoist_brakes", "portal_travel")


@pytest.mark.parametrize("paper", HYBRID_PAPERS)
def test_paper_declares_its_hybrid_models(paper):
    """The slot of the template: HYBRID_MODELS of HybridModel, re-exported by
    the package, each with parameters, settings and named outputs, and
    picklable (a sweep may send it to worker processes)."""
    models = registry.module(paper).HYBRID_MODELS
    assert models
    for name, model in models.items():
        assert isinstance(model, HybridModel) and model.name == name
        assert model.parameters and all(isinstance(p, str) for p in model.parameters)
        assert all(isinstance(s, str) for s in model.settings)
        assert model.outputs and model.summary
        assert pickle.loads(pickle.dumps(model)).name == name


def test_hoist_scene_tabulates_the_hybrid_model():
    """001's tabulated output is the run of hybrid.EMERGENCY_STOP: the same
    system, initial state, end, schedule and output."""
    from crane_sym.derivations.hoist_brakes.hybrid import EMERGENCY_STOP
    from crane_sym.derivations.hoist_brakes.outputs import tabulated
    scene = load_scene("hoist_table1")
    (out,) = tabulated()
    assert isinstance(out, TabulatedOutput)
    assert [s.name for s in out.args] == list(EMERGENCY_STOP.parameters)
    run = out.run(scene.parameters, scene.options)
    assert isinstance(run, HybridRun)
    mine = EMERGENCY_STOP.run(scene.parameters, scene.settings)
    assert type(run.system) is type(mine.system) and run.mode == mine.mode
    for A, B in zip(run.system.matrices(run.mode), mine.system.matrices(mine.mode)):
        assert np.array_equal(A, B)
    assert np.array_equal(run.x0, mine.x0) and run.t_end == mine.t_end == 1.0
    assert tuple(run.schedule) == tuple(mine.schedule)
    times = np.linspace(0.0, 1.0, 501)
    result = run.solve()
    solved = EMERGENCY_STOP.solve(scene.parameters, scene.settings)
    assert np.array_equal(solved.values("relative_torque", times),
                          values(result, times, run.output))
    assert solved.peak("relative_torque") == largest(result, run.system, run.output,
                                                     magnitude=True)


def test_hoist_sweep_output_is_the_model_peak():
    """The sweep output of 001 (both designs solved together by the batched
    solver) is |peak| of the model's run per design (the numeric eigenvector
    route), to rounding."""
    from crane_sym.derivations.hoist_brakes.hybrid import EMERGENCY_STOP
    from crane_sym.derivations.hoist_brakes.sweep_outputs import SWEEP_OUTPUTS
    scene = load_scene("hoist_table1")
    values = {n: scene.parameters[n] for n in EMERGENCY_STOP.parameters}
    values["m_p"] = np.array([0.0, 26e3])
    got = SWEEP_OUTPUTS["peak_elastic_gearbox_torque"].evaluate(values, scene.options)
    for k, payload in enumerate(values["m_p"]):
        one = EMERGENCY_STOP.solve({**values, "m_p": float(payload)}, scene.options,
                                   exact=False)
        assert got[k] == pytest.approx(abs(one.peak("relative_torque")[1]), rel=1e-12)


def test_portal_model_is_the_table1_model():
    """003's STARTUP on Table 1's chosen values is the run the steps' Table 1
    takes (startup.table1_results): same peak, time and step accelerations."""
    from crane_sym.derivations.portal_travel.drive_train import step_accelerations, total_load
    from crane_sym.derivations.portal_travel.hybrid import STARTUP
    from crane_sym.derivations.portal_travel.startup import (BACKLASH, CHOSEN, HOLDS,
                                                             reduced, table1_results)
    table = table1_results()
    for name, phi in BACKLASH.items():
        values = {**reduced(CHOSEN, phi), **{k: CHOSEN[k] for k in ("m_k", "c_l", "W_f",
                                                                     "W_w")}}
        solved = STARTUP.solve(values, {"holds": HOLDS, "end": 4.0})
        assert isinstance(solved, HybridSolution)
        when, peak = solved.peak("load")
        assert (peak / 1e3, when) == (table[name]["F_max_kN"], table[name]["t_max"])
        acc = step_accelerations(solved.result, solved.system)
        assert [float(a) for a in acc] == [table[name][f"a{k}"] for k in (1, 2, 3)]
        assert (when, peak) == largest(solved.result, solved.system,
                                       total_load(solved.system))


def test_state_outputs_are_the_state():
    """An output that is one state component reads exactly that component."""
    from crane_sym.derivations.portal_travel.hybrid import STARTUP
    from crane_sym.derivations.portal_travel.startup import BACKLASH, CHOSEN, HOLDS, reduced
    values = {**reduced(CHOSEN, BACKLASH["pi"]), **{k: CHOSEN[k] for k in ("m_k", "c_l",
                                                                         "W_f", "W_w")}}
    solved = STARTUP.solve(values, {"holds": HOLDS, "end": 4.0})
    times = np.linspace(0.0, 4.0, 801)
    x = solved.state(times)
    assert np.array_equal(solved.values("motor_speed", times), x[:, 1])
    assert np.array_equal(solved.values("crane_speed", times), x[:, 5])
    total = solved.values("load", times)
    left = solved.values("left_link_load", times)
    assert np.allclose(total, 2 * left, rtol=0, atol=1e-6 * np.max(np.abs(total)))


def test_scene_times_is_the_grid_of_its_settings():
    scene = load_scene("hoist_table1")
    t = scene.times()
    assert np.array_equal(t, np.linspace(0.0, scene.settings["duration"],
                                         scene.settings["points"]))
    assert t[-1] == scene.settings["duration"]
    startup = load_scene("fig12_startup_backlash")
    end = startup.settings["end"][0]
    assert np.array_equal(startup.times(end), np.linspace(0.0, end, startup.settings["points"]))


@pytest.mark.parametrize("paper", registry.ids())
def test_every_paper_declares_its_kinds_of_scene(paper):
    """REPORTS of SceneKind in every report.py, and scene_report answers by it."""
    report = __import__(f"crane_sym.derivations.{paper}.report", fromlist=["REPORTS"])
    assert report.REPORTS and all(isinstance(k, SceneKind) for k in report.REPORTS)
    assert registry.module(paper).scene_report is report.scene_report


def test_every_shipped_scene_has_a_kind():
    """Each shipped scene is taken by a kind of its paper, and the kinds that
    mark scenes by outputs or a load take their own."""
    taken = {}
    for name in list_scenes():
        scene = load_scene(name)
        report = __import__(f"crane_sym.derivations.{scene.derivation}.report",
                            fromlist=["REPORTS"])
        taken[name] = kind_of(report.REPORTS, scene).report.__name__
    assert taken["fig12_startup_backlash"] == "startup_report"
    assert taken["fig10_shift_limits"] == "fig10_report"
    assert taken["form1_gear_pair"] == "gear_pair_report"
    assert taken["portal_support_loads"] == "support_report"
    assert taken["hoist_user_drive_law"] == "drive_law_report"
    assert taken["hoist_fig3"] == "figure_report"
    assert taken["drum_drive_example"] == "example_report"
    assert taken["drum_drive_undamped"] == "state_report"


def test_kind_rules():
    def report(scene, module):
        return None
    marked = SceneKind("marked", report, outputs=("a",))
    loaded = SceneKind("loaded", report, load="law")
    rest = SceneKind("rest", report)
    scene = SimpleNamespace(name="s", outputs=("b",), load_table="")
    assert kind_of((marked, loaded, rest), scene) is rest
    assert kind_of((marked, rest), SimpleNamespace(name="s", outputs=("a",),
                                                   load_table="")) is marked
    with_load = SimpleNamespace(name="s", outputs=("b",), load_table="law")
    assert kind_of((marked, loaded, rest), with_load) is loaded
    with pytest.raises(ValueError, match="none of the kinds"):
        kind_of((marked, rest), SimpleNamespace(name="s", outputs=(), load_table="other"))


def test_portal_scene_tabulates_one_run_per_backlash(tmp_path):
    """003's start-up scene carries each curve per backlash of its settings
    (<name>_<k>), the tables of hybrid.STARTUP's runs; they agree with the
    double run on the scene module's own rim quantities to ~1e-10 of the peak."""
    from crane_sym.derivations.portal_travel.hybrid import STARTUP, scene_runs
    from crane_sym.derivations.portal_travel.options import STARTUP_CURVES
    from crane_sym.scenes.run import import_module_file
    from crane_sym.scenes.specialize import module_name, render_scene_module, tabulated_runs
    scene = load_scene("fig12_startup_backlash")
    assert set(STARTUP_CURVES) <= set(scene.outputs)
    runs = tabulated_runs(registry.get("portal_travel"), scene)
    gaps = scene.settings["backlash"]
    assert [out.name for out, _ in runs] == [f"{name}_{k}" for name in STARTUP_CURVES
                                             for k in range(len(gaps))]
    assert len(scene_runs("load", scene.parameters, scene.settings)) == len(gaps)
    path = tmp_path / module_name(scene)
    path.write_text(render_scene_module(scene), encoding="utf-8")
    module = import_module_file(path)
    q, end = scene.parameters, scene.settings["end"][0]
    rim = {"m_d": float(module.startup_motor_mass()), "m_k": q["m_k"], "c_l": q["c_l"],
           "b": float(module.startup_link_damping()),
           "v0": float(module.startup_no_load_speed()),
           "beta_1": float(module.startup_first_slope()),
           "q": float(module.startup_slope_ratio()), "W_f": q["W_f"], "W_w": q["W_w"]}
    times = scene.times(end)
    for k, phi in enumerate(gaps):
        s = float(module.startup_backlash_at_rim(phi))
        solved = STARTUP.solve({**rim, "s": s}, {"holds": scene.settings["holds"], "end": end})
        for output, name in zip(STARTUP.outputs, STARTUP_CURVES):
            ref = solved.values(output, times)
            got = getattr(module, f"{name}_{k}")(times)
            assert np.max(np.abs(got - ref)) < 1e-10 * np.max(np.abs(ref)), (name, k)


def test_startup_scene_without_its_curves_is_refused(tmp_path):
    from crane_sym.scenes.reading import SceneError, scene_path
    text = scene_path("fig12_startup_backlash").read_text(encoding="utf-8")
    short = text.replace('"startup_load", ', "")
    assert short != text
    path = tmp_path / "short.toml"
    path.write_text(short, encoding="utf-8")
    with pytest.raises(SceneError, match="startup_load"):
        load_scene(path)
