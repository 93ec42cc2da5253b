"""crane_sym.piecewise_linear: closed forms against expm, event search without a
skipped crossing, and paper 001's Fig. 9 run against solve_ivp with events
(and its backlash -> 0 limit against the no-backlash closed form)."""
import time

import numpy as np
import pytest

from crane_sym.derivations.hoist_brakes.elastic import FORWARD, HOLD, OFF, table1_hoist
from crane_sym.piecewise_linear import closed_form, first_crossing, simulate

linalg = pytest.importorskip("scipy.linalg")
integrate = pytest.importorskip("scipy.integrate")


def _expm_state(A, b, x0, t):
    n = len(b)
    M = np.zeros((n + 1, n + 1))
    M[:n, :n], M[:n, n] = A, b
    return (linalg.expm(M * t) @ np.append(x0, 1.0))[:n]


@pytest.mark.parametrize("exact", [True, False])
def test_closed_form_against_expm_with_a_rigid_mode(exact):
    """Three masses on two springs: a double zero eigenvalue (a Jordan block with
    the forcing) and two vibration modes."""
    k1, k2, m = 3e3, 5e3, np.array([2.0, 1.0, 4.0])
    K = np.array([[k1, -k1, 0], [-k1, k1 + k2, -k2], [0, -k2, k2]])
    A = np.block([[np.zeros((3, 3)), np.eye(3)], [-K / m[:, None], np.zeros((3, 3))]])
    b = np.array([0, 0, 0, 5.0, -1.0, 2.0])
    x0 = np.random.default_rng(7).normal(size=6)
    form = closed_form(A, b, exact=exact)
    assert 2 in set(form.powers.astype(int))          # t² from the forced rigid mode
    for t in (0.0, 1e-3, 0.37, 2.5):
        ref = _expm_state(A, b, x0, t)
        assert np.allclose(form.state(t, x0), ref, rtol=1e-11, atol=1e-11 * np.abs(ref).max())


def test_a_brief_excursion_is_not_skipped():
    """g = x1 − (1 − ε) on a unit oscillator: positive only for ~2·sqrt(2ε) of each
    period; a coarse sampler misses it, the certified search must not."""
    A = np.array([[0.0, 1.0], [-1.0, 0.0]])
    form = closed_form(A, np.zeros(2))
    x0 = np.array([0.0, -1.0])              # x1 = −sin t: reaches 1 at t = 3π/2
    eps = 1e-6
    hit = first_crossing(form, x0, np.array([1.0, 0.0]), -(1 - eps), 10.0, direction=1)
    exact = 1.5 * np.pi - np.arccos(1 - eps)
    assert hit == pytest.approx(exact, abs=1e-9)
    coarse = np.linspace(0, 10, 2001)        # spacing 5e-3 > excursion 2.8e-3
    g = -np.sin(coarse) - (1 - eps)
    assert not np.any(g > 0)


def test_no_crossing_returns_none():
    form = closed_form(np.array([[0.0, 1.0], [-4.0, 0.0]]), np.zeros(2))
    assert first_crossing(form, np.array([0.5, 0.0]), np.array([1.0, 0.0]), 0.6, 20.0) is None


@pytest.mark.parametrize("payload", [0.0, 52e3])
def test_fig9_against_solve_ivp(payload, integrated):
    hoist = table1_hoist(payload)
    schedule = [(0.0, "motor torque lost"), (0.1, "safety brake"), (0.4, "service brake")]
    omega = 50 * np.pi
    t0 = time.perf_counter()
    closed = hoist.run(omega, 0.3)
    t1 = time.perf_counter()
    times, states = integrated(hoist, 1e-4).run(*hoist.start(omega), 0.3, schedule)
    t2 = time.perf_counter()
    ours = closed.state(times)
    scale = np.abs(states).max(axis=0)
    err = np.max(np.abs(ours - states) / scale)
    print(f"closed form {t1 - t0:.3f} s, solve_ivp {t2 - t1:.3f} s, max rel. diff {err:.1e}")
    assert err < 1e-6
    peak_t, peak = hoist.peak(closed)
    sampled = hoist.relative_torque(closed, np.linspace(0, 0.3, 30001))
    assert abs(peak) >= np.max(np.abs(sampled)) - 1e-9


def test_solve_ivp_with_default_steps_skips_a_contact_the_closed_form_finds(integrated):
    """Lowering the hook: after the first rebound the flanks touch for ~4 ms at
    t = 0.163 s inside one solve_ivp step; its events miss it, the certified
    search does not."""
    hoist = table1_hoist(0.0)
    schedule = [(0.0, "motor torque lost"), (0.1, "safety brake"), (0.4, "service brake")]
    closed = [t for t, ev, _ in hoist.run(50 * np.pi, 0.2).events if ev == "close hold"]
    assert closed and 0.16 < closed[0] < 0.165
    seen = []
    switch = hoist.switch
    class Spy:
        matrices, guards = hoist.matrices, hoist.guards
        def switch(self, mode, name, t, x):  # noqa: E301
            seen.append((t, name))
            return switch(mode, name, t, x)
    integrated(Spy()).run(*hoist.start(50 * np.pi), 0.2, schedule)
    assert not any(name == "close hold" and t < 0.17 for t, name in seen)


