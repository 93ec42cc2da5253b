"""Laws a scene gives as numbers: piecewise polynomials in time, with units.

A scene load such as a drive acceleration a(t) is given in a TOML table as
breakpoints and polynomial coefficients per piece, with the units they are
written in::

    breakpoints = [0.0, 0.25, 1.0, 1.25]          # in time_unit
    coefficients = [[0.0, 2.0], [0.5], [0.5, -2.0]]  # c_kj in value_unit / time_unit^j
    time_unit = "s"

:func:`piecewise_law` builds the law from numbers only; :func:`read_law_table`
checks a table's keys, converts to SI and returns exact numbers. Entries are
checked by type (``loads.exact_number``): text is refused, never parsed or
evaluated; unit text is parsed by ``crane_sym.units``. The symbolic work a law
causes grows with its number of pieces and their degree, and its numbers
must stay where the printed double-precision code holds: a reader states
:class:`LawLimits` and :func:`read_law_table` refuses a law beyond them,
naming the limit, before anything is convolved or written.
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Any, Mapping, Sequence

import sympy as sp
from sympy.physics.units import time as _TIME
from sympy.physics.units.dimensions import Dimension

from crane_sym import units
from crane_sym.mechanics.loads import DEFAULT_TIME, PiecewiseLoad, exact_number, piecewise_polynomial
from crane_sym.scenes.options import did_you_mean

__all__ = ["LawLimits", "check_keys", "piecewise_law", "read_law_table"]


@dataclass(frozen=True)
class LawLimits:
    """Bounds on a law a scene gives as numbers, checked on reading.

    Attributes
    ----------
    pieces : int
        Most pieces (``len(breakpoints) - 1``).
    degree : int
        Highest polynomial degree of a piece (``len(row) - 1``).
    end : float
        Latest breakpoint [s]; the law starts at or after 0.
    shortest : float
        Shortest piece [s]: the Duhamel response of a short piece of high
        degree is a difference of large terms.
    value : float
        Largest :math:`|c_{kj}| b_{k+1}^j` (SI of the law's values): the
        printed code expands :math:`c_{kj} (t - b_k)^j` in powers of t, and no
        power exceeds about this on :math:`[0, b_{k+1}]`, so none cancels
        another beyond what double precision keeps.
    unit : str
        The SI unit of the law's values, for the messages.
    """

    pieces: int
    degree: int
    end: float
    shortest: float
    value: float
    unit: str

    def check_counts(self, rows: Any) -> None:
        """ValueError if the coefficient rows, as given, are more pieces or of a
        higher degree than allowed (rows that are no sequences are left to
        :func:`piecewise_law`)."""
        if not _is_list(rows):
            return
        if len(rows) > self.pieces:
            raise ValueError(f"has {len(rows)} pieces; at most {self.pieces} are allowed "
                             f"(len(coefficients) <= {self.pieces})")
        for k, row in enumerate(rows):
            if _is_list(row) and len(row) - 1 > self.degree:
                raise ValueError(f"coefficients[{k}] has degree {len(row) - 1}; at most "
                                 f"{self.degree} is allowed (len(coefficients[{k}]) <= "
                                 f"{self.degree + 1})")

    def check_values(self, breakpoints: Sequence[sp.Rational],
                     rows: Sequence[Sequence[sp.Rational]]) -> None:
        """ValueError naming the first breakpoint or coefficient (SI) beyond the
        limits."""
        if breakpoints[-1] > self.end:
            raise ValueError(f"breakpoints[{len(breakpoints) - 1}] = "
                             f"{float(breakpoints[-1]):g} s is after {self.end:g} s, the "
                             "latest end of a law")
        for k, row in enumerate(rows):
            start, end = breakpoints[k], breakpoints[k + 1]
            if end - start < self.shortest:
                raise ValueError(f"piece {k} [{float(start):g} s, {float(end):g} s] lasts "
                                 f"{float(end - start):g} s, less than {self.shortest:g} s, "
                                 "the shortest piece")
            for j, c in enumerate(row):
                if abs(c) * end ** j > self.value:
                    term = f"|c|*b^{j}" if j else "|c|"
                    at = f" (b = {float(end):g} s, the piece's end)" if j else ""
                    raise ValueError(
                        f"coefficients[{k}][{j}] = {float(c):.4g} (SI) is too large: {term} = "
                        f"{float(abs(c) * end ** j):.4g} {self.unit}{at}, more than "
                        f"{self.value:g} {self.unit}")


def _is_list(value: Any) -> bool:
    return isinstance(value, Sequence) and not isinstance(value, (str, bytes))


def piecewise_law(breakpoints: Sequence[Any], coefficients: Sequence[Sequence[Any]], *,
                  t: sp.Symbol = DEFAULT_TIME) -> PiecewiseLoad:
    """A law that is a polynomial per piece and 0 outside, from numbers only.

    .. math:: a(t) = \\sum_j c_{kj} (t - b_k)^j \\; (b_k \\le t < b_{k+1}),
              \\qquad a(t) = 0 \\; (t < b_0 \\text{ or } t \\ge b_N)

    Parameters
    ----------
    breakpoints : N + 1 numbers :math:`b_0 < \\dots < b_N`
    coefficients : N sequences of numbers :math:`c_{kj}`
    t : Symbol

    Returns
    -------
    PiecewiseLoad
        N + 1 pieces, the last one 0. A string entry raises ``TypeError`` and is
        never parsed or evaluated; counts and order raise ``ValueError``.
    """
    for what, seq in (("breakpoints", breakpoints), ("coefficients", coefficients)):
        if isinstance(seq, (str, bytes)) or not isinstance(seq, Sequence):
            raise TypeError(f"{what} must be a list of numbers, got {type(seq).__name__}")
    if len(breakpoints) < 2:
        raise ValueError(f"breakpoints needs at least 2 entries (start and end of the "
                         f"law), got {len(breakpoints)}")
    if len(coefficients) != len(breakpoints) - 1:
        raise ValueError(f"{len(breakpoints)} breakpoints bound {len(breakpoints) - 1} "
                         f"pieces, so coefficients needs {len(breakpoints) - 1} rows, "
                         f"got {len(coefficients)}")
    rows = list(coefficients) + [[0]]
    return piecewise_polynomial(list(breakpoints), rows, t=t)


def check_keys(table: Mapping[str, Any], allowed: Sequence[str],
               required: Sequence[str]) -> None:
    """ValueError naming the unknown and the missing keys of ``table`` (and the
    allowed key closest to an unknown one).

    Parameters
    ----------
    table : mapping
        The table as read.
    allowed : sequence of str
        Every key it may have.
    required : sequence of str
        The keys it must have.
    """
    unknown = sorted(set(table) - set(allowed))
    missing = [k for k in required if k not in table]
    if unknown or missing:
        wrong = " and ".join(([f"unknown keys {unknown}"] if unknown else [])
                             + ([f"missing {missing}"] if missing else []))
        hint = did_you_mean(unknown[0], allowed) if unknown else ""
        raise ValueError(f"has {wrong}; {hint}it takes {list(allowed)}")


def _unit_factor(table: Mapping[str, Any], key: str, default: str, dim: Dimension
                 ) -> sp.Rational:
    """The SI factor of the unit text ``table[key]`` (default ``default``)."""
    text = table.get(key, default)
    try:
        if not isinstance(text, str):
            raise units.UnitError(f"must be a unit text like {default!r}, got {text!r}")
        factor, found = units.parse_unit(text)
        if not units.same_dimension(found, dim):
            raise units.UnitError(f"{text!r} is {units.format_dimension(found)}, "
                                  f"expected {units.format_dimension(dim)}")
    except units.UnitError as exc:
        raise ValueError(f"{key}: {exc}") from None
    return exact_number(factor, key)


def read_law_table(table: Mapping[str, Any], value_key: str, dimension: Dimension,
                   default_unit: str, limits: LawLimits
                   ) -> tuple[tuple[sp.Rational, ...], tuple[tuple[sp.Rational, ...], ...]]:
    """Breakpoints [s] and coefficient rows (SI) of a law written in a table.

    The table holds ``breakpoints``, ``coefficients``, optionally ``time_unit``
    (default ``"s"``) and ``value_key`` (the unit of the law's values, of
    ``dimension``, default ``default_unit``); ``c_kj`` is in that unit per
    time unit to the power j. Other keys are the caller's to check.

    Raises ``TypeError`` for an entry that is not a number and ``ValueError``
    for a missing key, a bad unit, counts that do not match, or a law beyond
    ``limits`` (its counts checked before any entry is read).

    Parameters
    ----------
    table : mapping
        The table as read from TOML.
    value_key : str
        The key of the values' unit.
    dimension : Dimension
        The dimension of the law's values.
    default_unit : str
        The values' unit when the table names none.
    limits : LawLimits
        The largest law accepted.
    """
    missing = [k for k in ("breakpoints", "coefficients") if k not in table]
    if missing:
        raise ValueError(f"missing {missing}")
    to_s = _unit_factor(table, "time_unit", "s", _TIME)
    to_si = _unit_factor(table, value_key, default_unit, dimension)
    limits.check_counts(table["coefficients"])    # before any entry is read
    checked = piecewise_law(table["breakpoints"], table["coefficients"])
    rows = tuple(tuple(exact_number(c, "c") * to_si / to_s ** j for j, c in enumerate(row))
                 for row in table["coefficients"])
    breakpoints = tuple(b * to_s for b in checked.breakpoints)
    limits.check_values(breakpoints, rows)
    return breakpoints, rows
