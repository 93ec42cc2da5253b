"""Entire functions of one variable that cancel in closed form.

Responses to polynomial loads are combinations like
``(z**2*cos(z) - 2*z*sin(z) - 2*cos(z) + 2)/z**4``: entire functions whose
closed form is a difference of nearly equal terms at small ``z``. An
``entire(z, key)`` node stands for such a function; the generated module
evaluates it by its Taylor series (exact rational coefficients, so the
cancellation happens in exact arithmetic) where ``|z|`` is below a cutoff
and by the closed form above it. The cutoff and the number of terms are
chosen here, at generation time, from a running error bound of both forms
evaluated in mpmath.
"""
from __future__ import annotations

import hashlib
from dataclasses import dataclass
from fractions import Fraction
from functools import lru_cache

import mpmath
import sympy as sp

from crane_sym.codegen.identities import cos_pair_to_sin_squared, fold_constants

#: The variable every closed form is written in.
Z = sp.Symbol("z", real=True)
#: Unit roundoff of a double.
U = 2.0 ** -53
#: Error target of the series tail, relative to the local size of the function.
TAIL = 2.0 ** -60

_CLOSED: dict[int, sp.Expr] = {}


class entire(sp.Function):
    """``f(z)`` for the closed form registered under ``key`` (see
    ``entire_node``); evaluates symbolically to the closed form."""

    nargs = 2

    def _eval_rewrite_as_Add(self, z, key, **kwargs):  # noqa: N802
        return closed_form(int(key)).xreplace({Z: z})

    def _eval_evalf(self, prec):
        return self.rewrite(sp.Add)._eval_evalf(prec)


def closed_form(key: int) -> sp.Expr:
    """The closed form (in ``Z``) registered under ``key``."""
    return _CLOSED[key]


def entire_node(z: sp.Expr, closed: sp.Expr) -> sp.Expr:
    """``entire(z, key)`` for ``closed`` (an expression in ``Z``); the key is
    a hash of the closed form, so equal forms share one node in every run."""
    digest = hashlib.sha1(sp.srepr(closed).encode("utf-8")).hexdigest()
    key = int(digest[:12], 16)
    _CLOSED.setdefault(key, closed)
    return entire(z, sp.Integer(key))


# --- Taylor coefficients ---------------------------------------------------------------
def _trig_series(func, q: Fraction, order: int) -> dict[int, Fraction]:
    """sin(q z) or cos(q z) through z**order."""
    out, k = {}, 1 if func is sp.sin else 0
    term = q if k else Fraction(1)
    fact = 1
    while k <= order:
        out[k] = term / fact
        term *= -q * q
        fact *= (k + 1) * (k + 2)
        k += 2
    return out


def _product(a: dict[int, Fraction], b: dict[int, Fraction], order: int) -> dict[int, Fraction]:
    out: dict[int, Fraction] = {}
    for i, x in a.items():
        for j, y in b.items():
            if i + j <= order:
                out[i + j] = out.get(i + j, Fraction(0)) + x * y
    return out


def _fraction(r: sp.Rational) -> Fraction:
    return Fraction(int(r.p), int(r.q))


def laurent(closed: sp.Expr, order: int) -> dict[int, Fraction]:
    """Coefficients of the Laurent series of ``closed`` at 0 through ``Z**order``.

    ``closed`` must be a sum of rational multiples of ``Z**a``, ``sin(q Z)``
    and ``cos(q Z)`` products (q rational); raises ValueError otherwise.
    """
    total: dict[int, Fraction] = {}
    for term in sp.Add.make_args(sp.expand(closed)):
        coeff, factors = term.as_coeff_mul()
        if not coeff.is_Rational:
            raise ValueError(f"not a rational coefficient: {term}")
        power, series = 0, {0: _fraction(coeff)}
        trig = []
        for f in factors:
            base, e = f.as_base_exp()
            if base == Z and e.is_Integer:
                power += int(e)
            elif isinstance(base, (sp.sin, sp.cos)) and e.is_Integer and e > 0:
                q = sp.cancel(base.args[0] / Z)
                if not q.is_Rational:
                    raise ValueError(f"argument not a rational multiple of z: {base}")
                trig += [(base.func, _fraction(q))] * int(e)
            else:
                raise ValueError(f"unsupported factor {f} in {term}")
        # Series of the trig factors through the order needed once z**power is applied.
        need = order - power
        if need < 0:
            continue
        for func, q in trig:
            series = _product(series, _trig_series(func, q, need), need)
        for k, c in series.items():
            total[k + power] = total.get(k + power, Fraction(0)) + c
    return {k: c for k, c in sorted(total.items()) if c != 0}


# --- running error bounds --------------------------------------------------------------
def _bound(expr: sp.Expr, z: mpmath.mpf) -> tuple[mpmath.mpf, mpmath.mpf]:
    """(value, bound on the absolute rounding error) of ``expr`` at ``z``, evaluated
    in doubles in the order the tree gives (first order; z itself exact)."""
    if expr == Z:
        return z, mpmath.mpf(0)
    if expr.is_Number:
        v = mpmath.mpf(sp.Float(expr, 30))
        return v, (mpmath.mpf(0) if expr.is_Integer else U * abs(v))
    if expr.is_Add or expr.is_Mul:
        parts = [_bound(a, z) for a in expr.args]
        if expr.is_Add:
            v = mpmath.fsum(p for p, _ in parts)
            return v, mpmath.fsum(e for _, e in parts) + U * mpmath.fsum(abs(p) for p, _ in parts)
        v = mpmath.fprod(p for p, _ in parts)
        rel = mpmath.fsum(e / abs(p) if p else mpmath.inf for p, e in parts)
        return v, abs(v) * (rel + U * (len(parts) - 1))
    if expr.is_Pow and expr.exp.is_Integer:
        b, eb = _bound(expr.base, z)
        n = int(expr.exp)
        v = b ** n
        return v, abs(v) * (abs(n) * eb / abs(b) + U * (abs(n) + 1))
    if isinstance(expr, (sp.sin, sp.cos)):
        # A rounded phase q·z is a relative perturbation of z: the caller's
        # condition number covers it, so only the sine's own rounding counts.
        a, _ = _bound(expr.args[0], z)
        v = mpmath.sin(a) if isinstance(expr, sp.sin) else mpmath.cos(a)
        return v, U * abs(v)
    raise ValueError(f"no error bound for {expr}")


