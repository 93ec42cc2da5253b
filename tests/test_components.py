"""Component models: paper 001's Fig. 9 hoist and paper 003's start-up, the
papers' one hybrid route, against their equations of motion written by hand
(``hybrid_references.py``: SciPy's DOP853 with events) and, for 001, against
the batched family written for arrays; brakes that ramp or rise exponentially stop a
body when their closed forms say; brakes hold within their capacity; the
steady start balances the loads; the equations are Lagrange's of the parts."""
from __future__ import annotations

import importlib

import numpy as np
import pytest
import sympy as sp
from scipy.optimize import brentq

from crane_sym.components import (Brake, ComponentError, Drum, ElasticLink, Gear, Gravity,
                                  Inertia, Mass, Model, Motor, Resistance)


def fig9_parts(payload: float) -> list:
    """Table 1's hoist as components, lowering ``payload`` kg (+ = lowering)::

        motor J1 --[c, backlash δ·i_g]-- shaft --gear i_g-- drum J2 --drum r, i_t-- hook
    """
    return [Inertia("motor", "20 kg*m^2"), Inertia("shaft", 0),
            Inertia("drum", "500 kg*m^2"), Mass("hook", 10e3 + payload),
            Gear("gearbox", "shaft", "drum", "26.2"), Drum("rope", "drum", "hook", "0.5 m", 4),
            ElasticLink("coupling", "motor", "shaft", "4e4 N*m/rad",
                        backlash=np.radians(3.0) * 26.2),
            Gravity("weight", "hook", "9.81 m/s^2"),
            Motor("drive", "motor", "steady", off_at="0 s"),
            Brake("safety", "drum", "130 kN*m", delay="0.1 s"),
            Brake("service", "motor", "5.8 kN*m", delay="0.4 s")]


def test_fig9_parts_are_the_papers_model():
    """The parts above (examples/drive_trains/hoist_fig9.toml's) are the
    model of ``hybrid.EMERGENCY_STOP`` (``drive_train.fig9_model``). To rounding:
    the paper's model is a design of its template (its matrices from the shared
    lambdified form in NumPy), a file's is derived alone (its values folded in
    by SymPy), so the two round differently."""
    from crane_sym.derivations.hoist_brakes.drive_train import OMEGA1, table1_values
    from crane_sym.derivations.hoist_brakes.hybrid import EMERGENCY_STOP
    ours = Model(fig9_parts(52e3)).run(1.0, "motor", OMEGA1).peaks[0]
    paper = EMERGENCY_STOP.solve(table1_values(52e3), {"duration": 1.0})
    when, relative = paper.peak("relative_torque")
    assert ours.value / paper.system.assembly.links[0].reference == pytest.approx(
        relative, rel=1e-12)
    assert ours.time == pytest.approx(when, rel=1e-12)


@pytest.mark.parametrize("payload", [0.0, 52e3])
def test_fig9_run_agrees_with_the_papers_equations_integrated(payload):
    """Paper 001's emergency stop (``hybrid.EMERGENCY_STOP``, built from
    components) against the two-mass hoist's equations written by hand and
    integrated by DOP853 with events at rtol 1e-13: M_G/M_st everywhere on the
    run (measured: 5.9e-10 and 1.0e-9 of the peak; the reference's kinks at the
    flanks are stepped over, not located) and at the peak (2e-13, 6e-12)."""
    from hybrid_references import fig9_reference

    from crane_sym.derivations.hoist_brakes.drive_train import table1_values
    from crane_sym.derivations.hoist_brakes.hybrid import EMERGENCY_STOP
    q = table1_values(payload)
    solution = EMERGENCY_STOP.solve(q, {"duration": 1.0})
    when, peak = solution.peak("relative_torque")
    reference = fig9_reference(q, 1.0)
    times = np.linspace(0.0, 1.0, 20001)
    ours, theirs = solution.values("relative_torque", times), reference(times)
    assert np.max(np.abs(ours - theirs)) <= 3e-9 * abs(peak)
    assert reference([when])[0] == pytest.approx(peak, rel=1e-10)
    assert np.max(np.abs(theirs)) <= abs(peak) * (1 + 1e-9)
    # the start is steady lowering: the motor holds, twist M_L/c on the holding flank
    gear = q["r"] / (q["i_g"] * q["i_t"])
    M_L = (q["m_h"] + payload) * q["g"] * gear
    assert np.allclose(solution.run.x0, [0.0, q["omega1"], M_L / q["c"], q["omega1"]],
                       rtol=1e-12, atol=0)


