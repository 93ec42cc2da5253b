"""Duhamel's integral for the start-up of a crane hoist: rope loads and dynamic factors.

Source: ``002_f8509f3826f601de.txt`` — Yu. Chovnyuk, M. Dykteruk, S. Komotska,
"Use of Duhamel's integral in the analysis of forced vibrations and dynamic
loads of the elastic links of crane hoisting mechanisms at start-up"
(in Ukrainian).

The paper models the hoist as two masses (drive m1, load m2) joined by the
rope of stiffness C, reduces the system to one equation in the stretch
x = x1 − x2 (1)–(6), fixes the constants for lifting "with pick-up" (slack
rope) and "from weight" (preloaded rope) (7)–(14), writes the response as a
Duhamel integral (15)–(24), defines dynamic coefficients (25)–(27), the drive
laws (28)–(31), works four classic loads (32)–(53) and closes with an
Euler–Poisson "optimum" (54)–(66) and Tables 1–2.

This module rebuilds every step from the energies and forces of the model,
transcribes every printed formula (``hoist_startup_published``), and emits
the dynamic coefficient over time for each load case and for each drive law
a_i in both lifting cases. It does nothing on import; ``build()`` returns the
``Derivation``.
"""
from __future__ import annotations

from decimal import Decimal

import numpy as np
import sympy as sp
from sympy.physics.units import (acceleration, force, length, mass, time,
                                 velocity)
from sympy.utilities.lambdify import implemented_function

from crane_sym.derivation import Derivation, Output
from crane_sym.duhamel import duhamel, free_response, impulse_response
from crane_sym.elimination import relative_coordinate
from crane_sym.extrema import maximum_on_interval
from crane_sym.lagrange import lagrange_equations
from crane_sym.loads import PiecewiseLoad, linear, ramp, rectangular_pulse, step
from crane_sym.odes import solve_constant_coefficient
from crane_sym.rewriting import cos_pair_to_sin_squared
from crane_sym.symbols import (COORDINATE, DEFINED, TIME, PhysicalSymbol,
                               SymbolTable)
from crane_sym.variational import euler_poisson

from .hoist_startup_scenes import scene_report  # noqa: F401  (crane-sym run)

ID = "hoist_startup"
PAPER = "002_f8509f3826f601de.txt"
TITLE = ("Duhamel's integral for the start-up of a crane hoist: "
         "rope loads and dynamic factors")

# --- Symbols -----------------------------------------------------------------
t = sp.Symbol("t", nonnegative=True)
vt = sp.Symbol("vartheta", real=True)      # the print's integration variable θ
m1, m2, C, g, v0, t_n = sp.symbols("m1 m2 C g v0 t_n", positive=True)
Omega, m, T = sp.symbols("Omega m T", positive=True)
tau0, Q_0 = sp.symbols("tau_0 Q_0", positive=True)
P_at0, Q_at0, S_at0, a_at0 = sp.symbols("P_at0 Q_at0 S_at0 a_at0", real=True)
Pbar0, k, theta = sp.symbols("Pbar_0 k theta", positive=True)
C1, C2 = sp.symbols("C_1 C_2", real=True)
x_s0, x_s0_dot, x0, x0_dot = sp.symbols("xtilde_s xtilde_s_dot x_0 x_0_dot", real=True)
x_st, x_max, t_max, theta_half = sp.symbols("x_st x_max t_max theta_half", real=True)
d_max, F_r, F_ref, J = sp.symbols("d_max F_r F_ref J", real=True)
K_cell, k3_max, k4_max, t3_star, t4_star = sp.symbols(
    "K_cell k3_max k4_max t3_star t4_star", real=True)
col, t_a, dk_tau0, dQdot_tau0, v_end = sp.symbols(
    "col t_a dk_tau0 dQdot_tau0 v_end", real=True)

_real = {"real": True}
x1, x2, x = (sp.Function(n, **_real)(t) for n in ("x1", "x2", "x"))
x_s = sp.Function("x_*", **_real)(t)
P, Q = sp.Function("P", **_real)(t), sp.Function("Q", **_real)(t)
P_d = sp.Function("P_дин", **_real)(t)
K, K1, K2 = (sp.Function(n, **_real)(t) for n in ("K_дин", "K_дин^(1)", "K_дин^(2)"))
k_d, kt_d = sp.Function("k_дин", **_real)(t), sp.Function("ktilde_дин", **_real)(t)
a = sp.Function("a_i", **_real)(t)
A_LAW = {i: sp.Function(f"a_{i}", **_real)(t) for i in range(1, 5)}
K_OPT = {i: sp.Function(f"ktilde_дин{i}^(opt)", **_real)(t) for i in range(1, 5)}
Y, Y2 = sp.Function("Y", **_real)(t), sp.Function("Y_2", **_real)(t)


# The load S(t) and the force P̄(t) stay unknown in (15)–(34). The numeric
# check evaluates the Duhamel integrals of these formulas by quadrature, so
# each carries a fixed smooth test law (``implemented_function``); printed and
# derived sides always use the same one, and where printed and derived
# integrals are written alike the symbolic check decides before it.
def _test_S(s):
    """Test law standing in for S(θ) in the numeric check [m/s²]."""
    return 1 + s / 3 + s ** 2 / 7


def _test_Pbar(s):
    """Test law standing in for P̄(θ) in the numeric check [N]."""
    return 2 - s / 5 + s ** 3 / 11


S_f = implemented_function(sp.Function("S", real=True), _test_S)
Pbar_f = implemented_function(sp.Function("Pbar", real=True), _test_Pbar)
S, Pbar = S_f(t), Pbar_f(t)


def convolution(integrand: sp.Expr) -> sp.Integral:
    """The print's Duhamel integral over ``[0, t]``, unevaluated.

    .. math:: \\int_0^t f(\\theta)\\, d\\theta \\qquad \\text{(15), (17), (33)}

    Parameters
    ----------
    integrand : sympy.Expr
        In ``vartheta`` (the print's θ) and ``t``.

    Returns
    -------
    sympy.Integral
    """
    return sp.Integral(integrand, (vt, 0, t))


# The Duhamel integrals as the paper prints them.
SIN, COS = sp.sin(Omega * (t - vt)), sp.cos(Omega * (t - vt))
INT_S = convolution(S_f(vt) * SIN)                          # (17), (19), (21)–(27)
INT_S_Y = convolution(S_f(vt) * SIN / Omega)                 # (15) with Y of (16)
INT_S_COS = convolution(S_f(vt) * COS)                       # (18)
INT_P = convolution(Pbar_f(vt) * SIN)                        # (33)
INT_P_REV = convolution(Pbar_f(t - vt) * sp.sin(Omega * vt))  # (34)
INT_P_Y16 = convolution(Pbar_f(t - vt) * sp.sin(Omega * vt) / Omega)       # (34), Y of (16)
INT_P_YF = convolution(Pbar_f(t - vt) * sp.sin(Omega * vt) / (m * Omega))  # (34), Y per force

stiffness = force / length
frequency = 1 / time
one = length / length
_sym = PhysicalSymbol


def _defined(expr, dimension, unit, description, sign="real", rng=(0.5, 2.0)):
    return PhysicalSymbol(expr, dimension, unit, description, DEFINED, sign, rng)


