"""In-place evaluation of a generated function's array expression.

``k1*np.sin(k0*t)**2`` written as NumPy makes four full-size arrays, and the
allocator returns their memory between calls, so every call page-faults. When
the expression is a chain (each node has at most one operand that depends on
the arrays) it is evaluated instead in one output buffer, one ufunc pass per
node, with ``out=``: the fewest passes the expression needs and no temporary.
Expressions that are not a chain (two array operands meet, a Piecewise, a
kernel call) are left to the plain printer.
"""
from __future__ import annotations

from typing import Callable

import sympy as sp

__all__ = ["chain"]

#: SymPy function -> NumPy ufunc applied in place.
UNARY = {sp.sin: "np.sin", sp.cos: "np.cos", sp.tan: "np.tan", sp.exp: "np.exp",
         sp.log: "np.log", sp.Abs: "np.abs", sp.sinh: "np.sinh", sp.cosh: "np.cosh",
         sp.tanh: "np.tanh", sp.atan: "np.arctan", sp.asin: "np.arcsin",
         sp.acos: "np.arccos"}


def chain(expr: sp.Expr, heavy: set[sp.Symbol], print_: Callable[[sp.Basic], str],
          buffer: str = "out") -> list[str] | None:
    """Statements that leave ``expr`` in ``buffer``, one in-place pass per node.

    Parameters
    ----------
    expr : sympy.Expr
        The array part of a function (parameters already hoisted).
    heavy : set of Symbol
        Symbols that stand for arrays of the full size (time, array temporaries);
        every other symbol is cheap to broadcast (a hoisted parameter).
    print_ : callable
        The printer for the cheap operands.
    buffer : str
        Name of the output array, already allocated with the broadcast shape.

    Returns
    -------
    list of str or None
        The statements, or None when ``expr`` is not a chain.
    """
    lines: list[str] = []

    def is_heavy(e: sp.Basic) -> bool:
        return bool(e.free_symbols & heavy)

    def emit(e: sp.Expr) -> str | None:
        """Evaluate ``e`` into the buffer; the operand name that holds it."""
        if e.is_Symbol:
            return e.name                          # used as an operand, not copied
        if isinstance(e, (sp.Add, sp.Mul)):
            moving = [a for a in e.args if is_heavy(a)]
            if len(moving) != 1:
                return None
            rest = e.func(*[a for a in e.args if not is_heavy(a)])
            src = emit(moving[0])
            if src is None:
                return None
            if isinstance(e, sp.Add):
                lines.append(f"np.add({src}, {print_(rest)}, out={buffer})")
            elif rest == -1:
                lines.append(f"np.negative({src}, out={buffer})")
            else:
                num, den = sp.fraction(rest)
                if num != 1:
                    lines.append(f"np.multiply({src}, {print_(num)}, out={buffer})")
                    src = buffer
                if den != 1:
                    lines.append(f"np.divide({src}, {print_(den)}, out={buffer})")
                elif num == 1:
                    return src
            return buffer
        if isinstance(e, sp.Pow):
            base, exp = e.args
            if is_heavy(exp):
                if is_heavy(base):
                    return None
                src = emit(exp)
                if src is None:
                    return None
                lines.append(f"np.power({print_(base)}, {src}, out={buffer})")
                return buffer
            src = emit(base)
            if src is None:
                return None
            if exp == 2:
                lines.append(f"np.square({src}, out={buffer})")
            elif exp == sp.S.Half:
                lines.append(f"np.sqrt({src}, out={buffer})")
            elif exp == -1:
                lines.append(f"np.divide(1.0, {src}, out={buffer})")
            else:
                lines.append(f"np.power({src}, {print_(exp)}, out={buffer})")
            return buffer
        if type(e) in UNARY and len(e.args) == 1:
            src = emit(e.args[0])
            if src is None:
                return None
            lines.append(f"{UNARY[type(e)]}({src}, out={buffer})")
            return buffer
        return None

    if not is_heavy(expr):
        return None
    where = emit(expr)
    if where is None:
        return None
    if where != buffer:                            # expr was a bare array symbol
        lines.append(f"np.copyto({buffer}, {where})")
    return lines
