"""The piecewise-linear model of paper 003 behind the common interface
(``crane_sym.mechanics.hybrid_models``): the start-up of the three-mass travel
drive with backlash in both drives (Fig. 11, Fig. 12, Table 1).

The system (modes, guards, switching) is the component model of
``drive_train.fig11_design`` (``crane_sym.components``: the motors of each
side, the crane, the two links with backlash, the characteristics, friction
and wind as parts, the drive derived from them); this module says how a
scene's values build its run and which outputs it has. The values are the drive at the wheel rim: ``m_d``, ``b``, ``v0``,
``beta_1``, ``q`` and the backlash ``s`` at the rim, with the scene's ``m_k``,
``c_l``, ``W_f``, ``W_w``. A start-up scene's module tabulates its curves, one
run per backlash of the scene (:func:`scene_runs`, the rim quantities from
``startup.reduced``); the report takes its numbers from the same model run in
double on the rim quantities of the scene's module (``outputs.startup_outputs``).
Scenes, and through them the bench, reach it only through ``HYBRID_MODELS``.
"""
from __future__ import annotations

from functools import partial
from typing import Any, Hashable, Mapping

import numpy as np

from crane_sym.components.hybrid import ComponentSystem
from crane_sym.mechanics.hybrid_models import HybridModel, HybridOutput
from crane_sym.mechanics.phase_table import Affine, HybridRun

from .drive_train import fig11_design, speed_index, total_load
from .startup import reduced

__all__ = ["HYBRID_MODELS", "STARTUP", "rim_values", "scene_runs"]


def _start_up(values: Mapping[str, float], settings: Mapping[str, Any]) -> HybridRun:
    """The start-up from rest, gaps open on the trailing side, one
    characteristic per hold time of the setting ``holds`` then the natural
    one, up to the setting ``end`` [s]; its output is F1 + F2. The drive's
    equations are derived once and shared by every run (``fig11_design``), so
    a run here is the run of Table 1 and of the sweeps to the last bit."""
    return fig11_design(values, tuple(settings["holds"])).hybrid_run(settings["end"],
                                                                     rest=True)


def _left_link(system: ComponentSystem) -> Affine:
    return system.link_load(0)


def _component(index: int, size: int, mode: Hashable) -> tuple[np.ndarray, float]:
    return np.eye(size)[index], 0.0


def _speed(body: str, system: ComponentSystem) -> Affine:
    return partial(_component, speed_index(system, body), system.size)


#: Fig. 12: the three-mass drive starting on the stepped rheostat (rim quantities, SI).
STARTUP = HybridModel(
    "start_up",
    "Start-up from rest of the three-mass travel drive, both links with the backlash s at "
    "the rim, the start steps held for the setting holds, up to the setting end (Fig. 12).",
    ("m_d", "m_k", "c_l", "b", "s", "v0", "beta_1", "q", "W_f", "W_w"),
    ("holds", "end"),
    _start_up,
    {"load": HybridOutput("N", "F1 + F2, the force of both links on the crane",
                          total_load),
     "left_link_load": HybridOutput("N", "F1, the force of one link (left side)", _left_link),
     "motor_speed": HybridOutput("m/s", "v1, the speed of one side's motors at the rim",
                                 partial(_speed, "left")),
     "crane_speed": HybridOutput("m/s", "v_k, the speed of the crane", partial(_speed, "crane"))},
)

#: The paper's piecewise-linear models, by name.
HYBRID_MODELS = {STARTUP.name: STARTUP}


def rim_values(parameters: Mapping[str, float], phi_b: float) -> dict[str, float]:
    """STARTUP's values from a scene's parameters (Table 1's chosen names,
    ``startup.CHOSEN``) and the backlash ``phi_b`` of the fast shaft [rad]: the
    rim quantities of ``startup.reduced`` with ``m_k``, ``c_l``, ``W_f``, ``W_w``."""
    return {**reduced(parameters, phi_b),
            **{k: parameters[k] for k in ("m_k", "c_l", "W_f", "W_w")}}


def scene_runs(output: str, parameters: Mapping[str, float],
               settings: Mapping[str, Any]) -> tuple[HybridRun, ...]:
    """One run of STARTUP with the output ``output`` per backlash of a start-up
    scene's setting ``backlash``, start steps held for ``holds``, up to ``end``:
    what the scene's module tabulates (``outputs.tabulated``)."""
    timing = {"holds": tuple(settings["holds"]), "end": settings["end"][0]}
    return tuple(STARTUP.run(rim_values(parameters, phi), timing, output)
                 for phi in settings["backlash"])
