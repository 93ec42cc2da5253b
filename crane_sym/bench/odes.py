"""SciPy's integrators on a derivation's ODE systems, as a user would run them.

Each system is put in first-order form by SymPy and lambdified with the
``math`` module (scalar calls are what the solvers make); the implicit
methods get the exact Jacobian. Every method runs once per tolerance with
``t_eval`` on the bench grid, and every quantity the system declares is read
off the same solution. ``atol`` is ``rtol`` times each state's peak |value|
(from one tight probe run), so the tolerance means the same for every state.
"""
from __future__ import annotations

import warnings
from typing import Iterator, Sequence

import numpy as np
import sympy as sp

from crane_sym.bench.rows import INTEGRATOR, BenchRow, Target, least_time
from crane_sym.derivation import ODESystem


def parameters(system: ODESystem) -> list[sp.Symbol]:
    """Symbols of ``system`` other than time, sorted by name."""
    t = time_symbol(system)
    exprs = [*system.equations, *(v for _, v in system.initial),
             *(q for _, q in system.quantities), *(law for _, law in system.inputs)]
    free = set().union(*(sp.sympify(e).free_symbols for e in exprs))
    free -= {t} | {s for s, _ in system.inputs}
    return sorted(free, key=str)


def time_symbol(system: ODESystem) -> sp.Symbol:
    return system.coordinates[0].args[0]


def first_order(system: ODESystem, params: Sequence[sp.Symbol], user: bool = False):
    """``f(t, y, *p)``, its Jacobian ``jac(t, y, *p)``, ``y0(*p)`` and the
    quantities ``{name: q(y, *p)}`` (NumPy, over columns of states). The
    right-hand side is generated code (``math`` on floats, a list), or with
    ``user`` as a user would write it: NumPy functions, an array returned."""
    t = time_symbol(system)
    q = list(system.coordinates)
    qd = [c.diff(t) for c in q]
    inputs = dict(system.inputs)
    equations = [e.subs(inputs) for e in system.equations]
    acc = sp.solve(equations, [c.diff(t, 2) for c in q], dict=True)[0]
    state = sp.symbols(f"y0:{2 * len(q)}")
    to_state = {**dict(zip(qd, state[len(q):])), **dict(zip(q, state[:len(q)]))}
    rhs = list(state[len(q):]) + [acc[c.diff(t, 2)].subs(to_state) for c in q]
    jac = sp.Matrix(rhs).jacobian(state)
    f = sp.lambdify((t, state, *params), rhs, modules="numpy" if user else "math")
    j = sp.lambdify((t, state, *params), jac.tolist(), modules="numpy" if user else "math")
    if user:
        f = _as_array(f)
    init = dict(system.initial)
    y0 = sp.lambdify(params, [init[c] for c in q] + [init[c] for c in qd], modules="math")
    quantities = {name: sp.lambdify((state, *params), expr.subs(to_state), modules="numpy")
                  for name, expr in system.quantities}
    return f, j, y0, quantities


def _as_array(f):
    def rhs(*args):
        return np.array(f(*args))
    return rhs


#: Methods that also run with the right-hand side a user would write (odeint always does).
USER_METHODS = ("DOP853",)
#: A run that needs more right-hand-side evaluations is stopped and reported.
MAX_EVALUATIONS = 2_000_000


class _OverBudget(RuntimeError):
    def __init__(self) -> None:
        super().__init__(f"more than {MAX_EVALUATIONS} right-hand-side evaluations")


def budgeted(f):
    """``f`` that raises after MAX_EVALUATIONS calls (a run that would not end)."""
    calls = [0]

    def counted(*args):
        calls[0] += 1
        if calls[0] > MAX_EVALUATIONS:
            raise _OverBudget
        return f(*args)
    return counted


def run(call) -> tuple[str, float, np.ndarray | None]:
    """(suffix, least seconds, states or None) of ``call()`` (see
    ``bench.rows.least_time``); a failed or stopped run is marked in the suffix."""
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            seconds, (states, ok) = least_time(call)
    except _OverBudget:
        return f" (stopped after {MAX_EVALUATIONS} evaluations)", float("nan"), None
    return ("" if ok else " (failed)"), seconds, states


