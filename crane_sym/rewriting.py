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


class diff_of_products(sp.Function):
    """``a·b − c·d``, to be evaluated with one rounding (Dekker's TwoProduct).

    Printed as a call to a helper of the generated module; evaluates
    symbolically to the plain difference.
    """

    nargs = 4

    def _eval_rewrite_as_Add(self, a, b, c, d, **kwargs):  # noqa: N802
        return a * b - c * d

    def _eval_evalf(self, prec):
        a, b, c, d = self.args
        return (a * b - c * d)._eval_evalf(prec)


def _two_factors(term: sp.Expr) -> tuple[int, list[sp.Expr]] | None:
    """``(sign, [x, y])`` when ``term`` is ±x·y with non-numeric x, y."""
    coeff, factors = term.as_coeff_mul()
    if coeff not in (1, -1) or len(factors) != 2:
        return None
    if any(f.is_Number or f.is_Add for f in factors):
        return None
    return int(coeff), list(factors)


def exact_difference_of_products(expr: sp.Expr) -> sp.Expr:
    """``x·y − z·w → diff_of_products(x, y, z, w)``: a sum of two two-factor
    products of opposite sign, which cancels when the products are close."""
    def rewrite(add: sp.Add) -> sp.Expr:
        if len(add.args) != 2:
            return add
        parts = [_two_factors(term) for term in add.args]
        if None in parts or parts[0][0] == parts[1][0]:
            return add
        (s1, f1), (_, f2) = parts
        first, second = (f1, f2) if s1 == 1 else (f2, f1)
        return diff_of_products(*first, *second)

    return expr.replace(lambda e: e.is_Add, rewrite)


class sin_phase(sp.Function):
    """``sin(k·t)`` whose phase ``k·t`` is formed in double-double.

    ``t`` is the array argument and ``k`` a parameter-only factor. Where
    ``k·t`` is large, one rounding of the phase is a large *relative* error of
    the sine near its zeros; the generated kernel keeps the phase exact.
    """

    nargs = 2

    def _eval_rewrite_as_sin(self, t, k, **kwargs):
        return sp.sin(k * t)


class cos_phase(sp.Function):
    """``cos(k·t)`` with the phase ``k·t`` formed in double-double."""

    nargs = 2

    def _eval_rewrite_as_cos(self, t, k, **kwargs):
        return sp.cos(k * t)


def accurate_phase(varying: set[sp.Symbol]) -> Rule:
    """Rule: ``sin(k·t) → sin_phase(t, k)`` (likewise cos) for ``t`` in
    ``varying`` and ``k`` free of it."""
    def rewrite(f: sp.Function) -> sp.Expr:
        arg = f.args[0]
        for t in sorted(varying & arg.free_symbols, key=str):
            k = sp.simplify(arg / t)
            if not (k.free_symbols & varying):
                return (sin_phase if isinstance(f, sp.sin) else cos_phase)(t, k)
        return f

    def rule(expr: sp.Expr) -> sp.Expr:
        return expr.replace(lambda e: isinstance(e, (sp.sin, sp.cos)), rewrite)

    return rule


def sin_squared_form(expr: sp.Expr) -> sp.Expr:
    """Factor a numerator that became ``k·(1 − cos x)`` after collection."""
    return sp.factor_terms(expr)


def fold_constants(expr: sp.Expr) -> sp.Expr:
    """Evaluate every numeric subexpression that is not a rational number at
    40 digits (``pi*sqrt(858)/13 -> 7.0...``), so the printed constant is the
    correctly rounded double; exponents are kept (``sqrt`` stays ``sqrt``)."""
    if expr.is_Rational or (expr.is_Atom and not expr.is_number):
        return expr
    if expr.is_number:
        return sp.Float(sp.N(expr, 40), 40)
    if isinstance(expr, sp.Pow):
        return sp.Pow(fold_constants(expr.base), expr.exp)
    return expr.func(*[fold_constants(a) for a in expr.args])


#: Rules every generated expression goes through, in order.
DEFAULT_RULES: tuple[Rule, ...] = (
    sin_squared_form,
    cos_pair_to_sin_squared,
    exact_difference_of_products,
    expm1_opt,
    log1p_opt,
    fold_constants,
)


def rules_for(varying: set[sp.Symbol]) -> tuple[Rule, ...]:
    """The rules for a function whose array arguments are ``varying``."""
    return DEFAULT_RULES + (accurate_phase(varying),)


def optimize(expr: sp.Expr, rules: Sequence[Rule] = DEFAULT_RULES) -> sp.Expr:
    """Apply ``rules`` in order until the expression stops changing."""
    for _ in range(5):
        before = expr
        for rule in rules:
            expr = rule(expr)
        if expr == before:
            break
    return expr
