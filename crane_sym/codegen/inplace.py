"""In-place evaluation of a generated function's array expression.

``k1*np.sin(k0*t)**2`` written as NumPy makes four full-size arrays, and the
allocator returns their memory between calls, so every call page-faults. When
the expression is built of arithmetic and elementary functions it is
evaluated instead in the output buffer, one ufunc pass per node, with
``out=``: a chain (each node with one array operand) needs no other array;
where two array operands meet, the second is made in a work array, one per
nesting depth, allocated once and reused. Expressions with other nodes (a
Piecewise, a kernel call) are left to the plain printer. Either way a
function of time is evaluated a block of points at a time (:func:`blocked`):
its array temporaries, the work arrays included, are then block-sized, so a
call's peak memory is its input and output and a few blocks.
"""
from __future__ import annotations

from typing import Callable

import sympy as sp

__all__ = ["blocked", "chain"]

#: SymPy function -> NumPy ufunc applied in place.
UNARY = {sp.sin: "np.sin", sp.cos: "np.cos", sp.tan: "np.tan", sp.exp: "np.exp",
         sp.log: "np.log", sp.Abs: "np.abs", sp.sinh: "np.sinh", sp.cosh: "np.cosh",
         sp.tanh: "np.tanh", sp.atan: "np.arctan", sp.asin: "np.arcsin",
         sp.acos: "np.arccos"}


def chain(expr: sp.Expr, heavy: set[sp.Symbol], print_: Callable[[sp.Basic], str],
          buffer: str = "out") -> list[str] | None:
    """Statements that leave ``expr`` in ``buffer``, one in-place pass per node
    (and work arrays where two array operands meet).

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
        The statements, or None when ``expr`` holds a node without an in-place form.
    """
    lines: list[str] = []
    temps: list[str] = []                          # work arrays, made once, reused

    def is_heavy(e: sp.Basic) -> bool:
        return bool(e.free_symbols & heavy)

    def work(depth: int) -> str:
        while len(temps) <= depth:
            temps.append(f"_w{len(temps)}")
            lines.append(f"{temps[-1]} = np.empty_like({buffer})")
        return temps[depth]

    def emit(e: sp.Expr, buf: str, depth: int) -> str | None:
        """Evaluate ``e`` into ``buf``; the operand name that holds it. Work
        arrays below ``depth`` are in use by the caller."""
        if e.is_Symbol:
            return e.name                          # used as an operand, not copied
        if isinstance(e, (sp.Add, sp.Mul)):
            moving = [a for a in e.args if is_heavy(a)]
            rest = e.func(*[a for a in e.args if not is_heavy(a)])
            src = emit(moving[0], buf, depth)
            if src is None:
                return None
            ufunc = "np.add" if isinstance(e, sp.Add) else "np.multiply"
            for other in moving[1:]:               # two array operands meet
                tmp = work(depth)
                right = emit(other, tmp, depth + 1)
                if right is None:
                    return None
                lines.append(f"{ufunc}({src}, {right}, out={buf})")
                src = buf
            if isinstance(e, sp.Add):
                if rest != 0:
                    lines.append(f"np.add({src}, {print_(rest)}, out={buf})")
                    src = buf
                return src
            if rest == -1:
                lines.append(f"np.negative({src}, out={buf})")
                return buf
            num, den = sp.fraction(rest)
            if num == -1 and den != 1:             # one pass: divide by −den
                lines.append(f"np.divide({src}, {print_(-den)}, out={buf})")
                return buf
            if num != 1:
                lines.append(f"np.multiply({src}, {print_(num)}, out={buf})")
                src = buf
            if den != 1:
                lines.append(f"np.divide({src}, {print_(den)}, out={buf})")
                src = buf
            return src
        if isinstance(e, sp.Pow):
            base, exp = e.args
            if is_heavy(exp):
                if is_heavy(base):
                    return None
                src = emit(exp, buf, depth)
                if src is None:
                    return None
                lines.append(f"np.power({print_(base)}, {src}, out={buf})")
                return buf
            src = emit(base, buf, depth)
            if src is None:
                return None
            if exp == 2:
                lines.append(f"np.square({src}, out={buf})")
            elif exp in (3, 4):                    # products, not the pow function
                tmp = work(depth)
                lines.append(f"np.square({src}, out={tmp})")
                lines.append(f"np.multiply({src}, {tmp}, out={buf})" if exp == 3
                             else f"np.square({tmp}, out={buf})")
            elif exp == sp.S.Half:
                lines.append(f"np.sqrt({src}, out={buf})")
            elif exp == -1:
                lines.append(f"np.divide(1.0, {src}, out={buf})")
            else:
                lines.append(f"np.power({src}, {print_(exp)}, out={buf})")
            return buf
        if type(e) in UNARY and len(e.args) == 1:
            src = emit(e.args[0], buf, depth)
            if src is None:
                return None
            lines.append(f"{UNARY[type(e)]}({src}, out={buf})")
            return buf
        return None

    if not is_heavy(expr):
        return None
    where = emit(expr, buffer, 0)
    if where is None:
        return None
    if where != buffer:                            # expr was a bare array symbol
        lines.append(f"np.copyto({buffer}, {where})")
    return lines


def blocked(expr: sp.Expr, temporaries: list[tuple[sp.Symbol, sp.Expr]],
            names: list[str], heavy: set[sp.Symbol],
            print_: Callable[[sp.Basic], str]) -> list[str]:
    """Statements that fill ``out`` with ``expr`` a block of points at a time
    (the kernel ``_spans``): the array temporaries of the CSE computed per
    block, then ``expr`` by :func:`chain` into the block, or printed whole
    where it is not a chain (once: one point with no buffer gets the number
    back, where a chain prints it on its own).

    Parameters
    ----------
    expr : sympy.Expr
        The array part of a function (parameters already hoisted).
    temporaries : list of (Symbol, Expr)
        The CSE's array temporaries, in the order they are computed.
    names : list of str
        The names ``expr`` and the temporaries read, in a fixed order: the
        blocks slice those that are arrays.
    heavy : set of Symbol
        Symbols that stand for full-size arrays (as for :func:`chain`).
    print_ : callable
        The printer.
    """
    made = [f"{s} = {print_(v)}" for s, v in temporaries]
    steps = chain(expr, heavy, print_, buffer="_o")
    listed = ", ".join(names) + ("," if len(names) == 1 else "")
    loop = f"for _o, ({listed}) in _spans(out, shape, {', '.join(names)}):"
    if len(loop) > 90:                             # the values on a line of their own
        loop = f"for _o, ({listed}) in _spans(\n        out, shape, {', '.join(names)}):"
    if steps is None:                              # printed once: a number for one point
        return (["_one = out is None and not shape", "out = _out(out, shape)",
                 *loop.split("\n"), *[f"    {line}" for line in made],
                 f"    _o[...] = {print_(expr)}", "return out[()] if _one else out"])
    return (["if out is None and not shape:",
             *[f"    {line}" for line in made], f"    return {print_(expr)}",
             "out = _out(out, shape)", *loop.split("\n")]
            + [f"    {line}" for line in made + steps] + ["return out"])
