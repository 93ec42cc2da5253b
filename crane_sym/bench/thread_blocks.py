"""``crane-sym bench --parallel`` (and ``--sweep``, section (f)): both cores
on a NumPy-bound batched output (issue 39, item 2).

The case's grid of 9·10⁴ designs in the blocks a local sweep cuts it into
(:func:`crane_sym.sweep.blocks.chunks_for`), swept by Dask's threads
(nothing written) against the same blocks one after the other in this
process without Dask (the control): parallel efficiency T₁/(2·T₂), target
70 %. On a shared 2-core machine another job on the second core takes the
efficiency with it, so the sweep, its control and the machine's controls
(np.sin, np.copyto, np.add on one and two threads:
:func:`crane_sym.bench.roofline.control_trials`) are timed in the same
interleaved rounds (:mod:`crane_sym.bench.interleaved`), N of them; the
efficiency is given from the minimum times, with its median and range over
the rounds, and also relative to np.sin's in the same rounds: what the sweep
made of what this machine gave np.sin at that moment.
"""
from __future__ import annotations

import contextlib
import functools
from concurrent.futures import ThreadPoolExecutor
from typing import Any, Sequence

import numpy as np

from crane_sym.bench.batched import _grid
from crane_sym.bench.cases import BatchedBenchCase
from crane_sym.bench.interleaved import Rounds, Trial, efficiency, run_rounds
from crane_sym.bench.roofline import control_trials, fit_serial, roofline
from crane_sym.sweep.blocks import first_axis
from crane_sym.sweep.compute import compute_local, warm_pool
from crane_sym.sweep.grid import chunks_for, evaluate_block, grid_arrays, run_sweep
from crane_sym.sweep.summaries import summaries

__all__ = ["DESIGNS", "EFFICIENCY", "ROUNDS", "VARIANTS", "markdown_row", "relative",
           "thread_row", "variant_rows"]

#: Designs of the row (a square grid), the target, and the interleaved rounds.
DESIGNS = 90_000
EFFICIENCY = 0.70
ROUNDS = 3
#: The trials of the sweep as it runs: its control and Dask's threads.
ALONE, THREADS = "sweep, no Dask", "sweep, Dask's threads"
#: The changes tried (item 2), timed in the same rounds: (trial, blocks, Dask's
#: local scheduler); blocks None are the local sweep's, a scheduler None the
#: blocks one after the other without Dask; processes run on a warm pool
#: (started, imports and a first block done, before the rounds).
VARIANTS = (("6 blocks, no Dask", 6, None),
            ("6 blocks, Dask's threads", 6, "threads"),
            ("the sweep's blocks, Dask's processes (warm pool)", None, "processes"))


def _parts(axes: list[np.ndarray], chunks) -> list[list[np.ndarray]]:
    """Each block's axis values, in the grid's block order."""
    starts = [np.cumsum((0,) + c) for c in chunks]
    return [[a[s[i]:s[i + 1]] for a, s, i in zip(axes, starts, ix)]
            for ix in np.ndindex(*[len(c) for c in chunks])]


def _worst(blocks: list[np.ndarray]) -> float:
    return max(float(np.nanmax(b)) for b in blocks)


def relative(sweep: dict[str, Any], sin: dict[str, Any]) -> dict[str, float]:
    """The sweep's efficiency over np.sin's at the same moment: from the
    minima, and round by round (median, low, high).

    Parameters
    ----------
    sweep : dict
        :func:`crane_sym.bench.interleaved.efficiency` of the sweep.
    sin : dict
        The np.sin control of :func:`crane_sym.bench.roofline.roofline`.

    >>> r = relative({"least": 0.6, "rounds": [0.6, 0.4]},
    ...              {"efficiency": 0.8, "efficiency_rounds": [0.8, 0.5]})
    >>> round(r["least"], 2), round(r["low"], 2), round(r["high"], 2)
    (0.75, 0.75, 0.8)
    """
    each = np.array(sweep["rounds"]) / np.array(sin["efficiency_rounds"])
    return {"least": sweep["least"] / sin["efficiency"], "median": float(np.median(each)),
            "low": float(each.min()), "high": float(each.max())}


