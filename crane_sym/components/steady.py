"""The balance of a steady start: the positions, a ``steady`` motor's torque
and the first-order states that hold every group at its steady speed.

With the speeds v given (the steady speed) and the contacts fixed, the
unknowns are the groups' positions q (the first group's pinned at 0 unless a
link holds the drive to the ground), the torque T of a ``steady`` motor, and
the parts' first-order states s (a DC motor's current, a controller's
integral). They solve together

.. math::

    K q - T\\, u - S s = f_0 - D v, \\qquad
    R_q q + R_s s = -(R_v v + R_L L(0) + r_0),

the force balance of every group that no speed law moves (u: the unit
motor's force, S: the states' forces, k i on a DC motor's body) and every
state at rest (its rate 0, the laws' signals L at their value at t = 0): a
DC motor's current gives the torque that holds the load, k i, and a PI
loop's integral the voltage that keeps that current, R i + k ω − k_p e.
A state a limit holds must lie within it; else the limit cannot hold the
load, and the start is refused in one line.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from crane_sym.components.hybrid import ComponentSystem, Mode
from crane_sym.components.parts import UNITS, ComponentError

__all__ = ["Balance", "balance"]

#: The residual a balanced row may keep, relative to the size of its terms.
TOLERANCE = 1e-9


@dataclass(frozen=True)
class Balance:
    """The solved start: each group's position, the ``steady`` motor's torque
    (0 without one) and each first-order state, in SI."""

    positions: np.ndarray
    torque: float
    states: np.ndarray


def _rate_rows(probe: ComponentSystem, rates: np.ndarray, pinned: int
               ) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """(rows on the positions, rows on the states, right-hand side) of the
    states' rates set to 0 at the steady speeds ``rates``."""
    Rq, Rv, Rs, RL, r0 = probe.first_order.rates
    pieces = tuple(0 for _ in probe.laws)
    signals = probe.clock.signals(pieces, probe.size)[1]     # every clock at 0 at t = 0
    right = -(Rv @ rates + RL @ signals + r0.reshape(-1))
    return Rq[:, pinned:], Rs, right


def balance(probe: ComponentSystem, unit: ComponentSystem | None, mode: Mode,
            rates: np.ndarray, pinned: int) -> Balance:
    """The steady start's :class:`Balance` (see the module docstring);
    ComponentError if no motor torque balances the loads, if a state cannot
    rest, or if a limit cannot hold the state its load needs.

    Parameters
    ----------
    probe : ComponentSystem
        The model's system with a ``steady`` motor's torque at 0.
    unit : ComponentSystem or None
        The same with that torque at 1 (None: no ``steady`` motor).
    mode : Mode
        The mode at the start (the contacts of the links with backlash, the
        motors on).
    rates : ndarray
        Each group's steady speed.
    pinned : int
        1 where the first group's position is pinned at 0, else 0.
    """
    _, D, K, f0, _, _, S = probe.linear(mode)
    f = f0 - D @ rates
    columns = [K[:, pinned:]]
    if unit is not None:
        columns.append(-(unit.linear(mode)[3] - f0)[:, None])
    columns.append(-S)
    matrix = np.hstack(columns)
    free = [g for g in range(len(f)) if g not in {g for g, _ in probe.moved.values()}]
    matrix, f = matrix[free], f[free]
    n_states = S.shape[1]
    Rq, Rs, right = _rate_rows(probe, rates, pinned)
    lower = np.hstack([Rq] + ([np.zeros((len(right), 1))] if unit is not None else []) + [Rs])
    scale = np.abs(lower).max(axis=1, initial=0.0)           # each rate row to unit size
    scale = np.where(scale > 0, scale, 1.0) / max(np.abs(matrix).max(initial=0.0), 1.0)
    lower, right = lower / scale[:, None], right / scale
    system, rhs = np.vstack([matrix, lower]), np.concatenate([f, right])
    z = np.linalg.lstsq(system, rhs, rcond=None)[0] if system.shape[1] else np.zeros(0)
    if system.shape[1]:    # one step of iterative refinement: lstsq's rounding, κ eps,
        z = z + np.linalg.lstsq(system, rhs - system @ z, rcond=None)[0]   # to ~eps
    _check_fixed(probe, system, K.shape[1] - pinned, unit is not None)
    if n_states:           # the loads balanced by some states, whatever their rates?
        _check_forces(matrix, f, np.linalg.lstsq(matrix, f, rcond=None)[0])
    _check_rates(probe, lower, right, z)
    _check_forces(matrix, f, z)
    positions = np.concatenate([[0.0] * pinned, z[:K.shape[1] - pinned]])
    torque = float(z[K.shape[1] - pinned]) if unit is not None else 0.0
    states = z[len(z) - n_states:] if n_states else np.zeros(0)
    _check_limits(probe, states)
    return Balance(positions, torque, np.array(states, dtype=float))


