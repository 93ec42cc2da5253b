"""Paper 004's model: its symbols, symbol table, LaTeX names, the model text
(``MODEL``, with its diagram) and the model's energies T, Π, Φ.

The print's own notation (Q_i, δA_i, dm, dl, y(x, t), ...) is declared with the
printed formulas in ``published``. Nothing here builds anything on import
beyond the symbols and their table rows.
"""
from __future__ import annotations

import sympy as sp
from sympy.physics.units import (acceleration, energy, force, length, mass, time,
                                 velocity)
from sympy.physics.units.dimensions import Dimension

from crane_sym.symbols import (COORDINATE, DEFINED, PARAMETER, TIME,
                               PhysicalSymbol)
from crane_sym.symbols import STATE as STATE_ROLE

#: The paper's text file (``published`` cites it in every record).
PAPER = "004_f118c513e0426caf.txt"
#: The authors as the paper's header gives them (Ukrainian; transliterated).
AUTHORS = ("M.P. Martyntsiv", "O.M. Udovytskyi", "B.V. Sologub")

# --- Symbols -----------------------------------------------------------------
# The print's own notation (Q_i, δA_i, dm, dl, y(x, t), ...) is declared with the
# printed formulas in ``published``.
ONE = Dimension(1)
INERTIA, TORQUE, ROT_DAMP = mass * length**2, force * length, force * length * time
STIFF, DAMP = force / length, force * time / length
t = sp.Symbol("t", nonnegative=True)
phi1, phi2, phi3, y, z = (sp.Function(n)(t) for n in ("phi1", "phi2", "phi3", "y", "z"))
COORDS = (phi1, phi2, phi3, y, z)
#: State of the simulation, (q, q'): plain symbols for the generated right-hand side.
STATE = sp.symbols("s1:11", real=True)
(I1, I2, I3, C1, C2, nu1, nu2, m3, m_L, C_y, C_t, C_z, nu_y, nu_z, nu_t, q, L, r, D,
 M0, F0, F1, F2, mu, alpha, g, m_sum, mu_op, F1_t, F2_t, F3_t, F4_t, K1, K2, K3, K4,
 t_3) = sp.symbols("I1 I2 I3 C1 C2 nu1 nu2 m3 m_L C_y C_t C_z nu_y nu_z nu_t q L r D M0 "
                   "F0 F1 F2 mu alpha g m_sum mu_op F1_t F2_t F3_t F4_t K1 K2 K3 K4 t_3",
                   positive=True)
W = sp.Symbol("W", real=True)
(T_, T_el, T_b, Pi_, Phi_, xi, m_eff, v_s, omega, omega_1, omega_2, F1_lim) = sp.symbols(
    "T T_el T_b Pi Phi xi m_eff v_s omega omega_1 omega_2 F1_lim", positive=True)
(v_xi, a_v, b_v, v_A, v_B, e1, e2, dA, vphi1, vy, vz, y_s, y0, M_d, F_pulse, Delta,
 mu_alpha_min) = sp.symbols("v_xi a_v b_v v_A v_B e1 e2 dA vphi1 vy vz y_s y0 M_d F_pulse "
                            "Delta mu_alpha_min", real=True)


#: Damping coefficients: >= 0, since 0 turns a damper off (switch "damping").
DAMPERS = (nu1, nu2, nu_y, nu_z, nu_t)


def _entries(role: str, sign: str, rows) -> list[PhysicalSymbol]:
    """Table rows (symbol, dimension, unit, description[, sample range[, the
    range generated functions serve]])."""
    return [PhysicalSymbol(row[0], row[1], row[2], row[3], role,
                           "nonnegative" if row[0] in DAMPERS else sign,
                           row[4] if len(row) > 4 else (0.5, 2.0),
                           row[5] if len(row) > 5 else None) for row in rows]


