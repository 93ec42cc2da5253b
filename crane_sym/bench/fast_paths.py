"""``crane-sym bench --fast-paths``: the fast-path targets of the generated
time functions alone, in about a minute (issue 39, item 4).

The rows a whole ``crane-sym bench`` also prints, without its work-precision
tables and integrators: every time function against one ``np.cos`` at
10⁵ points (piecewise ≤ 3×; where the paper gives a hand-written NumPy
version of the same accuracy, that version timed in the same run as the
floor, and the generated one ≤ 1.25× it), and the peak memory of one call
on 10⁶ points against twice its input plus its output
(:mod:`crane_sym.bench.targets`, :mod:`crane_sym.bench.memory`). The load
average is given before and after, as the ratios move with it.
"""
from __future__ import annotations

import os
from typing import Any, Sequence

from crane_sym import progress, registry
from crane_sym.bench import functions as bench
from crane_sym.bench import memory as bench_memory
from crane_sym.bench import targets as bt
from crane_sym.derivation import Derivation
from crane_sym.scenes import reading as scenes

__all__ = ["MEMORY_POINTS", "POINTS", "bench_inputs", "fast_paths", "markdown"]

#: Points of the np.cos comparison and of the memory row.
POINTS = 10**5
MEMORY_POINTS = 10**6


def bench_inputs(i: str) -> tuple[Derivation, list, dict, float] | None:
    """(derivation, its benched scenes, the grid's scalar values, the longest
    duration) of paper ``i``, or None when it has no timed scene or no
    generated function.

    Parameters
    ----------
    i : str
        The derivation id.
    """
    chosen = [s for s in map(scenes.load_scene, scenes.list_scenes())
              if s.derivation == i and not s.load_table and "duration" in s.options]
    d = registry.get(i)
    if not chosen or not d.outputs:
        return None
    return (d, chosen, bench.grid_values(d, chosen),
            max(s.options["duration"] for s in chosen))


def fast_paths(ids: Sequence[str], points: int = POINTS,
               memory_points: int = MEMORY_POINTS) -> dict[str, Any]:
    """The ratios to np.cos at ``points``, the memory rows at
    ``memory_points`` and the targets met or not, of each paper in ``ids``
    that has timed scenes.

    Parameters
    ----------
    ids : sequence of str
        Derivation ids.
    points, memory_points : int
        Array lengths of the two measurements.
    """
    say = progress.current()
    load_before = os.getloadavg()[0]
    arrays, memory, goals = {}, {}, []
    for i in ids:
        found = bench_inputs(i)
        if found is None:
            continue
        d, _, values, duration = found
        with say.task(f"{i}: against np.cos at {points:.0e} points"):
            arrays[i] = bt.array_ratios(d, values, duration, [points])
        with say.task(f"{i}: peak memory on {memory_points:.0e} points"):
            memory[i] = bench_memory.function_memory(d, values, duration, memory_points)
        goals += [g for g in bt.goals(i, arrays[i], [], []) if "single" not in g.target]
        goals += bench_memory.goals(i, memory[i])
    return {"arrays": arrays, "memory": memory, "goals": goals, "points": points,
            "memory_points": memory_points, "load_before": load_before,
            "load_after": os.getloadavg()[0]}


def markdown(r: dict[str, Any]) -> str:
    """The section as Markdown: the targets (met / not met), then each paper's
    piecewise and hand-written rows and its memory rows.

    Parameters
    ----------
    r : dict
        The results of :func:`fast_paths`.
    """
    lines = ["# Bench: fast paths of the generated time functions", "",
             f"One run; load average {r['load_before']:.2f} before, {r['load_after']:.2f} "
             f"after ({os.cpu_count()} cores, shared: the ratios move with the load).", "",
             "## Targets", "", bt.goals_table(r["goals"])]
    for i, rows in r["arrays"].items():
        piece = [row for row in rows if row[1] != "single"]
        lines += ["", f"## {i}: against one np.cos at {r['points']:.0e} points "
                  "(piecewise and hand-written)", "", bt.arrays_table(piece) if piece
                  else "No piecewise time function.",
                  "", f"## {i}: peak memory of one call on {r['memory_points']:.0e} points", "",
                  bench_memory.as_markdown(r["memory"][i])]
    return "\n".join(lines + [""])
