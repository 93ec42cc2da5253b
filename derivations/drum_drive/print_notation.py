"""The print's own notation in paper 004 (``004_f118c513e0426caf.txt``).

Symbols the paper uses but never defines (φ4, x_i, the y_i, z_i of (8), (11),
(12), m1, m2, C3, ν3, C_екв, ω, ε of (12), ϑ_z) and the names of its displays,
chosen so that SymPy's LaTeX of each is the printed one; ``PRINT_SYMBOLS``
gives those the checks sample their dimension and range.
"""
from __future__ import annotations

import sympy as sp
from sympy.physics.units import energy, force, length, mass, time, velocity

from crane_sym.published import PublishedFormula, printed
from crane_sym.symbols import COORDINATE, DEFINED, PARAMETER, PhysicalSymbol

from .model import ONE, PAPER, ROT_DAMP, STIFF, TORQUE, t

# --- The print's notation ------------------------------------------------------
# Names chosen so that SymPy's LaTeX of each is the printed one.
m1, m2, C3, nu3, C_ekv, theta_z, delta_y, k = sp.symbols(
    "m1 m2 C3 nu3 C_ekv theta_z delta_y k", positive=True)
n_q, Q1, Q2, Q3, dT, dm, dl, dt, dy, v_z = sp.symbols(
    "n_q Q_1 Q_2 Q_3 dT dm dl dt dy v_(z)", positive=True)
omega_f, eps, dA1, dA2, dA3, vphi, A_y, a_ph, a17, b17, kappa = sp.symbols(
    "omega epsilon dA_1 dA_2 dA_3 delta_phi A a a_(17) b_(17) kappa", real=True)
x_ax, s_tg = sp.Symbol("x", real=True), sp.Symbol("s", real=True)
phi4 = sp.Function("phi4")(t)
y_h, y_p = sp.Function("y_1")(t), sp.Function("y_2")(t)
w = sp.Function("w")(x_ax, t)
xs = [sp.Function(f"x{i}")(t) for i in (1, 2, 3)]
yp = [sp.Function(f"y{i}")(t) for i in (1, 2, 3, 4)]
zp = [sp.Function(f"z{i}")(t) for i in (1, 2, 3, 4)]


#: Names that keep the print's symbols apart from the model's of the same letter.
PRINT_LATEX_NAMES = {omega_f: r"\omega_{(12)}", a_ph: r"a_{(14)}", y_h: r"y_\mathrm{h}",
                     y_p: r"y_\mathrm{p}"}


def _entries(role, sign, rows):
    return [PhysicalSymbol(row[0], row[1], row[2], row[3], role, sign,
                           row[4] if len(row) > 4 else (0.5, 2.0)) for row in rows]


PRINT_SYMBOLS = [
    *_entries(PARAMETER, "positive", [
        (m1, mass, "kg", "the print's m1 (mass of body 1; not in the model)", (1, 1e3)),
        (m2, mass, "kg", "the print's m2 (mass of body 2; not in the model)", (1, 1e3)),
        (C3, TORQUE, "N*m/rad", "the print's C3: i = 3 of Σ C_i; 'drum stiffness' in (13)",
         (1e3, 1e6)),
        (nu3, ROT_DAMP, "N*m*s/rad", "the print's ν3: i = 3 of Σ ν_i", (1, 1e3)),
        (C_ekv, STIFF, "N/m", "the print's C_екв, 'equivalent stiffness of the drive'",
         (1e3, 1e7)),
        (theta_z, velocity, "m/s", "the print's ϑ_z of (16)", (0.1, 10)),
        (delta_y, length, "m", "the print's δy in (7): length of the second span", (10, 3e3)),
        (omega_f, 1 / time, "rad/s", "the print's ω of (12) (not defined)", (0.5, 50)),
        (a17, time**2 / length**4, "s^2/m^4", "coefficient a of (17) (not given)",
         (1e-3, 1e3)),
        (b17, time / length**3, "s/m^3", "coefficient b of (17) (not given)", (1e-3, 1e3))]),
    *_entries(PARAMETER, "real", [(eps, ONE, "rad", "the print's ε of (12) (not defined)")]),
    *_entries(COORDINATE, "real", [
        (phi4, ONE, "rad", "the print's φ4 (i = 3 of Σ; not defined)"),
        *[(f, length, "m", f"the print's x_{i} of (2) (not defined)")
          for i, f in enumerate(xs, 1)],
        *[(f, length, "m", f"the print's y_{i} of (8), (11), (12) (not defined)")
          for i, f in enumerate(yp, 1)],
        *[(f, length, "m", f"the print's z_{i} of (8), (11), (12) (not defined)")
          for i, f in enumerate(zp, 1)],
        (y_h, length, "m", "y_1 of (14): solution of the homogeneous equation"),
        (y_p, length, "m", "y_2 of (14): a particular solution"),
        (w, length, "m", "y(x, t) of (15): deflection of the drum's bent axis (written w)"),
        (x_ax, length, "m", "coordinate along the drum axis")]),
    *_entries(DEFINED, "real", [
        (s_tg, length, "m", "ξ·tg φ, the variable of the last two integrals of (7)")]),
    *_entries(DEFINED, "positive", [
        (n_q, ONE, "1", "number of generalized coordinates"),
        (Q1, TORQUE, "N*m", "generalized force of φ"),
        (Q2, force, "N", "generalized force of z"),
        (Q3, force, "N", "generalized force of y"),
        (dT, energy, "J", "kinetic energy of a piece dm of the element"),
        (dm, mass, "kg", "mass of a piece dl of the element"),
        (dl, length, "m", "length of a piece of the element"),
        (dt, time, "s", "time increment"),
        (dy, length, "m", "increment of y"),
        (v_z, velocity, "m/s", "speed of the traction element, v_(z) of (5)"),
        (k, 1 / time, "rad/s", "frequency of the relative vibrations (13)")]),
    *_entries(DEFINED, "real", [
        *[(s, energy, "J", f"the print's δA_{i}") for i, s in enumerate((dA1, dA2, dA3), 1)],
        (vphi, ONE, "rad", "virtual rotation δφ of the drive"),
        (A_y, length, "m", "amplitude A of (14)"),
        (a_ph, ONE, "rad", "initial phase a of (14)"),
        (kappa, 1 / length**2, "1/m^2", "coefficient of ∂²y/∂x² that (17) lacks (−N/EI)")]),
]


def record(label: str, latex: str, relation: sp.Eq | None, note: str = "",
           **kwargs) -> PublishedFormula:
    """One record of paper 004 (``crane_sym.published.printed``)."""
    return printed(PAPER, label, latex, relation, note, **kwargs)


def dot(f: sp.Expr, n: int = 1) -> sp.Expr:
    """The n-th time derivative."""
    return f.diff(t, n)


#: The basis note of a record decided by its own terms' dimensions.
DIMENSIONS = "the verdict rests on the dimensions of the print's own terms"
