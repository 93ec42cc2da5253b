"""Guaranteed maximum of a (piecewise) smooth expression on a closed interval.

The maximum of a piece :math:`f` on :math:`[a, b]` is attained at an
endpoint, at a breakpoint, or at a critical point :math:`f'(t) = 0`.
Critical points are found

1. symbolically, by ``solveset`` on each factor of :math:`f'` (polynomials
   and sinusoids of one frequency; sums of sinusoids first turned into
   products), enumerating periodic solution families inside the interval:
   method ``"symbolic critical points"``;
2. otherwise numerically with proof: the interval is cut into boxes; on each
   box an interval-arithmetic enclosure (``mpmath.iv``) of :math:`f'` either
   excludes 0 (no critical point), or one of :math:`f''` excludes 0 (at
   most one root, found by ``mpmath.findroot`` when :math:`f'` changes sign
   between the box ends), or the box is halved. Method ``"interval-verified"``.

A box still undecided at the depth limit is bounded by an enclosure of
:math:`f` itself; the result is ``certified`` when no such bound exceeds the
maximum found. Used for the dynamic coefficients of Chovnyuk et al., eqs (37)–(53).
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Callable, Mapping

import mpmath
import sympy as sp
from mpmath import iv
from sympy.simplify.fu import TR9

from crane_sym.mechanics.intervals import enclosure
from crane_sym.mechanics.loads import as_expression, exact_number

SYMBOLIC = "symbolic critical points"
INTERVAL = "interval-verified"


@dataclass(frozen=True)
class Candidate:
    """A point where the maximum may be: ``endpoint``, ``breakpoint`` or
    ``critical point``."""

    location: sp.Expr
    value: sp.Expr
    kind: str


@dataclass(frozen=True)
class Extremum:
    """The maximum (or minimum) of an expression on ``interval``.

    ``value`` and ``location`` are exact when every candidate was found
    symbolically, floats with ``dps`` digits otherwise; ``method`` says how the
    critical points were found; ``certified`` is False only if a box the
    interval search could not resolve may hold a larger value (``detail``).
    """

    value: sp.Expr
    location: sp.Expr
    method: str
    candidates: tuple[Candidate, ...]
    interval: tuple[sp.Expr, sp.Expr]
    certified: bool
    detail: str


# --- ordering of possibly symbolic numbers -------------------------------------
def _leq(x: sp.Expr, y: sp.Expr, decide: bool = False) -> bool | None:
    """``x <= y`` when SymPy can decide it, else None (or, with ``decide``,
    ``ValueError``)."""
    d = y - x
    if d.is_number:
        value = sp.N(d, 50)
        if value.is_real and abs(value) > sp.Float("1e-40"):
            return bool(value > 0)
    for form in (d, sp.simplify(d)):
        if form.is_nonnegative is not None:
            return bool(form.is_nonnegative)
    if d.is_number:
        return True                             # equal to 50 digits
    if decide:
        raise ValueError(f"cannot decide whether {x} <= {y}; give numeric values "
                         f"with parameters={{...}}")
    return None


# --- pieces -----------------------------------------------------------------------
def smooth_pieces(expr: sp.Expr, t: sp.Symbol, a: sp.Expr,
                   b: sp.Expr) -> list[tuple[sp.Expr, sp.Expr, sp.Expr]]:
    """``(lo, hi, expr)`` pieces covering ``[a, b]`` for a Piecewise whose
    conditions read ``t < c`` or ``t <= c`` (in order) or True; a piece that
    holds at a single point of ``[a, b]`` is kept as ``(c, c, expr)``."""
    if not isinstance(expr, sp.Piecewise):
        return [(a, b, expr)]
    pieces, lower = [], a
    for e, cond in expr.args:
        last = cond == sp.true
        if not last and not (isinstance(cond, sp.core.relational._Inequality)
                             and cond.lts == t and t not in cond.gts.free_symbols):
            raise ValueError(f"Piecewise conditions must read {t} < c or {t} <= c, "
                             f"got {cond}")
        strict = not last and cond.rel_op in ("<", ">")
        if not last and _leq(cond.gts, lower, True) and (
                strict or not _leq(lower, cond.gts, True)):
            continue                                  # holds nowhere on [lower, b]
        high = b if last or _leq(b, cond.gts, True) else cond.gts
        pieces.append((lower, high, e))
        lower = high
        if last or (high == b and not (strict and _leq(cond.gts, b, True))):
            break                                     # this piece holds at t = b
    if not pieces or lower != b:
        raise ValueError(f"the Piecewise does not cover [{a}, {b}]")
    return pieces


# --- symbolic critical points -------------------------------------------------------
def _tractable(f: sp.Expr, t: sp.Symbol) -> bool:
    """Polynomial in t, or polynomial in sinusoids of one linear argument slope."""
    if f.is_polynomial(t):
        return True
    trig = [g for g in f.atoms(sp.sin, sp.cos, sp.tan) if g.has(t)]
    slopes = set()
    for g in trig:
        arg = g.args[0]
        if not arg.is_polynomial(t) or sp.degree(arg, t) != 1:
            return False
        slopes.add(sp.diff(arg, t))
    frozen = f.xreplace({g: sp.Dummy() for g in trig})
    return len(slopes) == 1 and t not in frozen.free_symbols


def _enumerate(solutions: sp.Set, lo: sp.Expr, hi: sp.Expr) -> list[sp.Expr] | None:
    """Members of ``solutions`` in ``[lo, hi]`` (None when not enumerable)."""
    if isinstance(solutions, sp.FiniteSet):
        return list(solutions)
    if solutions == sp.S.EmptySet:
        return []
    if isinstance(solutions, sp.Union):
        parts = [_enumerate(s, lo, hi) for s in solutions.args]
        return None if any(p is None for p in parts) else [x for p in parts for x in p]
    if isinstance(solutions, sp.ImageSet) and solutions.base_sets == (sp.S.Integers,):
        (n,), body = solutions.lamda.variables, solutions.lamda.expr
        if not body.is_polynomial(n) or sp.degree(body, n) != 1:
            return None
        start, period = body.subs(n, 0), sp.diff(body, n)
        ends = [sp.simplify((x - start) / period) for x in (lo, hi)]
        if not all(e.is_number for e in ends):
            return None
        first, last = sorted(ends, key=lambda e: sp.N(e, 50))
        k0, k1 = int(sp.ceiling(first)), int(sp.floor(last))
        if k1 - k0 > 10_000:
            return None
        return [body.subs(n, k) for k in range(k0, k1 + 1)]
    return None


def _tangent_form(f: sp.Expr, t: sp.Symbol) -> sp.Expr | None:
    """``tan(a t) + B/A`` when ``f = A sin(a t + ...) + B cos(a t + ...)`` has
    the same zeros (then ``A != 0``), else None."""
    trig = [g for g in f.atoms(sp.sin, sp.cos) if g.has(t)]
    if len(trig) < 2 or f.has(sp.tan):
        return None
    slope = sp.diff(trig[0].args[0], t)
    x = sp.Dummy("x")
    g = sp.expand(sp.expand_trig(f.subs(t, x / slope)))
    A, B = g.coeff(sp.sin(x)), g.coeff(sp.cos(x))
    if sp.expand(g - A * sp.sin(x) - B * sp.cos(x)) != 0 or A.has(x) or B.has(x) \
            or A.is_zero is not False:
        return None
    return sp.tan(slope * t) + B / A


def _zeros(f: sp.Expr, t: sp.Symbol, lo: sp.Expr, hi: sp.Expr) -> list[sp.Expr] | None:
    """Real zeros of ``f`` in ``[lo, hi]`` by ``solveset`` (None when not all
    are given in real closed form)."""
    for form in (_tangent_form(f, t), f):
        if form is None:
            continue
        found = sp.solveset(form, t, sp.Interval(lo, hi))
        if not isinstance(found, sp.FiniteSet):
            found = sp.solveset(form, t, sp.S.Reals)
        members = _enumerate(found, lo, hi)
        if members is not None and not any(p.has(sp.I) for p in members):
            return members
    return None


def _symbolic_critical(f: sp.Expr, t: sp.Symbol, lo: sp.Expr,
                       hi: sp.Expr) -> list[sp.Expr] | None:
    """Exact zeros of ``f'`` in ``[lo, hi]``, or None when SymPy cannot give all."""
    numerator, _ = sp.fraction(sp.together(sp.diff(f, t)))
    numerator = TR9(sp.expand(numerator)).replace(
        lambda e: isinstance(e, (sp.sin, sp.cos)), lambda e: e.func(sp.expand(e.args[0])))
    points: list[sp.Expr] = []
    for factor in sp.Mul.make_args(sp.factor_terms(numerator)):
        base = factor.base if factor.is_Pow and factor.exp.is_positive else factor
        if t not in base.free_symbols or isinstance(base, sp.exp):
            continue
        members = _zeros(base, t, lo, hi) if _tractable(base, t) else None
        if members is None:
            return None
        for p in members:
            inside = (_leq(lo, p), _leq(p, hi))
            if None in inside:
                return None
            if all(inside) and p not in points:
                points.append(p)
    return points


