"""crane_sym.mechanics.sampled_load against mpmath references derived by crane_sym.mechanics.duhamel.

Error norm, unless a test says otherwise: the worst |computed - exact| over
the checked samples divided by the peak |exact| over the same samples, for x
and x' separately ("relative to the peak"; x passes through zero, where a
pointwise relative error means nothing). Where the response is away from
zero (|exact| >= 0.1 peak) the pointwise relative error is checked too.
"""
import math

import mpmath
import numpy as np
import pytest
import sympy as sp
from hypothesis import given, settings
from hypothesis import strategies as st
from hypothesis.extra.numpy import arrays

from crane_sym.mechanics import sampled_load as sl
from crane_sym.bench.sampled import mp_exact, reference, samples
from crane_sym.mechanics.duhamel import duhamel

EPS = 2.0 ** -52
TOL = 1e-13


def _errors(got: np.ndarray, exact: np.ndarray) -> tuple[float, float]:
    """(error relative to the peak, worst pointwise relative error where
    |exact| >= 0.1 peak)."""
    peak = np.max(np.abs(exact))
    away = np.abs(exact) >= 0.1 * peak
    return (float(np.max(np.abs(got - exact)) / peak),
            float(np.max(np.abs(got - exact)[away] / np.abs(exact[away]))))


def _check(got: sl.SampledResponse, x: np.ndarray, v: np.ndarray, tol: float = TOL):
    for name, value, exact in (("x", got.x, x), ("v", got.v, v)):
        over_peak, pointwise = _errors(value, exact)
        assert over_peak <= tol, f"{name}: error / peak {over_peak:.2e}"
        assert pointwise <= tol, f"{name}: pointwise relative error {pointwise:.2e}"


# --- the segment weights -------------------------------------------------------------
@pytest.fixture(scope="module")
def weights_exact():
    """A, B and E = A + B by SymPy's integrals, and their series to theta^5
    (for the angles where the closed forms cancel beyond 120 digits)."""
    theta, sigma = sp.symbols("theta sigma", positive=True)
    kernel = sp.exp(-sp.I * theta * sigma)
    exprs = [sp.integrate(kernel * f, (sigma, 0, 1)) for f in (1 - sigma, sigma, 1)]
    closed = [sp.lambdify(theta, e, modules="mpmath") for e in exprs]
    series = [sp.lambdify(theta, sp.series(e, theta, 0, 6).removeO(), modules="mpmath")
              for e in exprs]
    return closed, series


def _parts(values):
    return [part(v) for v in values for part in (mpmath.re, mpmath.im)]


def test_segment_weights_against_sympy_integrals(weights_exact):
    closed, _ = weights_exact
    thetas = np.concatenate([np.logspace(-9, 1.5, 80), [np.pi, 2 * np.pi, 2.33, 4.49]])
    parts = sl.segment_weights(thetas)
    with mpmath.workdps(120):        # A and B cancel to ~theta**3 in their own form
        for i, th in enumerate(thetas):
            exact = _parts(f(mp_exact(th)) for f in closed)
            for got, want in zip((p[i] for p in parts), exact):
                # a few ulp of the part, or of its natural size where it crosses
                # zero (~1/theta); a cancelling form would be off by ~eps/theta^2
                scale = max(abs(float(want)), min(th, 1.0 / th) / 4)
                assert abs(got - want) <= 8 * EPS * scale, (th, got, want)


def test_segment_weights_at_zero_and_tiny_angles(weights_exact):
    # 0 is the segment of a jump (a time given twice); theta^2 underflows at 1e-300
    _, series = weights_exact
    thetas = np.array([0.0, 1e-300, 1e-21, 1.1e-20, 1e-15, 1e-10])
    parts = sl.segment_weights(thetas)
    with mpmath.workdps(50):
        for i, th in enumerate(thetas):
            exact = _parts(f(mp_exact(th)) for f in series)
            for got, want in zip((p[i] for p in parts), exact):
                assert abs(got - want) <= 2 * EPS * abs(want), (th, got, want)


# --- closed-form loads ---------------------------------------------------------------
# Every time and every load sample below is an exact double (dyadic grids,
# breakpoints at a power of 2 of steps), so the reference is the exact answer
# to the very input the function gets. With rounded samples a slow ramp's x'
# would differ from the ramp's by ~1e-11 of its peak whatever the method:
# sqrt(N) roundings of S ~ 4 S0 against x' ~ S0/(t1 Omega^2).
BREAKS = {"step": 4, "ramp": 4, "ramp_hold": 4, "pulse": 4, "trapezoid": 4}


