"""The three checks behind every verdict, in the order they run.

1. ``symbolic``: the printed and the derived relation are the same, i.e. the
   difference of their residuals simplifies to zero, or their ratio simplifies
   to a nonzero factor free of the unknowns (same equation, rearranged).
2. ``numeric``: the same question at seeded random points inside the physics
   (``crane_sym.audit.sampling``: data from their physical ranges, a factor of 2
   apart within a dimension, defined quantities from their definitions), in
   mpmath at ``dps`` digits. Unknowns of an implicit relation (time,
   coordinates and their derivatives, defined quantities) are drawn twice per
   point: two equivalent relations have one residual ratio at both draws.
3. ``dimension``: every term of the printed relation has one dimension.

Each returns a ``CheckOutcome`` whose ``status`` is ``pass``, ``fail`` or
``inconclusive``; a failing outcome says what differs.

What repeats within a run is done once: a relation's numeric function (the
derived step is compared with every reading of its print) and a dimension's
exponent vector.
"""
from __future__ import annotations

from functools import lru_cache
from typing import Callable, Iterable

import mpmath
import numpy as np
import sympy as sp

from sympy.core.function import AppliedUndef

from crane_sym.dimensions import check_equation, vector
from crane_sym.latex import latex
from crane_sym.outcomes import FAIL, INCONCLUSIVE, PASS, CheckOutcome
from crane_sym.audit.sampling import PointSampler, draw
from crane_sym.symbols import COORDINATE, DEFINED, TIME, SymbolTable



@lru_cache(maxsize=4096)
def _mpmath_function(args: tuple, expr: sp.Expr) -> Callable:
    """``expr`` as an mpmath function of ``args``, made once per run."""
    return sp.lambdify(list(args), expr, modules="mpmath")


@lru_cache(maxsize=None)
def _vector(dim: sp.Basic) -> tuple:
    """A dimension's exponent vector, found once per run."""
    return vector(dim)


def residual(relation: sp.Eq) -> sp.Expr:
    """``lhs - rhs`` of a relation."""
    return relation.lhs - relation.rhs


def _frozen(table: SymbolTable, exprs: Iterable[sp.Expr]) -> dict[sp.Basic, sp.Symbol]:
    """Plain symbols for every coordinate x(t) and derivative in ``exprs``,
    highest derivative first so substitution does not split them."""
    found: set[sp.Basic] = set()
    for expr in exprs:
        found |= expr.atoms(sp.Derivative)
        found |= {f for f in expr.atoms(sp.Function) if f in table}
    ordered = sorted(found, key=lambda e: (-sp.count_ops(e) - len(e.args), sp.srepr(e)))
    return {e: sp.Dummy(f"frz{i}", real=True) for i, e in enumerate(ordered)}


def unknowns_of(table: SymbolTable) -> set[sp.Basic]:
    """Symbols that are not data: time, coordinates, defined quantities."""
    return {e.expr for e in table.with_role(TIME, COORDINATE, DEFINED)}


def _abs_of_cases(expr: sp.Expr) -> sp.Expr | None:
    """``expr`` expanded with each Piecewise((x, x ≥ 0), (−x, True)) read as |x|,
    where it holds both (a print's |x| transcribed as its cases against a derived
    Abs: ``simplify`` took seconds to find what this shows); else None."""
    if not (expr.has(sp.Abs) and expr.has(sp.Piecewise)):
        return None

    def is_abs(p: sp.Basic) -> bool:
        if not isinstance(p, sp.Piecewise) or len(p.args) != 2 or p.args[1].cond != sp.true:
            return False
        (x, cond), (other, _) = p.args
        return other == -x and isinstance(cond, sp.core.relational.Relational) and \
            cond.canonical in {r.canonical for r in (sp.Ge(x, 0), sp.Gt(x, 0),
                                                     sp.Le(-x, 0), sp.Lt(-x, 0))}
    return sp.expand(expr.replace(is_abs, lambda p: sp.Abs(p.args[0].expr)))


