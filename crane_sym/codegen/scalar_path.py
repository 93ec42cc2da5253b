"""The scalar fast path of a generated function.

A call on plain numbers (Python or NumPy floats, ints) skips the array
machinery: its checks are plain comparisons against the range each argument
serves (``PhysicalSymbol.serves``), its arithmetic is the ``math`` module on
floats. A failed check falls through to the array path, which
raises the error that names the parameter, and so does a ``math`` error (a
zero division, a domain error), where the array path gives what NumPy gives
(inf, NaN). Only expressions of elementary
functions, exact arithmetic kernels (``_diff_of_products``) and Taylor
remainders (``_remainder_float``) get one; an expression with any other node
(an entire-function helper, a phase pair) does not.
"""
from __future__ import annotations

from typing import Sequence

import sympy as sp
from sympy.printing.pycode import PythonCodePrinter

__all__ = ["fast_path", "literal", "serves_literal"]


def literal(value: float) -> str:
    """The shortest source text that reads back as the double ``value``,
    written with an exponent outside [1e-4, 1e6) (``1e11``, not
    ``100000000000.0``); Python's own correctly rounded formatting, the same
    on every machine."""
    value = float(value)
    if value == 0 or 1e-4 <= abs(value) < 1e6:
        return repr(value)
    for digits in range(17):
        text = f"{value:.{digits}e}"
        if float(text) == value:
            mantissa, exponent = text.split("e")
            return f"{mantissa}e{int(exponent)}"
    return repr(value)


def serves_literal(serves: tuple[float, float]) -> str:
    """``(low, high)`` as source text (see :func:`literal`)."""
    return f"({literal(serves[0])}, {literal(serves[1])})"

#: Kernels that are plain arithmetic, so they run on Python floats.
_ARITHMETIC = ("diff_of_products",)


class _MathPrinter(PythonCodePrinter):
    """Python source with ``math`` functions; doubles in full precision."""

    def _print_Float(self, expr: sp.Float) -> str:
        return repr(float(expr))

    def _print_joined_sqrt(self, expr: sp.Basic) -> str:
        return f"math.sqrt({self._print(expr.args[0])})"

    def _print_sin_remainder(self, expr: sp.Basic) -> str:
        return f"_remainder_float({self._print(expr.args[0])}, {int(expr.args[1])}, 1)"

    def _print_cos_remainder(self, expr: sp.Basic) -> str:
        return f"_remainder_float({self._print(expr.args[0])}, {int(expr.args[1])}, 0)"

    def _print_Function(self, expr: sp.Basic) -> str:
        name = type(expr).__name__
        if name in _ARITHMETIC:
            return f"_{name}(" + ", ".join(self._print(a) for a in expr.args) + ")"
        return super()._print_Function(expr)


def fast_path(entries: Sequence, assignments: Sequence[tuple[sp.Symbol, sp.Expr]],
              value: sp.Expr, requires: Sequence[sp.Expr] = ()) -> list[str] | None:
    """Statements (unindented) that return ``value`` for scalar arguments, or
    None when an expression has no ``math`` form. ``entries`` are the
    arguments' symbol-table entries (name, sign), ``assignments`` the
    parameter-only names the expression uses, in order; ``requires`` are
    expressions that must be > 0 (an argument set that breaks one takes the
    array path, which names the condition)."""
    if not entries:                        # nothing to check: the array path is as short
        return None
    printer = _MathPrinter({"fully_qualified_modules": True, "inline": True})
    try:
        body = [f"{s} = {printer.doprint(v)}" for s, v in assignments]
        result = printer.doprint(value)
    except Exception:                      # a node with no math form: no fast path
        return None
    plain = [f"        and (type({e.name}) in (float, int) or type({e.name}) is np.float64)"
             for e in entries]
    try:
        clauses = [f"{literal(e.serves[0])} <= {e.name} <= {literal(e.serves[1])}"
                   for e in entries]
        clauses += [f"{printer.doprint(r)} > 0" for r in requires]
    except Exception:
        return None
    checks = [""]
    for clause in clauses:                 # clauses joined, lines of at most ~84
        if checks[-1] and len(checks[-1]) + len(clause) > 80:
            checks.append("and " + clause)
        else:
            checks[-1] += (" and " if checks[-1] else "") + clause
    return (["if (out is None", *plain[:-1], plain[-1] + "):",
             f"    if ({checks[0]}" + ("" if len(checks) > 1 else "):"),
             *[f"            {c}" + ("):" if k == len(checks) - 2 else "")
               for k, c in enumerate(checks[1:])],
             "        try:    # a failed check or a math error: the array path decides",
             *[f"            {line}" for line in body],
             f"            return np.float64({result})",
             "        except (ArithmeticError, ValueError):",
             "            pass"])