def thread_row(case: BatchedBenchCase, designs: int = DESIGNS, rounds: int = ROUNDS,
               elements: int | None = None,
               variants: Sequence[tuple[str, int | None, str | None]] = VARIANTS
               ) -> dict[str, Any]:
    """The case's grid of ``designs`` (a square) by Dask's threads in the
    local sweep's blocks against the same blocks without Dask, and the
    controls, in ``rounds`` interleaved rounds.

    Parameters
    ----------
    case : BatchedBenchCase
        The batched case marked for the targets.
    designs : int
        Designs of its grid (rounded to a square).
    rounds : int
        Interleaved rounds (N).
    elements : int, optional
        Elements of the controls' arrays (default: the roofline's).
    variants : sequence of (str, int or None, str or None)
        The changes timed beside the sweep (:data:`VARIANTS`).
    """
    n = int(round(designs ** (1 / len(case.axes))))
    chosen, spec, names, axes = _grid(case, n)
    call = (chosen.derivation, case.output, spec.kind, spec.args, names, dict(chosen.fixed),
            dict(chosen.options))
    chunks = chunks_for(chosen, workers=2)
    parts = _parts(axes, chunks)
    worsts: dict[str, float] = {}
    found: list = []
    sized = {} if elements is None else {"elements": elements}

    def alone(name: str, blocks: list) -> Trial:
        return Trial(name, lambda: worsts.__setitem__(
            name, _worst([evaluate_block(*call, *p) for p in blocks])))

    def on_dask(name: str, cut, local: str, pool) -> Trial:
        grid = grid_arrays(chosen, cut)
        return Trial(name, lambda: worsts.__setitem__(name, compute_local(
            lambda kept: summaries(chosen, grid, cut), local, True, False, pool=pool)[0][0]), 2)
    warm = functools.partial(evaluate_block, *call, *[a[:2] for a in axes])
    wanted = any(local == "processes" for _, _, local in variants)
    with ThreadPoolExecutor(2) as threads, \
            warm_pool("processes", warm) if wanted else contextlib.nullcontext() as processes:
        trials = [alone(ALONE, parts),
                  Trial(THREADS, lambda: found.append(run_sweep(chosen, None,
                                                                scheduler="threads")), 2)]
        for name, count, local in variants:
            cut = chunks if count is None else first_axis(chosen.shape, count)
            trials.append(alone(name, _parts(axes, cut)) if local is None else
                          on_dask(name, cut, local, processes if local == "processes"
                                  else None))
        trials += control_trials(threads, **sized)
        measured = run_rounds(trials, rounds)
    roof = roofline(measured, **sized)
    sweep = efficiency(measured, ALONE, THREADS)
    result = found[-1]
    worsts[THREADS] = result.worst[case.output][0]
    return {"output": case.output, "designs": chosen.points, "blocks": len(parts),
            "block_designs": [int(np.prod([len(a) for a in p])) for p in parts],
            "sweep_blocks": result.blocks, "scheduler": result.scheduler,
            "rounds": measured.count, "loads": list(measured.loads),
            "no_dask_seconds": measured.least(ALONE),
            "no_dask_median": measured.median(ALONE),
            "no_dask_cores": float(np.median(measured.cores[ALONE])),
            "dask_seconds": measured.least(THREADS), "dask_median": measured.median(THREADS),
            "dask_cores": float(np.median(measured.cores[THREADS])),
            "sweep": sweep, "efficiency": sweep["least"], "target": EFFICIENCY,
            "met": sweep["least"] >= EFFICIENCY, "relative": relative(sweep, roof["sin"]),
            "roofline": roof, "fit": fit_serial(sweep, roof),
            "variants": _variants(measured, [t for t in trials if t.name in worsts], roof),
            "same_worst": len(set(worsts.values())) == 1}


