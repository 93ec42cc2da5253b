"""Design sweeps on Dask: a chunked grid of designs, evaluated block-wise.

A :class:`crane_sym.sweep.spec.SweepPlan` names the axes (SI arrays, one per
swept parameter) and the outputs. Each axis becomes a one-dimensional
``dask.array`` in chunks chosen by bytes (:data:`CHUNK_BYTES` of float64 per
block of the grid); ``dask.array.blockwise`` hands every block of the outer
product to :func:`evaluate_block`, which calls the paper's generated NumPy
function with the block's axis values shaped to broadcast (one call per block,
the fixed values as scalars), or, for a simulated response, the paper's
``SweepOutput.evaluate`` (one integration per design). Nothing holds the grid:
each block is written to Zarr (through xarray, into a temporary of a
:func:`crane_sym.sweep.store.sweep_stage`, renamed with the PNG at the end)
and reduced to its worst value, the flat index of that value, the count
within the limit and its share of the PNG's data (:func:`strided`), in the
same pass, so memory is bounded by the chunk size times the number of
workers, not by the grid. How the graph runs, and is stopped on a failure or
signal before the temporary is removed, is :mod:`crane_sym.sweep.compute`.

Schedulers: with none named, Dask's local scheduler. Threads for the
closed forms: the generated functions spend their time in NumPy ufuncs, which
release the GIL, and threads share the blocks without pickling (measured on
this 2-core machine, 10⁸ designs of ``peak_elastic_force`` in 100 blocks:
threads 0.86 s, processes 8.7 s without writing; 3.8 s and 7.9 s with the
Zarr store; the difference is the blocks' transfer between processes).
Processes for the simulated responses: one SciPy integration per design runs
Python code that holds the GIL, so threads never pass one core (measured: 0.98
CPU seconds per wall second with two threads). On this shared machine the
measurement did not favour them (Martyntsiv et al.'s drum, 24 designs: threads 11.2 s, processes
14.1 s, synchronous 11.1 s at load ≈ 3 on 2 cores): starting two worker
processes costs ~3 s and the second core was busy; they are kept for large
simulated sweeps on a machine with free cores, the case they serve. A
NumPy-bound batched output (``SweepOutput.threads``) runs on threads, in few
large blocks (:mod:`crane_sym.sweep.blocks`). A component file's outputs run synchronously: a block asked for three times is
solved once in the process (:mod:`crane_sym.components.designs`). With
``scheduler=ADDRESS`` a ``dask.distributed`` scheduler runs the same graph
(its workers must see ``out``: a shared file system, or one machine).
"""
from __future__ import annotations

import contextlib
import functools
import importlib
import math
import shutil
import time
import warnings
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np

from crane_sym import registry
from crane_sym.output_files import Stage
from crane_sym.sweep.blocks import BATCH_DESIGNS, CHUNK_BYTES, chunks_for, local_scheduler
from crane_sym.sweep.compute import (compute_local, compute_remote, connect,
                                     cycles_collected_after, scheduler_lost)
from crane_sym.sweep.dataset import dataset, sweep_id
from crane_sym.sweep.plan import SweepError, SweepPlan
from crane_sym.sweep.store import deferred_signals, remove_settled, sweep_stage
from crane_sym.sweep.summaries import summaries

__all__ = ["BATCH_DESIGNS", "CHUNK_BYTES", "MAX_BLOCKS", "MAX_PLOT", "SweepResult", "check_grid",
           "chunks_for", "connect", "evaluate_block", "grid_arrays", "plotted", "run_sweep",
           "scheduler_lost", "strided", "sweep_id"]

#: The most blocks (all outputs together) a sweep plans: Dask keeps a few
#: tasks per block in memory and spends ~0.1 ms a task.
MAX_BLOCKS = 100_000
#: The most values per axis the PNG draws (a larger axis is strided).
MAX_PLOT = 1000
#: Free disk space kept in reserve beyond the dataset's size (bytes).
_RESERVE = 64 * 2**20


