"""The shared sines of a phase, the merged waves of a cell and their checked
fallback, and the block-wise evaluation of cells: each against mpmath or
against the per-wave formula it replaces."""
import mpmath
import numpy as np
import pytest
import sympy as sp

from crane_sym.kernels import phase as k
from crane_sym.kernels.cells import _blocks, _cancelled, _selector
from crane_sym.generated import hoist_startup as gen
from crane_sym.codegen.wave_sums import merge_waves
from crane_sym.codegen.waves import exact_phase, offset_wave, phase_cos, phase_sin, wave

rng = np.random.default_rng(11)
t, W, c1, c2 = sp.symbols("t W c1 c2", positive=True)
b1, b2, g1, g2, a1 = sp.symbols("b1 b2 g1 g2 a1", real=True)


def test_a_phase_keeps_its_sines_and_they_equal_fresh_ones():
    kk, tt = 25.0, np.linspace(0, 40, 1001)
    phase = k._exact_phase(kk, tt, 0.3)
    first = k._sincos_pair(phase, 1.0)
    assert k._sincos_pair(phase, 1.0)[0] is first[0]          # taken once
    fresh = k._sincos_pair(tuple(phase), 1.0)                  # a plain pair: no cache
    assert np.array_equal(first[0], fresh[0]) and np.array_equal(first[1], fresh[1])
    assert np.array_equal(k._sin_pair(phase, 0.5), k._sincos_pair(tuple(phase), 0.5)[0])


@pytest.mark.parametrize("fn, exact", [(k._sin_half_squared, lambda z: mpmath.sin(z / 2) ** 2),
                                       (k._cos_half_squared, lambda z: mpmath.cos(z / 2) ** 2)])
def test_half_angle_squares_from_the_shared_sines(fn, exact):
    # tiny phases, phases next to 2πj and (2j+1)π where one form cancels, large phases
    with mpmath.workdps(50):
        zs = [mpmath.mpf(10) ** -e for e in range(1, 12)]
        zs += [mpmath.pi * j + off for j in (1, 2, 7, 300)
               for off in (mpmath.mpf("1e-9"), mpmath.mpf("-3e-6"), mpmath.mpf("0.4"))]
        for z in zs:
            hi = float(z)
            got = fn((hi, float(z - hi)))
            want = exact(z)
            assert abs(got - want) <= 6e-16 * abs(want) + 1e-32, z


def test_offset_wave_falls_back_only_where_the_direct_sum_cancels():
    # level + b cos x + c sin x, swinging down to 1e-9 of the level: the
    # direct sum is kept where it is at least half the level, the
    # cancellation-free form (_offset_back) is taken elsewhere
    b, c = 0.6, -0.8
    level = 1.0 + 1e-9
    gap = float(mpmath.mpf(level) ** 2 - 1)
    x = np.linspace(0.0, 30.0, 4001)
    got = k._offset_wave(level, gap, b, c, (x, 0.0 * x))
    back = k._offset_back(level, gap, b, c, (x, 0.0 * x))
    direct = level + (b * np.cos(x) + c * np.sin(x))
    near = np.abs(direct) < 0.5 * level
    assert near.any() and (~near).any()
    assert np.array_equal(got[near], back[near])
    assert np.array_equal(got[~near], direct[~near])


def test_blocks_cover_a_selector_once_in_order():
    assert _blocks(None) == ()
    parts = _blocks(slice(3, 40_003))
    covered = np.concatenate([np.arange(40_003)[p] for p in parts])
    assert covered.tolist() == list(range(3, 40_003)) and all(
        p.stop - p.start <= 16384 for p in parts)
    index = np.flatnonzero(rng.uniform(size=50_000) < 0.7)
    assert np.array_equal(np.concatenate(_blocks(index)), index)


def test_cancelled_marks_points_below_half_the_bound():
    v = np.array([1.0, 0.2, -0.3, 0.9])
    assert np.arange(4)[_cancelled(v, 1.0)].tolist() == [1, 2]
    assert _cancelled(v, 0.1) is None
    assert _cancelled(np.array([0.1, 0.2, 5.0]), 1.0) == slice(0, 2)


def _cell():
    """A level, a wave switched on at c1, an offset wave at c2, a term in W·t."""
    p1, p2, p0 = exact_phase(W, t, c1), exact_phase(W, t, c2), exact_phase(W, t, 0)
    return (a1 + wave(b1, g1, p1) + 2 * offset_wave(1, 0, b2, g2, p2)
            + 3 * phase_sin(p0, sp.Rational(1, 2)) ** 2)


def test_merged_cell_equals_the_cell_and_its_bound_bounds_the_parts():
    cell = _cell()
    merged, bound = merge_waves(cell, t)
    assert len(merged.atoms(exact_phase) - {exact_phase(W, t, 0)}) == 2   # only the shifts
    def as_trig(e):
        e = e.replace(wave, lambda b, c, x: b * sp.cos(x) + c * sp.sin(x))
        e = e.replace(offset_wave, lambda lv, gp, b, c, x: lv + b * sp.cos(x) + c * sp.sin(x))
        e = e.replace(phase_sin, lambda z, q: sp.sin(q * z))
        e = e.replace(phase_cos, lambda z, q: sp.cos(q * z))
        return e.replace(exact_phase, lambda kk, tt, cc: kk * (tt - cc))

    for _ in range(20):
        values = {W: rng.uniform(1, 60), t: rng.uniform(0, 5), c1: rng.uniform(0, 2),
                  c2: rng.uniform(0, 2), a1: rng.normal(), b1: rng.normal(), b2: rng.normal(),
                  g1: rng.normal(), g2: rng.normal()}
        want, got = as_trig(cell).subs(values), as_trig(merged).subs(values)
        assert abs(float(got - want)) <= 1e-12 * (1 + abs(float(want)))
        parts = abs(values[a1]) + abs(values[b1]) + abs(values[g1]) + 2 * (
            1 + abs(values[b2]) + abs(values[g2]))
        assert abs(float(bound.subs(values)) - parts) <= 1e-12 * parts


def test_a_lone_wave_on_its_own_phase_is_left_alone():
    assert merge_waves(wave(b1, g1, exact_phase(W, t, c1)) + a1, t) is None


def test_generated_cells_redo_cancelled_points_with_their_own_formula():
    # pickup a1 after both switches: the merged sum is the fast path; where it
    # cancels (forced here by a bound that marks every point) the per-wave
    # formula must give the same values to a few ulp
    args = (25.0, 0.31392, 2000.0, 8000.0, 9.81, 0.25, 1.0)
    tt = np.linspace(1.05, 40.0, 30_001)
    fast = gen.dynamic_coefficient_pickup_a1(tt, *args)
    original = gen._cancelled
    try:
        gen._cancelled = lambda value, bound: _selector(np.ones(value.size, bool))
        redone = gen.dynamic_coefficient_pickup_a1(tt, *args)
    finally:
        gen._cancelled = original
    assert np.max(np.abs(fast - redone) / np.abs(redone)) < 4e-15
