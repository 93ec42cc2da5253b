"""Numeric functions for derivation 'travel_braking'. Generated; do not edit.

Source: crane_sym.derivations.travel_braking (paper 000_4ef6efc8a81a3b06.txt:
Dynamic loads when the travel mechanism of an overhead crane brakes).
Specialized to scene 'overhead_crane_50t' (50 t overhead crane: braking the bridge travel with full load): outputs elastic_force, velocity_m1, velocity_m2; folded in: m1 = 4400.0 kg, m2 = 110000.0 kg, c = 3000000.0 N/m, P_t = 24000.0 N, W = 11000.0 N, v0 = 1.3333333333333333 m/s.
Equations: (1), (2), (13), (14).
Printed by SymPy 1.14.0 with crane_sym 0.1.0; regenerate with `crane-sym generate --scene overhead_crane_50t --out <folder>`.

Functions and argument order:
    elastic_force(t) -> [N]    eq (14)
    velocity_m1(t) -> [m/s]    eq (1), (13)
    velocity_m2(t) -> [m/s]    eq (2), (13)
"""

import math

import numpy as np

__all__ = ['elastic_force', 'velocity_m1', 'velocity_m2']

SCENE_NAME = 'overhead_crane_50t'
SCENE_TITLE = '50 t overhead crane: braking the bridge travel with full load'


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


def elastic_force(t, *, out=None):
    """Force F(t) in the elastic link. Specialized to scene 'overhead_crane_50t'. Eq (14).

    Parameters
    ----------
    t : array_like
        time since the brake was applied [s], >= 0; served from 0.0 to 1e7
    out : ndarray, optional
        float64 array of the broadcast shape; the result is written into it and returned.

    Returns
    -------
    ndarray
        [N], broadcast over the arguments.
    """
    if (out is None
            and (type(t) in (float, int) or type(t) is np.float64)):
        if (0.0 <= t <= 1e7):
            try:    # a failed check or a math error: the array path decides
                return np.float64((589000/13)*math.sin(13.314380468978918*t)**2)
            except (ArithmeticError, ValueError):
                pass
    t = _checked('t', t, 'nonnegative', 'time since the brake was applied, s', (0.0, 1e7))
    shape = _broadcast(t=t)
    if out is None and not shape:
        return (589000/13)*np.sin(13.314380468978918*t)**2
    out = _out(out, shape)
    for _o, (t,) in _spans(out, shape, t):
        np.multiply(t, 13.314380468978918, out=_o)
        np.sin(_o, out=_o)
        np.square(_o, out=_o)
        np.multiply(_o, 589000, out=_o)
        np.divide(_o, 13, out=_o)
    return out


def velocity_m1(t, *, out=None):
    """Velocity of the motor-side mass m1. Specialized to scene 'overhead_crane_50t'. Eq (1), (13).

    Parameters
    ----------
    t : array_like
        time since the brake was applied [s], >= 0; served from 0.0 to 1e7
    out : ndarray, optional
        float64 array of the broadcast shape; the result is written into it and returned.

    Returns
    -------
    ndarray
        [m/s], broadcast over the arguments.
    """
    if (out is None
            and (type(t) in (float, int) or type(t) is np.float64)):
        if (0.0 <= t <= 1e7):
            try:    # a failed check or a math error: the array path decides
                return np.float64(-175/572*t - 0.1933473889602708*math.sin(26.628760937957836*t) + 6004799503160661/4503599627370496)
            except (ArithmeticError, ValueError):
                pass
    t = _checked('t', t, 'nonnegative', 'time since the brake was applied, s', (0.0, 1e7))
    shape = _broadcast(t=t)
    if out is None and not shape:
        return -175/572*t - 0.1933473889602708*np.sin(26.628760937957836*t) + 6004799503160661/4503599627370496
    out = _out(out, shape)
    for _o, (t,) in _spans(out, shape, t):
        np.multiply(t, -175, out=_o)
        np.divide(_o, 572, out=_o)
        _w0 = np.empty_like(_o)
        np.multiply(t, 26.628760937957836, out=_w0)
        np.sin(_w0, out=_w0)
        np.multiply(_w0, -0.1933473889602708, out=_w0)
        np.add(_o, _w0, out=_o)
        np.add(_o, 6004799503160661/4503599627370496, out=_o)
    return out


def velocity_m2(t, *, out=None):
    """Velocity of the crane-side mass m2. Specialized to scene 'overhead_crane_50t'. Eq (2), (13).

    Parameters
    ----------
    t : array_like
        time since the brake was applied [s], >= 0; served from 0.0 to 1e7
    out : ndarray, optional
        float64 array of the broadcast shape; the result is written into it and returned.

    Returns
    -------
    ndarray
        [m/s], broadcast over the arguments.
    """
    if (out is None
            and (type(t) in (float, int) or type(t) is np.float64)):
        if (0.0 <= t <= 1e7):
            try:    # a failed check or a math error: the array path decides
                return np.float64(-175/572*t + 0.007733895558410831*math.sin(26.628760937957836*t) + 6004799503160661/4503599627370496)
            except (ArithmeticError, ValueError):
                pass
    t = _checked('t', t, 'nonnegative', 'time since the brake was applied, s', (0.0, 1e7))
    shape = _broadcast(t=t)
    if out is None and not shape:
        return -175/572*t + 0.007733895558410831*np.sin(26.628760937957836*t) + 6004799503160661/4503599627370496
    out = _out(out, shape)
    for _o, (t,) in _spans(out, shape, t):
        np.multiply(t, -175, out=_o)
        np.divide(_o, 572, out=_o)
        _w0 = np.empty_like(_o)
        np.multiply(t, 26.628760937957836, out=_w0)
        np.sin(_w0, out=_w0)
        np.multiply(_w0, 0.007733895558410831, out=_w0)
        np.add(_o, _w0, out=_o)
        np.add(_o, 6004799503160661/4503599627370496, out=_o)
    return out
