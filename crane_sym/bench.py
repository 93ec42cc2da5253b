"""Speed against error: generated closed forms against what a user would
otherwise run, on one fixed, seeded grid of scene points.

For every generated function: evaluations per second and the worst relative
error against an mpmath reference (50 digits). For every quantity a
derivation also declares as an ODE system: SciPy's ``solve_ivp`` (RK45,
DOP853, LSODA, Radau) and ``odeint`` at four tolerances, on each ODE system
(absolute and relative coordinates). The throughput floor is one ``np.cos``
over an array of the same length. Times are this machine's; ratios are taken
within one run.
"""
from __future__ import annotations

import importlib
import time
from dataclasses import asdict, dataclass
from pathlib import Path
from typing import Callable, Sequence

import numpy as np
import sympy as sp

from .derivation import Derivation, ODESystem, Output
from .reference import mp_values, relative_errors

METHODS = ("RK45", "DOP853", "LSODA", "Radau")
RTOLS = (1e-3, 1e-6, 1e-9, 1e-12)


@dataclass(frozen=True)
class BenchRow:
    """One function evaluated one way on the grid."""

    derivation: str
    function: str
    method: str
    seconds: float
    points: int
    max_rel_error: float
    ratio_to_generated: float
    max_error_over_peak: float = float("nan")


def _best_time(f: Callable[[], object], budget: float = 0.3, repeats: int = 7) -> float:
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


def scene_grid(d: Derivation, parameters: dict[str, float], duration: float,
               points: int, seed: int = 1) -> dict[str, np.ndarray]:
    """Scene parameters (scalars) and ``points`` seeded times in [0, duration]."""
    rng = np.random.default_rng(seed)
    grid = {name: np.float64(v) for name, v in parameters.items()}
    grid["t"] = np.sort(rng.uniform(0.0, duration, points))
    return grid


def _columns(out: Output, grid: dict[str, np.ndarray], rng: np.random.Generator,
             points: int) -> dict[str, np.ndarray]:
    """Arguments for ``out``: the scene with time, or perturbed parameter sets
    when the function does not take time (so it still sees ``points`` inputs)."""
    if any(str(a) == "t" for a in out.args):
        return {str(a): grid[str(a)] for a in out.args}
    return {str(a): grid[str(a)] * 2.0 ** rng.uniform(-1, 1, points) for a in out.args}


def _over_peak(values: np.ndarray, exact: list) -> float:
    """Worst error relative to the largest |exact| value on the grid (normwise):
    meaningful where the quantity passes through zero."""
    ref = np.array([float(e) for e in exact])
    peak = np.max(np.abs(ref))
    return float(np.max(np.abs(np.asarray(values, dtype=float) - ref)) / peak) if peak else 0.0


def throughput(d: Derivation, parameters: dict[str, float], duration: float,
               points: int = 10**7) -> list[BenchRow]:
    """Large-array speed of each time-dependent generated function against one
    ``np.cos`` over the same array: first call and best of repeated calls."""
    generated = importlib.import_module(f"crane_sym.generated.{d.id}")
    t = np.linspace(0.0, duration, points)
    floor = _best_time(lambda: np.cos(t), budget=2.0, repeats=5)
    rows = [BenchRow(d.id, "np.cos", "floor", floor, points, float("nan"), 1.0)]
    for out in d.outputs:
        if not any(str(a) == "t" for a in out.args):
            continue
        fn = getattr(generated, out.name)
        args = [t if str(a) == "t" else parameters[str(a)] for a in out.args]
        t0 = time.perf_counter()
        fn(*args)
        first = time.perf_counter() - t0
        best = _best_time(lambda: fn(*args), budget=2.0, repeats=5)
        rows.append(BenchRow(d.id, out.name, "first call", first, points, float("nan"), first / floor))
        rows.append(BenchRow(d.id, out.name, "repeated", best, points, float("nan"), best / floor))
    return rows


