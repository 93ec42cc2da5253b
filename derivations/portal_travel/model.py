"""Paper 003's models: a spur-gear pair cut by a rack (Form 1, Fig. 10) and the
support loads of a portal (3)–(4); their symbols, LaTeX names and model text.

The lowest module of the package: everything else imports its symbols from here.
"""
from __future__ import annotations

import sympy as sp
from sympy.physics.units import energy, force, length, mass, time, velocity

from crane_sym.symbols import COORDINATE, DEFINED, PhysicalSymbol, SymbolTable

# --- The paper ---------------------------------------------------------------
ID = "portal_travel"
PAPER = "003_5e8a923a75d2f7ba.txt"
TITLE = ("Travel mechanisms of rail-mounted portal cranes: gear geometry, start-up with "
         "backlash and support loads")
#: From the paper's header (Е. Н. Андрианов, А. Н. Иванов), transliterated.
AUTHORS = ("E.N. Andrianov", "A.N. Ivanov")
CITATION = ("E.N. Andrianov, A.N. Ivanov, Vestnik of the Admiral Makarov State "
            "University of Maritime and Inland Shipping, issue 1")

ONE = sp.S.One * length / length

# --- Gear pair (Form 1) -----------------------------------------------------------
m = sp.Symbol("m", positive=True)
z1, z2, z = sp.symbols("z1 z2 z", positive=True)
a_w = sp.Symbol("a_w", positive=True)
ha = sp.Symbol("h_a", positive=True)
alpha = sp.Symbol("alpha", positive=True)
x1, x2 = sp.symbols("x1 x2", real=True)
k1, k2, k = sp.symbols("k1 k2 k", real=True)          # the print's "shortening" k
dy1, dy2, dy = sp.symbols("dy1 dy2 dy", nonnegative=True)  # tip shortening Δy ≥ 0
sigma = sp.Symbol("sigma", nonnegative=True)           # tip thickness over m
alpha_tw, alpha_a1, alpha_a2 = sp.symbols("alpha_tw alpha_a1 alpha_a2", positive=True)
x_sum = sp.Symbol("x_sum", real=True)
d_a1, d_a2 = sp.symbols("d_a1 d_a2", positive=True)
s_a1, eps_a = sp.Symbol("s_a1", real=True), sp.Symbol("epsilon_alpha", positive=True)
x_p = sp.Symbol("x_p", real=True)                      # the shift the appendix solves for
x_min = sp.Symbol("x_min", real=True)
x = sp.Symbol("x", real=True)                          # a gear's shift (generated code)
# involute geometry (general steps)
r_b, phi, theta = sp.symbols("r_b phi theta", positive=True)
r, r_y, alpha_y = sp.symbols("r r_y alpha_y", positive=True)
s, s_y = sp.symbols("s s_y", real=True)
# the appendix's own names: c := cos α, t := tan α, b := t − α, a := 0.5π, Fo(x)
c_ap, t_ap, b_ap, half_pi, Fo = sp.symbols("c_ap t_ap b_ap A_ap Fo", real=True)

# --- Form 1 as numbers (mm, degrees): the form's own data and results ------------
F_m, F_z1, F_z2, F_aw, F_ha, F_alpha = sp.symbols("F_m F_z1 F_z2 F_aw F_ha F_alpha",
                                                  positive=True)
F_x1, F_x2, F_k1, F_k2, F_k, F_z, F_x0 = sp.symbols("F_x1 F_x2 F_k1 F_k2 F_k F_z F_x0",
                                                    real=True)
V_atw, V_xsum, V_da1, V_da2, V_sa1, V_sa1m, V_eps, V_xp, V_samin = sp.symbols(
    "V_atw V_xsum V_da1 V_da2 V_sa1 V_sa1m V_eps V_xp V_samin", real=True)
C_sa, C_eps = sp.symbols("C_sa C_eps", real=True)     # 1 when a printed check holds