def _variants(measured: Rounds, trials: list[Trial], roof: dict[str, Any]) -> list[dict]:
    """Each sweep trial against the no-Dask control of the sweep's blocks:
    T₁/(p·T) from the minima and over the rounds (p its workers), and for
    two workers that efficiency over np.sin's in the same rounds."""
    rows = []
    for t in trials:
        least, each = measured.ratio(ALONE, t.name, t.workers)
        row = {"trial": t.name, "workers": t.workers, "least_s": measured.least(t.name),
               "median_s": measured.median(t.name), "ratio": least,
               "low": float(each.min()), "high": float(each.max())}
        if t.workers == 2:
            row["relative"] = relative({"least": least, "rounds": list(each)}, roof["sin"])
        rows.append(row)
    return rows


def markdown_row(t: dict[str, Any]) -> str:
    """The row of the target: the efficiency from the minima (median and
    range over the rounds), and relative to np.sin's in the same rounds."""
    s, rel = t["sweep"], t["relative"]
    sin = t["roofline"]["sin"]
    return (f"| {t['designs']} designs of {t['output']} on 2 threads ({t['blocks']} blocks of "
            f"{', '.join(str(d) for d in t['block_designs'])}, Dask's {t['scheduler']}) "
            f"against the same blocks one after the other without Dask; {t['rounds']} "
            f"interleaved rounds with the controls, load {min(t['loads']):.1f}–"
            f"{max(t['loads']):.1f} | efficiency {100 * s['least']:.0f} % from the minima "
            f"({t['no_dask_seconds']:.2f} s → {t['dask_seconds']:.2f} s; medians "
            f"{t['no_dask_median']:.2f} s → {t['dask_median']:.2f} s; rounds "
            f"{100 * s['low']:.0f}–{100 * s['high']:.0f} %, median {100 * s['median']:.0f} %; "
            f"the process got {t['dask_cores']:.2f} cores); np.sin control "
            f"{100 * sin['efficiency']:.0f} % in the same rounds, so the sweep made "
            f"{100 * rel['least']:.0f} % of what this machine gave np.sin at that moment "
            f"(rounds {100 * rel['low']:.0f}–{100 * rel['high']:.0f} %, median "
            f"{100 * rel['median']:.0f} %); same worst: {t['same_worst']} | "
            f"≥ {100 * t['target']:.0f} % | {'met' if t['met'] else 'not met'} |")


def variant_rows(t: dict[str, Any]) -> list[str]:
    """What each change gave (item 2): every sweep trial of the same rounds
    against the no-Dask control of the sweep's blocks."""
    lines = ["", f"What each change gave: every sweep of the {t['designs']} designs timed in "
             f"the same {t['rounds']} interleaved rounds (load {min(t['loads']):.1f}–"
             f"{max(t['loads']):.1f}), against the sweep's {t['blocks']} blocks one after "
             "the other without Dask (T₁); T₁/(p·T) from the minima, its range over the "
             "rounds; on two workers also over np.sin's efficiency in the same rounds.", "",
             "| sweep | workers | min [s] | median [s] | T₁/(p·T) (rounds) | of np.sin's |",
             "| --- | --- | --- | --- | --- | --- |"]
    for v in t["variants"]:
        rel = v.get("relative")
        lines.append(f"| {v['trial']} | {v['workers']} | {v['least_s']:.2f} | "
                     f"{v['median_s']:.2f} | {100 * v['ratio']:.0f} % ({100 * v['low']:.0f}–"
                     f"{100 * v['high']:.0f} %) | "
                     + ("—" if rel is None else f"{100 * rel['least']:.0f} % "
                        f"({100 * rel['low']:.0f}–{100 * rel['high']:.0f} %)") + " |")
    return lines
