"""The hoist of paper 001: its symbols, the data of Table 1 and the model text.

The lowest module of the package: everything else imports its symbols from here.
"""
from __future__ import annotations

import sympy as sp
from sympy.physics.units import Dimension, force, length, mass, time, velocity

from crane_sym.symbols import DEFINED, TIME, PhysicalSymbol, SymbolTable

# --- The paper ---------------------------------------------------------------
ID = "hoist_brakes"
PAPER = "001_544065b666a6bc39.txt"
TITLE = "Hoists with safety brakes: gearbox torque in an emergency stop"
#: From the paper's header (Штефан Фёт, Тюленев Максим Анатольевич), as the
#: citation gives them in Latin letters.
AUTHORS = ("S. Vöth", "M.A. Tyulenev")
CITATION = "S. Vöth, M.A. Tyulenev, Kuzbass State Technical University, 2016"

ONE = Dimension(1)
torque = force * length
inertia = mass * length ** 2
rate = 1 / time

# --- Symbols -----------------------------------------------------------------
omega1, J1, J2, r, i_g, i_t, g = sp.symbols("omega1 J1 J2 r i_g i_t g", positive=True)
m_h, m_r = sp.symbols("m_h m_r", positive=True)
m_p = sp.Symbol("m_p", nonnegative=True)
M_SB, M_BB, M_M, c = sp.symbols("M_SB M_BB M_M c", positive=True)
phi5, d_omega, d_t = sp.symbols("phi5 d_omega d_t", positive=True)
v, J, M_L, M_st, J_d = sp.symbols("v J M_L M_st J_d", positive=True)
alpha, M_G = sp.symbols("alpha M_G", real=True)
MF, LF, BF_SB, BF_BB = sp.symbols("MF LF BF_SB BF_BB", positive=True)
M_rel, M_rel_max, N = sp.symbols("M_rel M_rel_max N", real=True)
t = sp.Symbol("t", nonnegative=True)
t_SB, t_BB, delta = sp.symbols("t_SB t_BB delta", nonnegative=True)

