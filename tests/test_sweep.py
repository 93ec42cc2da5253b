"""Design sweeps (issue 16): the Done-when command, a real LocalCluster against
the local scheduler bit for bit, and every bad input refused by name, exit 2,
nothing written."""
from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest

from crane_sym import sweep
from crane_sym.cli import main
from crane_sym.scenes import load_scene
from crane_sym.sweep import run_sweep
from crane_sym.sweep_spec import plan

xr = pytest.importorskip("xarray")
DONE_WHEN = ["sweep", "overhead_crane_50t", "--vary", "m1=1:100:200:log", "--vary",
             "P_t=5:50:200", "--output", "peak_elastic_force", "--limit",
             "peak_elastic_force<=40 kN", "--format", "json", "--quiet"]


def _independent(m1_t, P_t_kN):
    """Eq. (14)'s peak by hand, from the scene's values (m2 = 110 t, W = 11 kN)."""
    m1, P = np.asarray(m1_t)[:, None] * 1e3, np.asarray(P_t_kN)[None, :] * 1e3
    return 2 * (P * 110e3 - 11e3 * m1) / (m1 + 110e3)


def test_done_when_command_writes_dataset_png_and_summary(tmp_path, capsys):
    out = tmp_path / "sweep"
    assert main([*DONE_WHEN, "--out", str(out)]) == 0
    data = json.loads(capsys.readouterr().out)
    m1, P = np.geomspace(1, 100, 200), np.linspace(5, 50, 200)
    expected = _independent(m1, P)
    assert data["points"] == 40000 and data["chunks"] >= 1 and data["seconds"] > 0
    worst = data["worst_case"]
    assert worst["unit"] == "kN" and worst["kind"] == "max"
    assert worst["value"] == pytest.approx(expected.max() / 1e3, rel=1e-13)
    i, j = np.unravel_index(np.argmax(expected), expected.shape)
    assert worst["design"] == {"m1": {"value": pytest.approx(m1[i]), "unit": "t"},
                               "P_t": {"value": pytest.approx(P[j]), "unit": "kN"}}
    assert data["limit"]["within"] == np.count_nonzero(expected <= 40e3)
    assert data["limit"]["fraction_within"] == pytest.approx(
        np.count_nonzero(expected <= 40e3) / 40000)
    ds = xr.open_zarr(data["dataset"])
    assert ds["peak_elastic_force"].dims == ("m1", "P_t")
    assert ds["m1"].attrs["units"] == "t" and ds["P_t"].attrs["units"] == "kN"
    assert ds["peak_elastic_force"].attrs["units"] == "N"
    np.testing.assert_allclose(ds["peak_elastic_force"].values, expected, rtol=1e-13)
    png = Path(data["plot"])
    assert png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    assert sorted(p.name for p in out.iterdir()) == ["overhead_crane_50t_sweep.png",
                                                     "overhead_crane_50t_sweep.zarr"]


def _three_axes():
    return plan(load_scene("overhead_crane_50t"),
                ["m1=1:100:60:log", "P_t=5:50:40", "c=1e6:1e7:3 N/m"],
                ["peak_elastic_force", "elastic_force"], ["t=120 ms"],
                "peak_elastic_force<=40 kN")


def test_local_cluster_is_bit_for_bit_the_local_scheduler(tmp_path):
    distributed = pytest.importorskip("distributed")
    chosen = _three_axes()
    local = run_sweep(chosen, tmp_path / "local", chunk_bytes=4096)
    assert local.blocks > 4                        # several blocks, not one
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                  dashboard_address=None) as cluster:
        remote = run_sweep(chosen, tmp_path / "cluster", scheduler=cluster.scheduler_address,
                           chunk_bytes=4096)
    assert remote.worst == local.worst and remote.within == local.within
    a, b = (xr.open_zarr(r.dataset).load() for r in (local, remote))
    for name in ("peak_elastic_force", "elastic_force"):
        assert np.array_equal(a[name].values.view(np.uint64), b[name].values.view(np.uint64))


def test_a_time_response_at_a_given_time_matches_the_generated_function(tmp_path):
    from crane_sym.generated.travel_braking import elastic_force
    chosen = _three_axes()
    result = run_sweep(chosen, None, chunk_bytes=4096, scheduler="synchronous")
    ax = {a.name: a.si() for a in chosen.axes}
    f = elastic_force(0.12, ax["m1"][:, None, None], 110e3, ax["c"][None, None, :],
                      ax["P_t"][None, :, None], 11e3)
    value, index = result.worst["elastic_force"]
    assert value == f.max() and index == np.unravel_index(np.argmax(f), f.shape)


def test_a_failing_block_leaves_nothing_that_looks_complete(tmp_path, monkeypatch):
    real = sweep.evaluate_block

    def broken(*args):
        if args[-3][0] > 50e3:                      # the blocks of the heavier m1
            raise RuntimeError("worker lost")
        return real(*args)

    monkeypatch.setattr(sweep, "evaluate_block", broken)
    with pytest.raises(RuntimeError, match="worker lost"):
        run_sweep(_three_axes(), tmp_path, chunk_bytes=4096, scheduler="threads")
    assert list(tmp_path.iterdir()) == []