def _dyadic_grid(theta, Omega, n_per, pieces, uniform_steps, rng, t0=1.25):
    """Times t0 + k q, k integers, q a power of 2 near theta/(16 Omega), with
    n_per samples (a power of 2) per t1 = 16 n_per q; random steps when not
    uniform. Returns (times, t1)."""
    unit = 16
    q = 2.0 ** round(math.log2(theta / Omega / unit))
    K = unit * n_per
    ks = [0]
    for p in range(pieces):
        if uniform_steps:
            inner = p * K + np.arange(unit, K + 1, unit)
        else:
            cuts = np.sort(rng.choice(np.arange(1, K), n_per - 1, replace=False))
            inner = np.append(p * K + cuts, (p + 1) * K)
        ks.extend(inner)
    return t0 + np.array(ks, dtype=float) * q, K * q


@pytest.mark.parametrize("family", list(BREAKS))
@pytest.mark.parametrize("theta", [1e-6, 1e-3, 0.1, 1.0])
@pytest.mark.parametrize("uniform_steps", [True, False], ids=["uniform", "nonuniform"])
def test_closed_form_loads_on_time_grids(family, theta, uniform_steps):
    rng = np.random.default_rng(int(theta * 1e6) + len(family))
    Omega, S0, t0 = 3.7, -2.25, 1.25
    t, t1 = _dyadic_grid(theta, Omega, 128, BREAKS[family], uniform_steps, rng, t0)
    if family == "pulse":                 # S drops to 0 at t1: that time is given twice
        at = int(np.searchsorted(t, t0 + t1))
        t = np.insert(t, at, t[at])
    since = t - t0                        # exact
    S = samples(family, since, S0, t1)
    x, v = reference(family, since, Omega, S0, t1)
    _check(sl.sampled_response(t, S, Omega), x, v)


@pytest.mark.parametrize("family", ["step", "ramp", "ramp_hold", "trapezoid"])
@pytest.mark.parametrize("theta", [1e-6, 1e-3, 0.1, 1.0])
def test_closed_form_loads_uniform_record(family, theta):
    Omega, S0, m = 3.7, 1.75, 128         # t1 = m dt
    dt = theta / Omega
    n = BREAKS[family] * m + 1
    S = samples(family, np.arange(n) / m, S0, 1.0)          # S at j dt = (j/m) t1, exact
    with mpmath.workdps(50):
        since = [k * mp_exact(dt) for k in range(n)]
        t1 = m * mp_exact(dt)
    x, v = reference(family, since, Omega, S0, t1)
    _check(sl.sampled_response_uniform(dt, S, Omega), x, v)


def test_acceleration_follows_the_equation():
    Omega, S0, dt, m = 2.9, 3.0, 0.01, 256
    S = samples("ramp_hold", np.arange(4 * m + 1) / m, S0, 1.0)
    with mpmath.workdps(50):
        since = [k * mp_exact(dt) for k in range(4 * m + 1)]
        t1 = m * mp_exact(dt)
        exact = reference("ramp_hold", since, Omega, S0, t1)
    got = sl.sampled_response_uniform(dt, S, Omega, acceleration=True)
    assert sl.sampled_response_uniform(dt, S, Omega).a is None
    a = S - Omega ** 2 * exact[0]         # x'' from the equation, up to rounding of S
    assert np.max(np.abs(got.a - a)) <= 4 * EPS * np.max(np.abs(S))
    assert np.max(np.abs(got.a - a)) <= TOL * np.max(np.abs(a))


# --- long records --------------------------------------------------------------------
@pytest.mark.parametrize("theta", [1e-6, 0.05, 1.0])
@pytest.mark.parametrize("family", ["step", "ramp_hold"])
def test_long_records(family, theta):
    # 1e5 samples: at theta = 1 that is 1e5 rad, ~16000 periods
    Omega, S0, n, m = 7.3, 2.5, 100_001, 1024
    check = np.unique(np.append(np.linspace(0, n - 1, 400).astype(int), [1, 2, m, n - 1]))
    S = samples(family, np.arange(n) / m, S0, 1.0)
    dt = theta / Omega
    with mpmath.workdps(50):
        since = [int(k) * mp_exact(dt) for k in check]
        t1 = m * mp_exact(dt)
    x, v = reference(family, since, Omega, S0, t1)
    got = sl.sampled_response_uniform(dt, S, Omega)
    _check(sl.SampledResponse(got.x[check], got.v[check], None), x, v)
    q = 2.0 ** round(math.log2(theta / Omega))   # the same as times 0.375 + k q
    t = 0.375 + np.arange(n) * q
    x, v = reference(family, t[check] - 0.375, Omega, S0, m * q)
    got = sl.sampled_response(t, S, Omega)
    _check(sl.SampledResponse(got.x[check], got.v[check], None), x, v)