SYMBOLS = SymbolTable([
    PhysicalSymbol(omega1, rate, "rad/s", "motor angular speed before braking (Table 1: "
                   "n1 = 1500 1/min)", sample_range=(10.0, 400.0)),
    PhysicalSymbol(J1, inertia, "kg*m^2", "inertia of the motor shafts (rotors, brake "
                   "discs, couplings), Table 1", sample_range=(1.0, 200.0)),
    PhysicalSymbol(J2, inertia, "kg*m^2", "inertia of the drum shafts, Table 1",
                   sample_range=(10.0, 5000.0), serve_range=(1e-12, 5e9)),  # hard case: J2 -> 0
    PhysicalSymbol(m_h, mass, "kg", "mass of the hook (load-handling device)",
                   sample_range=(1e2, 1e5), serve_range=(1e-6, 1e11)),  # hard case: m_h -> 0
    PhysicalSymbol(m_p, mass, "kg", "payload", sign="nonnegative", sample_range=(1e2, 1e5)),
    PhysicalSymbol(m_r, mass, "kg", "rated payload (Table 1: 52 t)", sample_range=(1e2, 1e5)),
    PhysicalSymbol(r, length, "m", "drum radius", sample_range=(0.1, 2.0)),
    PhysicalSymbol(i_g, ONE, "1", "gear ratio of the gearbox", sample_range=(5.0, 100.0)),
    PhysicalSymbol(i_t, ONE, "1", "ratio of the rope tackle (8 falls, 2 drums: 4)",
                   sample_range=(1.0, 8.0)),
    PhysicalSymbol(g, velocity / time, "m/s^2", "gravity", sample_range=(9.8, 9.82)),
    PhysicalSymbol(M_SB, torque, "N*m", "torque of the safety brakes on the drums",
                   sample_range=(1e3, 1e6)),
    PhysicalSymbol(M_BB, torque, "N*m", "torque of the service brakes on the motor shafts",
                   sample_range=(1e2, 1e5)),
    PhysicalSymbol(M_M, torque, "N*m", "motor torque", sign="real", sample_range=(1e2, 1e5)),
    PhysicalSymbol(c, torque, "N*m/rad", "torsional stiffness of the gearbox, at the "
                   "motor shaft", sample_range=(1e3, 1e7),
                   serve_range=(1e-6, 1e13)),                   # hard case: c -> 0
    PhysicalSymbol(phi5, ONE, "1", "dynamic factor φ5 of EN 13001-2",
                   sample_range=(1.0, 2.0)),
    PhysicalSymbol(d_omega, rate, "rad/s", "change of the motor angular speed while braking",
                   sample_range=(10.0, 400.0)),
    PhysicalSymbol(d_t, time, "s", "braking time", sample_range=(0.1, 10.0)),
    PhysicalSymbol(t, time, "s", "time since the emergency stop", TIME, "nonnegative",
                   (1e-3, 10.0)),
    PhysicalSymbol(t_SB, time, "s", "delay of the safety brakes", sign="nonnegative",
                   sample_range=(1e-3, 1.0)),
    PhysicalSymbol(t_BB, time, "s", "delay of the service brakes", sign="nonnegative",
                   sample_range=(1e-3, 1.0)),
    PhysicalSymbol(delta, ONE, "rad", "backlash of the drum coupling (at the drum)",
                   sign="nonnegative", sample_range=(1e-3, 0.5)),
    PhysicalSymbol(v, velocity, "m/s", "hoist speed", DEFINED),
    PhysicalSymbol(J, inertia, "kg*m^2", "inertia of the whole drive reduced to the motor "
                   "shaft (the print's J_ges*)", DEFINED),
    PhysicalSymbol(J_d, inertia, "kg*m^2", "inertia beyond the gearbox input, reduced to "
                   "the motor shaft", DEFINED),
    PhysicalSymbol(M_L, torque, "N*m", "static load torque at the motor shaft", DEFINED),
    PhysicalSymbol(M_st, torque, "N*m", "static load torque of the rated load at the "
                   "motor shaft (the print's M_st*)", DEFINED),
    PhysicalSymbol(alpha, rate / time, "rad/s^2", "angular acceleration of the motor shaft",
                   DEFINED, "real"),
    PhysicalSymbol(M_G, torque, "N*m", "torque at the gearbox input", DEFINED, "real"),
    PhysicalSymbol(MF, ONE, "1", "inertia factor J1/J", DEFINED, "nonnegative"),
    PhysicalSymbol(LF, ONE, "1", "load factor M_L/M_st", DEFINED),
    PhysicalSymbol(BF_SB, ONE, "1", "safety-brake factor M_SB/(i_g M_st)", DEFINED,
                   sample_range=(1.0, 4.0)),
    PhysicalSymbol(BF_BB, ONE, "1", "service-brake factor M_BB/M_st", DEFINED),
    PhysicalSymbol(M_rel, ONE, "1", "relative gearbox torque M_G/M_st", DEFINED, "real"),
    PhysicalSymbol(M_rel_max, ONE, "1", "largest relative gearbox torque", DEFINED, "real"),
    PhysicalSymbol(N, ONE, "1", "a number the paper prints", DEFINED, "real"),
])
LATEX_NAMES = {omega1: r"\omega_1", m_h: "m_h", m_p: "m_p", m_r: "m_r", i_g: "i_g",
               i_t: "i_t", M_SB: "M_{SB}", M_BB: "M_{BB}", M_M: "M_M", phi5: r"\varphi_5",
               d_omega: r"\Delta\omega", t_SB: "t_{SB}", t_BB: "t_{BB}", delta: r"\delta",
               d_t: r"\Delta t", J: "J_{ges}", J_d: "J_d",
               M_L: "M_L", M_st: "M_{st}", M_G: "M_G", BF_SB: "BF_{SB}",
               BF_BB: "BF_{BB}", M_rel: "M_{G,rel}", M_rel_max: r"M_{G,rel,\max}"}
#: The words a handout gives for the code names in this paper's notes (the audit's
#: notes keep them for a reviewer).
HANDOUT_WORDS = {"the two-mass hoist with backlash of elastic.py":
                 "the two-mass hoist with backlash of the model text",
                 " (elastic.FIG9_CHOSEN)": "", "BF_SB = 17/10": "BF_SB = 1.7",
                 "BF_SB = 33/10": "BF_SB = 3.3"}

