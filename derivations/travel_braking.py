"""Braking of the travel mechanism of an overhead (bridge) crane.

Source: ``000_4ef6efc8a81a3b06.txt`` — V.F. Semenyuk, A.N. Vudvud, "Analytical
determination of the dynamic loads arising when the travel mechanism of an
overhead crane brakes" (Odessa National Polytechnic University; in Russian).

The paper models the drive as two masses joined by an elastic link and
reduces the system to one equation in the relative coordinate x2 − x1
(Komarov's method), eqs (1)–(14). This module rebuilds every step from the
energies and forces of that model, transcribes the printed formulas as
printed, and adds what a user of the result needs: the peak force, its time,
the dynamic factor and the velocities of the two masses.

The module does nothing on import; ``build()`` returns the ``Derivation``.
"""
from __future__ import annotations

import numpy as np
import sympy as sp
from sympy.physics.units import force, length, mass, time, velocity

from crane_sym.derivation import Derivation, ODESystem, Output
from crane_sym.elimination import relative_coordinate
from crane_sym.lagrange import lagrange_equations
from crane_sym.odes import solve_constant_coefficient
from crane_sym.published import ASSUMPTION, Convention, PublishedFormula
from crane_sym.symbols import (COORDINATE, DEFINED, TIME, PhysicalSymbol,
                               SymbolTable)

ID = "travel_braking"
PAPER = "000_4ef6efc8a81a3b06.txt"
TITLE = "Dynamic loads when the travel mechanism of an overhead crane brakes"

# --- Symbols -----------------------------------------------------------------
t = sp.Symbol("t", nonnegative=True)
m1, m2 = sp.symbols("m1 m2", positive=True)
c, P_t, W, v0 = sp.symbols("c P_t W v0", positive=True)
x1, x2 = sp.Function("x1")(t), sp.Function("x2")(t)
u = sp.Function("u")(t)                         # u = x2 - x1, eliminated below
p, P = sp.symbols("p P", positive=True)         # P: the print's name for p in (6)
A, B = sp.symbols("A B", real=True)
x_p = sp.Symbol("x_p", real=True)               # the print's (x2 - x1)^*
F, F_r, F_max, t_max, k_d = sp.symbols("F F_r F_max t_max k_d", real=True)
u0, u0_dot = sp.symbols("u0 u0_dot", real=True)
v1, v2 = sp.symbols("v1 v2", real=True)

stiffness = force / length
frequency = 1 / time
SYMBOLS = SymbolTable([
    PhysicalSymbol(t, time, "s", "time since the brake was applied", TIME,
                   "nonnegative", (1e-3, 10.0)),
    PhysicalSymbol(m1, mass, "kg", "reduced mass of the rotating drive parts "
                   "(rotor, motor and brake couplings)", sample_range=(1e2, 1e5)),
    PhysicalSymbol(m2, mass, "kg", "reduced mass of the crane or trolley "
                   "(translating and rotating parts, wheels)", sample_range=(1e3, 1e6)),
    PhysicalSymbol(c, stiffness, "N/m", "reduced stiffness of the transmission "
                   "(mainly shafts)", sample_range=(1e5, 1e9)),
    PhysicalSymbol(P_t, force, "N", "braking force", sample_range=(1e3, 1e6)),
    PhysicalSymbol(W, force, "N", "static travel resistance", sign="nonnegative",
                   sample_range=(1e2, 1e5)),
    PhysicalSymbol(v0, velocity, "m/s", "travel speed when braking begins",
                   sample_range=(0.1, 5.0)),
    PhysicalSymbol(x1, length, "m", "coordinate of mass m1", COORDINATE, "real"),
    PhysicalSymbol(x2, length, "m", "coordinate of mass m2", COORDINATE, "real"),
    PhysicalSymbol(u, length, "m", "relative coordinate x2 - x1", COORDINATE, "real"),
    PhysicalSymbol(p, frequency, "rad/s", "natural frequency of the relative motion",
                   DEFINED),
    PhysicalSymbol(P, frequency, "rad/s", "the print's name for p in (6) "
                   "(clashes with P_t)", DEFINED),
    PhysicalSymbol(A, length, "m", "integration constant (cos term)", DEFINED, "real"),
    PhysicalSymbol(B, length, "m", "integration constant (sin term)", DEFINED, "real"),
    PhysicalSymbol(x_p, length, "m", "particular solution (x2 - x1)*", DEFINED, "real"),
    PhysicalSymbol(F, force, "N", "force in the elastic link", DEFINED, "real"),
    PhysicalSymbol(F_r, force, "N", "link force of the rigid (c → ∞) drive",
                   DEFINED, "real"),
    PhysicalSymbol(F_max, force, "N", "peak link force", DEFINED, "real"),
    PhysicalSymbol(t_max, time, "s", "time of the peak link force", DEFINED),
    PhysicalSymbol(k_d, sp.S.One * length / length, "1", "dynamic factor F_max/F_r",
                   DEFINED),
    PhysicalSymbol(u0, length, "m", "x2 - x1 at t = 0", DEFINED, "real"),
    PhysicalSymbol(u0_dot, velocity, "m/s", "d(x2 - x1)/dt at t = 0", DEFINED, "real"),
    PhysicalSymbol(v1, velocity, "m/s", "velocity of mass m1", DEFINED, "real"),
    PhysicalSymbol(v2, velocity, "m/s", "velocity of mass m2", DEFINED, "real"),
])
LATEX_NAMES = {x_p: "(x_2 - x_1)^*", u0: r"(x_2 - x_1)|_{t=0}",
               u0_dot: r"(\dot x_2 - \dot x_1)|_{t=0}", F_r: "F_r",
               F_max: r"F_{\max}", t_max: r"t_{\max}", k_d: "k_d"}

