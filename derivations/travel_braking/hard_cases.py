"""The seeded hard cases of paper 000 for ``crane-sym accuracy``: input grids
where a naive closed form of (13)–(14) loses accuracy.
"""
from __future__ import annotations

import numpy as np


def hard_cases(points: int = 400, seed: int = 20261121) -> dict[str, dict[str, np.ndarray]]:
    """Seeded input grids where a naive closed form loses accuracy.

    Returns case name -> columns (one array per argument of the outputs).
    """
    rng = np.random.default_rng(seed)

    def typical(n: int) -> dict[str, np.ndarray]:
        log = lambda lo, hi: 10.0 ** rng.uniform(np.log10(lo), np.log10(hi), n)
        return {"m1": log(1e2, 1e5), "m2": log(1e3, 1e6), "c": log(1e5, 1e9),
                "P_t": log(1e4, 1e6), "W": log(1e2, 1e4), "v0": log(0.1, 5.0)}

    def with_phase(cols: dict, phase: np.ndarray) -> dict:
        m1, m2, c = cols["m1"], cols["m2"], cols["c"]
        return {**cols, "t": phase / np.sqrt(c * (m1 + m2) / (m1 * m2))}

    n = points
    small_large = with_phase(typical(n), np.logspace(-9, 3, n))
    ratio = typical(n)
    ratio["m1"] = np.logspace(-6, 6, n) * ratio["m2"]
    ratio = with_phase(ratio, 10.0 ** rng.uniform(-9, 3, n))
    cancel = typical(n)
    cancel["W"] = cancel["P_t"] * cancel["m2"] / cancel["m1"] * (1 + np.logspace(-12, -1, n))
    cancel = with_phase(cancel, 10.0 ** rng.uniform(-3, 1, n))
    return {"p·t from 1e-9 to 1e3": small_large,
            "m1/m2 from 1e-6 to 1e6": ratio,
            "P_t·m2 − W·m1 cancels (1e-12 … 1e-1)": cancel}