def evaluate_block(derivation: str, output: str, kind: str, args: tuple[str, ...],
                   axis_names: tuple[str, ...], fixed: dict[str, float],
                   options: dict[str, float], *blocks: np.ndarray,
                   cached: bool = True) -> np.ndarray:
    """One block of the grid: ``output`` at the outer product of the axis
    blocks (SI), every other argument from ``fixed``. Looks the function up by
    name, so a worker process needs nothing but the installed package.

    Parameters
    ----------
    derivation : str
        The registered derivation id.
    output : str
        The output's name.
    kind : str
        ``"closed"`` (a generated function), ``"simulated"`` (a sweep output)
        or ``"component"`` (an elastic link of a component file, ``options``
        naming the file: :mod:`crane_sym.components.designs`).
    args : tuple of str
        The output's arguments, in order.
    axis_names : tuple of str
        The swept arguments, one per block.
    fixed : dict
        Every other argument's value (SI).
    options : dict
        The scene's settings a simulated output reads (``duration``, ...).
    *blocks : ndarray
        One block of values per axis (SI).
    cached : bool, optional
        False: a component file's block is solved afresh, not handed out from
        the blocks solved before in the process (the estimate's timed pilot).
    """
    n = len(blocks)
    shape = tuple(len(b) for b in blocks)
    grid = {name: np.asarray(b, dtype=float).reshape([-1 if k == i else 1 for k in range(n)])
            for i, (name, b) in enumerate(zip(axis_names, blocks))}
    values = {a: grid[a] if a in grid else fixed[a] for a in args if kind != "component"}
    window = options.get("window")
    if kind == "component":                    # a component file's link, batched
        from crane_sym.components.designs import evaluate_block as component_block
        with cycles_collected_after():
            result = component_block(options["component_file"], options["digest"], output,
                                     grid, cached)
    elif kind == "closed":
        func = getattr(importlib.import_module(f"crane_sym.generated.{derivation}"), output)
        result = func(*[values[a] for a in args])
        if window is not None and window[0] in args:   # the maximum over the window
            for value in window[1][1:]:
                values[window[0]] = value
                result = np.maximum(result, func(*[values[a] for a in args]))
    else:
        spec = registry.sweep_outputs(derivation)[output]
        # a block solved together builds its designs' systems at once; a
        # per-design loop leaves its garbage to the collector as it goes
        with cycles_collected_after() if spec.batched else contextlib.nullcontext():
            result = spec.evaluate(values, options)
    return np.ascontiguousarray(np.broadcast_to(np.asarray(result, dtype=float), shape))


def grid_arrays(plan: SweepPlan, chunks) -> dict[str, Any]:
    """The lazy grid of every output: output name -> dask array of ``plan.shape``.

    Parameters
    ----------
    plan : SweepPlan
        The checked sweep.
    chunks : tuple of tuple of int
        From :func:`chunks_for`.
    """
    import dask.array as da
    from dask.array import PerformanceWarning
    names = tuple(a.name for a in plan.axes)
    axes = [da.from_array(a.si(), chunks=(c,)) for a, c in zip(plan.axes, chunks)]
    index = "abcdefghijklmnopqrstuvwxyz"[:len(axes)]
    pairs = [x for i, ax in enumerate(axes) for x in (ax, index[i])]
    out = {}
    for o in plan.outputs:
        kernel = functools.partial(evaluate_block, plan.derivation, o.name, o.kind, o.args,
                                   names, dict(plan.fixed), dict(plan.options))
        with warnings.catch_warnings():     # an outer product has more blocks than
            warnings.simplefilter("ignore", PerformanceWarning)  # its axes: expected
            out[o.name] = da.blockwise(kernel, index, *pairs, dtype=np.float64)
    return out


