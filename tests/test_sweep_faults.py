"""Design sweeps under faults: signals to a real `crane-sym sweep`,
two sweeps into one folder, a lost Dask scheduler, a killed worker, and every
bad option — each ends in one line (or a whole result) with nothing left
behind that `xr.open_zarr` opens and no temporaries."""
from __future__ import annotations

import json
import os
import re
import signal
import subprocess
import sys
import threading
import time
import warnings
from pathlib import Path

import numpy as np
import pytest

from crane_sym.sweep import store as sweep_store
from crane_sym.cli.main import Terminated, main
from crane_sym.output_files import Stage
from crane_sym.scenes.reading import load_scene
from crane_sym.sweep.grid import check_grid, run_sweep
from crane_sym.sweep.spec import plan

xr = pytest.importorskip("xarray")
SCENE = "overhead_crane_50t"
#: A grid that takes a few seconds: 4·10⁶ designs, 11 times each.
SLOW = ["--vary", "m1=1:100:2000:log", "--vary", "P_t=5:50:2000", "--output", "elastic_force",
        "--at", "t=0:1.5:11", "--chunk-mib", "1"]

#: The harm these cases guard against (tests/fault_counts.py counts them).
pytestmark = pytest.mark.harm("one-line")


def _opens(folder: Path) -> list[Path]:
    """Every folder at or below ``folder`` (hidden ones too) that
    ``xr.open_zarr`` opens."""
    found = []
    for root, _, _ in os.walk(folder):
        try:
            with warnings.catch_warnings():
                warnings.simplefilter("ignore")
                xr.open_zarr(root)
        except Exception:
            continue
        found.append(Path(root))
    return found


def _start(out: Path, *argv: str) -> subprocess.Popen:
    return subprocess.Popen([sys.executable, "-m", "crane_sym", "sweep", SCENE, *argv, "--out",
                             str(out), "--quiet", "--format", "json"],
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)


def _when_partial(out: Path, proc: subprocess.Popen, timeout: float = 30.0) -> None:
    """Wait until the sweep's temporary dataset is being written."""
    deadline = time.monotonic() + timeout
    while not (out.is_dir() and any(p.name.endswith(".partial") for p in out.iterdir())):
        assert proc.poll() is None, proc.communicate()
        assert time.monotonic() < deadline, "the sweep wrote no temporary"
        time.sleep(0.02)


def _pair(out: Path) -> tuple[str, str]:
    """(the dataset's sweep_id, the PNG's sweep_id) in ``out``."""
    from PIL import Image
    ds = xr.open_zarr(out / f"{SCENE}_sweep.zarr")
    with Image.open(out / f"{SCENE}_sweep.png") as png:
        return ds.attrs["sweep_id"], png.info["sweep_id"]


@pytest.mark.parametrize("sig, code, word", [(signal.SIGTERM, 143, "terminated"),
                                             (signal.SIGINT, 130, "interrupted")])
def test_a_signal_mid_sweep_leaves_the_old_pair_and_nothing_else(tmp_path, sig, code, word):
    out = tmp_path / "out"
    assert main(["sweep", SCENE, "--vary", "m1=1:100:5", "--output", "peak_elastic_force",
                 "--out", str(out), "--quiet"]) == 0
    before = _pair(out)
    assert before[0] == before[1]
    proc = _start(out, *SLOW)
    _when_partial(out, proc)
    time.sleep(0.3)
    proc.send_signal(sig)
    _, err = proc.communicate(timeout=60)
    assert proc.returncode == code
    assert err.splitlines() == [f"crane-sym: {word} ({signal.Signals(sig).name}); "
                                "nothing half-written is left"]
    time.sleep(1.0)                                  # nothing written late either
    assert sorted(p.name for p in out.iterdir()) == [f"{SCENE}_sweep.png", f"{SCENE}_sweep.zarr"]
    assert _pair(out) == before
    assert _opens(out) == [out / f"{SCENE}_sweep.zarr"]


