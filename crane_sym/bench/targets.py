"""The speed targets of the generated code, measured in one run, and the
closed form against the best tuned integrator as the number of points grows.

Targets (ratios to one ``np.cos`` over the same array): a single-expression
time function at most 1.25x warm and 1.5x cold at 1e4-1e7 points; a
piecewise one (evaluated window by window) at most 3x at 1e5; where the
paper gives it a hand-written NumPy version of the same accuracy
(``HAND_WRITTEN``, :func:`crane_sym.bench.cases.hand_written`), that version
timed in the same run against the same 3x (the floor: where it misses, so
does any function of that accuracy) and the generated one at most 1.25x its
time (the margin a single expression has over ``np.cos``); a call on
scalars at most 1.5 µs; every closed form faster than the fastest integrator
that reaches 1e-9 of the peak, at every number of points compared. Warm is the
least time of repeated calls on one array; cold is a first call, on a fresh
array, against a first ``np.cos`` on another fresh array.
"""
from __future__ import annotations

import importlib
import inspect
import time
from dataclasses import dataclass
from typing import Sequence

import numpy as np

from crane_sym.bench import functions as bench
from crane_sym.bench.cases import hand_written
from crane_sym.bench.rows import GENERATED, INTEGRATOR, BenchRow, best_time
from crane_sym.derivation import Derivation
from crane_sym.markdown import markdown_table

SIZES = (10**4, 10**5, 10**6, 10**7)
QUICK_SIZES = (10**4, 10**5)
#: The kind of an :func:`array_ratios` row of a hand-written NumPy version.
HAND = "hand-written NumPy"
#: Numbers of points at which the closed form meets the best tuned integrator.
COMPARE_POINTS = (100, 2000, 10**5)
QUICK_COMPARE_POINTS = (100, 2000)
TARGET = 1e-9


@dataclass(frozen=True)
class Goal:
    """One target of one paper: the worst measured value against its limit."""

    paper: str
    target: str
    measured: float
    limit: float
    worst: str                     # the function (and size) that sets ``measured``

    @property
    def met(self) -> bool:
        """True when the worst measurement is within the limit."""
        return self.measured <= self.limit


def time_functions(d: Derivation) -> dict[str, str]:
    """Generated functions of ``d`` that take time: name -> 'piecewise' (window
    by window) or 'single' (one expression)."""
    module = importlib.import_module(f"crane_sym.generated.{d.id}")
    found = {}
    for out in d.outputs:
        if any(str(a) == "t" for a in out.args) and not hasattr(out.expr, "shape"):
            source = inspect.getsource(getattr(module, out.name))
            found[out.name] = "piecewise" if "_cells(" in source else "single"
    return found


def _cold(f, make) -> float:
    """Least time of a first call on a fresh array (three tries)."""
    times = []
    for _ in range(3):
        fresh = make()
        t0 = time.perf_counter()
        f(fresh)
        times.append(time.perf_counter() - t0)
        del fresh
    return min(times)


def array_ratios(d: Derivation, values: dict, duration: float, sizes: Sequence[int]
                 ) -> list[tuple[str, str, int, float, float]]:
    """(function, kind, points, warm ratio, cold ratio) to ``np.cos``; a
    function's hand-written NumPy version, if the paper gives one, timed
    beside it (kind :data:`HAND`).

    Parameters
    ----------
    d : Derivation
        The built derivation.
    values : dict
        Scalar values (SI) for the functions' other arguments.
    duration : float
        The time span [0, duration] [s].
    sizes : sequence of int
        Array lengths.
    """
    module = importlib.import_module(f"crane_sym.generated.{d.id}")
    kinds = time_functions(d)
    hands = hand_written(d.id)
    out = []
    for n in sizes:
        t = np.linspace(0.0, duration, n)
        fresh = lambda: np.linspace(0.0, duration, n)  # noqa: E731
        cos_warm = best_time(lambda: np.cos(t), budget=0.5, repeats=7)
        cos_cold = _cold(np.cos, fresh)
        for name, kind in kinds.items():
            fn = getattr(module, name)
            params = [p for p in inspect.signature(fn).parameters if p != "out"]

            def call(tt, fn=fn, params=params):
                return fn(*[tt if p == "t" else values[p] for p in params])
            warm = best_time(lambda: call(t), budget=0.5, repeats=7)
            out.append((name, kind, n, warm / cos_warm, _cold(call, fresh) / cos_cold))
            if name in hands:
                def by_hand(tt, fn=hands[name], params=params):
                    return fn(*[tt if p == "t" else values[p] for p in params])
                warm = best_time(lambda: by_hand(t), budget=0.5, repeats=7)
                out.append((name, HAND, n, warm / cos_warm, _cold(by_hand, fresh) / cos_cold))
    return out


def scalar_call(d: Derivation, values: dict, duration: float) -> list[tuple[str, float]]:
    """(function, seconds per call) of each single-expression time function on
    Python floats.

    Parameters
    ----------
    d : Derivation
        The built derivation.
    values : dict
        Scalar values (SI) for the functions' other arguments.
    duration : float
        The time span [s]; the call is at 0.37 of it.
    """
    module = importlib.import_module(f"crane_sym.generated.{d.id}")
    found = []
    for name, kind in time_functions(d).items():
        if kind != "single":
            continue
        fn = getattr(module, name)
        params = [p for p in inspect.signature(fn).parameters if p != "out"]
        args = [0.37 * duration if p == "t" else float(values[p]) for p in params]
        loops = 2000
        best = min(_loop(fn, args, loops) for _ in range(5)) / loops
        found.append((name, best))
    return found


