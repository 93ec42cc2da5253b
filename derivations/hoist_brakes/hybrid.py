"""The piecewise-linear model of paper 001 behind the common interface
(``crane_sym.mechanics.hybrid_models``): Fig. 9's emergency stop of the
two-mass hoist with coupling backlash and brakes that stick.

The system (modes, guards, switching) is the component model of
``drive_train.fig9_model`` (``crane_sym.components``: Table 1's motor shafts,
gearbox, drums, rope and hook as parts, the drive derived from them); this
module says how a scene's or a design's values build its run and which
outputs it has. Scenes (the tabulated ``elastic_gearbox_torque`` of
``outputs.py``, the report's hook-only run), design sweeps
(``sweep_outputs.py``) and the bench reach it only through
``HYBRID_MODELS``.
"""
from __future__ import annotations

from typing import Any, Mapping

from crane_sym.mechanics.hybrid_models import HybridModel, HybridOutput
from crane_sym.mechanics.phase_table import HybridRun

from .drive_train import emergency_stop, relative_torque

__all__ = ["EMERGENCY_STOP", "HYBRID_MODELS"]


def _emergency_stop(values: Mapping[str, float], settings: Mapping[str, Any]) -> HybridRun:
    """The emergency stop while lowering the payload ``values["m_p"]`` from ω1,
    motor torque lost at t = 0, brakes after t_SB and t_BB, up to the setting
    ``duration``; its output is M_G/M_st."""
    return emergency_stop(values, settings["duration"])


#: Fig. 9: the two-mass hoist lowering m_p, stopped (Table 1's names, SI).
EMERGENCY_STOP = HybridModel(
    "emergency_stop",
    "Emergency stop while lowering m_p: motor torque lost at t = 0, safety brakes after "
    "t_SB, service brakes after t_BB, the coupling backlash delta between the motor shafts "
    "and the drum side (Fig. 9).",
    ("J1", "J2", "m_h", "m_p", "m_r", "r", "i_g", "i_t", "g", "c", "delta", "M_SB", "M_BB",
     "t_SB", "t_BB", "omega1"),
    ("duration",),
    _emergency_stop,
    {"relative_torque": HybridOutput(
        "1", "gearbox torque over the rated static torque, M_G/M_st (negative: the drum "
        "side drives the motor shafts)", relative_torque, magnitude=True)},
)

#: The paper's piecewise-linear models, by name.
HYBRID_MODELS = {EMERGENCY_STOP.name: EMERGENCY_STOP}
