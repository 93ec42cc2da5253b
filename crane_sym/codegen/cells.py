"""Statements that evaluate a piecewise array expression window by window.

``np.select`` evaluates every branch on every point. Here the Piecewise
nodes of a function's array expression are folded into cells, one per
combination of their branches (two windows of two sides each: four cells),
each with its own formula; the generated code marks the cells once
(``_cells``), evaluates each cell's formula on the points that fall in it
(``_at``), in blocks of 16384 points that keep the temporaries in the cache
(``_blocks``), and writes it into the output buffer (``_put``). With sorted
times and scalar window edges a cell is a slice of the arrays, not a copy. A
call on scalars takes the one branch it needs (a conditional expression).
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
               taken: set[str] = frozenset(),
               fast: Callable[[sp.Expr], tuple[sp.Expr, sp.Expr] | None] = lambda cell: None
               ) -> list[str] | None:
    """Lines that return ``expr`` evaluated cell by cell into ``out`` (the
    shape in ``shape``), or None when ``expr`` has no Piecewise to split.
    ``print_scalar`` prints a Piecewise as a conditional expression; ``taken``
    are names in scope (arguments, parameter-only names) that a cell's
    temporaries must not shadow. ``fast`` gives a cell's fast form and the
    scale of its rounding error (``wave_sums.merge_waves``) or None: the cell
    is then evaluated by the fast form, and again by its own formula on the
    points where the fast one cancels (``_cancelled``)."""
    found = pieces(expr)
    if found is None:
        return None
    names = taken | {s.name for s in expr.free_symbols}
    prefix = next(p for p in ("v", "w", "u", "cell_v") if not any(
        n.startswith(p) and n[len(p):].isdigit() for n in names))
    part = next(n for n in ("part", "block", "cell_part") if n not in names)
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
        inside = ", ".join(local[s].name for s in operands) + ("," if len(operands) == 1 else "")
        lines.append(f"for {part} in _blocks(cells[{i}]):")
        if operands:
            given = ", ".join(s.name for s in operands)
            lines.append(f"    {inside} = _at({part}, shape, {given})")
        quick = fast(cell)
        if quick is None:
            lines += _assign(f"_put(out, {part}, {{}})", [cell.xreplace(local)], prefix,
                             print_, "    ")
            continue
        value, redo = f"{prefix}_sum", f"{prefix}_redo"
        lines += _assign(f"{value} = {{}}\n{redo} = _cancelled({value}, {{}})",
                         [e.xreplace(local) for e in quick], prefix, print_, "    ")
        lines += [f"    if {redo} is not None:      # where the fast sum cancels",
                  f"        {inside} = _at({redo}, {value}.shape, {inside})"]
        lines += _assign(f"{value}[{redo}] = {{}}", [cell.xreplace(local)], prefix,
                         print_, "        ")
        lines.append(f"    _put(out, {part}, {value})")
    return lines + ["return out"]


def _assign(template: str, exprs: list[sp.Expr], prefix: str,
            print_: Callable[[sp.Basic], str], indent: str) -> list[str]:
    """Lines of the common subexpressions of ``exprs`` (named ``prefix``
    0, 1, ...), then ``template`` with the reduced ``exprs`` filled in."""
    subs, reduced = sp.cse(exprs, symbols=sp.numbered_symbols(prefix),
                           order="canonical")
    body = template.format(*map(print_, reduced))
    return ([f"{indent}{s} = {print_(v)}" for s, v in subs]
            + [indent + line for line in body.split("\n")])
