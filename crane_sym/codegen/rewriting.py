"""Rewrite rules applied to every expression before it is printed as code.

Each rule is a callable ``expr -> expr`` that returns an equal expression in a
form that floating point evaluates without cancellation. ``optimize`` applies
them in order; the code generator uses ``DEFAULT_RULES`` for every paper, so a
stable form is never patched into one function by hand.
"""
from __future__ import annotations

from typing import Sequence

import sympy as sp
from sympy.codegen.cfunctions import log1p
from sympy.codegen.rewriting import expm1_opt, log1p_opt

from crane_sym.codegen.identities import Rule, cos_pair_to_sin_squared, fold_constants
from crane_sym.codegen.windows import window_pieces

__all__ = ["DEFAULT_RULES", "Rule", "accurate_phase", "cos_pair_to_sin_squared", "cos_phase",
           "cos_remainder", "diff_of_products", "exact_difference_of_products",
           "factor_polynomials", "fold_constants", "log1p_form", "optimize", "rules_for",
           "sin_phase", "sin_remainder", "sin_squared_form", "taylor_remainder",
           "trig_difference_to_product"]

class diff_of_products(sp.Function):
    """``a·b − c·d``, to be evaluated with one rounding (Dekker's TwoProduct).

    Printed as a call to a helper of the generated module; evaluates
    symbolically to the plain difference.
    """

    nargs = 4

    def _eval_rewrite_as_Add(self, a, b, c, d, **kwargs):  # noqa: N802
        return a * b - c * d

    def _eval_evalf(self, prec):
        a, b, c, d = self.args
        return (a * b - c * d)._eval_evalf(prec)


def _two_factors(term: sp.Expr) -> tuple[int, list[sp.Expr]] | None:
    """``(sign, [x, y])`` when ``term`` is ±x·y with non-numeric x, y."""
    coeff, factors = term.as_coeff_mul()
    if coeff not in (1, -1) or len(factors) != 2:
        return None
    if any(f.is_Number or f.is_Add for f in factors):
        return None
    return int(coeff), list(factors)


def exact_difference_of_products(expr: sp.Expr) -> sp.Expr:
    """``x·y − z·w → diff_of_products(x, y, z, w)``: a sum of two two-factor
    products of opposite sign, which cancels when the products are close."""
    def rewrite(add: sp.Add) -> sp.Expr:
        if len(add.args) != 2:
            return add
        parts = [_two_factors(term) for term in add.args]
        if None in parts or parts[0][0] == parts[1][0]:
            return add
        (s1, f1), (_, f2) = parts
        first, second = (f1, f2) if s1 == 1 else (f2, f1)
        return diff_of_products(*first, *second)

    return expr.replace(lambda e: e.is_Add, rewrite)


class sin_phase(sp.Function):
    """``sin(k·t)`` whose phase ``k·t`` is formed in double-double.

    ``t`` is the array argument and ``k`` a parameter-only factor. Where
    ``k·t`` is large, one rounding of the phase is a large *relative* error of
    the sine near its zeros; the generated kernel keeps the phase exact.
    """

    nargs = 2

    def _eval_rewrite_as_sin(self, t, k, **kwargs):
        return sp.sin(k * t)


class cos_phase(sp.Function):
    """``cos(k·t)`` with the phase ``k·t`` formed in double-double."""

    nargs = 2

    def _eval_rewrite_as_cos(self, t, k, **kwargs):
        return sp.cos(k * t)


def accurate_phase(varying: set[sp.Symbol]) -> Rule:
    """Rule: ``sin(k·t) → sin_phase(t, k)`` (likewise cos) for ``t`` in
    ``varying`` and ``k`` free of it."""
    def rewrite(f: sp.Function) -> sp.Expr:
        arg = f.args[0]
        for t in sorted(varying & arg.free_symbols, key=str):
            k = sp.cancel(arg / t)
            if not (k.free_symbols & varying):
                return (sin_phase if isinstance(f, sp.sin) else cos_phase)(t, k)
        return f

    def rule(expr: sp.Expr) -> sp.Expr:
        return expr.replace(lambda e: isinstance(e, (sp.sin, sp.cos)), rewrite)

    return rule


def _taylor(x: sp.Expr, n: int, odd: int) -> sp.Expr:
    return sum(((-1) ** k * x ** (2 * k + odd) / sp.factorial(2 * k + odd)
                for k in range(n)), sp.Integer(0))


class cos_remainder(sp.Function):
    """``cos(x) − Σ_{k<n} (−1)^k x^{2k}/(2k)!``, evaluated by its series where
    the difference cancels (small x)."""

    nargs = 2

    def _eval_rewrite_as_cos(self, x, n, **kwargs):
        return sp.cos(x) - _taylor(x, int(n), 0)


class sin_remainder(sp.Function):
    """``sin(x) − Σ_{k<n} (−1)^k x^{2k+1}/(2k+1)!`` (``x − sin x`` is
    ``−sin_remainder(x, 1)``)."""

    nargs = 2

    def _eval_rewrite_as_sin(self, x, n, **kwargs):
        return sp.sin(x) - _taylor(x, int(n), 1)


