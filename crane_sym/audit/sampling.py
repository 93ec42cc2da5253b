"""Seeded points inside the physics, for the numeric check.

A relation is compared at points where every symbol has a value it could have:
data (``parameter`` symbols) drawn log-uniformly from their physical ranges;
a quantity a step defines (``defined``) computed from its definition at those
data, not drawn on its own, so M_в is the moment of the drawn loads (not
−0.6 N·m) and α_tw the operating angle of the drawn gears (not 1.99 rad).
Symbols of one dimension are kept a factor of 2 apart where their ranges
allow (of several candidate points the best separated is taken), so that a
swap of m1 and m2, or of two lengths, moves the result by a visible amount and
the numeric check catches it on its own.

Unknowns of an implicit relation (time, coordinates, a defined quantity the
relation solves for) stay free: the check draws them twice, and a defined
one is drawn about its definition (within a factor of 3) so that its terms
keep the size they have in the physics.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Callable, Sequence

import mpmath
import numpy as np
import sympy as sp
from sympy.core.function import AppliedUndef

from crane_sym.symbols import DEFINED, PARAMETER, PhysicalSymbol, SymbolTable

__all__ = ["PointSampler", "draw", "physical_definitions", "separation"]

#: Candidate points tried for each point the check uses.
TRIES = 24
#: The separation sought between symbols of one dimension (a factor of 2).
SEPARATION = math.log(2.0)
#: The largest definition (SymPy operations) worth substituting.
_MAX_OPS = 400


def draw(entry: PhysicalSymbol, rng: np.random.Generator) -> float:
    """A value of ``entry`` in its physical range (log-uniform), with a random sign
    when the symbol is ``real``, below zero when it is ``negative``."""
    lo, hi = entry.sample_range
    value = float(np.exp(rng.uniform(np.log(lo), np.log(hi))))
    if entry.sign == "negative" or entry.sign == "real" and rng.random() < 0.5:
        value = -value
    return value


def physical_definitions(steps: Sequence, table: SymbolTable) -> dict[sp.Symbol, sp.Expr]:
    """Each ``defined`` symbol -> its definition in the data (``parameter`` symbols).

    A definition is a step that states the symbol alone on its left
    (``Eq(sym, expr)``, ``sym`` not in ``expr``); it is used only when it is the
    symbol's one definition (every such step gives the same expression: a
    symbol a paper computes several ways, like a torque hoisting and lowering,
    has no one value), when it is not a bare number (a special case, such as
    x̃_* = 0 for a start from rest, is not what the symbol means), and when it
    holds no time, coordinate, function or integral. Defined symbols in it are
    replaced by theirs. A symbol left out is drawn from its own range."""
    data = {e.expr for e in table.with_role(PARAMETER)}
    defined = {e.expr for e in table.with_role(DEFINED)}
    found: dict[sp.Symbol, set] = {}
    for step in steps:
        st = step.statement
        if isinstance(st, sp.Equality) and st.lhs in defined \
                and st.lhs not in st.rhs.free_symbols:
            found.setdefault(st.lhs, set()).add(st.rhs)
    raw: dict[sp.Symbol, sp.Expr] = {}
    for sym, rhss in found.items():
        if len(rhss) != 1:
            continue
        (rhs,) = rhss
        if (not rhs.free_symbols or rhs.atoms(AppliedUndef)
                or rhs.has(sp.Derivative, sp.Integral, sp.Piecewise)
                or sp.count_ops(rhs) > _MAX_OPS or not rhs.free_symbols <= data | defined):
            continue
        raw[sym] = rhs
    resolved: dict[sp.Symbol, sp.Expr] = {}
    for sym, expr in raw.items():
        for _ in range(6):
            inner = expr.free_symbols & set(raw)
            if not inner:
                break
            expr = expr.xreplace({s: raw[s] for s in inner})
        if expr.free_symbols <= data and sp.count_ops(expr) <= 4 * _MAX_OPS:
            resolved[sym] = expr
    return resolved


def separation(values: dict, dims: dict) -> float:
    """The smallest |log(a/b)| between two symbols of one dimension (inf if none)."""
    groups: dict = {}
    for sym, value in values.items():
        if value:
            groups.setdefault(dims[sym], []).append(math.log(abs(float(value))))
    gaps = [abs(a - b) for logs in groups.values()
            for i, a in enumerate(logs) for b in logs[i + 1:]]
    return min(gaps, default=math.inf)


def _sign_ok(entry: PhysicalSymbol, value) -> bool:
    if entry.sign == "positive":
        return value > 0
    if entry.sign == "negative":
        return value < 0
    return value >= 0 if entry.sign == "nonnegative" else True


@dataclass
class PointSampler:
    """Draws the data of a relation and computes the defined symbols it holds.

    Parameters
    ----------
    params : list of PhysicalSymbol
        Data symbols of the relation, drawn from their ranges.
    derived : dict of Symbol to Expr
        Defined symbols of the relation that are computed, with their
        definitions in data symbols (which need not appear in the relation).
    table : SymbolTable
        Where the data of the definitions and every dimension come from.
    """

    params: list[PhysicalSymbol]
    derived: dict[sp.Symbol, sp.Expr]
    table: SymbolTable

    def __post_init__(self) -> None:
        own = {e.expr for e in self.params}
        extra = set().union(*[d.free_symbols for d in self.derived.values()]) - own
        self._hidden = [self.table[s] for s in sorted(extra, key=str)]
        inputs = [e.expr for e in self.params + self._hidden]
        self._fns: list[tuple[sp.Symbol, Callable]] = [
            (s, sp.lambdify(inputs, d, modules="mpmath")) for s, d in self.derived.items()]
        self._dims = {e.expr: e.dimension for e in self.table}

    def point(self, rng: np.random.Generator,
              shown: dict | None = None) -> tuple[list, dict[sp.Symbol, mpmath.mpf]]:
        """(values of ``params`` in order, values of ``derived``): the best separated
        of up to ``TRIES`` candidates whose defined values are real and of their
        symbol's sign. ``shown`` adds further values (the unknowns) to the
        separation score."""
        best, best_score = None, -1.0
        for _ in range(TRIES):
            values = [mpmath.mpf(draw(e, rng)) for e in self.params + self._hidden]
            derived = {}
            try:
                for sym, fn in self._fns:
                    v = fn(*values)
                    if isinstance(v, (mpmath.mpc, complex)):
                        raise ValueError(sym)
                    v = mpmath.mpf(v)
                    if not mpmath.isfinite(v) or not _sign_ok(self.table[sym], v):
                        raise ValueError(sym)
                    derived[sym] = v
            except (ValueError, ZeroDivisionError, TypeError):
                continue
            scored = dict(zip([e.expr for e in self.params], values)) | derived
            score = separation(scored | (shown or {}), self._dims)
            if score > best_score:
                best, best_score = (values[:len(self.params)], derived), score
            if score >= SEPARATION:
                break
        if best is None:
            raise ValueError("no point inside the physics: every candidate gave a defined "
                             f"symbol out of its sign or not real ({list(self.derived)})")
        return best
