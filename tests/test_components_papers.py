"""Papers 002 and 004 as components.

Paper 002's two-mass hoist under a drive law gives the derivation's equations
(1) with P of (31) symbolically, and the rope force of the paper's generated
functions (Duhamel's integral, (22), (24), (26)) to 1e-9. Paper 004's drum
drive, as far as it fits the parts (element massless, drum shaft rigid), gives
its equations (12) so reduced symbolically, their solution to 1e-9, and the
chain's frequencies (13)."""
from __future__ import annotations

import importlib

import numpy as np
import pytest
import sympy as sp

from crane_sym import registry
from crane_sym.components import Model, MotorLaw
from crane_sym.components.compare import compare_equations
from crane_sym.components.component_file import read_component_file
from crane_sym.mechanics.exact_phases import exact_table

from test_components_laws import (BREAKS, EXAMPLES, G, M1, M2, ROWS, generated, hoist,
                                  rope_force)


def test_equations_are_paper_002s_lagrange_equations_with_the_drive_force_of_31():
    """(1): m1 x1'' + C (x1 − x2) = P, m2 x2'' − C (x1 − x2) = −Q, with P of (31)
    and Q = m2 g, from the components' T, Π and Q; a drive force without the
    weight is caught."""
    d = registry.get("hoist_startup")
    paper = importlib.import_module("crane_sym.derivations.hoist_startup.model")
    model = hoist(MotorLaw("motor", "drive", BREAKS, ROWS, "m/s^2", law="acceleration"))
    eq = model.equations
    s = {x.name: x for x in [*eq.values, *eq.signals]}
    t = eq.t                                    # the paper's equations in the parts' time
    names = {s["m_drive"]: paper.m1, s["m_load"]: paper.m2, s["c_rope"]: paper.C,
             s["d_rope"]: 0, s["g_weight"]: paper.g, s["a_motor"]: paper.a.func(t),
             eq.coordinates[0]: paper.x1.func(t), eq.coordinates[1]: paper.x2.func(t)}
    P = d.step("(31)").statement.rhs
    Q = d.step("(31), Q").statement.rhs
    reference = [d.step(label).statement.subs({paper.P: P, paper.Q: Q}).subs(paper.t, t)
                 for label in ("(1)", "(1), load")]
    records = compare_equations(eq, reference, {}, names)
    assert [r.outcome.status for r in records] == ["pass", "pass"]
    wrong = [reference[0].subs(paper.g, 0), reference[1]]
    assert [r.outcome.status for r in compare_equations(eq, wrong, {}, names)] == \
        ["fail", "pass"]


def test_from_weight_rope_force_equals_the_scenes_generated_function():
    """The example file (the scene hoist_user_drive_law as components): the rope
    force of the run, phase by phase, against the scene's generated rope_force
    (24), to 1e-9 of its largest value (and of the run's mpmath tables, which
    its module prints); the dynamic factor against (27)."""
    read = read_component_file(EXAMPLES / "hoist_drive_law.toml")
    run = read.model.run(read.duration, read.body, read.speed)
    times = np.linspace(0.0, 2.5, 2501)
    theirs = generated("scene_hoist_user_drive_law").rope_force(times)
    assert np.max(np.abs(rope_force(run, times) - theirs)) <= 1e-9 * np.max(np.abs(theirs))
    exact = exact_table(run.hybrid_run("rope"))(times)     # the module `crane-sym run` writes
    assert np.max(np.abs(exact - theirs)) <= 1e-9 * np.max(np.abs(theirs))
    k = generated("scene_hoist_user_drive_law").dynamic_coefficient(times)
    assert run.peaks[0].factor == pytest.approx(np.max(k), rel=1e-6)     # sampled maximum
    assert [e for _, e in run.events] == ["hoist next piece"] * 3


@pytest.mark.parametrize("i", [1, 3, 4])
def test_pickup_with_the_laws_of_30_equals_the_generated_dynamic_coefficient(i):
    """Lifting with pick-up (7), (26), (28)-(29), the laws a_i of (30) as printed
    (a_4 of degree 5: five clock states), the ground's reaction a torque law on
    the load: K(t) = C x / reference of (25) against the scene hoist_drive_laws's
    generated dynamic_coefficient_pickup_a<i>, to 1e-9 of its largest value."""
    v0, t_n, tau0 = 0.25, 1.0, 0.31392
    shape = {1: [1.0], 3: [0.0, 12.0, -24.0, 12.0], 4: [0.0, 0.0, 60.0, -180.0, 180.0, -60.0]}
    law = MotorLaw("motor", "drive", [0.0, t_n], [[v0 / t_n * c for c in shape[i]]], "m/s^2",
                   law="acceleration")
    ground = MotorLaw("ground", "load", [0.0, tau0], [[M2 * G, -M2 * G / tau0]], "N")
    run = hoist(law, ground).run(2.0, rest=True)
    times = np.linspace(0.0, 2.0, 4001)
    p0 = (M1 + M2) * v0 / t_n * shape[i][0] + M2 * G
    ours = rope_force(run, times) / (M2 * p0 / (M1 + M2))
    theirs = getattr(generated("scene_hoist_drive_laws"), f"dynamic_coefficient_pickup_a{i}")(
        times)
    assert np.max(np.abs(ours - theirs)) <= 1e-9 * np.max(np.abs(theirs))