@dataclass
class SweepResult:
    """What a sweep found: per output the worst value (SI), its grid index,
    the designs within the limit; timings; the files written."""

    plan: SweepPlan
    chunks: tuple[tuple[int, ...], ...]
    worst: dict[str, tuple[float, tuple[int, ...]]]
    within: int | None
    seconds: float
    scheduler: str
    dataset: Path | None = None
    plot: Path | None = None
    extra: dict[str, Any] = field(default_factory=dict)
    #: The PNG's data (SI), computed with the blocks: :func:`plotted` at the
    #: :func:`strided` first two axes, worst over the others; None if nothing
    #: was written.
    view: np.ndarray | None = None
    #: :func:`sweep_id` of the plan: in the dataset, the PNG and the summary.
    sweep_id: str = ""
    #: Per output, the designs without a value (NaN: a run stopped at the
    #: output's cap, ``SweepOutput.cap``), left out of the worst case.
    capped: dict[str, int] = field(default_factory=dict)

    @property
    def blocks(self) -> int:
        """Blocks of the grid (per output)."""
        return math.prod(len(c) for c in self.chunks)


def check_grid(plan: SweepPlan, out: Path | None, chunk_bytes: int = CHUNK_BYTES) -> None:
    """SweepError naming the option if the grid cannot be planned or held:
    an axis whose values do not fit in memory (``--vary``), a dataset larger
    than the free disk of ``out`` (``--out``), more blocks than
    :data:`MAX_BLOCKS` (``--chunk-mib``). Nothing is computed or written.

    Parameters
    ----------
    plan : SweepPlan
        The checked sweep.
    out : Path or None
        The output folder (None: nothing written).
    chunk_bytes : int, optional
        Size of a block.
    """
    import psutil
    free = psutil.virtual_memory().available
    for a in plan.axes:                        # values, SI, coordinate, Dask copy
        if 32 * a.n > free / 4:
            raise SweepError(f"--vary {a.name}: {a.n:.3g} values need about "
                             f"{32 * a.n / 2**30:.3g} GiB of memory, "
                             f"{free / 2**30:.3g} GiB are available")
    if out is not None:
        need = 8 * plan.points * len(plan.outputs) + _RESERVE
        probe = out
        while not probe.exists():
            probe = probe.parent
        free = shutil.disk_usage(probe).free
        if need > free:
            raise SweepError(f"--out {str(out)!r}: the grid of {plan.points:.3g} designs needs "
                             f"about {need / 2**30:.3g} GiB, only {free / 2**30:.3g} GiB are "
                             "free")
    blocks = math.prod(len(c) for c in chunks_for(plan, chunk_bytes)) * len(plan.outputs)
    if blocks > MAX_BLOCKS:
        raise SweepError(f"--chunk-mib {chunk_bytes / 2**20:.3g}: the grid of {plan.points:.3g} "
                         f"designs makes {blocks:.3g} blocks, more than the {MAX_BLOCKS} "
                         "Dask can plan; give larger blocks or fewer designs")


