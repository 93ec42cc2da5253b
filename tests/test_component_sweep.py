"""Design sweeps of a component file: the batched sweep against the per-design
component run on the same grid, a real LocalCluster bit for bit against the
local scheduler, and bad axes and outputs refused by name, exit 2, nothing
written."""
from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest

from crane_sym.cli.main import main
from crane_sym.components.designs import designs
from crane_sym.sweep.component_plan import plan_file
from crane_sym.sweep.grid import run_sweep
from crane_sym.sweep.report import text_lines

xr = pytest.importorskip("xarray")
FIG9 = str(Path(__file__).resolve().parents[1] / "examples" / "drive_trains" / "hoist_fig9.toml")
AXES = ["gearbox_mesh.stiffness=1e4:1e5:3:log", "hook.mass=40:62:2"]
OUTPUTS = ["gearbox_mesh.peak", "gearbox_mesh.factor"]


def test_the_sweep_equals_the_per_design_component_run_on_its_grid(tmp_path, capsys):
    """Every design of a 3 x 2 grid, both outputs, against ``Model.run`` of a
    model derived from scratch for that design (the route of `crane-sym run`),
    to 1e-9 of the peak; the summary's worst case is the grid's."""
    argv = ["sweep", FIG9, "--out", str(tmp_path / "out"), "--format", "json", "--quiet",
            "--scheduler", "synchronous"]
    for a in AXES:
        argv += ["--vary", a]
    for o in OUTPUTS:
        argv += ["--output", o]
    assert main(argv) == 0
    data = json.loads(capsys.readouterr().out)
    assert text_lines(data)[0].startswith("sweep of drive train hoist_fig9: 6 designs")
    stored = xr.open_zarr(data["dataset"]).load()
    found = designs(FIG9)
    stiffness = np.geomspace(1e4, 1e5, 3)[:, None]
    mass = np.linspace(40e3, 62e3, 2)[None, :]
    for name in OUTPUTS:
        reference = found.per_design(name, {"gearbox_mesh.stiffness": stiffness,
                                            "hook.mass": mass})
        swept = stored[name].values
        assert swept.shape == (3, 2)
        assert np.max(np.abs(swept - reference)) <= 1e-9 * np.max(reference)
        unit, factor = ("kN*m", 1e3) if name.endswith("peak") else ("", 1.0)
        worst = data["outputs"][name]["worst"]
        assert worst["unit"] == unit
        assert worst["value"] * factor == pytest.approx(reference.max(), rel=1e-9)
        i, j = np.unravel_index(np.argmax(reference), reference.shape)
        assert worst["design"]["gearbox_mesh.stiffness"]["value"] == \
            pytest.approx(stiffness[i, 0])
        assert worst["design"]["hook.mass"] == {"value": pytest.approx(mass[0, j] / 1e3),
                                                "unit": "t"}
    # at the file's own design the factor is what `crane-sym run` prints, |M_G/M_st|
    own = found.largest("gearbox_mesh.factor", {"gearbox_mesh.stiffness": np.array([4e4])})
    run = found.model.run(found.file.duration, found.file.body, found.file.speed)
    assert own[0] == pytest.approx(abs(run.peaks[0].factor), rel=1e-9)
    assert (tmp_path / "out" / "hoist_fig9_sweep.png").is_file()


def test_local_cluster_is_bit_for_bit_the_local_scheduler(tmp_path):
    distributed = pytest.importorskip("distributed")
    chosen = plan_file(FIG9, ["gearbox_mesh.stiffness=1e4:1e5:4:log",
                              "safety_brakes.delay=0.05:0.2:3"], ["gearbox_mesh.peak"])
    local = run_sweep(chosen, tmp_path / "local", chunk_bytes=24)
    assert local.blocks > 2                        # several blocks, not one
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                  dashboard_address=":0") as cluster:
        remote = run_sweep(chosen, tmp_path / "cluster", scheduler=cluster.scheduler_address,
                           chunk_bytes=24)
    assert remote.chunks == local.chunks and remote.worst == local.worst
    a, b = (xr.open_zarr(r.dataset).load()["gearbox_mesh.peak"].values
            for r in (local, remote))
    assert np.array_equal(a.view(np.uint64), b.view(np.uint64))
    assert np.all(np.isfinite(a)) and a.min() > 0


BAD = [
    (["--vary", "coupling.stiffness=1e4:1e5:3"], "--vary 'coupling.stiffness=1e4:1e5:3'",
     "no component 'coupling' in model 'hoist_fig9'"),
    (["--vary", "gearbox_mesh.stifness=1e4:1e5:3"], "--vary 'gearbox_mesh.stifness",
     "has no value 'stifness' to vary; did you mean 'stiffness'"),
    (["--vary", "stiffness=1e4:1e5:3"], "--vary 'stiffness=1e4:1e5:3'", "COMPONENT.FIELD"),
    (["--vary", "gearbox_mesh.stiffness=1e4:1e5:3 kN"], "--vary", "does not fit"),
    (["--vary", "gearbox_mesh.stiffness=1e4:1e5:3 furlong"], "--vary", "unknown unit"),
    (["--vary", "gearbox_mesh.stiffness=0:1e5:3"], "--vary", "must be > 0"),
    (["--vary", "gearbox_mesh.stiffness=1e4:1e5:3", "--vary",
      "gearbox_mesh.stiffness=1:2:3"], "--vary", "varied twice"),
    (["--vary", "gearbox_mesh.reference=1:2:3 kN*m"], "--vary gearbox_mesh.reference",
     "is not an argument of gearbox_mesh.peak"),
    (["--vary", "drive.torque=1:2:3"], "--vary 'drive.torque", "no value 'torque' to vary"),
    (["--vary", "hook.mass=40:62:3", "--at", "t=0.1"], "--at 't=0.1'", "maxima over"),
    (["--vary", "hook.mass=40:62:3", "--limit", "gearbox_mesh.peak<=40 kg"], "--limit",
     "does not fit"),
]


