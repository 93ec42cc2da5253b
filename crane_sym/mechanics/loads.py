"""Drive and load laws S(t) as SymPy objects: a small library of piecewise loads.

A load is a list of breakpoints and one expression per piece,

.. math::

    S(t) = S_k(t), \\qquad b_k \\le t < b_{k+1}, \\qquad k = 0, \\dots, N - 1,

with :math:`b_N = \\infty` and :math:`S(t) = 0` before :math:`b_0`. The
constructors build the laws of the Duhamel examples of Chovnyuk et al. (sudden
load, linear rise, linear rise then hold, rectangular pulse) and polynomial
laws given by numbers from a scene file. Numbers from a user are checked by
type and never parsed or evaluated (``exact_number``).
"""
from __future__ import annotations

import math
import numbers
from dataclasses import dataclass
from decimal import Decimal
from fractions import Fraction
from typing import NamedTuple, Sequence, Union

import sympy as sp

#: The time symbol used when a constructor is given none.
DEFAULT_TIME = sp.Symbol("t", nonnegative=True)

#: What a user may give where a number is expected.
Number = Union[int, float, Fraction, sp.Rational]


def exact_number(value: object, what: str) -> sp.Rational:
    """An exact SymPy rational from a number given by a user.

    Accepts ``int`` (any ``numbers.Integral`` but ``bool``), ``float``,
    ``fractions.Fraction`` and ``sympy.Rational``; a float is read as the
    decimal it prints as (``0.1 -> 1/10``). Everything else, strings first of
    all, is refused by type alone: the value is never converted, parsed or
    evaluated before it is accepted.

    Parameters
    ----------
    value : object
        The number as given.
    what : str
        Its name, for the error message.

    Raises
    ------
    TypeError
        For any other type, naming ``what``.
    ValueError
        For a float that is not finite.
    """
    if isinstance(value, (str, bytes)):
        raise TypeError(f"{what} must be a number (int, float, Fraction or "
                        f"sympy.Rational), got a string; text is never evaluated")
    if isinstance(value, bool):
        raise TypeError(f"{what} must be a number, got a bool")
    if isinstance(value, sp.Rational):
        return value
    if isinstance(value, numbers.Integral):
        return sp.Integer(int(value))
    if isinstance(value, Fraction):
        return sp.Rational(value.numerator, value.denominator)
    if isinstance(value, float):
        if not math.isfinite(value):
            raise ValueError(f"{what} must be finite, got {value}")
        num, den = Decimal(float.__repr__(value)).as_integer_ratio()
        return sp.Rational(num, den)
    raise TypeError(f"{what} must be a number (int, float, Fraction or "
                    f"sympy.Rational), got {type(value).__name__}")


def as_expression(value: object, what: str) -> sp.Expr:
    """A SymPy expression as given, or an exact number (see ``exact_number``).

    Used for the amplitudes and times of the constructors, which may be
    symbols (``S0``, ``theta``) or numbers; strings are refused.
    """
    if isinstance(value, sp.Expr):
        return value
    if isinstance(value, sp.Basic):
        raise TypeError(f"{what} must be a SymPy expression or a number, "
                        f"got {type(value).__name__}")
    return exact_number(value, what)


class Piece(NamedTuple):
    """An expression valid for ``start <= t < end`` (unpacks as a triple)."""

    start: sp.Expr
    end: sp.Expr
    expr: sp.Expr


