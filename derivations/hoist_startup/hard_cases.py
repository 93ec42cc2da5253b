"""Seeded hard cases of paper 002 for ``crane-sym accuracy``."""
from __future__ import annotations

import numpy as np


def hard_cases(points: int = 200, seed: int = 20261122) -> dict[str, dict[str, np.ndarray]]:
    """Seeded input grids where a naive closed form loses accuracy.

    Returns case name -> columns, one array per argument of the outputs
    (t, Omega, t_n, tau_0, theta, m1, m2, g, v0, C); a function ignores the
    columns it does not take. Ω is drawn on its own: the coefficients take it
    as an argument (from ``natural_frequency``).
    """
    rng = np.random.default_rng(seed)
    n = points
    log = lambda lo, hi, size=n: 10.0 ** rng.uniform(np.log10(lo), np.log10(hi), size)

    def typical() -> dict[str, np.ndarray]:
        return {"Omega": log(2.0, 60.0), "m1": log(1e2, 1e4), "m2": log(1e3, 5e4),
                "g": rng.uniform(9.80, 9.82, n), "v0": log(0.1, 1.0),
                "C": log(1e5, 1e8), "t_n": log(0.5, 3.0), "tau_0": log(5e-3, 0.5),
                "theta": log(1e-2, 2.0)}

    def near_and_long(cols: dict, window: np.ndarray) -> np.ndarray:
        """t within a decade of ``window`` (both sides of the switch) for half
        the points, Ωt from Ω·window/10 up to 1e3 (long times) for the rest."""
        near = window * log(0.1, 10.0)
        phase = 10.0 ** rng.uniform(np.log10(cols["Omega"] * window) - 1, 3.0)
        return np.where(np.arange(n) % 2 == 0, near, phase / cols["Omega"])

    def small_window(*names: str) -> dict[str, np.ndarray]:
        cols = typical()
        z = np.logspace(-9, 0, n)               # Ω·window
        rng.shuffle(z)
        for name in names:                      # windows of one size, within 0.3–3x
            cols[name] = z * log(0.3, 3.0) / cols["Omega"]
        cols["t"] = near_and_long(cols, cols[names[0]])
        return cols

    times = typical()
    times["t"] = np.logspace(-9, 3, n) / times["Omega"]

    switch = typical()
    z = 10.0 ** rng.uniform(-9, 2, n)           # Ω·window at the switch
    for name in ("t_n", "tau_0", "theta"):
        switch[name] = z * log(0.3, 3.0) / switch["Omega"]
    which = np.array(["t_n", "tau_0", "theta"])[np.arange(n) % 3]
    at = np.choose(np.arange(n) % 3, [switch["t_n"], switch["tau_0"], switch["theta"]])
    # θ = π/Ω switches the pulse maximum (47): a fifth of the rows sit there.
    pi_rows = np.arange(n) % 5 == 4
    switch["theta"] = np.where(pi_rows, np.pi / switch["Omega"], switch["theta"])
    at = np.where(pi_rows & (which == "theta"), switch["theta"], at)
    side = np.arange(n) // 3 % 3 - 1            # one ulp below, at, one ulp above
    switch["t"] = np.where(side < 0, np.nextafter(at, 0.0),
                           np.where(side > 0, np.nextafter(at, np.inf), at))

    masses = typical()
    masses["m1"] = np.logspace(-8, 8, n) * masses["m2"]
    masses["t"] = log(1e-9, 1e3) / masses["Omega"]

    limits = typical()
    limits["t"] = np.where(np.arange(n) % 2 == 0, 0.0, log(1e-30, 1e-9) / limits["Omega"])
    for name in ("t_n", "tau_0", "theta"):
        limits[name] = log(1e-15, 1e-9) / limits["Omega"]
    return {"Ω·t from 1e-9 to 1e3": times,
            "Ω·t_n from 1e-9 to 1": small_window("t_n"),
            "Ω·τ_0, Ω·θ from 1e-9 to 1": small_window("tau_0", "theta"),
            "Ω·t_n = Ω·τ_0 from 1e-9 to 1": small_window("t_n", "tau_0"),
            "t at t_n, τ_0, θ, π/Ω ± 1 ulp": switch,
            "m1/m2 from 1e-8 to 1e8": masses,
            "t = 0, Ω·t and Ω·windows < 1e-9 (0/0)": limits}
