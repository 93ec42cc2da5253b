"""Elementary rewrite rules: exact identities that the rule set of
``rewriting`` and the entire-function planner of ``entire`` both build on.

Kept apart so that ``entire`` (below ``windows`` and ``rewriting``) can use them
without importing its own users.
"""
from __future__ import annotations

from typing import Callable

import sympy as sp

__all__ = ["Rule", "cos_pair_to_sin_squared", "fold_constants"]

Rule = Callable[[sp.Expr], sp.Expr]


def cos_pair_to_sin_squared(expr: sp.Expr) -> sp.Expr:
    """``a·cos(x) − a → −2a·sin²(x/2)``: no ``1 − cos`` cancellation at small x.

    Matches any sum that, collected in one ``cos(x)``, is ``a·cos(x) + b``
    with ``a + b = 0``; other terms of the sum are kept.

    Parameters
    ----------
    expr : sympy.Expr
        The expression to rewrite (every sum in it).
    """
    def rewrite(add: sp.Add) -> sp.Expr:
        for cos_x in sorted(add.atoms(sp.cos), key=sp.default_sort_key):
            parts = sp.collect(add, cos_x, evaluate=False)
            a = parts.get(cos_x)
            if a is None or a.has(cos_x):
                continue
            b = parts.get(sp.S.One, sp.S.Zero)
            # b may hold other terms too: split off the one that cancels a.
            rest = sp.expand(b + a)
            if sp.count_ops(rest) < sp.count_ops(sp.expand(b)) or rest == 0:
                half = cos_x.args[0] / 2
                return rest - 2 * a * sp.sin(half) ** 2
        return add

    return expr.replace(lambda e: e.is_Add and e.has(sp.cos), rewrite)


def fold_constants(expr: sp.Expr) -> sp.Expr:
    """Evaluate every numeric subexpression that is not a rational number at
    40 digits (``pi*sqrt(858)/13 -> 7.0...``), so the printed constant is the
    correctly rounded double; exponents are kept (``sqrt`` stays ``sqrt``)."""
    if expr.is_Rational or (expr.is_Atom and not expr.is_number):
        return expr
    if expr.is_number:
        value = sp.N(expr, 40)
        if value.is_Float:
            return sp.Float(value, 40)
        # not a real number (an arc cosine out of its domain, left for the
        # generated code to refuse by name): fold only its arguments
        return expr.func(*[fold_constants(a) for a in expr.args]) if expr.args else expr
    if isinstance(expr, sp.Pow):
        return sp.Pow(fold_constants(expr.base), expr.exp)
    return expr.func(*[fold_constants(a) for a in expr.args])
