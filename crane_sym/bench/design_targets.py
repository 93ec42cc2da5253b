"""``crane-sym bench --sweep``, section (g): 10⁴ designs of a hybrid model
built from components, as a sweep runs them, against the targets of issue 39
(item 3), each row printed with met / not met and the machine's load:

- a paper's batched case that declares ``block_target`` (003's start-up:
  10⁴ designs in at most 1 s), its grid of ``n`` × ``n`` designs cut into
  blocks and scheduled as ``crane-sym sweep`` does on this machine
  (``crane_sym.sweep.blocks``: 003's NumPy-bound blocks on threads), each
  block solved by ``crane_sym.sweep.grid.evaluate_block``;
- a component file of 5 bodies (:data:`FILE_CASES`: ``bridge_travel.toml``,
  its two stiffnesses varied, 10⁴ designs in at most 2 s), one block (as a
  sweep of 10⁴ designs runs it: in its process) through
  ``crane_sym.components.designs.evaluate_block`` with Python's cycle
  collector paused as a sweep's worker pauses it
  (``crane_sym.sweep.compute.cycles_collected_after``), and the building of
  :data:`PROFILE_DESIGNS` of its designs' runs alone (``Designs.runs``: what
  of a block is per-design Python before the batched solve).

Beside each block, the floor of its method: the eigen-decompositions that
the batched closed forms made of it (the block's own distinct A, each once
for all its modes, kept while it ran:
``crane_sym.mechanics.batched_spectra.decomposed``), timed alone as the solver
makes them (``batched_spectra.decompose``: ``np.linalg.eig`` of each stack,
its left vectors from V⁻¹ or from ``np.linalg.eig`` of Aᵀ; :func:`eig_floor`,
the least of :data:`FLOOR_REPEATS`). A target below it
cannot be met by this solver on this machine, however little the rest costs.
Where the blocks run on threads, the floor's stacks are shared by as many
threads (LAPACK releases the GIL).

Each block is solved once (a run of a minute, not three). Where its time goes
comes from cProfile on a grid of :data:`PROFILE_DESIGNS` designs of the same
case, solved afresh: the functions with the most cumulative time, as
fractions of the profiled whole (:func:`profile_top`), printed beside a row
that is not met.
"""
from __future__ import annotations

import cProfile
import hashlib
import os
import pstats
import time
from dataclasses import dataclass
from pathlib import Path
from typing import Any, Callable

import numpy as np

from crane_sym import progress
from crane_sym.bench.batched import _grid
from crane_sym.bench.cases import BatchedBenchCase, batched_cases
from crane_sym.mechanics.batched_spectra import decompose, decomposed
from crane_sym.sweep.compute import cycles_collected_after
from crane_sym.sweep.grid import evaluate_block

__all__ = ["FILE_CASES", "FLOOR_REPEATS", "FileSweepCase", "PROFILE_DESIGNS", "eig_floor",
           "file_row", "markdown_rows", "paper_row", "profile_top", "run_rows"]

#: Designs of the profiled grid that says where a block's time goes.
PROFILE_DESIGNS = 1024
#: Entries of the profile a row keeps.
TOP = 8
#: Timings of the eigen-decompositions alone; the least is the floor.
FLOOR_REPEATS = 3


@dataclass(frozen=True)
class FileSweepCase:
    """A component file swept over two of its fields: ``n`` values each,
    from ``low`` to ``high`` in SI (``axes``: (field, low, high)), its
    ``output`` (``<link>.peak``), and the target in seconds for the block."""

    path: str
    output: str
    axes: tuple[tuple[str, float, float], ...]
    n: int = 100
    target: float = 2.0


#: The component files benched: 5 bodies (motors, shaft, wheels, bridge,
#: trolley in 3 groups), backlash, a friction brake that holds, a ramped brake.
FILE_CASES = (FileSweepCase("examples/drive_trains/bridge_travel.toml", "drive_line.peak",
                            (("drive_line.stiffness", 150.0, 350.0),
                             ("trolley_drive.stiffness", 1e6, 3e6))),)


