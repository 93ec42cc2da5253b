"""``crane-sym bench --sweep``, the batched rows: a hybrid sweep output solved
a block at a time against the per-design loop it replaces.

A paper declares :class:`crane_sym.bench.cases.BatchedBenchCase` values in
``BATCHED_BENCH_CASES``: a simulated sweep output that solves a block's
designs together (``SweepOutput.batched``), the scene and the axes of its
grid, and the per-design loop it replaces. :func:`bench_batched` evaluates
the whole grid of N designs as one block (the call a sweep's worker makes,
``crane_sym.sweep.grid.evaluate_block``) and a seeded sample of it by the
per-design loop; it reports both in designs per second, the per-design time
of N extrapolated from the sample's mean (stated), the largest relative
difference on the sample, and where the batched time went (closed forms,
event search, the output's extrema, switching, the per-design tail).
"""
from __future__ import annotations

import time
from typing import Any

import numpy as np

from crane_sym import progress
from crane_sym.bench.cases import BatchedBenchCase, batched_cases
from crane_sym.scenes.reading import load_scene
from crane_sym.sweep.grid import evaluate_block
from crane_sym.sweep.spec import plan

__all__ = ["REPEATS", "bench_batched", "markdown_rows"]

#: Runs of the whole block; the least is reported (all of them kept in the JSON).
REPEATS = 3


def _grid(case: BatchedBenchCase, n: int):
    chosen = plan(load_scene(case.scene), [a.format(n=n) for a in case.axes], [case.output],
                  list(case.at))
    spec = chosen.output(case.output)
    names = tuple(a.name for a in chosen.axes)
    axes = [a.si() for a in chosen.axes]
    return chosen, spec, names, axes


def bench_batched(paper: str, case: BatchedBenchCase, seed: int = 28) -> dict[str, Any]:
    """One case: its grid as one batched block against a sample per design."""
    chosen, spec, names, axes = _grid(case, case.n)
    call = (chosen.derivation, case.output, spec.kind, spec.args, names, dict(chosen.fixed),
            dict(chosen.options))
    say = progress.current()                  # a stage line each, so no stage is silent
    say.step(f"  {case.output}: the first call (imports, the derivation) ...")
    evaluate_block(*call, *[a[:2] for a in axes])            # imports, first call
    # the least of REPEATS runs: on a shared machine others only ever add time
    runs = []
    for k in range(REPEATS):
        say.step(f"  {case.output}: {int(np.prod([a.size for a in axes]))} designs as one "
                 f"block, run {k + 1} of {REPEATS} ...")
        start, cpu = time.perf_counter(), time.process_time()
        batched = evaluate_block(*call, *axes)
        runs.append((time.perf_counter() - start, time.process_time() - cpu))
    batched_seconds, batched_cpu = min(runs)
    rng = np.random.default_rng(seed)
    picks = [tuple(int(rng.integers(a.size)) for a in axes) for _ in range(case.sample)]
    values = {a: np.full(len(picks), v) for a, v in chosen.fixed.items() if a in spec.args}
    for k, name in enumerate(names):
        values[name] = np.array([axes[k][p[k]] for p in picks])
    say.step(f"  {case.output}: the per-design loop on a sample of {len(picks)} ...")
    start, cpu = time.perf_counter(), time.process_time()
    loop = np.asarray(case.per_design(values, dict(chosen.options)), dtype=float)
    loop_seconds = time.perf_counter() - start
    loop_cpu = time.process_time() - cpu
    mine = np.array([batched[p] for p in picks])
    rel = np.abs(mine - loop) / np.maximum(np.abs(loop), np.finfo(float).tiny)
    per_design = loop_seconds / len(picks)
    row = {"paper": paper, "output": case.output, "designs": int(batched.size),
           "batched_seconds": batched_seconds, "repeats": REPEATS,
           "batched_seconds_all": [w for w, _ in runs],
           "batched_designs_per_second": batched.size / batched_seconds,
           "sample": len(picks), "per_design_seconds": per_design,
           "per_design_designs_per_second": 1.0 / per_design,
           "per_design_extrapolated_seconds": per_design * batched.size,
           "speedup": per_design * batched.size / batched_seconds,
           # CPU seconds of this process: on a shared machine, what the work cost
           "batched_cpu_seconds": batched_cpu,
           "speedup_cpu": loop_cpu / len(picks) * batched.size / batched_cpu,
           "max_rel_difference": float(rel.max())}
    breakdown = getattr(case, "breakdown", None)
    if breakdown is not None:                     # where the batched time went
        say.step(f"  {case.output}: where the batched time went (a second run) ...")
        row["breakdown"] = breakdown(chosen, axes)
    return row


def run_all() -> list[dict[str, Any]]:
    """Every declared case, each said as it is measured."""
    say, rows = progress.current(), []
    for i, c in batched_cases():
        with say.task(f"  batched {i} {c.output}"):
            rows.append(bench_batched(i, c))
    return rows


def markdown_rows(rows: list[dict[str, Any]]) -> list[str]:
    """The section of ``bench_sweep.md`` for the batched rows."""
    if not rows:
        return []
    lines = ["## (e) Hybrid outputs: the batched solver against the per-design loop", "",
             "The whole grid of N designs evaluated as one block (as a sweep's worker "
             f"evaluates a block; the least of {REPEATS} runs); the per-design loop run on a "
             "seeded sample of it, its time for N extrapolated from the sample's mean; the "
             "difference is the largest relative difference of the peak on the sample. Wall "
             "times; the speed-up in CPU seconds of this process beside it (the machine is "
             "shared).", "",
             "| paper | output | N | batched [s] | batched [designs/s] | per design [ms] "
             "(sample) | loop [designs/s] | N by the loop (extrapolated) [s] | speed-up (CPU) | "
             "max rel. difference |", "| --- | --- | --- | --- | --- | --- | --- | --- | --- "
             "| --- |"]
    for r in rows:
        lines.append(f"| {r['paper']} | {r['output']} | {r['designs']} | "
                     f"{r['batched_seconds']:.2f} | {r['batched_designs_per_second']:.0f} | "
                     f"{1e3 * r['per_design_seconds']:.1f} ({r['sample']}) | "
                     f"{r['per_design_designs_per_second']:.1f} | "
                     f"{r['per_design_extrapolated_seconds']:.0f} | {r['speedup']:.3g}× "
                     f"({r['speedup_cpu']:.3g}×) | "
                     f"{r['max_rel_difference']:.1e} |")
    for r in rows:
        if "breakdown" in r:
            parts = ", ".join(f"{k} {v:.2f} s" for k, v in r["breakdown"].items())
            lines.append(f"\n{r['paper']} {r['output']}, where the batched time went "
                         f"(a second run, CPU seconds): {parts}.")
    lines.append("")
    return lines
