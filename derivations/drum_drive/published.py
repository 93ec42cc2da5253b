"""Published formulas of paper 004, transcribed as printed.

The LaTeX of each record is copied verbatim from ``004_f118c513e0426caf.txt``; a
display that makes several claims gives one record per claim (labels such as
``(10), Q2`` or ``(12), row 1``), each with the whole display. Ukrainian words
in the prints: "кг" = kg, "м" = m, "мм" = mm, "Нм" = N·m, "кН" = kN, "рад" =
rad, "с" = s, "екв" = equivalent, "T.OP." = тягового органу (traction element).

Notation. The OCR reads the drum index б as σ or δ (M_oσ, m_σ, r_σ, M_oδ) and
the Greek ν of the resistance coefficients as v; here M_oб is the driving torque
M0, m_б the drum's mass m3 and r_б the radius r. Symbols the paper uses but
never defines (φ4, x_i, the y_i, z_i of (8), (11), (12), m1, m2, C3, ν3, C_екв,
ω, ε of (12), ϑ_z) are kept as printed (``PRINT_SYMBOLS``). A Σ is written out
term by term, since the checks do not take a Sum.

The transcriptions keep the print's errors. A ``Convention`` is a reading of the
policy (``crane_sym.published.READINGS``): it is tried only when the literal print
fails, and a reading that does not match is kept in the record as well, to show
that the print's error is more than the lost mark.

Basis. Fig. 1 (the design scheme) is lost, so the model's pairing of coordinates
and the directions of the branch forces are reconstructed (``MODEL``): a record
measured against them has the basis ``reconstructed model``. A record decided by
dimensions or by the paper's own earlier line is ``internal``; one whose derived
step restates the print (a definition, a hypothesis adopted, a textbook form) is
``definition`` and can only be ``restated``, never confirmed. Every finding has a
``Cause`` (``CAUSES``); records that fail for the same reason share one.
"""
from __future__ import annotations

import sympy as sp
from sympy.physics.units import energy, force, length, mass, time, velocity

from .model import (
    C1, C2, C_t, C_y, C_z, D, F1, F1_lim, F2, I1, I2, I3, L, M0, M_d, ONE, PAPER, Phi_, Pi_,
    ROT_DAMP, STIFF, T_, T_el, TORQUE, a_v, alpha, b_v, g, m3, m_sum, mu, mu_op, nu1, nu2,
    nu_t, nu_y, nu_z, phi1, phi2, phi3, q, r, t, v_xi, vy, vz, xi, y, y0, z, F_pulse, F1_t,
    F2_t, F3_t, F4_t, K1, K2, K3, K4, t_3)
from crane_sym.published import (
    ASSUMPTION, DEFINITION, INTERNAL, LOST_MARK, RECONSTRUCTED, SYMBOL_FOR_ANOTHER, Cause,
    Convention, PublishedFormula, printed)
from crane_sym.symbols import COORDINATE, DEFINED, PARAMETER, PhysicalSymbol

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

# --- Why the findings are findings (one Cause per reason) ---------------------------
FIG1 = ("Fig. 1 is lost: the coordinates and the directions of the branch forces are "
        "reconstructed (MODEL: both branches leave the drum toward the line)")
C_COORDINATES = Cause(
    "004-1-three-coordinates",
    "(1) has Lagrange equations for three coordinates φ, z, y only, while the paper's own "
    "T (2), Π (8) and Φ (11) depend on three separate angles φ1, φ2, φ3 besides y and z, "
    "so they need at least five.")
C_RAYLEIGH_DOT = Cause(
    "004-1-rayleigh-dot",
    "(1) prints the Rayleigh term as ∂Φ/∂q, which is zero for a Φ of velocities; read "
    "with the dot lost from q, ∂Φ/∂q̇, it is Lagrange's equation with dissipation.")
C_KINETIC = Cause(
    "004-2-undefined-translations",
    "(2) gives the masses m_i translations ẋ_i that the paper never defines and counts "
    "the drum's mass twice (in Σ m_i·ẋ_i² and in ½·m3·(ẏ − r·φ̇3)²), where the "
    "reconstructed drive moves the drum by ẏ alone and the loaded run by ż.")
C_MOMENTUM = Cause(
    "004-3-speed-not-squared",
    "(3) writes the kinetic energy of a piece dm as dm/2 times a speed, the root "
    "√(ż² + ẏ²) (with dy/dt² printed for (dy/dt)²) and dl/dt, not times its square, so "
    "both members are a momentum [kg·m/s], not an energy.")
C_ROOT = Cause(
    "004-7-velocity-in-root",
    "(7) multiplies every integrand by √(1 + ẏ²) or √(1 + ż²), a number plus a squared "
    "speed; with the dots the numerators lost (q·ẏ², q·ż² for q·y², q·z²) it is the "
    "derived (7) times these roots, which would be 1 only as the arc-length factor "
    "√(1 + slope²) of a flat span, a slope and not a velocity.")
C_VELOCITY_POTENTIAL = Cause(
    "004-8-velocities-in-potential",
    "(8) builds the potential energy from velocity differences (φ̇_i − φ̇_(i+1), "
    "ẏ1 − ẏ2, ż1 − ż2, φ̇3·r − ż) where the shafts' twists and the branches' stretches "
    "belong, so every elastic term is in J/s², not J.")
