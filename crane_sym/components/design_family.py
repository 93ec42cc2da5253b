"""Designs of one component template as one family for the batched solver
(:class:`DesignFamily`, what :class:`crane_sym.mechanics.batched_runs.RunFamily`
asks where the runs' systems offer it): a mode's (A, b), guards and
generic switches for the designs in the mode at once.
"""
from __future__ import annotations

import numpy as np

from crane_sym.components.design_arrays import (DesignArray, free_limits, mode_guards,
                                                mode_matrices)
from crane_sym.components.design_switches import switched
from crane_sym.components.modes import Mode

__all__ = ["DesignFamily"]


class DesignFamily:
    """Designs of one template for the batched solver
    (:class:`crane_sym.mechanics.batched_runs.RunFamily`): a mode's (A, b)
    and guards for the designs at ``index`` in one evaluation."""

    def __init__(self, array: DesignArray) -> None:
        self.array = array

    def matrices(self, mode: Mode, index: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """(A, b) of the designs at ``index`` in ``mode``, stacked."""
        return mode_matrices(self.array.take(index), mode)

    def guards(self, mode: Mode, index: np.ndarray
               ) -> list[tuple[str, np.ndarray, np.ndarray, int]]:
        """The guards of the designs at ``index`` in ``mode``, stacked guard by guard."""
        array = self.array.take(index)
        return mode_guards(array, mode, lambda: mode_matrices(array, free_limits(mode)))

    def switch(self, mode: Mode, event: str, index: np.ndarray, x: np.ndarray
               ) -> tuple[list[Mode], np.ndarray] | None:
        """The next modes and states of the designs at ``index`` after
        ``event`` (x: (k, size), not changed), or None where each design
        switches by its own rule
        (:func:`~crane_sym.components.design_switches.switched`)."""
        return switched(self.array.take(index), mode, event, x.copy())
