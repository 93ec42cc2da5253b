"""How a sweep's grid is cut into blocks, and which local scheduler runs them.

Closed forms: blocks by bytes, on threads (NumPy ufuncs release the GIL).
Simulated outputs solved one design at a time: several small blocks a
worker, on processes (their Python holds the GIL). Outputs that solve a
block's designs together (``SweepOutput.batched``) come in two kinds, by the
output's ``threads`` flag:

- NumPy-bound (``SweepOutput.threads``: 001's emergency stop; 003's start-up
  where only its links' stiffness and damping are swept): its time is in
  array calls, and a block's Python per phase is paid once for all its
  designs, so blocks are few and large (``SweepOutput.thread_block``: 001
  at least :data:`THREAD_DESIGNS` designs, at most
  :data:`THREAD_MAX_DESIGNS`, ~6 kB a design while it runs; 003 2 500 to
  10 000, ~50 kB a design) and run on threads, which share them without
  pickling. Their parallel efficiency on two threads is measured by
  ``crane-sym bench --parallel`` (the README quotes its run), not kept here.
- Python-bound (003's start-up with other values swept, each design
  assembled; a component file's designs: its event search makes many small
  NumPy calls, and two threads took as long as one block, measured): one
  block per worker, at most :data:`BATCH_DESIGNS` designs, on processes; a
  grid of at most that many is one block in this process (worker processes
  take ~3 s to start).
"""
from __future__ import annotations

import math
import os

import numpy as np

from crane_sym import registry
from crane_sym.sweep.plan import SweepPlan

__all__ = ["BATCH_DESIGNS", "CHUNK_BYTES", "THREAD_DESIGNS", "THREAD_MAX_DESIGNS",
           "batched", "chunks_for", "first_axis", "local_scheduler", "thread_block",
           "threaded"]

#: Bytes of float64 output per block of the grid (closed forms).
CHUNK_BYTES = 8 * 2**20
#: The most designs in a block of a Python-bound batched output: its memory
#: grows with the designs of a block.
BATCH_DESIGNS = 10_000
#: The fewest designs in a block of a NumPy-bound batched output (unless the
#: grid has fewer), and the most: 2 blocks of 5·10⁴ run side by side hold ~0.6 GB.
THREAD_DESIGNS = 40_000
THREAD_MAX_DESIGNS = 50_000


def threaded(plan: SweepPlan) -> bool:
    """True where every simulated output of ``plan`` is a NumPy-bound batched
    one for the parameters it sweeps (``SweepOutput.threads``: True, or a
    tuple holding every swept name): its blocks run on threads.

    Parameters
    ----------
    plan : SweepPlan
        The checked sweep.
    """
    simulated = [o for o in plan.outputs if o.kind != "closed"]
    if not simulated or any(o.kind == "component" for o in simulated):
        return False
    specs = registry.sweep_outputs(plan.derivation)
    swept = {a.name for a in plan.axes}
    return all(_on_threads(getattr(specs.get(o.name), "threads", False), swept)
               for o in simulated)


def batched(plan: SweepPlan) -> bool:
    """True where ``plan`` has simulated outputs and each solves a block's
    designs together (a component file's; ``SweepOutput.batched``).

    Parameters
    ----------
    plan : SweepPlan
        The checked sweep.
    """
    simulated = [o for o in plan.outputs if o.kind != "closed"]
    if not simulated:
        return False
    specs = ({} if all(o.kind == "component" for o in simulated)
             else registry.sweep_outputs(plan.derivation))
    return all(o.kind == "component" or getattr(specs.get(o.name), "batched", False)
               for o in simulated)


def _on_threads(threads: bool | tuple[str, ...], swept: set[str]) -> bool:
    return threads is True or (isinstance(threads, tuple) and swept <= set(threads))


def thread_block(plan: SweepPlan) -> tuple[int, int]:
    """(fewest, most) designs of a block on threads for ``plan``'s simulated
    outputs (``SweepOutput.thread_block``; the tightest where there are
    several; :data:`THREAD_DESIGNS`, :data:`THREAD_MAX_DESIGNS` where none is
    declared).

    Parameters
    ----------
    plan : SweepPlan
        The checked sweep.
    """
    specs = registry.sweep_outputs(plan.derivation)
    bounds = [getattr(specs.get(o.name), "thread_block", None) or
              (THREAD_DESIGNS, THREAD_MAX_DESIGNS)
              for o in plan.outputs if o.kind != "closed"]
    fewest = max((b[0] for b in bounds), default=THREAD_DESIGNS)
    return fewest, max(fewest, min((b[1] for b in bounds), default=THREAD_MAX_DESIGNS))


