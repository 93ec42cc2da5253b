"""The rows of a bench and what they are measured against.

Shared by ``bench.functions`` and the modules that bench the alternatives
(``bench.odes``, ``bench.duhamel``, ``bench.linear``) and report them
(``bench.report``): the row and target types, the row kinds, the tolerances,
and the timers.
"""
from __future__ import annotations

import time
from dataclasses import dataclass
from typing import Callable

import numpy as np

from crane_sym.bench.accuracy import relative_errors

METHODS = ("RK45", "DOP853", "LSODA", "Radau")
#: Integrator tolerances: every half decade from 1e-6 to 1e-13 (atol scaled to each
#: state's peak); ``QUICK_RTOLS`` for ``crane-sym bench --quick``; the quadratures
#: of ``bench.duhamel`` take ``DUHAMEL_RTOLS``.
RTOLS = tuple(float(f"{10 ** (-k / 2):.3g}") for k in range(12, 27))
QUICK_RTOLS = (1e-6, 1e-9, 1e-12)
DUHAMEL_RTOLS = (1e-6, 1e-9, 1e-12)
#: Row kinds: the generated function, its baselines, and the alternatives.
GENERATED, FLOOR, LAMBDIFY = "generated", "floor", "lambdify"
INTEGRATOR, DUHAMEL, REFERENCE = "integrator", "duhamel", "reference"
NAN = float("nan")


@dataclass(frozen=True)
class BenchRow:
    """One function evaluated one way on the grid.

    ``ratio_to_generated`` is time per evaluation over the generated
    function's; ``ratio_to_floor`` is time over one ``np.cos`` of the same length.
    """

    derivation: str
    function: str
    method: str
    seconds: float
    points: int
    max_rel_error: float
    ratio_to_generated: float
    max_error_over_peak: float = NAN
    ratio_to_floor: float = NAN
    kind: str = ""


@dataclass(frozen=True)
class Target:
    """The reference an alternative to one function is measured against:
    exact values (mpf, element-major) at the grid indices ``check``."""

    derivation: str
    name: str
    check: np.ndarray
    exact: list
    seconds: float = NAN      # the generated function on the whole grid
    points: int = 1

    def row(self, method: str, seconds: float, points: int, values: np.ndarray,
            kind: str) -> BenchRow:
        """A row for ``values`` (at ``check``) obtained in ``seconds`` for ``points``."""
        rel, over = errors(values, self.exact)
        ratio = (seconds / points) / (self.seconds / self.points)
        return BenchRow(self.derivation, self.name, method, seconds, points, rel, ratio,
                        over, kind=kind)


def errors(values: np.ndarray, exact: list) -> tuple[float, float]:
    """Worst relative error, and worst error over the largest |exact| (normwise:
    meaningful where the quantity passes through zero)."""
    values = np.asarray(values, dtype=float).ravel()
    if values.size != len(exact):
        values = np.broadcast_to(values, (len(exact),))
    ref = np.array([float(e) for e in exact])
    peak = np.max(np.abs(ref))
    over = float(np.max(np.abs(values - ref)) / peak) if peak else float(np.max(np.abs(values)))
    return float(np.max(relative_errors(values, exact))), over


def best_time(f: Callable[[], object], budget: float = 0.3, repeats: int = 7) -> float:
    """Least wall time of ``f`` over a few calls (first call included)."""
    times = []
    start = time.perf_counter()
    for _ in range(repeats):
        t0 = time.perf_counter()
        f()
        times.append(time.perf_counter() - t0)
        if time.perf_counter() - start > budget and len(times) >= 2:
            break
    return min(times)


def least_time(call: Callable[[], object], budget: float = 0.2, repeats: int = 3
               ) -> tuple[float, object]:
    """(least wall time, result) of ``call`` over up to ``repeats`` calls, no
    more once ``budget`` seconds are spent: a slow alternative runs once."""
    best, start = float("inf"), time.perf_counter()
    for _ in range(repeats):
        t0 = time.perf_counter()
        result = call()
        best = min(best, time.perf_counter() - t0)
        if time.perf_counter() - start > budget:
            break
    return best, result