C_NOTHING = Cause(
    "004-only-a-definition",
    "The display only defines a symbol (Q_i = δA/δq_i in (9), y = y(x, t) in (15)), so "
    "it states no relation to check; what (9) defines is checked in the δA lines after "
    "it and in (10).")
C_CONTINUUM = Cause(
    "004-16-continuum-not-stated",
    "(16) sets z = ϑ_z·t for the continuum model (17) of the drum's axis, which the paper "
    "does not derive, with ϑ_z not defined, so the lumped model has nothing to compare "
    "it with.")
C_ARM = Cause(
    "004-dA1-weight-without-arm",
    "(9)'s δA_1 = (M_oб − m_б·g)·δφ subtracts the drum's weight [N] from a torque "
    "[N·m]; (10) writes the same term m_б·g·r_б, so the two lines disagree by the arm "
    "r_б.")
C_DRUM_PULL = Cause(
    "004-y-force-difference",
    "For the drum's displacement y the print takes F1 − F2, but with both branches "
    "leaving the drum toward the line (as reconstructed) both pull the drum the same "
    "way, and the force is F1 + F2.")
C_RUN_FORCE = Cause(
    "004-z-force",
    "For the run's displacement z the print has no F1 − F2 against the load resistance "
    "W: its δz line after (9) has the drum's weight m3·g, (10)'s Q2 the sum F1 + F2, and "
    "both subtract C_z·z, which the branch force F2 already holds.")
C_Q1_MOMENT = Cause(
    "004-10-Q1-weight-moment",
    "(10)'s Q1 = M_oб − m_б·g·r_б gives the drum's weight a moment about the drum's own "
    "axis, where it has none, and leaves out the moment −(F1 − F2)·r of the branch "
    "forces on the drum.")
C_Q2_NOT_FROM_9 = Cause(
    "004-10-Q2-not-from-9",
    "(10)'s Q2 = (F1 + F2) − C_z·z does not repeat the δz line after (9) it is said to "
    "follow from ('Отже'), which gives m3·g − C_z·z.")
C_UNDEFINED_RATES = Cause(
    "004-11-undefined-coordinates",
    "(11) uses φ4, y1, y2, z1, z2, which the paper never defines; read as φ3 (no fourth "
    "body), the drum's y and the slack branch's stretch z − y − r·φ3, it is the "
    "reconstructed Φ.")
C_MIXED_12 = Cause(
    "004-12-mixed-dimensions",
    "(12) puts the torsional stiffnesses C_i on acceleration differences in every row (and "
    "the torsional ν_i on linear velocities in the z and y rows, the masses m_i on "
    "angular accelerations in the φ row), so no row has terms of one dimension.")
C_STIFFNESS_ON_VELOCITY = Cause(
    "004-13-stiffness-on-velocity",
    "(13), said to neglect dissipation, has C_3·ẏ, the drum's stiffness times a "
    "velocity, beside ÿ [m/s²]; no stiffness makes that term an acceleration.")
C_K_THREE_MASSES = Cause(
    "004-13-k-three-masses",
    "(13)'s k = √(C_екв·(m1 + m2 + m3)/(m1·m2·m3)) is in 1/(kg^½·s) for any stiffness "
    "C_екв: the two-mass formula √(C·(m1 + m2)/(m1·m2)) extended to three masses keeps "
    "one mass too many in the denominator.")
C_DROPS_C3 = Cause(
    "004-14-drops-C3",
    "The homogeneous equation after (14), ÿ1 + k²·y1 = 0, drops the C_3·ẏ term of the "
    "(13) it claims to solve.")
C_BARE_SECOND = Cause(
    "004-17-bare-second-derivative",
    "(17) adds ∂²y/∂x² [1/m] to ∂⁴y/∂x⁴ [1/m³] without a coefficient, so no choice of "
    "the unstated a and b makes it consistent.")
C_SAFETY = Cause(
    "004-19-safety-factor",
    "(19) is Euler's traction limit F1 ≤ F2·e^(μα) with an unnamed safety factor 1.25 "
    "on F1, and it calls μ the element's resistance coefficient though it is the "
    "friction coefficient on the drum.")
C_TRACTION_F1 = Cause(
    "004-20-traction-named-F1",
    "(20) equates the tight-branch force F1 of (18)–(19) with the loads' resistance "
    "Σ m_i·g·μ_оп, while the run's steady balance gives F1 − F2 = Σ m_i·g·μ_оп + "
    "ν_t·v_s: the print's F1 is the traction force, without the element's running "
    "resistance ν_t·ż of (11).")
C_ZERO_STATE = Cause(
    "004-zero-state-not-at-rest",
    "The example starts from y(0) = 0, but the pretension F0 of both branches pulls the "
    "drum toward the line, so the reconstructed drive rests with its shaft deflected by "
    "2·F0·(C_t + C_z)/(C_t·C_y + 4·C_t·C_z + C_y·C_z) and the zero state is not at "
    "rest.")
