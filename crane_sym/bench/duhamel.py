"""Duhamel's integral the ways a user would evaluate it numerically.

For a one-coordinate system x'' + Ω²x = S(t) (the relative coordinate of
Semenyuk and Vudvud's travel brake and Chovnyuk et al.'s hoist start-up),

    x(t) = x(0)·cos Ωt + ẋ(0)/Ω·sin Ωt + (1/Ω)·∫_0^t S(θ)·sin Ω(t − θ) dθ,

and each quantity the system declares in x is compared with its generated
closed form by:

- ``quad`` (QUADPACK QAGS, QAGP with the breakpoints of a piecewise S) on the
  whole integrand, one call per time;
- ``quad(weight='cos'/'sin')`` (QUADPACK QAWO): sin Ω(t − θ) = sin Ωt·cos Ωθ −
  cos Ωt·sin Ωθ, two weighted integrals of S per time and piece;
- a discrete convolution on a uniform grid of n steps with trapezoid weights,
  by FFT (``scipy.signal.fftconvolve``) and by cumulative sums of the two
  weighted integrands (``cumulative_trapezoid``), read at the bench times by
  linear interpolation.

Quadrature costs the same for every time, so it runs on the reference points
only (the row gives how many; ratios are per evaluation); the grid methods
give the whole grid at once.
"""
from __future__ import annotations

import math
import warnings
from dataclasses import dataclass
from typing import Callable, Sequence

import numpy as np
import sympy as sp

from crane_sym.bench.rows import DUHAMEL, BenchRow, Target, least_time
from crane_sym.bench.odes import parameters, time_symbol
from crane_sym.derivation import ODESystem

#: Steps of the uniform grid of the discrete convolutions.
GRID_STEPS = (2**8, 2**11, 2**14, 2**17)


@dataclass(frozen=True)
class DuhamelForm:
    """x'' + Ω²x = S(t) with x(0), ẋ(0), numerically, and the quantities in x."""

    omega: float
    load: Callable           # S on an array (NumPy)
    load_scalar: Callable    # S at one time (math)
    breaks: tuple[float, ...]
    x0: float
    v0: float
    quantities: dict[str, Callable]

    def free(self, t: np.ndarray) -> np.ndarray:
        """The response to the initial state."""
        w = self.omega
        return self.x0 * np.cos(w * t) + self.v0 / w * np.sin(w * t)


def duhamel_form(system: ODESystem, values: dict) -> DuhamelForm | None:
    """The form of ``system`` at ``values``, or None when it is not one
    undamped constant-coefficient equation in one coordinate."""
    if len(system.coordinates) != 1 or len(system.equations) != 1:
        return None
    t, x = time_symbol(system), system.coordinates[0]
    X2, X1, X0 = sp.symbols("X2 X1 X0", cls=sp.Dummy)

    def frozen(e: sp.Expr) -> sp.Expr:
        return sp.sympify(e).xreplace({x.diff(t, 2): X2, x.diff(t): X1}).xreplace({x: X0})

    eq = system.equations[0].subs(dict(system.inputs))
    residual = sp.expand(frozen(eq.lhs - eq.rhs))
    a2, a1, a0 = (residual.diff(s) for s in (X2, X1, X0))
    if a1 != 0 or any(c.has(t, X0, X1, X2) for c in (a2, a0)):
        return None
    params = parameters(system)
    p = [float(values[str(s)]) for s in params]
    number = lambda e: float(sp.sympify(e).subs(dict(zip(params, p))))  # noqa: E731
    load = -residual.subs({X2: 0, X1: 0, X0: 0}) / a2
    init = dict(system.initial)
    quantities = {}
    for name, q in system.quantities:
        q = frozen(q)
        if not q.has(X1, X2):
            quantities[name] = _bound(sp.lambdify((X0, *params), q, modules="numpy"), p)
    breaks = sorted({number(b) for b in _breakpoints(load, t)})
    return DuhamelForm(math.sqrt(number(a0 / a2)),
                       _bound(sp.lambdify((t, *params), load, modules="numpy"), p),
                       _bound(sp.lambdify((t, *params), load, modules="math"), p),
                       tuple(breaks), number(init[x]), number(init[x.diff(t)]), quantities)


def _bound(f: Callable, p: list) -> Callable:
    return lambda arg: f(arg, *p)


def _breakpoints(expr: sp.Expr, t: sp.Symbol) -> list[sp.Expr]:
    """Times where a Piecewise condition in ``expr`` changes (t < b, t <= b)."""
    found = []
    for pw in expr.atoms(sp.Piecewise):
        for _, cond in pw.args:
            for rel in cond.atoms(sp.core.relational.Relational) | (
                    {cond} if isinstance(cond, sp.core.relational.Relational) else set()):
                side = rel.rhs if rel.lhs == t else rel.lhs if rel.rhs == t else None
                if side is not None:
                    found.append(side)
    return found


