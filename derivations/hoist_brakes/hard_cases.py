"""The seeded hard cases of paper 001 for ``crane-sym accuracy``: payload → 0,
MF → 1 (drum side and load vanishing against the motors), φ5 → 1, tiny and
huge stiffness, backlash → 0, brake delays at the stop instants; the safety
brakes alone always hold the load (the rigid stopping time exists).
"""
from __future__ import annotations

import numpy as np


def hard_cases(points: int = 400, seed: int = 20261123) -> dict[str, dict[str, np.ndarray]]:
    """Seeded input grids (case name -> one column per argument of the outputs)."""
    rng = np.random.default_rng(seed)
    n = points

    def log(lo: float, hi: float) -> np.ndarray:
        return 10.0 ** rng.uniform(np.log10(lo), np.log10(hi), n)

    def typical() -> dict[str, np.ndarray]:
        return {"m_p": log(1e2, 1e5), "J1": log(1.0, 200.0), "J2": log(10.0, 5e3),
                "m_h": log(1e2, 1e5), "m_r": log(1e3, 1e5), "r": log(0.1, 2.0),
                "i_g": log(5.0, 100.0), "i_t": log(1.0, 8.0), "g": np.full(n, 9.81),
                "omega1": log(10.0, 400.0), "d_t": log(0.1, 10.0), "phi5": log(1.0, 2.0),
                "MF": rng.uniform(0.0, 1.0, n), "LF": log(0.01, 1.0), "BF_SB": log(0.5, 5.0),
                "M_SB": log(1e4, 1e6), "M_BB": log(1e3, 1e5), "t_SB": log(1e-3, 0.5),
                "t_BB": log(1e-3, 1.0), "t": log(1e-3, 2.0), "c": log(1e3, 1e7),
                "delta": log(1e-3, 0.2)}

    empty = typical()
    empty["m_p"] = np.logspace(-12, 2, n)                 # payload -> 0
    motor = typical()
    motor["MF"] = 1 - np.logspace(-14, -1, n)               # MF -> 1
    motor["J2"] = motor["J1"] * np.logspace(-12, -2, n)     # drum side vanishing
    motor["m_h"] = np.logspace(-6, 1, n)
    motor["m_p"] = np.logspace(-8, 0, n)
    stiff = typical()
    stiff["c"] = np.logspace(-6, 12, n)                     # tiny to huge stiffness
    stiff["delta"] = np.logspace(-15, -1, n)                # backlash -> 0
    stiff["phi5"] = 1 + np.logspace(-15, -1, n)             # phi5 -> 1
    cases = {"payload from 1e-12 kg": empty, "MF -> 1 (drum side, load -> 0)": motor,
             "stiffness 1e-6..1e12, backlash and phi5 - 1 -> 0": stiff}
    for case in cases.values():     # brakes that can stop the drive (else no stopping time)
        held = case["g"] * case["r"] * (case["m_h"] + case["m_p"]) / case["i_t"]
        case["M_SB"] = np.maximum(case["M_SB"], 2.0 * held)
    return cases