def taylor_remainder(varying: set[sp.Symbol]) -> Rule:
    """Rule: ``c·cos(x) − c·(1 − x²/2 + …)`` → ``c·cos_remainder(x, n)``, and
    likewise for sin, for ``x`` linear in one array argument. The responses
    to polynomial loads are made of such differences; at small x they cancel
    to nothing in floating point."""
    def rewrite(add: sp.Add) -> sp.Expr:
        windows = add.atoms(sp.Heaviside, sp.Piecewise)
        if any(w.free_symbols & varying for w in windows):
            return add  # a coefficient would depend on x; the children are visited
        for f in sorted(add.atoms(sp.cos, sp.sin), key=sp.default_sort_key):
            arg = f.args[0]
            found = [v for v in sorted(varying, key=str) if arg.has(v)]
            if len(found) != 1 or arg.has(diff_of_products, sin_phase, cos_phase):
                continue
            v = found[0]
            slope = sp.diff(arg, v)
            if slope == 0 or slope.has(v):
                continue
            x = sp.Dummy("x")
            in_x = sp.expand(add.xreplace({v: (x - arg.subs(v, 0)) / slope}))
            parts = sp.collect(in_x, f.func(x), evaluate=False)
            c, rest = parts.get(f.func(x)), parts.get(sp.S.One, sp.S.Zero)
            if c is None or c.has(x) or set(parts) - {f.func(x), sp.S.One}:
                continue
            odd = int(f.func is sp.sin)

            def coefficient(power: int) -> sp.Expr:
                if power == 0:
                    return rest.as_independent(x, as_Add=True)[0]
                return rest.coeff(x, power)

            n = 0
            while sp.cancel(coefficient(2 * n + odd)
                            + c * (-1) ** n / sp.factorial(2 * n + odd)) == 0:
                n += 1
            if n < 2 - odd:  # 1 - cos x is left to cos_pair_to_sin_squared
                continue
            remainder = (sin_remainder if odd else cos_remainder)(x, n)
            new = c * remainder + sp.expand(rest + c * _taylor(x, n, odd))
            return new.xreplace({x: arg})
        return add

    memo: dict[sp.Basic, sp.Basic] = {}

    def rule(expr: sp.Expr) -> sp.Expr:
        # Top-down: the widest sum shows the longest Taylor polynomial.
        if expr.is_Atom or not expr.has(sp.sin, sp.cos):
            return expr
        if expr not in memo:
            new = rewrite(expr) if expr.is_Add else expr
            memo[expr] = (rule(new) if new != expr
                          else expr.func(*[rule(a) for a in expr.args]))
        return memo[expr]

    return rule


def trig_difference_to_product(expr: sp.Expr) -> sp.Expr:
    """``k·cos A − k·cos B → −2k·sin((A+B)/2)·sin((A−B)/2)`` (and the sine
    analogue): the small factor sin((A−B)/2) is computed directly instead of
    as the difference of two nearly equal cosines."""
    def split(term: sp.Expr):
        trig = [f for f in sp.Mul.make_args(term) if isinstance(f, (sp.cos, sp.sin))]
        if len(trig) != 1:
            return None
        return trig[0].func, sp.Mul(*[f for f in sp.Mul.make_args(term) if f is not trig[0]]), trig[0].args[0]

    def rewrite(add: sp.Add) -> sp.Expr:
        terms = list(add.args)
        parsed = [split(term) for term in terms]
        for i, pi in enumerate(parsed):
            for j in range(i + 1, len(terms)):
                pj = parsed[j]
                if pi is None or pj is None or pi[0] is not pj[0] or pi[2] == pj[2]:
                    continue
                if sp.expand(pi[1] + pj[1]) != 0:
                    continue
                func, k, a = pi
                b = pj[2]
                half_sum, half_diff = (a + b) / 2, (a - b) / 2
                if func is sp.cos:
                    product = -2 * k * sp.sin(half_sum) * sp.sin(half_diff)
                else:
                    product = 2 * k * sp.cos(half_sum) * sp.sin(half_diff)
                rest = [t for n, t in enumerate(terms) if n not in (i, j)]
                return sp.Add(product, *rest)
        return add

    return expr.replace(lambda e: e.is_Add and e.has(sp.sin, sp.cos), rewrite)


def sin_squared_form(expr: sp.Expr) -> sp.Expr:
    """Factor a numerator that became ``k·(1 − cos x)`` after collection."""
    return sp.factor_terms(expr)


