"""A motor (or any load) that follows a law in time: piecewise polynomial, as
paper 002's drive laws (Chovnyuk et al., eqs (28)-(31)).

The law is given as numbers with units, read by the scenes' law reader
(:func:`crane_sym.scenes.law_tables.read_law_table`, never evaluated): on
piece k, :math:`p(t) = \\sum_j c_{kj} (t - b_k)^j` for
:math:`b_k \\le t < b_{k+1}`, and 0 before :math:`b_0` and from :math:`b_N` on.
It is either

- ``"torque"``: the torque on a rotating body (a force on a translating one); or
- ``"acceleration"``: the acceleration a(t) of the body were the whole drive
  rigid, as paper 002 gives its laws; the motor then pushes with what drives the
  rigid drive along a(t) against the other loads,

  .. math:: P(t) = J_{red}\\, a(t) - \\sum_b \\rho_b F_b(t),

  :math:`J_{red}` the drive's inertia referred to the body, :math:`\\rho_b` the
  rigid ratio of body b to it and :math:`F_b` the loads constant in time on
  body b: weights, resistances, motors (brakes, speed characteristics and other
  laws are not anticipated). Paper 002's (31), :math:`P = (m_1 + m_2) a + m_2 g`;
  with pick-up its (28) as printed, the drive pulling the full weight from
  t = 0 while the ground still carries part of it (the ground's reaction a
  torque law on the load; a drive that anticipates it gets the same law, as a
  torque law, on its own body);
- ``"speed"``: the body's speed v(t), followed exactly (an ideal speed
  control: the motor gives whatever torque that takes), its group's equation
  of motion replaced by :math:`\\dot v = p'(t)`, its speed set to the next
  piece's value at each breakpoint.

Polynomial forcing stays exact in the phase-by-phase closed forms: a law of
degree K adds the states :math:`w_j = \\tau^j`, j = 1…K, of the time
:math:`\\tau = t - b_k` since its piece began (:math:`w_1' = 1`,
:math:`w_j' = j\\,w_{j-1}`, a chain of integrators, reset to 0 at each
breakpoint), and the law is :math:`c_{k0} + \\sum_j c_{kj} w_j`, linear in the
state (:class:`LawClock`).
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Any, Sequence

import numpy as np
import sympy as sp
from sympy.physics.units import Dimension

from crane_sym import units
from crane_sym.components.parts import Component, ComponentError, _name
from crane_sym.mechanics.loads import PiecewiseLoad
from crane_sym.scenes.law_tables import LawLimits, piecewise_law, read_law_table

__all__ = ["KINDS", "LIMITS", "SIGNALS", "LawClock", "MotorLaw", "clocked"]

#: What a law gives.
KINDS = ("torque", "acceleration", "speed")
#: What a law a part carries inside it gives: no load, a signal its own
#: first-order states read (a DC motor's armature voltage, a controller's
#: speed reference).
SIGNALS = ("voltage", "reference")
#: The largest law a component takes: its pieces and degree set the size of the
#: state (one state per degree) and the number of scheduled events.
LIMITS = LawLimits(pieces=50, degree=6, end=1e4, shortest=1e-6, value=1e12, unit="SI")


@dataclass(frozen=True)
class MotorLaw(Component):
    """A load on ``body`` that follows a piecewise polynomial law in time
    (see the module docstring): ``breakpoints`` in ``time_unit``, the rows of
    ``coefficients`` in ``unit`` per ``time_unit`` to the power j."""

    name: str
    body: str
    law: str
    breakpoints: tuple[sp.Rational, ...]
    coefficients: tuple[tuple[sp.Rational, ...], ...]
    dimension: Dimension
    unit: str
    kind = "motor law"

    def __init__(self, name: str, body: str, breakpoints: Sequence[Any],
                 coefficients: Sequence[Sequence[Any]], unit: str, law: str = "torque",
                 time_unit: str = "s") -> None:
        name = _name("motor law", name)
        owner = f"motor law {name!r}"
        if law not in KINDS + SIGNALS:
            raise ComponentError(f"{owner}: law must be one of {', '.join(KINDS)}, got {law!r}")
        if not isinstance(unit, str):
            raise ComponentError(f"{owner}: unit must be a unit text like 'N*m', got {unit!r}")
        try:
            dimension = units.parse_unit(unit)[1]
            table = {"breakpoints": breakpoints, "coefficients": coefficients,
                     "time_unit": time_unit, "unit": unit}
            b, rows = read_law_table(table, "unit", dimension, unit, LIMITS)
        except (ValueError, TypeError) as exc:
            raise ComponentError(f"{owner}: {exc}") from None
        for key, v in (("name", name), ("body", body), ("law", law), ("breakpoints", b),
                       ("coefficients", rows), ("dimension", dimension), ("unit", unit)):
            object.__setattr__(self, key, v)

    @property
    def laws(self) -> tuple["MotorLaw", ...]:
        """The laws in time it carries: itself."""
        return (self,)

    @property
    def degree(self) -> int:
        """The highest degree of a piece."""
        return max(len(row) for row in self.coefficients) - 1

    def pieces(self) -> list[tuple[float, tuple[float, ...]]]:
        """(start [s], coefficients in SI of τ^j) of every piece from t = 0 on,
        the zero pieces before :math:`b_0` and from :math:`b_N` included."""
        out = [] if self.breakpoints[0] == 0 else [(0.0, (0.0,))]
        out += [(float(b), tuple(float(c) for c in row))
                for b, row in zip(self.breakpoints, self.coefficients)]
        return out + [(float(self.breakpoints[-1]), (0.0,))]

    def symbolic(self, t: sp.Symbol) -> PiecewiseLoad:
        """The law as an exact piecewise polynomial in ``t`` (SI)."""
        return piecewise_law(self.breakpoints, self.coefficients, t=t)

    def value_at(self, t: float) -> float:
        """The law's value [SI] at ``t`` [s] (the piece holding there)."""
        start, row = [p for p in self.pieces() if p[0] <= t][-1]
        return float(sum(c * (t - start) ** j for j, c in enumerate(row)))