@pytest.mark.parametrize("extra, names, why", BAD, ids=[b[2][:30] for b in BAD])
def test_bad_axes_are_refused_by_name_with_nothing_written(tmp_path, capsys, extra, names,
                                                            why):
    out = tmp_path / "out"
    argv = ["sweep", FIG9, "--output", "gearbox_mesh.peak", "--out", str(out), "--quiet",
            *extra]
    assert main(argv) == 2
    err = capsys.readouterr().err
    assert names in err and why in err
    assert len(err.strip().splitlines()) == 1
    assert not out.exists()


def test_an_unknown_output_lists_the_known_ones(tmp_path, capsys):
    out = tmp_path / "out"
    assert main(["sweep", FIG9, "--vary", "hook.mass=40:62:3", "--output", "coupling.peak",
                 "--out", str(out)]) == 2
    err = capsys.readouterr().err
    assert "--output 'coupling.peak'" in err and "gearbox_mesh.peak, gearbox_mesh.factor" in err
    assert len(err.strip().splitlines()) == 1 and not out.exists()


def test_a_backlash_swept_from_zero_takes_the_derivation_of_its_own_structure():
    """A gap of 0 has no contact modes: that design is derived once for its
    structure, the others share the file's; all agree with the per-design run."""
    found = designs(FIG9)
    gaps = {"gearbox_mesh.backlash": np.radians([0.0, 10.0, 78.6])}
    swept = found.largest("gearbox_mesh.peak", gaps)
    reference = found.per_design("gearbox_mesh.peak", gaps, exact=False)
    assert np.max(np.abs(swept - reference)) <= 1e-9 * np.max(reference)
    assert swept[0] < swept[1] < swept[2]          # a wider gap, a harder impact


def test_the_factor_is_paper_001s_swept_peak_of_its_hand_written_model():
    """The file's gearbox_mesh.factor over the stiffness is 001's sweep output
    peak_elastic_gearbox_torque (|M_G/M_st| of its own batched family, the
    scene hoist_table1's values) to 1e-9."""
    from crane_sym import registry
    from crane_sym.scenes.reading import load_scene
    scene = load_scene("hoist_table1")
    spec = registry.sweep_outputs("hoist_brakes")["peak_elastic_gearbox_torque"]
    stiffness = np.array([1e4, 4e4, 1e5])
    values = {**{n: scene.parameters[n] for n in spec.parameters}, "c": stiffness}
    paper = spec.evaluate(values, {"duration": scene.options["duration"]})
    ours = designs(FIG9).largest("gearbox_mesh.factor", {"gearbox_mesh.stiffness": stiffness})
    assert np.allclose(ours, paper, rtol=1e-9, atol=0)
    assert paper[-1] == pytest.approx(8.5667312106, rel=1e-9)


EXAMPLES = sorted(Path(FIG9).parent.glob("*.toml"))


@pytest.mark.parametrize("path", EXAMPLES, ids=[p.stem for p in EXAMPLES])
def test_every_example_sweeps_its_links_as_the_per_design_run(path):
    """Each link's peak and each ground contact's reaction, the first link's
    stiffness (a pendulum's length) halved and doubled, against the per-design
    run (numeric closed forms) to 1e-9 of the peak."""
    found = designs(path)
    link = found.model.assembly.links[0]
    key, given = (("stiffness", link.stiffness) if f"{link.part.name}.stiffness" in found.fields
                  else ("length", link.part.length))
    axis = {f"{link.part.name}.{key}": np.array([0.5, 2.0]) * given}
    for name, (_, kind, _) in found.outputs().items():
        if kind in ("peak", "reaction"):
            swept = found.largest(name, axis)
            reference = found.per_design(name, axis, exact=False)
            assert np.max(np.abs(swept - reference)) <= 1e-9 * np.max(reference), name


def test_a_rest_start_design_runs_on_the_schedule_of_the_file_run_alone():
    """From rest, a brake that acts at once is engaged by the start: a sweep's
    design is scheduled as the file's own run (``Model.hybrid_run``), with no
    engaging at t = 0 left in its schedule."""
    found = designs(EXAMPLES[[p.stem for p in EXAMPLES].index("bridge_travel")])
    assert found.file.rest
    _, runs, _ = found.runs("drive_line.peak", {})
    alone = found.model.hybrid_run(found.file.duration, rest=True)
    assert runs[0].schedule == alone.schedule
    assert all(name != "rolling engages" for _, name in runs[0].schedule)