def _quad_qags(form: DuhamelForm, times: np.ndarray, rtol: float) -> np.ndarray:
    from scipy.integrate import quad
    w, s = form.omega, form.load_scalar
    out = np.empty(len(times))
    for i, ti in enumerate(times):
        inner = [b for b in form.breaks if 0.0 < b < ti] or None
        out[i] = quad(lambda th: s(th) * math.sin(w * (ti - th)), 0.0, ti, points=inner,
                      epsrel=rtol, epsabs=0.0, limit=200)[0] / w
    return out


def _quad_qawo(form: DuhamelForm, times: np.ndarray, rtol: float) -> np.ndarray:
    from scipy.integrate import quad
    w, s = form.omega, form.load_scalar
    out = np.empty(len(times))
    for i, ti in enumerate(times):
        edges = [0.0, *(b for b in form.breaks if 0.0 < b < ti), ti]
        ic = is_ = 0.0
        for a, b in zip(edges, edges[1:]):
            ic += quad(s, a, b, weight="cos", wvar=w, epsrel=rtol, epsabs=0.0)[0]
            is_ += quad(s, a, b, weight="sin", wvar=w, epsrel=rtol, epsabs=0.0)[0]
        out[i] = (math.sin(w * ti) * ic - math.cos(w * ti) * is_) / w
    return out


def _samples(form: DuhamelForm, end: float, n: int) -> tuple[np.ndarray, np.ndarray]:
    tau = np.linspace(0.0, end, n + 1)
    return tau, np.broadcast_to(np.asarray(form.load(tau), dtype=float), tau.shape)


def _fft(form: DuhamelForm, times: np.ndarray, n: int) -> np.ndarray:
    from scipy.signal import fftconvolve
    tau, s = _samples(form, times[-1], n)
    dt, h = tau[1], np.sin(form.omega * tau) / form.omega
    # Trapezoid weights: the full sum less half of each end term (h(0) = 0).
    conv = fftconvolve(s, h)[:n + 1] * dt - 0.5 * dt * s[0] * h
    return np.interp(times, tau, conv)


def _cumulative(form: DuhamelForm, times: np.ndarray, n: int) -> np.ndarray:
    from scipy.integrate import cumulative_trapezoid
    tau, s = _samples(form, times[-1], n)
    w = form.omega
    ic = cumulative_trapezoid(s * np.cos(w * tau), tau, initial=0.0)
    is_ = cumulative_trapezoid(s * np.sin(w * tau), tau, initial=0.0)
    return np.interp(times, tau, (np.sin(w * tau) * ic - np.cos(w * tau) * is_) / w)


def _warm_up() -> None:
    """Import and call each SciPy routine once, so no row pays for a first call."""
    from scipy.integrate import cumulative_trapezoid, quad
    from scipy.signal import fftconvolve
    fftconvolve(np.ones(64), np.ones(64))
    cumulative_trapezoid(np.ones(8), initial=0.0)
    quad(math.cos, 0.0, 1.0, weight="sin", wvar=2.0)


def duhamel_rows(system: ODESystem, grid: dict, targets: dict[str, Target],
                 rtols: Sequence[float], steps: Sequence[int] = GRID_STEPS
                 ) -> list[BenchRow]:
    """Rows for every quantity of ``system`` that is a generated function, or
    none when ``system`` is not of Duhamel's form."""
    form = duhamel_form(system, grid)
    if form is None:
        return []
    wanted = [n for n in form.quantities if n in targets]
    if not wanted:
        return []
    t = grid["t"]
    check = targets[wanted[0]].check
    _warm_up()
    runs = []
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        for rtol in rtols:
            for label, method in (("quad QAGS", _quad_qags), ("quad QAWO sin/cos", _quad_qawo)):
                seconds, x = least_time(lambda: method(form, t[check], rtol)
                                        + form.free(t[check]))
                runs.append((f"{label} rtol={rtol:g}", seconds, len(check), x))
    for n in steps:
        for label, method in (("FFT convolution", _fft), ("cumulative trapezoid", _cumulative)):
            seconds, x = least_time(lambda: method(form, t, n) + form.free(t))
            runs.append((f"{label} n={n}", seconds, len(t), x[check]))
    return [targets[name].row(f"{label} [Duhamel's integral]", seconds, points,
                              form.quantities[name](x), DUHAMEL)
            for label, seconds, points, x in runs for name in wanted]