# --- Support loads (3)–(4) ---------------------------------------------------------
psi = sp.Symbol("psi", positive=True)
G_g, G_pch, G_vs = sp.symbols("G_g G_pch G_vs", positive=True)
L_max, x_o, c_arm = sp.symbols("L_max x_o c", positive=True)
M_v, R_max, V_total = sp.symbols("M_v R_max V_total", real=True)
# --- Table 1 arithmetic ------------------------------------------------------------
psi_cell = sp.Symbol("psi_cell", positive=True)

_g = [
    PhysicalSymbol(m, length, "m", "module of the teeth", sample_range=(1e-3, 5e-2)),
    PhysicalSymbol(z1, ONE, "1", "number of teeth of the pinion", sample_range=(8, 150)),
    PhysicalSymbol(z2, ONE, "1", "number of teeth of the wheel", sample_range=(8, 150)),
    PhysicalSymbol(z, ONE, "1", "number of teeth", sample_range=(8, 150)),
    PhysicalSymbol(a_w, length, "m", "centre distance", sample_range=(0.05, 5.0)),
    PhysicalSymbol(ha, ONE, "1", "addendum coefficient of the basic rack h_a*",
                   sample_range=(0.8, 1.25)),
    # An involute profile angle lies below pi/2 (tan alpha finite): 80 degrees at most.
    PhysicalSymbol(alpha, ONE, "rad", "profile angle of the basic rack",
                   sample_range=(0.2, 0.5), serve_range=(2e-7, 1.4)),
    PhysicalSymbol(x1, ONE, "1", "shift coefficient of the pinion", sign="real",
                   sample_range=(0.05, 1.0)),
    PhysicalSymbol(x2, ONE, "1", "shift coefficient of the wheel", sign="real",
                   sample_range=(0.05, 1.0)),
    PhysicalSymbol(x, ONE, "1", "shift coefficient of the gear", sign="real",
                   sample_range=(0.05, 1.0)),
    PhysicalSymbol(k1, ONE, "1", "the print's 'shortening coefficient' of the pinion",
                   sign="real", sample_range=(0.01, 0.3)),
    PhysicalSymbol(k2, ONE, "1", "the print's 'shortening coefficient' of the wheel",
                   sign="real", sample_range=(0.01, 0.3)),
    PhysicalSymbol(k, ONE, "1", "the appendix's 'shortening coefficient'", sign="real",
                   sample_range=(0.01, 0.3)),
    PhysicalSymbol(dy1, ONE, "1", "tip shortening coefficient Δy of the pinion (>= 0)",
                   sign="nonnegative", sample_range=(0.01, 0.3)),
    PhysicalSymbol(dy2, ONE, "1", "tip shortening coefficient Δy of the wheel (>= 0)",
                   sign="nonnegative", sample_range=(0.01, 0.3)),
    PhysicalSymbol(dy, ONE, "1", "tip shortening coefficient Δy (>= 0)",
                   sign="nonnegative", sample_range=(0.01, 0.3)),
    PhysicalSymbol(sigma, ONE, "1", "tip tooth thickness over the module, s_a/m",
                   sign="nonnegative", sample_range=(0.01, 0.5)),
    PhysicalSymbol(alpha_tw, ONE, "rad", "operating (transverse) pressure angle", DEFINED),
    PhysicalSymbol(alpha_a1, ONE, "rad", "pressure angle at the pinion tip", DEFINED),
    PhysicalSymbol(alpha_a2, ONE, "rad", "pressure angle at the wheel tip", DEFINED),
    PhysicalSymbol(x_sum, ONE, "1", "sum of shift coefficients x1 + x2", DEFINED, "real"),
    PhysicalSymbol(d_a1, length, "m", "tip diameter of the pinion", DEFINED),
    PhysicalSymbol(d_a2, length, "m", "tip diameter of the wheel", DEFINED),
    PhysicalSymbol(s_a1, length, "m", "tooth thickness on the pinion's tip circle",
                   DEFINED, "real"),
    PhysicalSymbol(eps_a, ONE, "1", "transverse contact ratio", DEFINED),
    PhysicalSymbol(x_p, ONE, "1", "shift coefficient the appendix solves for", DEFINED,
                   "real", sample_range=(0.05, 2.0)),
    PhysicalSymbol(x_min, ONE, "1", "least shift free of undercut", DEFINED, "real"),
    PhysicalSymbol(r_b, length, "m", "base radius", DEFINED),
    PhysicalSymbol(phi, ONE, "rad", "roll angle of the involute", DEFINED),
    PhysicalSymbol(theta, ONE, "rad", "polar angle of an involute point", DEFINED),
    PhysicalSymbol(r, length, "m", "reference radius m z/2", DEFINED),
    PhysicalSymbol(r_y, length, "m", "a radius of the tooth profile", DEFINED),
    PhysicalSymbol(alpha_y, ONE, "rad", "pressure angle at radius r_y", DEFINED),
    PhysicalSymbol(s, length, "m", "tooth thickness on the reference circle", DEFINED, "real"),
    PhysicalSymbol(s_y, length, "m", "tooth thickness at radius r_y", DEFINED, "real"),
    PhysicalSymbol(c_ap, ONE, "1", "the appendix's c := cos α", DEFINED, "real"),
    PhysicalSymbol(t_ap, ONE, "1", "the appendix's t := tan α", DEFINED, "real"),
    PhysicalSymbol(b_ap, ONE, "1", "the appendix's b := t − α", DEFINED, "real"),
    PhysicalSymbol(half_pi, ONE, "1", "the appendix's a := 0.5π", DEFINED, "real"),
    PhysicalSymbol(Fo, ONE, "1", "the appendix's Fo(x) = cos of the tip pressure angle",
                   DEFINED, "real"),
]
_numbers = [PhysicalSymbol(sym, ONE, "1", what, DEFINED, "real") for sym, what in [
    (F_m, "Form 1: m in mm"), (F_z1, "Form 1: z1"), (F_z2, "Form 1: z2"),
    (F_aw, "Form 1: a_w in mm"), (F_ha, "Form 1: h_a"), (F_alpha, "Form 1: α in degrees"),
    (F_x1, "Form 1: x1"), (F_x2, "Form 1: x2"), (F_k1, "Form 1: k1"), (F_k2, "Form 1: k2"),
    (F_k, "Form 1 appendix: k"), (F_z, "Form 1 appendix: z"),
    (F_x0, "Form 1 appendix: the starting guess of Find"),
    (V_atw, "Form 1: α_tw in degrees"), (V_xsum, "Form 1: x_Σ"),
    (V_da1, "Form 1: d_a1 in mm"), (V_da2, "Form 1: d_a2 in mm"),
    (V_sa1, "Form 1: s_a1 in mm"), (V_sa1m, "Form 1: s_a1/m"),
    (V_eps, "Form 1: ε_α"), (V_xp, "Form 1 appendix: pointed-tip shift at z = 10"),
    (V_samin, "Form 1: least tip thickness 0.4·m in mm"),
    (C_sa, "1 if s_a1/m >= 0.4 (the form's check), else 0"),
    (C_eps, "1 if ε_α > 1.2 (the form's check), else 0"),
    (psi_cell, "Table 1: dynamic coefficient F_max/F_ср of one row"),
]]
_loads = [
    PhysicalSymbol(psi, ONE, "1", "dynamic coefficient of the hoisted load (printed у)",
                   sample_range=(1.0, 2.0)),
    PhysicalSymbol(G_g, force, "N", "rated weight of the load G_г", sample_range=(5e4, 5e5)),
    PhysicalSymbol(G_pch, force, "N", "weight of the slewing part G_пч",
                   sample_range=(5e5, 3e6)),
    PhysicalSymbol(G_vs, force, "N", "weight of the portal's upper structure G_вс",
                   sample_range=(1e5, 1e6)),
    PhysicalSymbol(L_max, length, "m", "maximum reach", sample_range=(15.0, 40.0)),
    PhysicalSymbol(x_o, length, "m", "distance of the slewing part's centre of gravity "
                   "from the slewing axis", sample_range=(0.5, 5.0)),
    PhysicalSymbol(c_arm, length, "m", "arm of the couple by which the slewing part "
                   "bears on the circular rail", sample_range=(3.0, 10.0)),
    PhysicalSymbol(M_v, force * length, "N*m", "moment of the vertical loads M_в",
                   DEFINED, "real"),
    PhysicalSymbol(R_max, force, "N", "largest vertical load on one portal leg",
                   DEFINED, "real"),
    PhysicalSymbol(V_total, force, "N", "vertical load carried by the portal", DEFINED,
                   "real"),
]
# --- Start-up with backlash (Fig. 11, Table 1) -------------------------------------
J_r, n_m, omega_n, omega_0, v_n, P_m, lam = sp.symbols(
    "J_r n_m omega_n omega_0 v_n P_m lambda_p", positive=True)
