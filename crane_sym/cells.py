"""Statements that evaluate a piecewise array expression window by window.

``np.select`` evaluates every branch on every point. Here the Piecewise
nodes of a function's array expression are folded into cells, one per
combination of their branches (two windows of two sides each: four cells),
each with its own formula; the generated code marks the cells once
(``_cells``), evaluates each cell's formula on the points that fall in it
(``_at``) and writes it into the output buffer (``_put``). With sorted times
and scalar window edges a cell is a slice of the arrays, not a copy. A call
on scalars takes the one branch it needs (a conditional expression).
"""
from __future__ import annotations

from itertools import product
from typing import Callable

import sympy as sp

__all__ = ["pieces", "statements"]


def pieces(expr: sp.Expr) -> list[sp.Piecewise] | None:
    """The Piecewise nodes of ``expr`` in a fixed order; None if there is none,
    or one holds another in a branch or a condition."""
    found = sorted(expr.atoms(sp.Piecewise), key=sp.default_sort_key)
    if not found or any(a.has(sp.Piecewise) for p in found for a in p.args
                        for a in (a.expr, a.cond)):
        return None
    if any(p.args[-1].cond != sp.true for p in found):
        return None
    return found


def statements(expr: sp.Expr, print_: Callable[[sp.Basic], str],
               print_scalar: Callable[[sp.Basic], str],
               taken: set[str] = frozenset()) -> list[str] | None:
    """Lines that return ``expr`` evaluated cell by cell into ``out`` (the
    shape in ``shape``), or None when ``expr`` has no Piecewise to split.
    ``print_scalar`` prints a Piecewise as a conditional expression; ``taken``
    are names in scope (arguments, parameter-only names) that a cell's
    temporaries must not shadow."""
    found = pieces(expr)
    if found is None:
        return None
    names = taken | {s.name for s in expr.free_symbols}
    prefix = next(p for p in ("v", "w", "u", "cell_v") if not any(
        n.startswith(p) and n[len(p):].isdigit() for n in names))
    choices = ", ".join("[" + ", ".join(print_(a.cond) for a in p.args[:-1]) + "]"
                        for p in found)
    lines = ["if out is None and not shape:      # one point: its own branch only",
             f"    return {print_scalar(expr)}",
             "out = _out(out, shape)",
             f"cells = _cells(shape, [{choices}])"]
    for i, combo in enumerate(product(*[p.args for p in found])):
        cell = expr.xreplace({p: branch.expr for p, branch in zip(found, combo)})
        operands = sorted(cell.free_symbols, key=str)
        local = {s: sp.Symbol(f"{s.name}_", **s.assumptions0) for s in operands}
        subs, (value,) = sp.cse([cell.xreplace(local)], symbols=sp.numbered_symbols(prefix),
                                order="canonical")
        lines.append(f"if cells[{i}] is not None:")
        if operands:
            inside = ", ".join(local[s].name for s in operands)
            given = ", ".join(s.name for s in operands)
            comma = "," if len(operands) == 1 else ""
            lines.append(f"    {inside}{comma} = _at(cells[{i}], shape, {given})")
        lines += [f"    {s} = {print_(v)}" for s, v in subs]
        lines.append(f"    _put(out, cells[{i}], {print_(value)})")
    return lines + ["return out"]
