"""The derivation steps of paper 000, in the paper's order: eqs (1)–(14), then
what a user of the result needs (initial state, peak force, velocities).

Each function adds one section's steps to the ``Derivation`` and returns what
the later sections need; ``build()`` in ``__init__`` calls them in order.
"""
from __future__ import annotations

import sympy as sp

from crane_sym.derivation import Derivation
from crane_sym.mechanics.elimination import RelativeEquation, relative_coordinate
from crane_sym.latex import latex
from crane_sym.mechanics.lagrange import lagrange_equations
from crane_sym.mechanics.odes import ODESolution, solve_constant_coefficient

from .model import (A, B, F, F_max, F_r, P_t, W, c, k_d, m1, m2, p, t, t_max, u,
                    u0, u0_dot, v0, v1, v2, x1, x2, x_p)


def energies(d: Derivation) -> tuple[sp.Expr, sp.Expr, dict]:
    """Kinetic and potential energy and the virtual work of the model.

    Returns ``(T, V, forces)``: the energies and coordinate -> generalized force.
    """
    T_, V_, dA = sp.Symbol("T"), sp.Symbol(r"\Pi"), sp.Symbol(r"\delta A")
    T = m1 * x1.diff(t) ** 2 / 2 + m2 * x2.diff(t) ** 2 / 2
    V = c * (x2 - x1) ** 2 / 2
    forces = {x1: -P_t, x2: -W}
    d.add("kinetic energy", sp.Eq(T_, T), "Sum of ½·m·v² of the two masses.",
          "Lagrange's equations need T and Π of the model.", "Energies")
    d.add("potential energy", sp.Eq(V_, V),
          "Strain energy of the link, ½·c·(stretch)².")
    d.add("virtual work", sp.Eq(dA, sum(Q * sp.Symbol(rf"\delta {latex(q.func(t))}")
                                        for q, Q in forces.items())),
          "P_t acts on m1 and W on m2, both against +x.",
          "The generalized forces are the coefficients of the virtual displacements.")
    return T, V, forces


def equations_of_motion(d: Derivation, T: sp.Expr, V: sp.Expr,
                        forces: dict) -> tuple[sp.Eq, sp.Eq]:
    """Eqs (1)–(3): Lagrange's equations of the two masses and the link force."""
    motion = lagrange_equations(T, V, [x1, x2], t, forces)
    eq1, eq2 = motion.equations
    d.add("(1)", eq1, "Lagrange's equation for x1 with Q1 = −P_t.",
          title="Equations of motion")
    d.add("(2)", eq2, "Lagrange's equation for x2 with Q2 = −W.")
    d.add("(3)", sp.Eq(F, sp.factor(sp.diff(V, x2))), "The link force is ∂Π/∂x2 = c·(x2 − x1).",
          title="Force in the elastic link")
    return eq1, eq2


def relative_equation(d: Derivation, eq1: sp.Eq, eq2: sp.Eq) -> RelativeEquation:
    """Eq (4): one equation in the relative coordinate x2 − x1."""
    rel = relative_coordinate(eq1, eq2, x1, x2, u)
    d.add("(4)", rel.in_coordinates(x1, x2),
          "Each equation solved for its acceleration and (1)/m1 subtracted from "
          "(2)/m2; x1 cancels, leaving one equation in x2 − x1 (Komarov's method).",
          "The link force depends on the stretch only, so one coordinate suffices.",
          "One equation in the relative coordinate")
    return rel