SYMBOLS = SymbolTable([
    _sym(t, time, "s", "time from the start of the drive", TIME, "nonnegative",
         (1e-2, 2.0)),
    _sym(vt, time, "s", "integration variable θ of the Duhamel integrals", TIME, "real",
         (1e-2, 2.0)),
    _sym(m1, mass, "kg", "reduced mass of the drive (first mass)", sample_range=(1e2, 1e4)),
    _sym(m2, mass, "kg", "mass of the load (second mass)", sample_range=(1e3, 5e4)),
    _sym(C, stiffness, "N/m", "stiffness of the rope (elastic link)",
         sample_range=(1e5, 1e8)),
    _sym(g, acceleration, "m/s^2", "acceleration of gravity", sample_range=(9.80, 9.82)),
    _sym(v0, velocity, "m/s", "steady hoisting speed after the start",
         sample_range=(0.1, 1.0)),
    _sym(t_n, time, "s", "duration of the start (transient) t_п", sample_range=(0.5, 3.0)),
    _sym(Pbar0, force, "N", "constant value P̄_0 of the reduced load in (35)–(53)",
         sample_range=(1e3, 1e5)),
    _sym(k, force / time, "N/s", "rate k of the linearly growing load P̄ = k t",
         sample_range=(1e3, 1e5)),
    _sym(theta, time, "s", "duration θ of the pulse or of the load rise (43)–(53)",
         sample_range=(1e-2, 2.0)),
    _sym(x1, length, "m", "displacement of the drive mass m1 (up)", COORDINATE, "real"),
    _sym(x2, length, "m", "displacement of the load m2 (up)", COORDINATE, "real"),
    _sym(x, length, "m", "stretch of the rope x = x1 − x2", COORDINATE, "real"),
    _sym(P, force, "N", "driving force P(t) on the drive mass", COORDINATE, "real"),
    _sym(Q, force, "N", "resistance Q(t) on the load (its weight once lifted)",
         COORDINATE, "real"),
    _sym(S, acceleration, "m/s^2", "reduced load S(t) of (2)", COORDINATE, "real"),
    _sym(Pbar, force, "N", "reduced force P̄(t) = m S(t) of (32)", COORDINATE, "real"),
    _sym(a, acceleration, "m/s^2", "acceleration law a_i(t) of the drive", COORDINATE,
         "real"),
    *[_sym(A_LAW[i], acceleration, "m/s^2", f"acceleration law a_{i}(t) of (30)",
           COORDINATE, "real") for i in range(1, 5)],
    _defined(Omega, frequency, "rad/s", "natural circular frequency Ω of the rope "
             "stretch", "positive", (2.0, 60.0)),
    _defined(m, mass, "kg", "reduced mass m = m1 m2/(m1 + m2) of (32)", "positive",
             (1e2, 1e4)),
    _defined(T, time, "s", "period of the natural vibration", "positive", (0.1, 3.0)),
    _defined(tau0, time, "s", "duration τ_0 of the contact of the load with the "
             "ground when lifting with pick-up", "positive", (5e-3, 0.5)),
    _defined(Q_0, force, "N", "weight Q_0 = m2 g in (28)", "positive", (1e4, 5e5)),
    _defined(P_at0, force, "N", "P(0), driving force at the start"),
    _defined(Q_at0, force, "N", "Q(0), resistance at the start"),
    _defined(S_at0, acceleration, "m/s^2", "S(0), reduced load at the start"),
    _defined(a_at0, acceleration, "m/s^2", "a_i(0), drive acceleration at the start"),
    _defined(x_s, length, "m", "particular solution x_*(t) of (2)"),
    _defined(C1, length, "m", "integration constant C_1 (cos term)"),
    _defined(C2, length, "m", "integration constant C_2 (sin term)"),
    _defined(x_s0, length, "m", "x̃_* = x_*(0)"),
    _defined(x_s0_dot, velocity, "m/s", "dx̃_* = ẋ_*(0)"),
    _defined(x0, length, "m", "x_0 = x(0), initial stretch"),
    _defined(x0_dot, velocity, "m/s", "ẋ_0 = ẋ(0), initial stretch rate"),
    _defined(P_d, force, "N", "dynamic rope force P_дин(t) = C x(t)"),
    _defined(Y, time, "s", "response Y(t) of (2) to a unit impulse of S (16)"),
    _defined(Y2, time ** 3, "s^3", "second integral Y_2(t) of Y(t)"),
    _defined(F_r, force, "N", "rope force of the rigid (C → ∞) hoist"),
    _defined(F_ref, force, "N", "reference force of a dynamic coefficient"),
    _defined(K, one, "1", "dynamic coefficient K_дин(t) (normalised as each "
             "equation says)"),
    _defined(K1, one, "1", "dynamic coefficient K^(1)_дин, lifting with pick-up"),
    _defined(K2, one, "1", "dynamic coefficient K^(2)_дин, lifting from weight"),
    _defined(x_st, length, "m", "static displacement x_ст of the load case"),
    _defined(x_max, length, "m", "largest displacement of the load case"),
    _defined(t_max, time, "s", "time of the largest displacement"),
    _defined(theta_half, time, "s", "pulse length that separates the two maxima"),
    _defined(d_max, one, "1", "largest (x − x_ст)/x_ст after the rise (53)"),
    _defined(k_d, one, "1", "dynamic coefficient k_дин(t) of (57)"),
    _defined(kt_d, one, "1", "coefficient k̃_дин(t) of (63)–(64)"),
    *[_defined(K_OPT[i], one, "1", f"optimal coefficient k̃_дин{i}^(opt)(t), "
               f"law a_{i}") for i in range(1, 5)],
    _defined(J, time, "s", "quality criterion ∫ k_дин² dt of (58)"),
    _defined(K_cell, one, "1", "a printed table cell"),
    _defined(k3_max, one, "1", "largest k̃_дин3^(opt)"),
    _defined(k4_max, one, "1", "largest k̃_дин4^(opt)"),
    _defined(t3_star, time, "s", "time t_3^* of the largest k̃_дин3^(opt)"),
    _defined(t4_star, time, "s", "time t_4^* of the largest k̃_дин4^(opt)"),
    _defined(col, one, "1", "column variable of Table 2"),
    _defined(t_a, time, "s", "time at which Table 2 evaluates a_i"),
    _defined(dk_tau0, one, "1", "jump k̃(τ_0 − 0) − k̃(τ_0 + 0)"),
    _defined(dQdot_tau0, force / time, "N/s", "jump of dQ/dt at t = τ_0"),
    _defined(v_end, velocity, "m/s", "speed the drive law reaches at t_n"),
])

LATEX_NAMES = {
    vt: r"\theta", x_s0: r"\tilde{x}_*", x_s0_dot: r"\dot{\tilde{x}}_*",
    x0_dot: r"\dot{x}_0", P_at0: "P(0)", Q_at0: "Q(0)", S_at0: "S(0)",
    a_at0: "a_i(0)", x_st: r"x_{ст}", x_max: r"x_{\max}", t_max: r"t_{\max}",
    theta_half: r"\theta_{1/2}", d_max: r"\left[(x - x_{ст})/x_{ст}\right]_{\max}",
    F_r: "F_r", F_ref: r"F_{ref}", t_n: r"t_п", tau0: r"\tau_0",
    K_cell: r"\tilde{k}_{cell}", k3_max: r"\tilde{k}_{дин3}^{(opt)}(t_3^*)",
    k4_max: r"\tilde{k}_{дин4}^{(opt)}(t_4^*)", t3_star: "t_3^*", t4_star: "t_4^*",
    col: r"\mathrm{col}", t_a: "t_a", dk_tau0: r"\Delta\tilde{k}(\tau_0)",
    dQdot_tau0: r"\Delta\dot{Q}(\tau_0)", v_end: "v(t_п)",
}

MODEL = r"""
The hoist as two masses on one elastic link (the paper's Fig. 1): the drive,
reduced to the rope, is m1 with displacement x1; the load m2 hangs on the rope
of stiffness C and moves by x2, both upward. The driving force P(t) acts on
m1; the resistance Q(t) on m2, downward (the weight once the load is off the
ground). Not modelled, as in the paper: damping, rope mass, drive dynamics
beyond P(t), slack rope after the start.

            P(t) ^
                 |
              [ m1 ]   drive        x1 ^
                 |
                 /
                 \    C  rope
                 /
                 |                  x2 ^
              [ m2 ]   load
                 |
            Q(t) v            g v
"""

# The drive laws of (30) as the paper prints them (taken from its ref. [7]):
# amplitude (in v0/t_n) times a shape in s = t/t_n.
_s = t / t_n
LAW_SHAPES = {1: sp.Integer(1), 2: 1 - _s, 3: _s * (1 - _s) ** 2,
              4: _s ** 2 * (1 - _s) ** 3}