c_l, zeta, m_k, W_f = sp.symbols("c_l zeta m_k W_f", positive=True)
W_w, phi_b, t_s = sp.symbols("W_w phi_b t_s", nonnegative=True)
v_gap = sp.Symbol("v_gap", real=True)
m_d, P_nom, v_0, beta_1, q_step, s_b, b_l, a_0 = sp.symbols(
    "m_d P_nom v_0 beta_1 q_step s_b b_l a_0", real=True)
F_peak = sp.Symbol("F_peak", real=True)              # a model's F_max over 1 kN
beta_k = sp.Symbol("beta_k", positive=True)          # slope of the characteristic in use
t = sp.Symbol("t", nonnegative=True)                  # time of the start-up
x_1, x_2, x_k = (sp.Function(n)(t) for n in ("x_1", "x_2", "x_k"))
F_1 = sp.Symbol("F_1")                               # load of the left link, first stage
a_cell = sp.Symbol("a_cell", real=True)              # an acceleration over 1 m/s²
_startup = [
    PhysicalSymbol(J_r, mass * length ** 2, "kg*m^2", "moment of inertia of one motor "
                   "rotor", sample_range=(0.05, 1.0)),
    PhysicalSymbol(n_m, ONE, "1", "number of motors on one side of the portal",
                   sample_range=(1, 4)),
    PhysicalSymbol(omega_n, 1 / time, "rad/s", "rated motor speed", sample_range=(50, 160)),
    PhysicalSymbol(omega_0, 1 / time, "rad/s", "no-load (synchronous) motor speed",
                   sample_range=(60, 170)),
    PhysicalSymbol(v_n, velocity, "m/s", "rated travel speed of the crane",
                   sample_range=(0.2, 1.0)),
    PhysicalSymbol(P_m, energy / time, "W", "rated power of one motor",
                   sample_range=(5e3, 5e4)),
    PhysicalSymbol(lam, ONE, "1", "starting-force multiple λ: force of the first "
                   "characteristic at standstill over the rated force", sample_range=(1.2, 2.5)),
    PhysicalSymbol(c_l, force / length, "N/m", "stiffness of one elastic link (portal "
                   "side and drive, at the rim)", sample_range=(1e6, 2e7)),
    PhysicalSymbol(zeta, ONE, "1", "damping ratio of a link against its motors",
                   sample_range=(0.01, 0.2)),
    PhysicalSymbol(m_k, mass, "kg", "mass of the crane", sample_range=(1e5, 5e5)),
    PhysicalSymbol(W_f, force, "N", "friction resistance to travel", sample_range=(1e4, 6e4)),
    PhysicalSymbol(W_w, force, "N", "wind resistance to travel", sign="nonnegative",
                   sample_range=(1e3, 6e4)),
    PhysicalSymbol(phi_b, ONE, "rad", "backlash of one drive, on its fast shaft",
                   sign="nonnegative", sample_range=(0.1, 6.3)),
    PhysicalSymbol(t_s, time, "s", "time from the start (first stage)", sign="nonnegative",
                   sample_range=(1e-3, 0.5)),
    PhysicalSymbol(v_gap, velocity, "m/s", "motor speed at the rim while its gap is open",
                   DEFINED, "real"),
    PhysicalSymbol(m_d, mass, "kg", "motor rotors of one side reduced to the wheel rim",
                   DEFINED, "real"),
    PhysicalSymbol(P_nom, force, "N", "rated force of one side at the rim", DEFINED, "real"),
    PhysicalSymbol(v_0, velocity, "m/s", "no-load speed at the rim", DEFINED, "real"),
    PhysicalSymbol(beta_1, force / velocity, "N*s/m", "slope of the first start "
                   "characteristic of one side", DEFINED, "real"),
    PhysicalSymbol(q_step, ONE, "1", "ratio of the slopes of consecutive characteristics",
                   DEFINED, "real"),
    PhysicalSymbol(s_b, length, "m", "backlash of one drive at the rim", DEFINED, "real"),
    PhysicalSymbol(b_l, force / velocity, "N*s/m", "damping coefficient of a link",
                   DEFINED, "real"),
    PhysicalSymbol(a_0, velocity / time, "m/s^2", "acceleration of the rigid drive at "
                   "break-away on the first characteristic", DEFINED, "real"),
    PhysicalSymbol(beta_k, force / velocity, "N*s/m", "slope of the start characteristic "
                   "a side is on (β_1 on the first)", sample_range=(1e5, 5e6)),
    PhysicalSymbol(F_1, force, "N", "load of the left link in the first stage (text: F)",
                   sign="real", sample_range=(1e3, 6e4)),
    PhysicalSymbol(t, time, "s", "time of the start-up in (1)-(2), phase by phase (not a "
                   "scene's clock)", sign="nonnegative",
                   sample_range=(1e-3, 5.0)),
    PhysicalSymbol(x_1, length, "m", "left motor masses' coordinate at the rim", COORDINATE,
                   "real"),
    PhysicalSymbol(x_2, length, "m", "right motor masses' coordinate at the rim", COORDINATE,
                   "real"),
    PhysicalSymbol(x_k, length, "m", "the crane's coordinate", COORDINATE, "real"),
    PhysicalSymbol(F_peak, ONE, "1", "the model's largest F1 + F2 in kN", DEFINED, "real"),
    PhysicalSymbol(a_cell, ONE, "1", "a crane acceleration of Table 1 in m/s^2", DEFINED,
                   "real"),
]
SYMBOLS = SymbolTable(_g + _numbers + _loads + _startup)

