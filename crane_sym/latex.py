"""LaTeX as a mechanics text writes it: x for x(t), ẋ and ẍ for its time derivatives.

SymPy prints a coordinate as ``x{\\left(t \\right)}`` and its derivative as
``\\frac{d}{d t} x{\\left(t \\right)}``; a reader of a paper expects ``x`` and
``\\dot{x}``. This printer changes only that, for functions of time alone.
"""
from __future__ import annotations

import sympy as sp
from sympy.printing.latex import LatexPrinter

__all__ = ["latex"]

_DOTS = {1: r"\dot", 2: r"\ddot", 3: r"\dddot", 4: r"\ddddot"}


def _of_time_only(f: sp.Basic) -> bool:
    return (isinstance(f, sp.core.function.AppliedUndef) and len(f.args) == 1
            and isinstance(f.args[0], sp.Symbol) and f.args[0].name == "t")


class _MechanicsPrinter(LatexPrinter):
    def _print_Function(self, expr, exp=None):  # noqa: N802 (SymPy's naming)
        if _of_time_only(expr):
            name = self._print(sp.Symbol(expr.func.__name__))
            return f"{name}^{{{exp}}}" if exp else name
        return super()._print_Function(expr, exp)

    def _print_Derivative(self, expr):  # noqa: N802
        f = expr.expr
        if _of_time_only(f) and all(v == f.args[0] for v, _ in expr.variable_count):
            n = sum(c for _, c in expr.variable_count)
            name = self._print(sp.Symbol(f.func.__name__))
            if n in _DOTS:
                base, _, sub = name.partition("_")
                return f"{_DOTS[n]}{{{base}}}" + (f"_{sub}" if sub else "")
            return f"{name}^{{({n})}}"
        return super()._print_Derivative(expr)


def latex(expr: sp.Basic, **settings) -> str:
    """LaTeX of ``expr`` with x(t) printed x and its time derivatives dotted."""
    return _MechanicsPrinter(settings).doprint(expr)