def scene_comparison(d: Derivation, scene, points: int = 10**6) -> list[str]:
    """Size (SymPy operation count) and speed of the scene-specialized module
    against the general one, for each output the scene asks for."""
    from .specialize import module_name, operation_count, specialize
    general = importlib.import_module(f"crane_sym.generated.{d.id}")
    special = importlib.import_module(f"crane_sym.generated.{module_name(scene)[:-3]}")
    t = np.linspace(0.0, scene.options["duration"], points)
    lines = []
    for out, small in zip([d.output(n) for n in scene.outputs], specialize(d, scene)):
        args = [t if str(a) == "t" else scene.parameters[str(a)] for a in out.args]
        big_time = _best_time(lambda: getattr(general, out.name)(*args), budget=1.0)
        small_time = _best_time(lambda: getattr(special, out.name)(t), budget=1.0)
        lines.append(f"{out.name}: operations {operation_count([out])} -> "
                     f"{operation_count([small])}, time {big_time * 1e3:.1f} -> "
                     f"{small_time * 1e3:.1f} ms on {points} points "
                     f"({big_time / small_time:.2f}x faster)")
    return lines


def _first_order(system: ODESystem, params: Sequence[sp.Symbol]):
    """``f(t, y, *params)``, the initial-state function and quantity functions."""
    t = system.coordinates[0].args[0]
    q = list(system.coordinates)
    qd = [c.diff(t) for c in q]
    acc = sp.solve(system.equations, [c.diff(t, 2) for c in q], dict=True)[0]
    state = sp.symbols(f"y0:{2 * len(q)}")
    to_state = {**{d: s for d, s in zip(qd, state[len(q):])},
                **{c: s for c, s in zip(q, state[:len(q)])}}

    def flat(expr: sp.Expr) -> sp.Expr:
        return expr.subs(to_state)

    rhs = list(state[len(q):]) + [flat(acc[c.diff(t, 2)]) for c in q]
    f = sp.lambdify((t, state, *params), rhs, modules="numpy")
    init = dict(system.initial)
    y0 = sp.lambdify(params, [init[c] for c in q] + [init[c] for c in qd], modules="numpy")
    quantities = {name: sp.lambdify((state, *params), flat(expr), modules="numpy")
                  for name, expr in system.quantities}
    return f, y0, quantities


def bench(d: Derivation, parameters: dict[str, float], duration: float,
          points: int = 2000, reference_points: int = 300,
          methods: Sequence[str] = METHODS, rtols: Sequence[float] = RTOLS
          ) -> list[BenchRow]:
    """Rows for every generated function and every alternative, one run."""
    from scipy.integrate import odeint, solve_ivp

    generated = importlib.import_module(f"crane_sym.generated.{d.id}")
    grid = scene_grid(d, parameters, duration, points)
    rng = np.random.default_rng(2)
    check = np.linspace(0, points - 1, reference_points).astype(int)
    rows: list[BenchRow] = []
    for out in d.outputs:
        cols = _columns(out, grid, rng, points)
        fn = getattr(generated, out.name)
        args = [cols[str(a)] for a in out.args]
        seconds = _best_time(lambda: fn(*args))
        sub = {k: (v[check] if np.ndim(v) else v) for k, v in cols.items()}
        exact = mp_values(out, sub)
        value = np.broadcast_to(fn(*[sub[str(a)] for a in out.args]), (len(check),))
        err = float(np.max(relative_errors(value, exact)))
        rows.append(BenchRow(d.id, out.name, "generated", seconds, points, err, 1.0,
                             _over_peak(value, exact)))
        floor_arg = np.asarray(args[0], dtype=float) * np.ones(points)
        floor = _best_time(lambda: np.cos(floor_arg))
        rows.append(BenchRow(d.id, out.name, "np.cos floor", floor, points, float("nan"),
                             floor / seconds))
        for system in d.ode_systems:
            names = dict(system.quantities)
            if out.name not in names:
                continue
            rows += _integrators(d, out, system, grid, check, exact, seconds,
                                 methods, rtols, solve_ivp, odeint)
    return rows


