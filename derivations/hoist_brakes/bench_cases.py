"""Bench cases of paper 001 (``crane_sym.bench.cases``).

- Batched: the Fig. 9 emergency stop's peak |M_G/M_st|
  (``peak_elastic_gearbox_torque``) over the gearbox stiffness c and the
  coupling backlash δ of scene ``hoist_table1``, 100 × 100 designs solved as one
  block by the batched solver, against the per-design loop on a sample.
"""
from __future__ import annotations

import time

import numpy as np

from crane_sym.bench.cases import BatchedBenchCase

from .elastic_batched import family_from
from .sweep_outputs import peak_per_design


def _breakdown(plan, axes) -> dict[str, float]:
    """Where the batched solver's time goes on the grid (a second run, CPU seconds)."""
    names = [a.name for a in plan.axes]
    grid = np.meshgrid(*axes, indexing="ij")
    q = {**plan.fixed, **dict(zip(names, grid))}
    start = time.process_time()
    result = family_from(q, plan.options["duration"]).peaks()
    out = dict(result.seconds)
    out["total"] = time.process_time() - start
    return out


def _run(values, options, i: int):
    """Design ``i`` of the grid's flat values as the per-design run."""
    return family_from(values, options["duration"]).run(i)


BATCHED_BENCH_CASES = (
    BatchedBenchCase("peak_elastic_gearbox_torque", "hoist_table1",
                     ("c=1e4:1e5:{n}:log", "delta=0.5:3:{n}"), peak_per_design, n=100, sample=24,
                     breakdown=_breakdown, run=_run, targets=True),
)
