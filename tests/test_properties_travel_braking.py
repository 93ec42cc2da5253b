"""Invariants of the generated paper-000 functions over extreme inputs
(Hypothesis, derandomized so every run sees the same examples)."""
import numpy as np
import pytest

hypothesis = pytest.importorskip("hypothesis")
from hypothesis import given, settings  # noqa: E402
from hypothesis import strategies as st  # noqa: E402

import crane_sym.generated.travel_braking as g  # noqa: E402

SETTINGS = settings(max_examples=150, deadline=None, derandomize=True)


def log_uniform(lo, hi):
    return st.floats(np.log10(lo), np.log10(hi)).map(lambda e: float(10.0 ** e))


masses = log_uniform(1e-2, 1e8)
stiffness = log_uniform(1e2, 1e10)
forces = log_uniform(1.0, 1e7)
phases = log_uniform(1e-9, 1e3)


@SETTINGS
@given(m1=masses, m2=masses, c=stiffness, P_t=forces, W=forces, phase=phases)
def test_force_stays_between_zero_and_twice_the_rigid_force(m1, m2, c, P_t, W, phase):
    t = phase / g.natural_frequency(m1, m2, c)
    F = g.elastic_force(t, m1, m2, c, P_t, W)
    F_r = g.rigid_link_force(m1, m2, P_t, W)
    if F_r == 0:
        assert F == 0
        return
    ratio = F / F_r
    assert -1e-15 <= ratio <= 2 * (1 + 1e-15)


@SETTINGS
@given(m1=masses, m2=masses, c=stiffness, P_t=forces, W=forces, phase=phases)
def test_swapping_the_masses_and_their_forces_flips_the_force(m1, m2, c, P_t, W, phase):
    t = phase / g.natural_frequency(m1, m2, c)
    a = g.elastic_force(t, m1, m2, c, P_t, W)
    b = g.elastic_force(t, m2, m1, c, W, P_t)
    assert abs(a + b) <= 1e-14 * max(abs(a), abs(b), 1e-300) * max(1.0, phase)


@SETTINGS
@given(m1=masses, m2=masses, c=stiffness, P_t=forces, W=forces,
       phase=log_uniform(1e-9, 1e-3))
def test_quadratic_start_without_cancellation(m1, m2, c, P_t, W, phase):
    # F = F_r (1 - cos pt) = F_r (pt)^2/2 (1 - (pt)^2/12 + ...)
    p = g.natural_frequency(m1, m2, c)
    F = g.elastic_force(phase / p, m1, m2, c, P_t, W)
    F_r = g.rigid_link_force(m1, m2, P_t, W)
    expected = F_r * phase ** 2 / 2 * (1 - phase ** 2 / 12)
    assert F == pytest.approx(expected, rel=1e-14, abs=0.0)


@SETTINGS
@given(m1=masses, m2=masses, c=stiffness, P_t=forces, W=forces, phase=phases,
       v0=log_uniform(0.01, 10))
def test_momentum_balance(m1, m2, c, P_t, W, phase, v0):
    # m1 v1 + m2 v2 = (m1 + m2) v0 - (P_t + W) t: the link force is internal.
    t = phase / g.natural_frequency(m1, m2, c)
    v1 = g.velocity_m1(t, m1, m2, c, P_t, W, v0)
    v2 = g.velocity_m2(t, m1, m2, c, P_t, W, v0)
    lhs = m1 * v1 + m2 * v2
    rhs = (m1 + m2) * v0 - (P_t + W) * t
    scale = (m1 + m2) * v0 + (P_t + W) * t + m1 * abs(v1) + m2 * abs(v2)
    assert abs(lhs - rhs) <= 1e-13 * scale


@SETTINGS
@given(m1=masses, m2=masses, c=stiffness, P_t=forces, W=forces)
def test_peak_is_the_force_at_the_peak_time(m1, m2, c, P_t, W):
    F_max = g.peak_elastic_force(m1, m2, P_t, W)
    at_peak = g.elastic_force(g.peak_time(m1, m2, c), m1, m2, c, P_t, W)
    assert at_peak == pytest.approx(F_max, rel=1e-14, abs=1e-300)
    assert F_max == pytest.approx(2 * g.rigid_link_force(m1, m2, P_t, W), rel=1e-15)
