"""``crane-sym bench --sweep``: design sweeps against per-design integration.

Four measurements in one run, on the cases the papers declare
(``SWEEP_BENCH_CASES``, :mod:`crane_sym.bench.cases`):

(a) a sweep of 10⁴ designs of each case's closed-form peak against SciPy
    integrating each design at matched accuracy: the peak of the integrated
    response (DOP853 dense output over one period past the load's last change,
    sampled, then polished by bounded Brent on the interpolant) within 1e-9 of
    the closed form on every design of a seeded sample, at the loosest rtol of
    1e-9 … 1e-13 that achieves it. Only the sample is integrated; the time
    for 10⁴ designs is extrapolated from its mean (stated in the report);
(b) parallel efficiency: one block list evaluated by Dask's threaded
    scheduler with 1 and with 2 workers, T₁ / (2·T₂);
(c) a 10⁸-design sweep of the main case's peak written to Zarr by the
    command line in a subprocess: its wall time and peak resident memory;
(d) a ``distributed.LocalCluster`` (2 worker processes, 1 thread each)
    against the local scheduler on the same plan, and whether the two
    datasets agree bit for bit;
(e) each hybrid output solved a block at a time against its per-design loop
    (:mod:`crane_sym.bench.batched`): N designs, designs per second, the
    largest relative difference;
(f) the batched solver's targets, met or not: 10⁴ designs in a block, 10⁶ as
    a sweep within 2 minutes and 1 GiB, against ``solve_ivp`` per design at
    1e-6 and 1e-9 of the peak, parallel efficiency beside a no-Dask control,
    the grid's worst case against the per-design solver
    (:mod:`crane_sym.bench.batched_targets`);
(g) 10⁴ designs of a model built from components as one block (a paper's
    case with a ``block_target``, a component file of 5 bodies), met or not,
    with the load and, where not met, where the time goes
    (:mod:`crane_sym.bench.design_targets`).
"""
from __future__ import annotations

import json
import os
import resource
import subprocess
import sys
import tempfile
import time
from pathlib import Path
from typing import Any

import numpy as np

from crane_sym import progress, registry
from crane_sym.bench import batched, batched_targets, design_targets
from crane_sym.bench.cases import SweepBenchCase, sweep_cases
from crane_sym.bench.odes import first_order, parameters
from crane_sym.bench.rows import least_time
from crane_sym.markdown import markdown_table
from crane_sym.scenes.reading import load_scene
from crane_sym.sweep.grid import chunks_for, grid_arrays, run_sweep
from crane_sym.sweep.plan import Axis, OutputSpec, SweepPlan
from crane_sym.sweep.spec import plan

__all__ = ["bench_sweep", "integrated_peak", "markdown"]

RTOLS = (1e-9, 1e-10, 1e-11, 1e-12, 1e-13)
MATCH = 1e-9
SAMPLE = 12


def integrated_peak(f, jac, y0, p: tuple, quantity, pieces: list[float], rtol: float) -> float:
    """Largest value of ``quantity`` over [0, pieces[-1]], integrated piece by
    piece (a breakpoint of the load starts a new piece) with DOP853's dense
    output; 400 samples a piece, the best polished by bounded Brent."""
    from scipy.integrate import solve_ivp
    from scipy.optimize import minimize_scalar
    best, y, start = -np.inf, np.asarray(y0, dtype=float), 0.0
    scale = None
    for end in pieces:
        if scale is None:
            probe = solve_ivp(f, (0.0, pieces[-1]), y, method="DOP853", args=p, rtol=1e-6)
            scale = np.maximum(np.max(np.abs(probe.y), axis=1), 1e-300)
        sol = solve_ivp(f, (start, end), y, method="DOP853", args=p, rtol=rtol,
                        atol=rtol * scale, dense_output=True)
        ts = np.linspace(start, end, 400)
        values = quantity(sol.sol(ts), *p)
        k = int(np.argmax(values))
        lo, hi = ts[max(k - 1, 0)], ts[min(k + 1, len(ts) - 1)]
        found = minimize_scalar(lambda t: -float(quantity(sol.sol(t), *p)), bounds=(lo, hi),
                                method="bounded", options={"xatol": 1e-13 * end})
        best = max(best, float(values[k]), -float(found.fun))
        y, start = sol.y[:, -1], end
    return best


