"""Responses on time windows, rewritten in local variables.

A load switched off at ``t = c`` gives a response
``(1 − H(t − c))·D(t) + H(t − c)·A(t)``. Printed as derived, ``A`` is a
difference of terms in ``Ωt`` and ``Ω(t − c)`` that cancels when ``Ωc`` is
small, and ``D`` is a sum of Taylor remainders of different orders that
cancel each other near ``t = c``. ``window_pieces`` rewrites every such
expression (any number of windows, any paper) as

* ``A`` anchored at its switch, ``α + β·cos x + γ·sin x`` with the exact
  phase ``x = Ω(t − c)``: a pure wave when α = 0, else an ``offset_wave``
  that stays accurate where the wave swings back to near zero; α, β, γ and
  ``α² − β² − γ²`` depend on the parameters only, through ``h = Ωc``, as
  entire functions of h;
* ``D`` and the parts present at all times as sums of
  ``(parameter monomial)·f(x)``, ``x = Ωt``, the monomials of one window
  regrouped in powers of ``(c − t)/c`` or ``t/c``, whichever sums without
  cancellation;

and each entire function ``f`` becomes an ``entire`` node (Taylor series
with exact coefficients at small argument, closed form above). The window
itself becomes a ``Piecewise``: each side is evaluated by its own formula.
"""
from __future__ import annotations

from collections import defaultdict
from typing import Callable

import mpmath
import sympy as sp

from crane_sym.codegen.entire import Z, entire_node, laurent, needs_series, stable_form

Rule = Callable[[sp.Expr], sp.Expr]


class exact_phase(sp.Function):
    """The phase ``k·(t − c)``, formed exactly as a pair (hi, lo) by the
    generated code (kernel ``_exact_phase``): at long times, or just after a
    switch, one rounding of it is a large error of a sine near its zeros."""

    nargs = 3

    def _eval_rewrite_as_Add(self, k, t, c, **kwargs):  # noqa: N802
        return k * (t - c)

    def _eval_evalf(self, prec):
        return self.rewrite(sp.Add)._eval_evalf(prec)


class phase_sin(sp.Function):
    """``sin(q·z)`` for an ``exact_phase`` z (q a power of two)."""

    nargs = 2

    def _eval_rewrite_as_sin(self, z, q, **kwargs):
        return sp.sin(q * z)


class phase_cos(sp.Function):
    """``cos(q·z)`` for an ``exact_phase`` z (q a power of two)."""

    nargs = 2

    def _eval_rewrite_as_cos(self, z, q, **kwargs):
        return sp.cos(q * z)


def on_phase(expr: sp.Expr, z: sp.Symbol, phase: sp.Expr) -> sp.Expr:
    """``expr`` (in z, trig of z only) with z set to an ``exact_phase``."""
    def trig(f):
        q = sp.cancel(f.args[0] / z)
        return (phase_sin if isinstance(f, sp.sin) else phase_cos)(phase, q)
    return expr.replace(lambda e: isinstance(e, (sp.sin, sp.cos)) and e.has(z), trig)


def _windows(expr: sp.Expr, t: sp.Symbol) -> dict[sp.Heaviside, sp.Expr]:
    """Heaviside(t − c, 0) atoms of ``expr`` -> their switch time c."""
    out = {}
    for h in expr.atoms(sp.Heaviside):
        c = t - h.args[0]
        if len(h.args) == 2 and h.args[1] == 0 and not c.has(t):
            out[h] = c
    return out


def _linear_parts(expanded: sp.Expr, marks: list[sp.Dummy]) -> dict | None:
    """{monomial exponents: coefficient} of an expanded sum, at most one mark a
    term (with the mark to the first power), else None."""
    index = {m: i for i, m in enumerate(marks)}
    collected: dict[tuple, list] = defaultdict(list)
    for term in sp.Add.make_args(expanded):
        rest, marked = term.as_independent(*marks, as_Add=False)
        monomial = [0] * len(marks)
        if marked != 1:
            if marked not in index:
                return None
            monomial[index[marked]] = 1
        collected[tuple(monomial)].append(rest)
    return {m: sp.Add(*terms) for m, terms in collected.items()}