#: Table 1 of 001_544065b666a6bc39.txt ("Технические характеристики подъемника"),
#: exact, in SI. "per" says what a value is counted for as printed.
TABLE1 = {
    "n1": sp.Integer(1500),                 # 1/min, motor speed
    "v": sp.Rational(45, 60),               # 45 m/min, hoist speed
    "J1": sp.Integer(20),                   # kg m², "момент инерции оси мотора"
    "J2": sp.Integer(500),                  # kg m², "момент инерции оси барабана"
    "m_h": sp.Integer(10_000),              # 10 t, hook
    "m_r": sp.Integer(52_000),              # 52 t, load
    "r": sp.Rational(1, 2),                 # m, drum radius
    "i_g": sp.Rational(262, 10),            # gear ratio
    "i_t": sp.Integer(4),                   # tackle 8/2
    "M_BB": sp.Integer(5_800),              # N m, service brake
    "t_BB": sp.Rational(4, 10),             # s, service-brake delay
    "M_SB": sp.Integer(130_000),            # N m, safety brake
    "t_SB": sp.Rational(1, 10),             # s, safety-brake delay
    "c": sp.Integer(40_000),                # N m/rad, gearbox stiffness
    "backlash_deg": sp.Integer(3),          # °, drum-coupling backlash
}
G = sp.Rational(981, 100)                   # m/s², not printed; standard value

MODEL = r"""
The hoist of Table 1 (the paper's Figs 1 and 4): two motors with service
brakes drive one gearbox; each of its two output shafts drives a drum with a
safety brake; each drum winds one end of a rope reeved 8/2 (8 falls, 2 ends,
ratio i_t = 4). The paper counts no friction and no losses.

   M_M, M_BB          gearbox, i_g         drum: J2, M_SB     rope, i_t
  [motors J1]==c/backlash==[ i_g ]==========[ drum r ]~~~~~~~~[ hook m_h + payload m_p ]
             ^ cut: M_G (gearbox input)

Everything is reduced to the motor shaft: a drum turns at ω1/i_g, the hook
moves at v = ω1·r/(i_g·i_t); kinetic energy gives J = J1 + J2/i_g² +
(m_h + m_p)·(r/(i_g·i_t))², the power of gravity the static torque
M_L = (m_h + m_p)·g·r/(i_g·i_t), a safety-brake torque M_SB at the drums acts
as M_SB/i_g. The rigid drive obeys J·α = ΣM (the paper's first, unnumbered
formula); cutting at the gearbox input leaves the motor shaft J1 with the
motor torque, the service brake and the gearbox torque M_G.

How the two trains are counted (one reading for the whole paper, declared
once): Table 1 gives J1 = 20 kg·m² ("the motor
shaft"), J2 = 500 kg·m² ("the drum shaft") and M_SB = 130 kN·m once, for a
hoist with two of each. Counted per train (twice each) the inertia factor over
the payload is MF = 0.933…0.960; counted as the values of the whole drive it is
0.903…0.954, the 0.90…0.95 of Fig. 8's legend, and M_SB = 130 kN·m in total
gives the text's "BF_SB = 1,7" (1.71; per drum 3.42). So J1, J2 and M_SB are
read as totals of the whole drive and M_L, M_st as the torque of the whole
load, in every record; a printed number that only the per-train reading
reproduces (the 4.4 "in some cases") is a finding that says so.
g = 9.81 m/s² is not printed.

Unstated quantities, named as such: the braking time Δt of (6)–(7), fitted
to the percentages of Figs 11–12 (they share Δt in [0.999, 1.005] s; Δt = 1 s
is taken); for Fig. 9 the position of the stiffness (taken at the motor
shaft), the backlash (3° at the drum, i.e. 3°·i_g at the motor shaft), the
brake law after the drum stops (it holds), and two values left free because
nothing argues for one: the mesh damping (0 taken, 0–0.05 plausible) and the
motor's delay in losing torque (0 taken, 0–0.1 s plausible), over which the
peak spans 8.47–9.13.
"""