#: Every cause of paper 004, by id.
CAUSES = {c.id: c for c in (
    C_COORDINATES, C_RAYLEIGH_DOT, C_KINETIC, C_MOMENTUM, C_ROOT, C_VELOCITY_POTENTIAL,
    C_NOTHING, C_CONTINUUM, C_ARM, C_DRUM_PULL, C_RUN_FORCE, C_Q1_MOMENT, C_Q2_NOT_FROM_9,
    C_UNDEFINED_RATES, C_MIXED_12, C_STIFFNESS_ON_VELOCITY, C_K_THREE_MASSES, C_DROPS_C3,
    C_BARE_SECOND, C_SAFETY, C_TRACTION_F1, C_ZERO_STATE)}

# --- The displays, verbatim --------------------------------------------------------
L1 = (r"\left. \begin{aligned} \frac{d}{dt} \left(\frac{\partial T}{\partial \dot{\varphi}} "
       r"\right) - \frac{\partial T}{\partial \varphi} + \frac{\partial \Pi}{\partial "
       r"\varphi} &= Q_1 - \frac{\partial \Phi}{\partial \varphi} \\ \frac{d}{dt} "
       r"\left(\frac{\partial T}{\partial \dot{z}} \right) - \frac{\partial T}{\partial z} + "
       r"\frac{\partial \Pi}{\partial z} &= Q_2 - \frac{\partial \Phi}{\partial z} \\ "
       r"\frac{d}{dt} \left(\frac{\partial T}{\partial \dot{y}} \right) - \frac{\partial "
       r"T}{\partial y} + \frac{\partial \Pi}{\partial y} &= Q_3 - \frac{\partial "
       r"\Phi}{\partial y} \end{aligned} \right\}, \quad (1)")
L2 = (r"T = \frac{1}{2} \sum_{i=1}^3 (I_i \cdot \dot{\varphi}_i^2 + m_i \cdot \dot{x}_i^2) "
       r"+ \frac{1}{2} m_3 (\dot{y} - r \dot{\varphi}_3)^2 + T_{T.OP.}, \quad (2)")
L3 = (r"dT_{T.OP.} = \frac{dm}{2} \sqrt{\left(\frac{dz}{dt} \right)^2 + \frac{dy}{dt^2}} = "
       r"\frac{dm dl}{2 dt}. \quad (3)")
L4 = r"dm = q \cdot dl. \quad (4)"
L5 = r"v_{(z)} = \frac{dl}{dt}. \quad (5)"
L6 = r"v_{\xi} = a + b \cdot \xi. \quad (6)"
L7 = (r"\begin{aligned} T_{T.OP.} &= \int_0^{z(t)} \frac{qy^2}{2z^2} \cdot \xi^2 \sqrt{1 + "
       r"(\dot{y})^2} d\xi + \int_{z(t)}^L \frac{qy^2}{2(z-L)^2} \cdot (\xi-L)^2 \times \\ "
       r"&\times \sqrt{1 + (\dot{y})^2} d\xi + \int_0^{y(t)} \frac{qz^2}{2y^2} \cdot (\xi "
       r"\cdot \operatorname{tg} \varphi)^2 \sqrt{1 + (\dot{z})^2} d(\xi \cdot "
       r"\operatorname{tg} \varphi) + \\ &+ \int_{y(t)}^{\delta y} \frac{qz^2}{2(y-\delta "
       r"y)^2} \cdot (\xi \cdot \operatorname{tg} \varphi - \delta y)^2 \sqrt{1 + "
       r"(\dot{z})^2} d(\xi \cdot \operatorname{tg} \varphi), \end{aligned} \quad (7)")
L8 = (r"\Pi = \frac{1}{2} \sum_{i=1}^3 C_i (\dot{\varphi}_i - \dot{\varphi}_{(i+1)})^2 + "
       r"\frac{1}{2} C_y (\dot{y}_1 - \dot{y}_2)^2 + \frac{1}{2} C_z (\dot{z}_1 - "
       r"\dot{z}_2)^2 + \frac{1}{2} C_t (\dot{\varphi}_3 \cdot r_\sigma - \dot{z})^2, \quad "
       r"(8)")
L9 = (r"Q_1 = \frac{\delta A_\varphi}{\delta \varphi}; Q_2 = \frac{\delta A_{Fz}}{\delta "
       r"z}; Q_3 = \frac{\delta A_{Fy}}{\delta y}, \quad (9)")
L9b = (r"\begin{aligned} \delta \varphi > 0; y = const; z = const; & \quad \delta A_1 = "
       r"(M_{o\sigma} - m_\sigma g) \delta \varphi; \\ \delta y > 0; \varphi = const; y = "
       r"const; & \quad \delta A_2 = (F_1 - F_2 - C_y y) \delta y; \\ \delta z > 0; \varphi "
       r"= const; y = const; & \quad \delta A_3 = (m_3 \cdot g - C_z z) \delta z. "
       r"\end{aligned}")
L10 = (r"\left. \begin{aligned} Q_1 &= M_{o\sigma} - m_\sigma \cdot g \cdot r_\sigma; \\ Q_2 "
       r"&= (F_1 + F_2) - C_z z; \\ Q_3 &= (F_1 - F_2) - C_y y. \end{aligned} \right\} \quad "
       r"(10)")
