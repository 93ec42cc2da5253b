"""Model only what a run needs: the components that cannot act on any body
over the run are dropped before the model is derived.

A run's outputs are the loads of its elastic links, and in a connected drive
every body and every link acts on every link: no body can be dropped. What can
be is a load that provably does nothing over [0, duration] from the run's start:

- a brake that engages at or after the end of the run (its delay ≥ the
  duration: it never presses, and a free body has no brake state);
- a motor of torque 0, or one switched off at t = 0 in a run from rest (a
  motor off at t = 0 in a steady start still sets the start's balance, and a
  ``steady`` motor always does: both are kept);
- a resistance of 0, a weight with g = 0;
- a torque law that is 0 throughout, or that starts at or after the end of the
  run (an acceleration law balances the other loads at the start: kept).

Each is the same system with fewer modes and states: its links' loads are the
full model's (tests/test_components_pruning.py). A pruned model remembers the
run it was pruned for and refuses a longer one, or a steady start where it was
pruned for a start at rest (:class:`Scope`). Each kind says when its part is
idle (``Kind.idle``, in its module of :mod:`crane_sym.components.kinds`).
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Sequence

from crane_sym.components import kinds
from crane_sym.components.parts import Component

__all__ = ["Dropped", "Scope", "needed"]


@dataclass(frozen=True)
class Dropped:
    """A component left out of the model, and why."""

    part: Component
    reason: str

    def line(self) -> str:
        """One line for ``crane-sym model show`` and ``crane-sym run``."""
        return f"dropped {self.part.label}: {self.reason}"


@dataclass(frozen=True)
class Scope:
    """The runs a pruned model holds for: up to ``duration`` [s], from rest
    when ``rest`` (a start at rest let a motor switched off at 0 go)."""

    duration: float
    rest: bool
    dropped: tuple[Dropped, ...]


def _why(part: Component, duration: float, rest: bool) -> str | None:
    """Why ``part`` does nothing over [0, duration], or None: its kind says."""
    idle = kinds.of(part).idle
    return None if idle is None else idle(part, duration, rest)


def needed(components: Sequence[Component], duration: float,
           rest: bool = False) -> tuple[list[Component], Scope]:
    """The components a run of ``duration`` [s] (from rest when ``rest``)
    needs, in their order, and the :class:`Scope` naming what was dropped.

    Parameters
    ----------
    components : sequence of Component
        The model's parts.
    duration : float
        The run's end [s].
    rest : bool
        The run starts at rest (else in its steady motion).
    """
    kept, dropped = [], []
    for part in components:
        reason = _why(part, duration, rest)
        if reason is None:
            kept.append(part)
        else:
            dropped.append(Dropped(part, reason))
    return kept, Scope(duration, rest, tuple(dropped))
