"""Design sweeps: a 200 × 200 design grid against Eq. (14) by hand, a real
LocalCluster against the local scheduler bit for bit, and every bad input
refused by name, exit 2, nothing written."""
from __future__ import annotations

import json
import re
from pathlib import Path

import numpy as np
import pytest

from crane_sym.sweep import grid as sweep
from crane_sym.cli.main import main
from crane_sym.scenes.reading import load_scene
from crane_sym.sweep.grid import run_sweep
from crane_sym.sweep.spec import plan

xr = pytest.importorskip("xarray")
GRID_200x200 = ["sweep", "overhead_crane_50t", "--vary", "m1=1:100:200:log", "--vary",
                "P_t=5:50:200", "--output", "peak_elastic_force", "--limit",
                "peak_elastic_force<=40 kN", "--format", "json", "--quiet"]


def _independent(m1_t, P_t_kN):
    """Eq. (14)'s peak by hand, from the scene's values (m2 = 110 t, W = 11 kN)."""
    m1, P = np.asarray(m1_t)[:, None] * 1e3, np.asarray(P_t_kN)[None, :] * 1e3
    return 2 * (P * 110e3 - 11e3 * m1) / (m1 + 110e3)


def test_a_200_by_200_sweep_writes_dataset_png_and_summary(tmp_path, capsys):
    out = tmp_path / "sweep"
    assert main([*GRID_200x200, "--out", str(out)]) == 0
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
                                  dashboard_address=":0") as cluster:
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
    (["--vary", "v0=1:2:3"], "--vary v0", "v0 is not an argument of peak_elastic_force"),
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
    from crane_sym.scenes.run import run_scene
    from crane_sym.scenes.reading import scene_path
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
    assert main([*GRID_200x200, "--out", str(tmp_path), "--certify"]) == 0
    data = json.loads(capsys.readouterr().out)
    c, grid = data["certified"], data["worst_case"]["value"]
    assert c["converged"] and c["upper"] - c["lower"] <= c["tolerance"]
    assert c["tolerance"] == pytest.approx(1e-6 * c["lower"])
    assert c["lower"] <= grid <= c["upper"] and c["grid_worst_inside"]


def test_certified_maximum_between_grid_points_is_above_the_grid(tmp_path):
    """elastic_force(t = 0.3 s) peaks inside the box: a coarse grid misses the
    peak, the enclosure holds it; a fine grid near it lands inside."""
    from crane_sym.sweep.certify import certify, prepare
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


@pytest.mark.parametrize("index", [0, 1])
def test_bench_integrated_peak_matches_the_closed_form_at_1e_9(index):
    """The bench's per-design alternative reaches the accuracy it is matched
    at, on each case a paper declares (SWEEP_BENCH_CASES)."""
    from crane_sym.bench import sweeps as bench_sweep
    from crane_sym.bench.cases import sweep_cases
    from crane_sym.scenes.reading import load_scene
    paper, case = sweep_cases()[index]
    chosen, f, jac, y0f, quantity, names = bench_sweep._prepared(paper, case)
    base = dict(load_scene(case.scene).parameters) if case.scene else dict(case.fixed)
    axes = [a.si() for a in chosen.axes]
    values, pieces, exact = case.design({**base, chosen.axes[0].name: axes[0][37],
                                         chosen.axes[1].name: axes[1][61]})
    p = tuple(values[n] for n in names)
    y0 = np.array(y0f(*p), dtype=float)
    peak = bench_sweep.integrated_peak(f, jac, y0, p, quantity, pieces, 1e-11)
    assert abs(peak - exact) <= 1e-9 * abs(exact)
    assert abs(bench_sweep.integrated_peak(f, jac, y0, p, quantity, pieces, 1e-4) - exact) \
        > 1e-9 * abs(exact)                       # a loose run is caught


def test_time_window_maximum_approaches_the_closed_form_peak_and_is_certified():
    """max over t of eq. (14) is peak_elastic_force: the sampled window stays
    below it and close; the certified box with time as a side encloses it."""
    from crane_sym.sweep.certify import certify, prepare
    chosen = plan(load_scene("overhead_crane_50t"), ["m1=1:100:20:log", "P_t=5:50:20"],
                  ["elastic_force", "peak_elastic_force"], ["t=0:1.5:1501"])
    assert chosen.window.name == "t" and chosen.window.n == 1501
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
    from crane_sym.scenes.run import run_scene
    scene = load_scene("hoist_table1")
    chosen = plan(scene, ["c=2e4:4e4:2", "delta=1:3:2"], ["peak_elastic_gearbox_torque"])
    assert chosen.output("peak_elastic_gearbox_torque").kind == "simulated"
    result = run_sweep(chosen, tmp_path / "sweep", scheduler="threads")
    values = xr.open_zarr(result.dataset)["peak_elastic_gearbox_torque"].values
    report, _ = run_scene(scene, tmp_path / "run")
    assert values[1, 1] == pytest.approx(abs(report.values["peak_fig9_payload"]), rel=1e-9)
    assert values[1, 1] > values[1, 0] and values[1, 1] > values[0, 1]


