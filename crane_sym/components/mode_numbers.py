"""The numbers of a mode's equations M q̈ + D q̇ + K q = f (:class:`ModeNumbers`):
the component model's equations evaluated at what the mode fixes (each
gapped link's contact and flank, the inputs the switching kinds give: a
motor's switch, a characteristic's slope), with the columns of f per brake's
friction, per law's value and per first-order state.

Kept per contacts and inputs: a run asks for them many times a phase, and a
batched sweep once a phase per design.
"""
from __future__ import annotations

from typing import Callable, Sequence

import numpy as np

from crane_sym.components.modes import Mode, memo

__all__ = ["ModeNumbers", "mode_linear"]


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
                by_role[events.role] += [float(np.broadcast_to(
                    events.value(self.system.alone, mode, i), (1,))[0])
                    for i in range(len(parts))]
        return tuple(by_role["switches"]), tuple(by_role["slopes"])

    def _linear_uncached(self, contacts: tuple[int, ...], on: tuple[float, ...],
                         slopes: tuple[float, ...]):
        chi, delta = self.flanks(contacts)
        counts = (len(self.system.equations.friction), len(self.system.laws),
                  len(self.system.equations.states))
        return tuple(m[0] for m in mode_linear(self._one, chi, [delta], [on], [slopes], counts))

    def _one(self, chi, delta, on, friction, slopes, signals=(), states=()):
        """This design's (M, D, K, f) with a leading axis of one design."""
        out = self._numeric(chi, list(delta[0]), list(on[0]), friction, list(slopes[0]),
                            signals, states)
        return tuple(m[None] for m in out)


def mode_linear(evaluate: Callable, chi: Sequence[float], delta, on, slopes,
                counts: tuple[int, int, int]) -> tuple[np.ndarray, ...]:
    """(M, D, K, f, E, G, S) of k designs in one mode, a leading axis of
    designs on each: f without friction, laws and first-order states, and
    each column of E, G and S as f with that one input at 1 less f.

    Parameters
    ----------
    evaluate : callable
        (χ, δ, on, B, β, L, s) -> (M, D, K, f) of the designs.
    chi : sequence of float
        Each gapped link's contact, 1 or 0 (the same for every design).
    delta, on, slopes : arrays (k, values)
        Each design's flanks, motor switches and characteristics' slopes.
    counts : (int, int, int)
        The frictions B, laws L and first-order states s.
    """
    friction, laws, states = counts
    zero = [0.0] * friction
    M, D, K, f = evaluate(chi, delta, on, zero, slopes)
    k, n = f.shape
    E = np.zeros((k, n, friction))
    for j in range(friction):
        unit = list(zero)
        unit[j] = 1.0
        E[:, :, j] = evaluate(chi, delta, on, unit, slopes)[3] - f
    G = np.zeros((k, n, laws))
    for j in range(laws):
        G[:, :, j] = evaluate(chi, delta, on, zero, slopes, np.eye(laws)[j])[3] - f
    S = np.zeros((k, n, states))
    for j in range(states):
        S[:, :, j] = evaluate(chi, delta, on, zero, slopes, (), np.eye(states)[j])[3] - f
    return M, D, K, f, E, G, S
