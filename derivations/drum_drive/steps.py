"""Paper 004's derivation steps, eqs (1)–(21), in the paper's order.

Each function adds the steps of one part of the paper to the ``Derivation``;
``build()`` in ``__init__`` calls them in turn: Lagrange's equations (1), the
kinetic energy (2)–(7), the potential energy and generalized forces (8)–(10),
the dissipation (11), the equations of motion (12), steady running, the
relative vibrations (13)–(14), the drum-shaft bending (17), the drum torque and
traction (18)–(19), the pulsating load (20)–(21) and the initial state.
"""
from __future__ import annotations

import sympy as sp

from crane_sym.derivation import Derivation
from crane_sym.mechanics.lagrange import lagrange_equations
from crane_sym.mechanics.modal import eigenvalues_2x2, relative_dynamic_matrix
from crane_sym.mechanics.odes import solve_constant_coefficient

from . import print_notation as notation
from . import published as pub
from .model import (
    C1, C2, C_t, C_y, C_z, COORDS, D, Delta, F0, F1, F1_lim, F2, FORCES, F_pulse, F1_t,
    F2_t, F3_t, F4_t, I1, I2, I3, K1, K2, K3, K4, L, M0, M_d, Phi_, Pi_, T_, T_b, T_el,
    W, _dot, a_v, alpha, b_v, dA, e1, e2, g, m_eff, m_sum, mu, mu_alpha_min, mu_op, nu1,
    nu2, nu_t, nu_y, nu_z, omega, omega_1, omega_2, phi1, phi2, phi3, q, r, t, t_3,
    v_s, v_xi, vphi1, vy, vz, xi, y, y0, y_s, z)


def lagrange(d: Derivation, e: dict) -> dict:
    """(1): Lagrange's equations of the model's T, Π, Φ; returns the equations of
    motion by coordinate name, for (12)."""
    motion = lagrange_equations(e["T"], e["Pi"], COORDS, t, FORCES, e["Phi"])
    eqs = dict(zip(("φ1", "φ2", "φ3", "y", "z"), motion.equations))
    d.add("(1), coordinates", sp.Eq(notation.n_q, len(COORDS)),
          "The model has five coordinates: φ1, φ2, φ3, y, z (see MODEL).",
          "The print's (1) has three (φ, z, y) while its T and Π use φ1, φ2, φ3.",
          "Lagrange's equations")
    for label, name, Q in (("(1), φ", "φ3", notation.Q1), ("(1), z", "z", notation.Q2),
                           ("(1), y", "y", notation.Q3)):
        d.add(label, sp.Eq(eqs[name].lhs, Q),
              f"d/dt ∂T/∂q̇ − ∂T/∂q + ∂Π/∂q + ∂Φ/∂q̇ for q = {name}, with the T, Π, Φ of "
              "(2)–(11); the generalized force named as in the print.",
              "The Rayleigh term is ∂Φ/∂q̇: Φ depends on the velocities only."
              if Q is notation.Q1 else "")
    return eqs


def kinetic_energy(d: Derivation, e: dict) -> None:
    """(2)–(7): the kinetic energy, the element's share under the linear speed (6)."""
    d.add("(2)", sp.Eq(T_, e["T_rigid"] + T_el),
          "½·I·φ̇² of the three rotating bodies, ½·m3·ẏ² of the drum's translation, "
          "½·m_L·ż² of the loaded run, plus the element's T_т.ор.",
          "Only the drum translates; motor and gearbox sit on rigid frames (the print's "
          "x_i are not defined).", "Kinetic energy")
    d.add("(3)", sp.Eq(notation.dT, notation.dm * (_dot(z)**2 + _dot(y)**2) / 2),
          "½·dm·v² of a piece with the velocity components ż and ẏ, as (3) sets it up.")
    d.add("(4)", sp.Eq(notation.dm, q * notation.dl), "Mass of a piece dl at q per metre.")
    d.add("(5)", sp.Eq(notation.v_z, notation.dl / notation.dt),
          "The element's speed, as the print defines it.")
    d.add("(6)", sp.Eq(v_xi, a_v + b_v * xi), "The paper's hypothesis, adopted.",
          "With it the element's kinetic energy becomes an effective mass.")
    # The print's geometry for (7): a span [0, L] at rest at both ends, moved
    # across at ξ = z(t) with ẏ; a second span [0, δy] moved along at s = y(t) with ż.
    pieces = []
    for vel, apex, end in ((_dot(y), z, L), (_dot(z), y, notation.delta_y)):
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
          "[y, δy]), integrated symbolically; √(1 + slope²) of a flat span is 1.",
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


