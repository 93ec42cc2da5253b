"""What a sweep will cost, from a timed pilot, before it starts.

A grid of 10⁶ designs of a component file is one command line away, and each
design is a run of its own: the sweep must say what it will take, and refuse
beyond ``--time-limit``, before any block is computed. The estimate is
measured, not modelled: every output is evaluated on a small pilot block of
the grid (:data:`PILOT_DESIGNS` designs, strided along the axes) by the same
function the sweep's blocks run, once to warm up (a component file derives
its template, a paper's module is imported) and once timed; the time per
design, times the designs, over the workers that will share them (no more
than the sweep's blocks), plus the warm-up each worker pays once, is the
time printed. An output that solves a block's designs together
(``SweepOutput.batched``, a component file) costs a fixed time a block and
less a design the larger the block (003's start-up: 0.85 ms a design in a
block of 100, 0.31 ms in one of 10⁴), so its pilot is timed at two sizes
(:data:`PILOT_DESIGNS` and :data:`BATCH_PILOT`, at most an eighth of the
grid; a grid under 512 designs, the first alone): the difference gives the
time a design, the rest the time a block, and the sweep's blocks
(``blocks.chunks_for``) are counted on the workers that run them, as if side
by side at full speed. Where a block's cost grows ever more slowly with its
designs (its Python paid once a phase: a component file's), the line through
the two pilots lies above it beyond them, so the estimate errs high. The
pilot solves its blocks afresh (``cached=False``): a block a sweep before it
solved in the process would be a look-up, and the estimate a fraction of the
sweep's time.
Memory: the results held
(8 bytes a design and output; a simulated output's blocks are kept for the
summary, the PNG and the store) and one block of values per worker.
"""
from __future__ import annotations

import math
import os
import time
from dataclasses import dataclass

import numpy as np

from crane_sym.sweep.blocks import batched, chunks_for
from crane_sym.sweep.grid import CHUNK_BYTES, evaluate_block
from crane_sym.sweep.plan import SweepError, SweepPlan

__all__ = ["BATCH_PILOT", "PILOT_DESIGNS", "Estimate", "check_estimate", "estimate"]

#: Designs in the timed pilot block (a closed form: 64 times as many).
PILOT_DESIGNS = 16
#: Designs of the second, larger pilot block of a batched output.
BATCH_PILOT = 1024


@dataclass(frozen=True)
class Estimate:
    """A sweep's estimated cost: ``seconds`` on ``workers``, ``bytes`` of
    memory, from a pilot of ``pilot`` designs per output timed at
    ``per_design`` seconds each (after a warm-up of ``warmup`` seconds);
    for a batched output also ``per_block`` seconds a block, from a second
    pilot of ``second`` designs."""

    designs: int
    outputs: int
    workers: int
    seconds: float
    bytes: int
    pilot: int
    per_design: float
    warmup: float
    per_block: float = 0.0
    second: int = 0

    def pilots(self) -> str:
        """What was timed: one pilot, or a batched output's two."""
        return (f"timed pilots of {self.pilot} and {self.second} designs" if self.second
                else f"a timed pilot of {self.pilot} designs")

    def line(self) -> str:
        """The estimate as the command prints it before the sweep starts."""
        pilot = f"{self.pilots()}: {self.per_design:.3g} s a design" + (
            f", {self.per_block:.3g} s a block" if self.second else "")
        return (f"estimate: {self.designs:.3g} designs x {self.outputs} output(s) on "
                f"{self.workers} worker(s): about {self.seconds:.3g} s and "
                f"{self.bytes / 2**20:.3g} MiB ({pilot}, {self.warmup:.3g} s to start)")


def _pilot_blocks(plan: SweepPlan, designs: int) -> list[np.ndarray]:
    """A block of at most ``designs`` designs, strided along each axis (SI)."""
    per_axis = max(1, int(designs ** (1 / len(plan.axes))))
    blocks = []
    for a in plan.axes:
        values = a.si()
        take = min(per_axis, len(values))
        blocks.append(values[np.linspace(0, len(values) - 1, take).round().astype(int)])
    return blocks


def estimate(plan: SweepPlan, chunk_bytes: int = CHUNK_BYTES) -> Estimate:
    """The sweep's time and memory from a timed pilot block (module docstring).

    Parameters
    ----------
    plan : SweepPlan
        The checked sweep.
    chunk_bytes : int, optional
        Size of a block of a closed form (``--chunk-mib``).
    """
    kinds = {o.kind for o in plan.outputs}
    count = math.prod(len(c) for c in chunks_for(plan, chunk_bytes))
    # a component file's blocks stay in this process; no more workers than blocks
    workers = 1 if kinds == {"component"} else min(os.cpu_count() or 1, count)
    size = PILOT_DESIGNS * (64 if kinds == {"closed"} else 1)
    blocks = _pilot_blocks(plan, size)
    pilot = math.prod(len(b) for b in blocks)
    larger = _pilot_blocks(plan, min(BATCH_PILOT, plan.points // 8)) if batched(plan) else blocks
    second = math.prod(len(b) for b in larger)
    two = second >= 4 * pilot                     # a block's cost and a design's
    names = tuple(a.name for a in plan.axes)
    warmup = per_design = per_block = 0.0
    for o in plan.outputs:
        run = lambda bs: evaluate_block(plan.derivation, o.name, o.kind, o.args,  # noqa: E731
                                        names, dict(plan.fixed), dict(plan.options), *bs,
                                        cached=False)         # timed, never looked up
        start = time.perf_counter()
        run([b[:1] for b in blocks])
        warmup += time.perf_counter() - start
        small = _seconds(run, blocks)
        if two:
            slope = max(0.0, (_seconds(run, larger) - small) / (second - pilot))
            per_design += slope
            per_block += max(0.0, small - slope * pilot)
        else:
            per_design += small / pilot
    n = plan.points
    seconds = warmup + (per_block * count + per_design * n) / workers
    held = 8 * n * len(plan.outputs) * (2 if kinds != {"closed"} else 1)
    return Estimate(n, len(plan.outputs), workers, seconds, held + workers * chunk_bytes,
                    pilot, per_design, warmup, per_block, second if two else 0)


def _seconds(run, blocks: list[np.ndarray]) -> float:
    start = time.perf_counter()
    run(blocks)
    return time.perf_counter() - start


def check_estimate(found: Estimate, time_limit: float) -> None:
    """SweepError naming ``--time-limit`` when the estimate passes it, and
    naming the memory when it passes what is free; nothing is computed.

    Parameters
    ----------
    found : Estimate
        From :func:`estimate`.
    time_limit : float
        ``--time-limit``, seconds.
    """
    if found.seconds > time_limit:
        raise SweepError(f"--time-limit {time_limit:g}: the sweep of {found.designs:.3g} designs "
                         f"would take about {found.seconds:.3g} s ({found.pilots()}); "
                         "give fewer designs or a larger limit")
    import psutil
    free = psutil.virtual_memory().available
    if found.bytes > free:
        raise SweepError(f"the sweep of {found.designs:.3g} designs would hold about "
                         f"{found.bytes / 2**30:.3g} GiB, only {free / 2**30:.3g} GiB are free")