def test_fig9_peaks_agree_with_the_batched_family_written_for_arrays():
    """The same emergency stop by a second hand-written route: the two-mass
    hoist reduced by hand and written for arrays of designs
    (``elastic_batched.family_from``), solved by the batched solver; the peak
    and its time for designs around Table 1's."""
    from crane_sym.derivations.hoist_brakes.drive_train import table1_values
    from crane_sym.derivations.hoist_brakes.elastic_batched import family_from
    from crane_sym.derivations.hoist_brakes.hybrid import EMERGENCY_STOP
    designs = [table1_values(m, backlash_deg=deg, stiffness=c) for m, deg, c in
               ((0.0, 3.0, 4e4), (52e3, 3.0, 4e4), (20e3, 1.0, 1e5), (0.0, 0.5, 1e4))]
    q = {k: np.array([d[k] for d in designs]) for k in designs[0]}
    batched = family_from(q, 1.0).peaks(tail=0)
    assert batched.summary["batched"] == len(designs)
    for i, design in enumerate(designs):
        when, peak = EMERGENCY_STOP.solve(design, {"duration": 1.0}).peak("relative_torque")
        assert batched.value[i] == pytest.approx(peak, rel=1e-9)
        assert batched.time[i] == pytest.approx(when, abs=1e-9)


def test_fig9_equations_are_the_two_mass_model():
    """The merged drum side carries J2/i² + m (r/(i n))², and the equations are
    M q̈ + K q = f with the hand-written model's matrices."""
    model = Model(fig9_parts(52e3))
    eq = model.equations
    M, D, K, f = eq.linear
    sym = {s.name: s for s in eq.values}
    i, r, n = sym["i_gearbox"], sym["r_rope"], sym["n_rope"]
    J_d = sym["J_drum"] / i**2 + sym["m_hook"] * (r / (i * n))**2 + sym["J_shaft"]
    assert sp.simplify(M - sp.diag(sym["J_motor"], J_d)) == sp.zeros(2)
    c = sym["c_coupling"]
    chi = eq.contact[0]
    assert sp.simplify(K - chi * c * sp.Matrix([[1, -1], [-1, 1]])) == sp.zeros(2)
    assert len(eq.latex()) == 2


def test_ramp_brake_stops_a_flywheel_when_the_closed_form_says():
    J, omega0, M, delay, ramp = 12.0, 30.0, 400.0, 0.05, 0.8
    model = Model([Inertia("wheel", J), Brake("b", "wheel", M, delay, "ramp", ramp)])
    run = model.run(3.0, "wheel", omega0)
    stop = dict((e, t) for t, e in run.events)["wheel rests"]
    # ω = ω0 − M τ²/(2 J T) during the ramp, ω0 − M (T/2 + τ − T)/J after it
    within = delay + np.sqrt(2 * ramp * J * omega0 / M)
    expected = within if within <= delay + ramp else delay + ramp / 2 + J * omega0 / M
    assert stop == pytest.approx(expected, rel=1e-9)
    assert run.result.segments[-1].mode.motion == ("0",)       # held at rest