def _sizer(closed: sp.Expr):
    """Local size of the function at z: largest |f| over about a period around
    z (an oscillating function is measured by its envelope, not its zeros)."""
    f = sp.lambdify(Z, closed, "mpmath")

    def size(z: float) -> mpmath.mpf:
        lo, hi = (z / 1.5, z * 1.5) if z < 2 * mpmath.pi else (z - mpmath.pi, z + mpmath.pi)
        return max(abs(f(mpmath.mpf(lo) + (hi - lo) * k / 8)) for k in range(9))
    return size


@dataclass(frozen=True)
class Plan:
    """How the generated helper evaluates one entire function."""

    printed: sp.Expr          # the closed form as printed (rewritten to stable forms)
    cutoff: float             # the Taylor series below |z| < cutoff
    power: int                # z**power * Σ coeffs[k] z**(step*k)
    step: int
    coeffs: tuple[float, ...]
    loss: float               # worst error bound over the grid, in units of U·size


_GRID = [2.0 ** (k / 4) for k in range(-24, 37)]    # 0.016 … 512
_ORDER = 400


def stable_form(closed: sp.Expr) -> sp.Expr:
    """``closed`` as printed: 1 − cos z as 2 sin²(z/2), constants folded."""
    return fold_constants(cos_pair_to_sin_squared(closed))


@lru_cache(maxsize=None)
def plan(key: int) -> Plan:
    """Cutoff, terms and printed form for the function registered under ``key``:
    the cutoff minimizes the worse of the two forms' error bounds on a grid."""
    closed = closed_form(key)
    printed = stable_form(closed)
    with mpmath.workdps(40):
        coeffs = laurent(closed, _ORDER)
        power = min(coeffs)
        step = 2 if all((k - power) % 2 == 0 for k in coeffs) else 1
        size = _sizer(closed)
        sizes = [size(z) for z in _GRID]
        closed_loss = [float(_bound(printed, mpmath.mpf(z))[1] / (U * s))
                       for z, s in zip(_GRID, sizes)]
        # |c_k| z**k, grid point by grid point until the series stops converging
        powers = list(coeffs)
        scale = [abs(mpmath.mpf(c.numerator) / c.denominator) for c in coeffs.values()]
        best, series_worst = None, 0.0
        for i, cut in enumerate(_GRID):
            if best is not None and series_worst >= best[0]:
                break       # the series' part only grows, the closed form's only shrinks
            tails = _tails(scale, _powers(mpmath.mpf(cut), powers))
            n = _terms(powers, tails, power, sizes[i])
            if n is None:
                break
            series_worst = max(series_worst, float(2 * tails[0] / sizes[i]))
            loss = max(series_worst, max(closed_loss[i:]))
            if best is None or loss < best[0]:
                best = (loss, cut, n)
    loss, cut, n = best
    taylor = tuple(float(coeffs.get(power + step * k, 0)) for k in range(n // step + 1))
    return Plan(printed, cut, power, step, taylor, loss)


def _powers(w: mpmath.mpf, powers: list[int]) -> list[mpmath.mpf]:
    """w**k for the increasing exponents ``powers``, each from the one before
    by one multiplication (a few roundings at 40 digits: far below the 2**-60
    the plan decides on)."""
    out, last, value = [], powers[0], w ** powers[0]
    steps: dict[int, mpmath.mpf] = {}
    for k in powers:
        if k != last:
            gap = k - last
            if gap not in steps:
                steps[gap] = w ** gap
            value *= steps[gap]
            last = k
        out.append(value)
    return out


def _tails(scale: list, powers: list) -> list:
    """tails[i] = Σ_{j ≥ i} scale[j]·powers[j]: what the series omits after i terms."""
    tails, running = [], mpmath.mpf(0)
    for a, p in zip(reversed(scale), reversed(powers)):
        running += a * p
        tails.append(running)
    tails.reverse()
    return tails


def _terms(powers: list[int], tails: list, power: int, size) -> int | None:
    """Fewest terms after the first so that the omitted ones (``tails``, the sums
    of the magnitudes from each term on) sum below TAIL·size."""
    for i, k in enumerate(powers):
        if k > _ORDER - 60:
            return None
        if i + 1 == len(powers) or tails[i + 1] <= TAIL * size:
            return k - power
    return None


def needs_series(closed: sp.Expr) -> bool:
    """Whether the stable closed form alone is not accurate everywhere: it has a
    pole that cancels at 0, or its error bound exceeds 8 u somewhere (a
    product of a few rounded factors stays below that)."""
    printed = stable_form(closed)
    coeffs = laurent(closed, 60)
    if not coeffs:
        return False
    negative = any(e.is_Pow and e.base == Z and e.exp < 0 for e in sp.preorder_traversal(printed))
    if negative and min(coeffs) >= 0:
        return True
    with mpmath.workdps(40):
        size = _sizer(closed)
        return any(_bound(printed, mpmath.mpf(z))[1] > 8 * U * size(z)
                   for z in _GRID[::4] + [1e-6])
