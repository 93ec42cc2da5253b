"""The numbers of a mode's equations M q̈ + D q̇ + K q = f (:class:`ModeNumbers`):
the component model's equations evaluated at what the mode fixes (each
gapped link's contact and flank, the inputs the switching kinds give: a
motor's switch, a characteristic's slope), with the columns of f per brake's
friction, per law's value and per first-order state.

Kept per contacts and inputs: a run asks for them many times a phase, and a
batched sweep once a phase per design.
"""
from __future__ import annotations

import numpy as np

from crane_sym.components.modes import Mode, memo

__all__ = ["ModeNumbers"]


class ModeNumbers:
    """(M, D, K, f, E, G, S) of a mode of ``system`` (a
    :class:`~crane_sym.components.hybrid.ComponentSystem`): f without
    friction, laws and first-order states; E = ∂f/∂B per friction B, G =
    ∂f/∂L per law's value L, S = ∂f/∂s per first-order state s."""

    def __init__(self, system) -> None:
        self.system = system
        self._numeric = system.equations.numeric(system.extra)
        self._linear = memo(self._linear_uncached)
        self._inputs = memo(self._inputs_uncached)

    def __call__(self, mode: Mode):
        return self._linear(mode.contacts, *self._inputs(mode))

    def flanks(self, contacts: tuple[int, ...]) -> tuple[list[float], list[float]]:
        """(χ, δ): each gapped link in contact (1) or not (0), and the flank it is on."""
        chi, delta = [], []
        for l, c in zip(self.system.backlash, contacts):
            lo, hi = l.part.flanks                          # SI, rad or m
            chi.append(0.0 if c == 0 else 1.0)
            delta.append(hi if c > 0 else lo if c < 0 else 0.0)
        return chi, delta

    def inputs(self, mode: Mode) -> tuple[tuple[float, ...], tuple[float, ...]]:
        """(switches, slopes): the numbers the mode gives the symbols of those
        roles (a motor's on, a characteristic's slope), from the kinds'
        ``Events.value``."""
        return self._inputs(mode)

    def _inputs_uncached(self, mode: Mode) -> tuple[tuple[float, ...], tuple[float, ...]]:
        by_role: dict[str, list[float]] = {"switches": [], "slopes": []}
        for events, _, parts in self.system.switching:
            if events.role:
                by_role[events.role] += [events.value(self.system, mode, i)
                                         for i in range(len(parts))]
        return tuple(by_role["switches"]), tuple(by_role["slopes"])

    def _linear_uncached(self, contacts: tuple[int, ...], on: tuple[float, ...],
                         slopes: tuple[float, ...]):
        n, laws, states = self.system.n, len(self.system.laws), len(self.system.equations.states)
        chi, delta = self.flanks(contacts)
        on, slopes = list(on), list(slopes)
        zero = [0.0] * len(self.system.equations.friction)
        M, D, K, f = self._numeric(chi, delta, on, zero, slopes)
        E = np.zeros((n, len(zero)))
        for k in range(len(zero)):
            unit = list(zero)
            unit[k] = 1.0
            E[:, k] = self._numeric(chi, delta, on, unit, slopes)[3] - f
        G = np.zeros((n, laws))
        for k in range(laws):
            G[:, k] = self._numeric(chi, delta, on, zero, slopes, np.eye(laws)[k])[3] - f
        S = np.zeros((n, states))
        for k in range(states):
            S[:, k] = self._numeric(chi, delta, on, zero, slopes, (), np.eye(states)[k])[3] - f
        return M, D, K, f, E, G, S