def test_exponential_brake_stops_a_flywheel_when_the_closed_form_says():
    J, omega0, M, delay, T = 5.0, 20.0, 300.0, 0.1, 0.2
    model = Model([Inertia("wheel", J), Brake("b", "wheel", M, delay, "exponential", T)])
    run = model.run(3.0, "wheel", omega0)
    stop = dict((e, t) for t, e in run.events)["wheel rests"]
    speed = lambda tau: omega0 - M / J * (tau - T * (1 - np.exp(-tau / T)))  # noqa: E731
    assert stop == pytest.approx(delay + brentq(speed, 1e-9, 10.0, xtol=1e-15), rel=1e-9)


@pytest.mark.parametrize("capacity, holds", [(2.0, True), (0.5, False)])
def test_a_brake_holds_the_load_within_its_capacity(capacity, holds):
    """A lowering hook braked at the drum: held at rest when the brake's torque
    exceeds the load's, sliding (and speeding up) when it does not."""
    m, g, r = 2000.0, 9.81, 0.4
    load = m * g * r
    model = Model([Inertia("drum", 50.0), Mass("hook", m), Drum("rope", "drum", "hook", r),
                   Gravity("weight", "hook", g), Motor("drive", "drum", "steady", off_at=0.0),
                   Brake("brake", "drum", capacity * load, delay=0.0)])
    run = model.run(2.0, "hook", "0.5 m/s")
    assert run.system.extra[model.steady_motor] == pytest.approx(-load, rel=1e-12)
    events = [e for _, e in run.events]
    assert ("drum rests" in events) is holds
    end = run.result.segments[-1]
    if holds:
        J = 50.0 + m * r**2
        stop = 0.5 / r / ((capacity * load - load) / J)
        assert dict((e, t) for t, e in run.events)["drum rests"] == pytest.approx(stop, rel=1e-9)
        assert end.mode.motion == ("0",)
    else:
        assert end.state(end.t1)[1] > 0.5 / r


def test_steady_start_balances_a_resistance():
    model = Model([Mass("trolley", "4 t"), Resistance("rolling", "trolley", "-1.2 kN"),
                   Motor("drive", "trolley", "steady")])
    mode, x0, extra = model.start("trolley", "1 m/s")
    assert extra[model.steady_motor] == pytest.approx(1200.0)
    assert x0[1] == 1.0
    run = model.run("1 s", "trolley", "1 m/s")
    assert run.result.segments[-1].state(1.0)[1] == pytest.approx(1.0, rel=1e-12)


def test_unbalanced_start_without_a_steady_motor_is_refused():
    with pytest.raises(ComponentError, match="steady"):
        Model([Mass("trolley", "4 t"), Resistance("rolling", "trolley", "-1.2 kN")]).start(
            "trolley", "1 m/s")


def test_a_damped_link_rings_down_to_its_new_static_load():
    """Two masses and a damped spring, b pulled by a constant force and a held
    by a steady motor until it lets go: the load is the pull until then, and
    settles to the pull's share m_a/(m_a + m_b) after; a phase of constant load
    is no trap for the search of extrema."""
    model = Model([Mass("a", 100.0), Mass("b", 300.0),
                   ElasticLink("spring", "a", "b", "1e5 N/m", "2000 N*s/m", reference="1 kN"),
                   Resistance("pull", "b", "1 kN"), Motor("hold", "a", "steady", off_at=0.5)])
    run = model.run("3 s", "a", 0.0)
    peak = run.peaks[0]
    assert peak.value == pytest.approx(1000.0, rel=1e-12) and peak.factor == pytest.approx(1)
    w, k = run.system.link_load(0)(run.result.segments[-1].mode)
    end = run.result.segments[-1]
    assert float(w @ end.state(3.0) + k) == pytest.approx(250.0, rel=1e-6)


