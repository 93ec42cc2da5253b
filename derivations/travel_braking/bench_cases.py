"""Bench cases of paper 000 (``crane_sym.bench.cases``).

- Sweep: the peak elastic force (14) over m1 × P_t of scene
  ``overhead_crane_50t``, against integrating the relative coordinate (4)
  over a period and a quarter of (6) (the peak comes at half a period).
- Sampled load: the elastic force (14) of the same crane from its constant
  reduced load S = P_t/m1 − W/m2 (paper 002's eq (2) in this paper's symbols).
"""
from __future__ import annotations

import numpy as np

from crane_sym.bench.cases import SampledBenchCase, SweepBenchCase


def _design(values):
    from crane_sym.generated.travel_braking import natural_frequency, peak_elastic_force
    period = 2 * np.pi / natural_frequency(values["m1"], values["m2"], values["c"])
    exact = peak_elastic_force(values["m1"], values["m2"], values["P_t"], values["W"])
    return values, [1.25 * period], exact


SWEEP_BENCH_CASES = (
    SweepBenchCase("peak_elastic_force", ("m1=1:100:{n}:log", "P_t=5:50:{n}"),
                   "overhead_crane_50t", "relative coordinate, (4)", "elastic_force", _design,
                   response=("elastic_force", "t=0.1")),
)


def SAMPLED_BENCH_CASES():
    """The scene's crane (m1 = 4.4 t, m2 = 110 t, c = 3 MN/m, P_t = 24 kN, W = 11 kN)."""
    import mpmath

    from crane_sym.generated import travel_braking as gen
    m1, m2, c, P_t, W = 4.4e3, 110e3, 3e6, 24e3, 11e3

    def exact():                        # Ω of (6) and S from the doubles, exactly
        M1, M2, C, P, Q = (mpmath.mpf(v) for v in (m1, m2, c, P_t, W))
        return mpmath.sqrt(C * (M1 + M2) / (M1 * M2)), P / M1 - Q / M2

    return (SampledBenchCase("travel_braking.elastic_force", "step",
                             float(gen.natural_frequency(m1, m2, c)), P_t / m1 - W / m2, 1.0,
                             2.0 ** -17, lambda t: gen.elastic_force(t, m1, m2, c, P_t, W), c,
                             exact),)
