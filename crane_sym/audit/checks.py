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
"""
from __future__ import annotations

from typing import Iterable

import mpmath
import numpy as np
import sympy as sp

from crane_sym.dimensions import check_equation, vector
from crane_sym.latex import latex
from crane_sym.outcomes import FAIL, INCONCLUSIVE, PASS, CheckOutcome
from crane_sym.audit.sampling import PointSampler, draw
from crane_sym.symbols import COORDINATE, DEFINED, TIME, SymbolTable



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


def symbolic_equivalence(printed: sp.Eq, derived: sp.Eq,
                         table: SymbolTable) -> CheckOutcome:
    """Decide by simplification whether two relations are the same equation."""
    rp, rd = residual(printed), residual(derived)
    if sp.simplify(rp - rd) == 0:
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
    f_p = sp.lambdify(args, rp, modules="mpmath")
    f_d = sp.lambdify(args, rd, modules="mpmath")
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
    best = None
    for a, b in pairs:  # expand cancels what the two share; no trigsimp roulette
        expanded = sp.expand(a - b)
        candidates = [expanded, sp.factor_terms(expanded)]
        if sp.count_ops(expanded) <= max_ops // 3:  # common denominators cancel
            candidates.append(sp.factor_terms(sp.cancel(expanded)))
        for diff in candidates:
            if best is None or sp.count_ops(diff) < sp.count_ops(best):
                best = diff
    return best if best is not None and sp.count_ops(best) <= max_ops else None


def dimension_consistency(relation: sp.Eq, table: SymbolTable,
                          names: dict | None = None) -> CheckOutcome:
    """Every term of ``relation``, as printed, has one dimension."""
    dims = {k: vector(v) for k, v in table.dimensions().items()}
    report = check_equation(relation.lhs, relation.rhs, dims, names)
    return CheckOutcome("dimension", PASS if report.consistent else FAIL, report.message)