def split_windows(expr: sp.Expr, t: sp.Symbol):
    """``expr = P + Σ_c [(1 − H_c)·D_c + H_c·A_c]``: returns (P, {c: (D_c, A_c)}),
    or None when ``expr`` is not linear in the windows."""
    windows = _windows(expr, t)
    if not windows or len(windows) != len(expr.atoms(sp.Heaviside)):
        return None
    bars = {h: sp.Dummy(f"off{i}") for i, h in enumerate(sorted(windows, key=sp.default_sort_key))}
    ons = {h: sp.Dummy(f"on{i}") for i, h in enumerate(sorted(windows, key=sp.default_sort_key))}
    marked = expr.xreplace({1 - h: bars[h] for h in windows}).xreplace(ons)
    parts = _linear_parts(sp.expand(marked), [*bars.values(), *ons.values()])
    if parts is None:
        return None
    n = len(windows)
    unit = lambda i: tuple(int(j == i) for j in range(2 * n))
    rest = sp.Add.make_args(parts.get((0,) * (2 * n), sp.Integer(0)))
    pieces = {}
    for i, h in enumerate(sorted(windows, key=sp.default_sort_key)):
        before = parts.get(unit(i), sp.Integer(0))
        after = parts.get(unit(n + i), sp.Integer(0))
        # A term of P that H_c·A_c cancels belongs to the window's "before" side.
        negated = set(sp.Add.make_args(-after))
        moved = [term for term in rest if term in negated]
        rest = [term for term in rest if term not in negated]
        pieces[windows[h]] = (before + sp.Add(*moved), after + sp.Add(*moved))
    return sp.Add(*rest), pieces


def _slope(piece: sp.Expr, t: sp.Symbol) -> sp.Expr | None:
    """The one frequency k of the sines and cosines in ``piece`` (arguments
    k·t + φ), or None."""
    slopes = set()
    for f in piece.atoms(sp.sin, sp.cos):
        if not f.has(t):
            continue
        arg = sp.expand(f.args[0])
        k = arg.coeff(t)
        if k == 0 or k.has(t) or sp.expand(arg - k * t).has(t):
            return None
        slopes.add(k)
    return slopes.pop() if len(slopes) == 1 else None


def _local(piece: sp.Expr, t: sp.Symbol, k: sp.Expr, anchor: sp.Expr, x: sp.Symbol) -> sp.Expr:
    """``piece`` with t = anchor + x/k, the sines and cosines of x + ψ
    expanded into sin x, cos x (ψ free of x)."""
    moved = sp.expand(piece.xreplace({t: anchor + x / k}))

    def expand(f):
        arg = sp.expand(f.args[0])
        psi = sp.expand(arg - x)
        if psi == 0 or psi.has(x):
            return f
        if isinstance(f, sp.sin):
            return sp.sin(x) * sp.cos(psi) + sp.cos(x) * sp.sin(psi)
        return sp.cos(x) * sp.cos(psi) - sp.sin(x) * sp.sin(psi)

    return sp.expand(moved.replace(lambda e: isinstance(e, (sp.sin, sp.cos)) and e.has(x),
                                   expand))


def _normal(f: sp.Expr) -> tuple[sp.Expr, sp.Expr]:
    """``f = c·g`` with c a number and g normalised (first term's coefficient 1)."""
    terms = sorted(sp.Add.make_args(sp.expand(f)), key=sp.default_sort_key)
    c = terms[0].as_coeff_Mul()[0]
    return c, sp.expand(f / c)


