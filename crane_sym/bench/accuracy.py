"""High-precision references for generated functions.

The reference evaluates the *derived* expression of an ``Output`` (before any
rewrite rule) in mpmath at the exact double inputs the generated function
received, so it checks the rewrites and the printer, not just the arithmetic.
The derived closed forms cancel badly in places (a response over a window
of length 1e-9/Ω loses ~9 digits per power of the window), so the working
precision is raised until two evaluations agree to the digits asked for.
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Callable, Mapping, Sequence

import mpmath
import numpy as np
import sympy as sp

from crane_sym.derivation import Output

#: Unit roundoff of a double: the relative error of rounding one input.
UNIT_ROUNDOFF = 2.0 ** -53
#: Largest working precision tried before giving up [digits].
MAX_DPS = 3200


def _agree(a, b, digits: int) -> bool:
    return a == b or abs(a - b) <= mpmath.mpf(10) ** -digits * max(abs(a), abs(b))


def reference_value(f: Callable, row: Sequence, digits: int = 50):
    """``f`` at ``row`` (mpf) to ``digits`` significant digits: evaluated at
    rising precision until two evaluations agree. Returns (value, dps)."""
    dps = digits + 10
    with mpmath.workdps(dps):
        previous = f(*row)
    while dps < MAX_DPS:
        dps *= 2
        with mpmath.workdps(dps):
            value = f(*row)
            if _agree(value, previous, digits):
                return +value, dps
        previous = value
    raise ArithmeticError(f"no {digits} stable digits at {MAX_DPS} digits of precision")


def condition_number(f: Callable, row: Sequence, value, dps: int):
    """Σ |x_i ∂f/∂x_i| / |f| at ``row``: the relative error of f when each
    input carries a relative error of 1, to first order (forward differences
    at ``dps`` digits)."""
    if value == 0:
        return mpmath.inf
    with mpmath.workdps(dps):
        step = mpmath.mpf(10) ** -(dps // 4)
        total = mpmath.mpf(0)
        for i, x in enumerate(row):
            if x == 0:
                continue
            moved = list(row)
            moved[i] = x * (1 + step)
            total += abs((f(*moved) - value) / step)
        return total / abs(value)


def _lambdified(out: Output) -> Callable:
    return sp.lambdify(out.args, out.expr, modules="mpmath")


def _rows(out: Output, columns: Mapping[str, np.ndarray]) -> list[list]:
    arrays = np.broadcast_arrays(*(np.asarray(columns[str(a)], dtype=float)
                                   for a in out.args))
    return [[mpmath.mpf(float(x)) for x in row] for row in zip(*(a.ravel() for a in arrays))]


def mp_values(out: Output, columns: Mapping[str, np.ndarray], dps: int = 50) -> list:
    """``out.expr`` at each row of ``columns`` (one array per argument), as mpf
    correct to ``dps`` significant digits."""
    f = _lambdified(out)
    return [reference_value(f, row, dps)[0] for row in _rows(out, columns)]


def relative_errors(computed: np.ndarray, exact: list) -> np.ndarray:
    """|computed - exact| / |exact| per point (inf where exact is 0 and computed
    is not, or where computed is NaN or inf)."""
    computed = np.asarray(computed, dtype=float).ravel()
    out = np.empty(computed.size)
    with mpmath.workdps(50):
        for i, (c, e) in enumerate(zip(computed, exact)):
            if not np.isfinite(c):
                out[i] = np.inf
            elif e == 0:
                out[i] = 0.0 if c == 0 else np.inf
            else:
                out[i] = float(abs((mpmath.mpf(float(c)) - e) / e))
    return out


@dataclass(frozen=True)
class AccuracyRow:
    """Worst relative error of one generated function on one hard case.

    ``bound`` is the condition number times the unit roundoff at the worst
    point: the error that rounding the inputs alone causes. ``excess`` is the
    largest ratio, over the points, of the error to ``max(tolerance, 2·bound)``
    (at most 1: within the target everywhere).
    """

    function: str
    case: str
    points: int
    max_rel_error: float
    where: dict
    bound: float
    excess: float


def accuracy(out: Output, function, case: str, columns: Mapping[str, np.ndarray],
             tolerance: float = 1e-15) -> AccuracyRow:
    """Compare ``function`` (generated) with the mpmath reference of ``out``.

    The condition number is computed at the worst point and wherever the
    error exceeds ``tolerance``.

    Parameters
    ----------
    out : Output
        The derived output; its expression, evaluated in mpmath, is the reference.
    function : callable
        The generated function of ``out``, called with the columns as keywords.
    case : str
        The hard case's name, for the row.
    columns : mapping of str to ndarray
        One array per argument of ``function``, all of one length.
    tolerance : float, optional
        Relative error above which a point's condition number is computed too.
    """
    args = [np.asarray(columns[str(a)], dtype=float) for a in out.args]
    computed = np.broadcast_to(function(*args), np.broadcast(*args).shape)
    f = _lambdified(out)
    rows = _rows(out, columns)
    exact = [reference_value(f, row) for row in rows]
    errors = relative_errors(computed, [v for v, _ in exact])
    worst = int(np.argmax(errors))
    bounds = np.zeros(errors.size)
    for i in set(np.flatnonzero(errors > tolerance)) | {worst}:
        kappa = condition_number(f, rows[i], *exact[i])
        bounds[i] = float(kappa) * UNIT_ROUNDOFF
    excess = float(np.max(errors / np.maximum(tolerance, 2 * bounds)))
    flat = [np.broadcast_to(a, computed.shape).ravel() for a in args]
    return AccuracyRow(out.name, case, errors.size, float(errors[worst]),
                       {str(a): float(v[worst]) for a, v in zip(out.args, flat)},
                       float(bounds[worst]), excess)