MODEL = r"""
Two masses joined by one elastic link (the paper's Fig. 1). The motor side m1
carries the braking force P_t; the crane side m2 the travel resistance W. Both
forces act against the direction of travel (+x). Not modelled, as in the
paper: load sway, damping in drive and structure, backlash; W is constant and
the wheels do not slip.

        P_t             c              W
      <---- [ m1 ]---/\/\/\/---[ m2 ] ---->      travel: +x
             x1                  x2
"""


# --- Steps -----------------------------------------------------------------------
def build() -> Derivation:
    """Rebuild eqs (1)–(14) from the energies and forces of the two-mass model."""
    d = Derivation(
        id=ID, paper=PAPER,
        title=TITLE,
        citation="V.F. Semenyuk, A.N. Vudvud, Odessa National Polytechnic University",
        model=MODEL, symbols=SYMBOLS)
    T_, V_, dA = sp.Symbol("T"), sp.Symbol(r"\Pi"), sp.Symbol(r"\delta A")
    T = m1 * x1.diff(t) ** 2 / 2 + m2 * x2.diff(t) ** 2 / 2
    V = c * (x2 - x1) ** 2 / 2
    forces = {x1: -P_t, x2: -W}
    d.add("kinetic energy", sp.Eq(T_, T), "Sum of ½·m·v² of the two masses.",
          "Lagrange's equations need T and Π of the model.", "Energies")
    d.add("potential energy", sp.Eq(V_, V),
          "Strain energy of the link, ½·c·(stretch)².")
    d.add("virtual work", sp.Eq(dA, sum(Q * sp.Symbol(rf"\delta {sp.latex(q.func(t))}")
                                        for q, Q in forces.items())),
          "P_t acts on m1 and W on m2, both against +x.",
          "The generalized forces are the coefficients of the virtual displacements.")

    motion = lagrange_equations(T, V, [x1, x2], t, forces)
    eq1, eq2 = motion.equations
    d.add("(1)", eq1, "Lagrange's equation for x1 with Q1 = −P_t.",
          title="Equations of motion")
    d.add("(2)", eq2, "Lagrange's equation for x2 with Q2 = −W.")
    d.add("(3)", sp.Eq(F, sp.factor(sp.diff(V, x2))), "The link force is ∂Π/∂x2 = c·(x2 − x1).",
          title="Force in the elastic link")

    rel = relative_coordinate(eq1, eq2, x1, x2, u)
    d.add("(4)", rel.in_coordinates(x1, x2),
          "Each equation solved for its acceleration and (1)/m1 subtracted from "
          "(2)/m2; x1 cancels, leaving one equation in x2 − x1 (Komarov's method).",
          "The link force depends on the stretch only, so one coordinate suffices.",
          "One equation in the relative coordinate")

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

    # Initial state. The paper assumes the link unstretched; steady travel just
    # before braking (drive force balancing W, no acceleration) would not.
    stretch0 = sp.solve(eq2.subs(x2.diff(t, 2), 0), x2)[0] - x1
    d.add("steady travel", sp.Eq(u0, sp.simplify(stretch0)),
          "In steady travel before braking x2'' = 0, so (2) gives c·(x2 − x1) = −W.",
          "To see what the paper's zero initial stretch assumes.",
          "Initial conditions")
    d.add("initial relative velocity", sp.Eq(u0_dot, 0),
          "In steady travel both masses move at the same speed.")

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

    # Beyond the paper: the start from steady travel, where the link already
    # carries -W (step "steady travel"), instead of the paper's zero stretch.
    F_pre = sp.Symbol("F_pre")
    preloaded = solve_constant_coefficient(
        ode, u, (A, B), initial={0: d.step("steady travel").statement.rhs, 1: 0})
    d.add("preloaded start", sp.Eq(F_pre, sp.collect(sp.expand(
        c * _eliminate_amplitude_p(preloaded.solution, rel.omega2)), sp.cos(p * t),
        sp.factor)),
          "(9) with x2 − x1 = −W/c, ẋ2 − ẋ1 = 0 at t = 0, times c.",
          "Shows what the zero initial stretch of the paper leaves out: the swing "
          "grows by W, so the extreme force becomes 2·F_r + W.")

    # Beyond the paper: what a designer reads off (14).
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

    d.published.extend(PUBLISHED)
    omega = sp.sqrt(rel.omega2)
    d.outputs.extend(_outputs(d, omega))
    d.ode_systems.extend([
        ODESystem("absolute coordinates, (1)-(2)", (eq1, eq2), (x1, x2),
                  ((x1, 0), (x2, 0), (x1.diff(t), v0), (x2.diff(t), v0)),
                  (("relative_displacement", x2 - x1), ("elastic_force", c * (x2 - x1)),
                   ("velocity_m1", x1.diff(t)), ("velocity_m2", x2.diff(t)))),
        ODESystem("relative coordinate, (4)", (rel.equation,), (u,),
                  ((u, 0), (u.diff(t), 0)),
                  (("relative_displacement", u), ("elastic_force", c * u))),
    ])
    return d


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


