"""Dimensional analysis of SymPy expressions against a symbol table.

Dimensions are held as exponent vectors over the SI base dimensions (from
``sympy.physics.units.systems.si.dimsys_SI``), so ``force`` and
``mass*length/time**2`` compare equal. The checker walks an expression *as
printed* (no simplification first), so a term that a simplifier would cancel
is still reported.
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Mapping

import sympy as sp
from sympy.core.function import AppliedUndef
from sympy.physics.units import Dimension
from sympy.physics.units.systems.si import dimsys_SI

from crane_sym.latex import latex

#: Exponent vector: base-dimension name -> rational exponent (zeros dropped).
DimVec = tuple[tuple[str, sp.Rational], ...]

DIMENSIONLESS: DimVec = ()
_BASE_UNIT = {"mass": "kg", "length": "m", "time": "s", "current": "A",
              "temperature": "K", "amount_of_substance": "mol",
              "luminous_intensity": "cd"}


class DimensionMismatch(Exception):
    """Terms of a sum, or the two sides of an equation, differ in dimension."""

    def __init__(self, message: str, terms: list[tuple[sp.Expr, DimVec]]):
        super().__init__(message)
        self.terms = terms


def vector(dim: Dimension) -> DimVec:
    """Canonical exponent vector of a SymPy ``Dimension``.

    Parameters
    ----------
    dim : Dimension
        A SymPy dimension.
    """
    deps = dimsys_SI.get_dimensional_dependencies(dim)
    return _normal({str(k.name): sp.Rational(v) for k, v in deps.items()})


_ORDER = tuple(_BASE_UNIT)


def _normal(exps: Mapping[str, sp.Rational]) -> DimVec:
    rank = {name: i for i, name in enumerate(_ORDER)}
    kept = [(k, v) for k, v in exps.items() if v != 0]
    return tuple(sorted(kept, key=lambda kv: (rank.get(kv[0], len(rank)), kv[0])))


def _mul(a: DimVec, b: DimVec, power: sp.Rational = sp.Integer(1)) -> DimVec:
    exps = dict(a)
    for k, v in b:
        exps[k] = exps.get(k, 0) + power * v
    return _normal(exps)


def _pow(a: DimVec, power: sp.Rational) -> DimVec:
    return _normal({k: v * power for k, v in a})


def format_vector(d: DimVec) -> str:
    """Readable SI form, e.g. ``kg·m/s²``; ``1`` when dimensionless."""
    if not d:
        return "1"
    sup = str.maketrans("0123456789-/", "⁰¹²³⁴⁵⁶⁷⁸⁹⁻ᐟ")

    def part(name: str, e: sp.Rational) -> str:
        unit = _BASE_UNIT.get(name, name)
        return unit if e == 1 else unit + str(e).translate(sup)

    num = [part(k, v) for k, v in d if v > 0]
    den = [part(k, -v) for k, v in d if v < 0]
    text = "·".join(num) or "1"
    return text + ("/" + "·".join(den) if den else "")


def dimension_of(expr: sp.Basic, dims: Mapping[sp.Basic, DimVec]) -> DimVec:
    """Dimension vector of ``expr``; raise ``DimensionMismatch`` on the first
    sum whose terms disagree, or a transcendental function of a dimensional
    argument."""
    if expr in dims:
        return dims[expr]
    if isinstance(expr, sp.Number) or expr in (sp.pi, sp.E):
        return DIMENSIONLESS
    if isinstance(expr, sp.Symbol):
        raise KeyError(f"symbol {expr} has no dimension in the symbol table")
    if isinstance(expr, AppliedUndef):  # S(theta) has the dimension of S(t)
        for key, d in dims.items():
            if isinstance(key, AppliedUndef) and key.func == expr.func:
                return d
        raise KeyError(f"function {expr.func} has no dimension in the symbol table")
    if isinstance(expr, sp.Integral):
        d = dimension_of(expr.function, dims)
        for limits in expr.limits:
            d = _mul(d, dimension_of(limits[0], dims))
        return d
    if isinstance(expr, sp.Abs):
        return dimension_of(expr.args[0], dims)
    if isinstance(expr, (sp.Min, sp.Max)):
        return _common(list(expr.args), dims, f"arguments of {expr}")
    if isinstance(expr, sp.Piecewise):
        return _common([branch for branch, _ in expr.args], dims, f"branches of {expr}")
    if isinstance(expr, sp.Derivative):
        d = dimension_of(expr.expr, dims)
        for var, count in expr.variable_count:
            d = _mul(d, dimension_of(var, dims), -sp.Integer(count))
        return d
    if isinstance(expr, sp.Mul):
        d = DIMENSIONLESS
        for factor in expr.args:
            d = _mul(d, dimension_of(factor, dims))
        return d
    if isinstance(expr, sp.Pow):
        base = dimension_of(expr.base, dims)
        if not base:
            _require_dimensionless(expr.exp, dims, expr)
            return DIMENSIONLESS
        if not expr.exp.is_Rational:
            raise DimensionMismatch(
                f"dimensional base raised to a symbolic power in {expr}", [])
        return _pow(base, expr.exp)
    if isinstance(expr, sp.Add):
        return _common(list(expr.args), dims, f"terms of {expr}")
    if isinstance(expr, sp.Function):
        for arg in expr.args:
            _require_dimensionless(arg, dims, expr)
        return DIMENSIONLESS
    raise TypeError(f"cannot take the dimension of {type(expr).__name__}: {expr}")


def _require_dimensionless(arg: sp.Basic, dims: Mapping, where: sp.Basic) -> None:
    d = dimension_of(arg, dims)
    if d:
        raise DimensionMismatch(
            f"the argument ${latex(arg)}$ of ${latex(where)}$ has dimension "
            f"{format_vector(d)}, "
            "must be dimensionless", [(arg, d)])


def _common(terms: list[sp.Expr], dims: Mapping, what: str) -> DimVec:
    found = [(term, dimension_of(term, dims)) for term in terms]
    kinds = {d for _, d in found}
    if len(kinds) > 1:
        listing = "; ".join(f"{t} [{format_vector(d)}]" for t, d in found)
        raise DimensionMismatch(f"{what} differ in dimension: {listing}", found)
    return found[0][1]


@dataclass(frozen=True)
class DimensionReport:
    """Outcome of a dimension check of a printed formula."""

    consistent: bool
    dimension: DimVec | None
    message: str
    offending: tuple[str, ...] = ()


def check_equation(lhs: sp.Expr, rhs: sp.Expr, dims: Mapping[sp.Basic, DimVec],
                   names: Mapping[sp.Basic, str] | None = None) -> DimensionReport:
    """Check that every term on both sides of ``lhs = rhs`` shares one dimension;
    offending terms are named in LaTeX (``names``: the paper's symbol names).

    Parameters
    ----------
    lhs, rhs : sympy.Expr
        The two sides.
    dims : mapping of sympy.Basic to DimVec
        The dimension of every symbol and function in them.
    names : mapping of sympy.Basic to str, optional
        LaTeX names for the report.
    """
    terms = list(sp.Add.make_args(lhs)) + list(sp.Add.make_args(rhs))
    terms = [t for t in terms if t != 0]
    try:
        d = _common(terms, dims, "terms of the equation")
    except DimensionMismatch as err:
        if len(err.terms) < 2:  # an argument that must be dimensionless
            return DimensionReport(False, None, str(err),
                                   tuple(_term(t, d, names) for t, d in err.terms))
        offending, reference = _offending(lhs, err.terms, names)
        message = "the term" + ("s " if len(offending) > 1 else " ") + ", ".join(offending)
        message += (" differ" if len(offending) > 1 else " differs") + f" from {reference}"
        return DimensionReport(False, None, message, offending)
    return DimensionReport(True, d, f"every term has dimension {format_vector(d)}")


def _term(t: sp.Expr, d: DimVec, names: Mapping | None = None) -> str:
    return f"${latex(t, symbol_names=dict(names or {}))}$ [{format_vector(d)}]"


def _offending(lhs: sp.Expr, found: list[tuple[sp.Expr, DimVec]],
               names: Mapping | None = None) -> tuple[tuple[str, ...], str]:
    """The terms to blame, and what they are measured against.

    A left-hand side of one term (the quantity the formula defines) sets the
    dimension; otherwise the most common dimension does, and with a tie every
    term is listed.
    """
    if len(sp.Add.make_args(lhs)) == 1 and lhs != 0 and found[0][0] == lhs:
        ref = found[0][1]
        return (tuple(_term(t, d, names) for t, d in found[1:] if d != ref),
                f"the left-hand side {_term(*found[0], names)}")
    counts: dict[DimVec, int] = {}
    for _, d in found:
        counts[d] = counts.get(d, 0) + 1
    top = max(counts.values())
    majors = [d for d, n in counts.items() if n == top]
    if len(majors) > 1:
        return (tuple(_term(t, d, names) for t, d in found), "each other (no majority)")
    return (tuple(_term(t, d, names) for t, d in found if d != majors[0]),
            f"the other terms' [{format_vector(majors[0])}]")