def symbolic_equivalence(printed: sp.Eq, derived: sp.Eq,
                         table: SymbolTable) -> CheckOutcome:
    """Decide by simplification whether two relations are the same equation."""
    rp, rd = residual(printed), residual(derived)
    if _abs_of_cases(rp - rd) == 0:
        return CheckOutcome("symbolic", PASS, "printed − derived expands to 0 with the "
                            "cases (x if x ≥ 0, else −x) read as |x|")
    if sp.expand(rp - rd) == 0 or sp.simplify(rp - rd) == 0:   # expanding is enough, mostly
        return CheckOutcome("symbolic", PASS, "printed − derived simplifies to 0")
    if printed.lhs == derived.lhs and printed.lhs.free_symbols & unknowns_of(table):
        # Both define the same quantity: only equal right-hand sides agree.
        return CheckOutcome("symbolic", INCONCLUSIVE,
                            "the right-hand sides did not simplify to the same expression")
    if sp.simplify(rp + rd) == 0:
        return CheckOutcome("symbolic", PASS,
                            "the same equation with its sides exchanged")
    frozen = _frozen(table, (rp, rd))
    ratio = sp.simplify(sp.cancel((rp / rd).xreplace(frozen)))
    unknown = unknowns_of(table) | set(frozen.values())
    if ratio.free_symbols.isdisjoint(unknown) and ratio.is_zero is False:
        return CheckOutcome(
            "symbolic", PASS,
            f"the same equation multiplied by ${latex(ratio)}$")
    return CheckOutcome("symbolic", INCONCLUSIVE,
                        "simplification did not reduce the difference to 0")


def numeric_equivalence(printed: sp.Eq, derived: sp.Eq, table: SymbolTable,
                        *, points: int = 6, dps: int = 30, seed: int = 2024,
                        tol: float = 1e-20, names: dict | None = None,
                        definitions: dict | None = None) -> CheckOutcome:
    """Compare two relations at seeded physical points in mpmath.

    Data are drawn from their physical ranges, a factor of 2 apart within a
    dimension where the ranges allow (``crane_sym.audit.sampling``). When both
    relations define the same quantity (same left-hand side) their right-hand
    sides are compared, within the relative tolerance ``tol`` (a printed
    number rounded to a few digits needs its half-unit of the last digit); a
    defined symbol in them takes the value of its definition (``definitions``,
    from ``sampling.physical_definitions``) at the drawn data. Otherwise the
    residual ratio must be one constant for two draws of the unknowns at each
    point, a defined unknown drawn within a factor of 3 of its definition.
    """
    same_lhs = printed.lhs == derived.lhs
    rp, rd = ((printed.rhs, derived.rhs) if same_lhs
              else (residual(printed), residual(derived)))
    frozen = _frozen(table, (rp, rd))
    rp, rd = rp.xreplace(frozen), rd.xreplace(frozen)
    free = rp.free_symbols | rd.free_symbols
    unknown_all = sorted((unknowns_of(table) | set(frozen.values())) & free, key=str)
    defs = definitions or {}
    computed = [u for u in unknown_all if same_lhs and u in defs]
    unknown = [u for u in unknown_all if u not in computed]
    params = [e for e in table if e.expr in free and e.expr not in unknown_all]
    stray = free - set(unknown_all) - {e.expr for e in params}
    if stray:
        raise ValueError(f"symbols {sorted(map(str, stray))} are not in the symbol table")
    args = [e.expr for e in params] + computed + unknown
    f_p, f_d = _mpmath_function(tuple(args), rp), _mpmath_function(tuple(args), rd)
    rng = np.random.default_rng(seed)
    entries = {e.expr: e for e in table}
    original = {v: k for k, v in frozen.items()}
    centred = [u for u in unknown if u in defs]
    sampler = PointSampler(params, {u: defs[u] for u in computed + centred}, table)

    def name_values(vals: list, syms: list) -> tuple[tuple[str, str], ...]:
        tex = dict(names or {})
        return tuple((latex(original.get(s, s), symbol_names=tex), mpmath.nstr(v, 12))
                     for s, v in zip(syms, vals))

    def draw_unknowns(at: dict) -> list:
        """Defined unknowns about their definitions, the others in their ranges (a
        frozen x(t) in x's); a derivative, which has no range, in [0.3, 3]."""
        out = []
        for u in unknown:
            entry = entries.get(u) or entries.get(original.get(u))
            if u in at and at[u] != 0:
                out.append(at[u] * mpmath.mpf(float(np.exp(rng.uniform(-np.log(3),
                                                                      np.log(3))))))
            else:
                out.append(mpmath.mpf(draw(entry, rng) if entry is not None
                                      else rng.uniform(0.3, 3.0)))
        return out

    worst = mpmath.mpf(0)
    tiny = mpmath.mpf(10) ** -dps
    with mpmath.workdps(dps):
        for _ in range(points):
            pvals, at = sampler.point(rng)
            known = pvals + [at[u] for u in computed]
            if same_lhs:
                uvals = draw_unknowns(at)
                a, b = f_p(*known, *uvals), f_d(*known, *uvals)
                dev = abs(a - b) / max(abs(b), tiny)
                if dev > tol:
                    point = name_values(known + uvals, args)
                    return CheckOutcome(
                        "numeric", FAIL,
                        f"at {_at(point)} the printed right-hand side is "
                        f"{mpmath.nstr(a, 12)}, the derived one {mpmath.nstr(b, 12)} "
                        f"(relative difference {mpmath.nstr(dev, 3)}, tolerance {tol:g})",
                        point=point)
            else:
                ratios, draws = [], []
                for _draw_no in range(2):
                    uvals = draw_unknowns(at)
                    a, b = f_p(*known, *uvals), f_d(*known, *uvals)
                    if b != 0:
                        ratios.append(a / b)
                        draws.append(uvals)
                if len(ratios) < 2:
                    continue
                r0, r1 = ratios
                dev = abs(r0 - r1) / max(abs(r0), abs(r1), tiny)
                if r0 == 0 or dev > tol:
                    second = ", ".join(f"{k} = {v}" for k, v in
                                       name_values(draws[1], unknown)) or "none"
                    point = name_values(known + draws[0], args)
                    return CheckOutcome(
                        "numeric", FAIL,
                        f"at {_at(point)} the printed/derived residual ratio is "
                        f"{mpmath.nstr(r0, 12)}; with the unknowns drawn again "
                        f"({second}) it is {mpmath.nstr(r1, 12)}: not the same relation",
                        point=point)
            worst = max(worst, dev)
    what = "relative difference" if same_lhs else "deviation of the residual ratio"
    return CheckOutcome(
        "numeric", PASS,
        f"same relation at {points} seeded points ({dps} digits), max {what} "
        f"{mpmath.nstr(worst, 2)}" + (f" within tolerance {tol:g}" if tol > 1e-20 else ""))