def _outputs(d: Derivation, omega: sp.Expr) -> list[Output]:
    """Generated functions: every result in the paper's own symbols."""
    def rhs(label: str) -> sp.Expr:
        return d.step(label).statement.rhs.subs(p, omega)

    loads = (t, m1, m2, c, P_t, W)
    return [
        Output("natural_frequency", rhs("(6)"), (m1, m2, c), ("(6)",),
               "Natural frequency p of the relative motion.", "rad/s"),
        Output("relative_displacement", rhs("(13)"), loads, ("(13)",),
               "Stretch x2 - x1 of the elastic link.", "m"),
        Output("elastic_force", rhs("(14)"), loads, ("(14)",),
               "Force F(t) in the elastic link.", "N"),
        Output("peak_elastic_force", rhs("peak force"), (m1, m2, P_t, W), ("(14)",),
               "Extreme link force F_max = F(pi/p); a maximum when P_t*m2 > W*m1.",
               "N"),
        Output("peak_time", rhs("peak time"), (m1, m2, c), ("(6)", "(14)"),
               "Time t_max = pi/p of the extreme link force.", "s"),
        Output("rigid_link_force", rhs("rigid limit"), (m1, m2, P_t, W), ("(14)",),
               "Link force of a rigid drive (c -> oo), the static reference.", "N"),
        Output("velocity_m1", rhs("velocity of m1"), loads + (v0,), ("(1)", "(13)"),
               "Velocity of the motor-side mass m1.", "m/s"),
        Output("velocity_m2", rhs("velocity of m2"), loads + (v0,), ("(2)", "(13)"),
               "Velocity of the crane-side mass m2.", "m/s"),
    ]


