"""The numeric kernels generated modules carry, against mpmath."""
import math
from fractions import Fraction

import mpmath
import numpy as np
import pytest

from crane_sym.kernels import arithmetic as k
from crane_sym.kernels import phase as pk

rng = np.random.default_rng(7)


def test_two_product_is_exact():
    a, b = rng.uniform(-1e6, 1e6, 500), rng.uniform(-1e3, 1e3, 500)
    p, e = k._two_product(a, b)
    for ai, bi, pi, ei in zip(a, b, p, e):
        assert Fraction(pi) + Fraction(ei) == Fraction(ai) * Fraction(bi)


def test_two_sum_is_exact():
    a, b = rng.uniform(-1e6, 1e6, 500), rng.uniform(-1e-6, 1e-6, 500)
    s, e = k._two_sum(a, b)
    for ai, bi, si, ei in zip(a, b, s, e):
        assert Fraction(si) + Fraction(ei) == Fraction(ai) + Fraction(bi)


@pytest.mark.parametrize("gap", [1e-15, 1e-12, 1e-6, 1e-1, 1.0])
def test_diff_of_products_when_products_nearly_cancel(gap):
    a, b = rng.uniform(1e3, 1e6, 200), rng.uniform(1e3, 1e6, 200)
    c = rng.uniform(1e3, 1e6, 200)
    d = a * b / c * (1 + gap)
    got = k._diff_of_products(a, b, c, d)
    for ai, bi, ci, di, g in zip(a, b, c, d, got):
        exact = Fraction(ai) * Fraction(bi) - Fraction(ci) * Fraction(di)
        assert abs(Fraction(g) - exact) <= 4 * 2.0 ** -53 * abs(exact)


def _mp(dd):
    return mpmath.mpf(float(dd[0])) + mpmath.mpf(float(dd[1]))


def test_double_double_arithmetic_to_30_digits():
    with mpmath.workdps(40):
        for x, y in rng.uniform(0.1, 1e4, (50, 2)):
            X, Y = k._dd(x), k._dd(y)
            mx, my = mpmath.mpf(x), mpmath.mpf(y)
            for got, exact in [(k._dd_add(X, Y), mx + my), (k._dd_mul(X, Y), mx * my),
                               (k._dd_div(X, Y), mx / my), (k._dd_sqrt(X), mpmath.sqrt(mx)),
                               (k._dd_sqrt(k._dd_div(X, Y)), mpmath.sqrt(mx / my))]:
                assert abs(_mp(got) - exact) <= mpmath.mpf(10) ** -30 * abs(exact)


@pytest.mark.parametrize("kernel, zero_offset, exact_fn",
                         [(k._sin_phase, 0.0, mpmath.sin), (k._cos_phase, 0.5, mpmath.cos)])
def test_phase_kernels_keep_relative_accuracy_near_zeros(kernel, zero_offset, exact_fn):
    # k*t lands within ~1e-16 of the zeros at phases up to 1e3, where one
    # rounding of the phase would cost up to ~1e-3 relative error. The
    # double-double phase leaves a few ulp plus its own rounding, 2**-104*|kt|.
    q = k._dd_sqrt(k._dd(2.0))
    with mpmath.workdps(40):
        kk = mpmath.sqrt(2)
        t = np.array([float(mpmath.pi * (j + zero_offset) / kk) for j in range(1, 300)])
        got = kernel(t, q)
        for ti, g in zip(t, got):
            exact = exact_fn(kk * mpmath.mpf(float(ti)))
            phase = float(kk) * ti
            assert abs(g - exact) <= 1.5e-15 * abs(exact) + 4 * 2.0 ** -104 * phase


def test_checked_messages():
    with pytest.raises(ValueError, match=r"m1 must be > 0 \(mass, kg\)"):
        k._checked("m1", [1.0, -2.0], "positive", "mass, kg")
    with pytest.raises(ValueError, match="t must be >= 0"):
        k._checked("t", -1e-300, "nonnegative", "time, s")
    with pytest.raises(ValueError, match="c must be finite"):
        k._checked("c", [1.0, np.nan], "positive", "stiffness, N/m")
    with pytest.raises(ValueError, match="c must be finite"):
        k._checked("c", np.inf, "positive", "stiffness, N/m")
    with pytest.raises(TypeError, match="W must be a number.*string"):
        k._checked("W", "1e3", "nonnegative", "force, N")
    with pytest.raises(TypeError, match="dtype bool"):
        k._checked("W", True, "nonnegative", "force, N")
    assert k._checked("x", 3, "real", "x").dtype == float