def factor_polynomials(varying: set[sp.Symbol], scales: frozenset = frozenset()) -> Rule:
    """Rule: a sum that is a polynomial in an array argument is factored
    (``12t³/t_n³ − 24t²/t_n² + 12t/t_n → 12t(t − t_n)²/t_n³``, ``1 − t/t_n →
    −(t − t_n)/t_n``), so it does not cancel near its real roots. ``scales`` are parameters of the
    argument's dimension (t_n for t): terms are grouped by their joint degree
    in the argument and its scales, and factored group by group, so
    ``g·t·t_n⁴ + 12τ_0·v0·t(t − t_n)²`` is not mixed into one polynomial
    that cancels."""
    def factored(add: sp.Expr) -> sp.Expr | None:
        new = sp.factor(add)
        if not new.is_Atom:
            new = new.func(*new.args)   # factor may leave -1·(1/2)·(...) unevaluated
        return new if new != add and not new.is_Add else None

    def paired(terms: list[sp.Expr], v: sp.Symbol) -> set[sp.Symbol]:
        """Symbols whose power rises as v's falls, term by term (t_n in
        ``t³/t_n³ − 2t²/t_n² + t/t_n``): scales even when none are given."""
        powers = [term.as_powers_dict() for term in terms]
        found = set()
        for s in set().union(*(term.free_symbols for term in terms)) - {v}:
            sums = {sp.sympify(p.get(v, 0) + p.get(s, 0)) for p in powers}
            if len(sums) == 1 and len({p.get(s, 0) for p in powers}) > 1:
                found.add(s)
        return found

    def signature(term: sp.Expr, skip: set) -> tuple:
        """The term's other parameters with their powers (numbers, the
        argument and its scales left out)."""
        return tuple(sorted((str(b), str(e)) for b, e in term.as_powers_dict().items()
                            if not b.is_number and b not in skip))

    def rule(expr: sp.Expr) -> sp.Expr:
        if expr.is_Atom:
            return expr
        if expr.is_Add:
            for v in sorted(varying & expr.free_symbols, key=str):
                if not (expr.is_polynomial(v) and sp.degree(expr, v) >= 1):
                    continue
                terms = sp.Add.make_args(sp.expand(expr))
                skip = set(scales) | {v} | paired(list(terms), v)
                groups: dict[tuple, list[sp.Expr]] = {}
                for term in terms:
                    groups.setdefault(signature(term, skip), []).append(term)
                if len(groups) == 1:
                    new = factored(expr)
                    if new is not None:
                        return new
                    continue
                parts = [factored(sp.Add(*g)) or sp.Add(*g) for _, g in sorted(groups.items())]
                if sp.Add(*parts) != expr:
                    return sp.Add(*parts, evaluate=False)
        return expr.func(*[rule(a) for a in expr.args])

    return rule


def _only_with(head: type, rule: Rule) -> Rule:
    """``rule`` applied only to expressions that contain ``head`` (SymPy's
    expm1/log1p optimizations are slow to find nothing)."""
    def guarded(expr: sp.Expr) -> sp.Expr:
        return rule(expr) if expr.has(head) else expr
    guarded.__name__ = getattr(rule, "__name__", type(rule).__name__)
    return guarded


def log1p_form(expr: sp.Expr) -> sp.Expr:
    """``log(1 + x) → log1p(x)`` (SymPy's ``log1p_opt``), log by log, taken only
    where it finds such a term: elsewhere ``log1p_opt`` expands ``log(a/b)`` into
    ``log(a) − log(b)``, which cancels when a ≈ b."""
    swaps = {}
    for term in expr.atoms(sp.log):
        found = log1p_opt(term)
        if found.has(log1p):
            swaps[term] = found
    return expr.xreplace(swaps) if swaps else expr


#: Rules every generated expression goes through, in order.
DEFAULT_RULES: tuple[Rule, ...] = (
    sin_squared_form,
    cos_pair_to_sin_squared,
    exact_difference_of_products,
    _only_with(sp.exp, expm1_opt),
    log1p_form,
    fold_constants,
)


def rules_for(varying: set[sp.Symbol], scales: frozenset = frozenset(),
              exact_phases: bool = False) -> tuple[Rule, ...]:
    """The rules for a function whose array arguments are ``varying``;
    ``scales`` are its other arguments of the same dimension.

    A phase ``k·t`` is rounded once, which keeps ``sin(k·t)`` within twice its
    condition bound (the error the rounding of ``t`` alone allows) at any
    ``t``. ``exact_phases=True`` forms it in double-double instead
    (:func:`accurate_phase`): about one ulp even near the zeros of the sine at
    long times, at the price of a second transcendental call and a dozen array
    operations (5-8 times the cost of the plain form)."""
    return ((window_pieces(varying), factor_polynomials(varying, scales),
             taylor_remainder(varying))
            + DEFAULT_RULES[:2]
            + (trig_difference_to_product,) + DEFAULT_RULES[2:]
            + ((accurate_phase(varying),) if exact_phases else ()))


def optimize(expr: sp.Expr, rules: Sequence[Rule] = DEFAULT_RULES) -> sp.Expr:
    """Apply ``rules`` in order until the expression stops changing."""
    for _ in range(5):
        before = expr
        for rule in rules:
            expr = rule(expr)
        if expr == before:
            break
    return expr
