"""``crane-sym bench --sweep``, the targets of the batched hybrid solver
(issue 28), each row printed with met / not met:

- 10⁴ designs in one block on one core in at most 1 s (the least of
  three runs, each printed), at least 500× the per-design loop (from
  :func:`crane_sym.bench.batched.bench_batched`);
- 10⁶ designs as a sweep (blocks on Dask's local scheduler, nothing written:
  threads for a NumPy-bound output, :mod:`crane_sym.sweep.blocks`)
  in at most 2 minutes and 1 GiB: run in a child process, its time and the
  largest summed resident memory of it and its workers, sampled every 50 ms
  (:func:`large_row`);
- against SciPy's ``solve_ivp`` with events per design: on a seeded sample of
  the grid, :func:`crane_sym.bench.piecewise.bench_run` (what ``crane-sym
  bench`` runs for a scene's hybrid run) finds per design the fastest
  integrator run whose output is within 1e-6 and 1e-9 of the peak; its mean
  time a design is extrapolated to the grid (stated) and set against the
  batched time of the grid, targets 100× and 1000× (:func:`ivp_rows`);
- parallel efficiency on 2 cores: 9·10⁴ designs by Dask's threads in the
  blocks a local sweep makes against the same blocks one after the other
  in this process without Dask, target 70 %, with an np.sin control
  (:func:`crane_sym.bench.thread_blocks.thread_row`; it replaces the row of
  10⁴ designs on processes, which a sweep now solves as one block);
- the worst case of the grid against the per-design solver: the designs
  whose batched value is within 1 % of the worst, and a seeded sample, run
  by the per-design solver (:func:`worst_row`).
"""
from __future__ import annotations

import json
import subprocess
import sys
import threading
import time
from typing import Any

import numpy as np

from crane_sym import progress
from crane_sym.bench.batched import _grid
from crane_sym.bench.cases import BatchedBenchCase
from crane_sym.bench.roofline import markdown_rows as roofline_rows
from crane_sym.bench.thread_blocks import markdown_row as thread_markdown_row
from crane_sym.bench.thread_blocks import thread_row, variant_rows
from crane_sym.sweep.grid import evaluate_block, run_sweep

__all__ = ["large_row", "ivp_rows", "worst_row", "markdown_rows", "parallel_section"]

#: The targets: seconds for 10⁴ designs, the speed-up over the per-design
#: loop, seconds and bytes for 10⁶, speed-ups over solve_ivp at 1e-6 and 1e-9.
ONE_BLOCK_SECONDS = 1.0
LOOP_SPEEDUP = 500.0
LARGE_SECONDS = 120.0
LARGE_BYTES = 2**30
IVP_SPEEDUP = {1e-6: 100.0, 1e-9: 1000.0}


def _call(case: BatchedBenchCase, n: int):
    chosen, spec, names, axes = _grid(case, n)
    return chosen, (chosen.derivation, case.output, spec.kind, spec.args, names,
                    dict(chosen.fixed), dict(chosen.options)), axes


def large_row(case: BatchedBenchCase, designs: int = 10**6) -> dict[str, Any]:
    """The grid of ``designs`` (a square) swept in a child process: seconds,
    the peak of the summed resident memory of it and its Dask workers."""
    import psutil
    n = int(round(designs ** (1 / len(case.axes))))
    code = ("import json, time, sys\n"
            "from crane_sym.bench.batched_targets import _large_child\n"
            f"print(json.dumps(_large_child({case.scene!r}, {case.output!r}, "
            f"{list(case.axes)!r}, {n})))\n")
    child = subprocess.Popen([sys.executable, "-c", code], stdout=subprocess.PIPE, text=True)
    peak, cpu, done = [0], {}, threading.Event()

    def watch() -> None:
        proc = psutil.Process(child.pid)
        while not done.is_set():
            try:
                tree = [proc, *proc.children(recursive=True)]
                peak[0] = max(peak[0], sum(p.memory_info().rss for p in tree))
                for p in tree:                    # the last CPU time seen of each
                    times = p.cpu_times()
                    cpu[p.pid] = times.user + times.system
            except psutil.Error:
                pass
            time.sleep(0.05)
    watcher = threading.Thread(target=watch, daemon=True)
    watcher.start()
    out, _ = child.communicate()
    done.set()
    watcher.join()
    row = json.loads(out.strip().splitlines()[-1])
    row["peak_bytes"] = peak[0]
    row["cpu_seconds"] = sum(cpu.values())        # the child and its workers, as sampled
    row["met"] = row["seconds"] <= LARGE_SECONDS and peak[0] <= LARGE_BYTES
    return row