def _check_fixed(probe: ComponentSystem, system: np.ndarray, positions: int,
                 torque: bool) -> None:
    """The torque and the states fixed by the balance: refused where a
    combination of them (a ``steady`` motor and a DC motor's current, two
    motors' currents) can change without unbalancing anything."""
    if system.shape[1] == positions + torque:     # no state: as solved without states
        return
    norms = np.linalg.norm(system, axis=0)
    _, sigma, vt = np.linalg.svd(system / np.where(norms > 0, norms, 1.0))
    null = vt[np.sum(sigma > 1e-10 * sigma.max(initial=0.0)):, positions:]
    loose = [j for j in np.flatnonzero(np.abs(null).max(axis=0, initial=0.0) > 1e-8)
             if norms[positions + j] > 0]     # a state that enters nothing stays at 0
    if loose:
        names = ["the 'steady' motor's torque"] * torque + [str(s) for s in
                                                           probe.equations.states]
        raise ComponentError(f"start: the steady start does not fix "
                             f"{' and '.join(names[j] for j in loose)}: they share the "
                             "load in any proportion; hold it by one of them")


def _check_forces(matrix: np.ndarray, f: np.ndarray, z: np.ndarray) -> None:
    """The force balance met, else no torque (or state) balances the loads."""
    residual = np.abs(matrix @ z - f).max() if len(f) else 0.0
    scale = np.abs(f).max(initial=0.0) + (np.abs(matrix).max() * np.abs(z).max()
                                          if z.size and matrix.size else 0.0)
    if residual > TOLERANCE * max(scale, 1e-300) and residual > 1e-12:
        raise ComponentError("the drive is not in a steady state at the start: its "
                             "constant loads do not balance; give one motor the torque "
                             "'steady'")


def _check_rates(probe: ComponentSystem, lower: np.ndarray, right: np.ndarray,
                 z: np.ndarray) -> None:
    """Every state's rate 0 at the solution, each row against its own terms."""
    for j, row in enumerate(lower):
        size = np.abs(row) @ np.abs(z) + abs(right[j])
        rest = float(row @ z - right[j])
        if abs(rest) > TOLERANCE * size and abs(rest) > 1e-12 * max(size, 1.0):
            state = probe.equations.states[j]
            raise ComponentError(f"start: {state} cannot rest at the steady start (its rate "
                                 f"stays off 0 whatever the states: a reference at t = 0 "
                                 f"other than the steady speed, or a loop without an "
                                 f"integral?); start = \"rest\"")


def _check_limits(probe: ComponentSystem, states: np.ndarray) -> None:
    """Each limited state within its bound at the start."""
    for limit, (name, symbol, _, _) in zip(probe.limits, probe.equations.limits):
        value = float(states[limit.state - probe.first])
        if abs(value) > limit.bound * (1 + 1e-12):
            unit = _unit_of(probe, symbol)
            raise ComponentError(f"start: {name}'s limit holds {symbol} within "
                                 f"±{limit.bound:.6g} {unit}; the steady start needs "
                                 f"{value:.6g} {unit}: the limit cannot hold the load")


def _unit_of(probe: ComponentSystem, state) -> str:
    """The unit a part reports ``state`` in (a DC motor's current: A), else "(SI)"."""
    for _, _, unit, value in probe.equations.outputs:
        if value == state and unit not in UNITS:
            return unit
    return "(SI)"
