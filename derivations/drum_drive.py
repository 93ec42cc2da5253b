"""Dynamic model of a drive with a driving drum (conveyors, rope installations).

Source: ``004_f118c513e0426caf.txt`` — M.P. Martyntsiv, O.M. Udovytskyi,
B.V. Sologub, "Dynamic model of the drive of transporting and hoisting machines
with a driving drum" (Lviv, 2010; in Ukrainian). The file opens with the tail
of an unrelated article on steering linkages, which is out of scope.

The paper writes Lagrange's equations (1) with a Rayleigh function, the
kinetic energy (2) with the traction element's share (3)–(7) under a linear
velocity distribution, the potential energy (8), the generalized forces
(9)–(10), the dissipation (11), the equations of motion (12), a relative
vibration equation (13)–(14), a drum-shaft bending equation (15)–(17), the drum
torque (18), the traction condition (19) and a pulsating load (20)–(21), then a
numerical example (Fig. 3). Fig. 1 is lost, and the printed energies and forces
do not fit together; this module builds one consistent model from the text
(``MODEL``), derives its equations, audits every printed formula against it and
against the paper's own preceding lines (``drum_drive_published``), and adds
what a user needs: drum torque, traction margin, pulsating load, natural
frequencies, the steady running state and a simulation of the example.

The module does nothing on import; ``build()`` returns the ``Derivation``.
"""
from __future__ import annotations

import sympy as sp
from sympy.physics.units import (acceleration, energy, force, length, mass, time,
                                 velocity)
from sympy.physics.units.dimensions import Dimension

from crane_sym.derivation import Derivation, ODESystem, Output, Switch
from crane_sym.lagrange import lagrange_equations
from crane_sym.modal import eigenvalues_2x2, relative_dynamic_matrix
from crane_sym.odes import solve_constant_coefficient
from crane_sym.symbols import (COORDINATE, DEFINED, PARAMETER, TIME,
                               PhysicalSymbol, SymbolTable)
from crane_sym.symbols import STATE as STATE_ROLE

from .drum_drive_hard_cases import hard_cases  # noqa: F401  (crane-sym accuracy)

ID = "drum_drive"
PAPER = "004_f118c513e0426caf.txt"
TITLE = "Dynamic model of a drive with a driving drum"

# --- Symbols -----------------------------------------------------------------
# The print's own notation (Q_i, δA_i, dm, dl, y(x, t), ...) is declared with the
# printed formulas in ``drum_drive_published``.
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
    """Table rows (symbol, dimension, unit, description[, sample range])."""
    return [PhysicalSymbol(row[0], row[1], row[2], row[3], role,
                           "nonnegative" if row[0] in DAMPERS else sign,
                           row[4] if len(row) > 4 else (0.5, 2.0)) for row in rows]