def _large_child(scene: str, output: str, axes: list[str], n: int) -> dict[str, Any]:
    """In the child: the sweep of n per axis on the local scheduler."""
    from crane_sym.scenes.reading import load_scene
    from crane_sym.sweep.spec import plan
    chosen = plan(load_scene(scene), [a.format(n=n) for a in axes], [output])
    start, cpu = time.perf_counter(), time.process_time()
    result = run_sweep(chosen, None)
    return {"designs": chosen.points, "seconds": time.perf_counter() - start,
            "parent_cpu_seconds": time.process_time() - cpu, "blocks": result.blocks,
            "scheduler": result.scheduler, "worst": result.worst[output][0],
            "capped": result.capped.get(output, 0)}


def ivp_rows(case: BatchedBenchCase, batched_seconds: float, designs: int,
             sample: int = 3, seed: int = 28) -> list[dict[str, Any]]:
    """Per accuracy (1e-6, 1e-9 of the peak): the mean over a seeded sample of
    designs of the fastest ``solve_ivp`` run reaching it, extrapolated to
    ``designs``, against ``batched_seconds`` for them."""
    from crane_sym.bench.piecewise import bench_run
    run_of, picks = _family(case, sample, seed)
    best = {tol: [] for tol in IVP_SPEEDUP}
    methods, runs, wrong = {tol: [] for tol in IVP_SPEEDUP}, 0, 0
    for i in picks:
        rows, table = bench_run(run_of(int(i)), points=200, reference_points=200,
                                repeats=1)
        integrators = [r for r in rows if np.isfinite(r.rtol)]
        runs += len(integrators)
        wrong += sum(r.phases != len(table.events) for r in integrators)
        for tol in IVP_SPEEDUP:
            ok = [r for r in integrators if r.error <= tol]
            fastest = min(ok, key=lambda r: r.seconds) if ok else None
            best[tol].append(np.inf if fastest is None else fastest.seconds)
            methods[tol].append("none" if fastest is None
                                else f"{fastest.method} rtol={fastest.rtol:g}")
    out = []
    for tol, limit in IVP_SPEEDUP.items():
        per = float(np.mean(best[tol]))
        speedup = per * designs / batched_seconds
        out.append({"accuracy": tol, "sample": len(picks), "per_design_seconds": per,
                    "extrapolated_seconds": per * designs, "designs": designs,
                    "batched_seconds": batched_seconds, "speedup": speedup, "target": limit,
                    "met": bool(speedup >= limit), "settings": methods[tol],
                    "integrator_runs": runs, "runs_with_other_phase_count": wrong})
    return out


def _family(case: BatchedBenchCase, sample: int, seed: int):
    """Design i of the case's grid as a per-design run, and seeded picks."""
    chosen, spec, names, axes = _grid(case, case.n)
    grid = np.meshgrid(*axes, indexing="ij")
    q = {**{a: v for a, v in chosen.fixed.items() if a in spec.args},
         **dict(zip(names, (g.ravel() for g in grid)))}
    rng = np.random.default_rng(seed)
    picks = rng.choice(grid[0].size, size=sample, replace=False)
    return (lambda i: case.run(q, dict(chosen.options), i)), picks


def worst_row(case: BatchedBenchCase, sample: int = 40, seed: int = 28) -> dict[str, Any]:
    """The grid's worst case by the batched solver against the per-design
    solver at every design within 1 % of it and at a seeded sample."""
    chosen, call, axes = _call(case, case.n)
    values = evaluate_block(*call, *axes)
    flat = values.ravel()
    worst = float(np.nanmax(flat))
    near = np.flatnonzero(flat >= 0.99 * worst)
    rng = np.random.default_rng(seed)
    picks = np.union1d(near, rng.choice(flat.size, size=sample, replace=False))
    index = np.unravel_index(picks, values.shape)
    q = {a: np.full(picks.size, v) for a, v in chosen.fixed.items()
         if a in chosen.output(case.output).args}
    for k, a in enumerate(chosen.axes):
        q[a.name] = axes[k][index[k]]
    start = time.perf_counter()
    per = np.asarray(case.per_design(q, dict(chosen.options)), dtype=float)
    seconds = time.perf_counter() - start
    rel = np.abs(flat[picks] - per) / np.abs(per)
    per_worst = float(per.max())
    return {"designs": int(flat.size), "checked": int(picks.size), "near_worst": int(near.size),
            "batched_worst": worst, "per_design_worst": per_worst,
            "max_rel_difference": float(rel.max()), "per_design_seconds": seconds,
            "met": bool(abs(worst - per_worst) <= 1e-9 * abs(per_worst))}