@pytest.mark.parametrize("value", [2.5, 3, np.float64(2.5), np.array(2.5), [2.5]])
def test_checked_plain_numbers_and_arrays_agree(value):
    """The fast path for plain numbers gives what the array path gives."""
    got = k._checked("m", value, "positive", "mass, kg")
    assert got.dtype == float and np.array_equal(got, np.asarray(value, dtype=float))
    for bad, message in [(-value if np.isscalar(value) else -np.asarray(value), "> 0"),
                         (float("nan"), "finite"), (float("inf"), "finite"), (10**400, "finite")]:
        with pytest.raises(ValueError, match=message):
            k._checked("m", bad, "positive", "mass, kg")
    with pytest.raises(ValueError, match=">= 0"):
        k._checked("t", -0.5, "nonnegative", "time, s")


def test_closure_lists_dependencies_in_order():
    assert k.closure({"_sin_phase"}) == ["_two_product", "_phase", "_sin_phase"]


@pytest.mark.parametrize("n", [1, 2, 3, 5])
@pytest.mark.parametrize("odd", [0, 1])
def test_taylor_remainders_against_mpmath(n, odd):
    xs = np.concatenate([-np.logspace(-8, 1.7, 40), np.logspace(-8, 1.7, 40)])
    got = k._taylor_remainder(xs, n, odd)
    with mpmath.workdps(150):  # the remainder of x = 1e-8 is ~1e-90: digits are needed
        for x, g in zip(xs, got):
            X = mpmath.mpf(float(x))
            f = mpmath.cos(X) if odd == 0 else mpmath.sin(X)
            exact = f - sum((-1) ** j * X ** (2 * j + odd) / mpmath.factorial(2 * j + odd)
                            for j in range(n))
            assert abs(g - exact) <= 4e-15 * abs(exact)


@pytest.mark.parametrize("n", [1, 2, 3])
@pytest.mark.parametrize("odd", [0, 1])
def test_taylor_remainders_of_small_arguments_only(n, odd):
    # every |x| < 2n + 2: the series alone, with as many terms as the largest needs
    for top in (1e-3, 0.5, 2.0 * n + 1.9):
        xs = np.linspace(-top, top, 41)
        got = k._taylor_remainder(xs, n, odd)
        with mpmath.workdps(80):
            for x, g in zip(xs, got):
                X = mpmath.mpf(float(x))
                f = mpmath.cos(X) if odd == 0 else mpmath.sin(X)
                exact = f - sum((-1) ** j * X ** (2 * j + odd) / mpmath.factorial(2 * j + odd)
                                for j in range(n))
                assert abs(g - exact) <= 4e-15 * abs(exact)
    assert k._taylor_remainder(0.5, n, odd).shape == ()


@pytest.mark.parametrize("kind", [float, complex])
def test_compensated_cumsum_against_exact_prefix_sums(kind):
    # terms of wildly different sizes that cancel: the plain cumsum loses digits
    r = np.random.default_rng(3)
    a = r.standard_normal(4000) * 10.0 ** r.integers(-8, 9, 4000)
    a = np.concatenate([a, -a[::-1]]) + 1e-3 * r.standard_normal(8000)
    if kind is complex:
        a = a + 1j * np.roll(a, 17)
    s = np.cumsum(a)
    assert np.array_equal(k._two_sum(s[:-1], a[1:])[0], s[1:])   # cumsum adds left to right
    got = k._compensated_cumsum(a)
    parts = (np.real, np.imag) if kind is complex else (np.real,)
    for part in parts:
        exact = np.cumsum([Fraction(x) for x in part(a)])
        err = [abs(Fraction(g) - e) for g, e in zip(part(got), exact)]
        scale = np.cumsum(np.abs(part(a)))
        # Sum2's bound: one rounding of the sum plus (n eps)^2 times sum |a|
        gamma2 = (a.size * 2.0 ** -53) ** 2
        assert all(e <= 2 * 2.0 ** -53 * abs(x) + gamma2 * sc
                   for e, x, sc in zip(err, exact, scale))
        plain = max(float(abs(Fraction(g) - e) / max(abs(e), Fraction(1, 10**30)))
                    for g, e in zip(part(s), exact))
        assert plain > 1e-12                  # the case is hard for np.cumsum


def test_taylor_where_replaces_only_the_small_entries():
    # sin(z)/z by its series below 0.5: the closed form elsewhere is kept as given.
    coeffs = tuple(float((-1) ** k / mpmath.factorial(2 * k + 1)) for k in range(12))
    z = np.concatenate([np.logspace(-12, 0.3, 60), [0.0]])
    small = np.abs(z) < 0.5
    closed = np.where(small, -7.0, np.sin(z) / np.where(small, 1.0, z))
    got = k._taylor_where(closed, small, z, 0, 2, coeffs)
    assert np.all(got[~small] == closed[~small])
    with mpmath.workdps(40):
        for zi, g in zip(z, got):
            exact = mpmath.sinc(mpmath.mpf(float(zi)))
            assert abs(g - exact) <= 2.5e-16 * abs(exact)
    scalar = k._taylor_where(np.sin(0.25) / 0.25, np.abs(0.25) < 0.5, 0.25, 0, 2, coeffs)
    assert scalar.shape == () and abs(float(scalar) - np.sin(0.25) / 0.25) < 3e-16