def _at(point: tuple[tuple[str, str], ...]) -> str:
    return ", ".join(f"${k}$ = {v}" for k, v in point) or "every sampled point"


def difference(printed: sp.Eq, derived: sp.Eq, *, max_ops: int = 300) -> sp.Expr | None:
    """What differs, expanded so that shared terms cancel: printed − derived
    right-hand sides when both define the same quantity, else the residuals
    scaled to agree in one term (so a missing or extra term shows by itself).
    ``None`` when the difference is too large to read."""
    if printed.lhs == derived.lhs:
        pairs = [(printed.rhs, derived.rhs)]
    else:
        rp, rd = residual(printed), residual(derived)
        pairs = [(rp, rd), (rp, -rd)]
        expanded_rp = sp.expand(rp)
        for term in sp.Add.make_args(sp.expand(rd)):
            scale, core = term.as_coeff_Mul()
            coeff = expanded_rp.coeff(core)
            if coeff != 0 and scale != 0:
                pairs.append((rp, rd * coeff / scale))
                break
    best, best_ops = None, None
    for a, b in pairs:  # expand cancels what the two share; no trigsimp roulette
        expanded = sp.expand(a - b)
        candidates = [_with_ops(expanded), _with_ops(sp.factor_terms(expanded))]
        if candidates[0][1] <= max_ops // 3:  # common denominators cancel
            candidates.append(_with_ops(sp.factor_terms(sp.cancel(expanded))))
        for diff, ops in candidates:
            if best is None or ops < best_ops:
                best, best_ops = diff, ops
    return best if best is not None and best_ops <= max_ops else None


def _with_ops(expr: sp.Expr) -> tuple[sp.Expr, int]:
    """``expr`` with its operation count, counted once."""
    return expr, sp.count_ops(expr)


def _witness_values(symbols: list, rng: np.random.Generator) -> list | None:
    """A value for each symbol that its SymPy assumptions allow (what
    ``simplify`` may rely on): of size 0.3 to 3, its sign as declared, random
    where none is; None when a symbol asks for more (an integer)."""
    values = []
    for sym in symbols:
        if sym.is_integer or sym.is_zero:
            return None
        size = mpmath.mpf(float(np.exp(rng.uniform(np.log(0.3), np.log(3.0)))))
        if sym.is_negative or sym.is_nonpositive:
            values.append(-size)
        elif sym.is_positive or sym.is_nonnegative or rng.random() < 0.5:
            values.append(size)
        else:
            values.append(-size)
    return values


def _signs(e: sp.Basic) -> dict[str, bool]:
    """The assumptions of a function value or derivative ``e`` that its plain
    stand-in keeps: real, and its sign (and integrality) where declared."""
    kept = {name: True for name in ("positive", "negative", "nonnegative", "nonpositive",
                                    "integer") if getattr(e, f"is_{name}")}
    return {"real": True, **kept}


