"""Readings made from the transcription by a named operation.

A reading of the print (``published.Convention``) is the transcription read
another way. Typed beside the transcription as a second relation, nothing ties
the two: a slip in the transcription never reaches the reading, and nothing
checks that the reading is the print read another way. A reading given as one
of these operations is made from the transcription each time it is tried, so
what the reading checks is the number or formula transcribed:

- ``Meaning``: names of the print given the quantities they stand for (a symbol
  for another; k1 read as −Δy1), a substitution;
- ``SignOnce``: the term after a line break whose operator is printed twice,
  −(−T), read with its sign once, −T;
- ``Scaled``: the whole right-hand side times a stated factor (Y per unit force
  is Y of (16) divided by m; ÷ over the whole product a·c divides by c twice
  more than left to right; a decimal comma lost, 154 read as 1.54).

>>> import sympy as sp
>>> k, dy, d = sp.symbols("k Delta_y d")
>>> Meaning(((k, -dy),)).applied(sp.Eq(d, 2 * (1 + k)))
Eq(d, 2 - 2*Delta_y)
"""
from __future__ import annotations

from dataclasses import dataclass

import sympy as sp

__all__ = ["Meaning", "Reinterpretation", "Scaled", "SignOnce"]


class Reinterpretation:
    """An operation that makes a reading from a transcription."""

    def applied(self, printed: sp.Eq) -> sp.Eq:
        """The reading of ``printed``, the transcription, under this operation."""
        raise NotImplementedError


@dataclass(frozen=True)
class Meaning(Reinterpretation):
    """Each printed name (a symbol, a function of time) replaced by the quantity
    it stands for, on both sides, derivatives taken again where a function of
    time was replaced."""

    pairs: tuple[tuple[sp.Basic, sp.Basic], ...]

    def applied(self, printed: sp.Eq) -> sp.Eq:
        """``printed`` with every name of ``pairs`` replaced at once."""
        sides = [side.subs(dict(self.pairs), simultaneous=True).replace(
                     lambda e: isinstance(e, sp.Derivative), lambda e: e.doit())
                 for side in (printed.lhs, printed.rhs)]
        return sp.Eq(*sides, evaluate=False)


@dataclass(frozen=True)
class SignOnce(Reinterpretation):
    """The term ``term`` printed after a line break as −(−term) (the minus
    repeated at the break, as Russian and Ukrainian typesetting does) read with
    one minus: the right-hand side less twice the term."""

    term: sp.Expr

    def applied(self, printed: sp.Eq) -> sp.Eq:
        """``printed`` with ``+term`` read as ``−term``."""
        return sp.Eq(printed.lhs, printed.rhs - 2 * self.term, evaluate=False)


@dataclass(frozen=True)
class Scaled(Reinterpretation):
    """The right-hand side times ``factor``: what a reading changes uniformly in
    a relation linear in the quantity it reads."""

    factor: sp.Expr

    def applied(self, printed: sp.Eq) -> sp.Eq:
        """``printed`` with its right-hand side times ``factor``."""
        return sp.Eq(printed.lhs, printed.rhs * self.factor, evaluate=False)
