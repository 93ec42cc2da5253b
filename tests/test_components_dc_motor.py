"""A DC motor's armature as a component: its current a first-order state of
the component system (L di/dt = V − R i − k ω, torque k i), checked against
the closed form of the motor alone on an inertia, derived here with SymPy."""
from __future__ import annotations

import numpy as np
import sympy as sp

from crane_sym.components import Inertia, Model
from crane_sym.components.laws import MotorLaw
from crane_sym.components.loads import DCMotor
from crane_sym.mechanics.phase_table import values

#: The motor alone: J [kg m²], R [Ω], L [H], k [N m/A], V [V] (a step at t = 0).
J, R, L, K, V = (sp.Rational(4, 5), sp.Rational(1, 2), sp.Rational(1, 50), sp.Rational(6, 5),
                 sp.Integer(100))


def motor_alone(voltage: MotorLaw) -> Model:
    return Model([Inertia("rotor", float(J)),
                  DCMotor("m", "rotor", f"{float(R)} ohm", f"{float(L)} H",
                          f"{float(K)} N*m/A", voltage)])


def state(run, index: int, times: np.ndarray) -> np.ndarray:
    """Component ``index`` of the run's state at ``times``."""
    unit = np.eye(run.system.size)[index]
    return values(run.result, times, lambda mode: (unit, 0.0))


def closed_form() -> tuple[sp.Expr, sp.Expr, sp.Symbol]:
    """(ω(t), i(t)) of J ω' = k i, L i' = V − R i − k ω from rest, V a step:
    the second-order linear system solved by Laplace's transform."""
    t, s = sp.symbols("t", positive=True), sp.Symbol("s")
    i_s = (V / s) * J * s / (L * J * s**2 + R * J * s + K**2)
    omega_s = K * i_s / (J * s)
    back = [sp.inverse_laplace_transform(sp.apart(f, s), s, t) for f in (omega_s, i_s)]
    return (*(sp.simplify(f.subs(sp.Heaviside(t), 1)) for f in back), t)


def test_the_current_is_a_first_order_state_with_its_rate_from_the_part():
    model = motor_alone(MotorLaw("m", "rotor", [0.0, 10.0], [[float(V)]], "V", "voltage"))
    eq = model.equations
    i, volts = sp.Symbol("i_m", real=True), sp.Symbol("V_m", real=True)
    Rs, Ls, Ks = (sp.Symbol(f"{x}_m", positive=True) for x in "RLk")
    theta = eq.coordinates[0]
    assert eq.states == (i,)
    assert sp.simplify(eq.rates[0] - (volts - Rs * i - Ks * theta.diff(eq.t)) / Ls) == 0
    assert sp.simplify(eq.forces[theta] - Ks * i) == 0


def test_dc_motor_on_an_inertia_against_its_closed_form():
    """A voltage step on the motor alone: speed and current against the
    closed form to 1e-10 of their peaks."""
    omega, current, t = closed_form()
    model = motor_alone(MotorLaw("m", "rotor", [0.0, 10.0], [[float(V)]], "V", "voltage"))
    run = model.run(0.5, rest=True)
    system = run.system
    assert system.size == 3 and system.first == 2          # (θ, ω, i)
    times = np.linspace(0.0, 0.5, 201)
    theirs_w = np.array([float(omega.subs(t, x)) if x else 0.0 for x in times])
    theirs_i = np.array([float(current.subs(t, x)) if x else 0.0 for x in times])
    ours_w, ours_i = state(run, system.v(0), times), state(run, system.first, times)
    assert np.max(np.abs(ours_w - theirs_w)) <= 1e-10 * np.max(np.abs(theirs_w))
    assert np.max(np.abs(ours_i - theirs_i)) <= 1e-10 * np.max(np.abs(theirs_i))
    # the steady speed V/k is where the back-emf meets the voltage
    assert abs(float(sp.limit(omega, t, sp.oo)) - float(V / K)) < 1e-12
