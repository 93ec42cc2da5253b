"""Sampled loads against closed forms: exact references and a speed/accuracy bench.

``exact_response`` derives, once per load family, the response of
:math:`\\ddot x + \\Omega^2 x = S(t)` with SymPy (``crane_sym.mechanics.duhamel``) and
evaluates it in mpmath at exact double inputs: the reference for
``crane_sym.mechanics.sampled_load``. ``sampled_comparison`` times the sampled-load
response at N = 1e5 against the generated closed form of the same quantity
and against what a user would otherwise run (FFT convolution, cumulative
trapezoid quadrature, QUADPACK's sine-weighted rule), each judged on the
exact response to its own double inputs.
"""
from __future__ import annotations

import math
import time
import warnings
from dataclasses import dataclass
from functools import lru_cache
from typing import Callable, Sequence

import mpmath
import numpy as np
import sympy as sp

from crane_sym.bench.cases import sampled_cases
from crane_sym.markdown import markdown_table
from crane_sym.mechanics import loads
from crane_sym.mechanics.duhamel import duhamel
from crane_sym.mechanics.sampled_load import _uniform, sampled_response, sampled_response_uniform

T = sp.Symbol("t", nonnegative=True)
OMEGA = sp.Symbol("Omega", positive=True)
X0, V0, S0 = sp.symbols("x0 v0 S0", real=True)
T1 = sp.Symbol("t1", positive=True)
_ARGS = (T, OMEGA, X0, V0, S0, T1)


def family_load(name: str) -> loads.PiecewiseLoad:
    """The load of one family in the amplitude ``S0`` and the time ``t1``.

    ``step`` S0 (Chovnyuk et al., eq (35)); ``ramp`` S0 t/t1 without end (eq (40));
    ``ramp_hold`` up to S0 at t1, then held (eqs (48)–(49)); ``pulse`` S0
    until t1 (eq (44)); ``trapezoid`` a polynomial of degree 1 on each of
    [0, t1], [t1, 2t1], [2t1, 3t1], zero after (rise, hold, fall); ``cubic``
    S0 (t/t1)^3, which is *not* linear between samples.
    """
    if name == "step":
        return loads.step(S0, t=T)
    if name == "ramp":
        return loads.linear(S0 / T1, t=T)
    if name == "ramp_hold":
        return loads.ramp(S0, T1, t=T)
    if name == "pulse":
        return loads.rectangular_pulse(S0, T1, t=T)
    if name == "trapezoid":
        return loads.PiecewiseLoad((0, T1, 2 * T1, 3 * T1),
                                   (S0 * T / T1, S0, S0 * (3 - T / T1), 0), T)
    if name == "cubic":
        return loads.PiecewiseLoad((0,), (S0 * (T / T1) ** 3,), T)
    raise ValueError(f"unknown load family {name!r}")


FAMILIES = ("step", "ramp", "ramp_hold", "pulse", "trapezoid", "cubic")


@dataclass(frozen=True)
class ExactResponse:
    """The response to one load family, derived by ``crane_sym.mechanics.duhamel``.

    ``state`` takes mpf values (exact images of doubles) and times measured
    from the start of the load, :math:`s = t - t_0`; ``load`` holds the
    pieces of :math:`S` as NumPy functions of (s, S0, t1).
    """

    family: str
    breakpoints: tuple[Callable, ...]
    load: tuple[Callable, ...]
    x: tuple[Callable, ...]
    v: tuple[Callable, ...]

    def state(self, s, Omega, x0, v0, S0_, t1):
        """(x, x') at time s after the start."""
        k = max(j for j, b in enumerate(self.breakpoints) if s >= b(t1))
        args = (s, Omega, x0, v0, S0_, t1)
        return self.x[k](*args), self.v[k](*args)


@lru_cache(maxsize=None)
def exact_response(family: str) -> ExactResponse:
    """Derive the family's response symbolically (cached) and lambdify it for mpmath."""
    load = family_load(family)
    result = duhamel(load, OMEGA, T, u0=X0, v0=V0, simplify=False)

    def mp(expr):
        return sp.lambdify(_ARGS, expr, modules="mpmath")

    return ExactResponse(
        family,
        tuple(sp.lambdify((T1,), b, modules="mpmath") for b in result.load.breakpoints),
        tuple(sp.lambdify((T, S0, T1), p, modules="numpy") for p in result.load.pieces),
        tuple(mp(p.expr) for p in result.pieces),
        tuple(mp(p.expr) for p in result.velocity_pieces))


def mp_exact(x: float) -> mpmath.mpf:
    """The double ``x`` as an mpf, exactly (mpmath keeps all 53 bits of a float)."""
    return mpmath.mpf(float(x))


