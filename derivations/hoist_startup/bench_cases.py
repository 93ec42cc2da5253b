"""Bench cases of paper 002 (``crane_sym.bench.cases``).

- Sweep: the peak factor of the ramp-hold load (48)–(53) over Ω × θ, against
  integrating the relative coordinate (2) through the ramp and 1.1 periods
  after it; masses of scene ``hoist_fig5`` (no shipped scene gives θ).
- Sampled loads: K(t) of the ramp (40)–(42) and of the ramp-hold (48)–(53),
  K = x/x_st with x_st = S0/Ω², at Ω = 31 rad/s, t_п = 1.5 s, θ = 0.5 s.
"""
from __future__ import annotations

import numpy as np

from crane_sym.bench.cases import SampledBenchCase, SweepBenchCase


def _design(values):
    from crane_sym.generated.hoist_startup import ramp_hold_peak_factor
    Omega, theta = values["Omega"], values["theta"]
    pieces = [theta, theta + 1.1 * 2 * np.pi / Omega]
    return values, pieces, ramp_hold_peak_factor(Omega, theta)


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
