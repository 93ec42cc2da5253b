"""Peak memory of the long-array functions, against their input and output.

A function over N points should need its input, its output and a bounded
amount of work space (chunks, blocks), so that a record of 10⁸ samples fits
where its input and output fit. The peak is what NumPy allocates during one
call, traced by :mod:`tracemalloc` (NumPy reports its buffers there); the
output is counted in it. The target: at most twice the input plus the output.
"""
from __future__ import annotations

import importlib
import inspect
import tracemalloc
from dataclasses import dataclass
from typing import Callable

import numpy as np

from crane_sym.bench.targets import Goal, time_functions
from crane_sym.derivation import Derivation
from crane_sym.markdown import markdown_table
from crane_sym.mechanics.sampled_load import sampled_response, sampled_response_uniform

__all__ = ["MemoryRow", "as_markdown", "function_memory", "goals", "peak_bytes",
           "sampled_memory"]

@dataclass(frozen=True)
class MemoryRow:
    """Peak bytes of one call against the bytes of its array input and output."""

    function: str
    points: int
    input_bytes: int
    output_bytes: int
    peak_bytes: int

    @property
    def limit(self) -> int:
        """The target: twice the input plus the output."""
        return 2 * self.input_bytes + self.output_bytes

    @property
    def met(self) -> bool:
        """True when the peak is within :attr:`limit`."""
        return self.peak_bytes <= self.limit


def peak_bytes(call: Callable[[], object]) -> tuple[int, int]:
    """(the most bytes traced at once during ``call()``, the bytes of the
    arrays it returns)."""
    tracemalloc.start()
    try:
        result = call()
        peak = tracemalloc.get_traced_memory()[1]
    finally:
        tracemalloc.stop()
    parts = result if isinstance(result, tuple) else (result,)
    return peak, sum(p.nbytes for p in parts if isinstance(p, np.ndarray))


def function_memory(d: Derivation, values: dict, duration: float,
                    points: int = 10**7) -> list[MemoryRow]:
    """A row for every generated time function of ``d`` on ``points`` times.

    Parameters
    ----------
    d : Derivation
        The built derivation.
    values : dict
        Scalar values (SI) for the functions' other arguments.
    duration : float
        The time span [0, duration] [s].
    points : int, optional
        Length of the time array.
    """
    module = importlib.import_module(f"crane_sym.generated.{d.id}")
    t = np.linspace(0.0, duration, points)
    rows = []
    for name in time_functions(d):
        fn = getattr(module, name)
        params = [p for p in inspect.signature(fn).parameters if p != "out"]
        args = [t if p == "t" else float(values[p]) for p in params]
        peak, output = peak_bytes(lambda: fn(*args))
        rows.append(MemoryRow(name, points, t.nbytes, output, peak))
    return rows


def sampled_memory(points: int = 10**7) -> list[MemoryRow]:
    """Rows for the sampled-load responses (x and x') on ``points`` samples;
    ``sampled_response`` takes the times as well, so its input is two arrays.

    Parameters
    ----------
    points : int, optional
        Number of load samples.
    """
    t = np.arange(points) * 1e-3
    S = np.sin(t) + 1.0
    uniform = peak_bytes(lambda: sampled_response_uniform(1e-3, S, 25.0))
    timed = peak_bytes(lambda: sampled_response(t, S, 25.0))
    return [MemoryRow("sampled_response_uniform", points, S.nbytes, uniform[1], uniform[0]),
            MemoryRow("sampled_response", points, S.nbytes + t.nbytes, timed[1], timed[0])]


def goals(paper: str, rows: list[MemoryRow]) -> list[Goal]:
    """The memory target of one paper as a row of the targets table: the
    worst peak over its limit (1 or less: met).

    Parameters
    ----------
    paper : str
        The derivation id, for the row.
    rows : list of MemoryRow
        Rows of :func:`function_memory`.
    """
    if not rows:
        return []
    worst = max(rows, key=lambda r: r.peak_bytes / r.limit)
    return [Goal(paper, "peak memory of one call (x its limit, 2 input + output)",
                 worst.peak_bytes / worst.limit, 1.0, f"{worst.function} at {worst.points:.0e}")]


def as_markdown(rows: list[MemoryRow]) -> str:
    """The rows as one Markdown table, with the target met or not.

    Parameters
    ----------
    rows : list of MemoryRow
        Rows from :func:`function_memory` or :func:`sampled_memory`.
    """
    return markdown_table(
        ["function", "points", "input MB", "output MB", "peak MB",
         "limit MB (2 input + output)", "met"],
        [[r.function, f"{r.points:.0e}", f"{r.input_bytes / 1e6:.0f}",
          f"{r.output_bytes / 1e6:.0f}", f"{r.peak_bytes / 1e6:.0f}", f"{r.limit / 1e6:.0f}",
          "met" if r.met else "NOT MET"] for r in rows], align="lrrrrrl")