def _groups(expr: sp.Expr, x: sp.Symbol) -> dict[sp.Expr, sp.Expr]:
    """``expr = Σ key·f_key(x)``, keys free of x, f in x; keys whose functions
    are proportional are merged (the key becomes a sum)."""
    by_key: dict[sp.Expr, sp.Expr] = defaultdict(lambda: sp.Integer(0))
    for term in sp.Add.make_args(expr):
        if any(b.is_Add and e.is_negative for b, e in (f.as_base_exp() for f in
                                                          sp.Mul.make_args(term))):
            term = sp.factor(term)          # a denominator that holds x as a factor
        indep, dep = term.as_independent(x, as_Add=False)
        num, key = indep.as_coeff_Mul()
        by_key[key] += num * dep
    by_function: dict[sp.Expr, sp.Expr] = defaultdict(lambda: sp.Integer(0))
    for key, f in by_key.items():
        if f == 0:
            continue
        c, g = _normal(f)
        by_function[g] += c * key
    out: dict[sp.Expr, sp.Expr] = defaultdict(lambda: sp.Integer(0))
    for g, key in by_function.items():
        out[sp.factor(key)] += g        # keys equal once factored: one function
    return {key: sp.expand(f) for key, f in out.items() if sp.expand(f) != 0}


def _function(f: sp.Expr, x: sp.Symbol, arg: sp.Expr) -> sp.Expr:
    """``f(x)`` at ``arg``: an ``entire`` node if its closed form cancels, or
    if ``arg`` is an exact phase and x appears outside sines and cosines."""
    closed = f.xreplace({x: Z})
    try:
        series = needs_series(closed)
    except ValueError:          # not a combination of z**a, sin, cos: keep as derived
        return f.xreplace({x: arg})
    if series:
        return entire_node(arg, closed)
    printed = stable_form(closed)
    if not isinstance(arg, exact_phase):
        return printed.xreplace({Z: arg})
    bare = printed.replace(lambda e: isinstance(e, (sp.sin, sp.cos)), lambda e: sp.Integer(1))
    if bare.has(Z):
        return entire_node(arg, closed)
    return on_phase(printed, Z, arg)


def _power_of(ratio: sp.Expr, h: sp.Expr, c: sp.Expr) -> int | None:
    """e when ``ratio`` is a rational multiple of h**e (h = k·c), else None."""
    if not (c.is_Symbol and h.has(c)):
        return None
    hs = sp.Dummy("h")
    (c_of_h,) = sp.solve(sp.Eq(h, hs), c) or (None,)
    if c_of_h is None:
        return None
    r = sp.simplify(ratio.xreplace({c: c_of_h}))
    if r.free_symbols - {hs}:
        return None
    coeff, e = sp.Integer(1), 0
    for f in sp.Mul.make_args(r):
        base, ex = f.as_base_exp()
        if base == hs and ex.is_Integer:
            e += int(ex)
        elif f.is_Rational:
            coeff *= f
        else:
            return None
    return e


def _loss(columns: list[sp.Expr], x: sp.Symbol, values) -> float:
    """Worst Σ|term| / |Σ term| of Σ_i v**i·f_i(x) over ``values`` of (v, x)."""
    fs = [sp.lambdify(x, f, "mpmath") for f in columns]
    worst = mpmath.mpf(1)
    with mpmath.workdps(30):
        for v, xv in values:
            terms = [mpmath.mpf(v) ** i * f(mpmath.mpf(xv)) for i, f in enumerate(fs)]
            total = abs(mpmath.fsum(terms))
            if total:
                worst = max(worst, mpmath.fsum(abs(s) for s in terms) / total)
    return float(worst)