L11 = (r"\Phi = \frac{1}{2} \sum_{i=1}^3 v_i (\dot{\varphi}_i - \dot{\varphi}_{(i+1)})^2 + "
       r"\frac{1}{2} v_y (\dot{y}_1 - \dot{y}_2)^2 + \frac{1}{2} v_z (\dot{z}_1 - "
       r"\dot{z}_2)^2 + \frac{1}{2} v_t \dot{z}^2, \quad (11)")
L12 = (r"\left. \begin{aligned} \sum_{i=1}^3 [(m_i \cdot \ddot{\varphi}_i - m_i \cdot "
       r"\ddot{y}_i) + C_i (\ddot{\varphi}_i - \ddot{\varphi}_{(i+1)})] - m_3 \ddot{y} + "
       r"\sum_{i=1}^3 v_i (\dot{\varphi}_i - \dot{\varphi}_{(i+1)}) &= \frac{M_{o\sigma}}{r} "
       r"- m_3 g; \\ \sum_{i=1}^3 [(m_i \cdot \ddot{z}_i) + C_i (\ddot{z}_i - "
       r"\ddot{z}_{(i+1)})] - m_3 \ddot{z} + \sum_{i=1}^3 v_i (\dot{z}_i - \dot{z}_{(i+1)}) "
       r"&= -(F_1 + F_2) \cdot \sin(\omega t + \varepsilon); \\ \sum_{i=1}^3 [(m_i \cdot "
       r"\ddot{y}_i) + C_i (\ddot{y}_i - \ddot{y}_{(i+1)})] + \sum_{i=1}^3 v_i (\dot{y}_i - "
       r"\dot{y}_{(i+1)}) &= (F_1 - F_2) \cdot \sin(\omega t + \varepsilon). \end{aligned} "
       r"\right\} \quad (12)")
L13 = r"\ddot{y} + C_3 \dot{y} + k^2 y = \frac{M_{o\sigma}}{m_3 r} + g, \quad (13)"
L14 = r"y = y_1 + y_2, \quad (14)"
L14b = r"\ddot{y}_1 + k^2 \cdot y_1 = 0; \quad y_1 = A \cdot \sin(kt + a);"
L15 = r"y = y(x, t). \quad (15)"
L16 = r"z = \vartheta_z \cdot t. \quad (16)"
L17 = (r"\frac{\partial^4 y}{\partial x^4} + a \frac{\partial^2 y}{\partial t^2} + b "
       r"\frac{\partial^2 y}{\partial x \cdot \partial t} + \frac{\partial^2 y}{\partial "
       r"x^2} = 0. \quad (17)")
L18 = r"M_{o\delta} = (F_1 - F_2) \cdot \frac{D}{2}. \quad (18)"
L19 = r"1.25 \frac{F_1}{F_2} < e^{\mu\alpha}, \quad (19)"
L20 = r"F_1 = F_i(t) = \sum_{i=1}^m m_i(t) \cdot g \cdot \mu_{on}, \quad (20)"
L21 = (r"F'(t) = \frac{F_1(t) \cdot \sin\left(\frac{\pi t}{t_3}\right) + K_1 - \left| F_2(t) "
       r"\cdot \sin\left(\frac{\pi t}{t_3}\right) - K_2 \right|}{4} + \frac{F_3(t) \cdot "
       r"\sin\left(\frac{\pi t}{t_3}\right) + K_3 - \left| F_4(t) \cdot \sin\left(\frac{\pi "
       r"t}{t_3}\right) - K_4 \right|}{4}, \quad (21)")
LEX1 = (r"I_1 = 13 \text{ кг} \cdot \text{м}^2; I_2 = 3 \text{ кг} \cdot \text{м}^2; I_3 = 50 "
       r"\text{ кг} \cdot \text{м}^2; M_0 = 440 \text{ Нм}; D_0 = 500 \text{ мм};")
LEX2 = (r"C_1 = 20 \text{ кН} / \text{рад}; C_2 = 50 \text{ кН} / \text{рад}; F_2 = 20 \text{ "
       r"кН}; t_3 = 3 \text{ с}; t_i = 10 \text{ с}.")
LINIT = (r"z(0) = 0; y(0) = 0; \varphi(0) = 0; \dot{z}(0) = 0; \dot{y}(0) = 0; "
       r"\dot{\varphi}(0) = 0.")
LK = r"k = \sqrt{C_{екв} \cdot \frac{m_1 + m_2 + m_3}{m_1 \cdot m_2 \cdot m_3}}"


def _printed(label: str, latex: str, relation: sp.Eq | None, note: str = "",
             **kwargs) -> PublishedFormula:
    return printed(PAPER, label, latex, relation, note, **kwargs)


def _dot(f: sp.Expr, n: int = 1) -> sp.Expr:
    return f.diff(t, n)


def printed_virtual_work() -> list[tuple[str, sp.Symbol, sp.Expr]]:
    """The print's δA lines after (9), each divided by its virtual displacement
    and named by (1)'s pairing (Q1: φ, Q2: z, Q3: y): what (10) should repeat."""
    return [("(9) ⇒ Q1, as printed", Q1, M0 - m3 * g),
            ("(9) ⇒ Q2, as printed", Q2, m3 * g - C_z * z),
            ("(9) ⇒ Q3, as printed", Q3, F1 - F2 - C_y * y)]