def reference(family: str, since: Sequence, Omega, S0_, t1, x0=0.0, v0=0.0,
              dps: int = 50) -> tuple[np.ndarray, np.ndarray]:
    """x and x' at the times ``since`` (from the start of the load), rounded to
    doubles. Every argument is a double, taken exactly, or an mpf."""
    exact = exact_response(family)
    with mpmath.workdps(dps):
        args = [a if isinstance(a, mpmath.mpf) else mp_exact(a)
                for a in (Omega, x0, v0, S0_, t1)]
        pairs = [exact.state(s if isinstance(s, mpmath.mpf) else mp_exact(s), *args)
                 for s in since]
    return (np.array([float(p[0]) for p in pairs]), np.array([float(p[1]) for p in pairs]))


def samples(family: str, since: np.ndarray, S0_: float, t1: float) -> np.ndarray:
    """The load of a family at the times ``since`` (from its start), in NumPy.
    Where a time is given twice (a jump), the first sample holds the value
    before the jump."""
    exact = exact_response(family)
    since = np.asarray(since, dtype=float)
    with mpmath.workdps(30):
        bps = np.array([float(b(mp_exact(t1))) for b in exact.breakpoints])
    piece = np.searchsorted(bps, since, side="right") - 1
    left = np.append(since[1:] == since[:-1], False)
    piece[left] = np.searchsorted(bps, since[left], side="left") - 1
    out = np.empty(since.shape)
    for k, f in enumerate(exact.load):
        mask = piece == k
        out[mask] = f(since[mask], S0_, t1)
    return out


# --- bench ---------------------------------------------------------------------------
@dataclass(frozen=True)
class SampledRow:
    """One way of computing one quantity on one record."""

    function: str
    method: str
    seconds: float
    points: int
    max_rel_error: float
    time_per_point_vs_closed_form: float = float("nan")


def _fft_convolution(S: np.ndarray, Omega: float, dt: float) -> np.ndarray:
    """x_k by the trapezoid rule written as one discrete convolution (FFT)."""
    from scipy.signal import fftconvolve
    g = np.sin(Omega * dt * np.arange(S.size)) / Omega
    x = fftconvolve(S, g)[:S.size] * dt
    x -= 0.5 * dt * S[0] * g          # end weight 1/2 at tau = t0 (g(0) = 0 at tau = t)
    return x


def _cumulative_trapezoid(t: np.ndarray, S: np.ndarray, Omega: float) -> np.ndarray:
    """x = (sin(wt) Ic(t) - cos(wt) Is(t))/w, Ic and Is the cumulative trapezoid
    integrals of cos(w tau) S and sin(w tau) S."""
    from scipy.integrate import cumulative_trapezoid
    phase = Omega * (t - t[0])
    c, s = np.cos(phase), np.sin(phase)
    ic = cumulative_trapezoid(c * S, t, initial=0.0)
    is_ = cumulative_trapezoid(s * S, t, initial=0.0)
    return (s * ic - c * is_) / Omega


def _quad_sine(t: np.ndarray, S: np.ndarray, Omega: float, where: np.ndarray) -> np.ndarray:
    """x(t_k) = (1/w) int_0^{t_k - t_0} sin(w u) S(t_k - u) du by QUADPACK's
    sine-weighted rule (QAWO), S linear between samples (np.interp)."""
    from scipy.integrate import IntegrationWarning, quad
    out = np.empty(where.size)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", IntegrationWarning)
        for i, k in enumerate(where):
            tk = t[k]
            out[i] = quad(lambda u: np.interp(tk - u, t, S), 0.0, tk - t[0], weight="sin",
                          wvar=Omega, limit=200)[0] / Omega
    return out


@dataclass(frozen=True)
class _Case:
    """A generated closed form and the sampled problem it solves."""

    function: str
    family: str
    Omega: float
    S0: float
    t1: float
    dt: float
    closed_form: Callable[[np.ndarray], np.ndarray]
    scale: float                      # quantity = scale * x
    exact_closed: Callable[[list], list]   # exact quantity for the closed form's inputs


def _cases() -> list[_Case]:
    """The cases the papers declare (``SAMPLED_BENCH_CASES``), each with the
    exact response to the closed form's own inputs."""
    cases = []
    for _, c in sampled_cases():
        def exact_closed(since, c=c):
            with mpmath.workdps(50):
                Omega, S0_ = c.exact() if c.exact else (mp_exact(c.Omega), mp_exact(c.S0))
                x = reference(c.family, [mp_exact(s) for s in since], Omega, S0_, c.t1)[0]
            return x * c.scale
        cases.append(_Case(c.name, c.family, c.Omega, c.S0, c.t1, c.step, c.closed_form,
                           c.scale, exact_closed))
    return cases


def _error(value: np.ndarray, exact: np.ndarray) -> float:
    return float(np.max(np.abs(value - exact)) / np.max(np.abs(exact)))


