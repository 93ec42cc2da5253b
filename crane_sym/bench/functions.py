"""Speed against error: generated closed forms against what a user would
otherwise run, on one fixed, seeded grid of scene points.

For every generated function: evaluations per second and the worst relative
error against an mpmath reference (50 digits), the same for a plain
``sympy.lambdify`` of the derived expression, and the throughput floor, one
``np.cos`` over an array of the same length. For every quantity a derivation
also declares as an ODE system: SciPy's integrators at four tolerances
(``bench.odes``) and, where the system is x'' + Ω²x = S(t), Duhamel's integral
by quadrature and by discrete convolution (``bench.duhamel``). A response with
no closed form is benched against a modal mpmath solution (``bench.linear``).
Times are this machine's; ratios are taken within one run. Tables and plots:
``bench.report``.
"""
from __future__ import annotations

import importlib
import time
from dataclasses import asdict, replace
from typing import Sequence

import numpy as np
import sympy as sp

from crane_sym import progress, units
from crane_sym.bench import duhamel as bench_duhamel
from crane_sym.bench import linear as bench_linear
from crane_sym.bench import odes as bench_odes
from crane_sym.bench.rows import (DUHAMEL, DUHAMEL_RTOLS, FLOOR, GENERATED, INTEGRATOR, LAMBDIFY,
                                  METHODS, NAN, QUICK_RTOLS, REFERENCE, RTOLS, BenchRow, Target,
                                  best_time, errors, least_time)
from crane_sym.derivation import Derivation, Output
from crane_sym.bench.accuracy import mp_values
from crane_sym.scenes.specialize import module_name, operation_count, specialize, switched_off

__all__ = ["DUHAMEL", "FLOOR", "GENERATED", "INTEGRATOR", "LAMBDIFY", "METHODS", "NAN",
           "QUICK_RTOLS", "REFERENCE", "RTOLS", "BenchRow", "Target", "as_dicts", "bench", "best_time",
           "errors", "grid_values", "least_time", "scene_comparison", "scene_grid",
           "throughput"]

def grid_values(d: Derivation, scenes: Sequence) -> dict[str, float]:
    """Scalar values of the bench grid (SI): the scenes' parameters (the first
    scene that sets one wins), scene options that name a symbol of ``d``
    (simulation values), then ``d.bench_parameters`` for what no scene sets.

    Parameters
    ----------
    d : Derivation
        The built derivation.
    scenes : sequence of Scene
        Its shipped scenes, in order (the first that sets a value wins).
    """
    values: dict[str, float] = {}
    for scene in scenes:
        for name, value in scene.parameters.items():
            values.setdefault(name, float(value))
        for name, raw in scene.options.items():
            if name in d.symbols and name not in values:
                values[name] = units.convert(name, raw, d.symbols[name].dimension)
    for symbol, expr in d.bench_parameters.items():
        if str(symbol) not in values:
            known = {s: values[str(s)] for s in sp.sympify(expr).free_symbols}
            values[str(symbol)] = float(sp.sympify(expr).subs(known))
    return values


def scene_grid(values: dict[str, float], duration: float, points: int,
               seed: int = 1) -> dict[str, np.ndarray]:
    """The scalars ``values`` and ``points`` seeded times in [0, duration]."""
    rng = np.random.default_rng(seed)
    grid = {name: np.float64(v) for name, v in values.items()}
    grid["t"] = np.sort(rng.uniform(0.0, duration, points))
    return grid


def _columns(out: Output, grid: dict[str, np.ndarray], rng: np.random.Generator,
             points: int) -> dict[str, np.ndarray]:
    """Arguments for ``out``: the scene with time, or perturbed parameter sets
    when the function does not take time (so it still sees ``points`` inputs)."""
    missing = [str(a) for a in out.args if str(a) not in grid]
    if missing:
        raise KeyError(f"bench grid lacks {missing} for {out.name}: give them in a scene "
                       "or in the derivation's bench_parameters")
    if any(str(a) == "t" for a in out.args):
        return {str(a): grid[str(a)] for a in out.args}
    return {str(a): grid[str(a)] * 2.0 ** rng.uniform(-1, 1, points) for a in out.args}


def _elements(out: Output) -> list[sp.Expr]:
    return list(out.expr) if isinstance(out.expr, sp.MatrixBase) else [out.expr]