def test_compensated_sum_is_what_keeps_long_records_accurate():
    # A step over 1e5 samples of Omega h = 1e-6: x (0.1 rad in all) is read off
    # w, whose plain cumsum loses ~sqrt(N) roundings; the blocked, compensated
    # prefix sum does not.
    Omega, S0, n, dt = 7.3, 2.5, 100_001, 1e-6 / 7.3
    S = np.full(n, S0)
    check = np.linspace(0, n - 1, 300).astype(int)
    with mpmath.workdps(50):
        since = [int(k) * mp_exact(dt) for k in check]
    x, _ = reference("step", since, Omega, S0, 1.0)
    errors = [_errors(sl._uniform(dt, S, Omega, 0.0, 0.0, False, c).x[check], x)[0]
              for c in (True, False)]
    assert errors[0] <= 2e-15 < errors[1]


# --- piecewise-linear loads: exactness ----------------------------------------------
@pytest.fixture(scope="module")
def one_segment():
    """x, x' after a time s under S = a + m s from (x0, v0), by crane_sym.mechanics.duhamel."""
    t = sp.Symbol("t", nonnegative=True)
    W = sp.Symbol("Omega", positive=True)
    a, m, x0, v0 = sp.symbols("a m x0 v0", real=True)
    result = duhamel(a + m * t, W, t, u0=x0, v0=v0)
    args = (t, W, a, m, x0, v0)
    return (sp.lambdify(args, result.pieces[0].expr, modules="mpmath"),
            sp.lambdify(args, result.velocity_pieces[0].expr, modules="mpmath"))


def _polyline_reference(one_segment, t, S, Omega, x0, v0):
    """x, x', x'' = S - Omega^2 x, segment by segment in mpmath: an
    independent route to the exact answer."""
    fx, fv = one_segment
    with mpmath.workdps(60):
        W = mp_exact(Omega)
        x, v = mp_exact(x0), mp_exact(v0)
        xs, vs = [x], [v]
        for j in range(t.size - 1):
            h = mp_exact(t[j + 1]) - mp_exact(t[j])
            a = mp_exact(S[j])
            if h > 0:
                m = (mp_exact(S[j + 1]) - a) / h
                x, v = fx(h, W, a, m, x, v), fv(h, W, a, m, x, v)
            xs.append(x)
            vs.append(v)
        acc = [mp_exact(s) - W ** 2 * e for s, e in zip(S, xs)]
    return tuple(np.array([float(e) for e in values]) for values in (xs, vs, acc))


@pytest.mark.parametrize("seed", range(4))
def test_polyline_loads_are_exact_on_coarse_grids(one_segment, seed):
    rng = np.random.default_rng(seed)
    Omega = rng.uniform(0.5, 5.0)
    t = np.cumsum(np.append(rng.uniform(-5, 5), rng.uniform(0.05, 2.0, 12)))
    if seed % 2:                            # a jump of S at t[6]
        t = np.insert(t, 6, t[6])
    S = rng.uniform(-3, 3, t.size)
    x0, v0 = rng.uniform(-1, 1, 2)
    x, v, a = _polyline_reference(one_segment, t, S, Omega, x0, v0)
    got = sl.sampled_response(t, S, Omega, x0, v0, acceleration=True)
    for value, exact in ((got.x, x), (got.v, v), (got.a, a)):
        assert np.max(np.abs(value - exact)) <= 16 * EPS * np.max(np.abs(exact))


def test_polyline_uniform_record_is_exact(one_segment):
    rng = np.random.default_rng(11)
    Omega, dt = 2.2, 0.3125                  # dt a power-of-2 fraction: k dt exact
    S = rng.uniform(-3, 3, 40)
    t = np.arange(S.size) * dt
    x, v, a = _polyline_reference(one_segment, t, S, Omega, 0.4, -0.7)
    got = sl.sampled_response_uniform(dt, S, Omega, 0.4, -0.7, acceleration=True)
    for value, exact in ((got.x, x), (got.v, v), (got.a, a)):
        assert np.max(np.abs(value - exact)) <= 16 * EPS * np.max(np.abs(exact))


def test_initial_conditions_free_and_loaded():
    Omega, dt, n = 4.1, 0.01, 2001
    x0, v0 = 0.12, -0.9
    with mpmath.workdps(50):
        since = [k * mp_exact(dt) for k in range(n)]
    for S0 in (0.0, 1.5):
        S = np.full(n, S0)
        x, v = reference("step", since, Omega, S0, 1.0, x0, v0)
        _check(sl.sampled_response_uniform(dt, S, Omega, x0, v0), x, v)
        assert sl.sampled_response_uniform(dt, S, Omega, x0, v0).x[0] == x0