def state_scale(f, span: tuple, y0: np.ndarray, t: np.ndarray, args: tuple = ()
                ) -> np.ndarray:
    """Peak |value| of each state from one probe run (DOP853, rtol 1e-8, atol
    1e-14: the states of these models are far above 1e-14 in SI, and a tinier
    atol would chase the rounding noise of states that start at exact rest).
    A state that stays near 0 gets 1e-9 of the largest peak."""
    from scipy.integrate import solve_ivp
    probe = solve_ivp(budgeted(f), span, y0, method="DOP853", t_eval=t, args=args, rtol=1e-8,
                      atol=1e-14)
    peak = np.max(np.abs(probe.y), axis=1)
    return np.maximum(peak, 1e-9 * max(peak.max(), 1e-300))


def solutions(system: ODESystem, compiled: tuple, p: tuple, grid: dict,
              methods: Sequence[str], rtols: Sequence[float]
              ) -> Iterator[tuple[str, float, np.ndarray]]:
    """(label, seconds, states at the grid times) for each method and tolerance;
    ``compiled`` is ``first_order(system, ...)``, ``p`` the parameter values."""
    f, jac, y0f, _ = compiled
    y0 = np.array(y0f(*p), dtype=float)
    yield from integrate(f, jac, y0, grid["t"], p, methods, rtols, system.name)
    fu, ju = first_order(system, parameters(system), user=True)[:2]
    yield from integrate(fu, ju, y0, grid["t"], p, [m for m in methods if m in USER_METHODS],
                         rtols, f"{system.name}; NumPy rhs")


def integrate(f, jac, y0: np.ndarray, t: np.ndarray, p: tuple, methods: Sequence[str],
              rtols: Sequence[float], name: str) -> Iterator[tuple[str, float, np.ndarray]]:
    """Each method at each tolerance, and odeint, from ``y0`` over the sorted
    times ``t``: (label, seconds, states; NaN for a failed run)."""
    from scipy.integrate import odeint, solve_ivp

    span = (0.0, float(t[-1]))
    scale = state_scale(f, span, y0, t, p)
    nan = np.full((len(y0), len(t)), np.nan)
    for rtol in rtols:
        atol = rtol * scale
        for method in methods:
            extra = {"jac": jac} if method in ("Radau", "LSODA", "BDF") else {}

            def ivp():
                sol = solve_ivp(budgeted(f), span, y0, method=method, t_eval=t, args=p,
                                rtol=rtol, atol=atol, **extra)
                return sol.y, sol.success
            note, seconds, states = run(ivp)
            yield (f"{method} rtol={rtol:g}{note} [{name}]", seconds,
                   nan if states is None or note else states)

        def lsoda():
            ys = odeint(budgeted(f), y0, np.concatenate(([0.0], t)), args=p, Dfun=jac,
                        tfirst=True, rtol=rtol, atol=atol, mxstep=10**6)
            return ys[1:].T, True
        note, seconds, states = run(lsoda)
        yield f"odeint rtol={rtol:g}{note} [{name}]", seconds, nan if states is None else states


def integrator_rows(system: ODESystem, grid: dict, targets: dict[str, Target],
                    methods: Sequence[str], rtols: Sequence[float]) -> list[BenchRow]:
    """Rows for every quantity of ``system`` that is a generated function."""
    params = parameters(system)
    compiled = first_order(system, params)
    quantities = compiled[-1]
    p = tuple(float(grid[str(s)]) for s in params)
    wanted = [name for name, _ in system.quantities if name in targets]
    rows = []
    for label, seconds, states in solutions(system, compiled, p, grid, methods, rtols):
        for name in wanted:
            target = targets[name]
            values = quantities[name](states[:, target.check], *p)
            rows.append(target.row(label, seconds, states.shape[1], values, INTEGRATOR))
    return rows
