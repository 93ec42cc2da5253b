"""Paper 002, generated functions on hard inputs: every function against
mpmath on every seeded hard case of ``hoist_startup.hard_cases`` (tiny and
long phases, switch points and their neighbours, extreme mass ratios, 0/0
limits), and properties that hold for any input (Hypothesis, derandomized):
continuity across switch points, static and short-window limits, exact
scaling invariances."""
import importlib
import inspect

import numpy as np
import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st

from crane_sym import registry
from crane_sym.bench.accuracy import accuracy

ID = "hoist_startup"
POINTS = 100                                # per case; mpmath at 50+ digits is slow
TOLERANCE = 1e-15                           # well-conditioned points; else 2·cond·u
gen = importlib.import_module(f"crane_sym.generated.{ID}")
CASES = registry.module(ID).hard_cases(POINTS)
PROPERTY = settings(max_examples=60, deadline=None, derandomize=True)


@pytest.fixture(scope="module")
def derivation():
    return registry.get(ID)


def test_hard_cases_give_every_argument(derivation):
    args = {str(a) for out in derivation.outputs for a in out.args}
    for case, columns in CASES.items():
        assert args <= set(columns), case
        assert all(np.all(np.isfinite(c)) for c in columns.values())
        n = {np.size(c) for c in columns.values()}
        assert n == {POINTS}, case
    switch = CASES["t at t_n, τ_0, θ, π/Ω ± 1 ulp"]
    at = [np.sum(switch["t"] == switch[w]) for w in ("t_n", "tau_0", "theta")]
    assert min(at) > 0


@pytest.mark.parametrize("case", list(CASES))
def test_every_function_against_mpmath(derivation, case):
    """Each point: relative error <= 1e-15, or <= 2·cond·u where the value is
    ill-conditioned (cond computed from the derived expression in mpmath)."""
    for out in derivation.outputs:
        row = accuracy(out, getattr(gen, out.name), case, CASES[case], TOLERANCE)
        assert row.excess <= 1.0, (out.name, row)


# --- properties ------------------------------------------------------------------------
LAWS = [f"dynamic_coefficient_{case}_a{i}" for case in ("pickup", "from_weight")
        for i in range(1, 5)]
positive = lambda lo, hi: st.floats(lo, hi, allow_nan=False, allow_infinity=False)


def _params(draw_omega, window_phase, m_ratio):
    return dict(Omega=draw_omega, m1=1e3 * m_ratio, m2=1e3, g=9.81, v0=0.5,
                t_n=window_phase / draw_omega, tau_0=0.37 * window_phase / draw_omega,
                theta=0.61 * window_phase / draw_omega)


def _call(name, t, p):
    f = getattr(gen, name)
    return f(*[t if a == "t" else p[a] for a in inspect.signature(f).parameters
               if a != "out"])


@settings(max_examples=25, deadline=None, derandomize=True)
@given(omega=positive(0.5, 80), phase=positive(1e-9, 50), ratio=positive(1e-6, 1e6))
def test_continuous_across_switch_points(omega, phase, ratio):
    # The formula changes at t = t_n, τ_0, θ; the response (a displacement)
    # is continuous with its slope there: one ulp moves it by ~|K'|·ulp only.
    # k̃ of (64) with pick-up drops by its static part g·t_n/v0 at τ_0.
    p = _params(omega, phase, ratio)
    names = LAWS + ["dynamic_coefficient_pulse", "dynamic_coefficient_ramp_hold",
                    *[f"optimal_coefficient_pickup_a{i}" for i in range(1, 5)]]
    for name in names:
        params = inspect.signature(getattr(gen, name)).parameters
        for w in ("t_n", "tau_0", "theta"):
            if w not in params:
                continue
            c = p[w]
            ts = np.array([np.nextafter(c, 0), c, np.nextafter(c, np.inf),
                           c * (1 - 1e-2), c * (1 + 1e-2)])
            k = _call(name, ts, p)
            if name.startswith("optimal_coefficient_pickup") and w == "tau_0":
                jump = p["g"] * p["t_n"] / p["v0"]
                assert abs(k[1] - k[2] - jump) <= 1e-13 * max(abs(k[1]), jump), name
                k[2] += jump
            assert np.ptp(k[:3]) <= 1e-12 * np.max(np.abs(k)), (name, w, k)