PRINTED_AMPLITUDES = {1: 1, 2: 1, 3: 12, 4: 60}
PRINTED_LAWS = {i: PRINTED_AMPLITUDES[i] * v0 / t_n * LAW_SHAPES[i] for i in range(1, 5)}

#: Table 2 as the numbers show it was computed (see ``_tables``).
TABLE2_G = sp.Rational(981, 100)
TABLE2_T_A = sp.Rational(1, 1000)


# --- Steps -------------------------------------------------------------------
def rhs(d: Derivation, label: str) -> sp.Expr:
    """Right-hand side of the step ``label`` of ``d``.

    Parameters
    ----------
    d : Derivation
    label : str
        A step label such as ``"(17)"``.

    Returns
    -------
    sympy.Expr
    """
    return d.step(label).statement.rhs


def build() -> Derivation:
    """Rebuild eqs (1)–(66) and Tables 1–2 from the two-mass model."""
    d = Derivation(id=ID, paper=PAPER, title=TITLE,
                   citation="Yu. Chovnyuk, M. Dykteruk, S. Komotska (Kyiv)",
                   model=MODEL, symbols=SYMBOLS)
    eq1, eq2 = _equations_of_motion(d)
    _initial_conditions(d, eq2)
    _duhamel_integral(d)
    _dynamic_coefficients(d, eq1, eq2)
    _drive_laws(d)
    loads = _load_cases(d)
    _optimum(d, eq1, eq2)
    _tables(d)
    from crane_sym.derivations.hoist_startup_published import PUBLISHED
    d.published.extend(PUBLISHED)
    d.outputs.extend(_outputs(d, loads))
    from crane_sym.derivations.hoist_startup_odes import attach
    attach(d)   # ODE systems and bench parameters for `crane-sym bench`
    return d


def _equations_of_motion(d: Derivation):
    """(1)–(6): Lagrange's equations, the stretch equation, general solution."""
    T_, V_, dA = sp.symbols("T_kin Pi delta_A")
    energy = m1 * x1.diff(t) ** 2 / 2 + m2 * x2.diff(t) ** 2 / 2
    strain = C * (x1 - x2) ** 2 / 2
    forces = {x1: P, x2: -Q}
    d.add("kinetic energy", sp.Eq(T_, energy), "Sum of ½·m·v² of drive and load.",
          "Lagrange's equations need the energies of the model.", "Energies and forces")
    d.add("potential energy", sp.Eq(V_, strain), "Strain energy ½·C·x² of the rope.")
    d.add("virtual work", sp.Eq(dA, P * sp.Symbol(r"\delta x1")
                                - Q * sp.Symbol(r"\delta x2")),
          "P(t) drives m1 up, Q(t) holds m2 down.",
          "The generalized forces are the coefficients of the virtual displacements.")
    eq1, eq2 = lagrange_equations(energy, strain, [x1, x2], t, forces).equations
    d.add("(1)", eq1, "Lagrange's equation for x1 with Q1 = P(t).",
          title="Equations of motion")
    d.add("(1), load", eq2, "Lagrange's equation for x2 with Q2 = −Q(t).")

    rel = relative_coordinate(eq2, eq1, x2, x1, x)
    d.add("(2)", sp.Eq(x.diff(t, 2) + Omega ** 2 * x, S),
          "Each equation solved for its acceleration and the load's subtracted from "
          "the drive's, in x = x1 − x2; the coefficients are named Ω² and S(t).",
          "The rope force depends on the stretch only, so one coordinate suffices.",
          "One equation for the stretch")
    d.add("(2), Ω²", sp.Eq(Omega ** 2, rel.omega2), "The coefficient of x.")
    d.add("(2), S(t)", sp.Eq(S, sp.factor(rel.forcing)), "The right-hand side.")
    d.add("(3)", sp.Eq(P_d, C * x), "The rope force ∂Π/∂x1 = C·(x1 − x2) in x.")
    d.add("(3), in x1 and x2", sp.Eq(P_d, sp.diff(strain, x1)),
          "The rope force is the derivative of the strain energy.")

    hom = solve_constant_coefficient(sp.Eq(x.diff(t, 2) + Omega ** 2 * x, 0), x, (C1, C2))
    general = x_s + C1 * hom.basis[0] + C2 * hom.basis[1]
    d.add("(4)", sp.Eq(x, general),
          "A particular solution x_* plus the solution of the homogeneous (2) for "
          "the roots ±iΩ.", title="General solution")
    d.add("(5)", sp.Eq(P_d, C * general), "(4) put into (3).")
    d.add("(6)", sp.Eq(T, sp.periodicity(hom.basis[0], t)),
          "The period of cos Ωt, the free part of (4).")
    return eq1, eq2


def _at_start(expr: sp.Expr) -> sp.Expr:
    """``expr`` at t = 0 with x_*(0), ẋ_*(0) named x̃_*, dx̃_* as in (8)."""
    return expr.subs(t, 0).xreplace({x_s.subs(t, 0): x_s0,
                                     x_s.diff(t).subs(t, 0): x_s0_dot})


def _constants(d: Derivation, start: sp.Expr, rate: sp.Expr) -> tuple[sp.Expr, sp.Expr]:
    """C1, C2 of (4) for x(0) = start, ẋ(0) = rate."""
    general = rhs(d, "(4)")
    (sol,) = sp.solve([_at_start(general) - start, _at_start(general.diff(t)) - rate],
                      [C1, C2], dict=True)
    return sol[C1], sol[C2]


def _initial_conditions(d: Derivation, eq2: sp.Eq) -> None:
    """(7)–(14): constants for lifting with pick-up and from weight."""
    general = rhs(d, "(4)")
    d.add("(7)", sp.Eq(x0, 0),
          "With pick-up the rope is slack before the start: P_дин(0) = C·x(0) = 0.",
          "The two lifting methods start from different states of the rope.",
          "Case 1: lifting with pick-up")
    d.add("(7), velocity", sp.Eq(x0_dot, 0), "Drive and load are at rest.")
    c1, c2 = _constants(d, 0, 0)
    d.add("(8)", sp.Eq(C1, c1), "x(0) = 0 put into (4), with x̃_* = x_*(0).")
    d.add("(8), C2", sp.Eq(C2, c2), "ẋ(0) = 0 put into (4) differentiated.")
    case1 = general.subs({C1: c1, C2: c2})
    d.add("(9)", sp.Eq(x, case1), "(8) put into (4).")
    d.add("(10)", sp.Eq(P_d, sp.expand(C * case1)), "(9) put into (3).")

    rest = eq2.subs(x2.diff(t, 2), 0).subs({x1: x2 + x0, Q: Q_at0})
    (stretch0,) = sp.solve(rest, x0)
    d.add("(11)", sp.Eq(x0, stretch0),
          "Load hanging at rest before the start: (1) for m2 with ẍ2 = 0 gives "
          "C·x(0) = Q(0).", title="Case 2: lifting from weight")
    d.add("(11), velocity", sp.Eq(x0_dot, 0), "Drive and load are at rest.")
    c1, c2 = _constants(d, stretch0, 0)
    d.add("(12)", sp.Eq(C1, c1), "x(0) = Q(0)/C put into (4).")
    d.add("(12), C2", sp.Eq(C2, c2), "ẋ(0) = 0 put into (4) differentiated.")
    case2 = general.subs({C1: c1, C2: c2})
    d.add("(13)", sp.Eq(x, case2), "(12) put into (4).")
    d.add("(14)", sp.Eq(P_d, sp.expand(C * case2)), "(13) put into (3).")


