"""A design sweep's reductions, block by block: per output the worst value,
its place in the grid, the designs within the limit and the designs without a
value (NaN: a hybrid run stopped at its output's cap), combined over the
blocks in the same pass that writes them (:func:`crane_sym.sweep.grid.run_sweep`).
"""
from __future__ import annotations

from typing import Any

import numpy as np

from crane_sym.sweep.plan import SweepPlan

__all__ = ["summaries"]


def _block_summary(block: np.ndarray, offsets: tuple[int, ...], shape: tuple[int, ...],
                   worst_is_max: bool, bound: float | None, op: str) -> tuple:
    """(worst value, its flat index in the grid, designs within the limit,
    designs without a value: NaN, a run stopped at its output's cap). The
    worst is taken over the designs with a value (NaN, -1 if none)."""
    missing = np.isnan(block)
    gaps = int(np.count_nonzero(missing))
    if gaps == block.size:
        return float("nan"), -1, -1 if bound is None else 0, gaps
    if gaps:
        fill = -np.inf if worst_is_max else np.inf
        k = int(np.argmax(np.where(missing, fill, block)) if worst_is_max
                else np.argmin(np.where(missing, fill, block)))
    else:
        k = int(np.argmax(block) if worst_is_max else np.argmin(block))
    local = np.unravel_index(k, block.shape)
    flat = int(np.ravel_multi_index(tuple(o + i for o, i in zip(offsets, local)), shape))
    within = -1 if bound is None else int(np.count_nonzero(
        block <= bound if op == "<=" else block >= bound))
    return float(block[local]), flat, within, gaps


def _combine(parts: list[tuple], worst_is_max: bool) -> tuple:
    """The grid's worst of the blocks' worsts (first in grid order on a tie),
    over the blocks with a value; the counts summed."""
    pick = max if worst_is_max else min
    valued = [p for p in parts if p[1] >= 0]
    gaps = sum(p[3] for p in parts)
    within = sum(max(p[2], 0) for p in parts) if any(p[2] >= 0 for p in parts) else -1
    if not valued:
        return float("nan"), 0, within, gaps
    value = pick(p[0] for p in valued)
    flat = min(p[1] for p in valued if p[0] == value)
    return value, flat, within, gaps


def summaries(plan: SweepPlan, arrays: dict[str, Any], chunks) -> list:
    """Per output, the delayed (worst value, its flat index, designs within
    the limit, designs without a value) of the whole grid, from the blocks'
    summaries.

    Parameters
    ----------
    plan : SweepPlan
        The checked sweep.
    arrays : dict
        Output name -> the grid's dask array.
    chunks : tuple of tuple of int
        The grid's chunks.
    """
    import dask
    starts = [np.cumsum((0,) + c[:-1]) for c in chunks]
    limit = plan.limit
    tasks = []
    for o in plan.outputs:
        worst_is_max = not (limit is not None and limit.output == o.name and limit.op == ">=")
        bound = limit.si if limit is not None and limit.output == o.name else None
        blocks = arrays[o.name].to_delayed()
        parts = [dask.delayed(_block_summary)(blocks[ix], tuple(int(s[i]) for s, i in
                                                                  zip(starts, ix)),
                                              plan.shape, worst_is_max, bound,
                                              limit.op if bound is not None else "")
                 for ix in np.ndindex(blocks.shape)]
        tasks.append(dask.delayed(_combine)(parts, worst_is_max))
    return tasks