def _prepared(paper: str, case: SweepBenchCase, n: int = 100):
    """The case's plan on n × n designs, the first-order system the integrator
    gets (f, jac, y0), the quantity it maximises, and the system's parameters."""
    d = registry.get(paper)
    system = next(s for s in d.ode_systems if s.name == case.system)
    names = [str(s) for s in parameters(system)]
    f, jac, y0f, quantities = first_order(system, parameters(system))
    axes = [a.format(n=n) for a in case.axes]
    if case.scene is not None:
        chosen = plan(load_scene(case.scene), axes, [case.output])
    else:                              # no shipped scene gives these axes: a direct plan
        spans = []
        for text in axes:
            name, spec = text.split("=")
            lo, hi, count, *log = spec.split(":")
            spans.append(Axis(name, float(lo), float(hi), int(count), bool(log),
                              case.units[name], 1.0))
        chosen = SweepPlan("bench", paper, tuple(spans),
                           (OutputSpec(case.output, "closed", tuple(a.name for a in spans),
                                       "1"),), {})
    return chosen, f, jac, y0f, quantities[case.quantity], names


def _matched(paper: str, case: SweepBenchCase, seed: int = 16) -> dict[str, Any]:
    """(a) for one case: sweep of 10⁴ designs against integrating a sample."""
    chosen, f, jac, y0f, quantity, names = _prepared(paper, case)
    base = dict(load_scene(case.scene).parameters) if case.scene else dict(case.fixed)
    rng = np.random.default_rng(seed)
    axes = [a.si() for a in chosen.axes]
    run_sweep(chosen, None, scheduler="threads")            # imports, first call
    sweep_seconds, swept = least_time(lambda: run_sweep(chosen, None, scheduler="threads"),
                                      budget=1.0, repeats=5)
    picks = [(axes[0][rng.integers(100)], axes[1][rng.integers(100)]) for _ in range(SAMPLE)]
    chosen_rtol, per_design, worst = None, None, None
    for rtol in RTOLS:
        errors, seconds = [], 0.0
        for a, b in picks:
            values, pieces, exact = case.design(
                {**base, chosen.axes[0].name: a, chosen.axes[1].name: b})
            p = tuple(values[n] for n in names)
            y0 = np.array(y0f(*p), dtype=float)
            t0 = time.perf_counter()
            peak = integrated_peak(f, jac, y0, p, quantity, pieces, rtol)
            seconds += time.perf_counter() - t0
            errors.append(abs(peak - exact) / abs(exact))
        worst = max(errors)
        if worst <= MATCH:
            chosen_rtol, per_design = rtol, seconds / SAMPLE
            break
    row = {"paper": paper, "output": case.output, "designs": 10**4,
           "sweep_seconds": sweep_seconds, "sample": SAMPLE, "rtol": chosen_rtol,
           "sample_worst_rel_error": worst}
    if per_design is not None:
        row.update(integrate_seconds_per_design=per_design,
                   integrate_seconds_extrapolated=per_design * 1e4,
                   speedup=per_design * 1e4 / sweep_seconds)
    row["sweep_blocks"] = swept.blocks
    return row


def main_case() -> SweepBenchCase:
    """The case the larger measurements (b)–(d) use: the first a paper
    declares with a scene and a time response."""
    return next(c for _, c in sweep_cases() if c.scene and c.response)


def _main_plan(n: int) -> SweepPlan:
    case = main_case()
    return plan(load_scene(case.scene), [a.format(n=n) for a in case.axes],
                [case.output, case.response[0]], [case.response[1]])