MODEL_SYMBOLS = [
    PhysicalSymbol(t, time, "s", "time from the start of the drive", TIME, "nonnegative",
                   (1e-2, 20.0)),
    *_entries(PARAMETER, "positive", [
        (I1, INERTIA, "kg*m^2", "moment of inertia of the motor rotor (reduced to the drum "
         "shaft)", (1, 100), (1e-8, 1e8)),      # hard cases: I1 -> 0
        (I2, INERTIA, "kg*m^2", "moment of inertia of the intermediate mass (gearbox, "
         "couplings; reduced)", (0.5, 50), (1e-8, 1e12)),  # hard cases: inertia ratios
        (I3, INERTIA, "kg*m^2", "moment of inertia of the driving drum", (5, 500),
         (1e-8, 5e8)),                                       # hard cases: I3 -> 0
        (C1, TORQUE, "N*m/rad", "torsional stiffness, motor to intermediate mass", (1e3, 1e6),
         (1e-8, 1e12)),                                      # hard cases: stiffness ratios
        (C2, TORQUE, "N*m/rad", "torsional stiffness, intermediate mass to drum", (1e3, 1e6),
         (1e-19, 1e19)),                                     # hard cases: stiffness ratios
        (nu1, ROT_DAMP, "N*m*s/rad", "resistance coefficient of the C1 shaft", (1, 1e3)),
        (nu2, ROT_DAMP, "N*m*s/rad", "resistance coefficient of the C2 shaft", (1, 1e3)),
        (m3, mass, "kg", "mass of the drum with its shaft's share (moves with y)", (50, 5e3)),
        (m_L, mass, "kg", "mass of the loaded run (loads, carriers, element), lumped at z",
         (1e2, 1e5)),
        (C_y, STIFF, "N/m", "bending stiffness of the drum shaft at the drum", (1e5, 1e8),
         (1e-3, 1e14)),                                      # hard cases: C_y -> 0
        (nu_y, DAMP, "N*s/m", "resistance coefficient of the drum-shaft bending", (1e2, 1e5)),
        (C_t, STIFF, "N/m", "longitudinal stiffness of the tight (incoming) branch", (1e3, 1e7)),
        (C_z, STIFF, "N/m", "longitudinal stiffness of the slack (outgoing) branch", (1e3, 1e7)),
        (nu_z, DAMP, "N*s/m", "resistance coefficient of the slack branch's stretching",
         (1, 1e4)),
        (nu_t, DAMP, "N*s/m", "running resistance of the element per unit speed", (1, 1e4)),
        (q, mass / length, "kg/m", "mass of one metre of the traction element", (0.5, 20)),
        (L, length, "m", "length of a branch (of the span in (7))", (10, 3e3)),
        (r, length, "m", "radius of the driving drum", (0.1, 2.0)),
        (D, length, "m", "diameter of the driving drum, D = 2r", (0.2, 4.0)),
        (M0, TORQUE, "N*m", "driving torque of the motor, reduced to the drum shaft",
         (10, 1e5)),
        (F0, force, "N", "pretension of both branches at rest", (1e3, 1e6)),
        (F1, force, "N", "force in the tight branch (F0 + C_t*e1 in the model)", (1e3, 1e6)),
        (F2, force, "N", "force in the slack branch (F0 + C_z*e2 in the model)", (1e3, 1e6),
         (1e-8, 1e13)),                                      # hard cases: F1/F2 extremes
        # exp(mu*alpha) of (19) is finite while mu*alpha < 709: a friction
        # coefficient of at most 2 and a wrap of at most 300 rad (48 turns).
        (mu, ONE, "1", "friction coefficient between element and drum", (0.05, 0.5),
         (5e-8, 2.0)),
        (alpha, ONE, "rad", "wrap angle of the element on the drum", (0.5, 10.0),
         (5e-7, 300.0)),
        (g, acceleration, "m/s^2", "acceleration of gravity", (9.80665, 9.80665)),
        (m_sum, mass, "kg", "total mass of the transported loads, Σ m_i(t) of (20)", (10, 1e5)),
        (mu_op, ONE, "1", "resistance coefficient of the loads' motion, μ_оп", (0.005, 0.1)),
        *[(s, force, "N", f"amplitude F_{i}(t) of the pulsating load (21)", (1e2, 1e5))
          for i, s in enumerate((F1_t, F2_t, F3_t, F4_t), 1)],
        *[(s, force, "N", f"constant K_{i} of (21) (pretension at the load)", (1e2, 1e5))
          for i, s in enumerate((K1, K2, K3, K4), 1)],
        (t_3, time, "s", "stop time t_3 of the transporter in (21)", (0.5, 30.0))]),
    *_entries(PARAMETER, "real", [
        (W, force, "N", "resistance of the loads to the motion of the run", (10, 1e5))]),
    *_entries(STATE_ROLE, "real", [
        (state, dim, unit, f"state {i}: {what}")
        for i, (state, (dim, unit, what)) in enumerate(zip(STATE, [
            (ONE, "rad", "φ1"), (ONE, "rad", "φ2"), (ONE, "rad", "φ3"), (length, "m", "y"),
            (length, "m", "z"), (1 / time, "rad/s", "dφ1/dt"), (1 / time, "rad/s", "dφ2/dt"),
            (1 / time, "rad/s", "dφ3/dt"), (velocity, "m/s", "dy/dt"),
            (velocity, "m/s", "dz/dt")]), 1)]),
    *_entries(COORDINATE, "real", [
        (phi1, ONE, "rad", "angle of the motor rotor"),
        (phi2, ONE, "rad", "angle of the intermediate mass"),
        (phi3, ONE, "rad", "angle of the drum"),
        (y, length, "m", "displacement of the drum centre (shaft deflection) toward the line"),
        (z, length, "m", "displacement of the loaded run along its path")]),
    *_entries(DEFINED, "positive", [
        (T_, energy, "J", "kinetic energy of the system"),
        (T_el, energy, "J", "kinetic energy of the traction element (the print's T_т.ор.)"),
        (T_b, energy, "J", "kinetic energy of one branch"),
        (Pi_, energy, "J", "potential energy of the system"),
        (Phi_, energy / time, "W", "Rayleigh dissipation function"),
        (xi, length, "m", "coordinate along the traction element"),
        (m_eff, mass, "kg", "effective mass of a span moved at one point"),
        (v_s, velocity, "m/s", "speed of steady running"),
        (omega, 1 / time, "rad/s", "a natural frequency of the drive chain"),
        (omega_1, 1 / time, "rad/s", "lower elastic natural frequency of the drive chain"),
        (omega_2, 1 / time, "rad/s", "higher elastic natural frequency of the drive chain"),
        (F1_lim, force, "N", "largest tight-branch force without slip")]),
    *_entries(DEFINED, "real", [
        (v_xi, velocity, "m/s", "speed of the element at the point ξ"),
        (a_v, velocity, "m/s", "constant a of the linear distribution (6)"),
        (b_v, 1 / time, "1/s", "slope b of the linear distribution (6)"),
        (v_A, velocity, "m/s", "speed of the upstream end of a branch"),
        (v_B, velocity, "m/s", "speed of the downstream end of a branch"),
        (e1, length, "m", "stretch of the tight branch"),
        (e2, length, "m", "stretch of the slack branch"),
        (dA, energy, "J", "virtual work"),
        (vphi1, ONE, "rad", "virtual rotation of the motor rotor"),
        (vy, length, "m", "virtual displacement of y"),
        (vz, length, "m", "virtual displacement of z"),
        (y_s, length, "m", "drum-shaft deflection in steady running"),
        (y0, length, "m", "drum-shaft deflection at the start"),
        (M_d, TORQUE, "N*m", "torque of the branch forces on the drum (18)"),
        (F_pulse, force, "N", "pulsating load F'(t) of (21)"),
        (Delta, ONE, "1", "traction margin e^(μα) − 1.25·F1/F2 of (19)"),
        (mu_alpha_min, ONE, "1", "least μα that satisfies (19)")]),
]
LATEX_NAMES = {
    I1: "I_1", I2: "I_2", I3: "I_3", C1: "C_1", C2: "C_2", nu1: r"\nu_1", nu2: r"\nu_2",
    m3: "m_3", m_L: "m_L", C_y: "C_y", C_t: "C_t", C_z: "C_z", nu_y: r"\nu_y",
    nu_z: r"\nu_z", nu_t: r"\nu_t", M0: r"M_{o\text{б}}", F0: "F_0", F1: "F_1", F2: "F_2",
    mu_op: r"\mu_{оп}", m_sum: r"\sum m_i(t)", F1_t: "F_1(t)", F2_t: "F_2(t)",
    F3_t: "F_3(t)", F4_t: "F_4(t)", t_3: "t_3", T_: "T", T_el: r"T_{т.ор.}", T_b: "T_b",
    Pi_: r"\Pi", Phi_: r"\Phi", v_xi: r"v_\xi", a_v: "a", b_v: "b", v_A: "v_A",
    v_B: "v_B", m_eff: r"m_{ef}", dA: r"\delta A", vphi1: r"\delta\varphi_1",
    vy: r"\delta y", vz: r"\delta z", v_s: "v_s", y_s: "y_s", y0: "y(0)",
    M_d: r"M_{o\delta}", F1_lim: r"F_{1,\lim}", F_pulse: "F'(t)", Delta: r"\Delta",
    mu_alpha_min: r"(\mu\alpha)_{\min}", omega_1: r"\omega_1", omega_2: r"\omega_2",
}
#: The words a handout gives for the code names in this paper's notes.
HANDOUT_WORDS = {"the toolkit's Lagrange equations": "Lagrange's equations"}

