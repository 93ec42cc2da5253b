"""The first-order states of a component system and the limits that hold them.

A part may bring states of its own beside the mechanical coordinates and
speeds (a DC motor's current i, a speed controller's integral z), each with a
rate affine in the groups' coordinates q and speeds q̇, the states s and the
laws' signals L:

.. math:: \\dot s = R_q\\, q + R_v\\, \\dot q + R_s\\, s + R_L\\, L + r_0 .

A limit keeps a state s within ±bound (a motor's torque limit: its current
within T_max / k). Its mode is 0 (free), ±1 (at the bound, s still and its
tracking state z, the controller's integral, frozen: conditional
integration, the controller's anti-windup) or ±2 (at the bound, z sliding).
With r = a·x + β the free rate of s: a free limit fires as s reaches a bound
(±1); at ±1, where r turns back through 0, the limit is released if the free
mode would move s back inside (ṙ of the free mode against the bound's
sign), else (integrating again would push s past the bound at once: the
chatter of conditional integration) it slides, ±2: z follows the value that
keeps r = 0 (ż from ṙ = 0), until ṙ of the free mode turns through 0.
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Callable, Sequence

import numpy as np
import sympy as sp


__all__ = ["FirstOrder", "Limit", "fill_rates", "hold_limits", "limit_guards", "rate_matrices"]


def rate_matrices(coordinates: Sequence[sp.Expr], t: sp.Symbol, states: Sequence[sp.Symbol],
                  rates: Sequence[sp.Expr], signals: Sequence[sp.Symbol]
                  ) -> tuple[sp.Matrix, ...]:
    """(R_q, R_v, R_s, R_L, r_0) of the rates of ``states`` (see the module docstring).

    Parameters
    ----------
    coordinates : sequence of sympy expressions
        q_g(t) of each group.
    t : Symbol
        Time.
    states, rates : sequences of sympy expressions
        Each first-order state and its rate.
    signals : sequence of Symbol
        The laws' values the rates may hold.
    """
    n = len(coordinates)
    plain = [sp.Dummy(f"q{i}") for i in range(n)]
    speeds = [sp.Dummy(f"v{i}") for i in range(n)]
    swap = {q.diff(t): v for q, v in zip(coordinates, speeds)}
    rows = sp.Matrix(len(rates), 1, [r.subs(swap).subs(dict(zip(coordinates, plain)))
                                     for r in rates])
    zero = {x: 0 for x in [*plain, *speeds, *states, *signals]}
    return tuple(rows.jacobian(x) if rows.rows else sp.zeros(0, len(x))
                 for x in (plain, speeds, list(states), list(signals))) + (rows.subs(zero),)


@dataclass(frozen=True)
class Limit:
    """A limit of part ``name``: the state at ``state`` (its index in x) within
    ±``bound``; the state at ``tracking`` follows while it is at a bound."""

    name: str
    state: int
    bound: float
    tracking: int


def _numbers(matrix: sp.Matrix, values: dict) -> np.ndarray:
    """``matrix`` with ``values`` put in, as floats; an empty one (a model
    without first-order states) without SymPy's xreplace, which cost a
    system built per design of a sweep ~0.1 ms for each of its five."""
    if 0 in matrix.shape:
        return np.zeros(matrix.shape)
    return np.array(matrix.xreplace(values), dtype=float).reshape(matrix.shape)


class FirstOrder:
    """The rows of the first-order states in x' = A x + b, from index ``first``
    of a state of ``size``, with the parameters' values (and ``extra``)."""

    def __init__(self, equations, n: int, first: int, size: int, extra: dict) -> None:
        values = {**equations.values, **extra}
        self.n, self.first, self.size = n, first, size
        self.rates = tuple(_numbers(m, values) for m in equations.first_order)
        index = {s: first + j for j, s in enumerate(equations.states)}
        self._values, self._index = values, index
        self._coordinates = equations.coordinates
        self.limits = [Limit(name, index[s], float(bound.xreplace(values)), index[z])
                       for name, s, bound, z in equations.limits]

    def weights(self, value: sp.Expr) -> np.ndarray:
        """w of ``value`` = w·x, ``value`` linear in the groups' coordinates q,
        speeds q̇ and the first-order states (an output a part reports).

        Parameters
        ----------
        value : sympy expression
            In the coordinates q_g(t), their derivatives and the states.
        """
        w = np.zeros(self.size)
        for g, q in enumerate(self._coordinates):
            speed = sp.Dummy("v")
            plain = value.subs(q.diff(q.args[0]), speed)
            w[2 * g + 1] = float(sp.diff(plain, speed).xreplace(self._values))
            w[2 * g] = float(sp.diff(plain.subs(speed, 0), q).xreplace(self._values))
        for s, at in self._index.items():
            w[at] = float(sp.diff(value, s).xreplace(self._values))
        return w

    def events(self) -> dict[str, tuple[str, int]]:
        """The events of the limits, by name: (kind, limit)."""
        return {f"{limit.name} {word}": (kind, j) for j, limit in enumerate(self.limits)
                for word, kind in (("limited +", "limit+"), ("limited -", "limit-"),
                                   ("demand within", "within"), ("released", "release"))}

    def switch(self, kind: str, j: int, limits: Sequence[int], x: np.ndarray,
               free: tuple[np.ndarray, np.ndarray]) -> tuple[int, ...]:
        """The limits after event ``kind`` of limit ``j``; a state reaching its
        bound is put on it (x changed in place; ``free`` as for :meth:`guards`)."""
        out, limit = list(limits), self.limits[j]
        if kind == "release":
            out[j] = 0
        elif kind == "within":
            a, sign = free[0][limit.state], int(np.sign(limits[j]))
            slope = float(a @ (free[0] @ x + free[1]))          # ṙ of the free mode
            out[j] = 2 * sign if slope * sign > 0 else 0
        else:
            out[j] = 1 if kind == "limit+" else -1
            x[limit.state] = out[j] * limit.bound
        return tuple(out)


