"""Motor laws in time (paper 002's piecewise polynomial drive laws) in component
models: a torque law of high degree, starting late, is exact per phase (against
solve_ivp at tight tolerance); bad laws are refused in one line. Paper 002's
hoist under its drive laws: tests/test_components_papers.py."""
from __future__ import annotations

import importlib
from pathlib import Path

import numpy as np
import pytest

from crane_sym.components import (Brake, ComponentError, ElasticLink, Gravity, Inertia, Mass, Model,
                                  Motor, MotorLaw)
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
    (lambda: MotorLaw("m", "drive", [0, 1], [[1, 2]], "m/s^3", law="jerk"),
     "motor law 'm': law must be one of torque, acceleration, speed, got 'jerk'"),
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


def test_acceleration_law_drives_the_referred_momentum_of_a_geared_hoist():
    """Table 1's hoist (coupling, gear, drum, hook) under an acceleration law on
    the motor: Σ ρ_g M_g q̇_g, the momentum referred to the motor (ρ: the rigid
    ratio of each group to it), grows by J_red ∫ a dt exactly, whatever the
    coupling does (ρᵀK = ρᵀD = 0: the links' forces cancel in it)."""
    from crane_sym.components import Drum, Gear
    rows = [[0.0, 40.0], [20.0], [20.0, -40.0]]          # rad/s^2 of the motor
    law = MotorLaw("start", "motor", [0.0, 0.5, 1.5, 2.0], rows, "1/s^2", law="acceleration")
    model = Model([Inertia("motor", "20 kg*m^2"), Inertia("shaft", 0),
                   Inertia("drum", "500 kg*m^2"), Mass("hook", "62 t"),
                   Gear("gearbox", "shaft", "drum", 26.2), Drum("rope", "drum", "hook", "0.5 m", 4),
                   ElasticLink("coupling", "motor", "shaft", "4e4 N*m/rad", "30 N*m*s/rad"),
                   Gravity("weight", "hook", direction="-"), law])
    run = model.run("2.5 s", "motor", 0.0)
    groups = model.assembly.groups
    J_red = sum(g.inertia for g in groups)                # both groups turn with the motor
    times = np.linspace(0.0, 2.5, 251)
    state = run.result.state(times)
    momentum = sum(g.inertia * state[:, 2 * k + 1] for k, g in enumerate(groups))
    speed = np.array([sum(c * ((min(t, e) - b) ** (j + 1)) / (j + 1)
                          for b, e, row in zip([0.0, 0.5, 1.5], [0.5, 1.5, 2.0], rows)
                          if t > b for j, c in enumerate(row)) for t in times])
    assert np.max(np.abs(momentum - J_red * speed)) <= 1e-11 * J_red * speed.max()
    # not a rigid drive: the motor itself strays from the law while the coupling rings
    assert np.max(np.abs(state[:, 1] - speed)) > 1e-6 * speed.max()


def test_a_motor_law_in_a_file_refuses_text_for_numbers(tmp_path):
    from crane_sym.components.component_file import read_component_file
    file = tmp_path / "law.toml"
    file.write_text('[model]\nname = "law"\n[[mass]]\nname = "a"\nmass = "1 kg"\n'
                    '[[mass]]\nname = "b"\nmass = "1 kg"\n'
                    '[[elastic]]\nname = "k"\nbetween = ["a", "b"]\nstiffness = "1 N/m"\n'
                    '[[motor_law]]\nname = "m"\nbody = "a"\nlaw = "torque"\nunit = "N"\n'
                    'breakpoints = [0.0, 1.0]\ncoefficients = [["1 + 1"]]\n'
                    '[run]\nduration = "1 s"\nstart = "rest"\n')
    with pytest.raises(ComponentError, match=r"motor law 'm': coefficients\[0\]\[0\] must be a "
                                             r"number .* text is never evaluated") as err:
        read_component_file(file)
    assert "\n" not in str(err.value)


def test_speed_law_moves_its_body_exactly_and_the_rest_follows():
    """An ideal speed control: the motor follows v(t) (a cubic start to 100 rad/s,
    then held), the load on its elastic shaft follows by its own equation; the
    shaft's torque against DOP853 at rtol 1e-12, the motor's speed the law's."""
    from scipy.integrate import solve_ivp
    rows = [[0.0, 0.0, 300.0, -200.0], [100.0]]               # v = 300 t^2 - 200 t^3
    law = MotorLaw("control", "motor", [0.0, 1.0, 3.0], rows, "rad/s", law="speed")
    model = Model([Inertia("motor", 2.0), Inertia("load", 5.0),
                   ElasticLink("shaft", "motor", "load", "2e4 N*m/rad", "30 N*m*s/rad"), law,
                   Motor("resisting", "load", "-50 N*m")])
    run = model.run(2.0, rest=True)
    times = np.linspace(0.0, 2.0, 401)
    state = run.result.state(times)
    assert np.max(np.abs(state[:, 1] - [law.value_at(t) for t in times])) <= 1e-10 * 100

    def motor_angle(t):
        return 100.0 * t ** 3 - 50.0 * t ** 4 if t < 1 else 50.0 + 100.0 * (t - 1)

    def rhs(t, y):
        torque = 2e4 * (y[0] - motor_angle(t)) + 30 * (y[1] - law.value_at(t))
        return [y[1], (-50.0 - torque) / 5.0]
    sol = solve_ivp(rhs, (0.0, 2.0), [0.0, 0.0], method="DOP853", rtol=1e-12, atol=1e-14,
                    t_eval=times, max_step=1e-3)
    theirs = (2e4 * (sol.y[0] - [motor_angle(t) for t in times])
              + 30 * (sol.y[1] - [law.value_at(t) for t in times]))
    assert np.max(np.abs(rope_force(run, times) - theirs)) <= 1e-7 * np.max(np.abs(theirs))
    with pytest.raises(ComponentError, match="its speed at t = 0 is 0, the steady start's 10"):
        model.run(2.0, "motor", "10 rad/s")
    from crane_sym.components.closed import link_response
    with pytest.raises(ComponentError, match="constant loads; motor law 'control' switches"):
        link_response(model)
    with pytest.raises(ComponentError, match="brake 'b' acts on a body whose speed motor law "
                                             "'control' sets"):
        Model([*model.components, Brake("b", "motor", "1 kN*m")])
