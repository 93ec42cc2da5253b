"""High-precision references for generated functions.

The reference evaluates the *derived* expression of an ``Output`` (before any
rewrite rule) in mpmath at the exact double inputs the generated function
received, so it checks the rewrites and the printer, not just the arithmetic.
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Mapping

import mpmath
import numpy as np
import sympy as sp

from .derivation import Output


def mp_values(out: Output, columns: Mapping[str, np.ndarray], dps: int = 50) -> list:
    """``out.expr`` at each row of ``columns`` (one array per argument), as mpf."""
    f = sp.lambdify(out.args, out.expr, modules="mpmath")
    arrays = np.broadcast_arrays(*(np.asarray(columns[str(a)], dtype=float)
                                   for a in out.args))
    with mpmath.workdps(dps):
        return [f(*(mpmath.mpf(float(x)) for x in row)) for row in zip(*(a.ravel() for a in arrays))]


def relative_errors(computed: np.ndarray, exact: list) -> np.ndarray:
    """|computed - exact| / |exact| per point (inf where exact is 0 and computed is not)."""
    computed = np.asarray(computed, dtype=float).ravel()
    out = np.empty(computed.size)
    with mpmath.workdps(50):
        for i, (c, e) in enumerate(zip(computed, exact)):
            if e == 0:
                out[i] = 0.0 if c == 0 else np.inf
            else:
                out[i] = float(abs((mpmath.mpf(float(c)) - e) / e))
    return out


@dataclass(frozen=True)
class AccuracyRow:
    """Worst relative error of one generated function on one hard case."""

    function: str
    case: str
    points: int
    max_rel_error: float
    where: dict


def accuracy(out: Output, function, case: str,
             columns: Mapping[str, np.ndarray]) -> AccuracyRow:
    """Compare ``function`` (generated) with the mpmath reference of ``out``."""
    args = [np.asarray(columns[str(a)], dtype=float) for a in out.args]
    computed = np.broadcast_to(function(*args), np.broadcast(*args).shape)
    errors = relative_errors(computed, mp_values(out, columns))
    worst = int(np.argmax(errors))
    flat = [np.broadcast_to(a, computed.shape).ravel() for a in args]
    return AccuracyRow(out.name, case, errors.size, float(errors[worst]),
                       {str(a): float(v[worst]) for a, v in zip(out.args, flat)})