@PROPERTY
@given(omega=positive(1.0, 60), phase=positive(1e3, 1e6), frac=positive(0.0, 1.0))
def test_static_limit_of_slow_loads(omega, phase, frac):
    # Ω·window -> ∞: the response follows the load; the remaining oscillation
    # is bounded exactly for the classic loads (eqs (42), (52)).
    w = phase / omega
    t = frac * 3 * w
    ramp = gen.dynamic_coefficient_ramp(t, omega, w)
    assert abs(ramp - t / w) <= 1 / (omega * w) * (1 + 1e-12) + 1e-15 * t / w
    hold = gen.dynamic_coefficient_ramp_hold(t, omega, w)
    if t > w:
        assert abs(hold - 1) <= 2 / (omega * w) * (1 + 1e-12)
    else:
        assert abs(hold - t / w) <= 1 / (omega * w) * (1 + 1e-12) + 1e-15


def _law(i, s):
    """a_i(t)·t_n/v0 of (30), s = t/t_n (printed amplitudes)."""
    return {1: 1.0, 2: 1 - s, 3: 12 * s * (1 - s) ** 2, 4: 60 * s ** 2 * (1 - s) ** 3}[i] * (s < 1)


@PROPERTY
@given(omega=positive(1.0, 60), phase=positive(1e4, 1e6), frac=positive(0.0, 1.5),
       ratio=positive(1e-4, 1e4))
def test_static_limit_of_smooth_drive_laws_from_weight(omega, phase, frac, ratio):
    # a_3, a_4 start and end smoothly: for Ω·t_n -> ∞, K -> 1 + a(t)/g (the rigid
    # hoist), the rest being ~a'/(Ω g) and a''/(Ω² g).
    p = _params(omega, phase, ratio)
    t = frac * p["t_n"]
    for i, (d1, d2) in {3: (12, 48), 4: (60 * 0.3, 60 * 2)}.items():
        k = _call(f"dynamic_coefficient_from_weight_a{i}", t, p)
        static = 1 + p["v0"] / p["t_n"] * _law(i, t / p["t_n"]) / p["g"]
        scale = p["v0"] / (p["t_n"] * p["g"])
        bound = 2 * scale * (d1 / phase + d2 / phase ** 2)
        assert abs(k - static) <= bound + 1e-15 * static, i


@PROPERTY
@given(omega=positive(0.5, 80), h=positive(1e-9, 1e-4), after=positive(0.0, 200))
def test_short_window_limits_match_the_series(omega, h, after):
    # Ω·θ -> 0: the pulse is an impulse, the rise a step (eqs (46), (52)).
    # The series itself is summed in doubles: its phase x = Ωt carries u·x.
    theta = h / omega
    t = theta + after / omega
    x = omega * t
    rounding = 4e-16 * (1 + x)
    pulse = gen.dynamic_coefficient_pulse(t, omega, theta)
    assert abs(pulse - (h * np.sin(x) - h * h / 2 * np.cos(x))) <= (h ** 3 + rounding * h)
    hold = gen.dynamic_coefficient_ramp_hold(t, omega, theta)
    series = 2 * np.sin(x / 2) ** 2 - h / 2 * np.sin(x)
    assert abs(hold - series) <= h * h / 2 + rounding * 2


MEANS = {3: 0.4, 4: 3 / 7}      # ∫ s·a_i ds / ∫ a_i ds over the start, s = t/t_n


@PROPERTY
@given(omega=positive(0.5, 80), h=positive(1e-9, 1e-4), after=positive(1e-3, 300),
       ratio=positive(1e-6, 1e6))