def general_solution(d: Derivation, rel: RelativeEquation
                     ) -> tuple[sp.Eq, ODESolution]:
    """Eqs (5)–(9): general solution, frequency p and particular solution.

    Returns ``(ode, free)``: (4) written with p², and its solution with A, B free.
    """
    ode = sp.Eq(u.diff(t, 2) + p ** 2 * u, rel.forcing)
    free = solve_constant_coefficient(ode, u, (A, B))
    particular = free.particular.subs(p, sp.sqrt(rel.omega2))
    d.add("(5)", sp.Eq(x2 - x1, A * free.basis[0] + B * free.basis[1] + x_p),
          "General solution of (4): the homogeneous part for the roots ±i·p of "
          "the characteristic equation, plus a particular solution.",
          title="General solution")
    d.add("(6)", sp.Eq(p, sp.sqrt(rel.omega2)),
          "p² is the coefficient of (x2 − x1) in (4).")
    d.add("(7)", sp.Eq(x_p, sp.Mul(rel.forcing, sp.Pow(rel.omega2, -1),
                                   evaluate=False)),
          "The right-hand side of (4) is constant, so a constant particular "
          "solution is its ratio to p².", title="Particular solution")
    d.add("(8)", sp.Eq(x_p, sp.factor(particular)), "(7) over a common denominator.")
    d.add("(9)", sp.Eq(x2 - x1, A * free.basis[0] + B * free.basis[1]
                       + sp.factor(particular)), "(8) put into (5).")
    return ode, free


def initial_conditions(d: Derivation, eq2: sp.Eq) -> None:
    """The state at t = 0, printed between (9) and (10)."""
    # Initial state. The paper assumes the link unstretched; steady travel just
    # before braking (drive force balancing W, no acceleration) would not.
    stretch0 = sp.solve(eq2.subs(x2.diff(t, 2), 0), x2)[0] - x1
    d.add("steady travel", sp.Eq(u0, sp.simplify(stretch0)),
          "In steady travel before braking x2'' = 0, so (2) gives c·(x2 − x1) = −W.",
          "To see what the paper's zero initial stretch assumes.",
          "Initial conditions")
    d.add("initial relative velocity", sp.Eq(u0_dot, 0),
          "In steady travel both masses move at the same speed.")


def integration_constants(d: Derivation, ode: sp.Eq, rel: RelativeEquation,
                          free: ODESolution) -> tuple[sp.Expr, sp.Expr]:
    """Eqs (10)–(14): constants A, B from the initial state; stretch and link force.

    Returns ``(stretch, force_t)``: the right-hand sides of (13) and (14).
    """
    constants = solve_constant_coefficient(ode, u, (A, B), initial={0: 0, 1: 0})
    d.add("(10)", sp.Eq(x2.diff(t) - x1.diff(t),
                        (A * free.basis[0] + B * free.basis[1]).diff(t)),
          "(9) differentiated; its particular part is constant.")
    d.add("(11)", sp.Eq(A, sp.factor(constants.constant_values[A]
                                     .subs(p, sp.sqrt(rel.omega2)))),
          "x2 − x1 = 0 at t = 0 put into (9).", title="Integration constants")
    d.add("(12)", sp.Eq(B, constants.constant_values[B]),
          "ẋ2 − ẋ1 = 0 at t = 0 put into (10).")
    stretch = sp.factor_terms(_eliminate_amplitude_p(constants.solution, rel.omega2))
    d.add("(13)", sp.Eq(x2 - x1, stretch), "(11) and (12) put into (9).",
          title="Relative displacement and link force")
    force_t = sp.factor_terms(c * stretch)
    d.add("(14)", sp.Eq(F, force_t), "(13) put into (3).")
    return stretch, force_t


def preloaded_start(d: Derivation, ode: sp.Eq, rel: RelativeEquation) -> None:
    """Beyond the paper: the start from steady travel, where the link already
    carries -W (step "steady travel"), instead of the paper's zero stretch."""
    F_pre = sp.Symbol("F_pre")
    preloaded = solve_constant_coefficient(
        ode, u, (A, B), initial={0: d.step("steady travel").statement.rhs, 1: 0})
    d.add("preloaded start", sp.Eq(F_pre, sp.collect(sp.expand(
        c * _eliminate_amplitude_p(preloaded.solution, rel.omega2)), sp.cos(p * t),
        sp.factor)),
          "(9) with x2 − x1 = −W/c, ẋ2 − ẋ1 = 0 at t = 0, times c.",
          "Shows what the zero initial stretch of the paper leaves out: the swing "
          "grows by W, so the extreme force becomes 2·F_r + W.")