def printed_homogeneous() -> tuple[str, sp.Eq]:
    """The print's (13) with its right-hand side set to zero: what (14) solves."""
    return ("(13) as printed, homogeneous",
            sp.Eq(_dot(y_h, 2) + C3 * _dot(y_h) + k**2 * y_h, 0))


def _chain(f: list, coeffs: list) -> sp.Expr:
    """Σ_{i=1}^{3} c_i (f_i − f_{i+1}) written out."""
    return sp.Add(*[c * (f[i] - f[i + 1]) for i, c in enumerate(coeffs)])


def _sum(terms) -> sp.Expr:
    return sp.Add(*terms)


LAGRANGE_FORM = (
    "(1) restates Lagrange's equations of the second kind with Rayleigh's function, a "
    "textbook form; both sides are built from the model's T, Π, Φ (the printed operator "
    "on one, the toolkit's Lagrange equations on the other), so the record tests only the printed "
    "operator, not the paper's energies")


def _lagrange_rows(e: dict) -> list[PublishedFormula]:
    T, V, R = e["T"], e["Pi"], e["Phi"]
    rows = []
    for label, qq, Q in (("(1), φ", phi3, Q1), ("(1), z", z, Q2), ("(1), y", y, Q3)):
        lhs = sp.expand(sp.diff(sp.diff(T, _dot(qq)), t) - sp.diff(T, qq) + sp.diff(V, qq))
        rows.append(_printed(
            label, L1, sp.Eq(lhs, Q - sp.diff(R, qq)),
            "the printed operator applied to the model's T, Π, Φ of (2)–(11); the "
            "Rayleigh term is printed as ∂Φ/∂q, which is 0 since Φ has velocities only"
            + ("; φ stands for each angle and is checked for the drum's φ3" if qq is phi3
               else ""),
            conventions=(Convention(
                "∂Φ/∂q in (1) means ∂Φ/∂q̇ (the Rayleigh term)",
                sp.Eq(lhs, Q - sp.diff(R, _dot(qq))), LOST_MARK),),
            basis=DEFINITION, basis_note=LAGRANGE_FORM, cause=C_RAYLEIGH_DOT))
    return rows


DIMENSIONS = "the verdict rests on the dimensions of the print's own terms"


def _energy_rows(e: dict) -> list[PublishedFormula]:
    half = sp.Rational(1, 2)
    inertias, masses = (I1, I2, I3), (m1, m2, m3)
    T2 = (half * _sum(I * _dot(p)**2 + m * _dot(x)**2 for I, p, m, x in
                      zip(inertias, (phi1, phi2, phi3), masses, xs))
          + half * m3 * (_dot(y) - r * _dot(phi3))**2 + T_el)
    # (7) as printed; the last two integrals run over s = ξ·tg φ, the variable
    # after d(...), so their limits are values of s.
    ry, rz = sp.sqrt(1 + _dot(y)**2), sp.sqrt(1 + _dot(z)**2)
    seven = (sp.Integral(q * y**2 / (2 * z**2) * xi**2 * ry, (xi, 0, z))
             + sp.Integral(q * y**2 / (2 * (z - L)**2) * (xi - L)**2 * ry, (xi, z, L))
             + sp.Integral(q * z**2 / (2 * y**2) * s_tg**2 * rz, (s_tg, 0, y))
             + sp.Integral(q * z**2 / (2 * (y - delta_y)**2) * (s_tg - delta_y)**2 * rz,
                           (s_tg, y, delta_y)))
    phis = [phi1, phi2, phi3, phi4]
    dotted = seven.xreplace({y**2: _dot(y)**2, z**2: _dot(z)**2})
    eight = (half * _sum(C * (_dot(phis[i]) - _dot(phis[i + 1]))**2
                         for i, C in enumerate((C1, C2, C3)))
             + half * C_y * (_dot(yp[0]) - _dot(yp[1]))**2
             + half * C_z * (_dot(zp[0]) - _dot(zp[1]))**2
             + half * C_t * (_dot(phi3) * r - _dot(z))**2)
    return [
        _printed("(2)", L2, sp.Eq(T_, T2),
                 "x_i are not defined; m3 is the drum's mass (I_i belong to m_i), so the "
                 "drum's mass enters twice, once with ẏ − r·φ̇3",
                 basis=RECONSTRUCTED, basis_note=FIG1 + "; the derived T moves the drum by "
                 "ẏ and the loaded run (mass m_L) by ż", cause=C_KINETIC),
        _printed("(3)", L3, sp.Eq(dT, dm / 2 * sp.sqrt(_dot(z)**2 + dy / dt**2)),
                 "first member; dy/dt² is printed, not (dy/dt)², and the root gives the "
                 "speed, not its square: the lost bracket alone does not make it an energy",
                 conventions=(Convention(
                     "(dy/dt)² for the printed dy/dt² (a bracket lost)",
                     sp.Eq(dT, dm / 2 * sp.sqrt(_dot(z)**2 + _dot(y)**2)), LOST_MARK),),
                 basis=INTERNAL, basis_note=DIMENSIONS, cause=C_MOMENTUM),
        _printed("(3), second member", L3, sp.Eq(dT, dm * dl / (2 * dt)),
                 "the last member, dm·dl/(2·dt) = dm·v/2 by (5): half a momentum",
                 compare_to="(3)", basis=INTERNAL, basis_note=DIMENSIONS, cause=C_MOMENTUM),
        _printed("(4)", L4, sp.Eq(dm, q * dl), basis=DEFINITION,
                 basis_note="the definition of q (mass per metre), restated by step (4)"),
        _printed("(5)", L5, sp.Eq(v_z, dl / dt), basis=DEFINITION,
                 basis_note="the definition of the element's speed, restated by step (5)"),
        _printed("(6)", L6, sp.Eq(v_xi, a_v + b_v * xi),
                 "the hypothesis of a linear speed distribution", kind=ASSUMPTION,
                 stated='"За гіпотезою про лінійний розподіл швидкостей тягового '
                 'органу" ("by the hypothesis of a linear distribution of the speeds"), '
                 'before (6)',
                 basis=DEFINITION, basis_note="the paper's hypothesis, adopted as printed "
                 "by step (6); what it implies is checked in (7)"),
        _printed("(7)", L7, sp.Eq(T_el, seven),
                 "the four integrals as printed, the last two over s = ξ·tg φ; the × and + "
                 "repeated at the line breaks are read once, as the typesetting repeats "
                 "them; the numerators are printed q·y², q·z² (displacements, where (3) "
                 "needs ẏ², ż²) and the root holds a velocity, √(1 + ẏ²). The lost dots "
                 "(a reading) do not suffice: the print is then the derived (7) times "
                 "√(1 + ẏ²) or √(1 + ż²), and taking the root as 1 is the model's flat "
                 "span, not a reading of the print",
                 conventions=(Convention(
                     "q·ẏ², q·ż² for the printed q·y², q·z² (dots lost)",
                     sp.Eq(T_el, dotted), LOST_MARK),),
                 basis=INTERNAL, basis_note=DIMENSIONS, cause=C_ROOT),
        _printed("(8)", L8, sp.Eq(Pi_, eight),
                 "Σ written out (i = 3 needs an undefined φ4); every elastic term has "
                 "velocities where displacements belong, so each carries an extra 1/s² "
                 "against Π; r_σ = r. No reading of the policy removes a dot printed "
                 "too many, and even without the dots and with (11)'s reading of φ4, y_i, "
                 "z_i the tight branch's (φ3·r − z) lacks the drum's y",
                 basis=INTERNAL, basis_note=DIMENSIONS, cause=C_VELOCITY_POTENTIAL),
    ]


