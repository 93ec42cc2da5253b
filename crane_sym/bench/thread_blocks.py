"""``crane-sym bench --sweep``, section (f): both cores on a NumPy-bound
batched output (issue 39, item 2).

The case's grid of 9·10⁴ designs in the blocks a local sweep cuts it into
(:func:`crane_sym.sweep.blocks.chunks_for`: blocks of at least 4·10⁴ designs,
one per core), swept by Dask's threads (nothing written) against the same
blocks one after the other in this process without Dask (the control):
parallel efficiency T₁/(2·T₂), target 70 %. Beside it the machine's own
answer, ``np.sin`` over two blocks in two plain threads against one after
the other, and the load average: on a shared 2-core machine another job on
the second core takes the efficiency with it, which the np.sin control shows.
"""
from __future__ import annotations

import os
import resource
import time
from concurrent.futures import ThreadPoolExecutor
from typing import Any, Callable

import numpy as np

from crane_sym import progress
from crane_sym.bench.batched import _grid
from crane_sym.bench.cases import BatchedBenchCase
from crane_sym.bench.roofline import roofline
from crane_sym.sweep.grid import chunks_for, evaluate_block, run_sweep

__all__ = ["DESIGNS", "EFFICIENCY", "REPEATS", "markdown_row", "thread_row"]

#: Designs of the row (a square grid), the target, and runs of each side
#: (the least kept: on a shared machine others only ever add time).
DESIGNS = 90_000
EFFICIENCY = 0.70
REPEATS = 2
#: Elements of each of the control's two np.sin blocks.
SIN_BLOCK = 10**7


def _cpu() -> float:
    usage = resource.getrusage(resource.RUSAGE_SELF)
    return usage.ru_utime + usage.ru_stime


def _least(run: Callable[[], Any]) -> tuple[float, float, list[float]]:
    """Wall seconds of the least of :data:`REPEATS` runs, the CPU seconds of
    this process per wall second in it, and every run's wall seconds."""
    best, cores, walls = np.inf, 0.0, []
    for _ in range(REPEATS):
        start, cpu = time.perf_counter(), _cpu()
        run()
        wall = time.perf_counter() - start
        walls.append(wall)
        if wall < best:
            best, cores = wall, (_cpu() - cpu) / wall
    return best, cores, walls


def _sin_control() -> dict[str, float]:
    """np.sin over two blocks: one after the other, and in two plain threads."""
    blocks = [np.linspace(0.0, 1.0 + k, SIN_BLOCK) for k in range(2)]

    def alone() -> None:
        for b in blocks:
            np.sin(b).max()

    def pair() -> None:
        with ThreadPoolExecutor(2) as pool:
            list(pool.map(lambda b: np.sin(b).max(), blocks))
    pair()                                                   # warm: the allocations
    one, _, _ = _least(alone)
    two, cores, _ = _least(pair)
    return {"one_thread_s": one, "two_threads_s": two, "efficiency": one / (2 * two),
            "cores_used_two": cores}


def thread_row(case: BatchedBenchCase, designs: int = DESIGNS) -> dict[str, Any]:
    """The case's grid of ``designs`` (a square) by Dask's threads in the
    local sweep's blocks, against the same blocks without Dask; with the
    np.sin control and the load average before and after."""
    say = progress.current()
    n = int(round(designs ** (1 / len(case.axes))))
    chosen, spec, names, axes = _grid(case, n)
    call = (chosen.derivation, case.output, spec.kind, spec.args, names, dict(chosen.fixed),
            dict(chosen.options))
    chunks = chunks_for(chosen, workers=2)
    starts = [np.cumsum((0,) + c) for c in chunks]
    parts = [[a[s[i]:s[i + 1]] for a, s, i in zip(axes, starts, ix)]
             for ix in np.ndindex(*[len(c) for c in chunks])]
    load_before = os.getloadavg()[0]
    evaluate_block(*call, *[a[:2] for a in axes])            # imports, the derivation
    say.step(f"  {chosen.points} designs in {len(parts)} blocks without Dask ...")
    kept: list[np.ndarray] = []

    def one_after_the_other() -> None:
        kept[:] = [evaluate_block(*call, *p) for p in parts]
    alone, alone_cores, alone_all = _least(one_after_the_other)
    say.step(f"  {chosen.points} designs in {len(parts)} blocks on Dask's threads ...")
    found = []
    dask_s, dask_cores, dask_all = _least(
        lambda: found.append(run_sweep(chosen, None, scheduler="threads")))
    result = found[-1]
    say.step("  the np.sin control ...")
    control = _sin_control()
    say.step("  the roofline: memory bandwidth, np.sin and np.add on 1 and 2 threads ...")
    roof = roofline()
    efficiency = alone / (2 * dask_s)
    worst = max(float(np.nanmax(b)) for b in kept)
    return {"output": case.output, "designs": chosen.points, "blocks": len(parts),
            "block_designs": [int(np.prod([len(a) for a in p])) for p in parts],
            "sweep_blocks": result.blocks, "scheduler": result.scheduler,
            "no_dask_seconds": alone, "no_dask_seconds_all": alone_all,
            "no_dask_cores": alone_cores, "dask_seconds": dask_s, "dask_seconds_all": dask_all,
            "dask_cores": dask_cores, "efficiency": efficiency, "target": EFFICIENCY,
            "met": efficiency >= EFFICIENCY, "sin": control, "roofline": roof,
            "same_worst": worst == result.worst[case.output][0],
            "load_before": load_before, "load_after": os.getloadavg()[0]}


def markdown_row(t: dict[str, Any]) -> str:
    """The row of table (f)."""
    s = t["sin"]
    return (f"| {t['designs']} designs of {t['output']} on 2 threads ({t['blocks']} blocks of "
            f"{', '.join(str(d) for d in t['block_designs'])}, Dask's {t['scheduler']}) "
            f"against the same blocks one after the other without Dask | efficiency "
            f"{100 * t['efficiency']:.0f} % ({t['no_dask_seconds']:.2f} s → "
            f"{t['dask_seconds']:.2f} s, least of {len(t['dask_seconds_all'])}; the process got "
            f"{t['dask_cores']:.2f} cores); np.sin control {100 * s['efficiency']:.0f} % "
            f"({s['one_thread_s']:.3f} s → {s['two_threads_s']:.3f} s); load "
            f"{t['load_before']:.1f} before, {t['load_after']:.1f} after; same worst: "
            f"{t['same_worst']} | ≥ {100 * t['target']:.0f} % | "
            f"{'met' if t['met'] else 'not met'} |")