def strided(n: int) -> slice:
    """Every k-th of ``n`` values, at most :data:`MAX_PLOT` of them."""
    return slice(None, None, max(1, -(-n // MAX_PLOT)))


def plotted(plan: SweepPlan) -> str:
    """The output the PNG shows: the limited one, else the first."""
    return plan.limit.output if plan.limit else plan.outputs[0].name


def _view(plan: SweepPlan, arrays: dict[str, Any]):
    """The PNG's data, as a delayed NumPy array: :func:`plotted` over the
    first two axes (:func:`strided`), its worst over any further axes (SI).
    (Delayed, not a Dask array: ``dask.compute`` of delayed, an array, and
    delayed again returned the results out of order.)"""
    import dask
    field = arrays[plotted(plan)]
    axes = plan.axes
    field = field[tuple(strided(a.n) if i < 2 else slice(None) for i, a in enumerate(axes))]
    if len(axes) > 2:
        others = tuple(range(2, len(axes)))
        worst_max = not (plan.limit and plan.limit.op == ">=")
        field = field.max(axis=others) if worst_max else field.min(axis=others)
    return dask.delayed(np.asarray)(field)


def run_sweep(plan: SweepPlan, out: Path | Stage | None, *, scheduler: str | None = None,
              chunk_bytes: int = CHUNK_BYTES, quiet: bool = True) -> SweepResult:
    """Evaluate the grid, write ``<scene>_sweep.zarr`` into ``out`` (a folder,
    or a :class:`~crane_sym.output_files.Stage` the caller commits with the
    PNG; None: write nothing), and reduce it to the worst case of each output,
    the designs within the limit and the PNG's data, in one pass over the
    blocks.

    ``scheduler``: None for Dask's local scheduler
    (:func:`crane_sym.sweep.blocks.local_scheduler`: threads for closed forms
    and NumPy-bound batched outputs, processes for other simulated responses,
    synchronous for a component file's or a grid of one block), ``"synchronous"``, ``"threads"``, ``"processes"``,
    or the address of a ``dask.distributed`` scheduler.
    On a failure or signal, the tasks that write are stopped (local pools) or
    cancelled and waited for (a live scheduler) before the partial dataset is
    removed; a lost scheduler is a SweepError naming ``--scheduler``.

    Parameters
    ----------
    plan : SweepPlan
        The checked sweep.
    out : Path, Stage or None
        Where the dataset goes.
    scheduler : str, optional
        Which scheduler evaluates the blocks.
    chunk_bytes : int, optional
        Size of a block.
    quiet : bool, optional
        No progress bar.
    """
    if out is not None and not isinstance(out, Stage):
        check_grid(plan, Path(out), chunk_bytes)
        with sweep_stage(Path(out)) as stage:
            return run_sweep(plan, stage, scheduler=scheduler, chunk_bytes=chunk_bytes,
                             quiet=quiet)
    check_grid(plan, None, chunk_bytes)
    client = None
    if scheduler and scheduler not in ("synchronous", "threads", "processes"):
        client = connect(scheduler)
    target = tmp = None
    if out is not None:
        target = out.folder / f"{plan.scene}_sweep.zarr"
        tmp = out.path(target.name)
    try:
        workers = len(client.scheduler_info()["workers"]) if client is not None else None
        chunks = chunks_for(plan, chunk_bytes, workers)
        lazy = grid_arrays(plan, chunks)
        order = [o.name for o in plan.outputs]
        simulated = any(o.kind != "closed" for o in plan.outputs)   # simulated, component

        def tasks(kept: dict[str, Any]) -> list:
            arrays = kept or lazy
            found = summaries(plan, arrays, chunks)
            if tmp is not None:
                found.append(_view(plan, arrays))
                # metadata written here, now; the blocks by the tasks; consolidated
                # below, here again: a worker never writes metadata
                found.append(dataset(plan, arrays).to_zarr(tmp, mode="w-", compute=False,
                                                            zarr_format=2, consolidated=False))
            return found
        # the summaries, the PNG and the Zarr store each read every block, and
        # Dask's graph optimisation renames the blocks' tasks for each: a
        # simulated block is computed once and kept (8 bytes a design)
        once = lazy if simulated and tmp is not None else None
        local = scheduler if client is None else None
        if client is None and local is None:
            local = local_scheduler(plan, chunks)
        # imported before the clock (Dask looks for a distributed client on its
        # first compute): the time printed is the sweep's, not the imports'
        for module in ("distributed",) + (("xarray", "zarr") if tmp is not None else ()):
            importlib.import_module(module)
        start = time.perf_counter()
        if client is not None:
            results = compute_remote(client, tasks, quiet, scheduler, once)
        else:
            results = compute_local(tasks, local, quiet, own_pool=tmp is not None, once=once)
        seconds = time.perf_counter() - start
        if tmp is not None:
            import zarr
            zarr.consolidate_metadata(str(tmp), zarr_format=2)
    except BaseException:
        if tmp is not None:
            # zarr writes from an I/O thread of its own, which a signal does not
            # stop, and a lost scheduler's workers may still write a block:
            # removed until it stays gone
            with deferred_signals():
                remove_settled(tmp, settle=1.0 if client is not None else 0.25)
        raise
    finally:
        if client is not None:
            client.close(timeout=2)
    worst, within, capped = {}, None, {}
    for name, (value, flat, count, gaps) in zip(order, results):
        worst[name] = (value, tuple(int(i) for i in np.unravel_index(flat, plan.shape)))
        if count >= 0:
            within = count
        capped[name] = gaps
    view = np.asarray(results[len(order)], dtype=float) if tmp is not None else None
    return SweepResult(plan, chunks, worst, within, seconds,
                       scheduler if client is not None else local, target, view=view,
                       sweep_id=sweep_id(plan), capped=capped)
