"""Numeric functions for derivation 'hoist_startup'. Generated; do not edit.

Source: crane_sym.derivations.hoist_startup (paper 002_f8509f3826f601de.txt:
Duhamel's integral for the start-up of a crane hoist: rope loads and dynamic factors).
Specialized to scene 'hoist_fig3' (Paper 002, Fig. 3: rope displacement under a suddenly applied load): outputs dynamic_coefficient_instant; folded in: m1 = 2000.0 kg, m2 = 8000.0 kg, C = 1000000.0 N/m, Omega = 25.0 rad/s.
Equations: (38).
Printed by SymPy 1.14.0 with crane_sym 0.1.0; regenerate with `crane-sym generate --scene hoist_fig3 --out <folder>`.

Functions and argument order:
    dynamic_coefficient_instant(t) -> [1]    eq (38)
"""

import math

import numpy as np

__all__ = ['dynamic_coefficient_instant']

SCENE_NAME = 'hoist_fig3'
SCENE_TITLE = 'Paper 002, Fig. 3: rope displacement under a suddenly applied load'


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


def dynamic_coefficient_instant(t, *, out=None):
    """K_din(t) under a suddenly applied constant load. Specialized to scene 'hoist_fig3'. Eq (38).

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
                return np.float64(2*math.sin((25/2)*t)**2)
            except (ArithmeticError, ValueError):
                pass
    t = _checked('t', t, 'nonnegative', 'time from the start of the drive, s', (0.0, 1e7))
    shape = _broadcast(t=t)
    if out is None and not shape:
        return 2*np.sin((25/2)*t)**2
    out = _out(out, shape)
    for _o, (t,) in _spans(out, shape, t):
        np.multiply(t, 25, out=_o)
        np.divide(_o, 2, out=_o)
        np.sin(_o, out=_o)
        np.square(_o, out=_o)
        np.multiply(_o, 2, out=_o)
    return out
