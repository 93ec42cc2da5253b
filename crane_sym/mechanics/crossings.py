"""The first instant at which a (piecewise) smooth expression reaches a level, with proof.

Where a model stops (or starts) holding is often the first instant a quantity
crosses a bound: a rope goes slack when its stretch falls below 0, a load
lifts once the rope force reaches its weight. :func:`first_reaching` finds
that instant on :math:`[a, b]` for :math:`g = f - \\text{level}` (or
:math:`\\text{level} - f`) without sampling: the interval is cut into boxes,
taken from the left, and on each box, with interval enclosures of :math:`g`
and :math:`g'` (:func:`crane_sym.mechanics.intervals.enclosure`):

1. the box's left end is the instant if :math:`g \\ge 0` there (up to
   rounding);
2. an enclosure below 0 means :math:`g < 0` on the box: the next box;
3. else, if an enclosure of :math:`g'` excludes 0 (:math:`g` monotone), the
   instant is the one root of :math:`g` in the box (``mpmath.findroot``,
   bracketed) or not in the box;
4. else the box is halved.

A box still undecided at ``max_depth`` (a tangency: :math:`g` touches 0) is
taken as reached at its left end, the earliest the instant can be, and the
result says it is not certified.
"""
from __future__ import annotations

from dataclasses import dataclass

import mpmath
import sympy as sp
from mpmath import iv

from crane_sym.mechanics.extrema import bracketed_root, smooth_pieces
from crane_sym.mechanics.intervals import enclosure
from crane_sym.mechanics.loads import as_expression

__all__ = ["Crossing", "first_reaching"]


@dataclass(frozen=True)
class Crossing:
    """The first instant on ``interval`` at which the condition holds.

    ``location`` is None when it holds nowhere there (proved by the
    enclosures); ``certified`` is False only when a box at the depth limit
    was taken as reached (``detail`` says how many boxes were searched).
    """

    location: float | None
    interval: tuple[float, float]
    certified: bool
    detail: str


def _first_in_piece(g: sp.Expr, t: sp.Symbol, lo, hi, boxes: int, max_depth: int):
    """(instant or None, certified, boxes searched) on one smooth piece ``[lo, hi]``."""
    enc_g = enclosure(g, (t,))
    enc_d = enclosure(sp.diff(g, t), (t,))
    point = sp.lambdify(t, g, modules="mpmath")

    def reached(x) -> bool:                     # g(x) >= 0, up to rounding
        return enc_g((iv.mpf(x),)).b >= 0

    if lo == hi:
        return (lo if reached(lo) else None), True, 1
    grid = [lo + (hi - lo) * k / boxes for k in range(boxes)] + [hi]
    stack = [(grid[k], grid[k + 1], 0) for k in reversed(range(boxes))]
    searched = 0
    while stack:
        left, right, depth = stack.pop()
        searched += 1
        if reached(left):                        # boxes come left first
            return left, True, searched
        box = (iv.mpf([left, right]),)
        if enc_g(box).b < 0:
            continue
        slope = enc_d(box)
        if 0 not in slope:                       # g monotone on the box
            if slope.a > 0 and reached(right):  # one root, or g(right) = 0 to rounding
                root = bracketed_root(point, left, right) if point(right) > 0 else right
                return root, True, searched
            continue
        if depth >= max_depth:
            return left, False, searched
        middle = (left + right) / 2
        stack += [(middle, right, depth + 1), (left, middle, depth + 1)]
    return None, True, searched


def first_reaching(expr: sp.Expr, t: sp.Symbol, a: object, b: object, level: object = 0,
                   *, above: bool = True, dps: int = 20, boxes: int = 64,
                   max_depth: int = 40) -> Crossing:
    """The earliest :math:`t \\in [a, b]` with :math:`f(t) \\ge` ``level``
    (``above``) or :math:`f(t) \\le` ``level`` (not ``above``).

    Parameters
    ----------
    expr : sympy.Expr
        :math:`f`, smooth in ``t`` or a ``Piecewise`` of smooth pieces with
        conditions ``t < c`` in increasing order; no other free symbol.
    t : Symbol
    a, b : numbers, ``a <= b``
    level : number
    above : bool
        Reach the level from below (True) or from above (False).
    dps : int
        Digits of the interval and root work.
    boxes, max_depth : int
        Initial boxes per piece and the bisection depth limit.

    Returns
    -------
    Crossing
    """
    f = as_expression(expr, "expr")
    g = f - as_expression(level, "level") if above else as_expression(level, "level") - f
    stray = sorted(str(s) for s in g.free_symbols - {t})
    if stray:
        raise ValueError(f"first_reaching: give numbers for {stray}")
    a, b = as_expression(a, "a"), as_expression(b, "b")
    if not bool(sp.N(b - a, 30) >= 0):
        raise ValueError(f"the interval [{a}, {b}] is empty: a > b")
    searched, certified = 0, True
    with mpmath.workdps(dps + 10):
        old = iv.prec
        iv.dps = dps + 10
        try:
            for lo, hi, piece in smooth_pieces(sp.piecewise_fold(g), t, a, b):
                x0, x1 = (mpmath.mpf(sp.N(x, dps + 10)) for x in (lo, hi))
                found, sure, n = _first_in_piece(piece, t, x0, x1, boxes, max_depth)
                searched += n
                certified = certified and sure
                if found is not None:
                    return Crossing(float(found), (float(a), float(b)), certified,
                                    f"{searched} boxes")
        finally:
            iv.prec = old
    return Crossing(None, (float(a), float(b)), certified, f"{searched} boxes")