def _force_rows() -> list[PublishedFormula]:
    from_nine = {lab.split(" ⇒ ")[1].split(",")[0]: lab for lab, _, _ in printed_virtual_work()}
    rows = [
        _printed("(9)", L9, None, not_checkable=(
            "definitions Q = δA/δq of the generalized forces (right as definitions); they "
            "pair Q2 with z and Q3 with y, while the lines that follow compute δA_2 for δy "
            "and δA_3 for δz"), basis=DEFINITION,
            basis_note="Q_i = δA_i/δq_i is the definition of a generalized force",
            cause=C_NOTHING),
        _printed("(9), δA_1", L9b, sp.Eq(dA1, (M0 - m3 * g) * vphi),
                 "first line after (9); m_σ (drum mass) read as m3",
                 basis=INTERNAL, basis_note=DIMENSIONS, cause=C_ARM),
        _printed("(9), δA_2", L9b, sp.Eq(dA2, (F1 - F2 - C_y * y) * vy),
                 "second line; its condition 'y = const' must mean z = const",
                 basis=RECONSTRUCTED, basis_note=FIG1, cause=C_DRUM_PULL),
        _printed("(9), δA_3", L9b, sp.Eq(dA3, (m3 * g - C_z * z) * vz),
                 "third line; C_y·y and C_z·z also stand in Π (8), so they count twice",
                 basis=RECONSTRUCTED, basis_note=FIG1, cause=C_RUN_FORCE),
    ]
    printed_q = {"Q1": (Q1, M0 - m3 * g * r), "Q2": (Q2, (F1 + F2) - C_z * z),
                 "Q3": (Q3, (F1 - F2) - C_y * y)}
    against_model = {"Q1": C_Q1_MOMENT, "Q2": C_RUN_FORCE, "Q3": C_DRUM_PULL}
    against_nine = {"Q1": C_ARM, "Q2": C_Q2_NOT_FROM_9, "Q3": None}
    for name, (sym, rhs) in printed_q.items():
        rows.append(_printed(f"(10), {name}", L10, sp.Eq(sym, rhs),
                             "against the model: the force of all given forces for the "
                             "coordinate (1) pairs with " + {"Q1": "φ", "Q2": "z",
                                                              "Q3": "y"}[name],
                             basis=RECONSTRUCTED, basis_note=FIG1,
                             cause=against_model[name]))
    for name, (sym, rhs) in printed_q.items():
        rows.append(_printed(f"(10), {name} vs (9)", L10, sp.Eq(sym, rhs),
                             "against the print's own δA line before it",
                             compare_to=from_nine[name], basis=INTERNAL,
                             basis_note="(10) against the print's own δA line after (9), "
                             "divided by its virtual displacement (step "
                             f"'{from_nine[name]}')", cause=against_nine[name]))
    return rows