def _pull_constants(expr: sp.Expr) -> sp.Expr:
    """Move factors free of the integration variable out of each Integral."""
    def pull(integral: sp.Integral) -> sp.Expr:
        (var, lo, hi), = integral.limits
        total = sp.Integer(0)
        for term in sp.Add.make_args(sp.expand(integral.function, deep=False)):
            outside, inside = term.as_independent(var, as_Add=False)
            total += outside * sp.Integral(inside, (var, lo, hi))
        return total
    return expr.replace(lambda e: isinstance(e, sp.Integral), pull)


def _duhamel_integral(d: Derivation) -> None:
    """(15)–(24): the particular solution as a Duhamel integral."""
    h = impulse_response(Omega, t)
    particular = convolution(S_f(vt) * h.subs(t, t - vt))
    residual = particular.diff(t, 2) + Omega ** 2 * particular - S
    if sp.simplify(_pull_constants(residual)) != 0:
        raise RuntimeError(f"(15) does not solve (2): residual {residual}")
    if particular.subs(t, 0).doit() != 0 or particular.diff(t).subs(t, 0).doit() != 0:
        raise RuntimeError("(15) does not start from rest")
    d.add("(15)", sp.Eq(x_s, particular),
          "Convolution of S with the unit-impulse response; differentiated under the "
          "integral sign (Leibniz) it satisfies (2) and starts from rest.",
          "A particular solution valid for any load S(t).", "Duhamel's integral")
    d.add("(16)", sp.Eq(Y, h),
          "Free motion of (2) from x(0) = 0, ẋ(0) = 1: the velocity a unit impulse of S "
          "gives.")
    xs_expr = _pull_constants(particular)
    d.add("(17)", sp.Eq(x_s, xs_expr), "(16) put into (15), 1/Ω taken out.")
    xs_dot = _pull_constants(xs_expr.diff(t))
    d.add("(18)", sp.Eq(x_s.diff(t), xs_dot),
          "(17) differentiated by Leibniz's rule; the boundary term S(t)·sin 0 vanishes.")
    d.add("(19)", sp.Eq(x_s.diff(t, 2), _pull_constants(xs_dot.diff(t))),
          "(18) differentiated; the boundary term is S(t)·cos 0.")
    d.add("(19), via (2)", sp.Eq(x_s.diff(t, 2), S - Omega ** 2 * x_s),
          "(2) solved for the acceleration of the particular solution.")
    d.add("(20)", sp.Eq(x_s0, xs_expr.subs(t, 0).doit()),
          "(17) at t = 0: the integral over [0, 0] vanishes.")
    d.add("(20), velocity", sp.Eq(x_s0_dot, xs_dot.subs(t, 0).doit()), "(18) at t = 0.")
    zero = {x_s0: 0, x_s0_dot: 0}
    case1 = rhs(d, "(9)").subs(zero).subs(x_s, xs_expr)
    case2 = rhs(d, "(13)").subs(zero).subs(x_s, xs_expr)
    d.add("(21)", sp.Eq(x, case1), "(20) and (17) put into (9).",
          title="Both lifting cases")
    d.add("(22)", sp.Eq(P_d, C * case1), "(21) put into (3).")
    d.add("(23)", sp.Eq(x, case2), "(20) and (17) put into (13).")
    d.add("(24)", sp.Eq(P_d, sp.expand(C * case2)), "(23) put into (3).")


def _rigid_rope_force(eq1: sp.Eq, eq2: sp.Eq) -> sp.Expr:
    """Rope force when x1 = x2: add the equations for the common acceleration,
    then read C·(x1 − x2) off the load's equation."""
    acc, link = sp.symbols("acc link")
    total = (eq1.lhs + eq2.lhs - eq1.rhs - eq2.rhs).subs(
        {x1.diff(t, 2): acc, x2.diff(t, 2): acc}).subs(x2, x1)
    (common,) = sp.solve(total, acc)
    on_load = eq2.subs(x1, x2 + link / C).doit().subs(x2.diff(t, 2), common)
    return sp.factor(sp.solve(on_load, link)[0])


def _dynamic_coefficients(d: Derivation, eq1: sp.Eq, eq2: sp.Eq) -> None:
    """(25)–(27): the rope force over the rigid hoist's force at t = 0."""
    rigid = _rigid_rope_force(eq1, eq2)
    d.add("rigid rope force", sp.Eq(F_r, rigid),
          "x1 = x2 in (1): (m1 + m2)·a = P − Q, and the load's equation gives the "
          "rope force.", "The reference of the dynamic coefficient (25).",
          "Dynamic coefficients")
    at0 = rigid.subs({P: P_at0, Q: Q_at0})
    d.add("(25)", sp.Eq(K, P_d / at0), "P_дин(t) over the rigid rope force at t = 0.")
    s0 = rhs(d, "(2), S(t)").subs({P: P_at0, Q: Q_at0})
    (p0,) = sp.solve(sp.Eq(S_at0, s0), P_at0)
    via_s0 = sp.factor(at0.subs(P_at0, p0))
    d.add("(25), via S(0)", sp.Eq(K, P_d / via_s0),
          "The reference written with S(0) from (2).")
    d.add("(26)", sp.Eq(K1, rhs(d, "(22)") / at0), "(22) put into (25).")
    d.add("(27)", sp.Eq(K2, rhs(d, "(24)") / at0), "(24) put into (25).")


def _drive_laws(d: Derivation) -> None:
    """(28)–(31): drive force, resistance and the acceleration laws."""
    acc = sp.Symbol("acc")
    # Rigid hoist accelerating at a_i against Q: (m1 + m2) a = P − Q.
    (drive,) = sp.solve(sp.Eq((m1 + m2) * acc, P - Q), P)
    drive = drive.subs(acc, a)
    d.add("(28)", sp.Eq(P, drive),
          "Both masses accelerating at a_i(t) against Q(t): the rigid-hoist law "
          "(m1 + m2)·a_i = P − Q.", "The drive force that gives the load the "
          "acceleration a_i.", "Drive laws")
    d.add("(28), P(0)", sp.Eq(P_at0, drive.subs({a: a_at0, Q: 0})),
          "The law at t = 0, where Q(0) = 0 with pick-up.")
    rope_speed = C * v0 * t          # the drum winds in rope at v0, load resting
    (contact,) = sp.solve(sp.Eq(rope_speed.subs(t, tau0), m2 * g), tau0)
    ramp_q = rope_speed.subs(C, sp.solve(sp.Eq(tau0, contact), C)[0]).subs(m2 * g, Q_0)
    d.add("(28), Q(t)", sp.Eq(Q, ramp_q),
          "For 0 ≤ t ≤ τ_0 the rope stretches at v0 while the load rests: "
          "Q = C·v0·t, with C·v0 = m2 g/τ_0 from (29).")
    d.add("(28), Q(t), t ≥ τ_0", sp.Eq(Q, Q_0),
          "Once the rope holds the weight Q_0 = m2 g the load leaves the ground.")
    d.add("(28), Q(0)", sp.Eq(Q_at0, ramp_q.subs(t, 0)), "(28), Q(t) at t = 0.")
    d.add("(28), Q_0", sp.Eq(Q_0, m2 * g), "The weight of the load.")
    d.add("(29)", sp.Eq(tau0, contact), "C·v0·τ_0 = m2 g: the load leaves the ground.")
    for i in range(1, 5):
        amp = sp.Symbol("A")
        (value,) = sp.solve(sp.integrate(amp * LAW_SHAPES[i], (t, 0, t_n)) - v0, amp)
        d.add(f"(30), a_{i}", sp.Eq(A_LAW[i], value * LAW_SHAPES[i]),
              f"Shape of a_{i} from ref. [7], scaled so that ∫₀^tп a dt = v0 (the "
              "drive reaches the steady speed at the end of the start).")
    d.add("(30), speed of a_2", sp.Eq(v_end, sp.integrate(PRINTED_LAWS[2], (t, 0, t_n))),
          "The printed a_2 integrated over the start.")
    weight = drive.subs(Q, m2 * g)
    d.add("(31)", sp.Eq(P, weight), "(28) with Q = m2 g: the load hangs on the rope.")
    d.add("(31), P(0)", sp.Eq(P_at0, weight.subs(a, a_at0)), "(31) at t = 0.")
    d.add("(31), Q", sp.Eq(Q, m2 * g), "The resistance is the weight throughout.")
    d.add("(31), Q(0)", sp.Eq(Q_at0, m2 * g), "The same at t = 0.")