def test_backlash_to_zero_is_the_linear_two_mass_solution():
    """s = 0: while the drum slides, the gearbox torque is that of the linear
    two-mass system (no contact logic), from expm."""
    h = table1_hoist(0.0, backlash_deg=0.0)
    run = h.run(50 * np.pi, 0.25)
    first_rest = next((t for t, ev, _ in run.events if "rests" in ev), 0.25)
    mode_a, mode_b = (HOLD, OFF, OFF, False), (HOLD, OFF, FORWARD, False)
    _, x0 = h.start(50 * np.pi)
    Aa, ba = h.matrices(mode_a)
    Ab, bb = h.matrices(mode_b)
    x_sb = _expm_state(Aa, ba, x0, 0.1)
    times = np.linspace(0.1, first_rest, 200)
    ref = np.array([_expm_state(Ab, bb, x_sb, t - 0.1) for t in times])
    torque = h.c * (ref[:, 2] - ref[:, 0]) / h.M_st
    assert np.allclose(h.relative_torque(run, times), torque, atol=1e-7 * np.abs(torque).max())
    # and with a tiny backlash the peak converges to the no-backlash one
    tiny = table1_hoist(0.0, backlash_deg=1e-7)
    assert tiny.peak(tiny.run(50 * np.pi, 0.25))[1] == pytest.approx(
        h.peak(run)[1], rel=1e-4)


def test_simulate_rejects_runaway_events():
    h = table1_hoist(0.0)
    with pytest.raises(RuntimeError, match="events"):
        simulate(h, *h.start(50 * np.pi), 1.0,
                 [(0.0, "motor torque lost"), (0.1, "safety brake")], max_events=3)


def test_generated_no_backlash_torque_is_the_backlash_to_zero_limit():
    from crane_sym.generated import hoist_brakes as gen
    h = table1_hoist(0.0, backlash_deg=0.0)
    run = h.run(50 * np.pi, 0.25)
    times = np.linspace(0.0, 0.25, 501)
    closed = gen.elastic_gearbox_torque_no_backlash(
        times, J1=20.0, J2=500.0, m_h=1e4, m_p=0.0, m_r=52e3, r=0.5, i_g=26.2, i_t=4.0,
        g=9.81, c=4e4, M_SB=130e3, t_SB=0.1)
    assert np.max(np.abs(closed - h.relative_torque(run, times))) < 1e-11
    with_backlash = table1_hoist(0.0)
    wb = with_backlash.relative_torque(with_backlash.run(50 * np.pi, 0.25), times)
    assert np.max(np.abs(closed - wb)) > 1.0          # the backlash matters


def test_first_crossing_is_never_later_than_a_dense_scan():
    """Random two-mode systems with a rigid mode: the certified search finds a
    crossing no later than the first sign change on a 2e-6 grid (none skipped)."""
    rng = np.random.default_rng(11)
    for _ in range(20):
        k1, k2 = 10 ** rng.uniform(2, 4, 2)
        m = 10 ** rng.uniform(-0.5, 0.5, 3)
        K = np.array([[k1, -k1, 0], [-k1, k1 + k2, -k2], [0, -k2, k2]])
        A = np.block([[np.zeros((3, 3)), np.eye(3)], [-K / m[:, None], np.zeros((3, 3))]])
        b = np.concatenate([np.zeros(3), rng.normal(size=3)])
        x0 = rng.normal(size=6)
        w = rng.normal(size=6)
        form = closed_form(A, b)
        grid = np.linspace(0, 0.2, 100_001)
        g = form.state(grid, x0) @ w - 0.3
        changes = np.flatnonzero(np.sign(g[1:]) != np.sign(g[:-1]))
        hit = first_crossing(form, x0, w, -0.3, 0.2)
        if changes.size == 0:
            continue
        assert hit is not None and hit <= grid[changes[0] + 1] + 1e-12
        assert abs(form.state(hit, x0) @ w - 0.3) < 1e-8 * (1 + np.abs(g).max())


def test_repeated_semisimple_eigenvalues_stay_numeric(monkeypatch):
    """Two equal drives on one crane (paper 003): each vibration eigenvalue twice,
    with a full set of eigenvectors; the numeric path keeps it (no exact Jordan
    form) and matches expm."""
    import crane_sym.piecewise_linear as pl

    m, c, b = 2.0, 4e3, 5.0               # state (x1, x2, x_k, v1, v2, v_k), crane held
    A = np.zeros((6, 6))
    A[0, 3] = A[1, 4] = 1.0
    for row, x in ((3, 0), (4, 1)):
        A[row, x], A[row, 2], A[row, row] = -c / m, c / m, -b / m
    rhs = np.array([0, 0, 0, 1.0, 1.0, 0])
    assert np.sum(np.isclose(np.linalg.eigvals(A), np.linalg.eigvals(A)[0])) == 2
    monkeypatch.setattr(pl, "_closed_form_cached", lambda *a: pytest.fail("went exact"))
    form = pl._closed_form_numeric(tuple(A.ravel()), tuple(rhs))
    x0 = np.random.default_rng(3).normal(size=6)
    for t in (0.0, 0.013, 0.4, 2.0):
        ref = _expm_state(A, rhs, x0, t)
        assert np.allclose(form.state(t, x0), ref, rtol=1e-10, atol=1e-10 * np.abs(ref).max())