def _flat(value, n: int) -> np.ndarray:
    """A function's value on ``n`` points, element-major (matrices: row-major)."""
    if isinstance(value, (list, tuple)):
        return np.concatenate([np.broadcast_to(np.asarray(v, float), (n,)) for v in value])
    value = np.asarray(value, dtype=float)
    return value.reshape(-1) if value.ndim > 1 else np.broadcast_to(value, (n,))


def _reference(out: Output, columns: dict[str, np.ndarray]) -> list:
    """mpmath values of every element of ``out`` at ``columns``, element-major."""
    return [v for e in _elements(out) for v in mp_values(replace(out, expr=e), columns)]


def _function_rows(d: Derivation, out: Output, fn, grid, rng, check,
                   floor: float) -> tuple[list[BenchRow], Target]:
    """Generated, lambdify and floor rows of one function, and its target."""
    n = len(grid["t"])
    cols = _columns(out, grid, rng, n)
    args = [cols[str(a)] for a in out.args]
    sub = [np.asarray(a)[check] if np.ndim(a) else a for a in args]
    target = Target(d.id, out.name, check,
                    _reference(out, {str(a): v for a, v in zip(out.args, sub)}),
                    best_time(lambda: fn(*args)), n)
    plain = sp.lambdify(out.args, _elements(out) if len(_elements(out)) > 1 else out.expr,
                        modules="numpy")
    rows = [replace(target.row("generated", target.seconds, n,
                               _flat(fn(*sub), len(check)), GENERATED),
                    ratio_to_floor=target.seconds / floor)]
    seconds = best_time(lambda: plain(*args))
    rows.append(replace(target.row("sympy.lambdify (numpy)", seconds, n,
                                   _flat(plain(*sub), len(check)), LAMBDIFY),
                        ratio_to_floor=seconds / floor))
    rows.append(BenchRow(d.id, out.name, "np.cos floor", floor, n, NAN,
                         floor / target.seconds, ratio_to_floor=1.0, kind=FLOOR))
    return rows, target


def bench(d: Derivation, values: dict[str, float], duration: float,
          points: int = 2000, reference_points: int = 300,
          methods: Sequence[str] = METHODS, rtols: Sequence[float] = RTOLS,
          seed: int = 1, alternatives: bool = True) -> list[BenchRow]:
    """Rows for every generated function and every alternative, one run. The
    quadratures of ``bench_duhamel`` run at the tolerances of ``rtols`` that
    are in ``DUHAMEL_RTOLS`` (all of ``rtols`` if none is); without
    ``alternatives``, the integrators alone.

    Parameters
    ----------
    d : Derivation
        The built derivation whose generated functions are benched.
    values : dict of str to float
        Scalar values of the grid (SI), from :func:`grid_values`.
    duration : float
        The time span [0, duration] the time functions are evaluated on [s].
    points : int, optional
        Grid points of the comparison.
    reference_points : int, optional
        Points of the grid checked against the mpmath reference.
    methods : sequence of str, optional
        ``solve_ivp`` methods (``odeint`` always runs).
    rtols : sequence of float, optional
        Integrator tolerances.
    seed : int, optional
        Seed of the random parameter sets of time-free functions.
    alternatives : bool, optional
        False: the integrators alone, no Duhamel quadratures.
    """
    generated = importlib.import_module(f"crane_sym.generated.{d.id}")
    grid = scene_grid(values, duration, points, seed)
    rng = np.random.default_rng(seed + 1)
    check = np.unique(np.linspace(0, points - 1, min(reference_points, points)).astype(int))
    floor = best_time(lambda: np.cos(grid["t"]))
    rows: list[BenchRow] = []
    targets: dict[str, Target] = {}
    say = progress.current()
    for out in d.outputs:
        say.step(f"{d.id}: {out.name} against mpmath and lambdify")
        more, targets[out.name] = _function_rows(d, out, getattr(generated, out.name),
                                                 grid, rng, check, floor)
        rows += more
    for system in d.ode_systems:
        say.step(f"{d.id}: integrators on {system.name}")
        if any(name in targets for name, _ in system.quantities):
            rows += bench_odes.integrator_rows(system, grid, targets, methods, rtols)
            if alternatives:
                quad = tuple(r for r in rtols if r in DUHAMEL_RTOLS) or tuple(rtols)
                rows += bench_duhamel.duhamel_rows(system, grid, targets, quad)
        elif alternatives:
            rows += bench_linear.linear_rows(d, system, grid, check, methods, rtols)
    order = {name: i for i, name in enumerate(dict.fromkeys(r.function for r in rows))}
    return sorted(rows, key=lambda r: order[r.function])