def _window_polynomial(groups: dict, x: sp.Symbol, k: sp.Expr, c: sp.Expr, t: sp.Symbol
                       ) -> list[tuple[sp.Expr, sp.Expr | None, list[sp.Expr]]]:
    """Keys that differ by powers of h = k·c make one polynomial in t/c or in
    (c − t)/c (the one whose terms cancel least on samples) with functions of
    x = k·t as coefficients. Returns (prefactor, variable, [f_0, f_1, …]) per
    class of keys; the variable is None for a key alone."""
    h = sp.expand(k * c)
    keys = list(groups)
    classes: list[list[tuple[sp.Expr, int, sp.Rational]]] = []
    for key in keys:
        for cls in classes:
            e = _power_of(sp.cancel(key / cls[0][0]), h, c)
            if e is not None:
                q = sp.simplify(key / cls[0][0] / h ** e)
                cls.append((key, e, q))
                break
        else:
            classes.append([(key, 0, sp.Integer(1))])
    sigma, w = t / c, (c - t) / c
    out = []
    for cls in classes:
        if len(cls) == 1:
            key = cls[0][0]
            out.append((key, None, [groups[key]]))
            continue
        top = max(e for _, e, _ in cls)
        # Σ key_j f_j = key_0 h**top Σ q_j σ**(top−e_j) x**(e_j−top) f_j
        low = min(top - e for _, e, _ in cls)
        in_sigma = defaultdict(lambda: sp.Integer(0))
        for key, e, q in cls:
            in_sigma[top - e - low] += q * x ** (e - top) * groups[key]
        degree = max(in_sigma)
        by_sigma = [sp.expand(in_sigma[i]) for i in range(degree + 1)]
        by_w = [sp.expand(sum((-1) ** i * sp.binomial(m, i) * f for m, f in in_sigma.items()
                              if m >= i)) for i in range(degree + 1)]
        samples = [(s, xv) for s in (0.02, 0.25, 0.5, 0.75, 0.98, 1.0)
                   for xv in (1e-3, 0.3, 1.0, 3.0, 10.0, 40.0)]
        loss_sigma = _loss(by_sigma, x, samples)
        loss_w = _loss(by_w, x, [(1 - s, xv) for s, xv in samples])
        prefactor = cls[0][0] * h ** top * sigma ** low
        if loss_w < loss_sigma:
            out.append((prefactor, w, by_w))
        else:
            out.append((prefactor, sigma, by_sigma))
    return out


def _horner(var: sp.Expr, parts: list[sp.Expr]) -> sp.Expr:
    total = parts[-1]
    for p in reversed(parts[:-1]):
        total = p + var * total
    return total


def _laurent_ok(f: sp.Expr, var: sp.Symbol) -> bool:
    try:
        laurent(f.xreplace({var: Z}), 4)
    except ValueError:
        return False
    return True


def _phase_of(expr: sp.Expr) -> sp.Expr | None:
    """The phase h of the sines and cosines of a parameter-only ``expr``
    (their arguments are rational multiples of h), or None."""
    trig = list(expr.atoms(sp.sin, sp.cos))
    if not trig:
        return None
    h = trig[0].args[0].as_coeff_Mul()[1]
    if any(not sp.cancel(f.args[0] / h).is_Rational for f in trig):
        return None
    return h


def _in_phase(expr: sp.Expr, h: sp.Expr, symbol: sp.Symbol | None = None):
    """``expr`` (parameter-only) as {key: f(hs)} with one symbol of h
    eliminated (hs stands for h): the given ``symbol``, or the first for
    which every group is a function of hs alone. Returns (symbol, hs, groups)
    or None."""
    hs = sp.Dummy("h")
    for s in ([symbol] if symbol is not None else sorted(h.free_symbols, key=str)):
        solved = sp.solve(sp.Eq(h, hs), s)
        if len(solved) != 1:
            continue
        local = sp.expand(sp.expand(expr).xreplace({s: solved[0]}))
        local = local.replace(lambda e: isinstance(e, (sp.sin, sp.cos)),
                              lambda e: e.func(sp.expand(e.args[0])))
        groups = _groups(local, hs)
        if all(_laurent_ok(f, hs) for f in groups.values()):
            return s, hs, groups
    return None


def _coefficient(expr: sp.Expr) -> sp.Expr:
    """A parameter-only coefficient, its entire functions of the phase h of
    its sines and cosines (h = Ω·c) as nodes."""
    expr = sp.expand(expr)
    h = _phase_of(expr)
    found = None if h is None else _in_phase(expr, h)
    if found is None:
        return expr
    _, hs, groups = found
    return sp.Add(*[key * _function(f, hs, h) for key, f in groups.items()])


class wave(sp.Function):
    """``b·cos x + c·sin x`` for an exact phase x (kernel ``_wave``)."""

    nargs = 3

    def _eval_rewrite_as_cos(self, b, c, x, **kwargs):
        return b * sp.cos(x) + c * sp.sin(x)


class offset_wave(sp.Function):
    """``level + b·cos x + c·sin x``, evaluated without cancellation where the
    wave swings back to near zero (kernel ``_offset_wave``); ``gap`` is
    ``level² − b² − c²``, supplied accurately."""

    nargs = 5

    def _eval_rewrite_as_cos(self, level, gap, b, c, x, **kwargs):
        return level + b * sp.cos(x) + c * sp.sin(x)


