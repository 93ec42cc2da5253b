"""Substitution checks of a piecewise solution: ODE residual on each piece,
continuity of u and u' at each breakpoint, initial values.

Used by ``duhamel.DuhamelResult.verify``; each check is symbolic first and can
be refuted numerically at seeded points when simplification cannot decide.
"""
from __future__ import annotations

import random
from dataclasses import dataclass

import sympy as sp

from crane_sym.outcomes import FAIL, INCONCLUSIVE, PASS
from crane_sym.mechanics.loads import Piece


@dataclass(frozen=True)
class VerificationItem:
    """One substitution check: what, ``pass``/``fail``/``inconclusive``, detail."""

    what: str
    status: str
    detail: str


@dataclass(frozen=True)
class Verification:
    """Report of ``DuhamelResult.verify``: ODE residuals, continuity, initial values."""

    items: tuple[VerificationItem, ...]

    @property
    def ok(self) -> bool:
        """True when every check passed."""
        return bool(self.items) and all(i.status == PASS for i in self.items)

    def failures(self) -> tuple[VerificationItem, ...]:
        """The checks that did not pass."""
        return tuple(i for i in self.items if i.status != PASS)


def _zero(what: str, expr: sp.Expr, seed: int = 2024) -> VerificationItem:
    """Symbolic zero test; when simplification cannot decide, a seeded numeric
    evaluation at positive values of every symbol can still refute it."""
    for form in (sp.simplify(expr), sp.simplify(sp.expand(sp.expand_trig(expr)))):
        if form == 0:
            return VerificationItem(what, PASS, "simplifies to 0")
    rng = random.Random(seed)
    symbols = sorted(expr.free_symbols, key=str)
    for _ in range(3):
        point = {s: sp.Rational(rng.randint(50, 200), 100) for s in symbols}
        value = sp.N(expr.subs(point), 30)
        if value.is_number and abs(value) > sp.Float("1e-20"):
            return VerificationItem(what, FAIL, f"is {sp.N(value, 6)} at {point}")
    return VerificationItem(what, INCONCLUSIVE,
                            f"did not simplify to 0: {sp.sstr(sp.simplify(expr))}")


def _verify_pieces(equation: sp.Eq, pieces: tuple[Piece, ...], t: sp.Symbol,
                   load: tuple[Piece, ...], u: sp.Expr | None, forcing: sp.Expr | None,
                   initial: dict[int, sp.Expr]) -> Verification:
    """Residual of ``equation`` on each piece, continuity of ``u`` and ``u'`` at
    each breakpoint, initial values at ``t = 0``."""
    items: list[VerificationItem] = []
    try:
        residual = equation.lhs - equation.rhs
        if u is None:
            found = {d.expr for d in residual.atoms(sp.Derivative)
                     if isinstance(d.expr, sp.core.function.AppliedUndef)}
            if len(found) != 1:
                return Verification((VerificationItem(
                    "equation", FAIL, f"expected one unknown under d/dt, found "
                    f"{sorted(map(str, found))}"),))
            (u,) = found
        for piece, force in zip(pieces, load):
            r = residual if forcing is None else residual.subs(forcing, force.expr)
            r = r.subs(u, piece.expr).doit()
            items.append(_zero(f"residual on [{piece.start}, {piece.end})", r))
        for before, after in zip(pieces, pieces[1:]):
            for order, name in ((0, "u"), (1, "u'")):
                jump = (before.expr.diff(t, order) - after.expr.diff(t, order)
                        ).subs(t, after.start)
                items.append(_zero(f"continuity of {name} at t = {after.start}", jump))
        if pieces[0].start == 0:
            for order, value in sorted(initial.items()):
                items.append(_zero(f"initial value of u^({order})",
                                   pieces[0].expr.diff(t, order).subs(t, 0) - value))
    except Exception as exc:  # the report, not the caller, carries the failure
        items.append(VerificationItem("verification", FAIL,
                                      f"{type(exc).__name__}: {exc}"))
    return Verification(tuple(items))
