"""Running a design sweep's graph, and stopping it: Dask's local scheduler
in a pool of its own, or a ``dask.distributed`` scheduler.

When the tasks write files (a Zarr store), a failure or a signal must not
leave a task writing after the partial store is removed. Local: the sweep's
threads or processes are its own (:func:`compute_local`), and the pool is
shut down, every started task finished and no other started, before the
exception leaves. A live ``dask.distributed`` scheduler: the tasks are
cancelled and the workers asked until none runs one (:func:`compute_remote`,
up to :data:`STOP_WAIT` seconds). A lost scheduler cannot be asked: its
workers may finish the block they run and write it; the caller keeps
removing the partial store for a while (:func:`crane_sym.sweep.store.remove_settled`),
and what comes later holds chunk files without Zarr metadata, in a hidden
``.partial`` folder. A lost scheduler, or workers that die running a block
again and again (``KilledWorker``), is a SweepError naming ``--scheduler``;
a worker that dies once is replaced by Dask and its blocks recomputed, the
same bits.
"""
from __future__ import annotations

import contextlib
import gc
import re
import sys
import time
from typing import Callable, Iterator

from crane_sym.sweep.plan import SweepError
from crane_sym.sweep.store import deferred_signals

__all__ = ["STOP_WAIT", "compute_local", "compute_remote", "connect", "cycles_collected_after",
           "scheduler_lost", "warm_pool"]

#: Seconds to wait for a live scheduler's workers to stop a cancelled sweep.
STOP_WAIT = 30.0


def connect(address: str, timeout: float = 3.0):
    """A ``distributed.Client`` on the scheduler at ``address``; SweepError
    naming ``--scheduler`` if the address is malformed or nothing answers."""
    if not re.fullmatch(r"(?:(?:tcp|tls|ucx|inproc)://)?[A-Za-z0-9_.\-\[\]:]{1,200}:\d{1,5}"
                        r"(?:/[A-Za-z0-9_\-]*)?", address):
        raise SweepError(f"--scheduler {address!r}: expected an address such as "
                         "tcp://127.0.0.1:8786")
    from distributed import Client
    try:
        return Client(address, timeout=timeout, set_as_default=False)
    except (OSError, TimeoutError) as exc:
        raise SweepError(f"--scheduler {address!r}: no Dask scheduler answers there "
                         f"within {timeout:g} s ({type(exc).__name__})") from None


def compute_local(tasks: Callable[[dict], list], local: str, quiet: bool, own_pool: bool,
                  once: dict | None = None, pool=None) -> tuple:
    """``dask.compute`` of ``tasks(arrays)`` on the local scheduler. With
    ``once`` (name -> dask array) those arrays are computed first, in the same
    pool, and kept, and ``tasks`` gets them computed (each block once, however
    many tasks read it); otherwise ``tasks({})``. With ``own_pool`` (the tasks
    write files) the threads or processes are this call's own, and on a
    failure or signal every task already started has finished, and no other
    starts, before the exception leaves.

    Parameters
    ----------
    tasks : callable
        The computed arrays of ``once`` (or {}) -> the Dask collections to compute.
    local : str
        ``"synchronous"``, ``"threads"`` or ``"processes"``.
    quiet : bool
        No progress bar.
    own_pool : bool
        A pool of this call's own, shut down before it returns or raises.
    once : dict, optional
        Arrays computed first and kept.
    pool : Executor, optional
        A started pool (:func:`warm_pool`) to run on instead: the caller's,
        left running.
    """
    import dask
    from dask.diagnostics import ProgressBar
    given = pool
    if given is None and own_pool:
        pool = _pool(local)
    bar = ProgressBar(minimum=2.0, out=sys.stderr) if not quiet else None
    if bar is not None:
        bar.register()
    try:
        extra = {"pool": pool} if pool is not None else {}
        if once is not None:
            names = list(once)
            kept = dask.persist(*[once[n] for n in names], scheduler=local, **extra)
            once = dict(zip(names, kept))
        return dask.compute(*tasks(once or {}), scheduler=local, **extra)
    finally:
        if bar is not None:
            bar.unregister()
        if pool is not None and given is None:
            with deferred_signals():
                pool.shutdown(wait=True, cancel_futures=True)


def _pool(local: str, warm: Callable[[], object] | None = None):
    """A pool like the one Dask's local scheduler ``local`` makes (None for
    the synchronous one); a process runs ``warm`` (picklable) as it starts."""
    from dask.system import CPU_COUNT
    if local == "threads":
        from concurrent.futures import ThreadPoolExecutor
        return ThreadPoolExecutor(CPU_COUNT)
    if local == "processes":
        from concurrent.futures import ProcessPoolExecutor

        from dask.multiprocessing import get_context
        return ProcessPoolExecutor(CPU_COUNT, mp_context=get_context(),
                                   initializer=_start_worker, initargs=(warm,))
    return None