def _offset(alpha: sp.Expr, beta: sp.Expr, gamma: sp.Expr, phase: sp.Expr) -> sp.Expr | None:
    """α + β cos x + γ sin x as key·offset_wave(a, a² − b² − c², b, c, x)
    when α, β, γ are one key times functions a, b, c of h each (entire
    functions, as nodes)."""
    h = _phase_of(sp.expand(beta + gamma))
    if h is None:
        return None
    first = _in_phase(beta + gamma, h)
    if first is None:
        return None
    symbol, hs, _ = first
    parts = [_in_phase(e, h, symbol) for e in (alpha, beta, gamma)]
    if any(p is None or len(p[2]) > 1 for p in parts):
        return None
    keys = [next(iter(p[2]), None) for p in parts]
    key = keys[0]
    funcs = []
    for p, k in zip(parts, keys):
        if k is None:
            funcs.append(sp.Integer(0))
            continue
        q = sp.cancel(k / key)
        if not q.is_Rational:
            return None
        funcs.append(q * p[2][k].xreplace({p[1]: hs}))
    a, b, c = funcs
    nodes = [_function(sp.expand(f), hs, h) for f in (a, b, c)]
    gap = sp.expand(a ** 2 - b ** 2 - c ** 2)
    simpler = sp.expand(sp.trigsimp(gap))
    gap = _function(simpler if _laurent_ok(simpler, hs) else gap, hs, h)
    return key * offset_wave(nodes[0], gap, nodes[1], nodes[2], phase)


def _stable_piece(piece: sp.Expr, t: sp.Symbol, anchor: sp.Expr,
                  window: sp.Expr | None) -> sp.Expr:
    """One side of a window (or the part present at all times) in local variables."""
    if piece == 0:
        return piece
    k = _slope(piece, t)
    if k is None:
        return piece
    x = sp.Dummy("x")
    local = _local(piece, t, k, anchor, x)
    if local.has(t):
        return piece
    phase = exact_phase(k, t, anchor)
    if anchor != 0:
        parts = sp.collect(local, [sp.cos(x), sp.sin(x)], evaluate=False)
        beta = parts.pop(sp.cos(x), sp.Integer(0))
        gamma = parts.pop(sp.sin(x), sp.Integer(0))
        alpha = parts.pop(sp.S.One, sp.Integer(0))
        if parts or beta.has(x) or gamma.has(x) or alpha.has(x):
            return piece
        sin_x = phase_sin(phase, 1)
        if alpha == 0:
            return wave(_coefficient(beta), _coefficient(gamma), phase)
        offset = _offset(alpha, beta, gamma, phase)
        if offset is not None:
            return offset
        level, swing, sway = (_coefficient(e) for e in (alpha + beta, beta, gamma))
        return level - 2 * swing * phase_sin(phase, sp.Rational(1, 2)) ** 2 + sway * sin_x
    groups = _groups(local, x)
    if window is None:
        return sp.Add(*[key * _function(f, x, phase) for key, f in groups.items()])
    total = sp.Integer(0)
    for prefactor, var, parts in _window_polynomial(groups, x, k, window, t):
        funcs = [_function(f, x, phase) for f in parts]
        total += prefactor * (funcs[0] if var is None else _horner(var, funcs))
    return total


def window_pieces(varying: set[sp.Symbol]) -> Rule:
    """Rule: windowed responses in local variables (see the module docstring)."""
    def rule(expr: sp.Expr) -> sp.Expr:
        if len(varying) != 1 or not expr.has(sp.Heaviside):
            return expr
        (t,) = varying
        split = split_windows(expr, t)
        if split is None:
            return expr
        rest, pieces = split
        total = _stable_piece(rest, t, sp.Integer(0), None)
        for c, (before, after) in sorted(pieces.items(), key=lambda p: sp.default_sort_key(p[0])):
            total += sp.Piecewise((_stable_piece(before, t, sp.Integer(0), c), t <= c),
                                  (_stable_piece(after, t, c, None), True))
        return total

    return rule
