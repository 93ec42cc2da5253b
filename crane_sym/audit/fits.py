"""A parameter the paper does not state, fitted to its printed numbers, shown.

A ``fitted value`` reading (``published.Fit``) takes one value of an unstated
parameter for several printed numbers. Each number, printed to a few digits,
allows an interval of the parameter (its derived step is a function of it);
the numbers agree on the parameter only where those intervals overlap. This
module finds each interval in mpmath and the overlap, so a record can say
"this print allows Δt in [0.93, 1.14] s, the eight together [0.999, 1.005] s,
the reading takes 1 s" instead of only "Δt = 1 s".
"""
from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache

import mpmath
import sympy as sp

from crane_sym.derivation import Derivation
from crane_sym.published import Fit, PublishedFormula

__all__ = ["FitResult", "allowed", "fit_of"]

#: Grid points over the bracket (log-spaced) before the ends are bisected.
_GRID = 400


@lru_cache(maxsize=1024)
def allowed(expr: sp.Expr, fit: Fit, printed: sp.Expr,
            tolerance: float) -> tuple[float, float] | None:
    """The interval of ``fit.symbol`` inside ``fit.bracket`` where ``expr`` is
    ``printed`` within ``tolerance`` (relative to ``expr``, as the numeric check
    compares), or None when no point of the bracket is; the ends bisected to
    12 digits. Between the first and the last point that pass, every grid
    point passes, or a ValueError says the set is not one interval. Cached:
    each record of a fit asks for every record's interval."""
    f = sp.lambdify(fit.symbol, expr, modules="mpmath")
    target = mpmath.mpf(sp.Rational(printed).p) / sp.Rational(printed).q
    tol = mpmath.mpf(max(tolerance, 1e-12))

    def inside(p) -> bool:
        value = f(p)
        return abs(value - target) <= tol * abs(value)

    with mpmath.workdps(30):
        lo, hi = (mpmath.mpf(b) for b in fit.bracket)
        grid = [lo * (hi / lo) ** (mpmath.mpf(k) / _GRID) for k in range(_GRID + 1)]
        hits = [inside(p) for p in grid]
        if not any(hits):
            return None
        first, last = hits.index(True), _GRID - hits[::-1].index(True)
        if not all(hits[first:last + 1]):
            raise ValueError(f"{fit.name}: the values a print allows are not one interval")

        def edge(a, b):   # a passes, b does not (or the bracket's end)
            for _ in range(60):
                mid = (a + b) / 2
                a, b = (mid, b) if inside(mid) else (a, mid)
            return a
        low = grid[0] if first == 0 else edge(grid[first], grid[first - 1])
        high = grid[-1] if last == _GRID else edge(grid[last], grid[last + 1])
        return float(low), float(high)


@dataclass(frozen=True)
class FitResult:
    """What a fit's printed numbers allow, alone and together."""

    fit: Fit
    each: tuple[tuple[str, tuple[float, float] | None], ...]   # label -> interval

    @property
    def common(self) -> tuple[float, float] | None:
        """The interval every printed number allows, or None."""
        spans = [span for _, span in self.each]
        if any(span is None for span in spans) or not spans:
            return None
        low, high = max(s[0] for s in spans), min(s[1] for s in spans)
        return (low, high) if low <= high else None

    @property
    def holds(self) -> bool:
        """True when the reading's value lies where every print allows."""
        common = self.common
        return common is not None and common[0] <= float(self.fit.value) <= common[1]

    def text(self, label: str) -> str:
        """The fit as one sentence, for the record ``label``."""
        f, unit = self.fit, f" {self.fit.unit}" if self.fit.unit else ""
        own = dict(self.each).get(label)
        common = self.common
        this = (f"this print allows {f.name} in [{own[0]:.4g}, {own[1]:.4g}]{unit}"
                if own else f"no {f.name} in [{f.bracket[0]:g}, {f.bracket[1]:g}]{unit} "
                "gives this print")
        together = (f"the {len(self.each)} prints it is fitted to together "
                    f"[{common[0]:.4g}, {common[1]:.4g}]{unit}" if common
                    else f"the {len(self.each)} prints it is fitted to share no value")
        return (f"{f.name} fitted: {this}; {together}; the reading takes "
                f"{sp.sstr(f.value)}{unit}" + ("" if self.holds else ", outside it"))


def fit_of(d: Derivation, fit: Fit, own: PublishedFormula | None = None) -> FitResult:
    """Every record of ``d`` whose reading carries ``fit``, with the interval its
    print allows (the derived step of the literal record, a function of the
    parameter, against the printed number); ``own`` (a record being audited, which
    may differ from the one of that label in ``d``) takes its label's place."""
    each = []
    for f in d.published:
        if own is not None and f.label == own.label:
            f = own
        if f.printed is None or not any(c.fit == fit for c in f.conventions):
            continue
        expr = d.step(f.target).statement.rhs
        each.append((f.label, allowed(expr, fit, f.printed.rhs, f.tolerance)))
    return FitResult(fit, tuple(each))
