"""Responses of paper 001 that a design sweep maps over its grid.

The emergency stop with coupling backlash (Fig. 9) has phases whose number
and ends depend on the design, so a sweep solves each design's run phase by
phase in closed form (``hybrid.EMERGENCY_STOP``, through
``HybridModel.peak_sweep``), with the numeric eigenvector route of the closed
forms (each design has new matrices; SymPy's exact Jordan form would cost
~0.2 s a design). A sweep of it gains only parallelism, not the closed forms'
vectorisation.
"""
from __future__ import annotations

from crane_sym.derivation import SweepOutput

from .hybrid import EMERGENCY_STOP

SWEEP_OUTPUTS = {
    "peak_elastic_gearbox_torque": SweepOutput(
        "peak_elastic_gearbox_torque", "1",
        "Largest |M_G/M_st| of the emergency stop while lowering, elastic drive with the "
        "coupling backlash (Fig. 9), phases in closed form", EMERGENCY_STOP.parameters, (),
        EMERGENCY_STOP.peak_sweep("relative_torque")),
}
