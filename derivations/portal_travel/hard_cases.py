"""The seeded hard cases of paper 003 for ``crane-sym accuracy``: small pressure
angles (tan a − a cancels), shifts near the pointed tip (with a no-load speed just
above the rated, for the start-up's slope ratio), large tooth numbers.

Every case gives every argument of every generated function, consistent with a
possible mesh (a_w above the base-circle sum, tips outside the base circles).
"""
from __future__ import annotations

import numpy as np

from crane_sym.mechanics.involute import involute_np, tip_shift_np


def _gear(rng: np.random.Generator, n: int, z_lo: float, z_hi: float,
          alpha: np.ndarray, ratio_w: np.ndarray) -> dict[str, np.ndarray]:
    """Columns with the operating angle alpha_w = ratio_w*alpha."""
    log = lambda lo, hi: 10.0 ** rng.uniform(np.log10(lo), np.log10(hi), n)  # noqa: E731
    m, z1, z2 = log(1e-3, 5e-2), log(z_lo, z_hi), log(z_lo, z_hi)
    alpha_w = np.minimum(ratio_w * alpha, 1.4)
    a_w = m * (z1 + z2) * np.cos(alpha) / (2 * np.cos(alpha_w))
    x_sum = (involute_np(alpha_w) - involute_np(alpha)) * (z1 + z2) / (2 * np.tan(alpha))
    return {"m": m, "z1": z1, "z2": z2, "z": z1, "a_w": a_w, "alpha": alpha, "x_sum": x_sum,
            "h_a": rng.uniform(0.8, 1.25, n), "x1": rng.uniform(-0.3, 0.8, n),
            "x2": rng.uniform(-0.3, 0.8, n), "x": rng.uniform(-0.3, 0.8, n),
            "dy": rng.uniform(0, 0.2, n), "dy1": rng.uniform(0, 0.2, n),
            "dy2": rng.uniform(0, 0.2, n), "sigma": rng.uniform(0, 0.45, n),
            "psi": rng.uniform(1, 2, n), "G_g": log(5e4, 5e5), "G_pch": log(5e5, 3e6),
            "G_vs": log(1e5, 1e6), "L_max": log(15, 40), "x_o": log(0.5, 5),
            "c": log(3, 10)}


def _startup(rng: np.random.Generator, n: int) -> dict[str, np.ndarray]:
    """Columns of the start-up's arguments (their own generator: the gear cases
    keep their points)."""
    log = lambda lo, hi: 10.0 ** rng.uniform(np.log10(lo), np.log10(hi), n)  # noqa: E731
    return {"J_r": log(0.05, 1.0), "n_m": rng.integers(1, 5, n) * 1.0,
            "omega_n": log(50, 150), "omega_0": np.full(n, 160.0), "v_n": log(0.2, 1.0),
            "P_m": log(5e3, 5e4), "lambda_p": rng.uniform(1.2, 2.5, n),
            "c_l": log(1e6, 2e7), "zeta": log(0.01, 0.2), "m_k": log(1e5, 5e5),
            "W_f": log(1e4, 6e4), "W_w": log(1e3, 6e4), "phi_b": log(1e-3, 6.3),
            "t_s": log(1e-9, 1.0)}


def hard_cases(points: int = 60, seed: int = 20261123) -> dict[str, dict[str, np.ndarray]]:
    """Seeded input grids where a naive closed form or solver loses accuracy.

    Returns case name -> columns (one array per argument of the outputs).
    """
    rng = np.random.default_rng(seed)
    n = points
    typical = _gear(rng, n, 8, 150, rng.uniform(0.25, 0.45, n), rng.uniform(0.9, 1.3, n))
    small = _gear(rng, n, 8, 150, np.logspace(-4, -1, n), rng.uniform(1.0001, 2.0, n))
    near = _gear(rng, n, 8, 150, rng.uniform(0.3, 0.4, n), rng.uniform(0.9, 1.3, n))
    x_tip = tip_shift_np(near["z"], near["alpha"], near["h_a"], near["dy"], 0.0)
    near["x"] = x_tip * (1 - np.logspace(-10, -2, n))
    near["sigma"] = np.logspace(-12, -1, n)
    large = _gear(rng, n, 150, 1e5, rng.uniform(0.3, 0.4, n), rng.uniform(0.9, 1.3, n))
    start = np.random.default_rng(seed + 1)
    for case in (typical, small, near, large):
        case.update(_startup(start, n))
    # the start-up's no-load speed just above the rated (the slope ratio's ω0 − ω_n)
    near["omega_0"] = near["omega_n"] * (1 + np.logspace(-9, -1, n))
    return {"typical gears": typical,
            "small angles alpha 1e-4..1e-1": small,
            "shift near the pointed tip": near,
            "large tooth numbers 150..1e5": large}
