"""One wave for the waves of one cell of a piecewise function.

After its switches a response is a level plus waves of one frequency, each on
its own exact phase ``Ω(t − c_i)`` (``windows``), and each then takes its own
sine and cosine (a term ``sin²(Ω(t − c)/2)`` stays as it is: it takes the
sine and cosine of its phase, and does not cancel). Summed, they are
``L + B·cos Ωt + C·sin Ωt``: B and C rotate
each wave's coefficients by ``Ω·c_i`` (parameter-only, once per call) and
``Ωt`` is the phase the cell's other terms (entire functions of ``Ωt``)
already use, so the cell needs one sine and one cosine a point (the kernels
share them, ``_Phase``).

The sum is only as accurate as the sizes of its parts allow: its rounding
error is a few ulp of ``M = Σ|level_i| + |b_i| + |c_i|``. The generated cell
evaluates the sum, and evaluates the cell's own per-wave formula again on
the points where the sum is below ``M/2`` (``_cancelled``): near a switch,
near a trough, wherever the parts cancel. So the merged sum is a fast path,
never a change of the result beyond a few ulp.
"""
from __future__ import annotations

from collections import defaultdict

import sympy as sp

from crane_sym.codegen.waves import exact_phase, offset_wave, phase_cos, phase_sin, wave

__all__ = ["merge_waves"]


def _parts(node: sp.Expr) -> tuple[sp.Expr, sp.Expr, sp.Expr, sp.Expr] | None:
    """``node`` as (phase, level, b, c), node = level + b·cos(phase) +
    c·sin(phase); None if it is no wave."""
    zero, one = sp.Integer(0), sp.Integer(1)
    if isinstance(node, wave):
        b, c, phase = node.args
        return phase, zero, b, c
    if isinstance(node, offset_wave):
        level, _, b, c, phase = node.args
        return phase, level, b, c
    if isinstance(node, (phase_sin, phase_cos)) and node.args[1] == 1:
        return (node.args[0], zero) + ((zero, one) if isinstance(node, phase_sin) else (one, zero))
    return None


def _wave_term(term: sp.Expr, t: sp.Symbol):
    """``term`` = coefficient·wave as (k, c, level, b, c_sin) on the phase
    k(t − c); None if it is not one."""
    factors = sp.Mul.make_args(term)
    nodes = [f for f in factors if f.has(t)]
    found = _parts(nodes[0]) if len(nodes) == 1 else None
    if found is None or not isinstance(found[0], exact_phase):
        return None
    phase, level, b, c = found
    k, tt, anchor = phase.args
    if tt != t or any(e.has(t) for e in (k, anchor, level, b, c)):
        return None
    coefficient = sp.Mul(*[f for f in factors if not f.has(t)])
    return k, anchor, coefficient * level, coefficient * b, coefficient * c


def merge_waves(expr: sp.Expr, t: sp.Symbol) -> tuple[sp.Expr, sp.Expr] | None:
    """(the cell ``expr`` with its waves of one frequency summed into one on
    the exact phase ``k·t``, the bound M of the module docstring); None when
    no frequency has two waves, or one that could share the sines of k·t."""
    waves: dict[sp.Expr, list] = defaultdict(list)
    rest, level, bound = [], sp.Integer(0), sp.Integer(0)
    for term in sp.Add.make_args(expr):
        found = _wave_term(term, t) if term.has(t) else None
        if found is not None:
            waves[found[0]].append((term,) + found[1:])
        elif term.has(t):
            rest.append(term)
        else:
            level += term
            bound += sp.Abs(term)
    # two waves or more, or one on a shifted phase where the cell's other
    # terms take the sine and cosine of k·t anyway
    worth = {k: len(group) > 1 or (group[0][1] != 0 and any(
        r.has(exact_phase(k, t, sp.Integer(0))) for r in rest)) for k, group in waves.items()}
    if not any(worth.values()):
        return None
    merged = []
    for k, group in sorted(waves.items(), key=lambda kv: sp.default_sort_key(kv[0])):
        if not worth[k]:
            rest.append(group[0][0])
            continue
        big_b = big_c = sp.Integer(0)
        for _, anchor, a, b, c in group:   # cos(kt − kc), sin(kt − kc) by angle addition
            shift = exact_phase(k, anchor, sp.Integer(0))
            cos_h, sin_h = ((phase_cos(shift, 1), phase_sin(shift, 1)) if anchor != 0
                            else (sp.Integer(1), sp.Integer(0)))
            level += a
            big_b += b * cos_h - c * sin_h
            big_c += b * sin_h + c * cos_h
            bound += sp.Abs(a) + sp.Abs(b) + sp.Abs(c)
        phase = exact_phase(k, t, sp.Integer(0))      # its sine and cosine shared
        merged.append(big_b * phase_cos(phase, 1) + big_c * phase_sin(phase, 1))
    return sp.Add(level, *merged, *rest), bound