def test_pickup_example_file_equals_the_paper_route():
    """The pick-up example against the paper's own route (drive_law.respond: the
    stretch by Duhamel's integral, (21)-(22)), to 1e-9 of the largest force."""
    drive_law = importlib.import_module("crane_sym.derivations.hoist_startup.drive_law")
    read = read_component_file(EXAMPLES / "hoist_drive_law_pickup.toml")
    run = read.model.run(read.duration, rest=read.rest)
    law = drive_law.drive_law([0, sp.Rational(1, 4), 1, sp.Rational(5, 4)],
                              [[0, 2], [sp.Rational(1, 2)], [sp.Rational(1, 2), -2]])
    response = drive_law.respond(law, 2000, 8000, 10**6, sp.Rational(981, 100), "pickup")
    assert response.contact_time == sp.Rational(15696, 100000)
    force = sp.lambdify(response.t, response.rope_force(), "mpmath")
    times = np.linspace(0.0, 2.5, 501)
    theirs = np.array([float(force(t)) for t in times])
    assert np.max(np.abs(rope_force(run, times) - theirs)) <= 1e-9 * np.max(np.abs(theirs))




# --- paper 004: the drum drive ----------------------------------------------------------
#: The example's values (SI), by the paper's symbol names.
DRUM = {"I1": 13.0, "I2": 3.0, "I3": 50.0, "C1": 2e4, "C2": 5e4, "nu1": 20.0, "nu2": 50.0,
        "r": 0.25, "m_L": 2500.0, "C_t": 5e4, "C_z": 5e4, "nu_z": 500.0, "nu_t": 400.0,
        "M0": 440.0, "W": 1000.0}


def drum_drive_reference():
    """004's equations (12) for φ1, φ2, φ3, z with the element massless (q = 0)
    and the drum shaft rigid (y = 0), in the time symbol ``t`` given later."""
    d = registry.get("drum_drive")
    paper = importlib.import_module("crane_sym.derivations.drum_drive.model")
    eqs = [d.step(f"(12), {name}").statement for name in ("φ1", "φ2", "φ3", "z")]
    return paper, [sp.Eq(e.lhs.subs(paper.q, 0).subs(paper.y, 0).doit(),
                         e.rhs.subs(paper.q, 0).subs(paper.y, 0).doit()) for e in eqs]


def test_drum_drive_equations_are_004s_with_a_massless_element_and_a_rigid_shaft():
    """The example's Lagrange equations, renamed to 004's symbols, are 004's
    (12) for φ1, φ2, φ3 and z with q = 0 and y = 0; with the element's mass
    kept, 004's φ3 and z equations differ from them (it does not fit)."""
    paper, reference = drum_drive_reference()
    model = read_component_file(EXAMPLES / "drum_drive.toml").model
    eq = model.equations
    t = eq.t
    s = {x.name: x for x in [*eq.values, *eq.switches, *eq.motor_loads, *eq.slopes]}
    p = paper
    names = {s["J_motor"]: p.I1, s["J_gearbox"]: p.I2, s["J_drum"]: p.I3, s["m_rim"]: 0,
             s["m_run"]: p.m_L, s["r_wrap"]: p.r, s["n_wrap"]: 1, s["c_shaft1"]: p.C1,
             s["d_shaft1"]: p.nu1, s["c_shaft2"]: p.C2, s["d_shaft2"]: p.nu2,
             s["c_tight"]: p.C_t, s["d_tight"]: 0, s["c_slack"]: p.C_z,
             s["d_slack"]: p.nu_z, s["beta_running"]: p.nu_t, s["v0_running"]: 0,
             s["R_load"]: -p.W, s["M_drive"]: p.M0}
    names.update({q: f.func(t) for q, f in zip(eq.coordinates, (p.phi1, p.phi2, p.phi3, p.z))})
    ours = [e.subs(p.t, t) for e in reference]
    records = compare_equations(eq, ours, {s["on_drive"]: 1}, names)
    assert [r.outcome.status for r in records] == ["pass"] * 4
    d = registry.get("drum_drive")
    massive = [d.step(f"(12), {n}").statement.subs(p.y, 0).doit().subs(p.t, t)
               for n in ("φ1", "φ2", "φ3", "z")]
    assert [r.outcome.status for r in compare_equations(eq, massive, {s["on_drive"]: 1},
                                                        names)] == \
        ["pass", "pass", "fail", "fail"]


