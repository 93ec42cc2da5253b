"""Initial states (``[[initial]]``, :class:`~crane_sym.components.loads.Initial`):
a body displaced from where the run's start puts it, or moving at a given
velocity, at t = 0.

.. code-block:: text

    [[initial]]
    name = "lifted"
    body = "hook"
    displacement = "-0.1 m"     # from where the start puts it (rad, deg on a shaft)
    velocity = "0 m/s"          # its velocity at t = 0 (rad/s, rpm on a shaft)

The start (:meth:`~crane_sym.components.model.Model.start`, steady or at rest)
places every rigid group; each initial state then moves its body's group by
displacement/κ and sets the group's speed to velocity/κ (κ: the body's
coordinate per unit of its group's). A link with backlash takes the contact
its new twist gives; a group that a brake holds at rest from t = 0 slides
when it is given a velocity. Refused in one line: an unknown body, a value of
the wrong dimension, two displacements or two velocities of one rigid group,
a velocity of a group a speed law moves, and a velocity beside a steady
start's nonzero [run] speed (which sets the speed of every group already).
"""
from __future__ import annotations

from dataclasses import dataclass, replace
from typing import Sequence

import numpy as np

from crane_sym.components.hybrid import ComponentSystem, Mode
from crane_sym.components.loads import Initial
from crane_sym.components.parts import DIMENSIONS, Component, ComponentError
from crane_sym.components.topology import Assembly, _unknown

__all__ = ["Shift", "apply", "shifts"]

#: Each key of an initial state and the kind of value it holds.
_VALUES = (("displacement", "displacement"), ("velocity", "speed"))


@dataclass(frozen=True)
class Shift:
    """An initial state on rigid group ``group``: its coordinate moved by
    ``displacement``, its speed set to ``velocity`` (in the group's
    coordinate, SI; None: as the start has it)."""

    part: Initial
    group: int
    displacement: float | None
    velocity: float | None


def shifts(components: Sequence[Component], assembly: Assembly) -> tuple[Shift, ...]:
    """The initial states among ``components`` on the groups of ``assembly``,
    checked (see the module docstring).

    Parameters
    ----------
    components : sequence of Component
        The model's parts; the :class:`Initial` ones are taken.
    assembly : Assembly
        The assembled parts (bodies, rigid groups, κ).
    """
    out, seen = [], {}
    for part in components:
        if not isinstance(part, Initial):
            continue
        if part.body not in assembly.bodies:
            raise _unknown(part.label, part.body, list(assembly.bodies))
        body = assembly.bodies[part.body]
        g, kappa, _ = assembly.place[part.body]
        where, found = f"{part.label} on {body.label}", {}
        for key, kind in _VALUES:
            given = getattr(part, key)
            if given is None:
                found[key] = None
                continue
            si = given.check(where, key, DIMENSIONS[kind][body.motion])
            if (g, key) in seen:
                raise ComponentError(f"{where}: {seen[g, key].label} gives the {key} of its "
                                     f"rigid group ({assembly.groups[g].name}) already")
            seen[g, key] = part
            found[key] = si / kappa
        out.append(Shift(part, g, found["displacement"], found["velocity"]))
    return tuple(out)


def apply(given: Sequence[Shift], system: ComponentSystem, mode: Mode, x: np.ndarray,
          speed: float = 0.0) -> tuple[Mode, np.ndarray]:
    """The start's ``mode`` and state ``x`` with the initial states ``given``
    applied: each group moved and set moving, each link with backlash on the
    contact its twist now gives (at a flank exactly: as the start had it).

    Parameters
    ----------
    given : sequence of Shift
        The model's initial states (:func:`shifts`).
    system : ComponentSystem
        The model's system (where each group sits in the state).
    mode, x : Mode, ndarray
        The start's mode and state.
    speed : float
        A steady start's [run] speed in SI (0 at rest); a velocity beside a
        nonzero one is refused.
    """
    x = np.array(x, dtype=float)
    for s in given:
        if s.velocity is not None:
            for k, (g, _) in system.moved.items():
                if g == s.group:
                    raise ComponentError(f"{s.part.label}: {system.laws[k].label} sets "
                                         f"the speed of {s.part.body!r}; give no velocity")
            if speed != 0:
                raise ComponentError(f"{s.part.label}: a velocity and the steady start's "
                                     f"[run] speed {speed:g} (SI) both set the speed of "
                                     f"{s.part.body!r}; give one (or start = \"rest\")")
            x[system.v(s.group)] = s.velocity
        if s.displacement is not None:
            x[system.q(s.group)] += s.displacement
    contacts = []
    for link, c in zip(system.backlash, mode.contacts):
        u = float(system.twist(link) @ x)
        lo, hi = link.part.flanks
        contacts.append(1 if u > hi else -1 if u < lo else 0 if lo < u < hi else c)
    return replace(mode, contacts=tuple(contacts)), x
