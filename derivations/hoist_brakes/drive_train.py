"""Fig. 9's hoist as components (``crane_sym.components``): the emergency stop
of the paper's two-mass hoist with coupling backlash, derived by the
component machinery (Lagrange's equations of the parts, the rigid gear and
drum merged into one drum side, the modes of its piecewise-linear system).

The paper (001_544065b666a6bc39.txt, Table 1, Figs 4 and 9); the direction of
lowering is +::

    motor J1 --[ c, backlash δ·i_g ]-- shaft --gear i_g-- drum J2 --drum r, i_t-- hook m_h + m_p
    motor torque (steady, lost at t_M)               safety brake M_SB        weight
    service brake M_BB

The gearbox stiffness c sits at the motor shaft, the drum coupling's backlash
δ referred to it (δ·i_g); the motor holds the lowering load until its torque
is lost, the brakes engage after their delays t_SB, t_BB as steps and hold a
side at rest within their torque (the model text of ``model.py``). The
link's reference load is the rated static torque M_st = (m_h + m_r) g r/(i_g i_t),
so its load over the reference is the paper's M_G/M_st.

``hybrid.EMERGENCY_STOP`` builds its runs here; :func:`fig9_peak` (the
derivation's step "Fig. 9") too.
"""
from __future__ import annotations

from functools import partial
from typing import Hashable, Mapping

import numpy as np

from crane_sym.components import (Brake, Drum, ElasticLink, Gear, Gravity, Inertia, Mass,
                                  Model, Motor)
from crane_sym.components.templates import Templates
from crane_sym.mechanics.phase_table import Affine, HybridRun

__all__ = ["OMEGA1", "T_BB", "T_SB", "emergency_stop", "fig9_model", "rated_torque",
           "relative_torque", "table1_values"]

#: Table 1's motor speed n1 = 1500 1/min [rad/s] and brake delays t_SB, t_BB [s].
OMEGA1, T_SB, T_BB = 1500 * 2 * np.pi / 60, 0.1, 0.4


def rated_torque(values: Mapping[str, float]) -> float:
    """M_st = (m_h + m_r) g r/(i_g i_t), the rated static torque at the motor
    shaft [N m] (the paper's reference of M_G,rel, eq (3))."""
    return (values["m_h"] + values["m_r"]) * values["g"] * values["r"] / (
        values["i_g"] * values["i_t"])


def fig9_model(values: Mapping[str, float], damping: float = 0.0, t_M: float = 0.0) -> Model:
    """The hoist of Fig. 9 lowering the payload ``values["m_p"]``, from SI values
    by Table 1's names (J1, J2, m_h, m_p, m_r, r, i_g, i_t, g, c, delta, M_SB,
    M_BB, t_SB, t_BB; J1, J2 and the brake torques of the whole drive, see the
    model text), the mesh damped by ``damping`` [N m s/rad] (the paper states
    none), the motor's torque lost at ``t_M`` [s] (Fig. 3's Δt_M, 0 in Fig. 9).
    """
    v = values
    return _TEMPLATES.design([
        Inertia("motor", v["J1"]),                 # Table 1: motor shafts
        Inertia("shaft", 0.0),                     # gearbox input: no inertia of its own
        Inertia("drum", v["J2"]),                  # Table 1: drum shafts
        Mass("hook", v["m_h"] + v["m_p"]),         # Table 1: hook 10 t, load 52 t
        Gear("gearbox", "shaft", "drum", v["i_g"]),            # Table 1: i_g
        Drum("rope", "drum", "hook", v["r"], v["i_t"]),        # Table 1: r, tackle 8/2
        ElasticLink("coupling", "motor", "shaft", v["c"], damping,   # Table 1: c
                    backlash=v["delta"] * v["i_g"],  # Table 1: δ at the drum coupling, × i_g
                    reference=rated_torque(v)),
        Gravity("weight", "hook", v["g"]),
        Motor("drive", "motor", "steady", off_at=t_M),          # Fig. 3: torque lost
        Brake("safety", "drum", v["M_SB"], delay=v["t_SB"]),    # Table 1: M_SB, t_SB
        Brake("service", "motor", v["M_BB"], delay=v["t_BB"]),  # Table 1: M_BB, t_BB
    ])


#: The derived models of Fig. 9's hoist, one per structure: runs with other
#: values (payloads, the audit's box of damping and delay) share the derivation.
_TEMPLATES = Templates("hoist_fig9", "Fig. 9: emergency stop while lowering")


def table1_values(payload: float, g: float = 9.81, backlash_deg: float | None = None,
                  stiffness: float | None = None) -> dict[str, float]:
    """Table 1's values (SI, its names) lowering ``payload`` kg at n1, the
    backlash [deg] or the stiffness [N m/rad] changed where given."""
    from .model import TABLE1
    q = {k: float(x) for k, x in TABLE1.items()}
    q.update(g=g, m_p=payload, omega1=OMEGA1,
             delta=float(np.radians(q["backlash_deg"] if backlash_deg is None
                                    else backlash_deg)))
    if stiffness is not None:
        q["c"] = stiffness
    return q


def _over_reference(system, mode: Hashable) -> tuple[np.ndarray, float]:
    w, k = system.link_load(0)(mode)
    reference = system.assembly.links[0].reference
    return w / reference, k / reference


def relative_torque(system) -> Affine:
    """M_G/M_st per mode as (w, k): the coupling's load over its reference
    (the rated static torque), of a system built by :func:`fig9_model`."""
    return partial(_over_reference, system)


def emergency_stop(values: Mapping[str, float], duration: float, damping: float = 0.0,
                   t_M: float = 0.0) -> HybridRun:
    """The emergency stop of :func:`fig9_model` from steady lowering at
    ``values["omega1"]`` (the motor's speed, Table 1's n1) over ``duration``
    [s]; its output is M_G/M_st."""
    run = fig9_model(values, damping, t_M).hybrid_run(duration, "coupling", "motor",
                                                      values["omega1"])
    return HybridRun(run.system, run.mode, run.x0, run.t_end, run.schedule,
                     relative_torque(run.system))