def throughput(d: Derivation, values: dict[str, float], duration: float,
               points: int = 10**6) -> list[BenchRow]:
    """Large-array speed of each time-dependent generated function against one
    ``np.cos`` over the same array: first call and best of repeated calls.

    Parameters
    ----------
    d : Derivation
        The built derivation.
    values : dict of str to float
        Scalar values of the grid (SI).
    duration : float
        The time span [0, duration] [s].
    points : int, optional
        Length of the time array.
    """
    generated = importlib.import_module(f"crane_sym.generated.{d.id}")
    t = np.linspace(0.0, duration, points)
    floor = best_time(lambda: np.cos(t), budget=1.0, repeats=5)
    rows = [BenchRow(d.id, "np.cos", "floor", floor, points, NAN, NAN, ratio_to_floor=1.0,
                     kind=FLOOR)]
    for out in d.outputs:
        if not any(str(a) == "t" for a in out.args):
            continue
        fn = getattr(generated, out.name)
        args = [t if str(a) == "t" else values[str(a)] for a in out.args]
        t0 = time.perf_counter()
        fn(*args)
        first = time.perf_counter() - t0
        best = best_time(lambda: fn(*args), budget=1.0, repeats=3)
        rows.append(BenchRow(d.id, out.name, "first call", first, points, NAN, NAN,
                             ratio_to_floor=first / floor, kind=GENERATED))
        rows.append(BenchRow(d.id, out.name, "repeated", best, points, NAN, NAN,
                             ratio_to_floor=best / floor, kind=GENERATED))
    return rows


def scene_comparison(d: Derivation, scene, points: int = 10**6) -> list[str]:
    """Size (SymPy operation count) and speed of the scene-specialized module
    against the general one, for each output the scene asks for.

    Parameters
    ----------
    d : Derivation
        The built derivation (its general module is the comparison).
    scene : Scene
        The scene whose specialized module is measured.
    points : int, optional
        Length of the time array each module is timed on.
    """
    general = importlib.import_module(f"crane_sym.generated.{d.id}")
    special = importlib.import_module(f"crane_sym.generated.{module_name(scene)[:-3]}")
    rng = np.random.default_rng(4)
    values = {**scene.parameters,
              **{str(k): float(v) for k, v in switched_off(d, scene).items()}}
    t = np.linspace(0.0, scene.options["duration"], points)
    lines = []
    exprs = [d.output(n) for n in scene.outputs if n not in {o.name for o in d.tabulated}]
    for out, small in zip(exprs, specialize(d, scene)):   # tables: bench_piecewise
        # what the scene leaves as arguments (time, inputs, state): sampled arrays
        free = {str(a): t if str(a) == "t" else rng.uniform(0.5, 1.5, points)
                for a in small.args}
        args = [free[str(a)] if str(a) in free else values[str(a)] for a in out.args]
        kept = [free[str(a)] for a in small.args]
        big_time = best_time(lambda: getattr(general, out.name)(*args), budget=0.5)
        small_time = best_time(lambda: getattr(special, out.name)(*kept), budget=0.5)
        lines.append(f"{out.name}: operations {operation_count([out])} -> "
                     f"{operation_count([small])}, time {big_time * 1e3:.1f} -> "
                     f"{small_time * 1e3:.1f} ms on {points} points "
                     f"({big_time / small_time:.2f}x faster)")
    return lines


def as_dicts(rows: Sequence[BenchRow]) -> list[dict]:
    """JSON-ready rows (keys function, method, seconds, points, max_rel_error, ...);
    a value that does not apply (NaN) is None.

    Parameters
    ----------
    rows : sequence of BenchRow
        The rows of one bench run.
    """
    return [{k: (None if isinstance(v, float) and v != v else v) for k, v in asdict(r).items()}
            for r in rows]

