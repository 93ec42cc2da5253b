"""Motor laws in time (paper 002's piecewise polynomial drive laws) in component
models: paper 002's two-mass hoist from components gives the derivation's
equations (1) with P of (31) symbolically, and the rope force of the paper's
generated functions (Duhamel's integral, (22), (24), (26)) to 1e-9; a torque law
of high degree is exact per phase (against solve_ivp at tight tolerance); bad
laws are refused in one line."""
from __future__ import annotations

import importlib
from pathlib import Path

import numpy as np
import pytest
import sympy as sp

from crane_sym import registry
from crane_sym.components import (ComponentError, ElasticLink, Gravity, Inertia, Mass, Model,
                                  Motor, MotorLaw)
from crane_sym.components.compare import compare_equations
from crane_sym.components.reading import read_component_file
from crane_sym.mechanics.phase_table import values

EXAMPLES = Path(__file__).resolve().parents[1] / "examples" / "drive_trains"
#: The user's law of the scene hoist_user_drive_law (and of the example files).
BREAKS, ROWS = [0.0, 0.25, 1.0, 1.25], [[0.0, 2.0], [0.5], [0.5, -2.0]]
M1, M2, C, G = 2000.0, 8000.0, 1e6, 9.81


def generated(name: str):
    """A shipped scene's generated module."""
    return importlib.import_module(f"crane_sym.generated.{name}")


def hoist(law: MotorLaw, *extra) -> Model:
    """Paper 002's Fig. 1 hoist: drive m1 over the rope C to the load m2, both up."""
    return Model([Mass("drive", M1), Mass("load", M2), ElasticLink("rope", "load", "drive", C),
                  Gravity("weight", "load", G, direction="-"), law, *extra])


def rope_force(run, times):
    return values(run.result, times, run.system.link_load(0))


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
    (24), to 1e-9 of its largest value; the dynamic factor against (27)."""
    read = read_component_file(EXAMPLES / "hoist_drive_law.toml")
    run = read.model.run(read.duration, read.body, read.speed)
    times = np.linspace(0.0, 2.5, 2501)
    theirs = generated("scene_hoist_user_drive_law").rope_force(times)
    assert np.max(np.abs(rope_force(run, times) - theirs)) <= 1e-9 * np.max(np.abs(theirs))
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


def test_torque_law_of_degree_five_against_solve_ivp():
    """A quintic torque law with a gap before it starts, on a two-inertia shaft
    with damping: the phases' closed forms against DOP853 at rtol 1e-12."""
    from scipy.integrate import solve_ivp
    rows = [[0.0, 0.0, 3e3, -4e3, 1.5e3, -0.2e3], [200.0]]
    law = MotorLaw("motor", "a", [0.1, 1.1, 1.6], rows, "N*m")
    model = Model([Inertia("a", 2.0), Inertia("b", 5.0),
                   ElasticLink("shaft", "a", "b", "2e4 N*m/rad", "30 N*m*s/rad"), law,
                   Motor("load", "b", "-50 N*m")])
    with pytest.raises(ComponentError, match="constant loads do not balance"):
        model.run(2.0)
    run = model.run(2.0, rest=True)
    assert [t for t, _ in run.events] == [0.1, 1.1, 1.6]

    def rhs(t, y):
        u = y[2] - y[0]
        F = 2e4 * u + 30 * (y[3] - y[1])
        return [y[1], (law.value_at(t) + F) / 2.0, y[3], (-50.0 - F) / 5.0]
    times = np.linspace(0.0, 2.0, 401)
    sol = solve_ivp(rhs, (0, 2), [0, 0, 0, 0], method="DOP853", rtol=1e-12, atol=1e-14,
                    t_eval=times, max_step=1e-3)
    theirs = 2e4 * (sol.y[2] - sol.y[0]) + 30 * (sol.y[3] - sol.y[1])
    assert np.max(np.abs(rope_force(run, times) - theirs)) <= 1e-7 * np.max(np.abs(theirs))


@pytest.mark.parametrize("build, message", [
    (lambda: MotorLaw("m", "drive", [0, 1], [[1, 2]], "m/s^2", law="speed"),
     "motor law 'm': law must be one of torque, acceleration"),
    (lambda: MotorLaw("m", "drive", [0, 1], [["2"]], "N"), "motor law 'm': "),
    (lambda: MotorLaw("m", "drive", [0, 1, 2], [[1]], "N"), "needs 2 rows"),
    (lambda: MotorLaw("m", "drive", [0, 1], [[1]], "furlongs"), "motor law 'm': unknown unit 'furlongs'"),
    (lambda: MotorLaw("m", "drive", [-1, 1], [[1]], "N"), "breakpoints\\[0\\] must be >= 0"),
    (lambda: hoist(MotorLaw("m", "drive", [0, 1], [[1]], "N*m")),
     "motor law 'm' on mass 'drive': its unit 'N\\*m' is"),
    (lambda: hoist(MotorLaw("m", "drive", [0, 1], [[1]], "m/s^2", law="acceleration"),
                   MotorLaw("n", "load", [0, 1], [[1]], "m/s^2", law="acceleration")),
     "motor law 'n': only one motor may balance the others"),
])
def test_bad_laws_are_refused_in_one_line(build, message):
    with pytest.raises(ComponentError, match=message) as err:
        build()
    assert "\n" not in str(err.value)