# --- Published formulas, as printed ---------------------------------------------
# LaTeX copied verbatim from 000_4ef6efc8a81a3b06.txt; Russian words in it:
# "где" = "where", "или" = "or". The OCR of this paper is clean.
def _printed(label: str, latex: str, printed: sp.Eq, note: str = "",
             **kwargs) -> PublishedFormula:
    where = f"{PAPER}, eq {label}" if label.startswith("(") else f"{PAPER}, {label}"
    return PublishedFormula(label, latex, printed, where + (f"; {note}" if note else ""),
                            **kwargs)


_stretch = x2 - x1
_x_star = (P_t * m2 - W * m1) / (c * (m1 + m2))

PUBLISHED = [
    _printed("(1)", r"m_1 \ddot{x}_1 - c(x_2 - x_1) = -P_t; \quad (1)",
             sp.Eq(m1 * x1.diff(t, 2) - c * _stretch, -P_t)),
    _printed("(2)", r"m_2 \ddot{x}_2 + c(x_2 - x_1) = -W; \quad (2)",
             sp.Eq(m2 * x2.diff(t, 2) + c * _stretch, -W)),
    _printed("(3)", r"F = c(x_2 - x_1) \quad (3)", sp.Eq(F, c * _stretch)),
    _printed("(4)", r"(\ddot{x}_2 - \ddot{x}_1) + c \cdot \frac{m_1 + m_2}{m_1 \cdot m_2}"
             r" (x_2 - x_1) = \frac{P_t}{m_1} - \frac{W}{m_2}; \quad (4)",
             sp.Eq(_stretch.diff(t, 2) + c * (m1 + m2) / (m1 * m2) * _stretch,
                   P_t / m1 - W / m2)),
    _printed("(5)", r"(x_2 - x_1) = A \cos pt + B \sin pt + (x_2 - x_1)^*, \quad (5)",
             sp.Eq(_stretch, A * sp.cos(p * t) + B * sp.sin(p * t) + x_p)),
    _printed("(6)", r"\text{где, } P = \sqrt{\frac{m_1 + m_2}{m_1 \cdot m_2} \cdot c}, \quad (6)",
             sp.Eq(P, sp.sqrt((m1 + m2) / (m1 * m2) * c)),
             "printed with a capital P, while (5), (9), (10), (13), (14) use p",
             conventions=(Convention(
                 "P in (6) is the frequency p of (5); it is not the braking force P_t",
                 sp.Eq(p, sp.sqrt((m1 + m2) / (m1 * m2) * c))),)),
    _printed("(7)", r"(x_2 - x_1)^* = \left( \frac{P_t}{m_1} - \frac{W}{m_2} \right) "
             r"\div \frac{m_1 + m_2}{m_1 \cdot m_2} c, \quad (7)",
             # Read as printed: ÷ and the product after it at equal precedence,
             # left to right, i.e. (P_t/m1 - W/m2) / ((m1+m2)/(m1*m2)) * c.
             sp.Eq(x_p, (P_t / m1 - W / m2) / ((m1 + m2) / (m1 * m2)) * c),
             "the divisor after ÷ is a fraction followed by the factor c",
             conventions=(Convention(
                 "÷ divides by the whole product (m1 + m2)/(m1·m2)·c that follows it",
                 sp.Eq(x_p, (P_t / m1 - W / m2) / ((m1 + m2) / (m1 * m2) * c))),)),
    _printed("(8)", r"\text{или } (x_2 - x_1)^* = \frac{P_t m_2 - W m_1}{c(m_1 + m_2)}, \quad (8)",
             sp.Eq(x_p, _x_star)),
    _printed("(9)", r"(x_2 - x_1) = A \cos pt + B \sin pt + \frac{P_t m_2 - W m_1}"
             r"{c(m_1 + m_2)}, \quad (9)",
             sp.Eq(_stretch, A * sp.cos(p * t) + B * sp.sin(p * t) + _x_star)),
    _printed("initial stretch", r"x_2 - x_1 = 0;", sp.Eq(u0, 0),
             "initial conditions at t = 0, printed between (9) and (10); the "
             "step 'preloaded start' gives F(t) from the preloaded state",
             compare_to="steady travel", kind=ASSUMPTION),
    _printed("initial relative velocity", r"\dot{x}_2 - \dot{x}_1 = 0.", sp.Eq(u0_dot, 0),
             "initial conditions at t = 0, printed between (9) and (10)",
             kind=ASSUMPTION),
    _printed("(10)", r"(\dot{x}_2 - \dot{x}_1) = -pA \sin pt + pB \cos pt, \quad (10)",
             sp.Eq(_stretch.diff(t), -p * A * sp.sin(p * t) + p * B * sp.cos(p * t))),
    _printed("(11)", r"A = -\frac{P_t m_2 - W m_1}{c(m_1 + m_2)}, \quad (11)",
             sp.Eq(A, -_x_star), "printed on one line with (12)"),
    _printed("(12)", r"B = 0. \quad (12)", sp.Eq(B, 0), "printed on one line with (11)"),
    _printed("(13)", r"(x_2 - x_1) = \frac{P_t m_2 - W m_1}{c(m_1 + m_2)} (1 - \cos pt), \quad (13)",
             sp.Eq(_stretch, _x_star * (1 - sp.cos(p * t)))),
    _printed("(14)", r"F = c(x_2 - x_1) = \frac{P_t m_2 - W m_1}{(m_1 + m_2)} (1 - \cos pt), \quad (14)",
             sp.Eq(F, (P_t * m2 - W * m1) / (m1 + m2) * (1 - sp.cos(p * t))),
             "a chain; its middle member c(x2 − x1) restates (3), so the "
             "transcription keeps the outer equality F = ..."),
]