def test_sigterm_into_a_new_folder_leaves_no_folder(tmp_path):
    out = tmp_path / "new"
    proc = _start(out, *SLOW)
    _when_partial(out, proc)
    proc.send_signal(signal.SIGTERM)
    _, err = proc.communicate(timeout=60)
    assert proc.returncode == 143 and len(err.splitlines()) == 1
    time.sleep(1.0)
    assert not out.exists()


def test_two_sweeps_into_one_folder_leave_a_pair_that_belongs_together(tmp_path):
    out = tmp_path / "shared"
    grids = [["m1=1:100:300:log", "P_t=5:50:300"], ["m1=2:50:200", "P_t=10:40:250"]]
    procs = [_start(out, "--vary", a, "--vary", b, "--output", "peak_elastic_force")
             for a, b in grids]
    ids = {}
    for proc, grid in zip(procs, grids):
        stdout, err = proc.communicate(timeout=120)
        assert proc.returncode in (0, 2), err
        if proc.returncode == 0:
            data = json.loads(stdout)
            ids[data["sweep_id"]] = data
        else:                                        # a failure is one line
            assert len(err.splitlines()) == 1 and err.startswith("crane-sym: error: --out")
    assert ids, "no sweep finished"
    assert sorted(p.name for p in out.iterdir()) == [f"{SCENE}_sweep.png", f"{SCENE}_sweep.zarr"]
    dataset_id, png_id = _pair(out)
    assert dataset_id == png_id and dataset_id in ids
    data = ids[dataset_id]
    ds = xr.open_zarr(out / f"{SCENE}_sweep.zarr")
    assert {k: v for k, v in ds.sizes.items()} == {k: v["n"] for k, v in data["axes"].items()}
    assert float(ds["peak_elastic_force"].max()) / 1e3 == pytest.approx(
        data["worst_case"]["value"], rel=1e-12)


def test_a_signal_during_the_renames_waits_for_both(tmp_path, monkeypatch):
    """SIGTERM right after the dataset's rename: the PNG is renamed too, then
    the signal is delivered — also with another thread alive, where masking
    the main thread alone would not hold it off."""
    (tmp_path / "a.zarr").mkdir()
    (tmp_path / "a.png").write_text("old")
    previous = signal.signal(signal.SIGTERM, lambda *_: (_ for _ in ()).throw(Terminated()))
    stop = threading.Event()
    threading.Thread(target=stop.wait, daemon=True).start()
    real = os.replace

    def replace_then_signal(src, dst):
        real(src, dst)
        if str(dst).endswith("a.zarr"):
            os.kill(os.getpid(), signal.SIGTERM)
            time.sleep(0.2)                       # let the handler have its chance
    monkeypatch.setattr(os, "replace", replace_then_signal)
    try:
        with pytest.raises(Terminated):
            with sweep_store.sweep_stage(tmp_path) as stage:
                stage.path("a.zarr").mkdir()
                stage.text("a.png", "new")
    finally:
        stop.set()
        signal.signal(signal.SIGTERM, previous)
    assert (tmp_path / "a.png").read_text() == "new"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["a.png", "a.zarr"]


def _cluster():
    distributed = pytest.importorskip("distributed")
    return distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                    dashboard_address=":0")


LOST = ("the connection to the Dask scheduler was lost during the sweep; nothing was written")
#: A grid a two-worker cluster takes a few seconds over, in many blocks.
REMOTE = ["--vary", "m1=1:100:1000:log", "--vary", "P_t=5:50:1000", "--output", "elastic_force",
          "--at", "t=0:1.5:11", "--chunk-mib", "0.5"]


def test_a_closed_local_cluster_is_one_line_and_leaves_nothing(tmp_path):
    out = tmp_path / "out"
    with _cluster() as cluster:
        proc = _start(out, *REMOTE, "--scheduler", cluster.scheduler_address)
        _when_partial(out, proc)
        time.sleep(0.5)
        cluster.close()
        _, err = proc.communicate(timeout=60)
    assert proc.returncode == 2
    assert err.splitlines() == [f"crane-sym: error: --scheduler {cluster.scheduler_address!r}: "
                                + LOST]
    time.sleep(1.0)
    assert not out.exists()