#: Names that only wrap the work below them (a comprehension, a memo).
_WRAPPERS = ("<listcomp>", "<genexpr>", "<lambda>", "cached")
#: A function with this share of the whole or more is the call's own frame.
_OUTER = 0.9


def profile_top(solve: Callable[[], Any], top: int = TOP) -> list[tuple[str, float]]:
    """Where ``solve()`` spends its time: (function, share of the whole) of the
    ``top`` functions of this package with the most cumulative time under
    cProfile; the frames around the whole (:data:`_OUTER` of it or more) and
    the wrappers (:data:`_WRAPPERS`) left out."""
    prof = cProfile.Profile()
    prof.enable()
    solve()
    prof.disable()
    stats = pstats.Stats(prof).stats
    total = max((v[3] for v in stats.values()), default=0.0)
    rows = []
    for (path, line, name), (_, _, _, cumulative, _) in stats.items():
        if "crane_sym" not in path or name in _WRAPPERS or cumulative >= _OUTER * total:
            continue
        where = path[path.rindex("crane_sym"):].removesuffix(".py").replace("/", ".")
        rows.append((f"{where}.{name}", cumulative / total if total else 0.0))
    rows.sort(key=lambda r: -r[1])
    return rows[:top]


def eig_floor(stacks: list[np.ndarray], repeats: int = FLOOR_REPEATS,
              threads: int = 1) -> dict[str, Any]:
    """The eigen-decompositions of a block alone, as the batched closed forms
    make them (``batched_spectra.decompose``: right and left vectors), the
    least of ``repeats`` timings, and how many took their left vectors from
    ``np.linalg.eig`` of Aᵀ (``transposed``) rather than from V⁻¹.

    Parameters
    ----------
    stacks : list of ndarray, each (m, n, n)
        The stacks a block decomposed (``batched_spectra.decomposed``).
    repeats : int
        Timings; the least is kept (others on the machine only add time).
    threads : int
        Threads that share the stacks (Dask's threaded scheduler: LAPACK
        releases the GIL), as a sweep's blocks share them.
    """
    import dask
    times, transposed = [], 0
    for _ in range(repeats):
        start = time.perf_counter()
        if threads > 1:
            found = dask.compute(*[dask.delayed(decompose)(A) for A in stacks],
                                 scheduler="threads", num_workers=threads)
        else:
            found = [decompose(A) for A in stacks]
        times.append(time.perf_counter() - start)
        transposed = int(sum(np.sum(~f[4]) for f in found))
    return {"seconds": min(times), "matrices": int(sum(A.shape[0] for A in stacks)),
            "transposed": transposed, "threads": threads,
            "sizes": sorted({int(A.shape[1]) for A in stacks}), "stacks": len(stacks)}


def _timed(solve: Callable[[], np.ndarray], threads: int = 1) -> dict[str, Any]:
    """One solve: wall and CPU seconds, the load average before and after,
    and the floor of its eigen-decompositions (:func:`eig_floor`, on as many
    ``threads`` as the solve's blocks, at most the cores)."""
    before = os.getloadavg()[0]
    with decomposed() as stacks:
        start, cpu = time.perf_counter(), time.process_time()
        values = solve()
        seconds, cpu_seconds = time.perf_counter() - start, time.process_time() - cpu
    return {"seconds": seconds, "cpu_seconds": cpu_seconds,
            "load_before": before, "load_after": os.getloadavg()[0],
            "designs": int(np.size(values)), "nan": int(np.isnan(values).sum()),
            "eig_floor": eig_floor(stacks, threads=min(threads, os.cpu_count() or 1))}


def _as_swept(case: BatchedBenchCase, n: int) -> tuple[Callable[[], np.ndarray], int, str]:
    """(solve, blocks, scheduler): the case's grid of ``n`` values an axis as
    ``crane-sym sweep`` runs it on this machine (``sweep.blocks.chunks_for``,
    ``local_scheduler``, Dask's local scheduler computing
    ``sweep.grid.grid_arrays``), nothing written."""
    import dask
    from crane_sym.sweep.blocks import chunks_for, local_scheduler
    from crane_sym.sweep.grid import grid_arrays
    chosen = _grid(case, n)[0]
    chunks = chunks_for(chosen)
    local = local_scheduler(chosen, chunks)
    field = grid_arrays(chosen, chunks)[case.output]
    blocks = int(np.prod([len(c) for c in chunks]))
    return lambda: dask.compute(field, scheduler=local)[0], blocks, local