# --- Scenes ----------------------------------------------------------------------
def scene_report(scene):
    """Numbers and curves of a scene (see ``crane_sym.scenes``) for this model.

    Uses the generated NumPy module, not SymPy.

    Parameters
    ----------
    scene : crane_sym.scenes.Scene
        With SI parameters ``m1, m2, c, P_t, W, v0`` and options
        ``duration`` [s] and ``points``.

    Returns
    -------
    crane_sym.scenes.SceneReport
        Lines to print; ``values`` (SI): ``p``, ``f``, ``F_r``, ``F_max``,
        ``t_max``, ``dynamic_factor``, ``F_max_over_P_t``, ``v1_min``,
        ``v2_min``, ``t_slip_end`` and ``t_v2_zero`` (NaN when not reached
        within the duration), ``t_stop_rigid``; panels "Elastic link force"
        and "Velocities".
    """
    import math

    import numpy as np

    from crane_sym.generated import travel_braking as gen
    from crane_sym.scenes import Panel, SceneReport, format_quantity as fq

    q = scene.parameters
    load = {k: q[k] for k in ("m1", "m2", "c", "P_t", "W")}
    rigid = {k: q[k] for k in ("m1", "m2", "P_t", "W")}
    duration = scene.options["duration"]
    times = np.linspace(0.0, duration, scene.options["points"])
    force = gen.elastic_force(times, **load)
    vel1 = gen.velocity_m1(times, v0=q["v0"], **load)
    vel2 = gen.velocity_m2(times, v0=q["v0"], **load)

    def first_zero(v):
        """First time ``v`` reaches 0 on the grid (linear interpolation), or NaN."""
        hits = np.flatnonzero(v <= 0.0)
        if hits.size == 0:
            return math.nan
        i = int(hits[0])
        if i == 0:
            return float(times[0])
        return float(times[i - 1] + (times[i] - times[i - 1]) * v[i - 1] / (v[i - 1] - v[i]))

    freq = float(gen.natural_frequency(q["m1"], q["m2"], q["c"]))
    link_rigid = float(gen.rigid_link_force(**rigid))
    peak = float(gen.peak_elastic_force(**rigid))
    peak_at = float(gen.peak_time(q["m1"], q["m2"], q["c"]))
    values = {
        "p": freq, "f": freq / (2 * math.pi), "F_r": link_rigid, "F_max": peak,
        "t_max": peak_at, "dynamic_factor": peak / link_rigid,
        "F_max_over_P_t": peak / q["P_t"],
        "v1_min": float(vel1.min()), "v2_min": float(vel2.min()),
        "t_slip_end": first_zero(vel1), "t_v2_zero": first_zero(vel2),
        "t_stop_rigid": q["v0"] * (q["m1"] + q["m2"]) / (q["P_t"] + q["W"]),
    }
    span = f"0…{fq(duration, 's')}"
    if math.isnan(values["t_slip_end"]):
        slip = (f"brake slips throughout {span}: v1 > 0 "
                f"(min v1 = {fq(values['v1_min'], 'm/s')})")
    else:
        slip = (f"brake stops slipping (v1 = 0) at t = {fq(values['t_slip_end'], 's')}; "
                "the model is not valid after that")
    if math.isnan(values["t_v2_zero"]):
        moving = (f"crane moves throughout {span}: v2 > 0 "
                  f"(min v2 = {fq(values['v2_min'], 'm/s')})")
    else:
        moving = (f"crane stops (v2 = 0) at t = {fq(values['t_v2_zero'], 's')}; "
                  "the model is not valid after that")
    lines = [
        f"natural frequency      p = {fq(freq, 'rad/s')}, f = p/2π = {fq(values['f'], 'Hz')}",
        f"rigid-drive link force F_r = {fq(link_rigid / 1e3, 'kN')}",
        f"peak elastic force     F_max = {fq(peak / 1e3, 'kN')} "
        f"at t_max = {fq(peak_at, 's')}",
        f"dynamic factor         F_max/F_r = {fq(values['dynamic_factor'])}",
        f"peak over brake force  F_max/P_t = {fq(values['F_max_over_P_t'])}",
        f"validity               {slip}",
        f"                       {moving}",
        f"rigid crane stops after v0·(m1 + m2)/(P_t + W) = "
        f"{fq(values['t_stop_rigid'], 's')}",
    ]
    if peak_at > duration:
        lines.append(f"note: t_max lies beyond the plotted duration {fq(duration, 's')}")
    elif peak_at > values["t_slip_end"]:
        lines.append("note: t_max comes after the brake stops slipping; "
                     "the peak is not reached")
    panels = [
        Panel("Elastic link force", "F [kN]", [
            ("F(t)", times, force / 1e3),
            ("F_r (rigid drive)", times, np.full_like(times, link_rigid / 1e3)),
        ]),
        Panel("Velocities", "v [m/s]", [
            ("v1 (motor side, m1)", times, vel1),
            ("v2 (crane side, m2)", times, vel2),
        ]),
    ]
    return SceneReport(lines=lines, values=values, panels=panels)