MODEL = r"""
The drive chain: motor rotor I1, intermediate mass I2 (gearbox, couplings) and
drum I3 on torsional shafts C1, C2 with resistance coefficients ν1, ν2, all
reduced to the drum shaft; the motor torque M0 acts on I1 (the paper's drum
index on M_oб is read as "reduced to the drum"). The print's Σ_{i=1}^{3} has no
φ4: the chain ends at the drum, so i = 3 is dropped.

The element wraps the drum (radius r, α = π): both branches leave it parallel,
toward the line. The drum centre moves by y toward the line on its bending
shaft (C_y, ν_y; the drum's mass m3 moves with it). The loaded run (loads,
carriers, element; mass m_L) moves by z along its path, against the load
resistance W(t) and the running resistance ν_t·ż. The tight branch (stiffness
C_t) joins the run to the drum and is stretched by e1 = r·φ3 − y − z; the slack
branch (C_z, ν_z) joins the drum to the rear of the run, e2 = z − y − r·φ3. Both
carry the pretension F0 at rest, so F1 = F0 + C_t·e1 and F2 = F0 + C_z·e2; the
pretension pulls the drum toward the line with 2·F0. Each branch has q per
metre and length L, its speed linear between its ends (the paper's hypothesis
(6)), which gives its kinetic energy (3)–(7). The model is linear (small
stretches, no sag, no slip on the drum) and has a rigid-body mode: the running.
The coordinates start from the unloaded, unstretched state (the paper's zero
initial state), so the pretension is applied at t = 0. Not modelled, as in the
paper: the motor's torque–speed curve, sag and slip. Unlike the print: the
drum's mass counts once (no ½·m3·(ẏ − r·φ̇3)², no undefined x_i); F1, F2 follow
from the stretches instead of being given; their sum loads the drum shaft and
their difference drives the run ((10) has it the other way round); y is
horizontal, so no weight m·g enters.

     M0                                                   C_y, ν_y
      ↓                                                  ////
    [ I1 ]--C1,ν1--[ I2 ]--C2,ν2--[ I3  drum r, m3 ]--------||   y → line
      φ1             φ2               φ3   |     |
                            tight C_t, e1  |     |  slack C_z, ν_z, e2
                                           |     |
                                   [   loaded run m_L, z   ] ← W(t), ν_t·ż
"""