def test_short_start_limit_from_weight_matches_the_series(omega, h, after, ratio):
    # Ω·t_n -> 0: the start is a speed step v0, K = 1 + (Ω²/g)·x_law with
    # x_law = v0/Ω·(sin Ωt − μ h cos Ωt) + O(h²), μ the law's mean time over t_n.
    p = _params(omega, h, ratio)
    t = p["t_n"] + after / omega
    x = omega * t
    amplitude = omega * p["v0"] / p["g"]
    for i, mu in MEANS.items():
        k = _call(f"dynamic_coefficient_from_weight_a{i}", t, p)
        series = 1 + amplitude * (np.sin(x) - mu * h * np.cos(x))
        assert abs(k - series) <= amplitude * h * h + 4e-16 * (1 + (1 + x) * amplitude), i


@PROPERTY
@given(omega=positive(0.5, 80), phase=positive(1e-9, 1e3), frac=positive(0.0, 4.0),
       ratio=positive(1e-8, 1e8), k=st.integers(-12, 12))
def test_exact_scaling_invariances(omega, phase, frac, ratio, k):
    # K depends on times only through Ω·t, Ω·t_n, …, on masses only through
    # m1/m2, on g and v0/t_n only through their ratio. Scaling by powers of two
    # is exact in binary, so every function must return the same doubles (up
    # to the last bit of a few roundings); 2**±12 keeps every argument but a
    # long time in the range the functions serve.
    p = _params(omega, phase, ratio)
    t = frac * max(p["t_n"], p["tau_0"])
    lam = 2.0 ** k
    assume(t * lam <= 1e7)            # the modules serve t up to 1e7 s (4 t_n at 2**12 passes)
    in_time = {**p, "Omega": p["Omega"] / lam, "v0": p["v0"] * lam,
               **{w: p[w] * lam for w in ("t_n", "tau_0", "theta")}}
    in_mass = {**p, "m1": p["m1"] * lam, "m2": p["m2"] * lam}
    in_accel = {**p, "g": p["g"] * lam, "v0": p["v0"] * lam}
    names = LAWS + ["dynamic_coefficient_instant", "dynamic_coefficient_ramp",
                    "dynamic_coefficient_pulse", "dynamic_coefficient_ramp_hold"]
    for name in names:
        base = _call(name, t, p)
        for q, tq in ((in_time, t * lam), (in_mass, t), (in_accel, t)):
            assert abs(_call(name, tq, q) - base) <= 4.5e-16 * abs(base), name


@PROPERTY
@given(omega=positive(0.5, 80), phase=positive(1e-9, 1e3), ratio=positive(1e-8, 1e8))
def test_values_at_the_start_and_the_peaks(omega, phase, ratio):
    p = _params(omega, phase, ratio)
    a0 = p["v0"] / p["t_n"]
    for i in range(1, 5):
        assert _call(f"dynamic_coefficient_pickup_a{i}", 0.0, p) == 0.0
        start = 1.0 if i >= 3 else p["g"] / (p["g"] + a0)    # rope preloaded by the weight
        assert abs(_call(f"dynamic_coefficient_from_weight_a{i}", 0.0, p) - start) <= 2.3e-16
    # the peak factors (47), (53) bound their responses and are reached: the
    # pulse at the time (47) gives; after the rise K = 1 − cos(Ω(t − θ/2))·sinc,
    # largest where the cosine is −sign(sin(Ωθ/2))
    theta = p["theta"]
    t = np.linspace(0, theta + 4 * np.pi / omega, 4001)
    offset = np.pi if np.sin(omega * theta / 2) >= 0 else 0.0
    turns = max(0.0, np.ceil((omega * theta / 2 - offset) / (2 * np.pi)))
    crest = theta / 2 + (2 * np.pi * turns + offset) / omega
    for response, peak, at in (
            (gen.dynamic_coefficient_pulse, gen.pulse_peak_factor,
             gen.pulse_peak_time(omega, theta)),
            (gen.dynamic_coefficient_ramp_hold, gen.ramp_hold_peak_factor, crest)):
        top = peak(omega, theta)
        assert np.max(response(t, omega, theta)) <= top * (1 + 1e-14)
        assert abs(response(at, omega, theta) - top) <= 1e-13 * top
