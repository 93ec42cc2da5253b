"""Simulated responses of paper 004 that a design sweep can map over its grid.

The drum drive has no closed-form time response under the pulsating load
(21): each design is integrated with the generated state derivative and
Jacobian of (12) (``report.rhs_functions``), as ``crane-sym run`` does for the
example of Fig. 3. A sweep of it gains only parallelism (one integration per
design), not the closed forms' vectorisation.
"""
from __future__ import annotations

import numpy as np

from crane_sym.derivation import SweepOutput

#: Integrator settings of a swept design (LSODA with the generated Jacobian).
RTOL, ATOL = 1e-9, 1e-12
_PARAMETERS = ("I1", "I2", "I3", "C1", "C2", "C_y", "C_t", "C_z", "q", "L", "M0", "F0", "D",
               "F1_t", "F2_t", "F3_t", "F4_t", "K1", "K2", "K3", "K4", "t_3")
_OPTIONS = ("m3", "m_L", "nu1", "nu2", "nu_y", "nu_z", "nu_t")


def _max_drum_shaft_deflection(values, options) -> np.ndarray:
    """max |y(t)| over the scene's time samples on [0, duration], one
    LSODA integration of the Fig. 3 start per design."""
    import importlib

    from scipy.integrate import solve_ivp

    from .report import argument_orders, rhs_functions

    generated = importlib.import_module("crane_sym.generated.drum_drive")
    make = rhs_functions(generated)
    load_args = argument_orders(generated)["pulsating_force"][1:]
    names = list(values)
    arrays = np.broadcast_arrays(*[np.asarray(values[n], dtype=float) for n in names])
    times = np.linspace(0.0, options["duration"], int(options["points"]))
    out = np.empty(arrays[0].shape)
    for index in np.ndindex(out.shape):
        p = {n: float(a[index]) for n, a in zip(names, arrays)}
        p["r"] = p["D"] / 2
        load_values = [p[a] for a in load_args]

        def load(t, load_values=load_values):
            return generated.pulsating_force(t, *load_values)

        rhs, jac, _, _ = make(p, load)
        sol = solve_ivp(rhs, (0.0, times[-1]), np.zeros(12), method="LSODA", jac=jac,
                        t_eval=times, rtol=RTOL, atol=ATOL)
        if not sol.success:
            raise RuntimeError(f"solve_ivp failed at {p}: {sol.message}")
        out[index] = np.max(np.abs(sol.y[3]))
    return out


SWEEP_OUTPUTS = {
    "max_drum_shaft_deflection": SweepOutput(
        "max_drum_shaft_deflection", "m",
        "Largest drum-shaft deflection |y| of the start under the load (21) (Fig. 3), "
        "simulated", _PARAMETERS, _OPTIONS, _max_drum_shaft_deflection),
}