def clocked(parts: Sequence[Component]) -> list[MotorLaw]:
    """The laws in time of ``parts``, in their order: the laws each part
    carries (its ``laws``: a motor law itself, a DC motor's voltage); the order of
    the signals the equations join and of the :class:`LawClock`'s states.

    Parameters
    ----------
    parts : sequence of Component
        The parts acting on bodies, in the assembly's order.
    """
    return [law for part in parts for law in getattr(part, "laws", ())]


class LawClock:
    """The states of the laws of a system: law k occupies ``degree_k`` states
    from ``offset_k``, :math:`w_j = \\tau^j` of its piece's own time."""

    def __init__(self, laws: Sequence[MotorLaw], first: int) -> None:
        self.laws = tuple(laws)
        self.pieces = [law.pieces() for law in self.laws]
        self.offsets, at = [], first
        for law in self.laws:
            self.offsets.append(at)
            at += law.degree
        self.size = at - first

    def rows(self, steps: Sequence[int]) -> list[tuple[float, ...]]:
        """The coefficients of each law's current piece."""
        return [pieces[min(k, len(pieces) - 1)][1] for pieces, k in zip(self.pieces, steps)]

    def signals(self, steps: Sequence[int], size: int) -> tuple[np.ndarray, np.ndarray]:
        """(W, c): law k's value is W[k]·x + c[k] on the current pieces."""
        return self.signals_of(self.rows(steps), size)

    def signals_of(self, rows: Sequence, size: int,
                   batch: tuple[int, ...] = ()) -> tuple[np.ndarray, np.ndarray]:
        """(W, c) of :meth:`signals` from each law's row of coefficients, a
        row of shape ``batch + (degree + 1,)``: one design's, or ``batch`` =
        (k,) designs' at once (``components.design_arrays``)."""
        W, c = np.zeros(batch + (len(self.laws), size)), np.zeros(batch + (len(self.laws),))
        for k, row in enumerate(rows):
            row = np.asarray(row, dtype=float)
            c[..., k] = row[..., 0]
            for j in range(1, row.shape[-1]):
                W[..., k, self.offsets[k] + j - 1] = row[..., j]
        return W, c

    def derivative(self, steps: Sequence[int], k: int, size: int) -> tuple[np.ndarray, float]:
        """(w, c): the rate of law k on its current piece, dp/dτ = w·x + c
        (:math:`c_{k1} + \\sum_{j \\ge 2} j c_{kj} w_{j-1}`)."""
        w, c = self.derivative_of(self.rows(steps)[k], k, size)
        return w, float(c)

    def derivative_of(self, row, k: int, size: int) -> tuple[np.ndarray, np.ndarray]:
        """(w, c) of :meth:`derivative` from law k's row of coefficients, of
        shape ``batch + (degree + 1,)`` (one design's, or k designs' at once)."""
        row = np.asarray(row, dtype=float)
        w = np.zeros(row.shape[:-1] + (size,))
        for j in range(2, row.shape[-1]):
            w[..., self.offsets[k] + j - 2] = j * row[..., j]
        return w, (row[..., 1] if row.shape[-1] > 1 else np.zeros(row.shape[:-1]))

    def fill(self, A: np.ndarray, b: np.ndarray, steps: Sequence[int]) -> None:
        """The clocks' rows of x' = A x + b: w_1' = 1, w_j' = j w_{j-1}, while
        a piece of positive degree runs; still otherwise."""
        for k, row in enumerate(self.rows(steps)):
            if len(row) < 2:
                continue
            o = self.offsets[k]
            b[o] = 1.0
            for j in range(2, len(row)):
                A[o + j - 1, o + j - 2] = float(j)

    def reset(self, x: np.ndarray, k: int) -> None:
        """Law k's clock back to 0 (its next piece begins)."""
        x[self.offsets[k]:self.offsets[k] + self.laws[k].degree] = 0.0

    def schedule(self) -> list[tuple[float, str]]:
        """(time, event) of each law's next piece."""
        return [(start, f"{law.name} next piece")
                for law, pieces in zip(self.laws, self.pieces) for start, _ in pieces[1:]]
