"""Window-by-window evaluation: the kernels that partition the points, and a
generated piecewise function against np.select on sorted, unsorted,
broadcast, scalar and out= inputs."""
import numpy as np
import pytest

from crane_sym.kernels.cells import _at, _cells, _put, _selector
from crane_sym.generated import hoist_startup as gen


def test_selector_is_a_slice_for_contiguous_points_and_indices_else():
    assert _selector(np.zeros(5, bool)) is None
    assert _selector(np.array([0, 1, 1, 1, 0], bool)) == slice(1, 4)
    assert _selector(np.ones(3, bool)) == slice(0, 3)
    assert _selector(np.array([1, 0, 1], bool)).tolist() == [0, 2]


@pytest.mark.parametrize("t", [np.linspace(0, 4, 41), np.random.default_rng(3).uniform(0, 4, 41)])
def test_cells_partition_like_the_first_true_condition(t):
    a, b = np.less_equal(t, 1.5), np.less_equal(t, 3.0)
    cells = _cells(t.shape, [[a], [b]])
    label = np.full(t.size, -1)
    for k, where in enumerate(cells):
        if where is not None:
            assert (label[where] == -1).all()          # every point in one cell only
            label[where] = k
    expected = np.select([a & b, a & ~b, ~a & b, ~a & ~b], [0, 1, 2, 3])
    assert (label == expected).all()


def test_at_broadcasts_arrays_and_keeps_scalars():
    t, p = np.arange(6.0).reshape(3, 2), np.array([10.0, 20.0])
    where = np.array([1, 4])
    tt, pp, s = _at(where, (3, 2), t, p, np.float64(7.0))
    assert tt.tolist() == [1.0, 4.0] and pp.tolist() == [20.0, 10.0] and s == 7.0


def test_put_writes_a_non_contiguous_buffer():
    base = np.zeros((4, 6))
    out = base[:, ::2]
    _put(out, np.array([0, 5]), np.array([1.0, 2.0]))
    assert out.reshape(-1)[[0, 5]].tolist() == [1.0, 2.0] and base.sum() == 3.0


def _reference(t, omega, theta):
    """The same function by np.select over every point (both branches everywhere)."""
    x0 = omega * theta
    before = (1 / (omega * theta)) * gen._entire_4(gen._exact_phase(omega, t))
    after = gen._offset_wave(1, gen._entire_1(x0), gen._entire_2(x0), gen._entire_3(x0),
                             gen._exact_phase(omega, t, theta))
    return np.select([t <= theta, True], [before, after])


@pytest.mark.parametrize("t", [np.linspace(0, 3, 301), np.random.default_rng(5).uniform(0, 3, 301)])
def test_piecewise_function_matches_every_branch_everywhere(t):
    got = gen.dynamic_coefficient_ramp_hold(t, 7.0, 0.4)
    assert np.array_equal(got, _reference(t, 7.0, 0.4))
    buffer = np.empty((301, 2))[:, 0]                  # a strided out= buffer
    assert gen.dynamic_coefficient_ramp_hold(t, 7.0, 0.4, out=buffer) is buffer
    assert np.array_equal(buffer, got)
    for k in (0, 40, 300):                             # scalars: the one branch
        assert gen.dynamic_coefficient_ramp_hold(float(t[k]), 7.0, 0.4) == got[k]


def test_piecewise_function_broadcasts_window_edges():
    t = np.linspace(0, 3, 31)[:, None]
    theta = np.array([0.2, 0.5, 1.0])
    got = gen.dynamic_coefficient_ramp_hold(t, 7.0, theta)
    assert got.shape == (31, 3)
    assert np.array_equal(got, _reference(t, 7.0, theta))
