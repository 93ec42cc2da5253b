"""Paper 002's model: the two-mass hoist, its symbols and the drive laws of (30).

The constants ``ID``, ``PAPER``, ``TITLE`` (here, the lowest module, because
the published records cite ``PAPER``; the package re-exports them), the
symbols and their table ``SYMBOLS``, ``LATEX_NAMES``, the model text
``MODEL`` with its diagram, the test laws that stand in for S(t) and P̄(t) in
the numeric check, the print's Duhamel integrals, the drive laws a_i of (30)
as printed. Nothing here builds a derivation.
"""
from __future__ import annotations

import sympy as sp
from sympy.physics.units import (acceleration, force, length, mass, time,
                                 velocity)
from sympy.utilities.lambdify import implemented_function

from crane_sym.symbols import (COORDINATE, DEFINED, TIME, PhysicalSymbol,
                               SymbolTable)

ID = "hoist_startup"
PAPER = "002_f8509f3826f601de.txt"
#: The authors as the paper's English header gives them.
AUTHORS = ("Yuriy Chovnyuk", "Mykhaylo Dykteruk", "Svetlana Komotskaya")
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

stiffness = force / length
frequency = 1 / time
one = length / length
_sym = PhysicalSymbol


def _defined(expr, dimension, unit, description, sign="real", rng=(0.5, 2.0), serve=None):
    return PhysicalSymbol(expr, dimension, unit, description, DEFINED, sign, rng, serve)


SYMBOLS = SymbolTable([
    _sym(t, time, "s", "time from the start of the drive", TIME, "nonnegative",
         (1e-2, 2.0), (1e-8, 1e7)),                     # hard cases: slow loads, long times
    _sym(vt, time, "s", "integration variable θ of the Duhamel integrals", TIME, "real",
         (1e-2, 2.0)),
    _sym(m1, mass, "kg", "reduced mass of the drive (first mass)", sample_range=(1e2, 1e4),
         serve_range=(1e-9, 1e17)),                     # hard cases: m1/m2 from 1e-12 to 1e12
    _sym(m2, mass, "kg", "mass of the load (second mass)", sample_range=(1e3, 5e4)),
    _sym(C, stiffness, "N/m", "stiffness of the rope (elastic link)",
         sample_range=(1e5, 1e8)),
    _sym(g, acceleration, "m/s^2", "acceleration of gravity", sample_range=(9.80, 9.82)),
    _sym(v0, velocity, "m/s", "steady hoisting speed after the start",
         sample_range=(0.1, 1.0)),
    _sym(t_n, time, "s", "duration of the start (transient) t_п", sample_range=(0.5, 3.0),
         serve_range=(1e-17, 1e7)),                     # hard cases: t_n -> 0 (0/0 forms)
    _sym(Pbar0, force, "N", "constant value P̄_0 of the reduced load in (35)–(53)",
         sample_range=(1e3, 1e5)),
    _sym(k, force / time, "N/s", "rate k of the linearly growing load P̄ = k t",
         sample_range=(1e3, 1e5)),
    _sym(theta, time, "s", "duration θ of the pulse or of the load rise (43)–(53)",
         sample_range=(1e-2, 2.0), serve_range=(1e-17, 1e7)),   # hard cases: θ -> 0
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
             "ground when lifting with pick-up", "positive", (5e-3, 0.5),
             (1e-17, 1e7)),                             # hard cases: τ_0 -> 0
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
    vt: r"\vartheta", x_s0: r"\tilde{x}_*", x_s0_dot: r"\dot{\tilde{x}}_*",
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