def chunks_for(plan: SweepPlan, chunk_bytes: int = CHUNK_BYTES,
               workers: int | None = None) -> tuple[tuple[int, ...], ...]:
    """Chunks of the grid (see the module docstring): by bytes for closed
    forms; for simulated outputs small enough to give every worker several
    blocks; for a Python-bound batched output one block per worker, at most
    :data:`BATCH_DESIGNS` designs, and on the local machine (``workers`` not
    given) a grid of at most that many one block; for a NumPy-bound one
    (:func:`threaded`) blocks of :func:`thread_block` designs, cut along the
    first axis.

    Parameters
    ----------
    plan : SweepPlan
        The checked sweep.
    chunk_bytes : int, optional
        Size of a block of a closed form.
    workers : int, optional
        Workers to share the blocks (default: the cores).
    """
    from dask.array.core import normalize_chunks
    simulated = [o for o in plan.outputs if o.kind != "closed"]
    if not simulated:
        return normalize_chunks("auto", plan.shape, limit=chunk_bytes, dtype=np.float64)
    local = workers is None
    workers = workers or os.cpu_count() or 1
    if threaded(plan):
        return _rows(plan, workers)
    if batched(plan):
        designs = (plan.points if local and plan.points <= BATCH_DESIGNS
                   else min(BATCH_DESIGNS, math.ceil(plan.points / workers)))
    else:
        designs = math.ceil(plan.points / (4 * workers))
    chunk_bytes = max(8, min(chunk_bytes, 8 * designs))
    return normalize_chunks("auto", plan.shape, limit=chunk_bytes, dtype=np.float64)


def _rows(plan: SweepPlan, workers: int) -> tuple[tuple[int, ...], ...]:
    """Blocks of a NumPy-bound batched output (:func:`thread_block`: fewest
    and most designs): as many as it takes to stay within the most, at least
    one per worker where each still holds the fewest, never one below that
    (unless the grid is); the first axis cut into near-equal runs (the rest
    whole), or, where one run of the first axis alone holds more than the
    most, every axis cut by size (a block's memory grows with its designs)."""
    from dask.array.core import normalize_chunks
    fewest, most = thread_block(plan)
    points = plan.points
    row = points // plan.shape[0]                # designs a row of the first axis
    if row > most:
        return normalize_chunks("auto", plan.shape, limit=8 * most, dtype=np.float64)
    count = max(math.ceil(plan.shape[0] / (most // row)), min(workers, points // fewest))
    return first_axis(plan.shape, max(1, min(count, points // fewest)))


def first_axis(shape: tuple[int, ...], count: int) -> tuple[tuple[int, ...], ...]:
    """Chunks of a grid of ``shape`` in ``count`` blocks (at most one a row
    of the first axis): the first axis cut into near-equal runs, the rest
    whole.

    Parameters
    ----------
    shape : tuple of int
        The grid's shape.
    count : int
        Blocks wanted.

    >>> first_axis((10, 3), 3)
    ((3, 4, 3), (3,))
    """
    count = max(1, min(count, shape[0]))
    edges = np.linspace(0, shape[0], count + 1).round().astype(int)
    return (tuple(int(d) for d in np.diff(edges)),) + tuple((n,) for n in shape[1:])


def local_scheduler(plan: SweepPlan, chunks) -> str:
    """Dask's local scheduler for the sweep when none is named: closed forms
    on threads; a simulated grid of one block in this process (synchronous),
    as a component file's sweep (its blocks are kept in the process);
    NumPy-bound batched outputs on threads; any other on processes.

    Parameters
    ----------
    plan : SweepPlan
        The checked sweep.
    chunks : tuple of tuple of int
        Its blocks (:func:`chunks_for`).
    """
    kinds = {o.kind for o in plan.outputs}
    if kinds == {"closed"}:
        return "threads"
    if kinds == {"component"} or all(len(c) == 1 for c in chunks):
        return "synchronous"
    return "threads" if threaded(plan) else "processes"
