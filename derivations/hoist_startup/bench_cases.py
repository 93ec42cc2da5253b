"""Bench cases of paper 002 (``crane_sym.bench.cases``).

- Sweep: the peak factor of the ramp-hold load (48)–(53) over Ω × θ, against
  integrating the relative coordinate (2) through the ramp and 1.1 periods
  after it; masses of scene ``hoist_fig5`` (no shipped scene gives θ).
- Sampled loads: K(t) of the ramp (40)–(42) and of the ramp-hold (48)–(53),
  K = x/x_st with x_st = S0/Ω², at Ω = 31 rad/s, t_п = 1.5 s, θ = 0.5 s.
- Hand-written NumPy: K(t) of the ramp-hold (51)–(52) as a careful hand writes
  it to the generated function's accuracy (exact phase, a sine and a cosine a
  point): the floor the piecewise target against ``np.cos`` is read beside.
"""
from __future__ import annotations

import math

import numpy as np

from crane_sym.bench.cases import SampledBenchCase, SweepBenchCase


def _design(values):
    from crane_sym.generated.hoist_startup import ramp_hold_peak_factor
    Omega, theta = values["Omega"], values["theta"]
    pieces = [theta, theta + 1.1 * 2 * np.pi / Omega]
    return values, pieces, ramp_hold_peak_factor(Omega, theta)


#: Dekker's split (2**27 + 1) and the block of points the hand-written
#: version works on (the generated functions' ``_blocks``).
_SPLIT, _BLOCK = 134217729.0, 16384
#: x − sin x = Σ_{k≥1} (−1)^(k+1) x^(2k+1)/(2k+1)!, by its series where |x| < 2.38.
_SERIES = tuple((-1.0) ** (k + 1) / math.factorial(2 * k + 1) for k in range(1, 14))


def _exact_product(a, b):
    """a*b as hi + lo exactly (Dekker's TwoProduct)."""
    p = a * b
    ah = a * _SPLIT
    ah -= ah - a
    bh = b * _SPLIT
    bh -= bh - b
    al, bl = a - ah, b - bh
    return p, ((ah * bh - p) + ah * bl + al * bh) + al * bl


def _sin_cos(hi, lo):
    """sin and cos of the phase hi + lo (|lo| below an ulp of hi)."""
    s, c = np.sin(hi), np.cos(hi)
    return s + c * lo, c - s * lo


def _ramp(t, Omega, a):
    """(Ωt − sin Ωt)/(Ωθ), eq (51): the phase exact, the series near 0."""
    hi, lo = _exact_product(Omega, t)
    value = hi - _sin_cos(hi, lo)[0]
    small = hi < 2.38
    if small.any():
        x = hi[small]
        x2, total = x * x, np.full_like(x, _SERIES[-1])
        for coefficient in _SERIES[-2::-1]:
            total = total * x2 + coefficient
        value[small] = total * x2 * x
    return value / a


def _hold(t, Omega, theta, b, c):
    """1 + b cos Ω(t − θ) + c sin Ω(t − θ), eq (52), the phase exact (TwoSum
    of t − θ, TwoProduct by Ω)."""
    d = t - theta
    v = d - t
    err = (t - (d - v)) + (-theta - v)
    p, pe = _exact_product(Omega, d)
    pe += Omega * err
    hi = p + pe
    s, co = _sin_cos(hi, pe - (hi - p))
    return 1.0 + (b * co + c * s)


def ramp_hold_numpy(t, Omega, theta):
    """K(t) of the ramp-hold, eqs (51)–(52), written by hand in NumPy to the
    generated function's accuracy: the phase exact (a double-double Ωt and
    Ω(t − θ)), one np.sin and one np.cos a point, x − sin x by its series
    near 0, a block of 16384 points at a time. It leaves out the generated
    function's case where the hold cancels (K below 1/2, only when
    Ωθ < 3.8) and refuses it; a scalar Ω and θ, a 1-D ``t``."""
    a = Omega * theta
    if a < 3.8:
        raise ValueError(f"ramp_hold_numpy: Omega*theta must be >= 3.8 (K >= 1/2), got {a!r}")
    b, c = -math.sin(a) / a, 2.0 * math.sin(0.5 * a) ** 2 / a
    out = np.empty_like(t)
    for i in range(0, t.size, _BLOCK):
        tb, ob = t[i:i + _BLOCK], out[i:i + _BLOCK]
        ramp = tb <= theta
        if ramp.all():
            ob[:] = _ramp(tb, Omega, a)
        elif not ramp.any():
            ob[:] = _hold(tb, Omega, theta, b, c)
        else:
            ob[ramp] = _ramp(tb[ramp], Omega, a)
            ob[~ramp] = _hold(tb[~ramp], Omega, theta, b, c)
    return out


#: Generated functions with a hand-written NumPy version (``crane_sym.bench.cases``).
HAND_WRITTEN = {"dynamic_coefficient_ramp_hold": ramp_hold_numpy}

SWEEP_BENCH_CASES = (
    SweepBenchCase("ramp_hold_peak_factor", ("Omega=5:50:{n}:log", "theta=0.05:1:{n}"), None,
                   "relative coordinate, (2): dynamic_coefficient_ramp_hold",
                   "dynamic_coefficient_ramp_hold", _design,
                   fixed={"m1": 2e3, "m2": 8e3, "g": 9.81},
                   units={"Omega": "rad/s", "theta": "s"}),
)


def SAMPLED_BENCH_CASES():
    """K(t) of the ramp and the ramp-hold, S0 = 1 (K scales x by Ω²)."""
    from crane_sym.generated import hoist_startup as gen
    Omega, t_n, theta = 31.0, 1.5, 0.5
    return (SampledBenchCase("hoist_startup.dynamic_coefficient_ramp", "ramp", Omega, 1.0, t_n,
                             2.0 ** -12, lambda t: gen.dynamic_coefficient_ramp(t, Omega, t_n),
                             Omega ** 2),
            SampledBenchCase("hoist_startup.dynamic_coefficient_ramp_hold", "ramp_hold", Omega,
                             1.0, theta, 2.0 ** -12,
                             lambda t: gen.dynamic_coefficient_ramp_hold(t, Omega, theta),
                             Omega ** 2))