def test_sigterm_on_a_live_cluster_stops_its_tasks_before_cleaning_up(tmp_path):
    """The sweep's tasks are cancelled and the workers asked until none runs
    one, so no block is written after the partial dataset is removed."""
    out = tmp_path / "out"
    with _cluster() as cluster:
        proc = _start(out, *REMOTE, "--scheduler", cluster.scheduler_address)
        _when_partial(out, proc)
        time.sleep(0.5)
        proc.send_signal(signal.SIGTERM)
        _, err = proc.communicate(timeout=60)
        time.sleep(1.0)                          # the workers still up: nothing comes
        assert proc.returncode == 143 and len(err.splitlines()) == 1
        assert not out.exists()


def test_a_killed_scheduler_whose_workers_run_on_is_one_line_and_leaves_nothing(tmp_path):
    """A scheduler process killed (SIGKILL) mid-run, its two worker processes
    left running what they hold: nothing of the sweep is left, even after the
    workers finish their blocks."""
    pytest.importorskip("distributed")
    out, info = tmp_path / "out", tmp_path / "scheduler.json"
    quiet = dict(stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    scheduler = subprocess.Popen([sys.executable, "-m", "distributed.cli.dask_scheduler",
                                  "--host", "127.0.0.1", "--port", "0", "--no-dashboard",
                                  "--scheduler-file", str(info)], **quiet)
    workers = subprocess.Popen([sys.executable, "-m", "distributed.cli.dask_worker",
                                "--scheduler-file", str(info), "--nworkers", "2", "--nthreads",
                                "1", "--no-dashboard"], **quiet)
    try:
        while not info.exists() or not info.read_text():
            assert scheduler.poll() is None
            time.sleep(0.05)
        time.sleep(0.2)
        address = json.loads(info.read_text())["address"]
        proc = _start(out, *REMOTE, "--scheduler", address)
        _when_partial(out, proc)
        time.sleep(0.5)
        scheduler.kill()
        _, err = proc.communicate(timeout=60)
        time.sleep(1.5)                          # the orphaned workers' late blocks
    finally:
        for p in (scheduler, workers):
            p.terminate()
        for p in (scheduler, workers):
            try:
                p.wait(timeout=10)
            except subprocess.TimeoutExpired:
                p.kill()
    assert proc.returncode == 2
    assert err.splitlines() == [f"crane-sym: error: --scheduler {address!r}: " + LOST]
    assert not out.exists()


def test_a_killed_worker_is_survived_bit_for_bit(tmp_path):
    chosen = plan(load_scene(SCENE), ["m1=1:100:600:log", "P_t=5:50:600"],
                  ["elastic_force"], ["t=0:1.5:11"])
    local = run_sweep(chosen, tmp_path / "local", chunk_bytes=2**18)
    with _cluster() as cluster, __import__("distributed").Client(cluster) as client:
        pids = list(client.run(os.getpid).values())
        remote_out = tmp_path / "cluster"

        def kill_one():
            while not (remote_out.is_dir() and any(remote_out.iterdir())):
                time.sleep(0.01)
            time.sleep(0.3)
            os.kill(pids[0], signal.SIGKILL)
        killer = threading.Thread(target=kill_one)
        killer.start()
        remote = run_sweep(chosen, remote_out, scheduler=cluster.scheduler_address,
                           chunk_bytes=2**18)
        killer.join()
        assert pids[0] not in client.run(os.getpid).values()   # it did die
    assert remote.worst == local.worst
    a, b = (xr.open_zarr(r.dataset).load() for r in (local, remote))
    assert np.array_equal(a["elastic_force"].values.view(np.uint64),
                          b["elastic_force"].values.view(np.uint64))


def test_what_a_late_worker_writes_never_opens_as_a_dataset(tmp_path, monkeypatch):
    """A worker of a lost scheduler may write its block after the cleanup: into
    the hidden ``.partial`` temporary, chunk files only (the metadata is this
    process's to write), which xr.open_zarr refuses."""
    from crane_sym.sweep import grid as sweep
    made = []
    real_path = Stage.path

    def path(self, name, suffix=""):
        made.append(real_path(self, name, suffix))
        return made[-1]
    monkeypatch.setattr(Stage, "path", path)
    real = sweep.evaluate_block

    def broken(*args):
        if args[-2][0] > 40e3:
            raise RuntimeError("block failed")
        return real(*args)
    monkeypatch.setattr(sweep, "evaluate_block", broken)
    with pytest.raises(RuntimeError, match="block failed"):
        run_sweep(plan(load_scene(SCENE), ["m1=1:100:50:log", "P_t=5:50:50"],
                       ["peak_elastic_force"]), tmp_path, chunk_bytes=4096)
    assert list(tmp_path.iterdir()) == []
    tmp, = made
    assert tmp.name.startswith(".") and tmp.name.endswith(".partial")
    late = tmp / "peak_elastic_force" / "0.0"       # what a late worker would write
    late.parent.mkdir(parents=True)
    late.write_bytes(np.zeros(16).tobytes())
    assert _opens(tmp_path) == []


BAD = [
    (["--limit", "peak_elastic_force<=1e999 kN"], "--limit", "finite"),
    (["--limit", "peak_elastic_force<=1e308 GN"], "--limit", "finite"),
    (["--chunk-mib", "1e-9"], "--chunk-mib 1e-09", "at least 0.1 MiB"),
    (["--chunk-mib", "nan"], "--chunk-mib nan", "at least 0.1 MiB"),
    (["--chunk-mib", "1e9"], "--chunk-mib 1e+09", "free memory"),
    (["--at", "t=1e999"], "--at", "finite"),
    (["--vary", "P_t=5:1e300:3 GN"], "--vary", "finite in SI"),
    (["--time-limit", "0"], "--time-limit 0", "must be > 0 s"),
    (["--time-limit", "nan"], "--time-limit nan", "must be > 0 s"),
]


@pytest.mark.parametrize("extra, names, why", BAD, ids=[b[1] + " " + b[2] for b in BAD])
def test_a_bad_option_is_one_line_naming_it(tmp_path, capsys, extra, names, why):
    out = tmp_path / "out"
    argv = ["sweep", SCENE, "--output", "peak_elastic_force", "--out", str(out), "--quiet",
            *extra]
    if "--vary" not in extra:
        argv += ["--vary", "m1=1:100:10"]
    assert main(argv) == 2
    err = capsys.readouterr().err
    assert len(err.splitlines()) == 1 and err.startswith(f"crane-sym: error: {names}")
    assert why in err
    assert not out.exists()


def test_out_an_existing_file_or_a_folder_not_writable(tmp_path, capsys, monkeypatch):
    base = ["sweep", SCENE, "--vary", "m1=1:100:10", "--output", "peak_elastic_force", "--quiet"]
    afile = tmp_path / "file"
    afile.write_text("keep")
    assert main([*base, "--out", str(afile)]) == 2
    assert capsys.readouterr().err == f"crane-sym: error: --out {str(afile)!r} is a file, " \
        "not a folder\n"
    assert main([*base, "--out", str(afile / "sub")]) == 2
    assert "--out" in capsys.readouterr().err
    locked = tmp_path / "locked"
    locked.mkdir()
    real = os.access
    monkeypatch.setattr(os, "access", lambda p, mode, **kw: Path(p) != locked and real(p, mode))
    assert main([*base, "--out", str(locked / "out")]) == 2
    err = capsys.readouterr().err
    assert err.splitlines() == [f"crane-sym: error: --out {str(locked / 'out')!r}: "
                                f"{str(locked)!r} is not writable (permission denied)"]
    assert afile.read_text() == "keep" and list(locked.iterdir()) == []


@pytest.mark.harm("bounds")
def test_grid_size_is_checked_against_memory_and_blocks_before_any_work(monkeypatch):
    import psutil
    chosen = plan(load_scene(SCENE), ["m1=1:100:100000000", "P_t=5:50:3"],
                  ["peak_elastic_force"])

    class Little:
        available = 2**30
    monkeypatch.setattr(psutil, "virtual_memory", lambda: Little)
    with pytest.raises(ValueError, match=r"^--vary m1: 1e\+08 values need about 2.98 GiB"):
        check_grid(chosen, None)
    monkeypatch.undo()
    many = plan(load_scene(SCENE), ["m1=1:100:100000", "P_t=5:50:100000"],
                ["peak_elastic_force"])
    with pytest.raises(ValueError, match=r"^--chunk-mib 0.1: the grid of 1e\+10 designs "
                                         r"makes .* blocks, more than the 100000"):
        check_grid(many, None, int(0.1 * 2**20))


FIG9 = Path(__file__).parents[1] / "examples" / "drive_trains" / "hoist_fig9.toml"
ESTIMATE = (r"estimate: [0-9.e+]+ designs x 1 output\(s\) on \d+ worker\(s\): about [0-9.e+-]+ s "
            r"and [0-9.e+-]+ MiB \((?:a timed pilot of \d+ designs: [0-9.e+-]+ s a design|"
            r"timed pilots of \d+ and \d+ designs: [0-9.e+-]+ s a design, [0-9.e+-]+ s a "
            r"block), [0-9.e+-]+ s to start\)")


@pytest.mark.harm("bounds")
def test_a_million_designs_of_a_component_file_are_estimated_and_refused(tmp_path, capsys):
    """10^6 designs of the Fig. 9 hoist (each a run of its own) under the
    default --time-limit: the estimate first, then one line, nothing written;
    with --quiet, the one line alone."""
    out = tmp_path / "out"
    argv = ["sweep", str(FIG9), "--vary", "gearbox_mesh.stiffness=1e4:1e5:1000:log",
            "--vary", "safety_brakes.torque=100:160:1000", "--output", "gearbox_mesh.peak",
            "--out", str(out)]
    assert main([*argv, "--quiet"]) == 2
    alone = capsys.readouterr().err.splitlines()
    assert main(argv) == 2          # the same pilot again: solved afresh, not looked up
    estimate, error = capsys.readouterr().err.splitlines()
    assert len(alone) == 1 and alone[0].startswith("crane-sym: error: --time-limit 900: ")
    assert re.fullmatch(ESTIMATE.replace("[0-9.e+]+ designs", "1e\\+06 designs"), estimate)
    assert re.fullmatch(r"crane-sym: error: --time-limit 900: the sweep of 1e\+06 designs would "
                        r"take about [0-9.e+]+ s \(timed pilots of 16 and 1024 designs\); give fewer "
                        r"designs or a larger limit", error)
    assert not out.exists()


@pytest.mark.harm("bounds")
def test_a_sweep_prints_its_estimate_before_it_starts(tmp_path, capsys):
    base = ["sweep", SCENE, "--vary", "m1=1:100:20", "--output", "peak_elastic_force"]
    assert main([*base, "--out", str(tmp_path / "slow"), "--time-limit", "1e-9"]) == 2
    err = capsys.readouterr().err.splitlines()
    assert re.fullmatch(ESTIMATE, err[0]) and err[1].startswith("crane-sym: error: "
                                                                "--time-limit 1e-09: ")
    assert not (tmp_path / "slow").exists()
    assert main([*base, "--out", str(tmp_path / "fine")]) == 0
    assert re.fullmatch(ESTIMATE, capsys.readouterr().err.splitlines()[0])
    assert (tmp_path / "fine" / f"{SCENE}_sweep.zarr").is_dir()


def test_certify_of_a_component_file_is_one_line_naming_it(tmp_path, capsys):
    """`sweep FILE --certify`: its outputs are a hybrid run's, with no interval
    enclosure; one line naming --certify and the output (it said "unknown
    derivation" with the file's path), before the estimate's pilot, nothing written."""
    out = tmp_path / "out"
    assert main(["sweep", str(FIG9), "--vary", "gearbox_mesh.stiffness=2e4:8e4:3",
                 "--output", "gearbox_mesh.peak", "--certify", "--out", str(out)]) == 2
    err = capsys.readouterr().err
    assert re.fullmatch(r"crane-sym: error: --certify: gearbox_mesh\.peak is a hybrid run "
                        r"\(phases that end at events found numerically\): .*; certify a "
                        r"paper's closed-form output \(a component file's outputs are all "
                        r"hybrid\)\n", err), err
    assert not out.exists()


@pytest.mark.harm("bounds")
def test_the_pilot_solves_afresh_what_the_process_has_solved_before(monkeypatch):
    """A block a sweep solved is kept in the process and handed out again; the
    estimate's pilot must time a solve, not that look-up: with its blocks
    already kept, they are solved again (Designs.largest called for the
    warm-up and the timed block), and the pilot keeps nothing."""
    from crane_sym.components import designs
    from crane_sym.sweep.component_plan import plan_file
    from crane_sym.sweep.estimate import estimate
    chosen = plan_file(str(FIG9), ["gearbox_mesh.stiffness=2e4:8e4:3"], ["gearbox_mesh.peak"],
                       [], None)
    solved = []
    real = designs.Designs.largest

    def counted(self, output, values):
        solved.append(output)
        return real(self, output, values)
    monkeypatch.setattr(designs.Designs, "largest", counted)
    monkeypatch.setattr(designs, "_SOLVED", {})   # whatever other tests kept here
    path, digest = chosen.options["component_file"], chosen.options["digest"]
    axis = chosen.axes[0].si()
    for block in (axis[:1], axis):          # the pilot's blocks, as a sweep keeps them
        designs.evaluate_block(path, digest, "gearbox_mesh.peak",
                               {"gearbox_mesh.stiffness": block})
    assert len(solved) == 2
    kept = set(designs._SOLVED)
    found = estimate(chosen)
    assert len(solved) == 4 and found.per_design > 0
    assert set(designs._SOLVED) == kept


def test_a_batched_outputs_estimate_is_a_time_a_block_and_a_time_a_design(monkeypatch):
    """003's start-up solves a block's designs together: its estimate times two
    pilots (16 and 1024 designs) and splits their times into a time a block
    and a time a design, counted over the sweep's blocks and workers."""
    from crane_sym.scenes.reading import load_scene
    from crane_sym.sweep import blocks, estimate as est
    from crane_sym.sweep.spec import plan
    monkeypatch.setattr(blocks.os, "cpu_count", lambda: 2)
    monkeypatch.setattr(est.os, "cpu_count", lambda: 2)
    sizes = []

    def affine(run, bs):                     # a block: 0.05 s, and 0.1 ms a design
        n = int(np.prod([len(b) for b in bs]))
        sizes.append(n)
        return 0.05 + 1e-4 * n
    monkeypatch.setattr(est, "_seconds", affine)
    chosen = plan(load_scene("fig12_startup_backlash"), ["c_l=2:8:100", "zeta=0.02:0.1:100"],
                  ["peak_startup_link_force"], ["phi_b=3.14159"])
    found = est.estimate(chosen)
    assert sizes == [16, 1024] and (found.pilot, found.second) == (16, 1024)
    assert found.per_design == pytest.approx(1e-4) and found.per_block == pytest.approx(0.05)
    assert found.workers == 2                # two blocks of 5 000 on two threads
    assert found.seconds == pytest.approx(found.warmup + (2 * 0.05 + 1e-4 * 10_000) / 2)
    assert "timed pilots of 16 and 1024 designs" in found.line()
    small = plan(load_scene("fig12_startup_backlash"), ["c_l=2:8:20", "zeta=0.02:0.1:20"],
                 ["peak_startup_link_force"], ["phi_b=3.14159"])
    sizes.clear()
    found = est.estimate(small)              # one block: one worker; too small for two pilots
    assert sizes == [16] and found.workers == 1 and found.second == 0
    assert found.seconds == pytest.approx(found.warmup + (0.05 + 1e-4 * 16) / 16 * 400)