def test_drum_drive_run_solves_004s_equations():
    """The example's run from rest against 004's reduced equations (12)
    integrated in their twists by DOP853 at rtol 1e-12: the shafts' torques and
    the tight branch's force of the run's generated tables (phases replayed in
    mpmath) to 1e-9 of their peaks, of the run in double precision to 2e-9."""
    from scipy.integrate import solve_ivp
    paper, reference = drum_drive_reference()
    p = paper
    coords = (p.phi1, p.phi2, p.phi3, p.z)
    acc = [sp.Symbol(f"a{i}") for i in range(4)]
    pos, vel = sp.symbols("q0:4"), sp.symbols("v0:4")
    plain = {}
    for c, a, x, v in zip(coords, acc, pos, vel):
        plain.update({c.diff(p.t, 2): a, c.diff(p.t): v})
    values = {getattr(p, k): v for k, v in DRUM.items()}
    rows = [(e.lhs - e.rhs).subs(plain).subs(dict(zip(coords, pos))).subs(values)
            for e in reference]
    solved = sp.solve(rows, acc, dict=True)[0]
    rate = sp.lambdify([pos, vel], [solved[a] for a in acc])

    r = DRUM["r"]

    def rhs(_, state):
        """In the twists θ1 = φ1 − φ2, θ2 = φ2 − φ3, e1 = r φ3 − z (nothing holds
        the drive to the frame: the equations see differences only, and these
        stay small while the angles grow)."""
        th1, th2, e1, v = state[0], state[1], state[2], state[3:]
        return [v[0] - v[1], v[1] - v[2], r * v[2] - v[3],
                *rate([th1 + th2, th2, 0.0, -e1], v)]
    read = read_component_file(EXAMPLES / "drum_drive.toml")
    run = read.model.run(read.duration, rest=read.rest)
    times = np.linspace(0.0, 10.0, 2001)
    sol = solve_ivp(rhs, (0.0, 10.0), [0.0] * 7, method="DOP853", rtol=1e-12, atol=1e-15,
                    t_eval=times)
    th1, th2, e1, w1, w2, w3, _ = sol.y
    theirs = {"shaft1": -DRUM["C1"] * th1 + DRUM["nu1"] * (w2 - w1),
              "shaft2": -DRUM["C2"] * th2 + DRUM["nu2"] * (w3 - w2),
              "tight": DRUM["C_t"] * e1}
    links = [l.part.name for l in run.system.assembly.links]
    for name, curve in theirs.items():
        peak = np.max(np.abs(curve))
        exact = exact_table(run.hybrid_run(name))(times)      # what `crane-sym run` prints
        assert np.max(np.abs(exact - curve)) <= 1e-9 * peak, name
        # the double-precision phases: the angles grow to ~70 rad while the
        # twists stay ~1e-2, and the run drifts by ~1.3e-9 of the peak over 10 s
        ours = rope_force_of(run, links.index(name), times)
        assert np.max(np.abs(ours - curve)) <= 2e-9 * peak, name


def rope_force_of(run, index, times):
    from crane_sym.mechanics.phase_table import values
    return values(run.result, times, run.system.link_load(index))


def test_drum_drive_chain_frequencies_are_004s_13():
    """The chain alone (I1–C1–I2–C2–I3, free at both ends): the frequencies of
    the component model's closed form are 004's generated ω1, ω2 of (13)."""
    from crane_sym.components import ElasticLink, Inertia, Motor
    model = Model([Inertia("motor", 13.0), Inertia("gearbox", 3.0), Inertia("drum", 50.0),
                   ElasticLink("shaft1", "motor", "gearbox", 2e4),
                   ElasticLink("shaft2", "gearbox", "drum", 5e4), Motor("drive", "motor", 440.0)])
    run = model.run(1.0, rest=True)
    omegas = sorted({round(w, 9) for w in run.result.segments[0].form.omegas if w > 0})
    module = generated("drum_drive")
    theirs = [float(f(13.0, 3.0, 50.0, 2e4, 5e4)) for f in
              (module.drive_chain_frequency_1, module.drive_chain_frequency_2)]
    assert omegas == pytest.approx(theirs, rel=1e-9)