def peak_force(d: Derivation, eq1: sp.Eq, eq2: sp.Eq, force_t: sp.Expr) -> None:
    """Beyond the paper: what a designer reads off (14) — the rigid-drive force,
    the time and size of the peak and the dynamic factor."""
    link_rigid = _rigid_link_force(eq1, eq2)
    d.add("rigid limit", sp.Eq(F_r, link_rigid),
          "With x1 = x2 the two equations add to (m1 + m2)·ẍ = −P_t − W; (2) then "
          "gives the link force.",
          "The load a rigid drive would carry: the reference for the dynamic factor.",
          "Peak force and dynamic factor")
    theta = sp.Symbol("theta", positive=True)
    amplitude, shape = force_t.subs(p * t, theta).as_independent(theta, as_Add=False)
    critical = sp.solveset(sp.diff(shape, theta), theta, sp.Interval.open(0, 2 * sp.pi))
    (theta_max,) = [th for th in critical if sp.diff(shape, theta, 2).subs(theta, th) != 0]
    d.add("peak time", sp.Eq(t_max, theta_max / p),
          "dF/dt = 0 within the first period at p·t = π, where F is extreme.")
    peak = sp.simplify(force_t.subs(t, theta_max / p))
    d.add("peak force", sp.Eq(F_max, peak), "(14) at t = t_max.")
    d.add("dynamic factor", sp.Eq(k_d, sp.simplify(peak / link_rigid)),
          "Peak force over the rigid-drive force.")


def velocities(d: Derivation, eq1: sp.Eq, eq2: sp.Eq, stretch: sp.Expr) -> None:
    """Beyond the paper: the velocities of the two masses during braking."""
    tau = sp.Symbol("tau", nonnegative=True)
    accel1 = sp.solve(eq1.subs(x2, x1 + stretch).doit(), x1.diff(t, 2))[0]
    accel2 = sp.solve(eq2.subs(x1, x2 - stretch).doit(), x2.diff(t, 2))[0]
    vel1, vel2 = (_collect_motion(v0 + sp.integrate(a.subs(t, tau), (tau, 0, t)))
                  for a in (accel1, accel2))
    d.add("velocity of m1", sp.Eq(v1, vel1),
          "(1) with the stretch (13), integrated from ẋ1(0) = v0.",
          "The model holds only while the brake keeps slipping (ẋ1 > 0).",
          "Velocities of the masses")
    d.add("velocity of m2", sp.Eq(v2, vel2),
          "(2) with the stretch (13), integrated from ẋ2(0) = v0.")


# --- Helpers of the steps -----------------------------------------------------
def _collect_motion(v: sp.Expr) -> sp.Expr:
    """A velocity as v0 + (drift)·t + (amplitude)·sin(p t), each factored."""
    return sp.collect(sp.expand(v), [sp.sin(p * t), t], sp.factor)


def _eliminate_amplitude_p(expr: sp.Expr, omega2: sp.Expr) -> sp.Expr:
    """Write p in terms of the data everywhere except in the phase p·t, as
    the paper keeps it in (13)–(14)."""
    phase = {f: sp.Dummy() for f in expr.atoms(sp.cos, sp.sin)}
    return expr.xreplace(phase).subs(p, sp.sqrt(omega2)).xreplace(
        {v: k for k, v in phase.items()})


def _rigid_link_force(eq1: sp.Eq, eq2: sp.Eq) -> sp.Expr:
    """Link force when x1 = x2: add the equations for the common acceleration,
    then read the link force c·(x2 − x1) off (2)."""
    acc = sp.Symbol("a")
    total = (eq1.lhs + eq2.lhs - eq1.rhs - eq2.rhs).subs(
        {x1.diff(t, 2): acc, x2.diff(t, 2): acc}).subs(x2, x1)
    a = sp.solve(total, acc)[0]
    link = sp.Symbol("link")
    on_m2 = eq2.subs(x2, x1 + link / c).doit().subs(x1.diff(t, 2), a)
    return sp.factor(sp.solve(on_m2, link)[0])