# --- Hard cases ---------------------------------------------------------------------
def hard_cases(points: int = 400, seed: int = 20261121) -> dict[str, dict[str, np.ndarray]]:
    """Seeded input grids where a naive closed form loses accuracy.

    Returns case name -> columns (one array per argument of the outputs).
    """
    rng = np.random.default_rng(seed)

    def typical(n: int) -> dict[str, np.ndarray]:
        log = lambda lo, hi: 10.0 ** rng.uniform(np.log10(lo), np.log10(hi), n)
        return {"m1": log(1e2, 1e5), "m2": log(1e3, 1e6), "c": log(1e5, 1e9),
                "P_t": log(1e4, 1e6), "W": log(1e2, 1e4), "v0": log(0.1, 5.0)}

    def with_phase(cols: dict, phase: np.ndarray) -> dict:
        m1, m2, c = cols["m1"], cols["m2"], cols["c"]
        return {**cols, "t": phase / np.sqrt(c * (m1 + m2) / (m1 * m2))}

    n = points
    small_large = with_phase(typical(n), np.logspace(-9, 3, n))
    ratio = typical(n)
    ratio["m1"] = np.logspace(-6, 6, n) * ratio["m2"]
    ratio = with_phase(ratio, 10.0 ** rng.uniform(-9, 3, n))
    cancel = typical(n)
    cancel["W"] = cancel["P_t"] * cancel["m2"] / cancel["m1"] * (1 + np.logspace(-12, -1, n))
    cancel = with_phase(cancel, 10.0 ** rng.uniform(-3, 1, n))
    return {"p·t from 1e-9 to 1e3": small_large,
            "m1/m2 from 1e-6 to 1e6": ratio,
            "P_t·m2 − W·m1 cancels (1e-12 … 1e-1)": cancel}