# --- interval enclosures --------------------------------------------------------
def _enclosure(expr: sp.Expr, t: sp.Symbol) -> Callable:
    """Compile ``expr`` into ``X -> ivmpf`` enclosing its range over the box X
    (:func:`crane_sym.mechanics.intervals.enclosure` in the one variable ``t``)."""
    compiled = enclosure(expr, (t,))
    return lambda X: compiled((X,))


def _interval_critical(f: sp.Expr, t: sp.Symbol, lo: sp.Expr, hi: sp.Expr, dps: int,
                       boxes: int, max_depth: int):
    """Critical points of ``f`` in ``[lo, hi]`` proven complete by enclosures.

    Returns ``(roots, unresolved, searched)``: roots as mpf, boxes undecided
    at ``max_depth`` with an upper bound of ``f`` on each, number of boxes.

    A box is dropped where f' has no zero, and bracketed where f' is monotone,
    each decided by the natural enclosure of f' (of f'') or by its mean-value
    form g(m) + g'(X)(X − m) about the box's middle m (:func:`_centred`): the
    natural one alone repeats t in every term, so it stays wide around a
    zero until the boxes are tiny; the centred one narrows with the box
    squared, and both enclose, so either may decide.
    """
    d1, d2, d3 = (sp.diff(f, t, k) for k in (1, 2, 3))
    e0, e1, e2, e3 = (_enclosure(g, t) for g in (f, d1, d2, d3))
    point = sp.lambdify(t, d1, modules="mpmath")
    x0, x1 = mpmath.mpf(sp.N(lo, dps + 10)), mpmath.mpf(sp.N(hi, dps + 10))
    grid = [x0 + (x1 - x0) * k / boxes for k in range(boxes)] + [x1]
    stack = [(grid[k], grid[k + 1], 0) for k in reversed(range(boxes))]
    roots, unresolved, searched = [], [], 0

    def sign(x):
        value = e1(iv.mpf(x))
        return 1 if value.a > 0 else -1 if value.b < 0 else 0

    while stack:
        left, right, depth = stack.pop()
        searched += 1
        box = iv.mpf([left, right])
        if 0 not in e1(box):
            continue
        middle = (left + right) / 2
        slope = e2(box)
        if 0 not in _centred(e1, slope, box, middle):
            continue
        if 0 not in slope or 0 not in _centred(e2, e3(box), box, middle):
            # f' strictly monotone on the box
            s0, s1 = sign(left), sign(right)
            roots += [x for x, s in ((left, s0), (right, s1)) if s == 0]
            if s0 * s1 < 0:
                roots.append(bracketed_root(point, left, right))
            continue
        if depth >= max_depth:
            unresolved.append((left, right, e0(box).b))
            continue
        stack += [(middle, right, depth + 1), (left, middle, depth + 1)]
    return roots, unresolved, searched