def _amplitude(expr: sp.Expr) -> sp.Expr:
    """Amplitude R of ``A cos Ωt + B sin Ωt``, written with |sin| where it can."""
    wave = sp.expand(sp.expand_trig(sp.expand(expr)))
    coeffs = sp.collect(wave, [sp.cos(Omega * t), sp.sin(Omega * t)], evaluate=False)
    if set(coeffs) - {sp.cos(Omega * t), sp.sin(Omega * t)}:
        raise ValueError(f"not a pure sinusoid in Ωt: {expr}")
    A, B = (coeffs.get(f, 0) for f in (sp.cos(Omega * t), sp.sin(Omega * t)))
    square = cos_pair_to_sin_squared(sp.trigsimp(sp.expand(A ** 2 + B ** 2)))
    return sp.sqrt(sp.factor(square))


def _static(load: sp.Expr) -> sp.Expr:
    """Static deflection under a constant ``load`` P̄: (32) with ẍ = 0."""
    (value,) = sp.solve(sp.Eq(Omega ** 2 * x, load / m), x)
    return value


def _in_stiffness(expr: sp.Expr) -> sp.Expr:
    """Write m Ω² as C (the print's step after (35))."""
    return sp.simplify(expr.subs(m, C / Omega ** 2))


def _load_cases(d: Derivation) -> dict:
    """(32)–(53): instantaneous, ramp, pulse and ramp-then-hold loads."""
    eq2 = d.step("(2)").statement
    d.add("(32)", sp.Eq(eq2.lhs, Pbar / m), "(2) with S = P̄/m.",
          "The classic load cases are written for a force P̄ on a reduced mass m.",
          "Classic load cases")
    d.add("(32), P̄", sp.Eq(Pbar, m * S), "Definition of P̄.")
    omega2 = rhs(d, "(2), Ω²")
    d.add("(32), m", sp.Eq(m, sp.factor(C / omega2)), "m = C/Ω² with Ω² of (2).")
    d.add("m Ω² = C (after (35))", sp.Eq(m * Omega ** 2, sp.factor(C / omega2 * omega2)),
          "(32), m times Ω² of (2).")
    free = free_response(Omega, t, x0, x0_dot)
    particular = _pull_constants(convolution(Pbar_f(vt) / m * impulse_response(
        Omega, t).subs(t, t - vt)))
    d.add("(33)", sp.Eq(x, free + particular),
          "Free motion from x_0, ẋ_0 plus the Duhamel integral (17) with S = P̄/m.")
    swapped = particular.replace(
        lambda e: isinstance(e, sp.Integral),
        lambda e: _flip(e.transform(vt, (t - vt, vt))))
    d.add("(34)", sp.Eq(x_s, swapped), "θ → t − θ in the integral of (33).")
    y_force = free_response(Omega, t, 0, 1 / m)
    d.add("Y per unit force", sp.Eq(Y, y_force),
          "Free motion from x(0) = 0, ẋ(0) = 1/m: the response of (32) to a unit "
          "impulse of P̄.")

    out = {}
    # 1. Instantaneous load.
    inst = duhamel(step(Pbar0 / m, t=t), Omega, t).pieces[0].expr
    d.add("(35)", sp.Eq(x, inst), "Duhamel's integral of a constant P̄_0 from rest.",
          title="1. Instantaneous load")
    d.add("x_ст (after (35))", sp.Eq(x_st, _static(Pbar0)),
          "Static deflection under P̄_0: (32) with ẍ = 0.")
    d.add("(36)", sp.Eq(x, cos_pair_to_sin_squared(sp.expand(inst))),
          "1 − cos Ωt = 2 sin²(Ωt/2).")
    d.add("(37)", sp.Eq(K, x / x_st), "Definition: displacement over static deflection.")
    out["instant"] = cos_pair_to_sin_squared(sp.expand(sp.simplify(
        inst / rhs(d, "x_ст (after (35))"))))
    d.add("(38)", sp.Eq(K, out["instant"]), "(35) over x_ст.")

    # 2. Linear ramp.
    y2 = sp.integrate((t - vt) * y_force.subs(t, vt), (vt, 0, t))
    d.add("(39)", sp.Eq(x, k * y2), "∫ k(t − θ) Y(θ) dθ with Y per unit force.",
          title="2. Linearly growing load")
    d.add("Y_2 (after (39))", sp.Eq(Y2, sp.integrate(sp.integrate(
        impulse_response(Omega, t).subs(t, vt), (vt, 0, t)).subs(t, vt), (vt, 0, t))),
        "Y of (16) integrated twice from 0.")
    rising = duhamel(linear(k / m, t=t), Omega, t).pieces[0].expr
    if sp.simplify(rising - k * y2) != 0:
        raise RuntimeError("(39) and Duhamel's integral of k t disagree")
    d.add("(40), in m and Ω", sp.Eq(x, rising), "Duhamel's integral of P̄ = k t.")
    d.add("(40)", sp.Eq(x, _in_stiffness(rising)), "m Ω² = C.")
    d.add("(41)", sp.Eq(x_st, _in_stiffness(_static(k * t_n))),
          "Static deflection under P̄(t_п) = k t_п, with m Ω² = C.")
    out["ramp"] = sp.simplify(_in_stiffness(rising) / rhs(d, "(41)"))
    d.add("(42)", sp.Eq(K, out["ramp"]), "(40) over (41).")

    # 3. Rectangular pulse.
    pulse = duhamel(rectangular_pulse(Pbar0 / m, theta, t=t), Omega, t)
    during, after = (p.expr for p in pulse.pieces)
    d.add("(43), in m and Ω", sp.Eq(x, during), "Duhamel's integral for 0 ≤ t ≤ θ.",
          title="3. Rectangular pulse")
    d.add("(43)", sp.Eq(x, _in_stiffness(during)), "m Ω² = C.")
    d.add("(44), in m and Ω", sp.Eq(x, after),
          "Duhamel's integral for t ≥ θ: the load piece ends at θ.")
    d.add("(44)", sp.Eq(x, _in_stiffness(after)), "m Ω² = C.")
    d.add("x_ст (before (45))", sp.Eq(x_st, _in_stiffness(_static(Pbar0))),
          "Static deflection under P̄_0, with m Ω² = C.")
    k_during = sp.simplify(_in_stiffness(during) / rhs(d, "x_ст (before (45))"))
    k_after = sp.simplify(_in_stiffness(after) / rhs(d, "x_ст (before (45))"))
    d.add("(45)", sp.Eq(K, k_during), "(43) over x_ст.")
    d.add("(46)", sp.Eq(K, k_after), "(44) over x_ст.")
    out["pulse"] = sp.Piecewise((k_during, t <= theta), (k_after, True))
    peak, when, half = _pulse_peak(k_during, k_after)
    d.add("half period (before (47))", sp.Eq(theta_half, half),
          "First maximum of (45) at Ωt = π; it falls within the pulse when θ ≥ π/Ω.")
    short, long_ = (branch for branch, _ in peak.args)
    d.add("(47)", sp.Eq(x_max, Pbar0 / C * short),
          "For θ < π/Ω the amplitude after the pulse exceeds the value at t = θ.")
    d.add("(47), in x_ст", sp.Eq(x_max, x_st * short), "The same with x_ст = P̄_0/C.")
    d.add("x_max for θ ≥ π/Ω (before (47))", sp.Eq(x_max, Pbar0 / C * long_),
          "For θ ≥ π/Ω the maximum of (45) at Ωt = π falls within the pulse.")
    d.add("x_max for θ ≥ π/Ω, in x_ст", sp.Eq(x_max, x_st * long_),
          "The same with x_ст = P̄_0/C.")
    d.add("(47), time", sp.Eq(t_max, when), "Where the larger maximum is reached.")
    out["pulse_peak"], out["pulse_peak_time"] = peak, when

    # 4. Rise over θ, then hold.
    rise = duhamel(ramp(Pbar0 / m, theta, t=t), Omega, t)
    up, hold = (p.expr for p in rise.pieces)
    d.add("(48)", sp.Eq(x, up), "Duhamel's integral for 0 ≤ t ≤ θ.",
          title="4. Load rising over θ, then held")
    d.add("(49)", sp.Eq(x, hold), "Duhamel's integral for t ≥ θ.")
    xst = _static(Pbar0)
    d.add("(50), x_ст", sp.Eq(x_st, xst), "Static deflection under P̄_0: (32) with ẍ = 0.")
    d.add("(50)", sp.Eq(x, x_st * sp.simplify(hold / xst)), "(49) over x_ст.")
    k_up, k_hold = sp.simplify(up / xst), sp.simplify(hold / xst)
    d.add("(51)", sp.Eq(K, k_up), "(48) over x_ст.")
    d.add("(52)", sp.Eq(K, k_hold), "(49) over x_ст.")
    out["ramp_hold"] = sp.Piecewise((k_up, t <= theta), (k_hold, True))
    excess = _amplitude(k_hold - 1)
    d.add("(53)", sp.Eq(d_max, excess), "Amplitude of the oscillating part of (52).")
    out["ramp_hold_peak"] = 1 + excess
    return out