def _start_worker(warm: Callable[[], object] | None) -> None:
    """In a new worker process: Dask's set-up, then ``warm`` (imports, a
    first call)."""
    from dask.multiprocessing import initialize_worker_process
    initialize_worker_process()
    if warm is not None:
        warm()


@contextlib.contextmanager
def warm_pool(local: str, warm: Callable[[], object]) -> Iterator:
    """A pool for Dask's local scheduler ``local`` whose workers are started
    and have run ``warm`` (a picklable call: the imports and a first block)
    before the block is entered, so a clock started inside times the sweep,
    not the workers' start (~3 s for two processes here); shut down on exit.
    ``compute_local(..., pool=...)`` runs on it.

    Parameters
    ----------
    local : str
        ``"threads"`` or ``"processes"``.
    warm : callable
        Run once in each worker process as it starts (for threads: once, here).

    >>> with warm_pool("threads", lambda: None) as pool:
    ...     pool.submit(sum, [1, 2]).result()
    3
    """
    pool = _pool(local, warm)
    if pool is None:
        raise ValueError(f"warm_pool: {local!r} has no pool (threads or processes)")
    try:
        if local == "threads":
            warm()
        # one task a worker, each long enough that every worker gets one: all started
        list(pool.map(time.sleep, [0.2] * getattr(pool, "_max_workers", 1)))
        yield pool
    finally:
        with deferred_signals():
            pool.shutdown(wait=True, cancel_futures=True)


def compute_remote(client, tasks: Callable[[dict], list], quiet: bool, address: str,
                   once: dict | None = None) -> list:
    """``tasks(arrays)`` on a ``dask.distributed`` scheduler, the arrays of
    ``once`` persisted on the cluster first (as :func:`compute_local`). On a
    failure or signal with the scheduler still there, the tasks are cancelled
    and the call waits (up to :data:`STOP_WAIT` seconds) until no worker runs
    one; a lost scheduler becomes a SweepError naming ``--scheduler``."""
    if once is not None:
        names = list(once)
        once = dict(zip(names, client.persist([once[n] for n in names])))
    tasks = tasks(once or {})
    futures = client.compute(tasks)
    try:
        if not quiet:
            from distributed import progress
            progress(futures)
        return client.gather(futures)
    except BaseException as exc:
        why = scheduler_lost(client, exc)
        if why is not None:
            raise SweepError(f"--scheduler {address!r}: {why}; nothing was written") from None
        with deferred_signals():
            _stop_remote(client, futures, tasks)
        raise


def scheduler_lost(client, exc: BaseException) -> str | None:
    """Why the scheduler failed the sweep in a few words (lost, or its
    workers died running a block), or None if ``exc`` is the sweep's own
    error or a signal."""
    from distributed.client import FutureCancelledError
    if isinstance(exc, FutureCancelledError):
        if "connection" in exc.reason or client.status != "running":
            return "the connection to the Dask scheduler was lost during the sweep"
        return f"the Dask scheduler cancelled the sweep ({exc.reason})"
    if type(exc).__name__ == "KilledWorker":
        return ("the Dask workers died running one block of the sweep too often "
                "(KilledWorker)")
    if isinstance(exc, Exception) and client.status != "running":
        return ("the connection to the Dask scheduler was lost during the sweep "
                f"({type(exc).__name__})")
    return None


def _busy(names: set, dask_worker=None) -> int:
    """On a worker: how many of the tasks it runs belong to ``names`` (layers
    of the sweep's graph)."""
    state = dask_worker.state
    return sum((ts.key[0] if isinstance(ts.key, tuple) else ts.key) in names
               for ts in (*state.executing, *state.long_running))


def _stop_remote(client, futures: list, tasks: list) -> bool:
    """Cancel the sweep's tasks and wait until no worker runs one; True if
    they stopped within :data:`STOP_WAIT` seconds."""
    names = {str(name) for t in tasks for name in t.__dask_graph__().layers}
    try:
        client.cancel(futures, force=True)
        deadline = time.monotonic() + STOP_WAIT
        while time.monotonic() < deadline:
            if not any(client.run(_busy, names).values()):
                return True
            time.sleep(0.1)
    except Exception:                          # the scheduler went away meanwhile
        pass
    return False


@contextlib.contextmanager
def cycles_collected_after() -> Iterator[None]:
    """Python's cycle collector paused while a batched block runs: a block
    builds a system per design (about a hundred objects each), which the
    collector would walk again and again (a quarter of 003's start-up block,
    measured); they hold no cycle, so they are freed as the block drops them,
    and the collector runs as usual after the block. The switch is the
    process's: blocks run side by side in threads (``--scheduler threads``)
    make it best effort (the first to finish turns the collector back on),
    and it is never left off."""
    was_enabled = gc.isenabled()
    gc.disable()
    try:
        yield
    finally:
        if was_enabled:
            gc.enable()