def _interleaved_best(functions: Sequence[Callable[[], object]], rounds: int = 25,
                      budget: float = 4.0) -> list[float]:
    """Least wall time of each function over ``rounds`` rounds that call every
    function once in turn, so that a busy machine slows all of them alike."""
    best = [math.inf] * len(functions)
    start = time.perf_counter()
    for r in range(rounds):
        for i, f in enumerate(functions):
            t0 = time.perf_counter()
            f()
            best[i] = min(best[i], time.perf_counter() - t0)
        if r >= 4 and time.perf_counter() - start > budget:
            break
    return best


def sampled_comparison(points: int = 100_000, reference_points: int = 2000,
                       quad_points: int = 20) -> list[SampledRow]:
    """Time and worst error of each way of computing each case on ``points``
    samples (N = points - 1 segments of a power-of-2 step, so that the times
    k*dt are exact doubles and both sampled routes see the same record).

    The error is the largest |computed - exact| over the checked samples
    divided by the largest |exact| there (relative to the peak), the exact
    value being the response to the method's own double inputs, by mpmath at
    50 digits; ``reference_points`` evenly spaced samples are checked. The
    QUADPACK rule runs on ``quad_points`` samples only, and its time is for
    those. Times are the least of interleaved repeats; the sampled routes
    return x and x', the closed form one quantity.
    ``time_per_point_vs_closed_form`` is seconds per point over the closed
    form's.

    Parameters
    ----------
    points : int, optional
        Number of samples.
    reference_points : int, optional
        Samples checked against mpmath.
    quad_points : int, optional
        Samples the QUADPACK rule runs on.
    """
    rows = []
    check = np.unique(np.linspace(0, points - 1, min(reference_points, points)).astype(int))
    quad_at = np.unique(np.linspace(0, points - 1, min(quad_points, points)).astype(int))
    for case in _cases():
        dt, Om, scale = case.dt, case.Omega, case.scale
        t = np.arange(points) * dt
        S = samples(case.family, t, case.S0, case.t1)
        exact = reference(case.family, t[check], Om, case.S0, case.t1)[0] * scale
        # the same load on times jittered by up to 0.3 dt (t1's multiples kept)
        kept = np.arange(points) % round(case.t1 / dt) == 0
        rng = np.random.default_rng(5)
        tj = np.where(kept, t, t + rng.uniform(-0.3, 0.3, points) * dt)
        Sj = samples(case.family, tj, case.S0, case.t1)
        exact_j = reference(case.family, tj[check], Om, case.S0, case.t1)[0] * scale
        methods = [
            ("closed form (generated)", lambda: case.closed_form(t)),
            ("sampled_response_uniform", lambda: sampled_response_uniform(dt, S, Om).x),
            ("sampled_response (times array)", lambda: sampled_response(t, S, Om).x),
            ("sampled_response (times array, jittered steps)",
             lambda: sampled_response(tj, Sj, Om).x),
            ("sampled_response_uniform, plain cumsum",
             lambda: _uniform(dt, S, Om, 0.0, 0.0, False, False).x),
            ("FFT convolution (scipy.signal.fftconvolve)", lambda: _fft_convolution(S, Om, dt)),
            ("cumulative trapezoid (scipy.integrate)", lambda: _cumulative_trapezoid(t, S, Om)),
        ]
        seconds = _interleaved_best([f for _, f in methods])
        closed_exact = np.asarray(case.exact_closed(list(t[check])), dtype=float)
        for (name, f), sec in zip(methods, seconds):
            value = np.asarray(f())[check]
            if name.startswith("closed form"):
                err = _error(value, closed_exact)
            elif "jittered" in name:
                err = _error(value * scale, exact_j)
            else:
                err = _error(value * scale, exact)
            rows.append(SampledRow(case.function, name, sec, points, err, sec / seconds[0]))
        t0 = time.perf_counter()
        q = _quad_sine(t, S, Om, quad_at) * scale
        sec = time.perf_counter() - t0
        q_exact = reference(case.family, t[quad_at], Om, case.S0, case.t1)[0] * scale
        rows.append(SampledRow(case.function, "scipy.integrate.quad weight='sin' (QAWO)", sec,
                               quad_at.size, _error(q, q_exact),
                               (sec / quad_at.size) / (seconds[0] / points)))
    return rows


def as_markdown(rows: Sequence[SampledRow]) -> str:
    """The rows as one Markdown table.

    Parameters
    ----------
    rows : sequence of SampledRow
        Rows from :func:`sampled_comparison`.
    """
    return markdown_table(
        ["function", "method", "points", "seconds", "time/point vs closed form",
         "max error / peak"],
        [[r.function, r.method, r.points, f"{r.seconds:.3g}",
          f"{r.time_per_point_vs_closed_form:.3g}", f"{r.max_rel_error:.2e}"] for r in rows],
        align="llrrrr")