# --- sweeps say what they did ----------------------------------------------------------
USER_LAW = ["sweep", "hoist_user_drive_law", "--vary", "m2=5:20:4", "--at", "t=0:2:21",
            "--at", "Omega=25", "--at", "v0=0.5", "--at", "t_n=1", "--quiet"]


def test_an_axis_the_output_does_not_depend_on_is_refused_naming_both(tmp_path, capsys):
    """dynamic_coefficient_from_weight_a1 is written with Ω: its function takes m2
    and ignores it, so sweeping m2 alone gave equal values and no word."""
    out = tmp_path / "out"
    argv = [*USER_LAW, "--output", "dynamic_coefficient_from_weight_a1", "--out", str(out)]
    assert main(argv) == 2
    err = capsys.readouterr().err
    assert "--vary m2" in err and "m2 is not an argument of dynamic_coefficient_from_weight_a1" \
        in err and "depends on t, Omega, g, v0, t_n" in err
    assert main([*argv, "--output", "dynamic_coefficient_from_weight_a2"]) == 2
    assert "m2 is not an argument of any output (dynamic_coefficient_from_weight_a1, " \
           "dynamic_coefficient_from_weight_a2)" in capsys.readouterr().err
    assert not out.exists()


def test_an_axis_only_some_outputs_depend_on_is_said_in_the_summary(tmp_path, capsys):
    argv = [*USER_LAW, "--output", "dynamic_coefficient_from_weight_a1", "--output",
            "natural_frequency", "--out", str(tmp_path), "--format", "json"]
    assert main(argv) == 0
    data = json.loads(capsys.readouterr().out)
    assert data["outputs"]["dynamic_coefficient_from_weight_a1"]["independent_of"] == ["m2"]
    assert "independent_of" not in data["outputs"]["natural_frequency"]
    ds = xr.open_zarr(data["dataset"])
    assert ds["dynamic_coefficient_from_weight_a1"].attrs["independent_of"] == "m2"
    values = ds["dynamic_coefficient_from_weight_a1"].values
    assert np.all(values == values[0])                 # constant along m2, as it says
    assert main([*argv[:-2], "--format", "table"]) == 0
    assert "(dynamic_coefficient_from_weight_a1 does not depend on m2: constant along that " \
           "axis)" in capsys.readouterr().out


def _sweep(tmp_path, *argv):
    """JSON and text summaries of one sweep, the plan and result behind them."""
    from crane_sym.sweep import report as sweep_report
    chosen = plan(load_scene(argv[0]), *argv[1:])
    result = run_sweep(chosen, tmp_path, scheduler="synchronous")
    data = sweep_report.summary(result)
    return chosen, result, data, "\n".join(sweep_report.text_lines(data))


def test_one_unit_per_quantity_in_text_json_dataset_and_png(tmp_path):
    """Forces in the scene's kN everywhere (no limit: it was 98900.9 N beside a
    certified 98.9009 kN), a limit given in N shown in kN; axes in t and kN."""
    chosen, result, data, text = _sweep(
        tmp_path, "overhead_crane_50t", ["m1=1:100:20:log", "P_t=5:50:20"],
        ["peak_elastic_force", "elastic_force"], ["t=0:1.5:151"], "peak_elastic_force<=40000 N")
    assert {o: e["worst"]["unit"] for o, e in data["outputs"].items()} == {
        "peak_elastic_force": "kN", "elastic_force": "kN"}
    assert data["outputs"]["elastic_force"]["unit"] == "kN"
    assert data["worst_case"]["value"] == pytest.approx(98.9009, rel=1e-5)
    assert data["limit"]["text"] == "peak_elastic_force <= 40 kN"
    assert "max 98.9009 kN at m1 = 1 t, P_t = 50 kN" in text
    assert "within peak_elastic_force <= 40 kN" in text
    assert not re.search(r"\d N\b", text)           # no force left in N
    ds = xr.open_zarr(result.dataset)
    for name in ("peak_elastic_force", "elastic_force"):
        assert ds[name].attrs["units"] == "N"       # the dataset stays SI ...
        assert ds[name].attrs["display_units"] == "kN"  # ... and names the shown unit
        assert ds[name].attrs["display_to_SI"] == 1e3
    assert {a: ds[a].attrs["units"] for a in ("m1", "P_t")} == \
        {a: e["unit"] for a, e in data["axes"].items()} == {"m1": "t", "P_t": "kN"}
    from crane_sym.sweep.report import figure, labels
    assert labels(chosen) == {"m1": "$m_{1}$ [t]", "P_t": "$P_{t}$ [kN]",
                              "peak_elastic_force": r"$F_{\max}$ [kN]",
                              "elastic_force": "elastic force [kN]", "t": "$t$ [s]"}
    fig = figure(result)
    ax, bar = fig.axes
    assert (ax.get_xlabel(), ax.get_ylabel()) == ("$m_{1}$ [t]", "$P_{t}$ [kN]")
    said = {o.name: o.summary for o in chosen.outputs}
    assert said["peak_elastic_force"]                    # the colour bar says what it shows
    assert bar.get_ylabel().replace("\n", " ") == \
        r"$F_{\max}$ [kN]: " + said["peak_elastic_force"]
    assert [t.get_text() for t in fig.legends[0].get_texts()] == [
        r"limit: $F_{\max}$ ≤ 40 kN", "worst: 98.901 kN"]