def _centred(g: Callable, slope, box, middle):
    """The mean-value enclosure g(m) + slope·(X − m) of g over ``box`` (``slope``
    encloses g' there, m = ``middle`` inside it)."""
    return g(iv.mpf(middle)) + slope * (box - middle)


def bracketed_root(func: Callable, left, right):
    """The single root of ``func`` in ``[left, right]`` (a sign change):
    Anderson–Björck, falling back to bisection."""
    try:
        root = mpmath.findroot(func, (left, right), solver="anderson")
        if left <= root <= right:
            return root
    except (ValueError, ZeroDivisionError, mpmath.libmp.NoConvergence):
        pass
    return mpmath.findroot(func, (left, right), solver="bisect",
                           maxsteps=4 * mpmath.mp.prec)


# --- driver -------------------------------------------------------------------------
def _largest(candidates: list[Candidate], dps: int) -> Candidate:
    if all(c.value.is_number for c in candidates):
        return max(candidates, key=lambda c: sp.N(c.value, dps))
    best = candidates[0]
    for c in candidates[1:]:
        if _leq(c.value, best.value, True):
            continue
        best = c
    return best


def maximum_on_interval(expr: sp.Expr, t: sp.Symbol, a: object, b: object, *,
                        parameters: Mapping[sp.Symbol | str, object] | None = None,
                        dps: int = 30, symbolic: bool = True, boxes: int = 64,
                        max_depth: int = 60) -> Extremum:
    """Maximum of ``expr`` over :math:`t \\in [a, b]`, with its location.

    .. math::

        \\max_{a \\le t \\le b} f(t) = \\max\\{f(a), f(b), f(b_k^\\pm),
        f(t_c) : f'(t_c) = 0\\}

    Parameters
    ----------
    expr : sympy.Expr
        Smooth in ``t``, or a ``Piecewise`` of smooth pieces with conditions
        ``t < c`` in increasing order (as ``DuhamelResult.piecewise()``); at a
        jump both one-sided values are candidates (the result is a supremum).
    t : Symbol
    a, b : numbers or expressions, ``a <= b``
    parameters : mapping symbol (or its name) -> number, optional
        Values of the other symbols; required for the interval search.
    dps : int
        Digits of the numeric work.
    symbolic : bool
        Try ``solveset`` first (default); False forces the interval search.
    boxes, max_depth : int
        Initial sampling boxes and the bisection depth limit.
    """
    expr = as_expression(expr, "expr")
    a, b = as_expression(a, "a"), as_expression(b, "b")
    if parameters:                  # matched by name: assumptions may differ
        names = {(k if isinstance(k, str) else k.name): exact_number(v, str(k))
                 for k, v in parameters.items()}
        values = {s: names[s.name] for s in (expr.free_symbols | a.free_symbols
                                             | b.free_symbols) - {t} if s.name in names}
        expr, a, b = (x.subs(values) for x in (expr, a, b))
    if not _leq(a, b, True):
        raise ValueError(f"the interval [{a}, {b}] is empty: a > b")
    pieces = smooth_pieces(sp.piecewise_fold(expr), t, a, b)
    candidates: list[Candidate] = []
    method, unresolved, searched = SYMBOLIC, [], 0
    for k, (lo, hi, f) in enumerate(pieces):
        ends = ("endpoint" if k == 0 else "breakpoint",
                "endpoint" if k == len(pieces) - 1 else "breakpoint")
        candidates += [Candidate(x, f.subs(t, x), kind) for x, kind in zip((lo, hi), ends)]
        found = _symbolic_critical(f, t, lo, hi) if symbolic else None
        if found is not None:
            candidates += [Candidate(x, f.subs(t, x), "critical point") for x in found]
            continue
        stray = (f.free_symbols | lo.free_symbols | hi.free_symbols) - {t}
        if stray:
            raise ValueError(f"critical points of {f} need the interval search; give "
                             f"values for {sorted(map(str, stray))} with parameters=")
        method = INTERVAL
        with mpmath.workdps(dps + 10):
            old = iv.prec
            iv.dps = dps + 10
            try:
                roots, more, n = _interval_critical(f, t, lo, hi, dps, boxes, max_depth)
                value = sp.lambdify(t, f, modules="mpmath")
                candidates += [Candidate(sp.Float(r, dps), sp.Float(value(r), dps),
                                         "critical point") for r in roots]
            finally:
                iv.prec = old
        unresolved += more
        searched += n
    best = _largest(candidates, dps)
    top = mpmath.mpf(sp.N(best.value, dps + 10)._mpf_) if best.value.is_number else None
    doubtful = [box for box in unresolved if top is None or box[2] > top]
    if method == SYMBOLIC:
        detail = f"solveset on {len(pieces)} piece(s)"
    else:
        detail = (f"{searched} boxes; {len(unresolved)} undecided at depth {max_depth}, "
                  f"{len(doubtful)} of them may exceed the maximum")
    return Extremum(best.value, best.location, method, tuple(candidates), (a, b),
                    not doubtful, detail)


def minimum_on_interval(expr: sp.Expr, t: sp.Symbol, a: object, b: object,
                        **options) -> Extremum:
    """Minimum of ``expr`` on ``[a, b]``: ``maximum_on_interval`` of ``-expr``."""
    found = maximum_on_interval(-as_expression(expr, "expr"), t, a, b, **options)
    flipped = tuple(Candidate(c.location, -c.value, c.kind) for c in found.candidates)
    return Extremum(-found.value, found.location, found.method, flipped,
                    found.interval, found.certified, found.detail)