BAD = [
    (["--vary", "m9=1:100:20"], "--vary 'm9=1:100:20'", "not a parameter of the scene"),
    (["--vary", "m1=1..100"], "--vary 'm1=1..100'", "expected NAME=START:STOP:N"),
    (["--vary", "m1=5:5:10"], "--vary 'm1=5:5:10'", "empty"),
    (["--vary", "m1=1:5:1"], "--vary 'm1=1:5:1'", "empty"),
    (["--vary", "m1=50:5:10"], "--vary 'm1=50:5:10'", "reversed"),
    (["--vary", "P_t=-5:50:10:log"], "--vary 'P_t=-5:50:10:log'", "log axis"),
    (["--vary", "m1=1:100:10 kN"], "--vary 'm1=1:100:10 kN'", "does not fit"),
    (["--vary", "m1=1:100:10 furlong"], "--vary 'm1=1:100:10 furlong'", "unknown unit"),
    (["--vary", "m1=-1:100:10"], "--vary 'm1=-1:100:10'", "must be > 0"),
    (["--vary", "m1=1:100:10", "--vary", "m1=1:2:3"], "--vary", "varied twice"),
    (["--vary", "v0=1:2:3"], "--vary v0", "none of the outputs"),
    (["--vary", "m1=1:100:10", "--limit", "peak_elastic_force<=40 kg"], "--limit",
     "does not fit"),
    (["--vary", "m1=1:100:10", "--limit", "peak_elastic_force<40"], "--limit",
     "expected NAME<=VALUE UNIT"),
    (["--vary", "m1=1:100:1000000", "--vary", "P_t=5:50:10000000"], "--out", "GiB"),
    (["--vary", "m1=1:100:10", "--scheduler", "tcp://127.0.0.1:9"], "--scheduler",
     "no Dask scheduler answers"),
    (["--vary", "m1=1:100:10", "--scheduler", "http://x;rm"], "--scheduler",
     "expected an address"),
]


@pytest.mark.parametrize("extra, names, why", BAD, ids=[b[2] + str(i) for i, b in enumerate(BAD)])
def test_bad_input_is_refused_by_name_with_nothing_written(tmp_path, capsys, extra, names, why):
    out = tmp_path / "out"
    argv = ["sweep", "overhead_crane_50t", "--output", "peak_elastic_force", "--out", str(out),
            "--quiet", *extra]
    assert main(argv) == 2
    err = capsys.readouterr().err
    assert names in err and why in err
    assert not out.exists()


def test_unknown_output_and_missing_time_are_named(tmp_path, capsys):
    base = ["sweep", "overhead_crane_50t", "--vary", "m1=1:100:10", "--out", str(tmp_path / "o")]
    assert main([*base, "--output", "peak_force"]) == 2
    assert "--output 'peak_force'" in capsys.readouterr().err
    assert main([*base, "--output", "elastic_force"]) == 2
    assert "--at NAME=VALUE" in capsys.readouterr().err
    assert not (tmp_path / "o").exists()


def test_drum_drive_response_without_closed_form_is_swept_per_design(tmp_path):
    """Paper 004: max |y| of the Fig. 3 start, one integration per design; at
    the scene's own design it is what `crane-sym run` reports (rtol 1e-10)."""
    from crane_sym.scene_run import run_scene
    from crane_sym.scenes import scene_path
    text = scene_path("drum_drive_example").read_text(encoding="utf-8")
    short = tmp_path / "drum_short.toml"
    short.write_text(text.replace('name = "drum_drive_example"', 'name = "drum_short"')
                     .replace('duration = "10 s"', 'duration = "1.5 s"')
                     .replace("points = 2001", "points = 301"), encoding="utf-8")
    scene = load_scene(short)
    chosen = plan(scene, ["C_y=2e7:4e7:2 N/m", "m_L=2500:3000:2"],
                  ["max_drum_shaft_deflection"])
    assert chosen.output("max_drum_shaft_deflection").kind == "simulated"
    result = run_sweep(chosen, tmp_path / "sweep", scheduler="threads")
    values = xr.open_zarr(result.dataset)["max_drum_shaft_deflection"].values
    report, _ = run_scene(scene, tmp_path / "run")
    assert values[0, 0] == pytest.approx(report.values["y_max"], rel=1e-6)
    assert values[1, 0] < values[0, 0]            # a stiffer shaft deflects less
    assert result.worst["max_drum_shaft_deflection"][0] == values.max()


def test_certified_enclosure_holds_the_grid_maximum(tmp_path, capsys):
    assert main([*DONE_WHEN, "--out", str(tmp_path), "--certify"]) == 0
    data = json.loads(capsys.readouterr().out)
    c, grid = data["certified"], data["worst_case"]["value"]
    assert c["converged"] and c["upper"] - c["lower"] <= c["tolerance"]
    assert c["tolerance"] == pytest.approx(1e-6 * c["lower"])
    assert c["lower"] <= grid <= c["upper"] and c["grid_worst_inside"]