MODEL_SYMBOLS = [
    PhysicalSymbol(t, time, "s", "time from the start of the drive", TIME, "nonnegative",
                   (1e-2, 20.0)),
    *_entries(PARAMETER, "positive", [
        (I1, INERTIA, "kg*m^2", "moment of inertia of the motor rotor (reduced to the drum "
         "shaft)", (1, 100)),
        (I2, INERTIA, "kg*m^2", "moment of inertia of the intermediate mass (gearbox, "
         "couplings; reduced)", (0.5, 50)),
        (I3, INERTIA, "kg*m^2", "moment of inertia of the driving drum", (5, 500)),
        (C1, TORQUE, "N*m/rad", "torsional stiffness, motor to intermediate mass", (1e3, 1e6)),
        (C2, TORQUE, "N*m/rad", "torsional stiffness, intermediate mass to drum", (1e3, 1e6)),
        (nu1, ROT_DAMP, "N*m*s/rad", "resistance coefficient of the C1 shaft", (1, 1e3)),
        (nu2, ROT_DAMP, "N*m*s/rad", "resistance coefficient of the C2 shaft", (1, 1e3)),
        (m3, mass, "kg", "mass of the drum with its shaft's share (moves with y)", (50, 5e3)),
        (m_L, mass, "kg", "mass of the loaded run (loads, carriers, element), lumped at z",
         (1e2, 1e5)),
        (C_y, STIFF, "N/m", "bending stiffness of the drum shaft at the drum", (1e5, 1e8)),
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
        (F2, force, "N", "force in the slack branch (F0 + C_z*e2 in the model)", (1e3, 1e6)),
        (mu, ONE, "1", "friction coefficient between element and drum", (0.05, 0.5)),
        (alpha, ONE, "rad", "wrap angle of the element on the drum", (0.5, 10.0)),
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


# --- Steps -------------------------------------------------------------------
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


def build() -> Derivation:
    """Rebuild eqs (1)–(21) of the drum-drive model; attach the print and outputs."""
    from crane_sym.derivations import drum_drive_published as pub

    d = Derivation(id=ID, paper=PAPER, title=TITLE,
                   citation="M.P. Martyntsiv, O.M. Udovytskyi, B.V. Sologub, Lviv, 2010",
                   model=MODEL, symbols=SymbolTable(MODEL_SYMBOLS + pub.PRINT_SYMBOLS))
    e = model_energies()
    motion = lagrange_equations(e["T"], e["Pi"], COORDS, t, FORCES, e["Phi"])
    eqs = dict(zip(("φ1", "φ2", "φ3", "y", "z"), motion.equations))
    d.add("(1), coordinates", sp.Eq(pub.n_q, len(COORDS)),
          "The model has five coordinates: φ1, φ2, φ3, y, z (see MODEL).",
          "The print's (1) has three (φ, z, y) while its T and Π use φ1, φ2, φ3.",
          "Lagrange's equations")
    for label, name, Q in (("(1), φ", "φ3", pub.Q1), ("(1), z", "z", pub.Q2),
                           ("(1), y", "y", pub.Q3)):
        d.add(label, sp.Eq(eqs[name].lhs, Q),
              f"d/dt ∂T/∂q̇ − ∂T/∂q + ∂Π/∂q + ∂Φ/∂q̇ for q = {name}, with the T, Π, Φ of "
              "(2)–(11); the generalized force named as in the print.",
              "The Rayleigh term is ∂Φ/∂q̇: Φ depends on the velocities only."
              if Q is pub.Q1 else "")
    _kinetic_energy(d, e, pub)
    _potential_and_forces(d, e, pub)
    d.add("(11)", sp.Eq(Phi_, e["Phi"]),
          "½·ν·(rate)² for each damped link: shafts ν1, ν2, shaft bending ν_y, slack branch "
          "ν_z; and ½·ν_t·ż² for the running resistance of the element.",
          "The tight branch gets no damper: the print gives none for C_t.", "Dissipation")
    for i, (name, eq) in enumerate(eqs.items()):
        d.add(f"(12), {name}", eq, f"Lagrange's equation with dissipation for {name}: "
              "crane_sym.lagrange.lagrange_equations of T, Π, Φ and δA.",
              "The model is linear already (quadratic T, Π, Φ with constant coefficients), "
              "so the paper's 'first approximation' changes nothing." if i == 0 else "",
              "Equations of motion" if i == 0 else "")
    rest = _steady_running(d, eqs)
    _frequencies(d, eqs, pub)
    _torque_traction_load(d, e, pub)
    d.add("initial state", sp.Eq(y0, sp.factor(rest)),
          "(12) at rest under the pretension alone (M0 = 0, W = 0), solved for y.",
          "The equilibrium the drive starts from; the example's zero state is not it.",
          "Initial state of the example")
    d.published.extend(pub.published(e))
    d.outputs.extend(_outputs(d))
    d.switches["damping"] = Switch(
        "damping", "the Rayleigh dissipation Φ of (11)",
        tuple((nu, sp.S.Zero) for nu in DAMPERS))
    d.ode_systems.append(_load_response(d))
    d.bench_parameters.update(BENCH_PARAMETERS)
    return d


def _kinetic_energy(d: Derivation, e: dict, pub) -> None:
    d.add("(2)", sp.Eq(T_, e["T_rigid"] + T_el),
          "½·I·φ̇² of the three rotating bodies, ½·m3·ẏ² of the drum's translation, "
          "½·m_L·ż² of the loaded run, plus the element's T_т.ор.",
          "Only the drum translates; motor and gearbox sit on rigid frames (the print's "
          "x_i are not defined).", "Kinetic energy")
    d.add("(3)", sp.Eq(pub.dT, pub.dm * (_dot(z)**2 + _dot(y)**2) / 2),
          "½·dm·v² of a piece with the velocity components ż and ẏ, as (3) sets it up.")
    d.add("(4)", sp.Eq(pub.dm, q * pub.dl), "Mass of a piece dl at q per metre.")
    d.add("(5)", sp.Eq(pub.v_z, pub.dl / pub.dt), "The element's speed, as the print "
          "defines it.")
    d.add("(6)", sp.Eq(v_xi, a_v + b_v * xi), "The paper's hypothesis, adopted.",
          "With it the element's kinetic energy becomes an effective mass.")
    # The print's geometry for (7): a span [0, L] at rest at both ends, moved
    # across at ξ = z(t) with ẏ; a second span [0, δy] moved along at s = y(t) with ż.
    pieces = []
    for vel, apex, end in ((_dot(y), z, L), (_dot(z), y, pub.delta_y)):
        left = sp.solve([a_v, a_v + b_v * apex - vel], [a_v, b_v])
        right = sp.solve([a_v + b_v * apex - vel, a_v + b_v * end], [a_v, b_v])
        pieces += [((a_v + b_v * xi).subs(left), 0, apex),
                   (sp.factor((a_v + b_v * xi).subs(right)), apex, end)]
    d.add("(6), ξ < z", sp.Eq(v_xi, pieces[0][0]),
          "a and b of (6) fitted to v = 0 at ξ = 0 and v = ẏ at ξ = z (first integral).")
    d.add("(6), ξ > z", sp.Eq(v_xi, pieces[1][0]),
          "a and b fitted to v = ẏ at ξ = z and v = 0 at ξ = L (second integral).")
    total = sp.Add(*[sp.integrate(q * v**2 / 2, (xi, lo, hi)) for v, lo, hi in pieces])
    total = sp.collect(sp.simplify(total), [_dot(y)**2, _dot(z)**2])
    d.add("(7)", sp.Eq(T_el, total),
          "∫ q·v²/2 dξ over the four pieces (the last two with ż along [0, y] and "
          "[y, δy]), integrated by SymPy; √(1 + slope²) of a flat span is 1.",
          "The result does not depend on where the moved point sits (z or y): each span "
          "moves like a third of its mass.")
    d.add("effective mass", sp.Eq(m_eff, sp.diff(total, _dot(y), 2)),
          "∂²T_т.ор./∂ẏ² of (7): the mass that, moving with ẏ, has the span's kinetic "
          "energy — Rayleigh's third of q·L.")
    d.add("branch kinetic energy", sp.Eq(T_b, e["T_b"]),
          "(6) with v = v_A at ξ = 0 and v = v_B at ξ = L, ∫ q·v²/2 dξ over [0, L].",
          "In the model both ends of a branch move; with v_A = 0 this is ½·(q·L/3)·v_B², "
          "the effective mass above.")
    d.add("element kinetic energy", sp.Eq(T_el, e["T_el"]),
          "Tight branch: v_A = ż, v_B = r·φ̇3 − ẏ; slack branch: v_A = r·φ̇3 + ẏ, "
          "v_B = ż (speeds along the running direction).")


def _in_branch_forces(expr: sp.Expr, e: dict) -> sp.Expr:
    """``expr`` with the stretches replaced by C_t·e1 = F1 − F0, C_z·e2 = F2 − F0."""
    G = sp.Dummy("G")
    sol = sp.solve([sp.Eq(G, expr), sp.Eq(F1, F0 + C_t * e["e1"]),
                    sp.Eq(F2, F0 + C_z * e["e2"])], [G, y, phi3], dict=True)[0]
    return sp.expand(sol[G])


def _potential_and_forces(d: Derivation, e: dict, pub) -> None:
    d.add("tight-branch stretch", sp.Eq(e1, e["e1"]),
          "The drum hauls in r·φ3; the drum (by y) and the run (by z) move toward each "
          "other.", title="Potential energy")
    d.add("slack-branch stretch", sp.Eq(e2, e["e2"]),
          "The drum pays out r·φ3 and moves by y toward the run; the run's rear moves "
          "away by z.")
    d.add("(8)", sp.Eq(Pi_, e["Pi"]), "½·C·(stretch)² of the shafts C1, C2, the "
          "drum-shaft bending C_y and the branches C_t, C_z.")
    d.add("tight-branch force", sp.Eq(F1, F0 + C_t * e1), "Pretension plus C_t·e1.")
    d.add("slack-branch force", sp.Eq(F2, F0 + C_z * e2), "Pretension plus C_z·e2.")
    d.add("generalized forces", sp.Eq(dA, sum(Q * v for Q, v in zip(
        FORCES.values(), (vphi1, vy, vz)))),
          "M0 turns the rotor; the pretensions F0 of both branches pull the drum toward "
          "the line (on φ3 and z they cancel); W resists the run.",
          "The branches' elastic forces are in Π, so they are not in δA.",
          "Generalized forces")
    # The print's δA lines take the branch forces F1, F2 as given and put the
    # elastic forces in as well: the virtual work of every force on one body.
    Vb = (C_t * e["e1"]**2 + C_z * e["e2"]**2) / 2
    torque = _in_branch_forces(M0 - sum(sp.diff(Vb, p) for p in (phi1, phi2, phi3)), e)
    on_drum = _in_branch_forces(2 * F0 - sp.diff(Vb, y), e) - C_y * y
    on_run = _in_branch_forces(-W - sp.diff(Vb, z), e)
    for label, dA_i, Q, v, what in (
            ("(9), δA_1", pub.dA1, torque, pub.vphi, "a rigid rotation δφ of the drive "
             "(shafts unstrained): M0 and the branch torque"),
            ("(9), δA_2", pub.dA2, on_drum, vy, "δy of the drum: both branch forces pull "
             "it toward the line, the shaft resists"),
            ("(9), δA_3", pub.dA3, on_run, vz, "δz of the run: F1 pulls it forward, F2 "
             "back, W resists")):
        d.add(label, sp.Eq(dA_i, Q * v), f"Virtual work of every force on {what} (branch "
              "forces taken as given, as in the print).", "To check the print's lines on "
              "their own terms." if label.endswith("1") else "")
    for label, Q, Qv in pub.printed_virtual_work():
        d.add(label, sp.Eq(Q, Qv), "The print's own δA line divided by its virtual "
              "displacement (9), uncorrected.", "To compare (10) with the lines it "
              "should repeat.")
    for label, Q, Qv, on in (("(10), Q1", pub.Q1, torque, "δφ"), ("(10), Q2", pub.Q2,
                                                               on_run, "δz"),
                             ("(10), Q3", pub.Q3, on_drum, "δy")):
        d.add(label, sp.Eq(Q, Qv), f"(9): the derived δA line divided by {on}.")


def _steady_running(d: Derivation, eqs: dict) -> sp.Expr:
    """Steps for steady running; returns y at rest under the pretension."""
    vel = sp.Symbol("v", real=True)
    rigid = {p.diff(t, 2): 0 for p in COORDS} | {_dot(p): vel / r for p in COORDS[:3]}
    rigid |= {_dot(y): 0, _dot(z): vel}
    static = [sp.expand(eq.lhs - eq.rhs).subs(rigid).subs(phi3, 0) for eq in eqs.values()]
    sol = sp.solve(static, [phi1, phi2, y, z, vel], dict=True)[0]
    d.add("steady running", sp.Eq(v_s, sp.factor(sol[vel])),
          "(12) with no accelerations and all bodies at the running speed v "
          "(φ̇_i = v/r, ż = v, ẏ = 0): a linear system in the stretches and v.",
          "The drive runs when M0/r > W; the stretches then no longer change.",
          "Steady running")
    at = {p: sol[p] for p in (phi1, phi2, y, z)} | {phi3: 0}
    for label, sym, pull in (("running tight force", F1, F0 + C_t * (r * phi3 - y - z)),
                             ("running slack force", F2, F0 + C_z * (z - y - r * phi3))):
        d.add(label, sp.Eq(sym, sp.factor(pull.subs(at).subs(r, D / 2))),
              "The branch force with the steady stretches, r = D/2.",
              "Independent of W and ν_t: in steady running the drum passes M0 on."
              if sym is F1 else "")
    d.add("running drum-shaft deflection", sp.Eq(y_s, sp.factor(sol[y].subs(r, D / 2))),
          "y of the steady solution: the shaft carries F1 + F2.")
    at_rest = sp.solve([s_.subs({vel: 0, M0: 0, W: 0}) for s_ in static],
                       [phi1, phi2, y, z], dict=True)[0]
    return at_rest[y]


def _frequencies(d: Derivation, eqs: dict, pub) -> None:
    still = {nu1: 0, nu2: 0, nu_y: 0, nu_z: 0, nu_t: 0}
    lhs = sp.expand(eqs["y"].lhs.subs(still))
    m_yy = lhs.coeff(_dot(y, 2))
    d.add("(13)", sp.Eq(sp.expand(lhs / m_yy), sp.factor(eqs["y"].rhs / m_yy)),
          "The y equation of (12) without resistances, divided by its mass m3 + 2·q·L/3.",
          "No elimination of r·φ̈ isolates y: the drum is tied to the chain and the run "
          "through both branches.", "Relative vibrations")
    lam = sp.Symbol("lambda")
    K = sp.Matrix([[C1, -C1, 0], [-C1, C1 + C2, -C2], [0, -C2, C2]])
    char = sp.factor((K - lam * sp.diag(I1, I2, I3)).det())
    d.add("drive-chain characteristic equation", sp.Eq(char.subs(lam, omega**2), 0),
          "det(K − ω²·M) = 0 for the chain I1–C1–I2–C2–I3, free at both ends (the drum "
          "not held by the element).", "One root ω = 0 (the chain turns as a whole) and "
          "a quadratic in ω² for the two elastic modes.")
    a2, a1, a0 = sp.Poly(sp.cancel(char / lam), lam).all_coeffs()
    b, c = sp.factor(-a1 / a2), sp.factor(a0 / a2)
    A = relative_dynamic_matrix(sp.diag(I1, I2, I3), K)
    twists = sp.Matrix([sp.Function(f"theta_{k}")(t) for k in (1, 2)])
    d.add("drive-chain relative twists", sp.Eq(twists.diff(t, 2), -A * twists),
          "The twists θ1 = φ1 − φ2, θ2 = φ2 − φ3 remove the rigid rotation: θ̈ = −A·θ.",
          "Its eigenvalues are the roots ω² of the quadratic; its discriminant "
          "(a11 − a22)² + 4·a12·a21 is a sum of non-negative terms (a12·a21 = C1·C2/I2²).")
    small, large = eigenvalues_2x2(A)
    assert sp.simplify(small + large - b) == 0 and sp.simplify(small * large - c) == 0
    d.add("ω2", sp.Eq(omega_2, sp.sqrt(large)),
          "The larger eigenvalue of A; its sum and product with the smaller are b and c.",
          "b² − 4c would cancel when the two frequencies are close (and can round to a "
          "negative number there); the sum of squares cannot.")
    d.add("ω1", sp.Eq(omega_1, sp.sqrt(small)),
          "The smaller root as det A/ω2² (Vieta), which avoids b − √(b² − 4c).")
    d.add("(13), k", sp.Eq(pub.k, c**sp.Rational(1, 4)),
          "Vieta: ω1²·ω2² = C1·C2·(I1 + I2 + I3)/(I1·I2·I3); its fourth root, the geometric "
          "mean of ω1 and ω2, is the one frequency of the printed shape.")
    label, statement = pub.printed_homogeneous()
    d.add(label, statement, "The print's (13) with its right-hand side set to zero.",
          "(14) should solve this.")
    d.add("(14)", sp.Eq(y, pub.y_h + pub.y_p),
          "A linear equation's general solution: homogeneous plus particular.")
    Cc, Cs = sp.symbols("C_c C_s")
    free = solve_constant_coefficient(sp.Eq(_dot(pub.y_h, 2) + pub.k**2 * pub.y_h, 0),
                                      pub.y_h, (Cc, Cs))
    shifted = pub.A_y * sp.sin(pub.k * t + pub.a_ph)
    assert sp.simplify(sp.expand_trig(shifted) - free.general.subs(
        {Cc: pub.A_y * sp.sin(pub.a_ph), Cs: pub.A_y * sp.cos(pub.a_ph)})) == 0
    d.add("(14), y1", sp.Eq(pub.y_h, shifted),
          "dsolve of ÿ1 + k²·y1 = 0 gives C_c·cos kt + C_s·sin kt; C_c = A·sin a, "
          "C_s = A·cos a make it A·sin(kt + a).")


def _torque_traction_load(d: Derivation, e: dict, pub) -> None:
    w, x = pub.w, pub.x_ax
    d.add("(17)", sp.Eq(w.diff(x, 4) + pub.a17 * w.diff(t, 2) + pub.b17 * w.diff(x, t)
                        + pub.kappa * w.diff(x, 2), 0),
          "The printed form with a coefficient κ on ∂²y/∂x² (κ = −N/EI for an axial "
          "force N); a and b stay unspecified, as printed.",
          "The least change that gives every term the dimension 1/m³.",
          "Bending of the drum shaft")
    torque = _in_branch_forces(sp.diff((C_t * e["e1"]**2 + C_z * e["e2"]**2) / 2, phi3), e)
    d.add("(18)", sp.Eq(M_d, sp.factor(torque.subs(r, D / 2))),
          "∂Π/∂φ3 of the branches, with C_t·e1 = F1 − F0 and C_z·e2 = F2 − F0, r = D/2.",
          title="Drum torque and traction")
    theta, S = sp.Symbol("theta", nonnegative=True), sp.Function("S")
    belt = sp.dsolve(sp.Eq(S(theta).diff(theta), mu * S(theta)), S(theta),
                     ics={S(0): F2}).rhs
    d.add("(19)", sp.Eq(F1_lim, belt.subs(theta, alpha)),
          "Euler's belt friction dS/dθ = μ·S on the wrap, S(0) = F2, solved by dsolve.")
    d.add("traction margin", sp.Eq(Delta, sp.exp(mu * alpha) - sp.Rational(5, 4) * F1 / F2),
          "The printed condition (19) as a difference: it holds while Δ > 0.")
    d.add("least μα", sp.Eq(mu_alpha_min, sp.log(sp.Rational(5, 4) * F1 / F2)),
          "(19) solved for μα at equality.")
    run = d.step("(12), z").statement
    vel = sp.Symbol("v", real=True)
    steady = {p.diff(t, 2): 0 for p in COORDS} | {_dot(p): vel / r for p in COORDS[:3]}
    steady |= {_dot(y): 0, _dot(z): vel}
    sol = sp.solve([sp.expand(run.lhs - run.rhs).subs(steady),
                    sp.Eq(F1, F0 + C_t * e["e1"]), sp.Eq(F2, F0 + C_z * e["e2"])],
                   [F1, y, phi3], dict=True)[0]
    d.add("(20)", sp.Eq(F1, sol[F1].subs({W: m_sum * g * mu_op, vel: v_s})),
          "The run's equation (12) in steady running, with the branch forces, solved for "
          "F1; W = Σm_i·g·μ_оп.", "F1 is a branch force in (18)–(19).", "Pulsating load")
    s = sp.sin(sp.pi * t / t_3)
    pulse = ((F1_t * s + K1 - sp.Abs(F2_t * s - K2)) / 4
             + (F3_t * s + K3 - sp.Abs(F4_t * s - K4)) / 4)
    d.add("(21)", sp.Eq(F_pulse, pulse),
          "The print's load model, adopted as printed (an empirical formula).",
          "The simulation drives the run with W(t) = F'(t).")
    lows = sp.Min(F1_t * s, K1) / 2 + sp.Min(F3_t * s, K3) / 2
    assert sp.simplify(pulse.subs({F2_t: F1_t, K2: K1, F4_t: F3_t, K4: K3})
                       - lows.rewrite(sp.Abs)) == 0
    d.add("(21), min form", sp.Eq(F_pulse, lows),
          "With F2 = F1, K2 = K1, F4 = F3, K4 = K3: (a + b − |a − b|)/2 = min(a, b).",
          "Each bracket is a sine clipped at K_i; for t3 < t < 2·t3 the sine is negative, "
          "so F' < 0 half of each period 2·t3.")


# --- Outputs -----------------------------------------------------------------
def _outputs(d: Derivation) -> list[Output]:
    """Generated functions, in the paper's symbols."""
    def rhs(label: str) -> sp.Expr:
        return d.step(label).statement.rhs

    chain = (I1, I2, I3, C1, C2)
    running = (M0, D, F0, C_t, C_z, C_y)
    return [
        Output("branch_effective_mass", rhs("effective mass"), (q, L), ("(7)",),
               "Effective mass q*L/3 of a span moved at one point (linear speed (6)).", "kg"),
        Output("drive_chain_frequency_1", rhs("ω1"), chain, ("(13)",),
               "Lower elastic natural frequency of the free-free chain I1-C1-I2-C2-I3.",
               "rad/s"),
        Output("drive_chain_frequency_2", rhs("ω2"), chain, ("(13)",),
               "Higher elastic natural frequency of the free-free chain I1-C1-I2-C2-I3.",
               "rad/s"),
        Output("running_tight_force", rhs("running tight force"), running, ("(12)",),
               "Tight-branch force F1 in steady running.", "N"),
        Output("running_slack_force", rhs("running slack force"), running, ("(12)",),
               "Slack-branch force F2 in steady running.", "N"),
        Output("running_drum_shaft_deflection", rhs("running drum-shaft deflection"),
               running, ("(12)",), "Drum-shaft deflection y in steady running.", "m"),
        Output("drum_torque", rhs("(18)"), (F1, F2, D), ("(18)",),
               "Torque (F1 - F2)*D/2 of the branch forces on the drum.", "N*m"),
        Output("traction_margin", rhs("traction margin"), (F1, F2, mu, alpha), ("(19)",),
               "Margin exp(mu*alpha) - 1.25*F1/F2 of the traction condition; > 0 holds.",
               "1"),
        Output("least_mu_alpha", rhs("least μα"), (F1, F2), ("(19)",),
               "Least mu*alpha that satisfies the traction condition (19).", "1"),
        Output("pulsating_force", rhs("(21)"),
               (t, F1_t, F2_t, F3_t, F4_t, K1, K2, K3, K4, t_3), ("(21)",),
               "Pulsating load F'(t) of (21), as printed.", "N"),
        *_simulation_outputs(d),
    ]


def _linear_system(d: Derivation):
    """(12) as M·q̈ + C·q̇ + K·q = F(W), q = (φ1, φ2, φ3, y, z), from the steps."""
    rows = [d.step(f"(12), {n}").statement for n in ("φ1", "φ2", "φ3", "y", "z")]
    qs, vs, accs = STATE[:5], STATE[5:], sp.symbols("a0:5")
    frozen = ({c.diff(t, 2): a for c, a in zip(COORDS, accs)}
              | {c.diff(t): v for c, v in zip(COORDS, vs)} | dict(zip(COORDS, qs)))
    res = [sp.expand((e.lhs - e.rhs).xreplace(frozen)) for e in rows]
    M, C, K = (sp.Matrix([[sp.diff(r_, s_) for s_ in group] for r_ in res])
               for group in (accs, vs, qs))
    F = -sp.Matrix([r_.xreplace({s_: 0 for s_ in accs + vs + qs}) for r_ in res])
    return M, C, K, F


def _simulation_outputs(d: Derivation) -> list[Output]:
    """State derivative and Jacobian of (12) for SciPy's integrators, and the
    matrices the energy balance needs."""
    M, C, K, F = _linear_system(d)
    Minv = M.inv()
    n = len(COORDS)
    J = sp.Matrix(sp.BlockMatrix([[sp.zeros(n), sp.eye(n)],
                                  [-Minv * K, -Minv * C]]))
    f = J * sp.Matrix(STATE) + sp.Matrix.vstack(sp.zeros(n, 1), Minv * F)
    J, f = J.applyfunc(sp.factor), f.applyfunc(sp.factor)

    def ordered(*exprs: sp.Expr) -> tuple:
        free = set().union(*(e.free_symbols for e in exprs))
        return tuple(e.expr for e in d.symbols if e.expr in free)

    return [
        Output("state_derivative", f, ordered(f), ("(12)",),
               "Right-hand side d(state)/dt of (12) for scipy.integrate.solve_ivp; state "
               "(phi1, phi2, phi3, y, z, and their rates) = (s1, ..., s10).", "SI"),
        Output("state_jacobian", J, ordered(J), ("(12)",),
               "Jacobian of state_derivative (constant: the model is linear).", "SI"),
        Output("mass_matrix", M, ordered(M), ("(12)",), "Mass matrix M of (12).", "SI"),
        Output("damping_matrix", C, ordered(C), ("(12)",), "Damping matrix C of (12).", "SI"),
        Output("stiffness_matrix", K, ordered(K), ("(12)",), "Stiffness matrix K of (12).",
               "SI"),
        Output("generalized_forces", F, ordered(F), ("(10)", "(12)"),
               "Generalized forces F(W) of (12).", "SI"),
    ]


# --- Bench -------------------------------------------------------------------
#: Values the bench gives to arguments no scene sets [SI]: the drum radius from
#: the scene's D, and one state and load of the order the example reaches
#: (the grid of time-free functions perturbs each by a factor 1/2 ... 2).
BENCH_PARAMETERS = {r: D / 2, W: sp.Float(1.0e3),
                    **dict(zip(STATE, map(sp.Float, (10.0, 10.0, 10.0, 1e-3, 2.5,
                                                     16.0, 16.0, 16.0, 1e-2, 4.0))))}


def _load_response(d: Derivation) -> ODESystem:
    """(12) from rest under W = F'(t) of (21): the example's response, which has
    no closed form; the bench integrates it with the generated state derivative
    and Jacobian against a modal mpmath solution."""
    rest = tuple((c, 0) for c in COORDS) + tuple((c.diff(t), 0) for c in COORDS)
    return ODESystem(
        "(12) from rest, W = F'(t) of (21)",
        tuple(d.step(f"(12), {n}").statement for n in ("φ1", "φ2", "φ3", "y", "z")),
        COORDS, rest,
        (("drum_shaft_displacement", y), ("run_speed", z.diff(t)),
         ("tight_branch_force", F0 + C_t * model_energies()["e1"])),
        ((W, d.step("(21)").statement.rhs),))


# --- Scenes ------------------------------------------------------------------
#: Simulation-only values a scene gives in [options] (not arguments of any output).
SIM_OPTIONS = ("m3", "m_L", "nu1", "nu2", "nu_y", "nu_z", "nu_t")


def _rhs_functions(d: Derivation):
    """Right-hand side, Jacobian and energy of (12) from the generated module.

    The state is (q, q̇, E_in, E_d): q̇ and q̈ come from the generated
    ``state_derivative``; E_in = ∫F·q̇ dt is the work of the given forces and
    E_d = ∫q̇·C·q̇ dt = ∫2Φ dt the dissipated energy.

    Returns
    -------
    make(values, load) -> (rhs, jac, energy, matrices)
        ``values``: SI values by symbol name; ``load``: W as a function of t.
    """
    import importlib

    import numpy as np

    generated = importlib.import_module(f"crane_sym.generated.{d.id}")
    order = {o.name: [str(a) for a in o.args] for o in d.outputs}
    n = len(COORDS)

    def make(values: dict, load):
        def call(name: str, **more) -> np.ndarray:
            given = {**values, **more}
            return getattr(generated, name)(*[given[a] for a in order[name]])

        Mn, Cn, Kn = (call(name) for name in ("mass_matrix", "damping_matrix",
                                             "stiffness_matrix"))
        Jn = call("state_jacobian")
        # The model is linear: f(x, W) = J·x + f0 + W·fW and F(W) = F0 + W·FW, all
        # taken from the generated functions once per parameter set.
        rest = {str(s_): 0.0 for s_ in STATE}
        f0 = call("state_derivative", W=0.0, **rest).ravel()
        fW = call("state_derivative", W=1.0, **rest).ravel() - f0
        F0n = call("generalized_forces", W=0.0).ravel()
        FWn = call("generalized_forces", W=1.0).ravel() - F0n

        def force(tt):
            return F0n + load(tt) * FWn

        def rhs(tt, x):
            dx = np.empty(2 * n + 2)
            dx[:2 * n] = Jn @ x[:2 * n] + f0 + load(tt) * fW
            v = x[n:2 * n]
            dx[2 * n], dx[2 * n + 1] = force(tt) @ v, v @ Cn @ v
            return dx

        def jac(tt, x):
            J = np.zeros((2 * n + 2, 2 * n + 2))
            J[:2 * n, :2 * n] = Jn
            J[2 * n, n:2 * n], J[2 * n + 1, n:2 * n] = force(tt), 2 * Cn @ x[n:2 * n]
            return J

        def energy(x):
            qq, v = x[:n], x[n:2 * n]
            return 0.5 * np.einsum("i...,ij,j...->...", v, Mn, v) + \
                0.5 * np.einsum("i...,ij,j...->...", qq, Kn, qq)

        return rhs, jac, energy, (Mn, Cn, Kn)

    return make


def scene_report(scene):
    """Simulate the example of the paper (Fig. 3) with the consistent model.

    Parameters
    ----------
    scene : crane_sym.scenes.Scene
        SI parameters of the outputs; options ``duration``, ``points``, the
        simulation-only values ``SIM_OPTIONS`` and ``m_L_empty`` (mass of the run
        without loads), with units, and optionally ``method`` of ``solve_ivp``.

    Returns
    -------
    crane_sym.scenes.SceneReport
        ``values`` (SI): ``omega_1``, ``omega_2`` (chain), ``f_loaded_i``,
        ``f_empty_i`` (model frequencies, Hz), ``y_max``, ``y_swing`` (after 1 s),
        ``F1_max``, ``F2_min``, ``v_end``, ``margin_min``, ``running_*``,
        ``rest_y``, ``design_margin``, ``least_mu_alpha``, ``drum_torque``,
        ``energy_error``, ``run_time``; panels: drum-shaft displacement (Fig. 3),
        branch forces, load, speed.
    """
    import time as clock

    import numpy as np
    from scipy.integrate import solve_ivp

    from crane_sym import registry, units
    from crane_sym.scenes import Panel, SceneReport, format_quantity as fq

    d = registry.get(scene.derivation)
    p = dict(scene.parameters)
    p.update({n: units.convert(n, scene.options[n], d.symbols[n].dimension)
              for n in SIM_OPTIONS}, r=p["D"] / 2)
    empty = units.convert("m_L_empty", scene.options["m_L_empty"], mass)

    def ev(expr, **at):
        args = sorted(expr.free_symbols, key=str)
        return sp.lambdify(args, expr, "numpy")(*[({**p, **at})[str(a)] for a in args])

    pulse = d.output("pulsating_force")
    f_pulse = sp.lambdify(pulse.args, pulse.expr, "numpy")
    load = lambda tt: f_pulse(tt, *[p[str(a)] for a in pulse.args[1:]])  # noqa: E731
    make = _rhs_functions(d)
    rhs, jac, energy, (Mn, _, Kn) = make(p, load)

    def hertz(M):
        lam = np.sort(np.linalg.eigvals(np.linalg.solve(M, Kn)).real)
        return np.sqrt(lam[lam > 1e-9 * lam.max()]) / (2 * np.pi)

    f_loaded, f_empty = hertz(Mn), hertz(make({**p, "m_L": empty}, load)[3][0])
    duration, method = scene.options["duration"], scene.options.get("method", "LSODA")
    times = np.linspace(0.0, duration, scene.options["points"])
    implicit = {"jac": jac} if method in ("LSODA", "Radau", "BDF") else {}
    start = clock.perf_counter()
    sol = solve_ivp(rhs, (0.0, duration), np.zeros(12), method=method, t_eval=times,
                    rtol=1e-10, atol=1e-12, **implicit)
    run_time = clock.perf_counter() - start
    if not sol.success:
        raise RuntimeError(f"solve_ivp failed: {sol.message}")
    x = sol.y
    F1_sim = p["F0"] + p["C_t"] * (p["r"] * x[2] - x[3] - x[4])
    F2_sim = p["F0"] + p["C_z"] * (x[4] - x[3] - p["r"] * x[2])
    W_mean = float(np.mean(load(np.linspace(0, 2 * p["t_3"], 2001)[:-1])))
    v = {"omega_1": ev(d.output("drive_chain_frequency_1").expr),
         "omega_2": ev(d.output("drive_chain_frequency_2").expr),
         **{f"f_loaded_{i}": f for i, f in enumerate(f_loaded, 1)},
         **{f"f_empty_{i}": f for i, f in enumerate(f_empty, 1)},
         "y_max": np.max(np.abs(x[3])), "y_swing": np.ptp(x[3][times > 1.0]),
         "F1_max": F1_sim.max(), "F2_min": F2_sim.min(), "v_end": x[9][-1],
         "margin_min": np.min(np.exp(p["mu"] * p["alpha"]) - 1.25 * F1_sim / F2_sim),
         **{f"running_{k}": ev(d.output(n).expr) for k, n in (
             ("F1", "running_tight_force"), ("F2", "running_slack_force"),
             ("y", "running_drum_shaft_deflection"))},
         "running_speed": ev(d.step("steady running").statement.rhs, W=W_mean),
         "rest_y": ev(d.step("initial state").statement.rhs),
         "design_margin": ev(d.output("traction_margin").expr),
         "least_mu_alpha": ev(d.output("least_mu_alpha").expr),
         "drum_torque": ev(d.output("drum_torque").expr),
         "energy_error": np.max(np.abs(x[10] - x[11] - energy(x[:10])))
         / max(np.max(np.abs(x[10])), 1e-300), "run_time": run_time}
    v = {k: float(val) for k, val in v.items()}
    hz = lambda fs: ", ".join(fq(f, "Hz") for f in fs)  # noqa: E731
    mm, kn = (lambda a: fq(a * 1e3, "mm")), (lambda a: fq(a / 1e3, "kN"))  # noqa: E731
    lines = [
        f"drive chain (free-free)  ω1 = {fq(v['omega_1'], 'rad/s')}, "
        f"ω2 = {fq(v['omega_2'], 'rad/s')}",
        f"model frequencies        loaded run ({fq(p['m_L'], 'kg')}): {hz(f_loaded)}",
        f"                         empty run ({fq(empty, 'kg')}): {hz(f_empty)}",
        f"drum-shaft displacement  max |y| = {mm(v['y_max'])} "
        f"({'within' if v['y_max'] <= 0.010 else 'NOT within'} the paper's 10 mm); "
        f"swing after 1 s {mm(v['y_swing'])}",
        f"                         at rest under 2·F0 {mm(v['rest_y'])}; steady running "
        f"{mm(v['running_y'])}",
        f"branch forces            F1 max {kn(v['F1_max'])}, F2 min {kn(v['F2_min'])}; "
        f"running {kn(v['running_F1'])} / {kn(v['running_F2'])}",
        f"traction (19)            margin at the scene's F1, F2 {fq(v['design_margin'])}, "
        f"least along the run {fq(v['margin_min'])}; least μα {fq(v['least_mu_alpha'])}",
        f"run speed                {fq(v['v_end'], 'm/s')} at {fq(duration, 's')}; "
        f"steady (mean load) {fq(v['running_speed'], 'm/s')}",
        f"energy balance           max |work − dissipation − (T + Π)| / work = "
        f"{v['energy_error']:.1e}",
        f"solve_ivp ({method})      {fq(run_time, 's')} for {fq(duration, 's')}",
        "paper, Fig. 3            'frequency rises as the load falls': the load force W(t) "
        "does not change the linear model's frequencies; a lighter run (fewer loads) "
        "raises the lowest one, as listed above",
    ]
    panels = [
        Panel("Drum-shaft displacement (Fig. 3)", "y [mm]", [("y(t)", times, x[3] * 1e3)]),
        Panel("Branch forces", "F [kN]", [("F1 (tight)", times, F1_sim / 1e3),
                                          ("F2 (slack)", times, F2_sim / 1e3)]),
        Panel("Load on the run, (21)", "W [kN]", [("W(t) = F'(t)", times, load(times) / 1e3)]),
        Panel("Speed of the run", "dz/dt [m/s]", [("ż(t)", times, x[9])]),
    ]
    return SceneReport(lines=lines, values=v, panels=panels)