def _integrators(d, out, system, grid, check, exact, generated_seconds,
                 methods, rtols, solve_ivp, odeint) -> list[BenchRow]:
    params = [e.expr for e in d.symbols if e.role == "parameter" and e.name in grid]
    f, y0f, quantities = _first_order(system, params)
    pvals = [float(grid[str(p)]) for p in params]
    t = grid["t"]
    y0 = np.array(y0f(*pvals), dtype=float)
    probe = solve_ivp(f, (0, t[-1]), y0, method="DOP853", t_eval=t, args=tuple(pvals),
                      rtol=1e-10, atol=1e-30)
    scale = np.maximum(np.max(np.abs(probe.y), axis=1), 1e-300)
    rows = []

    def row(method: str, seconds: float, states: np.ndarray) -> BenchRow:
        values = np.broadcast_to(quantities[out.name](states[:, check], *pvals), (len(check),))
        err = float(np.max(relative_errors(values, exact)))
        return BenchRow(d.id, out.name, f"{method} [{system.name}]", seconds, len(t), err,
                        seconds / generated_seconds, _over_peak(values, exact))

    for rtol in rtols:
        atol = rtol * scale
        for method in methods:
            t0 = time.perf_counter()
            sol = solve_ivp(f, (0, t[-1]), y0, method=method, t_eval=t, args=tuple(pvals),
                            rtol=rtol, atol=atol)
            rows.append(row(f"{method} rtol={rtol:g}", time.perf_counter() - t0, sol.y))
        t0 = time.perf_counter()
        ys = odeint(f, y0, np.concatenate(([0.0], t)), args=tuple(pvals), tfirst=True,
                    rtol=rtol, atol=atol, mxstep=10**6)
        rows.append(row(f"odeint rtol={rtol:g}", time.perf_counter() - t0, ys[1:].T))
    return rows


def as_dicts(rows: Sequence[BenchRow]) -> list[dict]:
    """JSON-ready rows (keys function, method, seconds, points, max_rel_error, ...)."""
    return [asdict(r) for r in rows]


def as_markdown(rows: Sequence[BenchRow]) -> str:
    """One Markdown table per derivation."""
    lines = ["| function | method | evals/s | max rel. error | max error / peak | time / generated |",
             "| --- | --- | ---: | ---: | ---: | ---: |"]
    for r in rows:
        lines.append(f"| {r.function} | {r.method} | {r.points / r.seconds:.3g} | "
                     f"{r.max_rel_error:.2e} | {r.max_error_over_peak:.2e} | "
                     f"{r.ratio_to_generated:.3g} |")
    return "\n".join(lines)


def headline(rows: Sequence[BenchRow], target: float = 1e-9) -> list[str]:
    """Per function: generated against the fastest integrator reaching
    ``target`` in the normwise error (error over the peak |value|)."""
    lines = []
    for name in dict.fromkeys(r.function for r in rows):
        mine = [r for r in rows if r.function == name]
        gen = next(r for r in mine if r.method == "generated")
        ok = [r for r in mine if r.method not in ("generated", "np.cos floor")
              and r.max_error_over_peak <= target]
        text = (f"{name}: {gen.points / gen.seconds:.3g} evals/s, max rel. error "
                f"{gen.max_rel_error:.1e}")
        if any(r.method not in ("generated", "np.cos floor") for r in mine):
            if ok:
                best = min(ok, key=lambda r: r.seconds)
                text += (f"; fastest integrator within {target:g} of the peak: "
                         f"{best.method}, {best.ratio_to_generated:.3g}x slower")
            else:
                text += f"; no integrator came within {target:g} of the peak"
        lines.append(text)
    return lines


def plot(rows: Sequence[BenchRow], path: Path, title: str) -> Path:
    """Work-precision plot: time against error, log-log, one panel per function."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    names = [n for n in dict.fromkeys(r.function for r in rows)
             if any(r.method not in ("generated", "np.cos floor") for r in rows if r.function == n)]
    fig, axes = plt.subplots(len(names), 1, figsize=(8, 3.4 * max(len(names), 1)), squeeze=False)
    for ax, name in zip(axes[:, 0], names):
        mine = [r for r in rows if r.function == name]
        by_method: dict[str, list[BenchRow]] = {}
        for r in mine:
            if r.method in ("generated", "np.cos floor"):
                continue
            key = r.method.split(" rtol=")[0] + " " + r.method.split("] ")[0].split("[")[-1]
            by_method.setdefault(key, []).append(r)
        for key, rs in sorted(by_method.items()):
            ax.loglog([max(r.max_rel_error, 1e-17) for r in rs], [r.seconds for r in rs],
                      marker="o", label=key)
        gen = next(r for r in mine if r.method == "generated")
        ax.loglog([max(gen.max_rel_error, 1e-17)], [gen.seconds], marker="*", ms=14,
                  color="k", linestyle="none", label="generated closed form")
        ax.set(title=name, xlabel="max relative error", ylabel="seconds")
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=6, ncol=2)
    fig.suptitle(title)
    fig.tight_layout()
    fig.savefig(path, dpi=110, metadata={"Software": None})
    plt.close(fig)
    return path