def _stand_ins(expr: sp.Expr, rng: np.random.Generator) -> dict | None:
    """A polynomial of degree 2 with seeded coefficients for each undefined
    function of one argument inside an integral of ``expr`` (S(θ) under
    ∫ S(θ) sin Ω(t − θ) dθ), of the sign it is declared; an identity in any
    function holds in these. None when one takes more arguments, must be an
    integer, or is also differentiated (its stand-in would not be frozen)."""
    inside = {f for i in expr.atoms(sp.Integral) for f in i.atoms(AppliedUndef)}
    if any(dv.expr.func in {f.func for f in inside} for dv in expr.atoms(sp.Derivative)):
        return None
    out = {}
    for func in sorted({f.func for f in inside}, key=str):
        applied = next(f for f in inside if f.func is func)
        if len(applied.args) != 1 or applied.is_integer:
            return None
        c = [sp.Rational(int(rng.integers(300, 3000)), 1000) for _ in range(3)]
        u = sp.Dummy("u", real=True)
        if applied.is_positive or applied.is_nonnegative:
            body = c[0] + c[2] * u**2
        elif applied.is_negative or applied.is_nonpositive:
            body = -c[0] - c[2] * u**2
        else:
            body = c[0] - c[1] * u + c[2] * u**2
        out[func] = sp.Lambda(u, body)
    return out


def numerically_nonzero(expr: sp.Expr, *, points: int = 2, seed: int = 2024) -> bool:
    """True when ``expr`` is shown not to be identically 0: at a seeded point
    its symbols' assumptions allow (an undefined function under an integral
    a seeded polynomial, :func:`_stand_ins`), it is real, finite and not 0 in
    mpmath at 20 and at 40 digits, the two values agreeing to 10 digits (a
    sum that is 0 leaves rounding noise, which does not). Then no
    simplification can reduce it to 0, and none need be tried. False when the
    numbers cannot tell: a sum, a derivative of more than a function, a
    complex or undefined value, a symbol that must be an integer.

    Parameters
    ----------
    expr : Expr
        The expression, such as the difference of two relations' residuals.
    points : int, optional
        Seeded points tried.
    seed : int, optional
        The seed of the points.

    >>> x, y = sp.symbols("x y", positive=True)
    >>> numerically_nonzero(sp.sin(x)**2 + sp.cos(x)**2 - 1), numerically_nonzero(x - y)
    (False, True)
    """
    rng = np.random.default_rng(seed)
    stand_ins = _stand_ins(expr, rng)
    if stand_ins is None or expr.has(sp.Sum, sp.Product) or any(
            not isinstance(dv.expr, AppliedUndef) for dv in expr.atoms(sp.Derivative)):
        return False
    expr = expr.replace(lambda e: isinstance(e, AppliedUndef) and e.func in stand_ins,
                        lambda e: stand_ins[e.func](*e.args))
    frozen = {e: sp.Dummy(f"frz{i}", **_signs(e)) for i, e in enumerate(
        sorted(expr.atoms(sp.Derivative) | expr.atoms(AppliedUndef),
               key=lambda e: (-len(e.args), sp.srepr(e))))}
    flat = expr.xreplace(frozen)
    if flat.atoms(AppliedUndef) or flat.has(sp.Derivative):
        return False
    symbols = sorted(flat.free_symbols, key=sp.default_sort_key)
    try:
        f = sp.lambdify(symbols, flat, modules="mpmath")
        for _ in range(points):
            values = _witness_values(symbols, rng)
            if values is None:
                return False
            with mpmath.workdps(20):
                coarse = f(*values)
            with mpmath.workdps(40):
                fine = f(*values)
            if all(isinstance(v, mpmath.mpf) and mpmath.isfinite(v) for v in (coarse, fine)) \
                    and fine != 0 and abs(coarse - fine) <= mpmath.mpf(10) ** -10 * abs(fine):
                return True
    except (ValueError, TypeError, ArithmeticError, NameError, AttributeError):
        return False
    return False


def dimension_consistency(relation: sp.Eq, table: SymbolTable,
                          names: dict | None = None) -> CheckOutcome:
    """Every term of ``relation``, as printed, has one dimension."""
    dims = {k: _vector(v) for k, v in table.dimensions().items()}
    report = check_equation(relation.lhs, relation.rhs, dims, names)
    return CheckOutcome("dimension", PASS if report.consistent else FAIL, report.message)