def potential_and_forces(d: Derivation, e: dict) -> None:
    """(8)–(10): stretches, potential energy, branch forces, generalized forces."""
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
            ("(9), δA_1", notation.dA1, torque, notation.vphi,
             "a rigid rotation δφ of the drive (shafts unstrained): M0 and the branch torque"),
            ("(9), δA_2", notation.dA2, on_drum, vy, "δy of the drum: both branch forces pull "
             "it toward the line, the shaft resists"),
            ("(9), δA_3", notation.dA3, on_run, vz, "δz of the run: F1 pulls it forward, F2 "
             "back, W resists")):
        d.add(label, sp.Eq(dA_i, Q * v), f"Virtual work of every force on {what} (branch "
              "forces taken as given, as in the print).", "To check the print's lines on "
              "their own terms." if label.endswith("1") else "")
    for label, Q, Qv in pub.printed_virtual_work():
        d.add(label, sp.Eq(Q, Qv), "The print's own δA line divided by its virtual "
              "displacement (9), uncorrected.", "To compare (10) with the lines it "
              "should repeat.")
    for label, Q, Qv, on in (("(10), Q1", notation.Q1, torque, "δφ"), ("(10), Q2", notation.Q2,
                                                               on_run, "δz"),
                             ("(10), Q3", notation.Q3, on_drum, "δy")):
        d.add(label, sp.Eq(Q, Qv), f"(9): the derived δA line divided by {on}.")


def dissipation(d: Derivation, e: dict) -> None:
    """(11): the Rayleigh dissipation function."""
    d.add("(11)", sp.Eq(Phi_, e["Phi"]),
          "½·ν·(rate)² for each damped link: shafts ν1, ν2, shaft bending ν_y, slack branch "
          "ν_z; and ½·ν_t·ż² for the running resistance of the element.",
          "The tight branch gets no damper: the print gives none for C_t.", "Dissipation")


def equations_of_motion(d: Derivation, eqs: dict) -> None:
    """(12): the equations of motion, one step per coordinate."""
    for i, (name, eq) in enumerate(eqs.items()):
        d.add(f"(12), {name}", eq, f"Lagrange's equation with dissipation for {name}: "
              "Lagrange's equations of the second kind of T, Π, Φ and δA.",
              "The model is linear already (quadratic T, Π, Φ with constant coefficients), "
              "so the paper's 'first approximation' changes nothing." if i == 0 else "",
              "Equations of motion" if i == 0 else "")


def steady_running(d: Derivation, eqs: dict) -> sp.Expr:
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


def frequencies(d: Derivation, eqs: dict) -> None:
    """(13)–(14): relative vibrations of the drum and the drive chain's frequencies."""
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
    d.add("(13), k", sp.Eq(notation.k, c**sp.Rational(1, 4)),
          "Vieta: ω1²·ω2² = C1·C2·(I1 + I2 + I3)/(I1·I2·I3); its fourth root, the geometric "
          "mean of ω1 and ω2, is the one frequency of the printed shape.")
    label, statement = pub.printed_homogeneous()
    d.add(label, statement, "The print's (13) with its right-hand side set to zero.",
          "(14) should solve this.")
    d.add("(14)", sp.Eq(y, notation.y_h + notation.y_p),
          "A linear equation's general solution: homogeneous plus particular.")
    Cc, Cs = sp.symbols("C_c C_s")
    y_h, k = notation.y_h, notation.k
    free = solve_constant_coefficient(sp.Eq(_dot(y_h, 2) + k**2 * y_h, 0), y_h, (Cc, Cs))
    shifted = notation.A_y * sp.sin(notation.k * t + notation.a_ph)
    assert sp.simplify(sp.expand_trig(shifted) - free.general.subs(
        {Cc: notation.A_y * sp.sin(notation.a_ph), Cs: notation.A_y * sp.cos(notation.a_ph)})) == 0
    d.add("(14), y1", sp.Eq(notation.y_h, shifted),
          "dsolve of ÿ1 + k²·y1 = 0 gives C_c·cos kt + C_s·sin kt; C_c = A·sin a, "
          "C_s = A·cos a make it A·sin(kt + a).")


def torque_traction_load(d: Derivation, e: dict) -> None:
    """(17)–(21): shaft bending, drum torque, traction and the pulsating load."""
    w, x = notation.w, notation.x_ax
    d.add("(17)", sp.Eq(w.diff(x, 4) + notation.a17 * w.diff(t, 2) + notation.b17 * w.diff(x, t)
                        + notation.kappa * w.diff(x, 2), 0),
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


def initial_state(d: Derivation, rest: sp.Expr) -> None:
    """y at rest under the pretension; ``rest`` from ``steady_running``."""
    d.add("initial state", sp.Eq(y0, sp.factor(rest)),
          "(12) at rest under the pretension alone (M0 = 0, W = 0), solved for y.",
          "The equilibrium the drive starts from; the example's zero state is not it.",
          "Initial state of the example")