# --- The model's energies and forces ------------------------------------------
def _dot(f: sp.Expr, n: int = 1) -> sp.Expr:
    return f.diff(t, n)


def branch_energy() -> sp.Expr:
    """Kinetic energy of a branch of length L whose speed is linear (6) between
    its ends v_A (ξ = 0) and v_B (ξ = L): ∫ q·v²/2 dξ, integrated by SymPy."""
    fit = sp.solve([sp.Eq(a_v, v_A), sp.Eq(a_v + b_v * L, v_B)], [a_v, b_v])
    return sp.factor(sp.integrate(q * (a_v + b_v * xi).subs(fit) ** 2 / 2, (xi, 0, L)))


def model_energies() -> dict[str, sp.Expr]:
    """T, Π, Φ and the branch stretches of the model, in the coordinates."""
    s1, s2 = r * phi3 - y - z, z - y - r * phi3
    Tb = branch_energy()
    tight = Tb.subs({v_A: _dot(z), v_B: r * _dot(phi3) - _dot(y)}, simultaneous=True)
    slack = Tb.subs({v_A: r * _dot(phi3) + _dot(y), v_B: _dot(z)}, simultaneous=True)
    T_rigid = (I1 * _dot(phi1)**2 + I2 * _dot(phi2)**2 + I3 * _dot(phi3)**2
               + m3 * _dot(y)**2 + m_L * _dot(z)**2) / 2
    V = (C1 * (phi1 - phi2)**2 + C2 * (phi2 - phi3)**2 + C_y * y**2
         + C_t * s1**2 + C_z * s2**2) / 2
    R = (nu1 * _dot(phi1 - phi2)**2 + nu2 * _dot(phi2 - phi3)**2 + nu_y * _dot(y)**2
         + nu_z * _dot(s2)**2 + nu_t * _dot(z)**2) / 2
    return {"T_rigid": T_rigid, "T_el": tight + slack, "T": T_rigid + tight + slack,
            "Pi": V, "Phi": R, "e1": s1, "e2": s2, "T_b": Tb}


#: Generalized forces: M0 on the rotor, the pretension of both branches on the
#: drum, the load resistance on the run.
FORCES = {phi1: M0, y: 2 * F0, z: -W}
