"""Numeric functions for derivation 'hoist_startup'. Generated; do not edit.

Source: crane_sym.derivations.hoist_startup (paper 002_f8509f3826f601de.txt:
Duhamel's integral for the start-up of a crane hoist: rope loads and dynamic factors).
Specialized to scene 'hoist_fig5' (Paper 002, Fig. 5: rope displacement under a linearly growing load): outputs dynamic_coefficient_ramp; folded in: m1 = 2000.0 kg, m2 = 8000.0 kg, C = 1000000.0 N/m, t_n = 1.0 s, Omega = 25.0 rad/s.
Equations: (42).
Printed by SymPy 1.14.0 with crane_sym 0.1.0; regenerate with `crane-sym generate --scene hoist_fig5 --out <folder>`.

Functions and argument order:
    dynamic_coefficient_ramp(t) -> [1]    eq (42)
"""

import math

import numpy as np

__all__ = ['dynamic_coefficient_ramp']

SCENE_NAME = 'hoist_fig5'
SCENE_TITLE = 'Paper 002, Fig. 5: rope displacement under a linearly growing load'


def _checked(name, value, sign, what, serves=None):
    """``value`` as a float array; ValueError naming ``name`` if it is not a
    finite number of the required sign or lies outside ``serves`` (low, high),
    the range the function returns finite values for; TypeError if it is not
    a number."""
    scalar = type(value) in (float, int, np.float64)
    if scalar:                                   # a plain number: no array pass
        number = float(value) if abs(value) < 1e308 else float("inf")
        if number != number or abs(number) == float("inf"):
            raise ValueError(f"{name} must be finite ({what}), got a NaN or inf")
        low = high = number
    else:
        if isinstance(value, (str, bytes)):
            raise TypeError(f"{name} must be a number or array of numbers "
                            f"({what}), got a string {value!r}")
        array = np.asarray(value)
        if array.dtype.kind not in "iuf":
            raise TypeError(f"{name} must be a number or array of numbers "
                            f"({what}), got dtype {array.dtype}")
        array = array.astype(float, copy=False)
        if array.size == 0:
            return array
        low, high = array.min(), array.max()
        if not (np.isfinite(low) and np.isfinite(high)):
            raise ValueError(f"{name} must be finite ({what}), got a NaN or inf")
    if sign == "positive" and not low > 0:
        raise ValueError(f"{name} must be > 0 ({what}), got {low!r}")
    if sign == "nonnegative" and not low >= 0:
        raise ValueError(f"{name} must be >= 0 ({what}), got {low!r}")
    if serves is not None and not serves[0] <= low <= high <= serves[1]:
        bad = low if low < serves[0] else high
        raise ValueError(f"{name} must be within [{serves[0]!r}, {serves[1]!r}] ({what}; "
                         f"the range this function serves), got {float(bad)!r}")
    return np.float64(number) if scalar else array


def _broadcast(**arrays):
    """The broadcast shape of the arguments; ValueError naming those that do
    not broadcast together."""
    shapes = {k: v.shape for k, v in arrays.items() if v.ndim}  # _checked's arrays
    if len(shapes) < 2:
        return next(iter(shapes.values()), ())
    try:
        return np.broadcast_shapes(*shapes.values())
    except ValueError:
        listing = ", ".join(f"{k} {s}" for k, s in shapes.items())
        raise ValueError(f"the arguments do not broadcast together: {listing}") from None


def _out(out, shape):
    """A new float64 array of ``shape``, or ``out`` if it is one (written in place)."""
    if out is None:
        return np.empty(shape)
    if not (isinstance(out, np.ndarray) and out.dtype == np.float64
            and out.shape == tuple(shape) and out.flags.writeable):
        raise ValueError(f"out must be a writeable float64 array of shape {tuple(shape)}, "
                         f"got {type(out).__name__} "
                         f"{getattr(out, 'dtype', '')} {getattr(out, 'shape', '')}")
    return out


def _taylor_tail(x, n, odd):
    """The Taylor series of cos(x) (odd=0) or sin(x) (odd=1) from the term
    x**(2n+odd) on, summed for |x| < 2n + 2 until the terms fall below 1e-17
    of the first: as many terms as the largest |x| needs, at most 60."""
    x2 = -x * x
    t = np.ones_like(x) if odd == 0 else x.copy()
    for k in range(n):  # the first term, (-1)**n x**(2n+odd)/(2n+odd)!
        m = 2 * k + odd
        t *= x2
        t /= (m + 1) * (m + 2)
    reach, bound = float(np.max(-x2, initial=0.0)), 1.0
    total = np.zeros_like(x)
    for k in range(n, n + 60):
        total += t
        m = 2 * k + odd
        t *= x2
        t /= (m + 1) * (m + 2)
        bound *= reach / ((m + 1) * (m + 2))  # >= |next term / first| at every x
        if bound < 1e-17:
            break
    return total