def test_a_load_that_is_not_linear_between_samples_converges_at_second_order():
    # S = S0 (t/t1)^3: the chords' error is at most max|S''| h^2 / 8, with
    # max|S''| = 6 S0 / t1^2, and the response's at most (t/Omega) times that
    Omega, S0, t1 = 2.0, 1.0, 1.0
    errors = []
    for n in (101, 201):
        dt = t1 / (n - 1)
        S = samples("cubic", np.arange(n) * dt, S0, t1)
        with mpmath.workdps(50):
            since = [k * mp_exact(dt) for k in range(n)]
        x, _ = reference("cubic", since, Omega, S0, t1)
        err = np.max(np.abs(sl.sampled_response_uniform(dt, S, Omega).x - x))
        assert err <= (t1 / Omega) * (6 * S0 / t1 ** 2) * dt ** 2 / 8
        errors.append(err)
    assert 3.5 < errors[0] / errors[1] < 4.5


# --- validation ----------------------------------------------------------------------
T3, S3 = np.array([0.0, 0.1, 0.2]), np.array([1.0, 2.0, 3.0])


@pytest.mark.parametrize("kwargs, match", [
    ({"t": [0.0, 0.2, 0.1]}, r"t must be non-decreasing: t\[2\] = 0.1 < t\[1\] = 0.2"),
    ({"t": [0.0, 0.1, 0.1, 0.1], "S": [1, 2, 3, 4]}, "t repeats t\\[1\\] = 0.1 more than twice"),
    ({"t": [[0.0, 0.1, 0.2]]}, "t must be a 1-D array"),
    ({"t": [0.0]}, "t needs at least 2 samples"),
    ({"t": [0.0, np.inf, 1.0]}, "t must be finite"),
    ({"S": [1.0, 2.0]}, "S must have one sample per time: t has 3, S has 2"),
    ({"S": [1.0, np.nan, 2.0]}, "S must be finite"),
    ({"S": [[1.0, 2.0, 3.0]]}, "S must be a 1-D array"),
    ({"Omega": 0.0}, "Omega must be > 0"),
    ({"Omega": -1.0}, "Omega must be > 0"),
    ({"Omega": np.nan}, "Omega must be finite"),
    ({"Omega": [1.0, 2.0]}, "Omega must be a scalar"),
    ({"x0": np.inf}, "x0 must be finite"),
    ({"v0": np.nan}, "v0 must be finite"),
])
def test_invalid_arguments_name_the_argument(kwargs, match):
    args = {"t": T3, "S": S3, "Omega": 2.0, **kwargs}
    with pytest.raises(ValueError, match=match):
        sl.sampled_response(**args)


@pytest.mark.parametrize("kwargs, match", [
    ({"dt": 0.0}, "dt must be > 0"),
    ({"dt": np.nan}, "dt must be finite"),
    ({"S": [1.0]}, "S needs at least 2 samples"),
    ({"S": [1.0, np.inf]}, "S must be finite"),
    ({"Omega": -2.0}, "Omega must be > 0"),
])
def test_invalid_arguments_uniform(kwargs, match):
    args = {"dt": 0.1, "S": S3, "Omega": 2.0, **kwargs}
    with pytest.raises(ValueError, match=match):
        sl.sampled_response_uniform(**args)


def test_text_is_refused_by_type():
    with pytest.raises(TypeError, match="S must be a number"):
        sl.sampled_response(T3, "1, 2, 3", 2.0)
    with pytest.raises(TypeError, match="Omega must be a number"):
        sl.sampled_response_uniform(0.1, S3, "2.0")


# --- a property ----------------------------------------------------------------------
finite = st.floats(-1e3, 1e3, allow_nan=False, allow_infinity=False)


@settings(max_examples=60, deadline=None)
@given(steps=arrays(float, 12, elements=st.floats(1e-3, 1.0)),
       S1=arrays(float, 13, elements=finite), S2=arrays(float, 13, elements=finite),
       a=st.floats(-10, 10), b=st.floats(-10, 10), Omega=st.floats(0.05, 50.0),
       uniform=st.booleans())