def _motion_rows(e: dict) -> list[PublishedFormula]:
    half = sp.Rational(1, 2)
    phis = [phi1, phi2, phi3, phi4]
    nus, Cs, ms = [nu1, nu2, nu3], [C1, C2, C3], [m1, m2, m3]
    eleven = (half * _sum(n * (_dot(phis[i]) - _dot(phis[i + 1]))**2 for i, n in enumerate(nus))
              + half * nu_y * (_dot(yp[0]) - _dot(yp[1]))**2
              + half * nu_z * (_dot(zp[0]) - _dot(zp[1]))**2 + half * nu_t * _dot(z)**2)
    read = (half * _sum(n * (_dot(p) - _dot(p2))**2 for n, p, p2 in
                        zip(nus, (phi1, phi2, phi3), (phi2, phi3, phi3)))
            + half * nu_y * _dot(y)**2 + half * nu_z * _dot(e["e2"])**2
            + half * nu_t * _dot(z)**2)
    acc = [_dot(p, 2) for p in phis]
    row1 = sp.Eq(_sum(ms[i] * acc[i] - ms[i] * _dot(yp[i], 2) for i in range(3))
                 + _chain(acc, Cs) - m3 * _dot(y, 2) + _chain([_dot(p) for p in phis], nus),
                 M0 / r - m3 * g)
    forcing = sp.sin(omega_f * t + eps)
    row2 = sp.Eq(_sum(ms[i] * _dot(zp[i], 2) for i in range(3))
                 + _chain([_dot(f, 2) for f in zp], Cs) - m3 * _dot(z, 2)
                 + _chain([_dot(f) for f in zp], nus), -(F1 + F2) * forcing)
    row3 = sp.Eq(_sum(ms[i] * _dot(yp[i], 2) for i in range(3))
                 + _chain([_dot(f, 2) for f in yp], Cs)
                 + _chain([_dot(f) for f in yp], nus), (F1 - F2) * forcing)
    note = ("Σ written out; ν printed as v; m_i multiply angular accelerations and C_i "
            "accelerations; the y_i, z_i (i ≤ 4), φ4, ω, ε are not defined")
    return [
        _printed("(11)", L11, sp.Eq(Phi_, eleven), "Σ written out; ν printed as v",
                 conventions=(Convention(
                     "φ4 ≡ φ3 (no fourth body), y1 − y2 ≡ y (the drum against its "
                     "bearing), z1 − z2 ≡ the slack branch's stretch z − y − r·φ3",
                     sp.Eq(Phi_, read), SYMBOL_FOR_ANOTHER),),
                 basis=RECONSTRUCTED, basis_note=FIG1 + "; the reading gives the undefined "
                 "φ4, y1 − y2, z1 − z2 the meaning they have in that reconstruction",
                 cause=C_UNDEFINED_RATES),
        *[_printed(f"(12), row {i}", L12, row, note + what, compare_to=target,
                   basis=INTERNAL, basis_note=DIMENSIONS, cause=C_MIXED_12)
          for i, row, what, target in (
              (1, row1, "; the row for φ, checked against the drum's equation", "(12), φ3"),
              (2, row2, "; the row for z", "(12), z"), (3, row3, "; the row for y", "(12), y"))],
    ]


def _bracket(Fa, Ka, Fb, Kb) -> sp.Expr:
    """One bracket of (21): (Fa·sin + Ka − |Fb·sin − Kb|)/4, |X| written out."""
    x = Fb * sp.sin(sp.pi * t / t_3) - Kb
    return (Fa * sp.sin(sp.pi * t / t_3) + Ka - sp.Piecewise((x, x >= 0), (-x, True))) / 4


