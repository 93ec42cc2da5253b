"""crane_sym.mechanics.piecewise_linear: closed forms against expm, event search without a
skipped crossing, and paper 001's Fig. 9 run against solve_ivp with events
(and its backlash -> 0 limit against the no-backlash closed form)."""
from dataclasses import replace

import numpy as np
import pytest

from crane_sym.bench.piecewise import integrate_hybrid
from crane_sym.components.hybrid import Mode
from crane_sym.derivations.hoist_brakes.drive_train import (emergency_stop, rated_torque,
                                                            table1_values)
from crane_sym.mechanics.phase_table import largest, values
from crane_sym.mechanics.event_search import first_crossing
from crane_sym.mechanics.piecewise_linear import closed_form, simulate

linalg = pytest.importorskip("scipy.linalg")
integrate = pytest.importorskip("scipy.integrate")


def _stop(payload, duration, **changes):
    """Paper 001's emergency stop (``drive_train.emergency_stop``, the hoist as
    components) of Table 1's hoist lowering ``payload`` from 50π rad/s."""
    q = {**table1_values(payload, **changes), "omega1": 50 * np.pi}
    return emergency_stop(q, duration), q


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


def test_a_start_on_the_surface_with_zero_slope_does_not_fire_on_rounding_noise():
    """A speed that leaves rest at zero acceleration (a group that slips where
    its load just reaches the brake's capacity), a hair below 0 by rounding:
    the guard 'rests' (falling through 0) must not fire at h_min; the speed
    rises to V and settles there. A speed heading down at once still fires at once."""
    w, zeta, V = 30.0, 0.5, 2.0                      # v'' = -w^2 (v - V) - 2 zeta w v'
    A = np.array([[0.0, 1.0], [-w * w, -2 * zeta * w]])
    form = closed_form(A, np.array([0.0, w * w * V]))
    noise = np.array([-1e-15, 3e-16])                # v, v' at the start, rounding only
    assert form.state(1e-10, noise)[0] < 0            # what the old search fired on
    assert first_crossing(form, noise, np.array([1.0, 0.0]), 0.0, 2.0, direction=-1) is None
    assert np.min(form.state(np.linspace(1e-3, 2.0, 2000), noise)[:, 0]) > 0
    down = first_crossing(form, np.array([0.0, -1.0]), np.array([1.0, 0.0]), 0.0, 2.0,
                          direction=-1)
    assert down is not None and down <= 2e-10


@pytest.mark.parametrize("payload", [0.0, 52e3])
def test_fig9_against_solve_ivp(payload):
    """The phases in closed form against DOP853 with events (rtol 1e-12, steps
    capped at 0.1 ms), state and torque."""
    run, _ = _stop(payload, 0.3)
    closed = run.solve()
    integrated = integrate_hybrid(run, 1e-12, 1e-12, "DOP853", max_step=1e-4)
    assert len(integrated.phases) == len([s for s in closed.segments if s.t1 > s.t0])
    times = np.linspace(0.0, 0.3, 3001)
    states = integrated.state(times)
    scale = np.abs(states).max(axis=0)
    assert np.max(np.abs(closed.state(times) - states) / scale) < 1e-6
    torque = integrated.output(run, times)
    assert np.max(np.abs(run.table(closed)(times) - torque)) < 1e-6 * np.abs(torque).max()
    peak_t, peak = largest(closed, run.system, run.output, magnitude=True)
    sampled = values(closed, np.linspace(0, 0.3, 30001), run.output)
    assert abs(peak) >= np.max(np.abs(sampled)) - 1e-9


def test_solve_ivp_with_default_steps_skips_a_contact_the_closed_form_finds():
    """Lowering the hook: after the first rebound the flanks touch for ~4 ms at
    t = 0.163 s inside one solve_ivp step; its events miss it, the certified
    search does not."""
    run, _ = _stop(0.0, 0.2)
    hoist = run.system
    closed = [t for t, ev, _ in run.solve().events if ev == "coupling closes +"]
    assert closed and 0.16 < closed[0] < 0.165
    seen = []

    class Spy:
        matrices, guards = hoist.matrices, hoist.guards

        def switch(self, mode, name, t, x):
            seen.append((t, name))
            return hoist.switch(mode, name, t, x)
    integrate_hybrid(replace(run, system=Spy()), 1e-12, 1e-12, "DOP853")
    assert not any(name == "coupling closes +" and t < 0.17 for t, name in seen)