def fill_rates(rates: Sequence[np.ndarray], n: int, first: int, A: np.ndarray, b: np.ndarray,
               W: np.ndarray, c: np.ndarray) -> None:
    """The states' rows of x' = A x + b, free, for k designs at once (a
    leading axis on every array): ``rates`` (R_q, R_v, R_s, R_L, r_0) per
    design, the signals L = W x + c."""
    Rq, Rv, Rs, RL, r0 = rates
    if not Rq.shape[1]:
        return
    rows = slice(first, first + Rq.shape[1])
    A[:, rows, 0:2 * n:2], A[:, rows, 1:2 * n:2] = Rq, Rv
    A[:, rows, first:] = Rs
    A[:, rows] += RL @ W
    b[:, rows] = (RL @ c[:, :, None])[:, :, 0] + r0.reshape(len(r0), -1)


def hold_limits(limits: Sequence[Limit], A: np.ndarray, b: np.ndarray,
                at: Sequence[int]) -> None:
    """The free (A, b) of k designs changed in place for the limits at a
    bound: the state still; its tracking state frozen (±1) or keeping the
    free rate r = a·x + β at 0 (±2)."""
    for limit, where in zip(limits, at):
        if not where:
            continue
        a = A[:, limit.state].copy()
        A[:, limit.state], b[:, limit.state] = 0.0, 0.0
        pivot = a[:, limit.tracking].copy()
        a[:, limit.state], a[:, limit.tracking] = 0.0, 0.0
        if abs(where) == 1:
            A[:, limit.tracking], b[:, limit.tracking] = 0.0, 0.0
        else:
            A[:, limit.tracking] = -(a[:, None, :] @ A)[:, 0] / pivot[:, None]
            b[:, limit.tracking] = -(a * b).sum(axis=1) / pivot


def limit_guards(limits: Sequence[Limit], bounds: np.ndarray, at: Sequence[int], size: int,
                 free: Callable[[], tuple[np.ndarray, np.ndarray]]
                 ) -> list[tuple[str, np.ndarray, np.ndarray, int]]:
    """The limits' guards for k designs, (event, w (k, size), constant (k,),
    direction) each: a free limit's state reaching ±bound (``bounds``: (k,
    limits)); at ±1 its free rate r turning back through 0; at ±2 ṙ of the
    free mode turning (``free()``: (A, b) per design with every limit free,
    asked only where a limit is at its bound)."""
    out, k = [], len(bounds)
    A, b = free() if any(at) else (None, None)
    for j, (limit, where) in enumerate(zip(limits, at)):
        sign = int(np.sign(where))
        if where:
            a = A[:, limit.state]
        if where == 0:
            unit = np.zeros((k, size))
            unit[:, limit.state] = 1.0
            out += [(f"{limit.name} limited +", unit, -bounds[:, j], 1),
                    (f"{limit.name} limited -", unit.copy(), bounds[:, j].copy(), -1)]
        elif abs(where) == 1:
            out.append((f"{limit.name} demand within", a.copy(), b[:, limit.state].copy(),
                        -sign))
        else:
            out.append((f"{limit.name} released", (a[:, None, :] @ A)[:, 0],
                        (a * b).sum(axis=1), -sign))
    return out