@pytest.mark.parametrize("scale", [1e-3, 1.0, 1e3, 1e6])
def test_exact_phase_is_the_product_to_double_double(scale):
    kk = rng.uniform(0.5, 60.0, 200)
    t = rng.uniform(0.0, scale, 200)
    c = t * rng.uniform(0.0, 2.0, 200)              # t − c from cancelling to large
    hi, lo = pk._exact_phase(kk, t, c)
    for ki, ti, ci, h, l in zip(kk, t, c, hi, lo):
        exact = Fraction(ki) * (Fraction(ti) - Fraction(ci))
        assert abs(Fraction(h) + Fraction(l) - exact) <= 2.0 ** -100 * abs(Fraction(ki) * Fraction(ti))


@pytest.mark.parametrize("fn, exact_fn", [(pk._sin_pair, mpmath.sin), (pk._cos_pair, mpmath.cos)])
def test_sine_of_a_phase_pair_near_its_zeros(fn, exact_fn):
    # Phases up to 1e3 within 1e-12 of the zeros of sin and cos: a rounded
    # phase would cost up to ~1e-1 relative error there, the pair a few ulp.
    with mpmath.workdps(50):
        for j in range(1, 300, 7):
            zero = mpmath.pi * j + (0 if fn is pk._sin_pair else mpmath.pi / 2)
            for off in (mpmath.mpf("1e-12"), mpmath.mpf("-3e-9")):
                z = zero + off
                hi = float(z)
                pair = (hi, float(z - hi))
                for q in (1.0, 0.5):
                    got = fn(pair, q)
                    exact = exact_fn(q * z)
                    assert abs(got - exact) <= 4e-16 * abs(exact) + 1e-31 * abs(z)


def _mp_wave(level, b, c, x):
    return mpmath.mpf(level) + mpmath.mpf(b) * mpmath.cos(x) + mpmath.mpf(c) * mpmath.sin(x)


@pytest.mark.parametrize("depth", [1e-1, 1e-6, 1e-12])
def test_offset_wave_near_its_minimum(depth):
    # level + b cos x + c sin x with level = (1 + depth)·hypot(b, c): the wave
    # swings down to depth·level. At the bottom the naive sum cancels ~1/depth;
    # the kernel keeps a few ulp plus what the rounding of the phase offset
    # atan2(c, b) costs through the slope r·sin(x − d) (the x-conditioning).
    with mpmath.workdps(60):
        for _ in range(40):
            b, c = rng.uniform(-1, 1, 2)
            r = mpmath.sqrt(mpmath.mpf(b) ** 2 + mpmath.mpf(c) ** 2)
            level = float(r * (1 + mpmath.mpf(depth)))
            gap = float(mpmath.mpf(level) ** 2 - r ** 2)
            bottom = mpmath.atan2(c, b) + mpmath.pi          # where cos(x − d) = −1
            for turn in (0, 7, 300):
                for off in (mpmath.mpf(0), mpmath.mpf("1e-5"), mpmath.mpf("0.3"), mpmath.mpf(2)):
                    x = bottom + 2 * mpmath.pi * turn + off
                    hi = float(x)
                    got = pk._offset_wave(level, gap, b, c, (hi, float(x - hi)))
                    exact = _mp_wave(level, b, c, x)
                    slope = 4 * 2.0 ** -53 * r * abs(mpmath.sin(off)) * (abs(x) + 4)
                    assert abs(got - exact) <= 8e-16 * abs(exact) + slope
                    got = pk._offset_wave(-level, gap, -b, -c, (hi, float(x - hi)))
                    assert abs(got + exact) <= 8e-16 * abs(exact) + slope


@pytest.mark.parametrize("n, odd", [(1, 1), (2, 0), (3, 1)])
def test_remainder_on_one_float_is_the_array_remainder(n, odd):
    # the scalar path's Taylor remainder: the same sums as the array kernel
    # on both sides of its cutoff, and a few ulp of mpmath
    for x in (1e-9, 0.3, 2.9, 2.0 * n + 1.999, 2.0 * n + 2.0, 7.5, 41.0):
        got = k._remainder_float(x, n, odd)
        assert abs(got - float(k._taylor_remainder(np.array([x]), n, odd)[0])) <= 1e-15 * abs(got)
        with mpmath.workdps(150):          # the tail at x = 1e-9 is x**7/7! of sin
            head = mpmath.fsum((-1) ** j * mpmath.mpf(x) ** (2 * j + odd)
                               / mpmath.factorial(2 * j + odd) for j in range(n))
            exact = (mpmath.cos(x) if odd == 0 else mpmath.sin(x)) - head
        largest = max(abs(x) ** (2 * j + odd) / math.factorial(2 * j + odd) for j in range(n))
        assert abs(got - exact) <= 4e-16 * abs(exact) + 2.3e-16 * largest   # the polynomial's rounding