def paper_row(paper: str, case: BatchedBenchCase) -> dict[str, Any]:
    """The case's grid of ``case.block_n`` ** 2 designs as a sweep runs it
    (:func:`_as_swept`: its blocks, on threads where the output is
    NumPy-bound) against its ``block_target``, and where a grid of
    :data:`PROFILE_DESIGNS` designs, one block, spends its time."""
    say = progress.current()

    def solver(n: int) -> Callable[[], np.ndarray]:
        chosen, spec, names, axes = _grid(case, n)
        call = (chosen.derivation, case.output, spec.kind, spec.args, names,
                dict(chosen.fixed), dict(chosen.options))
        return lambda: evaluate_block(*call, *axes, cached=False)
    solver(2)()                                              # imports, the derivation
    solve, blocks, local = _as_swept(case, case.block_n)
    say.step(f"  {case.output}: {case.block_n ** len(case.axes)} designs as a sweep runs "
             f"them ({blocks} block(s), {local}) ...")
    row = {"name": f"{paper} {case.output}", **_timed(solve, threads=blocks),
           "target": case.block_target, "blocks": blocks, "scheduler": local}
    row["met"] = row["seconds"] <= case.block_target
    say.step(f"  {case.output}: where the time goes ({PROFILE_DESIGNS} designs, cProfile) ...")
    row["profile"] = profile_top(solver(round(PROFILE_DESIGNS ** (1 / len(case.axes)))))
    return row


def _file_values(case: FileSweepCase, n: int) -> dict[str, np.ndarray]:
    """The grid of ``n`` values a field of ``case``, field -> SI array."""
    grids = np.meshgrid(*[np.linspace(lo, hi, n) for _, lo, hi in case.axes], indexing="ij")
    return {name: g for (name, _, _), g in zip(case.axes, grids)}


def file_row(case: FileSweepCase, root: Path) -> dict[str, Any]:
    """A component file's grid of ``case.n`` ** 2 designs as one block
    against ``case.target``, and where a grid of :data:`PROFILE_DESIGNS`
    spends its time; ``root`` is the folder ``case.path`` is relative to."""
    from crane_sym.components.designs import designs, evaluate_block as file_block
    path = root / case.path
    name = f"{case.path} {case.output}"
    if not path.is_file():
        return {"name": name, "skipped": f"{case.path} not found under {root}"}
    digest = hashlib.sha256(path.read_bytes()).hexdigest()
    say = progress.current()

    def solver(n: int) -> Callable[[], np.ndarray]:
        values = _file_values(case, n)
        def solve() -> np.ndarray:
            with cycles_collected_after():             # as sweep.grid.evaluate_block
                return file_block(str(path), digest, case.output, values, cached=False)
        return solve
    solver(2)()                                              # read, derived
    say.step(f"  {name}: {case.n ** len(case.axes)} designs as one block ...")
    row = {"name": name, **_timed(solver(case.n)), "target": case.target}
    row["met"] = row["seconds"] <= case.target
    say.step(f"  {name}: {PROFILE_DESIGNS} designs built, not solved ...")
    found = designs(str(path), digest)
    values = _file_values(case, round(PROFILE_DESIGNS ** (1 / len(case.axes))))

    def built() -> np.ndarray:            # a block where it applies, else a run a design
        block = found.plain(case.output, values)[1]
        if block is None:
            return found.runs(case.output, values)[2]
        return block.starts()[1][:, 0]
    with cycles_collected_after():
        row["construction"] = _timed(built)
    say.step(f"  {name}: where the time goes ({PROFILE_DESIGNS} designs, cProfile) ...")
    row["profile"] = profile_top(solver(round(PROFILE_DESIGNS ** (1 / len(case.axes)))))
    return row


