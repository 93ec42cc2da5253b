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
The waves and their coefficients are built in :mod:`crane_sym.codegen.waves`.
"""
from __future__ import annotations

from collections import defaultdict
from functools import lru_cache
from typing import Callable

import mpmath
import sympy as sp

from crane_sym.codegen.waves import (coefficient, entire_at, exact_phase, grouped, offset_form,
                                     phase_sin, wave)

Rule = Callable[[sp.Expr], sp.Expr]


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


@lru_cache(maxsize=None)
def _stable_piece(piece: sp.Expr, t: sp.Symbol, anchor: sp.Expr,
                  window: sp.Expr | None) -> sp.Expr:
    """One side of a window (or the part present at all times) in local
    variables; cached, as a module's functions and its scenes share pieces."""
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
            return wave(coefficient(beta), coefficient(gamma), phase)
        offset = offset_form(alpha, beta, gamma, phase)
        if offset is not None:
            return offset
        level, swing, sway = (coefficient(e) for e in (alpha + beta, beta, gamma))
        return level - 2 * swing * phase_sin(phase, sp.Rational(1, 2)) ** 2 + sway * sin_x
    groups = grouped(local, x)
    if window is None:
        return sp.Add(*[key * entire_at(f, x, phase) for key, f in groups.items()])
    total = sp.Integer(0)
    for prefactor, var, parts in _window_polynomial(groups, x, k, window, t):
        funcs = [entire_at(f, x, phase) for f in parts]
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
