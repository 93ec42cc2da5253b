"""Interval enclosures of SymPy expressions (``mpmath.iv``, outward rounding).

:func:`enclosure` compiles an expression into a function of boxes: given one
interval per variable it returns an interval that contains every value of the
expression on that box. It is the enclosure behind the interval-verified
maxima of :mod:`crane_sym.mechanics.extrema` (one variable, time) and the certified
worst case of a design sweep (:mod:`crane_sym.sweep.certify`, one variable
per swept parameter). The enclosure is of the natural interval extension: a
variable that appears several times makes it wider than the true range, but
never narrower, and the excess shrinks with the width of the box.
"""
from __future__ import annotations

from typing import Callable, Sequence

import mpmath
import sympy as sp
from mpmath import iv

__all__ = ["Enclosure", "enclosure"]

#: A compiled enclosure: one ``iv.mpf`` per variable -> ``iv.mpf``.
Enclosure = Callable[[Sequence], object]

_IV_FUNCS = {sp.sin: iv.sin, sp.cos: iv.cos, sp.tan: iv.tan, sp.exp: iv.exp,
             sp.log: iv.log}


def enclosure(expr: sp.Expr, variables: Sequence[sp.Symbol]) -> Enclosure:
    """Compile ``expr`` into ``X -> ivmpf`` enclosing its range over the box
    ``X`` (a sequence of ``iv.mpf``, one per symbol of ``variables``).

    Parameters
    ----------
    expr : sympy.Expr
        The expression to enclose.
    variables : sequence of Symbol
        Its free symbols, in the order of the box.

    Raises
    ------
    ValueError
        For a symbol not among ``variables`` or a function with no interval
        extension here (e.g. ``Piecewise``, ``Max``), naming it.
    """
    expr = expr.rewrite(sp.exp) if expr.has(sp.sinh, sp.cosh, sp.tanh) else expr
    return _compile(expr, {v: k for k, v in enumerate(variables)})


def _compile(expr: sp.Expr, index: dict[sp.Symbol, int]) -> Enclosure:
    if expr in index:
        k = index[expr]
        return lambda X: X[k]
    if expr.is_Rational:
        p, q = int(expr.p), int(expr.q)
        return lambda X: iv.mpf(p) / iv.mpf(q)
    if expr.is_Float:
        value = mpmath.mpf(expr._mpf_)
        return lambda X: iv.mpf(value)
    if expr == sp.pi:
        return lambda X: iv.pi
    if expr == sp.E:
        return lambda X: iv.e
    if expr.is_Symbol:
        raise ValueError(f"no interval enclosure: symbol {expr} has no value")
    args = [_compile(a, index) for a in expr.args]
    if expr.is_Add or expr.is_Mul:
        def fold(X, add=expr.is_Add):
            out = args[0](X)
            for g in args[1:]:
                out = out + g(X) if add else out * g(X)
            return out
        return fold
    if expr.is_Pow:
        base, power = args
        if expr.exp.is_Integer:
            k = int(expr.exp)
            return lambda X: base(X) ** k
        if expr.exp == sp.Rational(1, 2):
            return lambda X: iv.sqrt(base(X))
        return lambda X: iv.exp(iv.log(base(X)) * power(X))
    if isinstance(expr, sp.Abs):
        return lambda X: abs(args[0](X))
    if type(expr) in _IV_FUNCS:
        func = _IV_FUNCS[type(expr)]
        return lambda X: func(args[0](X))
    raise ValueError(f"no interval enclosure for {type(expr).__name__} in {expr}")
