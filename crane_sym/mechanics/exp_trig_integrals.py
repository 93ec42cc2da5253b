"""Definite integrals of :math:`\\tau^j e^{\\alpha(\\tau)}` times sines and cosines
of linear arguments, in closed form (the terms of a Duhamel convolution).

A term :math:`\\tau^j e^{\\alpha(\\tau)} \\prod_k \\operatorname{trig}(\\beta_k(\\tau))`,
:math:`\\alpha, \\beta_k` linear in :math:`\\tau`, is first written by the
product-to-sum formulas as a sum of :math:`\\tau^j e^{\\alpha}` times one
:math:`\\cos\\varphi` or :math:`\\sin\\varphi`, :math:`\\varphi = b\\tau + c`. With
:math:`a = \\alpha'` and :math:`D = a^2 + b^2 \\ne 0`, integration by parts gives

.. math::

    \\int \\tau^j e^{\\alpha} (p\\cos\\varphi + q\\sin\\varphi)\\,d\\tau
    = e^{\\alpha} \\sum_{m=0}^{j} (-1)^m \\frac{j!}{(j-m)!}\\, \\tau^{j-m}
      \\bigl(p_{m+1}\\cos\\varphi + q_{m+1}\\sin\\varphi\\bigr),

    \\begin{pmatrix} p_{k+1} \\\\ q_{k+1} \\end{pmatrix} = \\frac{1}{D}
    \\begin{pmatrix} a & -b \\\\ b & a \\end{pmatrix}
    \\begin{pmatrix} p_k \\\\ q_k \\end{pmatrix}, \\quad (p_0, q_0) = (p, q),

(the matrix inverts :math:`d/d\\tau` on :math:`e^{\\alpha}(p\\cos\\varphi +
q\\sin\\varphi)`); at resonance, :math:`a = b = 0`, the term is
:math:`\\tau^{j+1}/(j+1)` times its constant factors. Where :math:`D = 0` is
undecidable for real :math:`a, b` the result is a ``Piecewise`` of the two.
The antiderivative is evaluated at the bounds, as SymPy's ``integrate`` does,
so no integration algorithm (heurisch, Risch, Meijer G) runs; a term outside
this class (a power of τ that is not a whole number, a hyperbolic function)
goes to ``sympy.integrate``.
"""
from __future__ import annotations

from dataclasses import dataclass

import sympy as sp

_TRIG = (sp.sin, sp.cos)


@dataclass(frozen=True)
class _Term:
    """``coefficient · τ^power · exponential · trig``: ``exponential`` is a
    product of ``exp`` factors (or 1) with rate ``rate``; ``trig`` one sin or
    cos (or None) with frequency ``frequency``."""

    coefficient: sp.Expr
    power: int
    exponential: sp.Expr
    rate: sp.Expr
    trig: sp.Expr | None


def _linear_rate(argument: sp.Expr, tau: sp.Symbol) -> sp.Expr | None:
    """d(argument)/dτ when ``argument`` is linear in τ, else None."""
    rate = sp.diff(argument, tau)
    return None if rate.has(tau) else rate


def _product_to_sum(first: sp.Expr, second: sp.Expr) -> sp.Expr:
    """sin/cos(A) · sin/cos(B) as a sum of single sines and cosines."""
    A, B = first.args[0], second.args[0]
    if first.func is sp.sin and second.func is sp.sin:
        return (sp.cos(A - B) - sp.cos(A + B)) / 2
    if first.func is sp.cos and second.func is sp.cos:
        return (sp.cos(A - B) + sp.cos(A + B)) / 2
    s, c = (A, B) if first.func is sp.sin else (B, A)
    return (sp.sin(s + c) + sp.sin(s - c)) / 2


def _split(term: sp.Expr, tau: sp.Symbol) -> list[_Term] | None:
    """``term`` as a sum of ``_Term``; None when it is outside the class."""
    power, exps, rate, trigs, rest = 0, [], sp.Integer(0), [], []
    for factor in sp.Mul.make_args(term):
        base, exponent = factor.as_base_exp()
        if not factor.has(tau):
            rest.append(factor)
        elif base == tau and exponent.is_Integer and exponent >= 0:
            power += int(exponent)
        elif isinstance(factor, sp.exp):
            r = _linear_rate(factor.args[0], tau)
            if r is None:
                return None
            exps.append(factor)
            rate += r
        elif isinstance(base, _TRIG) and exponent.is_Integer and exponent > 0:
            if _linear_rate(base.args[0], tau) is None:
                return None
            trigs += [base] * int(exponent)
        else:
            return None
    coefficient, exponential = sp.Mul(*rest), sp.Mul(*exps)
    wave = sp.Mul(*trigs[:1])
    for other in trigs[1:]:
        wave = sp.expand(sp.Add(*(_times(part, other, tau) for part in sp.Add.make_args(wave))))
    terms = []
    for part in sp.Add.make_args(wave):
        factor, trig = part.as_independent(tau, as_Add=False)
        terms.append(_Term(coefficient * factor, power, exponential, rate,
                           trig if trig.has(tau) else None))
    return terms


