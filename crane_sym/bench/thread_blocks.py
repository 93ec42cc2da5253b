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

from concurrent.futures import ThreadPoolExecutor
from typing import Any

import numpy as np

from crane_sym.bench.batched import _grid
from crane_sym.bench.cases import BatchedBenchCase
from crane_sym.bench.interleaved import Trial, efficiency, run_rounds
from crane_sym.bench.roofline import control_trials, fit_serial, roofline
from crane_sym.sweep.grid import chunks_for, evaluate_block, run_sweep

__all__ = ["DESIGNS", "EFFICIENCY", "ROUNDS", "markdown_row", "relative", "thread_row"]

#: Designs of the row (a square grid), the target, and the interleaved rounds.
DESIGNS = 90_000
EFFICIENCY = 0.70
ROUNDS = 5
#: The trials of the sweep: its control and Dask's threads.
ALONE, THREADS = "sweep, no Dask", "sweep, Dask's threads"


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
               elements: int | None = None) -> dict[str, Any]:
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
    """
    n = int(round(designs ** (1 / len(case.axes))))
    chosen, spec, names, axes = _grid(case, n)
    call = (chosen.derivation, case.output, spec.kind, spec.args, names, dict(chosen.fixed),
            dict(chosen.options))
    chunks = chunks_for(chosen, workers=2)
    starts = [np.cumsum((0,) + c) for c in chunks]
    parts = [[a[s[i]:s[i + 1]] for a, s, i in zip(axes, starts, ix)]
             for ix in np.ndindex(*[len(c) for c in chunks])]
    kept: list[np.ndarray] = []
    found: list = []
    sized = {} if elements is None else {"elements": elements}
    with ThreadPoolExecutor(2) as pool:
        trials = [Trial(ALONE, lambda: kept.__setitem__(
                      slice(None), [evaluate_block(*call, *p) for p in parts])),
                  Trial(THREADS, lambda: found.append(run_sweep(chosen, None,
                                                                scheduler="threads")), 2),
                  *control_trials(pool, **sized)]
        measured = run_rounds(trials, rounds)
    roof = roofline(measured, **sized)
    sweep = efficiency(measured, ALONE, THREADS)
    result = found[-1]
    worst = max(float(np.nanmax(b)) for b in kept)
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
            "same_worst": worst == result.worst[case.output][0]}


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
