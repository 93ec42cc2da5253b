"""Tests for crane_sym.mechanics.extrema: symbolic and interval-verified maxima."""
import mpmath
import numpy as np
import pytest
import sympy as sp

from crane_sym.mechanics.extrema import (INTERVAL, SYMBOLIC, maximum_on_interval,
                                         minimum_on_interval)

t = sp.Symbol("t", real=True)
A, omega, S0, theta = sp.symbols("A omega S0 theta", positive=True)


def test_sine_with_parameters_symbolically():
    peak = maximum_on_interval(A * sp.sin(omega * t), t, 0, sp.pi / omega)
    assert peak.method == SYMBOLIC and peak.certified
    assert peak.value == A
    assert sp.simplify(sp.sin(omega * peak.location) - 1) == 0
    kinds = {c.kind for c in peak.candidates}
    assert kinds == {"endpoint", "critical point"}


def test_sine_with_phase_is_found_exactly_and_matches_interval_route():
    f = 3 * sp.sin(2 * t + sp.Rational(3, 10))
    exact = maximum_on_interval(f, t, 0, 5)
    assert exact.method == SYMBOLIC
    assert exact.value == 3
    assert sp.simplify(sp.sin(2 * exact.location + sp.Rational(3, 10)) - 1) == 0
    boxed = maximum_on_interval(f, t, 0, 5, symbolic=False)
    assert boxed.method == INTERVAL and boxed.certified
    assert abs(boxed.value - 3) < 1e-25
    assert abs(boxed.location - exact.location) < 1e-12   # a flat top: sqrt(eps) accuracy


@pytest.mark.parametrize("seed", [0, 1, 2, 3])
def test_symbolic_and_interval_routes_agree(seed):
    rng = np.random.default_rng(seed)
    w, phase, decay = (sp.Rational(int(rng.integers(5, 40)), 10) for _ in range(3))
    f = sp.exp(-decay * t / 4) * sp.sin(w * t + phase) + sp.Rational(1, 7)
    exact = maximum_on_interval(f, t, 0, 6)
    boxed = maximum_on_interval(f, t, 0, 6, symbolic=False)
    assert exact.method == SYMBOLIC and boxed.method == INTERVAL and boxed.certified
    assert abs(sp.N(exact.value, 40) - boxed.value) < 1e-25


def test_narrow_peak_missed_by_coarse_sampling_is_found():
    c = sp.Rational(2345, 1000)
    f = sp.sin(t) + sp.exp(-(1000 * (t - c)) ** 2)
    coarse = max(float(f.subs(t, x)) for x in np.linspace(0, 6, 61))
    peak = maximum_on_interval(f, t, 0, 6)
    assert peak.method == INTERVAL and peak.certified
    assert peak.value > coarse + 0.5              # sampling on the grid misses it
    # Independent: Newton on f' started at the peak centre, in mpmath.
    with mpmath.workdps(40):
        fp = sp.lambdify(t, f.diff(t), modules="mpmath")
        root = mpmath.findroot(fp, (mpmath.mpf(c) - mpmath.mpf("5e-4"), mpmath.mpf(c)),
                               solver="anderson")
        value = sp.lambdify(t, f, modules="mpmath")(root)
    assert abs(peak.location - sp.Float(root, 40)) < 1e-20
    assert abs(peak.value - sp.Float(value, 40)) < 1e-25


def test_undecided_boxes_make_the_result_uncertified():
    c = sp.Rational(2345, 1000)
    f = sp.sin(t) + sp.exp(-(1000 * (t - c)) ** 2)
    shallow = maximum_on_interval(f, t, 0, 6, boxes=4, max_depth=3)
    assert not shallow.certified
    assert "may exceed" in shallow.detail


def test_piecewise_maximum_at_a_breakpoint():
    f = sp.Piecewise((t ** 2, t < 1), (2 - t, True))
    peak = maximum_on_interval(f, t, 0, 3)
    assert (peak.value, peak.location) == (1, 1)
    assert any(c.kind == "breakpoint" for c in peak.candidates)


def test_piecewise_with_interval_route_and_parameters():
    # Duhamel response to a rectangular pulse (derived in test_duhamel); the
    # interval search and solveset must agree on it.
    f = sp.Piecewise((S0 * (1 - sp.cos(omega * t)) / omega ** 2, t < theta),
                     (S0 * (sp.cos(omega * (t - theta)) - sp.cos(omega * t)) / omega ** 2,
                      True))
    values = {"S0": 1, "omega": sp.Rational(3, 2), "theta": sp.Rational(4, 5)}
    exact = maximum_on_interval(f, t, 0, 10, parameters=values)
    boxed = maximum_on_interval(f, t, 0, 10, parameters=values, symbolic=False)
    assert exact.method == SYMBOLIC and boxed.method == INTERVAL
    assert abs(sp.N(exact.value, 40) - boxed.value) < 1e-25
    assert abs(sp.N(exact.location, 40) - boxed.location) < 1e-12


def test_discontinuous_piecewise_gives_the_supremum():
    f = sp.Piecewise((t, t < 1), (t - 1, True))
    peak = maximum_on_interval(f, t, 0, sp.Rational(3, 2))
    assert (peak.value, peak.location) == (1, 1)


def test_piecewise_value_at_the_right_end_comes_from_the_piece_holding_there():
    f = sp.Piecewise((t, t < 1), (2, True))
    assert maximum_on_interval(f, t, 0, 1).value == 2
    assert maximum_on_interval(f, t, 1, 1).value == 2
    g = sp.Piecewise((t, t <= 1), (t - 5, t < 3), (7, True))
    assert maximum_on_interval(g, t, 0, 2).value == 1
    assert maximum_on_interval(g, t, 0, 3).value == 7


def test_minimum():
    low = minimum_on_interval(sp.cos(t), t, 0, 2 * sp.pi)
    assert (low.value, low.location) == (-1, sp.pi)


def test_validation():
    with pytest.raises(ValueError, match="empty"):
        maximum_on_interval(sp.sin(t), t, 2, 1)
    with pytest.raises(ValueError, match=r"values for \['A'\]"):
        maximum_on_interval(A * sp.cos(t) + t ** 2 * sp.sin(t), t, 0, 3)
    with pytest.raises(TypeError):
        maximum_on_interval(A * sp.sin(t), t, 0, 3, parameters={A: "2"})
    with pytest.raises(ValueError, match="cannot decide"):
        maximum_on_interval(sp.Piecewise((t, t < theta), (theta, True)), t, 0, 1)