def _efficiency(n: int = 4000) -> dict[str, Any]:
    """(b) one block list (n × n designs of the main case's peak and of its
    time response), threads with 1 and with 2 workers."""
    case = main_case()
    chosen = _main_plan(n)
    arrays = grid_arrays(chosen, chunks_for(chosen))
    out = {"designs": chosen.points, "blocks": arrays[case.response[0]].npartitions,
           "outputs": [case.output, case.response[0]]}
    # the machine's own answer: np.sin over blocks of the same size, no Dask
    blocks = [np.linspace(0.0, 1.0 + k, chosen.points // 16) for k in range(16)]
    arrays["np.sin (no Dask, control)"] = blocks
    for name, array in arrays.items():
        times, cores = {}, {}
        run = _control if isinstance(array, list) else _dask_max
        run(array, 2)                                          # warm: allocations, imports
        for workers in (1, 2) * 3:
            start, cpu = time.perf_counter(), _cpu()
            run(array, workers)
            wall = time.perf_counter() - start
            if wall < times.get(workers, np.inf):
                times[workers], cores[workers] = wall, (_cpu() - cpu) / wall
        # cores: CPU seconds of this process per wall second; below 2 with two
        # workers means other jobs held the second core, not that Dask idled
        out[name] = {"one_worker_s": times[1], "two_workers_s": times[2],
                     "efficiency": times[1] / (2 * times[2]), "cores_used_two": cores[2]}
    return out


def _dask_max(array, workers: int) -> None:
    import dask
    dask.compute(array.max(), scheduler="threads", num_workers=workers)


def _control(blocks: list, workers: int) -> None:
    from concurrent.futures import ThreadPoolExecutor
    with ThreadPoolExecutor(workers) as pool:
        list(pool.map(lambda b: np.sin(b).max(), blocks))


def _cpu() -> float:
    usage = resource.getrusage(resource.RUSAGE_SELF)
    return usage.ru_utime + usage.ru_stime


def _big(out: Path, n: int = 10_000) -> dict[str, Any]:
    """(c) the command line on n × n designs of the main case, in a subprocess;
    its peak RSS."""
    case = main_case()
    argv = [sys.executable, "-m", "crane_sym", "sweep", case.scene,
            *[part for a in case.axes for part in ("--vary", a.format(n=n))],
            "--output", case.output, "--out", str(out), "--format", "json", "--quiet"]
    start = time.perf_counter()
    done = subprocess.run(argv, capture_output=True, text=True, check=True)
    wall = time.perf_counter() - start
    data = json.loads(done.stdout)
    rss = resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss / 1024
    return {"designs": data["points"], "blocks": data["chunks"], "sweep_seconds":
            data["seconds"], "command_seconds": wall, "peak_rss_mib": rss,
            "output": case.output}


def _cluster(out: Path, n: int = 3000) -> dict[str, Any]:
    """(d) LocalCluster (2 processes × 1 thread) against the local scheduler."""
    import xarray as xr
    from distributed import LocalCluster
    chosen = _main_plan(n)
    local = run_sweep(chosen, out / "local")
    start = time.perf_counter()
    with LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                      dashboard_address=":0") as cluster:
        up = time.perf_counter() - start
        remote = run_sweep(chosen, out / "cluster", scheduler=cluster.scheduler_address)
    a, b = (xr.open_zarr(r.dataset).load() for r in (local, remote))
    same = all(np.array_equal(a[k].values.view(np.uint64), b[k].values.view(np.uint64))
               for k in a.data_vars)
    return {"designs": chosen.points, "outputs": 2, "blocks": local.blocks,
            "local_s": local.seconds, "cluster_s": remote.seconds, "cluster_start_s": up,
            "bit_for_bit": same and local.worst == remote.worst}


def bench_sweep() -> dict[str, Any]:
    """The measurements (a)–(g), each said on stderr as it starts and ends
    (:mod:`crane_sym.progress`); datasets in a temporary folder."""
    say = progress.current()
    with tempfile.TemporaryDirectory(prefix="crane_sym_bench_sweep_") as tmp:
        with say.task("(e) hybrid outputs batched against their per-design loop"):
            rows = batched.run_all()
        matched = []
        for i, c in sweep_cases():
            with say.task(f"(a) {i} {c.output}: 10^4 designs against integrating a sample"):
                matched.append(_matched(i, c))
        with say.task("(b) parallel efficiency, 1 and 2 workers"):
            efficiency = _efficiency()
        with say.task("(c) the command line on 10^8 designs"):
            large = _big(Path(tmp) / "big")
        with say.task("(d) a LocalCluster against the local scheduler"):
            cluster = _cluster(Path(tmp))
        with say.task("(f) the batched targets"):
            targets = batched_targets.run_targets(rows)
        with say.task("(g) 10^4 designs of a model from components, one block"):
            designs = design_targets.run_rows()
        return {"matched_accuracy": matched, "parallel_efficiency": efficiency,
                "large": large, "cluster": cluster, "batched": rows,
                "batched_targets": targets, "design_targets": designs, "cores": os.cpu_count(),
                "load_average": os.getloadavg()[0]}


def _matched_row(a: dict[str, Any]) -> list[str]:
    """A row of table (a): the sweep against the integrator that matched it."""
    if a.get("rtol") is None:
        return [a["paper"], a["output"], f"{a['sweep_seconds']:.4f}",
                f"none reached {MATCH:g} (best {a['sample_worst_rel_error']:.1e})", "", "", ""]
    return [a["paper"], a["output"], f"{a['sweep_seconds']:.4f}", f"{a['rtol']:g}",
            f"{1e3 * a['integrate_seconds_per_design']:.2f}",
            f"{a['integrate_seconds_extrapolated']:.1f}", f"{a['speedup']:.3g}×"]


def markdown(r: dict[str, Any]) -> str:
    """The results as the Markdown of ``bench_sweep.md``.

    Parameters
    ----------
    r : dict
        The results of :func:`bench_sweep`.
    """
    lines = ["# Bench: design sweeps (crane-sym sweep)", "",
             f"{r['cores']} cores, load average {r['load_average']:.1f} at the end (the "
             "machine is shared; ratios come from this one run).", "",
             "## (a) Sweep of 10⁴ designs against per-design SciPy integration", "",
             f"Integration: DOP853 with dense output, peak sampled and polished; loosest rtol "
             f"reaching {MATCH:g} of the closed-form peak on all {SAMPLE} sampled designs; "
             "time for 10⁴ designs extrapolated from the sample mean.", "",
             markdown_table(["paper", "output", "sweep of 10⁴ [s]", "rtol", "per design [ms]",
                             "10⁴ integrated (extrapolated) [s]", "speed-up"],
                            [_matched_row(a) for a in r["matched_accuracy"]])]
    e = r["parallel_efficiency"]
    lines += ["", f"## (b) Parallel efficiency, {e['designs']:.3g} designs in {e['blocks']} "
              "blocks, threads", "", markdown_table(
                  ["output", "1 worker [s]", "2 workers [s]", "T₁/(2·T₂)",
                   "cores the process got with 2 workers"],
                  [[name, f"{e[name]['one_worker_s']:.3f}", f"{e[name]['two_workers_s']:.3f}",
                    f"{100 * e[name]['efficiency']:.0f} %", f"{e[name]['cores_used_two']:.2f}"]
                   for name in (*e["outputs"], "np.sin (no Dask, control)")])]
    b, c = r["large"], r["cluster"]
    lines += ["", f"## (c) 10⁸ designs of {b['output']}, written to Zarr", "",
              f"{b['designs']:.3g} designs in {b['blocks']} blocks: sweep {b['sweep_seconds']:.2f}"
              f" s, whole command (imports, Zarr, PNG) {b['command_seconds']:.1f} s, peak "
              f"resident memory {b['peak_rss_mib']:.0f} MiB.", "",
              "## (d) LocalCluster (2 processes × 1 thread) against the local scheduler", "",
              f"{c['designs']:.3g} designs × {c['outputs']} outputs, {c['blocks']} blocks "
              f"each: local {c['local_s']:.2f} s, cluster {c['cluster_s']:.2f} s (start "
              f"{c['cluster_start_s']:.1f} s); bit for bit identical: {c['bit_for_bit']}.", ""]
    lines += batched.markdown_rows(r.get("batched", []))
    lines += batched_targets.markdown_rows(r.get("batched_targets", {}))
    lines += design_targets.markdown_rows(r.get("design_targets", []))
    return "\n".join(lines)