def _taylor_remainder(x, n, odd):
    """cos(x) (odd=0) or sin(x) (odd=1) minus its Taylor polynomial through the
    term x**(2n-2+odd): by the series where the direct difference cancels.
    The direct difference is formed in place in the array np.sin/np.cos makes."""
    x = np.asarray(x, dtype=float)
    small = np.abs(x) < 2.0 * n + 2.0
    if small.all():  # no mask, no direct difference
        return _taylor_tail(x, n, odd)
    direct = np.asarray(np.cos(x) if odd == 0 else np.sin(x))
    coeffs = [(-1.0) ** k / np.prod(np.arange(1.0, 2 * k + odd + 1)) for k in range(n)]
    poly = np.full_like(x, coeffs[-1])
    if n > 1:
        x2 = x * x
        for c in coeffs[-2::-1]:  # Horner in x**2
            poly *= x2
            poly += c
    if odd:
        poly *= x
    direct -= poly
    if np.any(small):
        direct[small] = _taylor_tail(x[small], n, odd)
    return direct


def _sin_remainder(x, n):
    """sin(x) - sum_{k<n} (-1)**k x**(2k+1)/(2k+1)!, accurate at small |x|."""
    return _taylor_remainder(x, n, 1)


def _remainder_float(x, n, odd):
    """_taylor_remainder on one float with ``math`` (the scalar path): the
    same sums, term for term."""
    if abs(x) >= 2.0 * n + 2.0:
        direct = math.cos(x) if odd == 0 else math.sin(x)
        coeffs = [(-1.0) ** k / math.factorial(2 * k + odd) for k in range(n)]
        poly = coeffs[-1]
        for c in coeffs[-2::-1]:  # Horner in x**2
            poly = poly * (x * x) + c
        return direct - (poly * x if odd else poly)
    x2, t = -x * x, (1.0 if odd == 0 else x)
    for k in range(n):
        m = 2 * k + odd
        t = t * x2 / ((m + 1) * (m + 2))
    reach, bound, total = -x2, 1.0, 0.0
    for k in range(n, n + 60):
        total += t
        m = 2 * k + odd
        t = t * x2 / ((m + 1) * (m + 2))
        bound *= reach / ((m + 1) * (m + 2))
        if bound < 1e-17:
            break
    return total


def _spans(out, shape, *values, size=16384):
    """(a piece of ``out``, ``values`` on it) for each block of at most
    ``size`` points of the flat ``out``, when ``out`` and every array among
    ``values`` are C-contiguous of the full ``shape``: an expression's
    temporaries then stay block-sized and in the cache, so a call needs no
    full-size work array. Else one piece, the whole (broadcasting as is)."""
    full = tuple(shape)
    flat = out.flags.c_contiguous and all(
        np.ndim(v) == 0 or (v.shape == full and v.flags.c_contiguous) for v in values)
    if not flat or out.size <= size:
        return [(out, values)]
    o = out.reshape(-1)
    arrays = [v if np.ndim(v) == 0 else v.reshape(-1) for v in values]
    return [(o[i:i + size], tuple(v if np.ndim(v) == 0 else v[i:i + size] for v in arrays))
            for i in range(0, o.size, size)]


def dynamic_coefficient_ramp(t, *, out=None):
    """K_din(t) under a linearly growing load, over the static deflection at t_n. Specialized to scene 'hoist_fig5'. Eq (42).

    Parameters
    ----------
    t : array_like
        time from the start of the drive [s], >= 0; served from 0.0 to 1e7
    out : ndarray, optional
        float64 array of the broadcast shape; the result is written into it and returned.

    Returns
    -------
    ndarray
        [1], broadcast over the arguments.
    """
    if (out is None
            and (type(t) in (float, int) or type(t) is np.float64)):
        if (0.0 <= t <= 1e7):
            try:    # a failed check or a math error: the array path decides
                return np.float64(-1/25*_remainder_float(25*t, 1, 1))
            except (ArithmeticError, ValueError):
                pass
    t = _checked('t', t, 'nonnegative', 'time from the start of the drive, s', (0.0, 1e7))
    shape = _broadcast(t=t)
    _one = out is None and not shape
    out = _out(out, shape)
    for _o, (t,) in _spans(out, shape, t):
        _o[...] = -1/25*_sin_remainder(25*t, 1)
    return out[()] if _one else out
