"""Paper 004's outputs: the generated functions (in the paper's symbols), the
state derivative and Jacobian of (12) for SciPy, the "damping" switch, the
bench's parameter values and the ODE system the bench integrates.
"""
from __future__ import annotations

import sympy as sp

from crane_sym.derivation import Derivation, ODESystem, Output, Switch

from .model import (
    C1, C2, C_t, C_y, C_z, COORDS, D, DAMPERS, F0, F1, F1_t, F2, F2_t, F3_t, F4_t, I1,
    I2, I3, K1, K2, K3, K4, L, M0, STATE, W, alpha, model_energies, mu, q, r, t, t_3, y,
    z)


def outputs(d: Derivation) -> list[Output]:
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
    # each row of f over one denominator (cancel): factoring its numerator,
    # linear in all ten states, took seconds and found no shorter form
    J, f = J.applyfunc(sp.factor), f.applyfunc(sp.cancel)

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


# --- Switches ----------------------------------------------------------------
def damping_switch() -> Switch:
    """Switch "damping": the model without the Rayleigh dissipation Φ of (11)."""
    return Switch(
        "damping", "the Rayleigh dissipation Φ of (11)",
        tuple((nu, sp.S.Zero) for nu in DAMPERS))


# --- Bench -------------------------------------------------------------------
#: Values the bench gives to arguments no scene sets [SI]: the drum radius from
#: the scene's D, and one state and load of the order the example reaches
#: (the grid of time-free functions perturbs each by a factor 1/2 ... 2).
BENCH_PARAMETERS = {r: D / 2, W: sp.Float(1.0e3),
                    **dict(zip(STATE, map(sp.Float, (10.0, 10.0, 10.0, 1e-3, 2.5,
                                                     16.0, 16.0, 16.0, 1e-2, 4.0))))}


def load_response(d: Derivation) -> ODESystem:
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