def test_response_is_linear_in_the_load(steps, S1, S2, a, b, Omega, uniform):
    if uniform:
        run = lambda S: sl.sampled_response_uniform(steps[0], S, Omega)     # noqa: E731
        span = steps[0] * 12
    else:
        t = np.append(0.0, np.cumsum(steps))
        run = lambda S: sl.sampled_response(t, S, Omega)                    # noqa: E731
        span = t[-1]
    whole, one, two = run(a * S1 + b * S2), run(S1), run(S2)
    # |x| <= span max|S| / Omega and |x'| <= span max|S| bound every term summed
    size = (abs(a) * np.max(np.abs(S1)) + abs(b) * np.max(np.abs(S2))) * span + 1e-300
    assert np.max(np.abs(whole.x - (a * one.x + b * two.x))) <= 1e-13 * size / Omega
    assert np.max(np.abs(whole.v - (a * one.v + b * two.v))) <= 1e-13 * size


# --- chunks and memory ----------------------------------------------------------------
@pytest.mark.parametrize("uniform", [True, False])
def test_chunks_do_not_change_the_response(monkeypatch, uniform):
    """Chunks of 128 samples and one chunk for the whole record agree to a few
    ulp of the peak (a ramp-hold with a jump, read off both states)."""
    from crane_sym.mechanics import sampled_states
    n = 5001
    t = np.arange(n) * 1e-3
    S = np.where(t < 2.0, t, 2.0) + np.where(t > 3.0, 0.5, 0.0)
    run = ((lambda: sl.sampled_response_uniform(1e-3, S, 25.0, acceleration=True)) if uniform
           else (lambda: sl.sampled_response(t, S, 25.0, acceleration=True)))
    monkeypatch.setattr(sampled_states, "CHUNK", 1 << 20)
    whole = run()
    monkeypatch.setattr(sampled_states, "CHUNK", 128)
    chunked = run()
    for a, b in zip(whole, chunked):
        assert np.max(np.abs(a - b)) <= 8e-16 * np.max(np.abs(a))


def test_memory_is_the_output_and_a_few_chunks():
    """Peak memory of a call (NumPy's allocations, traced) on 2e6 samples is
    the output plus less than one input: the work is done in chunks."""
    import tracemalloc
    n = 2_000_001
    S = np.sin(np.arange(n) * 1e-4) + 1.0
    tracemalloc.start()
    try:
        got = sl.sampled_response_uniform(1e-3, S, 25.0, acceleration=True)
        peak = tracemalloc.get_traced_memory()[1]
    finally:
        tracemalloc.stop()
    output = sum(a.nbytes for a in got)
    assert peak < output + 0.5 * S.nbytes


# --- finite in, finite out --------------------------------------------------------------
@settings(max_examples=150, deadline=None, derandomize=True)
@given(st.floats(-90, 90), st.floats(-90, 90), st.floats(-90, 90), st.floats(-90, 90),
       st.floats(-90, 90), st.booleans())
def test_every_accepted_argument_gives_finite_values(log_omega, log_dt, log_s, log_x, log_v,
                                                     uniform):
    """Omega, dt, the load and the initial state anywhere within 1e±90
    (sl.SERVES) and a phase span within 1e15 rad: x, x' and x'' are finite."""
    Omega, dt = 10.0 ** log_omega, 10.0 ** log_dt
    if Omega * dt * 4 > sl.PHASE_SPAN:
        with pytest.raises(ValueError, match=r"^Omega\*\(t\[-1\] - t\[0\]\) must be <= 1e\+15"):
            sl.sampled_response_uniform(dt, np.zeros(5), Omega)
        return
    S = 10.0 ** log_s * np.array([0.0, 0.5, -0.5, 0.25, 1.0])
    x0, v0 = 10.0 ** log_x, -(10.0 ** log_v)
    if uniform:
        got = sl.sampled_response_uniform(dt, S, Omega, x0, v0, acceleration=True)
    else:
        t = np.cumsum(np.full(S.size, dt)) - dt
        if not np.all(np.diff(t) > 0):
            return                              # dt below the spacing of doubles at t
        got = sl.sampled_response(t, S, Omega, x0, v0, acceleration=True)
    for part in got:
        assert np.all(np.isfinite(part))


@pytest.mark.parametrize("kwargs,match", [
    ({"Omega": 1e300}, r"^Omega must be within \[1e-90, 1e\+?90\]"),
    ({"Omega": 1e-300}, r"^Omega must be within"), ({"x0": -1e100}, r"^x0 must be within"),
    ({"S": np.array([0.0, 1e300])}, r"^S must be within")])
def test_beyond_the_served_range_is_refused(kwargs, match):
    args = {"dt": 1e-3, "S": np.array([0.0, 1.0, 2.0]), "Omega": 25.0} | kwargs
    with pytest.raises(ValueError, match=match):
        sl.sampled_response_uniform(**args)
