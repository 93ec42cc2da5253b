"""The generic events of a component model switched for k designs at once
(:func:`switched`): a group coming to rest (held, or sliding on the way its
load pushes), a held group slipping, a law's next piece. The new state is a
simple function of x, so one pass over the designs' arrays does it. A
kind's own rule that sets the mode from the mode alone (``Events.plain``: a
contact closing, a characteristic's next step) is asked once for all the
designs, and a rule a kind gives for k designs at once (``Events.together``:
a brake engaging) on them all; the other rules of a kind and a first-order
limit's switch are Python per design, and left to the caller (None).
"""
from __future__ import annotations

from dataclasses import replace

import numpy as np

from crane_sym.components.design_arrays import DesignArray
from crane_sym.components.modes import BACKWARD, FORWARD, Mode

__all__ = ["switched"]


def switched(array: DesignArray, mode: Mode, event: str, x: np.ndarray
             ) -> tuple[list[Mode], np.ndarray] | None:
    """Each design's next mode and its state after ``event`` (x: (k, size),
    changed in place: floats, or mpmath numbers in an exact replay), or None
    where the event is a kind's own or a limit's (switched per design)."""
    system = array.model
    if event in system.plain:                 # the mode's rule, the same for every design
        rule, i = system.rules[event]
        return [rule(system, mode, i, x[0])[0]] * array.k, x
    if event in system.together:              # a kind's rule for the designs at once
        rule, i = system.together[event]
        return rule(array, mode, i, x)
    if event in system.rules or system.events[event][0] not in ("rest", "slip+", "slip-",
                                                               "piece"):
        return None
    kind, i = system.events[event]
    if kind == "piece":
        pieces = list(mode.pieces)
        pieces[i] += 1
        start = system.clock.offsets[i]
        x[:, start:start + system.clock.laws[i].degree] = 0.0
        if i in system.moved:          # a speed law sets its group's speed to the new piece's
            g = system.moved[i][0]
            row = array.pieces[i][:, min(pieces[i], array.pieces[i].shape[1] - 1)]
            x[:, system.v(g)] = row[:, 0] / array.kappas[:, list(system.moved).index(i)]
        return [replace(mode, pieces=tuple(pieces))] * array.k, x
    x[:, system.v(i)] = 0.0
    if kind == "rest":
        motions = array.settled(mode, i, x)
        kept = {m: mode.moving(i, m) for m in set(motions)}    # each new mode made once
        return [kept[m] for m in motions], x
    return [mode.moving(i, FORWARD if kind == "slip+" else BACKWARD)] * array.k, x