def _flip(integral: sp.Integral) -> sp.Expr:
    """``∫_t^0 −f`` written as ``∫_0^t f``."""
    (var, lo, hi), = integral.limits
    if lo == t and hi == 0:
        return sp.Integral(sp.expand(-integral.function), (var, 0, t))
    return integral


def _pulse_peak(k_during: sp.Expr, k_after: sp.Expr):
    """Largest K of the pulse, where it occurs, and the pulse length that
    separates the two cases."""
    first = min(sp.solveset(sp.diff(k_during, t), t, sp.Interval.open(0, 2 * sp.pi / Omega)),
                key=lambda r: sp.N(r.subs(Omega, 1)))
    top = sp.simplify(k_during.subs(t, first))
    amplitude = _amplitude(k_after)
    # For θ < π/Ω, 0 < sin(Ωθ/2) < 1: the amplitude after the pulse exceeds the
    # value (45) reaches at t = θ; check at one such pulse length.
    probe = {theta: sp.pi / (3 * Omega)}
    if not sp.simplify((amplitude - k_during.subs(t, theta)).subs(probe)) > 0:
        raise RuntimeError("the pulse maximum is not the amplitude after the pulse")
    after_at = sp.solve(sp.diff(k_after, t).subs(t, theta / 2 + sp.Symbol("u") / Omega),
                        sp.Symbol("u"))
    crest = min((u for u in after_at if u.is_positive), key=lambda u: sp.N(u))
    peak = sp.Piecewise((amplitude.subs(sp.Abs(sp.sin(Omega * theta / 2)),
                                        sp.sin(Omega * theta / 2)), theta < first),
                        (top, True))
    when = sp.Piecewise((theta / 2 + crest / Omega, theta < first), (first, True))
    return peak, when, first


def _optimum(d: Derivation, eq1: sp.Eq, eq2: sp.Eq) -> None:
    """(54)–(66): the load's fourth-order equation and the Euler–Poisson optimum."""
    (x1_of_x2,) = sp.solve(eq2, x1)
    fourth = sp.expand(eq1.lhs.subs(x1, x1_of_x2).doit() - eq1.rhs)
    lead = fourth.coeff(x2.diff(t, 4))
    fourth = sp.expand(fourth / lead)
    omega2 = rhs(d, "(2), Ω²")
    coeff = fourth.coeff(x2.diff(t, 2))
    if sp.simplify(coeff - omega2) != 0:
        raise RuntimeError(f"coefficient of ẍ2 is {coeff}, not Ω²")
    lhs = x2.diff(t, 4) + Omega ** 2 * x2.diff(t, 2)
    right = sp.expand(-(fourth - x2.diff(t, 4) - coeff * x2.diff(t, 2)))
    d.add("(54)", sp.Eq(lhs, right),
          "x1 from the load's equation (1) put into the drive's, divided by m1 m2/C.",
          "The optimum is sought for the load's own motion.", "The optimum")
    rigid = rhs(d, "(28)")
    d.add("(55)", sp.Eq(P, rigid), "The rigid-hoist law of (28).")
    with_law = sp.expand(right.subs(P, rigid))
    d.add("(56)", sp.Eq(lhs, sp.expand(with_law.subs(C, Omega ** 2 * m1 * m2 / (m1 + m2)))),
          "(55) put into (54); C (m1 + m2)/(m1 m2) = Ω².")
    ref = m2 * v0 / t_n
    d.add("(57), rope force", sp.Eq(k_d, C * (x1 - x2) / ref),
          "Definition: rope force over m2·v0/t_п.")
    d.add("(57)", sp.Eq(k_d, (m2 * x2.diff(t, 2) + Q) / ref),
          "(1) for the load gives C·(x1 − x2) = m2 ẍ2 + Q.")
    coefficient = rhs(d, "(57)")
    d.add("(58)", sp.Eq(J, sp.Integral(coefficient ** 2, (t, 0, t_n))),
          "The criterion to be made smallest.")
    ep = euler_poisson(coefficient ** 2, x2, t).lhs
    factor, core = sp.factor_terms(ep).as_coeff_Mul()
    scale, body = core.as_independent(x2, Q, as_Add=False)
    d.add("(59)", sp.Eq(sp.expand(body), 0),
          f"Euler–Poisson equation of (58) for x2, divided by {sp.sstr(factor * scale)}.")
    q_ramp = rhs(d, "(28), Q(t)")
    q_held = rhs(d, "(28), Q(t), t ≥ τ_0")
    if any(sp.diff(p, t, 2) != 0 for p in (q_ramp, q_held, m2 * g)):
        raise RuntimeError("Q is not linear on its pieces")
    d.add("Q̈ = 0 (before (60))", sp.Eq(Q.diff(t, 2), 0),
          "Q of (28) and (31) is linear in t on each piece.")
    jump = sp.diff(q_held, t) - sp.diff(q_ramp, t)
    d.add("Q̇ at τ_0 (before (60))", sp.Eq(dQdot_tau0, jump),
          "With pick-up Q̇ drops from Q_0/τ_0 to 0 at τ_0, so Q̈ holds a delta there.")
    d.add("(60)", sp.Eq(x2.diff(t, 4), 0), "(59) with Q̈ = 0.")
    reduced = d.step("(56)").statement.subs(Q.diff(t, 2), 0).subs(x2.diff(t, 4), 0)
    (acc,) = sp.solve(reduced, x2.diff(t, 2))
    d.add("(61)", sp.Eq(x2.diff(t, 2), acc), "(60) put into (56) with Q̈ = 0.")
    for i in range(1, 5):
        d.add(f"(61), i = {i}", sp.Eq(x2.diff(t, 4), sp.expand(
            PRINTED_LAWS[i].diff(t, 2))),
              f"ẍ2 = a_{i} of (30) differentiated twice.")
    optimal = coefficient.subs(x2.diff(t, 2), acc)
    d.add("(62)", sp.Eq(k_d, optimal), "(61) put into (57).")
    static = (m2 * g) / ref
    weight_only = sp.simplify(optimal.subs(Q, m2 * g) - static)
    d.add("(63)", sp.Eq(kt_d, weight_only),
          "(62) from weight, less the static part m2 g/(m2 v0/t_п).")
    early = optimal.subs(Q, q_ramp.subs(Q_0, m2 * g))
    d.add("(64)", sp.Eq(kt_d, early), "(62) with Q = m2 g t/τ_0 of (28), for t ≤ τ_0.")
    d.add("(64), τ_0 < t", sp.Eq(kt_d, weight_only), "(63) once the load is lifted.")
    d.add("(64), jump at τ_0", sp.Eq(dk_tau0, sp.simplify(
        early.subs(t, tau0) - weight_only.subs(t, tau0))),
          "k̃ just before τ_0 less k̃ just after.")
    for i in range(1, 5):
        d.add(f"(65), i = {i}", sp.Eq(K_OPT[i], sp.expand(weight_only.subs(
            a, PRINTED_LAWS[i]))), f"(63) with a_{i} of (30).")
    for i in range(1, 5):
        d.add(f"(66), i = {i}", sp.Eq(K_OPT[i], sp.expand(early.subs(
            a, PRINTED_LAWS[i]))), f"(64) with a_{i} of (30).")
    for i in (3, 4):
        s = sp.Symbol("s", nonnegative=True)
        shape = sp.expand(weight_only.subs(a, PRINTED_LAWS[i]).subs(t, s * t_n))
        best = maximum_on_interval(shape, s, 0, 1)
        d.add(f"t{i}* (after (66))", sp.Eq(t3_star if i == 3 else t4_star,
                                          best.location * t_n),
              f"Largest (65), i = {i} on [0, t_п], by its critical points.")
        d.add(f"max k̃{i} (after (66))", sp.Eq(k3_max if i == 3 else k4_max, best.value),
              f"(65), i = {i} at t_{i}^*.")
    # Beyond the paper: the reference forces behind its coefficients.
    d.add("reference of (25), from weight", sp.Eq(F_ref, sp.expand(
        rhs(d, "rigid rope force").subs(
            {P: rhs(d, "(31)"), Q: m2 * g}).subs(a, a_at0))),
          "The rigid rope force of (25) with the law (31) at t = 0.",
          "Compares the normalisations of (25) and (57).")


