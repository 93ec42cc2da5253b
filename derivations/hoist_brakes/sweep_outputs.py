"""Responses of paper 001 that a design sweep maps over its grid.

The emergency stop with coupling backlash (Fig. 9) has phases whose number
and ends depend on the design, so a sweep solves each design's run phase by
phase in closed form (``elastic.py``, ``crane_sym.mechanics.piecewise_linear``), with
the numeric eigenvector route of the closed forms (each design has new
matrices; SymPy's exact Jordan form would cost ~0.2 s a design). A sweep of
it gains only parallelism, not the closed forms' vectorisation.
"""
from __future__ import annotations

from dataclasses import replace

import numpy as np

from crane_sym.derivation import SweepOutput

_PARAMETERS = ("J1", "J2", "m_h", "m_p", "m_r", "r", "i_g", "i_t", "g", "c", "delta",
               "M_SB", "M_BB", "t_SB", "t_BB", "omega1")


def _peak_elastic_gearbox_torque(values, options) -> np.ndarray:
    """max |M_G/M_st| of the emergency stop while lowering m_p, over the
    scene's duration, one piecewise closed-form run per design."""
    from .elastic import hoist_from

    names = list(values)
    arrays = np.broadcast_arrays(*[np.asarray(values[n], dtype=float) for n in names])
    out = np.empty(arrays[0].shape)
    for index in np.ndindex(out.shape):
        q = {n: float(a[index]) for n, a in zip(names, arrays)}
        hoist = hoist_from(q, q["m_p"])
        run = replace(hoist.emergency_stop(q["omega1"], options["duration"], 0.0, q["t_SB"],
                                           q["t_BB"]), exact=False)
        out[index] = abs(hoist.peak(run.solve())[1])
    return out


SWEEP_OUTPUTS = {
    "peak_elastic_gearbox_torque": SweepOutput(
        "peak_elastic_gearbox_torque", "1",
        "Largest |M_G/M_st| of the emergency stop while lowering, elastic drive with the "
        "coupling backlash (Fig. 9), phases in closed form", _PARAMETERS, (),
        _peak_elastic_gearbox_torque),
}