def run_rows(root: Path | None = None) -> list[dict[str, Any]]:
    """Every row of section (g): the papers' cases with a ``block_target``,
    then :data:`FILE_CASES` (relative to ``root``, default the folder above
    the package: a checkout's examples).

    Parameters
    ----------
    root : Path, optional
        The folder the files of :data:`FILE_CASES` are relative to.
    """
    root = root or Path(__file__).resolve().parents[2]
    say, rows = progress.current(), []
    for paper, case in batched_cases():
        if case.block_target is not None:
            with say.task(f"  (g) {paper} {case.output}"):
                rows.append(paper_row(paper, case))
    for case in FILE_CASES:
        with say.task(f"  (g) {case.path}"):
            rows.append(file_row(case, root))
    return rows


def markdown_rows(rows: list[dict[str, Any]]) -> list[str]:
    """The section of ``bench_sweep.md`` (and of ``bench_designs.md``) for
    :func:`run_rows`.

    Parameters
    ----------
    rows : list of dict
        The rows :func:`run_rows` measured.
    """
    if not rows:
        return []
    lines = ["## (g) 10⁴ designs of a model from components, as a sweep runs them "
             "(issue 39)", "",
             "Each grid solved once, cut into blocks and scheduled as ``crane-sym sweep`` "
             "does here; wall and CPU seconds of this process, the load average before "
             "and after (the machine is shared).", "",
             "| target | measured | limit | met |", "| --- | --- | --- | --- |"]
    for r in rows:
        if "skipped" in r:
            lines.append(f"| {r['name']} | skipped: {r['skipped']} | | |")
            continue
        blocks = r.get("blocks", 1)
        how = ("one block" if blocks == 1 else
               f"{blocks} blocks on {r.get('scheduler', 'threads')}")
        lines.append(f"| {r['designs']} designs of {r['name']}, {how} | "
                     f"{r['seconds']:.2f} s wall, {r['cpu_seconds']:.2f} s CPU "
                     f"({1e3 * r['seconds'] / r['designs']:.2f} ms a design; NaN "
                     f"{r['nan']}); load {r['load_before']:.1f} before, "
                     f"{r['load_after']:.1f} after | ≤ {r['target']:g} s | "
                     f"{'met' if r['met'] else 'not met'} |")
    for r in rows:
        floor = r.get("eig_floor")
        if floor and floor["matrices"]:
            below = floor["seconds"] > r["target"]
            lines.append(f"\n{r['name']}: the eigen-decompositions alone, the floor of the "
                         f"batched closed forms: {floor['matrices']} distinct A of size "
                         f"{', '.join(map(str, floor['sizes']))} in {floor['stacks']} stacks "
                         f"(one a round and mode, each A once for all its modes), "
                         f"``np.linalg.eig`` of each, its left vectors from V⁻¹ "
                         f"({floor['matrices'] - floor.get('transposed', 0)}) or from "
                         f"``np.linalg.eig`` of Aᵀ ({floor.get('transposed', 0)}): "
                         f"{floor['seconds']:.2f} s"
                         + (f" on {floor['threads']} threads" if floor.get("threads", 1) > 1
                            else "") + f", least of {FLOOR_REPEATS}; "
                         + (f"the target of {r['target']:g} s is below it: this solver "
                            "cannot meet it on this machine, whatever the rest costs."
                            if below else f"{floor['seconds'] / r['target']:.0%} of the "
                            f"target of {r['target']:g} s."))
    for r in rows:
        if "construction" in r:
            c = r["construction"]
            lines.append(f"\n{r['name']}: its {c['designs']} designs built, not solved "
                         f"(one block: its model, the values as columns, the bound on "
                         f"periods, the starts at rest, ``Designs.plain``; else a run a "
                         f"design, ``Designs.runs``): "
                         f"{c['seconds']:.2f} s wall, {c['cpu_seconds']:.2f} s CPU "
                         f"({1e3 * c['seconds'] / c['designs']:.2f} ms a design); load "
                         f"{c['load_before']:.1f} before.")
    for r in rows:
        if r.get("profile") and not r["met"]:
            parts = "; ".join(f"{name} {100 * share:.0f} %" for name, share in r["profile"])
            lines.append(f"\n{r['name']}: where the time goes ({PROFILE_DESIGNS} designs, "
                         f"cProfile, cumulative share of the block): {parts}.")
    lines.append("")
    return lines