def _tables(d: Derivation) -> None:
    """Table 1 from (65); Table 2 from (66) as its numbers show it was computed."""
    for i in (2, 3, 4):
        law = rhs(d, f"(65), i = {i}")
        for frac in TABLE_COLUMNS:
            d.add(table1_label(i, frac), sp.Eq(K_cell, law.subs(t, frac * t_n)),
                  f"(65), i = {i} at t/t_п = {frac}.", title="Table 1" if (
                      i, frac) == (2, TABLE_COLUMNS[0]) else "")
    d.add("Table 2, columns", sp.Eq(col, t / tau0),
          "The g term of (66) reproduces the printed numbers only with the column "
          "read as t/τ_0, the range the caption gives (t ∈ [0, τ_0]).", title="Table 2")
    d.add("Table 2, a_i term", sp.Eq(t_a, TABLE2_T_A),
          "The a_i term reproduces the printed k̃_дин2 = 0.999 (t_п = 1 s) and 0.9995 "
          "(t_п = 2 s) in every column only at t = 1 ms.")
    for i in TABLE2_ROWS:
        law = rhs(d, f"(66), i = {i}")
        a_part, g_part = law.as_independent(g)
        for speed, duration in TABLE2_BLOCKS:
            for frac in TABLE_COLUMNS:
                fixed = {v0: speed, t_n: duration}
                value = (a_part.subs(fixed).subs(t, TABLE2_T_A)
                         + g_part.subs(fixed).subs({g: TABLE2_G, t: frac * tau0}))
                d.add(table2_label(i, speed, duration, frac), sp.Eq(K_cell, value),
                      f"(66), i = {i} with g = 9.81, t/τ_0 = {frac} in the g term, "
                      "t = 1 ms in the a_i term.")


TABLE_COLUMNS = tuple(sp.Rational(n, 4) for n in range(5))
TABLE2_ROWS = (1, 3, 2, 4)                       # the printed order
TABLE2_BLOCKS = tuple((sp.Rational(v), sp.Integer(tp)) for v in ("1/4", "1/2")
                      for tp in (1, 2))


def _dec(x: sp.Rational) -> str:
    return str(Decimal(int(x.p)) / Decimal(int(x.q))).rstrip("0").rstrip(".") or "0"


def table1_label(i: int, frac: sp.Rational) -> str:
    """Label of a Table 1 cell, e.g. ``Table 1, k3, t/tn=0.25``.

    Parameters
    ----------
    i : int
        Row: the law a_i of k̃_дин,i^(opt).
    frac : sympy.Rational
        Column t/t_п.
    """
    return f"Table 1, k{i}, t/tn={_dec(frac)}"


def table2_label(i: int, speed: sp.Rational, duration: sp.Integer,
                 frac: sp.Rational) -> str:
    """Label of a Table 2 cell, e.g. ``Table 2, k1, v0=0.25, tn=1, col=0.5``.

    Parameters
    ----------
    i : int
        Row: the law a_i.
    speed, duration : sympy.Rational
        The block: v0 [m/s] and t_п [s].
    frac : sympy.Rational
        The printed column (see step ``Table 2, columns`` for its reading).
    """
    return f"Table 2, k{i}, v0={_dec(speed)}, tn={duration}, col={_dec(frac)}"


# --- Outputs ---------------------------------------------------------------------
def windowed(expr: sp.Expr) -> sp.Expr:
    """Every ``Piecewise`` in time, ``(e0, t < b1), (e1, t < b2), ..., (en, True)``,
    written as ``Σ e_k·[H(t − b_k) − H(t − b_{k+1})]`` with H(0) = 0.

    ``codegen.hoist`` cannot yet take a Piecewise apart; windows keep each
    superposed part on its own breakpoints, so no order of τ_0 and t_п is
    assumed.
    """
    def window(pw: sp.Piecewise) -> sp.Expr:
        total, start = sp.Integer(0), None
        for e, cond in pw.args:
            if cond == sp.true:
                end = None
            elif isinstance(cond, (sp.StrictLessThan, sp.LessThan)) and cond.lhs == t:
                end = cond.rhs
            else:
                raise ValueError(f"cannot window the condition {cond}")
            low = 1 if start is None else sp.Heaviside(t - start, 0)
            high = 0 if end is None else sp.Heaviside(t - end, 0)
            total += e * (low - high)
            start = end
        return total
    return expr.replace(lambda e: isinstance(e, sp.Piecewise) and e.has(t), window)


def _polynomial_response(shape: sp.Expr, until: sp.Expr, basis: dict) -> sp.Expr:
    """Duhamel response (x_* of (17)) to ``shape`` on [0, until), 0 after, from the
    responses to t^j on [0, until) (superposition, as the paper advises)."""
    poly = sp.Poly(sp.expand(shape), t)
    total = sp.Integer(0)
    for (j,), c in zip(poly.monoms(), poly.coeffs()):
        if j not in basis:
            basis[j] = duhamel(PiecewiseLoad((0, until), (t ** j, 0), t), Omega, t,
                               simplify=False).piecewise()
        total += c * basis[j]
    return total


def _drive_law_coefficients() -> dict[tuple[int, int], sp.Expr]:
    """K^(1)(t), K^(2)(t) of (26)–(27) for each law a_i, by Duhamel's integral.

    S = P/m1 + Q/m2 with (28) or (31); after t_п the drive runs steadily (a = 0).
    By superposition: the a_i part (switched off at t_п), the weight part of P
    (a step) and Q (a ramp to τ_0 or a step), each with its own breakpoints."""
    basis: dict = {}
    weight_step = duhamel(step(sp.Integer(1), t=t), Omega, t).piecewise()
    pickup = duhamel(ramp(sp.Integer(1), tau0, t=t), Omega, t, simplify=False).piecewise()
    result = {}
    for i in range(1, 5):
        law = _polynomial_response(PRINTED_LAWS[i], t_n, basis)
        drive = (m1 + m2) / m1 * law + m2 * g / m1 * weight_step
        for case, (q_part, q0) in {1: (m2 * g / m2 * pickup, 0),
                                   2: (m2 * g / m2 * weight_step, m2 * g)}.items():
            x_star = drive + q_part
            p0 = (m1 + m2) * PRINTED_LAWS[i].subs(t, 0) + m2 * g
            reference = (m2 * p0 + m1 * q0) / (m1 + m2)
            result[(case, i)] = (C * x_star + q0 * sp.cos(Omega * t)) / reference
    return result


