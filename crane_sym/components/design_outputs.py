"""The load of elastic links as the output of a run (:class:`LinkLoad`), for
one design or for the designs of one template at once (:func:`link_loads`).

On a flank a link's load is F = a u + b u̇ + e δ (``Equations.link_laws``,
the derivatives of ∂Π/∂u + ∂Φ/∂u̇): u = w·x its twist, δ the flank it rests
on; in its gap it is 0. Each design's twist weights and (a, b, e) are asked
of it once (:meth:`~crane_sym.components.design_arrays.DesignArray.gather`);
a mode's loads are then one pass over the designs' arrays. One design alone
is the array of one: the batched solver and a run's table take one route.
"""
from __future__ import annotations

from typing import Sequence

import numpy as np

from crane_sym.components.design_arrays import DesignArray
from crane_sym.components.modes import Mode

__all__ = ["LinkLoad", "link_loads"]


def link_loads(array: DesignArray, links: Sequence[int], mode: Mode
               ) -> tuple[np.ndarray, np.ndarray]:
    """The summed load of elastic links ``links`` (their places among the
    assembly's links) in ``mode``, w·x + k per design: (k, size) and (k,)."""
    system = array.model
    w, k = np.zeros((array.k, system.size)), np.zeros(array.k)
    delta = array.contact(mode.contacts)[1]
    for index in links:
        link = system.assembly.links[index]
        place = next((j for j, l in enumerate(system.backlash) if l is link), None)
        if place is not None and mode.contacts[place] == 0:
            continue                                     # in its gap: no load
        u = array.gather(("link twist", index), lambda s: s.twist(s.assembly.links[index]))
        rate = np.roll(u, 1, axis=1)                     # q̇ sits right after q
        rate[:, 2 * system.n:] = 0.0
        a, b, e = array.gather(("link coefficients", index),
                               lambda s: s.equations.link_coefficients(index, s.extra)).T
        w = w + (a[:, None] * u + b[:, None] * rate)
        k = k + e * (delta[:, place] if place is not None else 0.0)
    return w, k


class LinkLoad:
    """The summed load of elastic links ``links`` of ``system`` (one design)
    per mode, as (w, k): the output a run's table and its peak take, and
    which a batched sweep of the design's template evaluates for all its
    designs at once (:meth:`DesignFamily.output`)."""

    def __init__(self, system, links: Sequence[int]) -> None:
        self.system, self.links = system, tuple(links)

    def __call__(self, mode: Mode) -> tuple[np.ndarray, float]:
        w, k = link_loads(self.system.alone, self.links, mode)
        return w[0], float(k[0])