def test_backlash_to_zero_is_the_linear_two_mass_solution():
    """s = 0: while the drum slides, the gearbox torque is that of the linear
    two-mass system (no contact logic), from expm."""
    h, q = _stop(0.0, 0.25, backlash_deg=0.0)
    run = h.solve()
    first_rest = next((t for t, ev, _ in run.events if "rests" in ev), 0.25)
    # motor off, no brake yet; then the safety brake sliding on the drum side
    mode_a = Mode((), ("free", "free"), (False, False), (False,), (False, False))
    mode_b = Mode((), ("free", "+"), (True, False), (False,), (False, False))
    Aa, ba = h.system.matrices(mode_a)
    Ab, bb = h.system.matrices(mode_b)
    x_sb = _expm_state(Aa, ba, h.x0, 0.1)
    times = np.linspace(0.1, first_rest, 200)
    ref = np.array([_expm_state(Ab, bb, x_sb, t - 0.1) for t in times])
    torque = q["c"] * (ref[:, 2] - ref[:, 0]) / rated_torque(q)
    assert np.allclose(values(run, times, h.output), torque, atol=1e-7 * np.abs(torque).max())
    # and with a tiny backlash the peak converges to the no-backlash one
    tiny, _ = _stop(0.0, 0.25, backlash_deg=1e-7)
    assert largest(tiny.solve(), tiny.system, tiny.output, magnitude=True)[1] == \
        pytest.approx(largest(run, h.system, h.output, magnitude=True)[1], rel=1e-4)


def test_simulate_rejects_runaway_events():
    h, _ = _stop(0.0, 1.0)
    with pytest.raises(RuntimeError, match="events"):
        simulate(h.system, h.mode, h.x0, 1.0, [(0.0, "drive off"), (0.1, "safety engages")],
                 max_events=3)


def test_generated_no_backlash_torque_is_the_backlash_to_zero_limit():
    from crane_sym.generated import hoist_brakes as gen
    h, _ = _stop(0.0, 0.25, backlash_deg=0.0)
    times = np.linspace(0.0, 0.25, 501)
    closed = gen.elastic_gearbox_torque_no_backlash(
        times, J1=20.0, J2=500.0, m_h=1e4, m_p=0.0, m_r=52e3, r=0.5, i_g=26.2, i_t=4.0,
        g=9.81, c=4e4, M_SB=130e3, t_SB=0.1)
    assert np.max(np.abs(closed - values(h.solve(), times, h.output))) < 1e-11
    with_backlash, _ = _stop(0.0, 0.25)
    wb = values(with_backlash.solve(), times, with_backlash.output)
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


# --- the tabulated response a scene's module carries (crane_sym.mechanics.phase_table) -------
def _scene_module(tmp_path):
    from crane_sym.scenes.run import import_module_file
    from crane_sym.scenes.specialize import scene_files
    (name, text), = scene_files("hoist_table1").items()
    (tmp_path / name).write_text(text)
    return import_module_file(tmp_path / name)


def test_scene_module_carries_the_derivation_table(tmp_path):
    """The printed arrays are the run's table rounded to 13 digits, and the
    function is the phases' closed forms to ~1e-12 of the peak."""
    from crane_sym.derivations.hoist_brakes.hybrid import EMERGENCY_STOP
    from crane_sym.mechanics.exact_phases import exact_table
    from crane_sym.scenes.reading import load_scene
    from crane_sym.codegen.tabulated import rounded
    module = _scene_module(tmp_path)
    scene = load_scene("hoist_table1")
    table = exact_table(EMERGENCY_STOP.run(scene.parameters, scene.options))
    for printed, ours in zip(module._TABLE_ELASTIC_GEARBOX_TORQUE, rounded(table).arrays()):
        assert np.array_equal(printed, ours)
    times = np.linspace(0.0, 1.0, 100_001)
    ref = EMERGENCY_STOP.solve(scene.parameters, {"duration": 1.0}).values("relative_torque",
                                                                            times)
    got = module.elastic_gearbox_torque(times)
    assert np.max(np.abs(got - ref)) < 2e-11 * np.max(np.abs(ref))
    assert np.max(np.abs(table(times) - ref)) < 1e-12 * np.max(np.abs(ref))
    buffer = np.empty_like(times)
    assert module.elastic_gearbox_torque(times, out=buffer) is buffer
    assert float(module.elastic_gearbox_torque(0.5)) == pytest.approx(got[50_000], abs=1e-15)