#: The Mathcad variables of Form 1 and its appendix are set in typewriter type
#: (\mathtt), so that they stay apart from the geometry's symbols of the same letter.
LATEX_NAMES = {
    z1: "z_1", z2: "z_2", a_w: "a_w", ha: "h_a", alpha: r"\alpha", x1: "x_1", x2: "x_2",
    k1: "k_1", k2: "k_2", dy1: r"\Delta y_1", dy2: r"\Delta y_2", dy: r"\Delta y",
    alpha_tw: r"\alpha_{tw}", alpha_a1: r"\alpha_{a1}", alpha_a2: r"\alpha_{a2}",
    x_sum: r"x_\Sigma", d_a1: "d_{a1}", d_a2: "d_{a2}", s_a1: "s_{a1}",
    eps_a: r"\varepsilon_\alpha", x_p: r"\mathtt{x}", x_min: r"x_{\min}", r_b: "r_b",
    r_y: "r_y", alpha_y: r"\alpha_y", s_y: "s_y", c_ap: r"\mathtt{c}", t_ap: r"\mathtt{t}",
    b_ap: r"\mathtt{b}", half_pi: r"\mathtt{a}", Fo: r"\mathtt{Fo}(\mathtt{x})",
    psi: r"\psi", G_g: r"G_{г}", G_pch: r"G_{пч}", G_vs: r"G_{вс}", L_max: r"L_{\max}",
    x_o: "x_o", c_arm: "c", M_v: r"M_{в}", R_max: r"R_{\max}", V_total: "V",
    psi_cell: r"\psi_{\mathrm{Table\,1}}", J_r: "J_r", n_m: "n_m", omega_n: r"\omega_n",
    omega_0: r"\omega_0", v_n: "v_n", P_m: "P_m", lam: r"\lambda", c_l: r"C_{пр}",
    zeta: r"\zeta", m_k: "m_k", W_f: "W_f", W_w: "W_w", phi_b: r"\varphi_b", m_d: "m_d",
    P_nom: "P_n", v_0: "v_0", beta_1: r"\beta_1", q_step: "q", s_b: "s_b", b_l: "b",
    a_0: "a_0", F_peak: r"F_{\max}/\mathrm{kN}",
    a_cell: r"a/(\mathrm{m/s^2})", t_s: "t", v_gap: r"v_{\mathrm{gap}}",
    F_m: r"\mathtt{m}", F_z1: r"\mathtt{z1}", F_z2: r"\mathtt{z2}", F_aw: r"\mathtt{a_w}",
    F_ha: r"\mathtt{h_a}", F_alpha: r"\mathtt{\alpha}^\circ", F_x1: r"\mathtt{x1}",
    F_x2: r"\mathtt{x2}", F_k1: r"\mathtt{k1}", F_k2: r"\mathtt{k2}", F_k: r"\mathtt{k}",
    F_z: r"\mathtt{z}", F_x0: r"\mathtt{x}_{(0)}", V_atw: r"\mathtt{\alpha_{tw}}^\circ",
    V_xsum: r"\mathtt{x_\Sigma}", V_da1: r"\mathtt{d_{a1}}", V_da2: r"\mathtt{d_{a2}}",
    V_sa1: r"\mathtt{s_{a1}}", V_sa1m: r"\mathtt{s_{a1}}/\mathtt{m}",
    V_eps: r"\mathtt{\varepsilon_\alpha}", V_xp: r"\mathtt{x}_{z=10}",
    V_samin: r"0.4\,\mathtt{m}", C_sa: r"[\mathtt{s_{a1}}/\mathtt{m} \ge 0.4]",
    C_eps: r"[\mathtt{\varepsilon_\alpha} > 1.2]",
}
#: The words a handout gives for the Mathcad names and spelled-out Greek letters in
#: this paper's labels and notes (the audit keeps them for a reviewer).
HANDOUT_WORDS = {
    "alpha_tw": r"$\alpha_{tw}$", "atw": r"$\alpha_{tw}$", "alpha_a1": r"$\alpha_{a1}$",
    "alpha_a2": r"$\alpha_{a2}$", "alpha": r"$\alpha$", "x_sum": r"$x_\Sigma$",
    "xsum": r"$x_\Sigma$", "da1": r"$d_{a1}$", "da2": r"$d_{a2}$", "sa1": r"$s_{a1}$", "s_a1": r"$s_{a1}$",
    "d_a1": r"$d_{a1}$", "d_a2": r"$d_{a2}$",
    "sa1m": r"$s_{a1}/m$", "s_a1/m": r"$s_{a1}/m$", "epsilon_alpha": r"$\varepsilon_\alpha$",
    "eps": r"$\varepsilon_\alpha$", "xp": "the shift of the pointed tip", "psi": r"$\psi$",
    "2pi": r"$2\pi$", "pi": r"$\pi$",
    "the three-mass start-up of startup.py": "the three-mass start-up of the model text",
    " (startup.PLAUSIBLE)": "", "(startup.py, model text)": "(from the model text)"}