def _loop(fn, args, loops: int) -> float:
    t0 = time.perf_counter()
    for _ in range(loops):
        fn(*args)
    return time.perf_counter() - t0


def scaling(d: Derivation, values: dict, duration: float, rows: Sequence[BenchRow],
            points: Sequence[int]) -> list[tuple[str, int, str, float, float]]:
    """(function, points, fastest integrator reaching TARGET of the peak, its
    seconds, closed form's seconds) at each number of points; the methods and
    tolerances tried are those of the fastest run reaching TARGET in ``rows``
    (the full run), per function.

    Parameters
    ----------
    d : Derivation
        The built derivation.
    values : dict
        Scalar values (SI) for the functions' other arguments.
    duration : float
        The time span [0, duration] [s].
    rows : sequence of BenchRow
        The rows of the full bench run, which name the methods to try.
    points : sequence of int
        The numbers of points to compare at.
    """
    good = []
    for name in dict.fromkeys(r.function for r in rows):
        ok = [r for r in rows if r.function == name and r.kind == INTEGRATOR
              and r.max_error_over_peak <= TARGET]
        good += [min(ok, key=lambda r: r.seconds)] if ok else []
    if not good:
        return []
    methods = sorted({r.method.split()[0] for r in good} - {"odeint"})
    rtols = sorted({float(r.method.split("rtol=")[1].split()[0]) for r in good})
    found = []
    for n in points:
        at_n = bench.bench(d, values, duration, points=n, reference_points=60,
                           methods=methods, rtols=rtols, alternatives=False)
        gens = {r.function: r for r in at_n if r.kind == GENERATED}
        for name in dict.fromkeys(r.function for r in at_n if r.kind == INTEGRATOR):
            ok = [r for r in at_n if r.function == name and r.kind == INTEGRATOR
                  and r.max_error_over_peak <= TARGET]
            if name in gens and ok:
                best = min(ok, key=lambda r: r.seconds)
                found.append((name, n, best.method, best.seconds, gens[name].seconds))
    return found


def goals(paper: str, arrays, scalars, scaled) -> list[Goal]:
    """The targets of one paper from the measurements above.

    Parameters
    ----------
    paper : str
        The derivation id, for the rows.
    arrays : sequence of tuple
        Rows of :func:`array_ratios`.
    scalars : sequence of tuple
        Rows of :func:`scalar_call`.
    scaled : sequence of tuple
        Rows of :func:`scaling`.
    """
    def worst(items, limit, what):
        if not items:
            return []
        value, where = max(items)
        return [Goal(paper, what, value, limit, where)]

    single = [(w, f"{f} at {n:.0e}") for f, k, n, w, _ in arrays if k == "single"]
    cold = [(c, f"{f} at {n:.0e}") for f, k, n, _, c in arrays if k == "single"]
    piece = [(w, f"{f}") for f, k, n, w, _ in arrays if k == "piecewise" and n == 10**5]
    floor = {f: w for f, k, n, w, _ in arrays if k == HAND and n == 10**5}
    by_hand = [(w / floor[f], f"{f}: {w:.3g}x np.cos, by hand {floor[f]:.3g}x")
               for f, k, n, w, _ in arrays if k == "piecewise" and n == 10**5 and f in floor]
    return (worst(single, 1.25, "single expression, warm (x np.cos)")
            + worst(cold, 1.5, "single expression, cold (x np.cos)")
            + worst(piece, 3.0, "piecewise at 1e5, warm (x np.cos)")
            + worst([(w, f) for f, w in floor.items()], 3.0,
                    "piecewise at 1e5 written by hand, same accuracy, warm (x np.cos)")
            + worst(by_hand, 1.25, "piecewise at 1e5, warm, against by hand (time ratio)")
            + worst([(s * 1e6, f) for f, s in scalars], 1.5, "scalar call (µs)")
            + worst([(g / i, f"{f} at N={n} vs {m}") for f, n, m, i, g in scaled], 1.0,
                    "closed form / best integrator (time)"))


def goals_table(found: Sequence[Goal]) -> str:
    """Markdown table of the targets with a met / not met column.

    Parameters
    ----------
    found : sequence of Goal
        Rows of :func:`goals`.
    """
    return markdown_table(
        ["paper", "target", "measured (worst)", "limit", "met", "worst case"],
        [[g.paper, g.target, f"{g.measured:.3g}", f"{g.limit:g}",
          "met" if g.met else "NOT MET", g.worst] for g in found], align="llrrll")


def scaling_table(scaled) -> str:
    """Markdown: closed form against the best tuned integrator at each N.

    Parameters
    ----------
    scaled : sequence of tuple
        Rows of :func:`scaling`.
    """
    return markdown_table(
        ["function", "points", "best integrator reaching 1e-9 of the peak", "integrator s",
         "closed form s", "integrator / closed form"],
        [[f, n, m, f"{i:.3g}", f"{g:.3g}", f"{i / g:.3g}" + (" (integrator wins)" if i < g else "")]
         for f, n, m, i, g in scaled], align="lrlrrr")


def arrays_table(arrays) -> str:
    """Markdown: warm and cold ratios to np.cos per function and size.

    Parameters
    ----------
    arrays : sequence of tuple
        Rows of :func:`array_ratios`.
    """
    return markdown_table(["function", "kind", "points", "warm / np.cos", "cold / np.cos"],
                          [[f, k, n, f"{w:.3g}", f"{c:.3g}"] for f, k, n, w, c in arrays],
                          align="llrrr")