def test_scene_module_against_solve_ivp(tmp_path):
    """The generated function against DOP853 with events at rtol 1e-12, the
    whole run of the scene (1 s, the rated payload lowered)."""
    from crane_sym.derivations.hoist_brakes.hybrid import EMERGENCY_STOP
    from crane_sym.scenes.reading import load_scene
    module = _scene_module(tmp_path)
    scene = load_scene("hoist_table1")
    run = EMERGENCY_STOP.run(scene.parameters, scene.options)
    times = np.linspace(0.0, 1.0, 10_001)
    ref = integrate_hybrid(run, 1e-12, 1e-12, "DOP853", max_step=1e-4).output(run, times)
    got = module.elastic_gearbox_torque(times)
    assert np.max(np.abs(got - ref)) < 1e-6 * np.max(np.abs(ref))


@pytest.mark.parametrize("payload,stiffness,backlash_deg", [
    (0.0, 4e4, 3.0), (52e3, 4e4, 3.0), (0.0, 4e2, 3.0), (0.0, 4e7, 3.0),
    (0.0, 4e4, 1e-9), (52e3, 4e4, 0.0)])
def test_table_is_the_run_on_hard_cases(payload, stiffness, backlash_deg):
    """Payload -> 0, tiny and huge stiffness, backlash -> 0: the table (what a
    scene's module evaluates) against the run's own closed forms."""
    from crane_sym.mechanics.phase_table import tabulate
    h, _ = _stop(payload, 1.0, backlash_deg=backlash_deg, stiffness=stiffness)
    run = h.solve()
    table = tabulate(run, h.output)
    times = np.sort(np.concatenate([np.linspace(0, 1, 20_001), table.edges]))
    ref = values(run, times, h.output)      # w·x(t) summed in another order
    assert np.max(np.abs(table(times) - ref)) < 4e-12 * np.max(np.abs(ref))


def test_table_with_backlash_to_zero_is_the_no_backlash_closed_form():
    """delta -> 0: the tabulated response agrees with the generated
    no-backlash closed form while that one holds (drum sliding, before t_BB)."""
    from crane_sym.derivations.hoist_brakes.hybrid import EMERGENCY_STOP
    from crane_sym.derivations.hoist_brakes.model import TABLE1
    from crane_sym.generated import hoist_brakes as gen
    q = {k: float(v) for k, v in TABLE1.items()} | {"g": 9.81, "m_p": 0.0,
                                                     "omega1": 50 * np.pi}
    table = EMERGENCY_STOP.run(q | {"delta": 1e-12}, {"duration": 0.25}).table()
    rest = next((t for t, e in zip(table.edges[1:], table.events) if "rests" in e), 0.25)
    times = np.linspace(0.0, rest, 2001)
    closed = gen.elastic_gearbox_torque_no_backlash(
        times, J1=q["J1"], J2=q["J2"], m_h=q["m_h"], m_p=0.0, m_r=q["m_r"], r=q["r"],
        i_g=q["i_g"], i_t=q["i_t"], g=9.81, c=q["c"], M_SB=q["M_SB"], t_SB=q["t_SB"])
    assert np.max(np.abs(table(times) - closed)) < 1e-8 * np.max(np.abs(closed))


@pytest.mark.parametrize("bad,match", [(-0.1, ">= 0"), (1.5, "<= 1.0"), (np.nan, "finite"),
                                       ("0.3", "number")])
def test_scene_function_rejects_bad_times(tmp_path, bad, match):
    module = _scene_module(tmp_path)
    with pytest.raises((ValueError, TypeError), match=match) as info:
        module.elastic_gearbox_torque(bad)
    assert "t" in str(info.value)


def test_check_flags_a_last_digit_change_of_a_table(tmp_path):
    """generate --check compares bytes: a table number one digit off in its
    last place is stale (the table is solved in mpmath, the same everywhere)."""
    from crane_sym.codegen.files import compare
    from crane_sym.scenes.specialize import scene_files
    files = scene_files("hoist_table1")
    (name, text), = files.items()
    (tmp_path / name).write_text(text, encoding="utf-8")
    assert compare(files, tmp_path).ok
    number = text.split("# cos_amps")[1].split("[")[1].split(",")[0]
    last = number[:-1] + str((int(number[-1]) + 1) % 10)
    (tmp_path / name).write_text(text.replace(number, last, 1), encoding="utf-8")
    assert compare(files, tmp_path).differs == [name]
