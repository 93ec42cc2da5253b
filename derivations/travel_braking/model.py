"""The two-mass model of paper 000: its symbols, their LaTeX names and the model text.

The lowest module of the package: everything else imports its symbols from here.
"""
from __future__ import annotations

import sympy as sp
from sympy.physics.units import force, length, mass, time, velocity

from crane_sym.symbols import (COORDINATE, DEFINED, TIME, PhysicalSymbol,
                               SymbolTable)

# --- The paper ---------------------------------------------------------------
ID = "travel_braking"
PAPER = "000_4ef6efc8a81a3b06.txt"
TITLE = "Dynamic loads when the travel mechanism of an overhead crane brakes"
#: The authors as the paper's header gives them (Russian; transliterated).
AUTHORS = ("V.F. Semenyuk", "A.N. Vudvud")
CITATION = "V.F. Semenyuk, A.N. Vudvud, Odessa National Polytechnic University"

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
                   "(rotor, motor and brake couplings)", sample_range=(1e2, 1e5),
                   serve_range=(1e-4, 1e12)),                   # hard cases: m2/m1 -> 0
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