def _late_rows() -> list[PublishedFormula]:
    return [
        _printed("(13)", L13, sp.Eq(_dot(y, 2) + C3 * _dot(y) + k**2 * y, M0 / (m3 * r) + g),
                 "said to neglect dissipation, yet C3 (called the drum's stiffness) "
                 "multiplies ẏ", basis=INTERNAL, basis_note=DIMENSIONS + " (the derived "
                 "step is the model's y equation, which the print does not match either)",
                 cause=C_STIFFNESS_ON_VELOCITY),
        _printed("(13), k", LK, sp.Eq(k, sp.sqrt(C_ekv * (m1 + m2 + m3) / (m1 * m2 * m3))),
                 "the 'where' clause of (13)", basis=INTERNAL,
                 basis_note=DIMENSIONS + ", whatever the stiffness C_екв; the derived step "
                 "(13), k is chosen to have the printed shape (the geometric mean of the "
                 "drive chain's two frequencies) and is no evidence either way",
                 cause=C_K_THREE_MASSES),
        _printed("(14)", L14, sp.Eq(y, y_h + y_p), "y_1, y_2 of (14) are y_h, y_p here",
                 read_as="the print's y_1, y_2 in (14) are the homogeneous and the particular "
                 "solution (y_h, y_p), not the coordinates y_1, y_2 of (12)",
                 basis=DEFINITION, basis_note="y = y1 + y2 names the homogeneous and the "
                 "particular solution; step (14) restates it"),
        _printed("(14), homogeneous equation", L14b,
                 sp.Eq(_dot(y_h, 2) + k**2 * y_h, 0),
                 "first member of the line after (14): the homogeneous equation of (13) "
                 "as the print states it", compare_to="(13) as printed, homogeneous",
                 basis=INTERNAL, basis_note="the print's own (13) with its right-hand side "
                 "set to zero", cause=C_DROPS_C3),
        _printed("(14), y1", L14b, sp.Eq(y_h, A_y * sp.sin(k * t + a_ph)),
                 "second member; A is the amplitude, a the initial phase", basis=INTERNAL,
                 basis_note="the general solution (dsolve) of the print's own homogeneous "
                 "equation ÿ1 + k²·y1 = 0, not of the model"),
        _printed("(15)", L15, None, not_checkable=(
            "notation: the drum's bent axis is a function y(x, t); nothing to check"),
            basis=DEFINITION, basis_note="notation for the deflection of the drum's axis",
            cause=C_NOTHING),
        _printed("(16)", L16, None, not_checkable=(
            "a kinematic assumption for (17), z = ϑ_z·t: the element's position moves "
            "uniformly; its z is not the lumped model's coordinate and ϑ_z is not "
            "defined"), cause=C_CONTINUUM),
        _printed("(17)", L17, sp.Eq(w.diff(x_ax, 4) + a17 * w.diff(t, 2)
                                    + b17 * w.diff(x_ax, t) + w.diff(x_ax, 2), 0),
                 "y(x, t) written w; a and b are not given, so they get the dimensions "
                 "that fit the first term; ∂²y/∂x² has no coefficient",
                 basis=INTERNAL, basis_note=DIMENSIONS, cause=C_BARE_SECOND),
        _printed("(18)", L18, sp.Eq(M_d, (F1 - F2) * D / 2), "M_oδ is the drum torque"),
        _printed("(19)", L19, sp.Eq(sp.Rational(5, 4) * F1_lim / F2, sp.exp(mu * alpha)),
                 "the boundary of the printed inequality, F1 at its largest value F1_lim; "
                 "1.25 is a traction safety factor the text does not name, and μ is called "
                 "the element's resistance coefficient though it is its friction on the drum",
                 kind=ASSUMPTION, stated='"При виборі натягу тягово-несучого елемента '
                 'необхідно задовольнити умову [1]" ("choosing the tension, the condition '
                 '[1] must be met"), before (19)', cause=C_SAFETY),
        _printed("(20)", L20, sp.Eq(F1, m_sum * g * mu_op),
                 "Σ m_i(t) written m_sum; the print calls F1 the traction force, while "
                 "(18)–(19) use it as the tight branch's force",
                 conventions=(Convention(
                     "F1 in (20) is the traction force F1 − F2 (one name for two forces)",
                     sp.Eq(F1 - F2, m_sum * g * mu_op), SYMBOL_FOR_ANOTHER),),
                 basis=RECONSTRUCTED, basis_note=FIG1 + "; the derived F1 is the run's "
                 "equation (12) in steady running, with the running resistance ν_t·ż of "
                 "(11)", cause=C_TRACTION_F1),
        _printed("(21)", L21, sp.Eq(F_pulse, _bracket(F1_t, K1, F2_t, K2)
                                    + _bracket(F3_t, K3, F4_t, K4)),
                 "an empirical load model, adopted by the model as step (21); |X| is written "
                 "as its definition, X for X ≥ 0 and −X otherwise, since the dimension "
                 "check does not take Abs; with F2 = F1, K2 = K1, F4 = F3, K4 = K3 it is "
                 "½·min(F1·sin, K1) + ½·min(F3·sin, K3), negative for half of each period "
                 "2·t3 (step '(21), min form')", kind=ASSUMPTION, basis=DEFINITION,
                 stated='"Дискретну пульсуючу силу можна подати у вигляді [9]" ("the '
                 'discrete pulsing force can be written as [9]"), before (21)',
                 basis_note="an empirical load model, adopted as printed by step (21); "
                 "what it implies is shown by step '(21), min form'"),
        _printed("initial state", LINIT, sp.Eq(y0, 0, evaluate=False),
                 "the zero initial state of the example; y(0) = 0 is checked",
                 kind=ASSUMPTION, stated='"Як початкові умови прийнято: z(0) = 0; y(0) = '
                 '0; φ(0) = 0; ..." ("taken as the initial conditions"), before Fig. 3',
                 basis=RECONSTRUCTED, basis_note=FIG1 + "; the "
                 "pretension F0 of both branches is the model's", cause=C_ZERO_STATE),
    ]


def published(e: dict) -> list[PublishedFormula]:
    """Every printed formula of paper 004, in the paper's order."""
    head = [_printed("(1), coordinates", L1, sp.Eq(n_q, 3),
                     "(1) has three equations, for φ, z, y ('φ, z, y – відповідні "
                     "узагальнені координати'), while (2), (8), (11) use φ1, φ2, φ3",
                     basis=INTERNAL, basis_note="(1) against the paper's own (2), (8), "
                     "(11), which use φ1, φ2, φ3, y, z: the model's five coordinates",
                     cause=C_COORDINATES)]
    return (head + _lagrange_rows(e) + _energy_rows(e) + _force_rows() + _motion_rows(e)
            + _late_rows())