@dataclass(frozen=True)
class PiecewiseLoad:
    """A load given piece by piece in time.

    Parameters
    ----------
    breakpoints : sequence of expressions
        :math:`b_0 < b_1 < \\dots`, with :math:`b_0 \\ge 0`. Symbolic
        breakpoints are allowed; an order SymPy cannot decide is taken as
        given.
    pieces : sequence of expressions in ``t``
        ``pieces[k]`` holds on :math:`[b_k, b_{k+1})`, the last one for all
        later times; the load is zero before :math:`b_0`.
    t : Symbol
        The time symbol of the pieces.
    """

    breakpoints: tuple[sp.Expr, ...]
    pieces: tuple[sp.Expr, ...]
    t: sp.Symbol = DEFAULT_TIME

    def __post_init__(self) -> None:
        if not isinstance(self.t, sp.Symbol):
            raise TypeError(f"t must be a sympy.Symbol, got {type(self.t).__name__}")
        if isinstance(self.breakpoints, (str, bytes)) or isinstance(self.pieces, (str, bytes)):
            raise TypeError("breakpoints and pieces must be sequences, not strings")
        bps = tuple(as_expression(b, f"breakpoints[{k}]")
                    for k, b in enumerate(self.breakpoints))
        pcs = tuple(as_expression(p, f"pieces[{k}]") for k, p in enumerate(self.pieces))
        object.__setattr__(self, "breakpoints", bps)
        object.__setattr__(self, "pieces", pcs)
        if not bps:
            raise ValueError("a load needs at least one breakpoint (its start)")
        if len(bps) != len(pcs):
            raise ValueError(f"{len(bps)} breakpoints need {len(bps)} pieces, "
                             f"got {len(pcs)}")
        for k, b in enumerate(bps):
            if self.t in b.free_symbols:
                raise ValueError(f"breakpoints[{k}] = {b} depends on {self.t}")
        if bps[0].is_negative:
            raise ValueError(f"breakpoints[0] must be >= 0, got {bps[0]}")
        for k in range(1, len(bps)):
            if (bps[k] - bps[k - 1]).is_positive is False:
                raise ValueError(f"breakpoints must increase: breakpoints[{k}] = "
                                 f"{bps[k]} is not above breakpoints[{k - 1}] = "
                                 f"{bps[k - 1]}")

    @property
    def intervals(self) -> tuple[Piece, ...]:
        """One ``Piece`` per interval; the last ``end`` is ``oo``."""
        ends = self.breakpoints[1:] + (sp.oo,)
        return tuple(Piece(*args) for args in zip(self.breakpoints, ends, self.pieces))

    def starting_at_zero(self) -> "PiecewiseLoad":
        """The same load with a zero piece on :math:`[0, b_0)` when
        :math:`b_0 \\ne 0`, so that its pieces cover all :math:`t \\ge 0`."""
        if self.breakpoints[0] == 0:
            return self
        return PiecewiseLoad((sp.Integer(0),) + self.breakpoints,
                             (sp.Integer(0),) + self.pieces, self.t)

    def as_piecewise(self) -> sp.Piecewise:
        """The load as one ``sympy.Piecewise`` in ``t`` (zero before :math:`b_0`)."""
        args = [(sp.Integer(0), self.t < self.breakpoints[0])]
        for piece in self.intervals[:-1]:
            args.append((piece.expr, self.t < piece.end))
        args.append((self.pieces[-1], True))
        return sp.Piecewise(*args)

    def at(self, time: sp.Expr) -> sp.Expr:
        """The load at ``time`` (a number or an expression)."""
        return self.as_piecewise().subs(self.t, time)

    def scaled(self, factor: sp.Expr) -> "PiecewiseLoad":
        """The load multiplied by ``factor`` (e.g. ``1/m`` for a force)."""
        factor = as_expression(factor, "factor")
        return PiecewiseLoad(self.breakpoints, tuple(factor * p for p in self.pieces),
                             self.t)


# --- Constructors ------------------------------------------------------------
def step(S0: sp.Expr | Number, *, t: sp.Symbol = DEFAULT_TIME) -> PiecewiseLoad:
    """Sudden load :math:`S(t) = S_0` for :math:`t \\ge 0` (Chovnyuk et al., eq (35)).

    Parameters
    ----------
    S0 : expression or number
        The load.
    t : Symbol, optional
        Time.
    """
    return PiecewiseLoad((0,), (as_expression(S0, "S0"),), t)


