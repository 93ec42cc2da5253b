"""Window-by-window evaluation: the kernels that partition the points, and a
generated piecewise function against np.select on sorted, unsorted,
broadcast, scalar and out= inputs; block-by-block evaluation (``_spans``) of
the functions without windows, against the whole-array formula, and their
peak memory."""
import numpy as np
import pytest

from crane_sym.bench.memory import peak_bytes
from crane_sym.kernels.cells import _at, _cells, _put, _selector, _spans
from crane_sym.generated import drum_drive
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


def test_spans_blocks_full_contiguous_arrays_and_keeps_the_rest_whole():
    out, t, k = np.empty(40000), np.arange(40000.0), np.float64(2.0)
    spans = _spans(out, out.shape, t, k, size=16384)
    assert [o.size for o, _ in spans] == [16384, 16384, 7232]
    assert all(np.shares_memory(o, out) and v[1] is k for o, v in spans)
    assert spans[2][1][0][0] == 32768.0                # the values sliced with the piece
    grid = np.empty((200, 300))
    for values in ((np.arange(300.0),), (np.empty((300, 200)).T,)):   # broadcast, strided
        (whole,) = _spans(grid, grid.shape, *values)
        assert whole[0] is grid and whole[1][0] is values[0]


@pytest.mark.parametrize("size", [1, 16384, 40001])
def test_blocked_functions_equal_the_formula_on_the_whole_array(size):
    t = np.linspace(0.0, 5.0, size)
    whole = -1 / (25.0 * 1.0) * gen._sin_remainder(25.0 * t, 1)
    assert np.array_equal(gen.dynamic_coefficient_ramp(t, 25.0, 1.0), whole)
    buffer = np.empty((size, 2))[:, 1]                 # a strided out=: one piece
    assert gen.dynamic_coefficient_ramp(t, 25.0, 1.0, out=buffer) is buffer
    assert np.array_equal(buffer, whole)
    a4 = -60 / 1.5**5 * t**2 * (t - 1.5)**3
    np.testing.assert_allclose(gen.optimal_coefficient_from_weight_a4(t, 1.5), a4,
                               rtol=1e-13, atol=1e-13 * np.abs(a4).max())
    assert np.ndim(gen.dynamic_coefficient_ramp(np.float64(0.3), 25.0, 1.0)) == 0


def test_in_place_chains_need_their_input_and_output_only():
    """Peak traced memory of the three chains the fast-path targets name: at
    most twice the input plus the output (bench.memory's limit)."""
    t = np.linspace(0.0, 5.0, 200_000)
    calls = {"ramp": lambda: gen.dynamic_coefficient_ramp(t, 25.0, 1.0),
             "a4": lambda: gen.optimal_coefficient_from_weight_a4(t, 1.5),
             "pulsating": lambda: drum_drive.pulsating_force(
                 t, 1200.0, 1200.0, 600.0, 600.0, 800.0, 800.0, 400.0, 400.0, 3.0)}
    for name, call in calls.items():
        peak, output = peak_bytes(call)
        assert output == t.nbytes and peak <= 2 * t.nbytes + output, (name, peak)
