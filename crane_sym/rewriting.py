"""Rewrite rules applied to every expression before it is printed as code.

Each rule is a callable ``expr -> expr`` that returns an equal expression in a
form that floating point evaluates without cancellation. ``optimize`` applies
them in order; the code generator uses ``DEFAULT_RULES`` for every paper, so a
stable form is never patched into one function by hand.
"""
from __future__ import annotations

from typing import Callable, Sequence

import sympy as sp
from sympy.codegen.rewriting import expm1_opt, log1p_opt

Rule = Callable[[sp.Expr], sp.Expr]


def cos_pair_to_sin_squared(expr: sp.Expr) -> sp.Expr:
    """``a·cos(x) − a → −2a·sin²(x/2)``: no ``1 − cos`` cancellation at small x.

    Matches any sum that, collected in one ``cos(x)``, is ``a·cos(x) + b``
    with ``a + b = 0``; other terms of the sum are kept.
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


def sin_squared_form(expr: sp.Expr) -> sp.Expr:
    """Factor a numerator that became ``k·(1 − cos x)`` after collection."""
    return sp.factor_terms(expr)


#: Rules every generated expression goes through, in order.
DEFAULT_RULES: tuple[Rule, ...] = (
    sin_squared_form,
    cos_pair_to_sin_squared,
    expm1_opt,
    log1p_opt,
)


def optimize(expr: sp.Expr, rules: Sequence[Rule] = DEFAULT_RULES) -> sp.Expr:
    """Apply ``rules`` in order until the expression stops changing."""
    for _ in range(5):
        before = expr
        for rule in rules:
            expr = rule(expr)
        if expr == before:
            break
    return expr