def test_certified_maximum_between_grid_points_is_above_the_grid(tmp_path):
    """elastic_force(t = 0.3 s) peaks inside the box: a coarse grid misses the
    peak, the enclosure holds it; a fine grid near it lands inside."""
    from crane_sym.sweep_certify import certify, prepare
    scene = load_scene("overhead_crane_50t")
    coarse = plan(scene, ["m1=1:100:12:log", "c=1e6:1e7:12"], ["elastic_force"], ["t=0.3"])
    task = prepare(coarse, 1e-5)
    found = certify(task)
    assert found.converged and found.upper - found.lower <= found.tolerance
    grid = run_sweep(coarse, None, scheduler="synchronous").worst["elastic_force"][0]
    assert grid <= found.upper
    fine = plan(scene, ["m1=1:100:3000:log", "c=1e6:1e7:3000"], ["elastic_force"], ["t=0.3"])
    best = run_sweep(fine, None).worst["elastic_force"][0]
    assert found.lower - 1e-4 * abs(found.lower) <= best <= found.upper


def test_certify_refuses_an_output_without_an_enclosure(tmp_path, capsys):
    argv = ["sweep", "drum_drive_example", "--vary", "C_y=1e7:2e7:2 N/m", "--output",
            "max_drum_shaft_deflection", "--certify", "--out", str(tmp_path / "o")]
    assert main(argv) == 2
    assert "--certify: max_drum_shaft_deflection is a simulated response" \
        in capsys.readouterr().err
    assert not (tmp_path / "o").exists()


def test_bench_integrated_peak_matches_the_closed_form_at_1e_9():
    """The bench's per-design alternative reaches the accuracy it is matched at."""
    from crane_sym import bench_sweep
    chosen, f, jac, y0f, quantity, design = bench_sweep._case_000()
    p, pieces, exact = design(2.0e3, 40e3)
    y0 = np.array(y0f(*p), dtype=float)
    peak = bench_sweep.integrated_peak(f, jac, y0, p, quantity, pieces, 1e-11)
    assert abs(peak - exact) <= 1e-9 * abs(exact)
    assert abs(bench_sweep.integrated_peak(f, jac, y0, p, quantity, pieces, 1e-4) - exact) \
        > 1e-9 * abs(exact)                       # a loose run is caught


def test_time_window_maximum_approaches_the_closed_form_peak_and_is_certified():
    """max over t of eq. (14) is peak_elastic_force: the sampled window stays
    below it and close; the certified box with time as a side encloses it."""
    from crane_sym.sweep_certify import certify, prepare
    chosen = plan(load_scene("overhead_crane_50t"), ["m1=1:100:20:log", "P_t=5:50:20"],
                  ["elastic_force", "peak_elastic_force"], ["t=0:1.5:1501"])
    assert chosen.window[0] == "t" and len(chosen.window[1]) == 1501
    result = run_sweep(chosen, None, scheduler="synchronous")
    sampled, peak = result.worst["elastic_force"][0], result.worst["peak_elastic_force"][0]
    assert peak * (1 - 1e-4) < sampled <= peak * (1 + 1e-15)
    found = certify(prepare(chosen, 1e-4))
    assert found.converged and found.lower <= peak <= found.upper


def test_window_arguments_are_checked(tmp_path, capsys):
    base = ["sweep", "overhead_crane_50t", "--vary", "m1=1:100:10", "--output", "elastic_force",
            "--out", str(tmp_path / "o")]
    assert main([*base, "--at", "t=1:0:10"]) == 2
    assert "--at 't=1:0:10'" in capsys.readouterr().err
    assert main([*base, "--at", "t=0:1:10 kg"]) == 2
    assert "does not fit" in capsys.readouterr().err
    assert not (tmp_path / "o").exists()


def test_001_piecewise_peak_is_sweepable(tmp_path):
    """Paper 001's Fig. 9 peak (a piecewise-linear run per design, numeric
    closed forms) over stiffness and backlash: at Table 1's design it is the
    peak the scene reports (exact Jordan forms), and more backlash hits harder."""
    from crane_sym.scene_run import run_scene
    scene = load_scene("hoist_table1")
    chosen = plan(scene, ["c=2e4:4e4:2", "delta=1:3:2"], ["peak_elastic_gearbox_torque"])
    assert chosen.output("peak_elastic_gearbox_torque").kind == "simulated"
    result = run_sweep(chosen, tmp_path / "sweep", scheduler="threads")
    values = xr.open_zarr(result.dataset)["peak_elastic_gearbox_torque"].values
    report, _ = run_scene(scene, tmp_path / "run")
    assert values[1, 1] == pytest.approx(abs(report.values["peak_fig9_payload"]), rel=1e-9)
    assert values[1, 1] > values[1, 0] and values[1, 1] > values[0, 1]