def _outputs(d: Derivation, loads: dict) -> list[Output]:
    """Generated functions, with the paper's symbols as arguments."""
    omega = sp.sqrt(rhs(d, "(2), Ω²"))
    contact = rhs(d, "(29)")
    outs = [
        Output("natural_frequency", omega, (m1, m2, C), ("(2)",),
               "Natural circular frequency Omega of the rope stretch.", "rad/s"),
        Output("pickup_contact_time", contact, (m2, g, C, v0), ("(29)",),
               "Duration tau_0 of the load's contact with the ground (pick-up).", "s"),
        Output("dynamic_coefficient_instant", loads["instant"], (t, Omega), ("(38)",),
               "K_din(t) under a suddenly applied constant load.", "1"),
        Output("dynamic_coefficient_ramp", loads["ramp"], (t, Omega, t_n), ("(42)",),
               "K_din(t) under a linearly growing load, over the static deflection "
               "at t_n.", "1"),
        Output("dynamic_coefficient_pulse", windowed(loads["pulse"]), (t, Omega, theta),
               ("(45)", "(46)"), "K_din(t) under a rectangular pulse of length theta.",
               "1"),
        Output("pulse_peak_factor", loads["pulse_peak"], (Omega, theta), ("(47)",),
               "Largest x/x_st under a rectangular pulse of length theta.", "1"),
        Output("pulse_peak_time", loads["pulse_peak_time"], (Omega, theta), ("(47)",),
               "Time of the largest displacement under the pulse.", "s"),
        Output("dynamic_coefficient_ramp_hold", windowed(loads["ramp_hold"]), (t, Omega, theta),
               ("(51)", "(52)"), "K_din(t) under a load rising over theta, then held.",
               "1"),
        Output("ramp_hold_peak_factor", loads["ramp_hold_peak"], (Omega, theta),
               ("(53)",), "Largest x/x_st under the rise-then-hold load.", "1"),
    ]
    # Ω and τ_0 are arguments (from natural_frequency and pickup_contact_time):
    # with C = m Ω² the expressions stay a quarter of their size in m1, m2, C.
    stiff = Omega ** 2 * m1 * m2 / (m1 + m2)
    for (case, i), expr in sorted(_drive_law_coefficients().items()):
        name, label = ("pickup", "(26)") if case == 1 else ("from_weight", "(27)")
        args = ((t, Omega, tau0) if case == 1 else (t, Omega)) + (m1, m2, g, v0, t_n)
        how = ("lifting with pick-up (tau_0 from pickup_contact_time)" if case == 1
               else "lifting from weight")
        outs.append(Output(f"dynamic_coefficient_{name}_a{i}",
                           windowed(expr.subs(C, stiff)), args, (label, "(28)", "(30)"),
                           f"K_din^({case})(t) for the drive law a_{i} of (30), {how}; "
                           "Omega from natural_frequency.", "1"))
    for i in range(1, 5):
        outs.append(Output(f"optimal_coefficient_from_weight_a{i}",
                           rhs(d, f"(65), i = {i}"), (t, t_n),
                           ("(63)", "(65)"),
                           f"k~_din{i}^(opt)(t) from weight, 0 <= t <= t_n.", "1"))
        early = rhs(d, f"(66), i = {i}")
        late = rhs(d, f"(65), i = {i}")
        outs.append(Output(f"optimal_coefficient_pickup_a{i}",
                           windowed(sp.Piecewise((early, t <= tau0), (late, True))),
                           (t, t_n, v0, g, tau0), ("(64)", "(65)", "(66)"),
                           f"k~_din{i}^(opt)(t) with pick-up, 0 <= t <= t_n.", "1"))
    return outs


# --- Hard cases --------------------------------------------------------------------
def hard_cases(points: int = 200, seed: int = 20261122) -> dict[str, dict[str, np.ndarray]]:
    """Seeded input grids where a naive closed form loses accuracy.

    Returns case name -> columns, one array per argument of the outputs
    (t, Omega, t_n, tau_0, theta, m1, m2, g, v0, C); a function ignores the
    columns it does not take. Ω is drawn on its own: the coefficients take it
    as an argument (from ``natural_frequency``).
    """
    rng = np.random.default_rng(seed)
    n = points
    log = lambda lo, hi, size=n: 10.0 ** rng.uniform(np.log10(lo), np.log10(hi), size)

    def typical() -> dict[str, np.ndarray]:
        return {"Omega": log(2.0, 60.0), "m1": log(1e2, 1e4), "m2": log(1e3, 5e4),
                "g": rng.uniform(9.80, 9.82, n), "v0": log(0.1, 1.0),
                "C": log(1e5, 1e8), "t_n": log(0.5, 3.0), "tau_0": log(5e-3, 0.5),
                "theta": log(1e-2, 2.0)}

    def near_and_long(cols: dict, window: np.ndarray) -> np.ndarray:
        """t within a decade of ``window`` (both sides of the switch) for half
        the points, Ωt from Ω·window/10 up to 1e3 (long times) for the rest."""
        near = window * log(0.1, 10.0)
        phase = 10.0 ** rng.uniform(np.log10(cols["Omega"] * window) - 1, 3.0)
        return np.where(np.arange(n) % 2 == 0, near, phase / cols["Omega"])

    def small_window(*names: str) -> dict[str, np.ndarray]:
        cols = typical()
        z = np.logspace(-9, 0, n)               # Ω·window
        rng.shuffle(z)
        for name in names:                      # windows of one size, within 0.3–3x
            cols[name] = z * log(0.3, 3.0) / cols["Omega"]
        cols["t"] = near_and_long(cols, cols[names[0]])
        return cols

    times = typical()
    times["t"] = np.logspace(-9, 3, n) / times["Omega"]

    switch = typical()
    z = 10.0 ** rng.uniform(-9, 2, n)           # Ω·window at the switch
    for name in ("t_n", "tau_0", "theta"):
        switch[name] = z * log(0.3, 3.0) / switch["Omega"]
    which = np.array(["t_n", "tau_0", "theta"])[np.arange(n) % 3]
    at = np.choose(np.arange(n) % 3, [switch["t_n"], switch["tau_0"], switch["theta"]])
    # θ = π/Ω switches the pulse maximum (47): a fifth of the rows sit there.
    pi_rows = np.arange(n) % 5 == 4
    switch["theta"] = np.where(pi_rows, np.pi / switch["Omega"], switch["theta"])
    at = np.where(pi_rows & (which == "theta"), switch["theta"], at)
    side = np.arange(n) // 3 % 3 - 1            # one ulp below, at, one ulp above
    switch["t"] = np.where(side < 0, np.nextafter(at, 0.0),
                           np.where(side > 0, np.nextafter(at, np.inf), at))

    masses = typical()
    masses["m1"] = np.logspace(-8, 8, n) * masses["m2"]
    masses["t"] = log(1e-9, 1e3) / masses["Omega"]

    limits = typical()
    limits["t"] = np.where(np.arange(n) % 2 == 0, 0.0, log(1e-30, 1e-9) / limits["Omega"])
    for name in ("t_n", "tau_0", "theta"):
        limits[name] = log(1e-15, 1e-9) / limits["Omega"]
    return {"Ω·t from 1e-9 to 1e3": times,
            "Ω·t_n from 1e-9 to 1": small_window("t_n"),
            "Ω·τ_0, Ω·θ from 1e-9 to 1": small_window("tau_0", "theta"),
            "Ω·t_n = Ω·τ_0 from 1e-9 to 1": small_window("t_n", "tau_0"),
            "t at t_n, τ_0, θ, π/Ω ± 1 ulp": switch,
            "m1/m2 from 1e-8 to 1e8": masses,
            "t = 0, Ω·t and Ω·windows < 1e-9 (0/0)": limits}