def linear(rate: sp.Expr | Number, *, t: sp.Symbol = DEFAULT_TIME) -> PiecewiseLoad:
    """Unbounded linear rise :math:`S(t) = k t` (Chovnyuk et al., eq (40)).

    Parameters
    ----------
    rate : expression or number
        The slope :math:`k`.
    t : Symbol, optional
        Time.
    """
    return PiecewiseLoad((0,), (as_expression(rate, "rate") * t,), t)


def ramp(S0: sp.Expr | Number, t1: sp.Expr | Number, *,
         t: sp.Symbol = DEFAULT_TIME) -> PiecewiseLoad:
    """Linear rise to :math:`S_0` at :math:`t_1`, then hold (Chovnyuk et al., eqs (48)–(49)).

    .. math::

        S(t) = S_0 \\frac{t}{t_1} \\; (0 \\le t < t_1), \\qquad S(t) = S_0 \\; (t \\ge t_1)

    Parameters
    ----------
    S0 : expression or number
        The load held after the rise.
    t1 : expression or number
        Duration of the rise (> 0).
    t : Symbol, optional
        Time.
    """
    S0, t1 = as_expression(S0, "S0"), as_expression(t1, "t1")
    return PiecewiseLoad((0, t1), (S0 * t / t1, S0), t)


def rectangular_pulse(S0: sp.Expr | Number, theta: sp.Expr | Number, *,
                      t: sp.Symbol = DEFAULT_TIME) -> PiecewiseLoad:
    """Load :math:`S_0` for :math:`0 \\le t < \\theta`, zero after (Chovnyuk et al., eq (44)).

    Parameters
    ----------
    S0 : expression or number
        The load during the pulse.
    theta : expression or number
        Duration of the pulse (> 0).
    t : Symbol, optional
        Time.
    """
    S0, theta = as_expression(S0, "S0"), as_expression(theta, "theta")
    return PiecewiseLoad((0, theta), (S0, sp.Integer(0)), t)


def piecewise_polynomial(breakpoints: Sequence[Number],
                         coefficients: Sequence[Sequence[Number]], *,
                         t: sp.Symbol = DEFAULT_TIME) -> PiecewiseLoad:
    """A polynomial per piece, from numbers only (e.g. from a scene file).

    .. math::

        S(t) = \\sum_j c_{kj} (t - b_k)^j, \\qquad b_k \\le t < b_{k+1}

    Parameters
    ----------
    breakpoints : sequence of numbers
        :math:`b_0 < b_1 < \\dots`.
    coefficients : sequence of sequences of numbers
        ``coefficients[k][j]`` is :math:`c_{kj}`.
    t : Symbol, optional
        Time.

    Every entry must be an ``int``, ``float``, ``Fraction`` or
    ``sympy.Rational`` (see ``exact_number``); anything else, a string in
    particular, raises ``TypeError`` before any entry is used.
    """
    if isinstance(breakpoints, (str, bytes)) or isinstance(coefficients, (str, bytes)):
        raise TypeError("breakpoints and coefficients must be sequences of numbers, "
                        "not strings")
    bps = [exact_number(b, f"breakpoints[{k}]") for k, b in enumerate(breakpoints)]
    rows = []
    for k, row in enumerate(coefficients):
        if isinstance(row, (str, bytes)) or not isinstance(row, Sequence):
            raise TypeError(f"coefficients[{k}] must be a sequence of numbers, "
                            f"got {type(row).__name__}")
        rows.append([exact_number(c, f"coefficients[{k}][{j}]")
                     for j, c in enumerate(row)])
    if len(rows) != len(bps):
        raise ValueError(f"{len(bps)} breakpoints need {len(bps)} coefficient rows, "
                         f"got {len(rows)}")
    pieces = [sum((c * (t - b) ** j for j, c in enumerate(row)), sp.Integer(0))
              for b, row in zip(bps, rows)]
    return PiecewiseLoad(tuple(bps), tuple(pieces), t)
