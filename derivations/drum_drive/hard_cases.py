"""Hard-case grids for the generated functions of paper 004 (``crane-sym accuracy 004``).

Seeded columns, one array per argument; a function takes the columns it needs.
The grids span inertia, stiffness and force ratios of 1e-8 … 1e8, a drive
chain whose two elastic frequencies nearly coincide (C1/I1 = C2/I3 with a
heavy intermediate mass: the textbook discriminant b² − 4c cancels and can go
negative), branch forces with F1 ≈ F2 (the torque and the traction margin
cancel; their condition number is printed beside the error), and times from
1e-9 s to 1e3 s for the pulsating load (21).
"""
from __future__ import annotations

import numpy as np

SEED = 20261121


def hard_cases(points: int = 300, seed: int = SEED) -> dict[str, dict[str, np.ndarray]]:
    """Case name -> columns, for every scalar output of ``drum_drive``."""
    rng = np.random.default_rng(seed)

    def log(lo: float, hi: float) -> np.ndarray:
        return 10.0 ** rng.uniform(np.log10(lo), np.log10(hi), points)

    ratios = {"I1": log(1e-8, 1e8), "I2": log(1e-8, 1e8), "I3": log(1e-8, 1e8),
              "C1": log(1e-8, 1e8), "C2": log(1e-8, 1e8), "q": log(1e-3, 1e3),
              "L": log(1e-2, 1e3), "M0": log(1.0, 1e6), "D": log(0.1, 5.0),
              "F0": log(1.0, 1e6), "C_t": log(1e-3, 1e13), "C_z": log(1e-3, 1e13),
              "C_y": log(1e-3, 1e13), "F1": log(1.0, 1e6), "mu": log(0.05, 1.0),
              "alpha": log(0.5, 10.0), "t": log(1e-9, 1e3), "t_3": log(0.1, 10.0),
              **{f"F{i}_t": log(1.0, 1e4) for i in range(1, 5)},
              **{f"K{i}": log(1.0, 1e4) for i in range(1, 5)}}
    ratios["F2"] = ratios["F1"] * 10.0 ** rng.uniform(-8, 8, points)
    close = dict(ratios, F2=ratios["F1"] * (1 + np.logspace(-12, -1, points)))
    degenerate = dict(ratios, I2=log(1e6, 1e12))
    degenerate["C2"] = degenerate["C1"] * degenerate["I3"] / degenerate["I1"]
    return {"ratios 1e-8 … 1e8": ratios,
            "F1/F2 − 1 from 1e-12 to 1e-1": close,
            "chain frequencies nearly equal": degenerate}
