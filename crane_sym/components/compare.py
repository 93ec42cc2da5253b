"""A component model's equations against a hand-written model's, symbolically.

A paper's drive written as components must give the paper's equations, not
only its numbers. :func:`compare_equations` puts a mode's contacts, switches
and friction into the component model's Lagrange equations, renames its
symbols to the paper's (a mapping such as ``m_hook -> m_h + m_p``), and checks
each against the hand-written equation of the same coordinate by simplifying
the difference, as the audit checks a printed formula (symbolic identity
first). The record says which equations agree, and what is left where one
does not.
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Mapping, Sequence

import sympy as sp

from crane_sym.components.equations import Equations
from crane_sym.outcomes import FAIL, PASS, CheckOutcome

__all__ = ["EquationRecord", "compare_equations"]


@dataclass(frozen=True)
class EquationRecord:
    """One coordinate's equation: the component model's (after the mode and the
    renaming), the hand-written one, and the outcome of the check."""

    coordinate: str
    derived: sp.Eq
    reference: sp.Eq
    outcome: CheckOutcome

    def latex(self) -> str:
        """Both equations and the verdict, for a handout or a review."""
        return (f"derived: ${sp.latex(self.derived)}$; hand-written: "
                f"${sp.latex(self.reference)}$; {self.outcome.status} "
                f"({self.outcome.detail})")


def compare_equations(equations: Equations, reference: Sequence[sp.Eq],
                      mode: Mapping[sp.Symbol, sp.Expr],
                      names: Mapping[sp.Basic, sp.Expr]) -> list[EquationRecord]:
    """Check each Lagrange equation of ``equations`` against ``reference[i]``.

    Parameters
    ----------
    equations : the component model's derivation
    reference : the hand-written equations, one per coordinate, in its order
    mode : values of the mode's symbols (contact χ, flank δ, motor switches,
        brake friction B): what the hand-written model has in the mode compared
    names : the component symbols and coordinates renamed to the paper's
    """
    if len(reference) != len(equations.lagrange.equations):
        raise ValueError(f"{len(reference)} hand-written equations for "
                         f"{len(equations.lagrange.equations)} coordinates")
    records = []
    for q, eq, ref in zip(equations.coordinates, equations.lagrange.equations, reference):
        derived = sp.Eq(eq.lhs.subs(mode).subs(names), eq.rhs.subs(mode).subs(names))
        left = sp.simplify((derived.lhs - derived.rhs) - (ref.lhs - ref.rhs))
        if left == 0:
            outcome = CheckOutcome("symbolic", PASS, "derived − hand-written simplifies to 0")
        elif sp.simplify((derived.lhs - derived.rhs) + (ref.lhs - ref.rhs)) == 0:
            outcome = CheckOutcome("symbolic", PASS, "the same equation, sides exchanged")
        else:
            outcome = CheckOutcome("symbolic", FAIL, f"the difference is ${sp.latex(left)}$")
        records.append(EquationRecord(str(q.func), derived, ref, outcome))
    return records
