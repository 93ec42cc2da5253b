"""Designs of one component template as one family for the batched solver
(:class:`DesignFamily`, what :class:`crane_sym.mechanics.batched_runs.RunFamily`
asks where the runs' systems offer it): a mode's (A, b), guards, generic
switches and links' loads for the designs in the mode at once.
"""
from __future__ import annotations

from typing import Callable, Sequence

import numpy as np

from crane_sym.components.design_arrays import (DesignArray, free_limits, mode_guards,
                                                mode_matrices)
from crane_sym.components.design_outputs import LinkLoad, link_loads
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

    def outputs(self, outputs: Sequence) -> Callable | None:
        """``output(mode, index)``: the runs' outputs ``outputs`` (one a design,
        in order) for the designs at ``index`` in ``mode``, (w, k) stacked,
        where each is the load of the same links of its own design
        (:class:`~crane_sym.components.design_outputs.LinkLoad`); else None
        (each asked in turn)."""
        links = getattr(outputs[0], "links", None)
        if not all(isinstance(o, LinkLoad) and o.links == links and o.system is s
                   for o, s in zip(outputs, self.array.systems)):
            return None
        return lambda mode, index: link_loads(self.array.take(index), links, mode)