def test_fig9_equations_match_the_hand_written_model_symbolically():
    """The component model's Lagrange equations, renamed to Table 1's symbols,
    are the two-mass model's, written by hand here, in each kind of mode (J1 θ̈_m =
    T − M_M + brake, J_d θ̈_d = −T + M_L − brake, T = c (θ_d − θ_m + off)); a
    hand-written model that forgets the hook's inertia is caught."""
    from crane_sym.components.compare import compare_equations
    model = Model(fig9_parts(52e3))
    eq = model.equations
    s = {x.name: x for x in eq.values} | {x.name: x for x in
                                          (*eq.contact, *eq.flank, *eq.switches, *eq.friction,
                                           *eq.motor_loads)}
    t = eq.t
    J1, J2, m_h, m_p, r, i_g, i_t, g, c, gap, M_SB, M_L_ = sp.symbols(
        "J1 J2 m_h m_p r i_g i_t g c s M_SB M_L", positive=True)
    th_m, th_d = sp.Function("theta_m")(t), sp.Function("theta_d")(t)
    names = {s["J_motor"]: J1, s["J_shaft"]: 0, s["J_drum"]: J2, s["m_hook"]: m_h + m_p,
             s["i_gearbox"]: i_g, s["r_rope"]: r, s["n_rope"]: i_t, s["g_weight"]: g,
             s["c_coupling"]: c, s["d_coupling"]: 0,
             eq.coordinates[0]: th_m, eq.coordinates[1]: th_d}
    J_d = J2 / i_g**2 + (m_h + m_p) * (r / (i_g * i_t))**2
    M_L = (m_h + m_p) * g * r / (i_g * i_t)

    def hand(off, motor, drum_brake, J_drum=J_d):
        T = c * (th_d - th_m + off)
        return [sp.Eq(J1 * th_m.diff(t, 2), T + motor),
                sp.Eq(J_drum * th_d.diff(t, 2), -T + M_L + drum_brake)]

    modes = {   # holding flank, motor holding; other flank, motor off, safety brake sliding
        "holding": ({s["chi_coupling"]: 1, s["delta_coupling"]: 0, s["on_drive"]: 1,
                     s["M_drive"]: -M_L_, s["B_safety"]: 0, s["B_service"]: 0},
                    hand(0, -M_L_, 0)),
        "other flank": ({s["chi_coupling"]: 1, s["delta_coupling"]: -gap, s["on_drive"]: 0,
                         s["B_safety"]: -M_SB, s["B_service"]: 0},
                        hand(gap, 0, -M_SB / i_g)),
    }
    for name, (mode, reference) in modes.items():
        records = compare_equations(eq, reference, mode, names)
        assert [r.outcome.status for r in records] == ["pass", "pass"], name
        assert "hand-written" in records[1].latex()
    mode, _ = modes["holding"]
    wrong = compare_equations(eq, hand(0, -M_L_, 0, J_drum=J2 / i_g**2), mode, names)
    assert [r.outcome.status for r in wrong] == ["pass", "fail"]
    assert "m_{h}" in wrong[1].outcome.detail


@pytest.mark.parametrize("phi_b", [0.0, np.pi, 2 * np.pi])
def test_paper_003_start_up_agrees_with_the_papers_equations_integrated(phi_b):
    """Paper 003's travel drive (``hybrid.STARTUP``, built from components:
    two links with backlash, a stepped start, the crane held by its friction)
    against the three-mass equations written by hand and integrated by DOP853
    with events at rtol 1e-12, for Table 1's three backlash values: F1 + F2
    everywhere on the run (measured: 5e-13, 9e-12, 5e-12 of the peak) and at the
    peak."""
    from hybrid_references import fig11_reference

    from crane_sym.derivations.portal_travel.hybrid import STARTUP, rim_values
    from crane_sym.derivations.portal_travel.startup import CHOSEN, HOLDS
    v = rim_values(CHOSEN, phi_b)
    solution = STARTUP.solve(v, {"holds": HOLDS, "end": 4.0})
    when, peak = solution.peak("load")
    reference = fig11_reference(v, HOLDS, 4.0)
    times = np.linspace(0.0, 4.0, 40001)
    ours, theirs = solution.values("load", times), reference(times)
    assert np.max(np.abs(ours - theirs)) <= 1e-9 * peak
    assert reference([when])[0] == pytest.approx(peak, rel=1e-10)
    assert np.max(theirs) <= peak * (1 + 1e-9)