MODEL = r"""
Form 1 and Fig. 10: a pair of involute spur gears cut by generating with a
basic rack (profile angle α, addendum h_a·m), the rack's rolling line shifted
by x·m from its datum line. The involute is the path of the end of a string
unwound from the base circle r_b = r·cos α; the gear's tooth thickness on its
reference circle equals the rack's space width on the rolling line; two gears
mesh without backlash when their tooth thicknesses on the operating pitch
circles add up to the operating pitch. Tips are cut to d_a = m·z + 2(h_a + x −
Δy)·m with a tip shortening Δy >= 0. Only the geometry is modelled (no
tolerances, no tip rounding of the rack).

              rack datum ------------------------  +x·m (rolling line)
                  \____/    \____/    \____/        flank at α to the normal
                    gear: base circle r_b, involute flanks

Support loads (3)–(4), reconstructed (the paper does not draw the portal): a
four-legged portal carries the vertical load V = ψ·G_г + G_пч + G_вс in equal
quarters; the slewing part bears on a circular rail and passes the moment of
the vertical loads about the slewing axis, M_в = ψ·G_г·L_max − G_пч·x_o, to
the portal as a couple of forces ±M_в/c, each shared by the two legs under it.

        ψG_г <---- L_max ----> | axis <- x_o -> G_пч
             ====== circular rail, couple arm c ======
             leg   leg                       leg   leg

Start-up with backlash (Fig. 11, Table 1; the paragraphs before Table 1 of
the paper). The paper's equations (1)–(2) are lost in the OCR
(only "(1) Щ md \mdi тк J тк ' тк W8 (2) V" survives); the model is built from
the text's definitions: "the masses of the motor rotors of the right and left
side of the portal, reduced to the rim of the running wheel, m_d, joined by two
elastic links to the crane mass m_к"; "the motor's tractive force depends
linearly on the speed"; "P_p1, the initial starting force on the first
mechanical characteristic; v0, the no-load speed; λ, the starting-torque
multiple"; "C_пр, the reduced longitudinal stiffness of the portal; α, the
damping coefficient"; "first stage: the backlash is taken up and the link load
reaches the resistance to travel; second stage: joint motion of the motor and
crane masses"; friction 30 kN, friction and wind together 60 kN, the wind below
the friction (taken as a constant head wind); the motor MTF311-6, 13 kW at 935 rpm; hold times 0.4, 0.8, 0.8 s.

    motors, left  m_d --[ c, b, gap s ]--\
                                          crane m_к  <- W_w (wind), W_f (friction)
    motors, right m_d --[ c, b, gap s ]--/

Newton for each mass (c is the text's C_пр, s = s_b the backlash at the rim,
b the damping behind its α): m_d·v̇_i = β_k(v0 − v_i) − F_i, m_к·v̇_к = F_1 + F_2 − W_w
− W_f while the crane moves forward; F_i = c(u_i − s) + b·u̇_i on the driving
flank (u_i = x_i − x_к ≥ s), 0 in the gap, c·u_i + b·u̇_i on the trailing flank
(u_i ≤ 0). The crane stands (first stage) while W_w − W_f ≤ F_1 + F_2 ≤ W_w + W_f.
Characteristic k of the stepped rheostat start is the line β_k(v0 − v) through
the no-load speed; β_1 = λ·P_n/v0 (P_p1 = λ·P_n at standstill); the slopes grow
by a constant ratio q up to the natural characteristic P_n/(v0 − v_n), three
steps (q³ = v0/(λ(v0 − v_n))), switched after the printed hold times.

Parameters the paper does not state (chosen, not fitted): two MTF311-6 per side
(four motors: 4 × 13 kW covers 60 kN at the rated speed, 32 kW; two would not);
rotor inertia J_r = 0.225 kg·m² (catalogue value of the MTF311-6); synchronous
speed 1000 rpm (six poles, 50 Hz); rated travel speed 32 m/min (usual for portal
cranes; Table 1's step accelerations times the hold times add up to 0.48–0.52
m/s at 2 s); crane mass 250 t (30 kN of friction at the usual specific
resistance of about 0.012 gives 2.5 MN of weight, a 16 t, 32 m portal crane of
the paper's reference [8]); λ = 2 (a usual peak of a relay start, below the
MTF311-6's breakdown multiple of about 2.4); link stiffness c = 5 MN/m per side
(20 mm of longitudinal deflection of a portal side under 100 kN); damping ratio
ζ = 0.05 of a link against its motors (logarithmic decrement about 0.3), b =
2ζ·√(c·m_d). Table 1's F_max is read as the load of both drives on the portal,
F_1 + F_2: the model's mean F_1 + F_2 over the 2 s of the start, 122–125 kN,
is of the order of Table 1's F_ср = 150 kN (per side it would be half). Each
row's backlash is in both drives.
"""
