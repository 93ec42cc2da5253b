"""Waves on exact phases: the pieces a windowed response is written in.

A response anchored at a switch is ``α + β·cos x + γ·sin x`` with the exact
phase ``x = k·(t − c)`` (``exact_phase``, formed as a pair by the generated
code); its coefficients depend on the parameters only, through ``h = Ωc``, and
are written as entire functions of h (``coefficient``), so that the printer
evaluates them without cancellation. ``wave`` and ``offset_wave`` are the
printed forms (kernels ``_wave`` and ``_offset_wave``); ``groups`` and
``entire_at`` write ``Σ key·f(x)`` with each ``f`` as an ``entire`` node where
its closed form cancels. Used by :mod:`crane_sym.codegen.windows`.
"""
from __future__ import annotations

from collections import defaultdict

import sympy as sp

from crane_sym.codegen.entire import Z, entire_node, laurent, needs_series, stable_form


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


def normal(f: sp.Expr) -> tuple[sp.Expr, sp.Expr]:
    """``f = c·g`` with c a number and g normalised (first term's coefficient 1)."""
    terms = sorted(sp.Add.make_args(sp.expand(f)), key=sp.default_sort_key)
    c = terms[0].as_coeff_Mul()[0]
    return c, sp.expand(f / c)


def grouped(expr: sp.Expr, x: sp.Symbol) -> dict[sp.Expr, sp.Expr]:
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
        c, g = normal(f)
        by_function[g] += c * key
    out: dict[sp.Expr, sp.Expr] = defaultdict(lambda: sp.Integer(0))
    for g, key in by_function.items():
        # keys equal once factored: one function (a product of powers is its own factoring)
        out[sp.factor(key) if key.has(sp.Add) else key] += g
    return {key: sp.expand(f) for key, f in out.items() if sp.expand(f) != 0}


def entire_at(f: sp.Expr, x: sp.Symbol, arg: sp.Expr) -> sp.Expr:
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


def laurent_ok(f: sp.Expr, var: sp.Symbol) -> bool:
    try:
        laurent(f.xreplace({var: Z}), 4)
    except ValueError:
        return False
    return True


def phase_of(expr: sp.Expr) -> sp.Expr | None:
    """The phase h of the sines and cosines of a parameter-only ``expr``
    (their arguments are rational multiples of h), or None."""
    trig = list(expr.atoms(sp.sin, sp.cos))
    if not trig:
        return None
    h = trig[0].args[0].as_coeff_Mul()[1]
    if any(not sp.cancel(f.args[0] / h).is_Rational for f in trig):
        return None
    return h


def in_phase(expr: sp.Expr, h: sp.Expr, symbol: sp.Symbol | None = None):
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
        groups = grouped(local, hs)
        if all(laurent_ok(f, hs) for f in groups.values()):
            return s, hs, groups
    return None


def coefficient(expr: sp.Expr) -> sp.Expr:
    """A parameter-only coefficient, its entire functions of the phase h of
    its sines and cosines (h = Ω·c) as nodes."""
    expr = sp.expand(expr)
    h = phase_of(expr)
    found = None if h is None else in_phase(expr, h)
    if found is None:
        return expr
    _, hs, groups = found
    return sp.Add(*[key * entire_at(f, hs, h) for key, f in groups.items()])


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


def offset_form(alpha: sp.Expr, beta: sp.Expr, gamma: sp.Expr, phase: sp.Expr) -> sp.Expr | None:
    """α + β cos x + γ sin x as key·offset_wave(a, a² − b² − c², b, c, x)
    when α, β, γ are one key times functions a, b, c of h each (entire
    functions, as nodes)."""
    h = phase_of(sp.expand(beta + gamma))
    if h is None:
        return None
    first = in_phase(beta + gamma, h)
    if first is None:
        return None
    symbol, hs, _ = first
    parts = [in_phase(e, h, symbol) for e in (alpha, beta, gamma)]
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
    nodes = [entire_at(sp.expand(f), hs, h) for f in (a, b, c)]
    gap = sp.expand(a ** 2 - b ** 2 - c ** 2)
    simpler = sp.expand(sp.trigsimp(gap))
    gap = entire_at(simpler if laurent_ok(simpler, hs) else gap, hs, h)
    return key * offset_wave(nodes[0], gap, nodes[1], nodes[2], phase)