def _times(part: sp.Expr, other: sp.Expr, tau: sp.Symbol) -> sp.Expr:
    """``part`` (a factor times one sin or cos, or a constant) times ``other``."""
    factor, trig = part.as_independent(tau, as_Add=False)
    if not trig.has(tau):
        return part * other
    return factor * _product_to_sum(trig, other)


def _antiderivative(term: _Term, tau: sp.Symbol) -> sp.Expr | None:
    """An antiderivative of ``term`` in τ (module docstring); None where
    :math:`D = a^2 + b^2` may vanish and a, b are not known to be real."""
    a = term.rate
    trig = term.trig if term.trig is not None else sp.Integer(1)
    b = sp.Integer(0) if term.trig is None else sp.diff(trig.args[0], tau)
    j = term.power
    resonant = term.coefficient * term.exponential * trig * tau ** (j + 1) / (j + 1)
    if a == 0 and b == 0:
        return resonant
    D = a ** 2 + b ** 2
    if term.trig is None:
        # e^{α} alone: the matrix reduces to 1/a
        sums = [(sp.Integer(1) / a ** (m + 1), sp.Integer(0)) for m in range(j + 1)]
        waves = (sp.Integer(1), sp.Integer(0))
    else:
        phi = trig.args[0]
        p, q = (sp.Integer(1), sp.Integer(0)) if trig.func is sp.cos else (0, 1)
        sums = []
        for _ in range(j + 1):
            p, q = _inverse_step(a, b, D, p, q)
            sums.append((p, q))
        waves = (sp.cos(phi), sp.sin(phi))
    polynomial = sum((-1) ** m * sp.ff(j, m) * tau ** (j - m) * (pm * waves[0] + qm * waves[1])
                     for m, (pm, qm) in enumerate(sums))
    generic = term.coefficient * term.exponential * polynomial
    if D.is_zero is False:
        return generic
    if a.is_real and b.is_real:
        return sp.Piecewise((resonant, sp.Eq(a, 0) & sp.Eq(b, 0)), (generic, True))
    return None


def _inverse_step(a: sp.Expr, b: sp.Expr, D: sp.Expr, p: sp.Expr,
                  q: sp.Expr) -> tuple[sp.Expr, sp.Expr]:
    """(p, q) ↦ M (p, q), M = [[a, −b], [b, a]]/D: the inverse of d/dτ on
    e^{α}(p cos φ + q sin φ). Exact; with a = 0 it is (−q/b, p/b)."""
    if a == 0:
        return -q / b, p / b
    return sp.cancel((a * p - b * q) / D), sp.cancel((b * p + a * q) / D)


def definite_integral(integrand: sp.Expr, tau: sp.Symbol, lower: sp.Expr,
                      upper: sp.Expr) -> sp.Expr:
    """:math:`\\int_{lower}^{upper}` ``integrand`` :math:`d\\tau`, exactly.

    Each term of the expanded integrand in the class of the module docstring
    is integrated in closed form, its value a sum of products (as
    ``integrate`` gives it); any other term by ``sympy.integrate``
    (``ValueError`` where SymPy cannot).

    Parameters
    ----------
    integrand : sympy.Expr
        The function of ``tau`` to integrate.
    tau : Symbol
        The variable of integration.
    lower, upper : sympy.Expr
        The bounds (free of ``tau``).

    >>> tau, t, w = sp.symbols("tau t omega", positive=True)
    >>> definite_integral(tau * sp.sin(w * tau - w * t), tau, 0, t)
    -t/omega + sin(omega*t)/omega**2
    """
    total = sp.Integer(0)
    for term in sp.Add.make_args(sp.expand(integrand)):
        if term == 0:
            continue
        pieces = _split(term, tau)
        primitives = (None if pieces is None
                      else [_antiderivative(piece, tau) for piece in pieces])
        if primitives is None or any(p is None for p in primitives):
            total += _by_sympy(term, tau, lower, upper)
            continue
        primitive = sp.Add(*primitives)
        total += sp.expand_mul(primitive.subs(tau, upper) - primitive.subs(tau, lower))
    return total


def _by_sympy(term: sp.Expr, tau: sp.Symbol, lower: sp.Expr, upper: sp.Expr) -> sp.Expr:
    """The fallback: SymPy's ``integrate`` for a term outside the class."""
    integral = sp.integrate(term, (tau, lower, upper))
    if integral.has(sp.Integral):
        raise ValueError(f"SymPy cannot integrate {term} over {tau}")
    return integral