def test_a_dimensionless_output_prints_no_bare_1(tmp_path):
    chosen, result, data, text = _sweep(
        tmp_path, "hoist_drive_laws", ["v0=0.1:1:5", "t_n=0.5:2:4"],
        ["dynamic_coefficient_from_weight_a1"], ["t=0:3:61"])
    entry = data["outputs"]["dynamic_coefficient_from_weight_a1"]
    assert entry["worst"]["unit"] == ""
    assert entry["unit"] == ""
    assert re.search(r"max [\d.]+ at v0 = ", text) and not re.search(r"\d 1\b", text)
    attrs = xr.open_zarr(result.dataset)["dynamic_coefficient_from_weight_a1"].attrs
    assert attrs["units"] == attrs["display_units"] == ""
    from crane_sym.sweep.report import figure, labels
    label = labels(chosen)
    assert label["v0"] == "$v_{0}$ [m/s]" and label["t_n"] == r"$t_\mathrm{п}$ [s]"
    assert label["dynamic_coefficient_from_weight_a1"] == "dynamic coefficient from weight a1"
    assert not any("[1]" in v for v in label.values())
    worst = [t.get_text() for t in figure(result).legends[0].get_texts()][-1]
    assert re.fullmatch(r"worst: [\d.]+", worst)


def test_a_time_window_says_max_over_t_and_records_the_window(tmp_path):
    """--at t=START:STOP:N: "max over t in [a, b]" in the text, JSON and PNG;
    the window in the dataset's attributes; fixed_SI without a fake t = 0.0."""
    chosen, result, data, text = _sweep(
        tmp_path, "overhead_crane_50t", ["m1=1:100:20:log", "P_t=5:50:20"],
        ["elastic_force", "peak_elastic_force"], ["t=0:1500:151 ms"])
    assert "  elastic_force, max over t in [0, 1500] ms: max " in text
    assert "  peak_elastic_force: max " in text     # takes no t: no window
    assert data["outputs"]["elastic_force"]["over"] == "max over t in [0, 1500] ms"
    assert "over" not in data["outputs"]["peak_elastic_force"]
    assert data["window"] == {"name": "t", "start": 0.0, "stop": 1500.0, "points": 151,
                              "unit": "ms", "to_SI": 1e-3, "reduction": "max",
                              "text": "max over t in [0, 1500] ms"}
    ds = xr.open_zarr(result.dataset)
    assert {k: ds.attrs[k] for k in ("window_variable", "window_start", "window_stop",
                                     "window_points", "window_units")} == {
        "window_variable": "t", "window_start": 0.0, "window_stop": 1500.0,
        "window_points": 151, "window_units": "ms"}
    assert "t=" not in ds.attrs["fixed_SI"] and "m2=110000.0" in ds.attrs["fixed_SI"]
    assert ds["elastic_force"].attrs["cell_methods"] == "t: maximum"
    assert "cell_methods" not in ds["peak_elastic_force"].attrs
    from crane_sym.sweep.report import figure
    fig = figure(result)
    summary = next(o.summary for o in chosen.outputs if o.name == "elastic_force")
    assert fig.axes[1].get_ylabel().replace("\n", " ") == \
        f"elastic force [kN], max over $t$ in [0, 1500] ms: {summary}"
    assert "max over t in [0, 1500] ms" in fig.get_suptitle()