def test_a_brake_engaged_at_rest_holds_its_own_body():
    """The crane of paper 003 listed after the motors (its group is not the
    brake's number): the friction engaged at t = 0 holds the crane, not the
    first motor, and the run is the one with the crane listed first."""
    from crane_sym.components import Characteristic
    from crane_sym.components.hybrid import HELD
    from crane_sym.mechanics.phase_table import values

    def parts(crane_first: bool) -> list:
        bodies = [Mass("left", 15e3), Mass("crane", 250e3)]
        return (bodies if not crane_first else bodies[::-1]) + [
            ElasticLink("link", "crane", "left", 5e6, 2e4, 0.02, contact="negative"),
            Characteristic("motors", "left", 0.57, [1.7e5, 3.4e5], [0.4]),
            Brake("friction", "crane", 30e3), Resistance("wind", "crane", -10e3)]
    # numeric closed forms: the exact route (SymPy's Jordan forms of this damped
    # link's modes) took 146 s and is not what the test is about
    last, first = (Model(parts(f)).run(2.0, rest=True, exact=False) for f in (False, True))
    crane = last.system.assembly.place["crane"][0]
    assert crane == 1 and last.result.segments[1].mode.motion[crane] == HELD
    assert last.result.segments[1].mode.motion[0] == "free"
    times = np.linspace(0.0, 2.0, 2001)
    np.testing.assert_allclose(values(last.result, times, last.system.link_load(0)),
                               values(first.result, times, first.system.link_load(0)),
                               rtol=0, atol=1e-9 * abs(last.peaks[0].value))


def test_paper_000_two_mass_braking_gives_eq_14_symbolically():
    """Paper 000's bridge braked through an elastic link, as components: the
    closed form of the link force, derived in the parts' symbols from the
    relaxed start, is the paper's eq (14) (with p of eq (6))."""
    from crane_sym import registry
    from crane_sym.components.closed import link_response
    model = Model([Mass("one", "4 t"), Mass("two", "20 t"),
                   ElasticLink("link", "one", "two", "1e6 N/m"),
                   Resistance("braking", "one", "-10 kN"),
                   Resistance("resistance", "two", "-2 kN")])
    response = link_response(model)
    d = registry.get("travel_braking")
    paper = importlib.import_module("crane_sym.derivations.travel_braking.model")
    s = {x.name: x for x in model.equations.values}
    names = {s["m_one"]: paper.m1, s["m_two"]: paper.m2, s["c_link"]: paper.c,
             s["R_braking"]: -paper.P_t, s["R_resistance"]: -paper.W,
             model.equations.t: paper.t}
    eq14 = d.step("(14)").statement.rhs.subs(paper.p, d.step("(6)").statement.rhs)
    assert sp.simplify(response.force.subs(names) - eq14) == 0
    with pytest.raises(ComponentError, match="constant loads"):
        link_response(Model(fig9_parts(0.0)[:6] + [
            ElasticLink("coupling", "motor", "shaft", "4e4 N*m/rad"),
            Brake("safety", "drum", "130 kN*m")]))


def test_a_brake_engaged_at_rest_holds_its_own_group():
    """A brake on the second group engaged at t = 0, everything at rest: that
    group is held (the link's load, at most 2 kN, stays within its 5 kN), while
    the first, pushed by 1 kN, swings freely on the link."""
    model = Model([Mass("a", "1 t"), Mass("b", "2 t"), ElasticLink("l", "a", "b", "1e5 N/m"),
                   Motor("push", "a", "1 kN"), Brake("hold", "b", "5 kN")])
    run = model.run("1 s", rest=True)
    times = np.linspace(0.0, 1.0, 1001)
    x = run.result.state(times)
    assert np.max(np.abs(x[:, 2:4])) < 1e-15
    assert np.allclose(x[:, 0], 1e3 / 1e5 * (1 - np.cos(10 * times)), rtol=0, atol=1e-12)
    assert run.result.segments[-1].mode.motion == ("free", "0")