def markdown_rows(r: dict[str, Any]) -> list[str]:
    """Section (f) of ``bench_sweep.md``: the batched solver's targets."""
    if not r:
        return []
    met = lambda ok: "met" if ok else "not met"  # noqa: E731
    one = r["one_block"]
    lines = ["## (f) Hybrid outputs: the targets of the batched solver", "",
             "| target | measured | limit | met |", "| --- | --- | --- | --- |",
             f"| {one['designs']} designs of {one['output']}, one block, one core | "
             f"{one['batched_seconds']:.2f} s wall, {one['batched_cpu_seconds']:.2f} s CPU "
             f"(least of {one['repeats']}: "
             f"{', '.join(f'{w:.2f}' for w in one['batched_seconds_all'])} s) | "
             f"≤ {ONE_BLOCK_SECONDS:g} s | {met(one['batched_seconds'] <= ONE_BLOCK_SECONDS)} |",
             f"| speed-up over the per-design loop (sample of {one['sample']}, extrapolated) | "
             f"{one['speedup']:.0f}× | ≥ {LOOP_SPEEDUP:g}× | "
             f"{met(one['speedup'] >= LOOP_SPEEDUP)} |"]
    if "large" in r:
        g = r["large"]
        lines.append(f"| {g['designs']:.0e} designs as a sweep ({g['blocks']} blocks, "
                     f"{g['scheduler']}) | {g['seconds']:.1f} s ("
                     f"{g.get('cpu_seconds', float('nan')):.0f} CPU s in it and its workers), "
                     f"peak {g['peak_bytes'] / 2**20:.0f} MiB (summed over the processes) | "
                     f"≤ {LARGE_SECONDS:g} s and ≤ 1 GiB | {met(g['met'])} |")
    for v in r.get("ivp", []):
        lines.append(f"| against solve_ivp with events within {v['accuracy']:g} of the peak "
                     f"({v['per_design_seconds'] * 1e3:.0f} ms a design, mean of {v['sample']} "
                     f"sampled designs, extrapolated to {v['designs']}: "
                     f"{v['extrapolated_seconds']:.0f} s) | {v['speedup']:.0f}× | "
                     f"≥ {v['target']:g}× | {met(v['met'])} |")
    if "threads" in r:
        lines.append(thread_markdown_row(r["threads"]))
    if "worst" in r:
        w = r["worst"]
        lines.append(f"| worst case of the {w['designs']} designs against the per-design "
                     f"solver ({w['checked']} designs run per design: the {w['near_worst']} "
                     f"within 1 % of the worst and a seeded sample) | rel. difference "
                     f"{abs(w['batched_worst'] - w['per_design_worst']) / w['per_design_worst']:.1e}"
                     f" (largest on the checked {w['max_rel_difference']:.1e}) | ≤ 1e-9 | "
                     f"{met(w['met'])} |")
    ivp = r.get("ivp", [])
    if ivp:
        lines += ["", "Fastest integrator settings per sampled design: " + "; ".join(
            f"{v['accuracy']:g}: " + ", ".join(v["settings"]) for v in ivp)
            + f". {ivp[0]['runs_with_other_phase_count']} of {ivp[0]['integrator_runs']} "
            "integrator runs found another number of phases than the closed form."]
    if "roofline" in r.get("threads", {}):
        t = r["threads"]
        lines += variant_rows(t) + roofline_rows(t["efficiency"], t["target"], t["roofline"],
                                                  t["fit"])
    lines.append("")
    return lines


def parallel_section() -> str:
    """``bench --parallel``: row (f) of the two threads alone, with the
    roofline and the scaling curve of 1..16 workers beside it (a minute or
    two, where a whole ``bench --sweep`` takes many on a busy machine)."""
    from crane_sym.bench.cases import batched_cases
    found = [c for _, c in batched_cases() if c.targets]
    if not found:
        return "# Bench: both cores\n\nNo batched case is marked for the targets.\n"
    t = thread_row(found[0])
    return "\n".join(["# Bench: both cores on a batched sweep, and why", "",
                      "| target | measured | limit | met |", "| --- | --- | --- | --- |",
                      thread_markdown_row(t), *variant_rows(t),
                      *roofline_rows(t["efficiency"], t["target"], t["roofline"], t["fit"]),
                      ""])


def run_targets(rows: list[dict[str, Any]], designs: int = 10**6) -> dict[str, Any]:
    """Every row of section (f) for the case marked ``targets``, its one-block
    row taken from ``rows`` (:func:`crane_sym.bench.batched.run_all`).

    Parameters
    ----------
    rows : list of dict
        The batched rows of this run.
    designs : int
        Designs of the large sweep.
    """
    from crane_sym.bench.cases import batched_cases
    found = [(p, c) for p, c in batched_cases() if c.targets]
    if not found:
        return {}
    paper, case = found[0]
    one = next(r for r in rows if r["paper"] == paper and r["output"] == case.output)
    say = progress.current()
    out: dict[str, Any] = {"one_block": one}
    with say.task("  9·10⁴ designs on two threads"):
        out["threads"] = thread_row(case)
    with say.task("  the worst design"):
        out["worst"] = worst_row(case)
    with say.task(f"  {designs:.0e} designs"):
        out["large"] = large_row(case, designs)
    if case.run is not None:
        with say.task("  against solve_ivp"):
            out["ivp"] = ivp_rows(case, one["batched_seconds"], one["designs"])
    return out
