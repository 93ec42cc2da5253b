"""The start-up of the travel drive with backlash (Fig. 11, Table 1, Fig. 12): the
parameters chosen for Table 1's drive, their reduction to the rim of the running
wheels, and the model's Table 1 (peak link force, its time, ψ, the crane's mean
acceleration per start step) with its range over the box of what the paper does not state.

The drive itself is built from components (``drive_train.fig11_design``, derived
once per structure and shared by the designs of the sensitivity sweep: three
masses, two elastic links with backlash, a stepped rheostat start, the crane held
by its friction) and solved phase by phase in closed form by
``crane_sym.mechanics.piecewise_linear``; scenes, sweeps and the bench reach the
same model through ``hybrid.py`` (``STARTUP``).
"""
from __future__ import annotations

import hashlib
from functools import partial

import numpy as np

from crane_sym.mechanics.phase_table import largest
from crane_sym.sensitivity import OPTIMISER_RUNS, STEP, Chosen, Extreme, Sensitivity, sweep

from .drive_train import fig11_design, step_accelerations, total_load


#: The parameters chosen for Table 1's drive (SI; reasons in the model text).
CHOSEN = {"J_r": 0.225, "n_m": 2.0, "omega_n": 935 * np.pi / 30, "omega_0": 1000 * np.pi / 30,
          "v_n": 32 / 60, "P_m": 13e3, "lambda_p": 2.0, "c_l": 5e6, "zeta": 0.05,
          "m_k": 250e3, "W_f": 30e3, "W_w": 30e3}
#: Table 1's hold times [s], its backlash values [rad of the fast shaft], F_ср [N].
HOLDS, BACKLASH, F_MEAN = (0.4, 0.8, 0.8), {"0": 0.0, "pi": np.pi, "2pi": 2 * np.pi}, 150e3


def reduced(p: dict[str, float], phi_b: float) -> dict[str, float]:
    """The rim quantities of the steps (m_d, P_n, v0, β1, q, s, b) from ``p``."""
    m_d = p["n_m"] * p["J_r"] * (p["omega_n"] / p["v_n"]) ** 2
    P_n = p["n_m"] * p["P_m"] / p["v_n"]
    v0 = p["v_n"] * p["omega_0"] / p["omega_n"]
    if not v0 > p["v_n"]:
        raise ValueError("omega_0 must exceed omega_n (the no-load speed is above the rated)")
    return {"m_d": m_d, "P_n": P_n, "v0": v0, "beta_1": p["lambda_p"] * P_n / v0,
            "q": (v0 / (p["lambda_p"] * (v0 - p["v_n"]))) ** (1 / 3),
            "s": phi_b * p["v_n"] / p["omega_n"], "b": 2 * p["zeta"] * np.sqrt(p["c_l"] * m_d)}


#: The parameters of ``CHOSEN`` the paper does not state, with the range each could
#: plausibly take (the others follow from the text: the motor MTF311-6 and its
#: speeds, two per side to cover the stated 60 kN, 30 kN of friction and wind).
PLAUSIBLE = (
    Chosen("J_r", "rotor inertia J_r", "kg·m²", 0.225, 0.2, 0.3, "the MTF311-6 catalogue "
           "rotor, up to a coupling or brake pulley more on the fast shaft"),
    Chosen("v_n", "rated travel speed v_n", "m/min", 32, 25, 40, "portal cranes travel at "
           "25–40 m/min", scale=1 / 60),
    Chosen("lambda_p", "starting-force multiple λ", "", 2.0, 1.6, 2.4, "a relay start, "
           "below the MTF311-6's breakdown multiple of about 2.4"),
    Chosen("c_l", "link stiffness C_пр", "MN/m", 5, 2, 10, "10–50 mm of longitudinal "
           "deflection of a portal side under 100 kN", scale=1e6),
    Chosen("zeta", "damping ratio ζ of a link", "", 0.05, 0.02, 0.1, "a logarithmic "
           "decrement of about 0.1–0.6"),
    Chosen("m_k", "crane mass m_к", "t", 250, 200, 300, "the stated 30 kN of friction at a "
           "specific resistance of 0.010–0.015", scale=1e3),
)


def table1_results(t_end: float = 4.0, p: dict[str, float] | None = None,
                   gaps: tuple[str, ...] = tuple(BACKLASH)) -> dict[str, dict[str, float]]:
    """Per backlash of Table 1 (those of ``gaps``): F_max [kN], its time [s],
    ψ = F_max/F_ср, the crane's mean acceleration over each start step [m/s²];
    with the parameters ``p`` (default: ``CHOSEN``)."""
    p = CHOSEN if p is None else p
    out = {}
    for name in gaps:
        values = {**reduced(p, BACKLASH[name]), **{k: p[k] for k in ("m_k", "c_l", "W_f", "W_w")}}
        run = fig11_design(values, HOLDS).hybrid_run(t_end, rest=True)   # derived once
        result = run.solve()
        when, peak = largest(result, run.system, total_load(run.system))
        acc = step_accelerations(result, run.system)
        out[name] = {"F_max_kN": peak / 1e3, "t_max": when, "psi": peak / F_MEAN,
                     **{f"a{k + 1}": float(a) for k, a in enumerate(acc)}}
    return out


def _numbers(gap: str, p: dict[str, float]) -> dict[str, float]:
    """The Table 1 numbers of one backlash by name (``"F_max, pi"``, ...)."""
    r = table1_results(p=p, gaps=(gap,))[gap]
    return {f"F_max, {gap}": r["F_max_kN"], f"psi, {gap}": r["psi"],
            **{f"a{k}, {gap}": r[f"a{k}"] for k in (1, 2, 3)}}


def table1_sensitivities(committed: bool = True) -> dict[str, Sensitivity]:
    """How far each of the model's Table 1 numbers moves when the parameters of
    ``PLAUSIBLE`` go over their ranges together: ``"F_max, <backlash>"``,
    ``"psi, <backlash>"``, ``"a<k>, <backlash>"`` -> Sensitivity (one box per
    backlash, so the optimiser of a number runs that backlash's start-up alone).

    The boxes' extremes (about 700 start-ups, minutes) come from the committed
    table ``box_extremes.py`` where it was found for these inputs
    (:func:`box_inputs`), else, and with ``committed=False``, from the runs;
    ``tests/test_portal_box.py`` runs every extreme at its place and studies
    the box of backlash 0 again."""
    from .box_extremes import EXTREMES, INPUTS
    known = ({name: tuple(Extreme(v, at, by) for v, at, by in ends)
              for name, ends in EXTREMES.items()}
             if committed and INPUTS == box_inputs() else {})
    return {name: s for gap in BACKLASH
            for name, s in sweep(partial(_numbers, gap), PLAUSIBLE, CHOSEN, known).items()}


def box_inputs() -> str:
    """Digest of what the boxes' extremes depend on beside the model's code: the
    chosen values, the ranges, the backlash values, the holds and the
    optimiser's settings."""
    text = repr((sorted(CHOSEN.items()), PLAUSIBLE, sorted(BACKLASH.items()), HOLDS,
                 OPTIMISER_RUNS, STEP))
    return hashlib.sha256(text.encode()).hexdigest()
