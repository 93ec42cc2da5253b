"""Fig. 11's travel drive as components (``crane_sym.components``): the
start-up of the portal crane with backlash in both drives, derived by the
component machinery (Lagrange's equations of the parts, the modes of its
piecewise-linear system).

The paper (003, Fig. 11, Fig. 12, Table 1); everything reduced to the rim of
the running wheels, travel is +::

    motors, left  m_d --[ c, b, gap s ]--\\
                                           crane m_k   <- wind W_w, friction W_f
    motors, right m_d --[ c, b, gap s ]--/

Every gap is open on its trailing side at the start (twist u = x_motor −
x_crane = 0; the driving flank closes at u = s: ``contact = "negative"``, the
gap 0 < u < s). A side's motors follow the rheostat characteristics β_k (v0 −
v), β_k = β1 q^(k−1), the next one after each hold time, then the natural
one. The crane stands while the link forces minus the wind stay within its
friction (a brake engaged from t = 0, holding at rest within W_f), moves
forward or back against W_w ± W_f, and sticks again when its speed returns
to zero inside that band.

``hybrid.STARTUP`` builds its runs here.
"""
from __future__ import annotations

from typing import Mapping, Sequence

import numpy as np

from crane_sym.components import (Brake, Characteristic, ElasticLink, Mass, Model,
                                  Resistance)
from crane_sym.components.templates import Templates
from crane_sym.components.hybrid import ComponentSystem
from crane_sym.mechanics.phase_table import Affine
from crane_sym.mechanics.piecewise_linear import PiecewiseResult

__all__ = ["fig11_design", "fig11_model", "fig11_parts", "speed_index", "step_accelerations", "total_load"]

_NAME, _TITLE = "portal_startup", "Fig. 12: start-up with backlash"


def fig11_model(values: Mapping[str, float], holds: Sequence[float]) -> Model:
    """The three-mass drive of Fig. 11 from rim values by name: ``m_d`` (one
    side's motors), ``m_k`` (the crane), ``c_l`` and ``b`` (a link's stiffness
    and damping), ``s`` (its backlash), ``v0`` (no-load speed), ``beta_1`` and
    ``q`` (the first characteristic's slope and the ratio of the next),
    ``W_f``, ``W_w`` (friction and wind), optionally ``s_right`` (the right
    link's backlash, where it differs); one characteristic per hold time of
    ``holds`` [s], then the natural one (Table 1's start)."""
    return Model(fig11_parts(values, holds), name=_NAME, title=_TITLE)


def fig11_parts(values: Mapping[str, float], holds: Sequence[float]) -> list:
    """The parts of :func:`fig11_model` (its values and holds as there)."""
    v = values
    slopes = [v["beta_1"] * v["q"] ** k for k in range(len(holds) + 1)]
    parts = [Mass("left", v["m_d"]), Mass("right", v["m_d"]), Mass("crane", v["m_k"])]
    for side in ("left", "right"):
        gap = v.get("s_right", v["s"]) if side == "right" else v["s"]
        parts += [ElasticLink(f"link_{side}", "crane", side, v["c_l"], v["b"], gap,
                              contact="negative"),                  # Fig. 11: C_пр, gap
                  Characteristic(f"motors_{side}", side, v["v0"], slopes, list(holds))]
    if v["W_f"] > 0:
        parts.append(Brake("friction", "crane", v["W_f"]))          # Table 1: W_f
    if v["W_w"] != 0:
        parts.append(Resistance("wind", "crane", -v["W_w"]))       # Table 1: W_w, against
    return parts


#: The derived models the designs of a sweep take their derivation from, one
#: per structure (which gaps, friction, wind; the number of holds).
_TEMPLATES = Templates(_NAME, _TITLE)


def fig11_design(values: Mapping[str, float], holds: Sequence[float]) -> Model:
    """:func:`fig11_model` for a design of a sweep: the parts with this
    design's values, Lagrange's equations derived once per structure and
    shared (``Model.with_parts``), not derived again for every design."""
    return _TEMPLATES.design(fig11_parts(values, holds))


def speed_index(system: ComponentSystem, body: str) -> int:
    """The position of ``body``'s speed in the state of ``system``."""
    return system.v(system.assembly.place[body][0])


def step_accelerations(result: PiecewiseResult, system: ComponentSystem) -> np.ndarray:
    """The crane's mean acceleration over each start step [m/s²]: Δv_k / hold
    time (Table 1's a_k), the holds of the left side's characteristic."""
    holds = system.of_kind["characteristic"][0].part.holds
    edges = np.concatenate([[0.0], np.cumsum(holds)])
    speeds = result.state(edges)[:, speed_index(system, "crane")]
    return np.diff(speeds) / np.diff(edges)


def total_load(system: ComponentSystem) -> Affine:
    """F1 + F2, the force of both links on the crane, per mode as (w, k)."""
    return system.links_load((0, 1))
