"""The ground contacts of a run: each one's mode at the start (resting where
the ground must push, off it where the start lifts its body) and its
reaction over the run, with its peak (:class:`ContactPeak`).

The reaction is no force of its own: it is what holds the resting group
still, R = s N/κ from the rest of its load N
(:meth:`crane_sym.components.hybrid.ComponentSystem.reaction`), 0 off the
ground.
"""
from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np

from crane_sym.components.hybrid import FREE, HELD, ComponentSystem, Mode
from crane_sym.components.parts import ROTATING, ComponentError
from crane_sym.mechanics.phase_table import largest
from crane_sym.mechanics.piecewise_linear import PiecewiseResult

__all__ = ["ContactPeak", "contact_peaks", "resting"]


@dataclass(frozen=True)
class ContactPeak:
    """The largest reaction of a ground contact over a run, when it occurs and
    its reaction at the start (the body's share of the ground's push)."""

    contact: str
    time: float
    value: float
    unit: str
    start: float


def resting(system: ComponentSystem, mode: Mode, x: np.ndarray) -> Mode:
    """``mode`` with each contact's group held where its body rests on the
    ground at the start (at x = 0, at rest, R ≥ 0) and free where it is lifted
    off it; ComponentError for a body started below the ground.

    Parameters
    ----------
    system : ComponentSystem
        The model's system.
    mode, x : Mode, ndarray
        The start's mode and state, at rest but for the initial states.
    """
    motion = list(mode.motion)
    for j, contact in enumerate(system.contacts):
        g = contact.group
        height = contact.part.sign * contact.kappa * float(x[system.q(g)])
        if height > 0:
            raise ComponentError(f"{contact.part.label}: its body starts "
                                 f"{height:.6g} (SI) below the ground (x = 0)")
        held = replace(mode, motion=tuple(HELD if i == g else m for i, m in enumerate(motion)))
        w, k = system.reaction(held, j)
        on = height == 0 and x[system.v(g)] == 0 and float(w @ x + k) >= 0
        motion[g] = HELD if on else FREE
    return replace(mode, motion=tuple(motion))


def contact_peaks(result: PiecewiseResult, system: ComponentSystem, mode: Mode,
                  x0: np.ndarray) -> list[ContactPeak]:
    """The peak reaction of every ground contact, in the order given.

    Parameters
    ----------
    result : PiecewiseResult
        The run.
    system : ComponentSystem
        Its system.
    mode, x0 : Mode, ndarray
        Its start.
    """
    out = []
    for j, contact in enumerate(system.contacts):
        when, peak = largest(result, system, system.contact_load(j))
        w, k = system.reaction(mode, j)
        body = system.assembly.bodies[contact.part.body]
        out.append(ContactPeak(contact.part.name, when, peak,
                               "N*m" if body.motion == ROTATING else "N", float(w @ x0 + k)))
    return out
