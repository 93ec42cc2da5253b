"""Numeric functions for derivation 'drum_drive'. Generated; do not edit.

Source: crane_sym.derivations.drum_drive (paper 004_f118c513e0426caf.txt:
Dynamic model of a drive with a driving drum).
Specialized to scene 'drum_drive_example' (Driving drum of a closed-rope installation: start under a pulsating load): outputs pulsating_force; folded in: I1 = 13.0 kg*m^2, I2 = 3.0 kg*m^2, I3 = 50.0 kg*m^2, C1 = 20000.0 N*m/rad, C2 = 50000.0 N*m/rad, C_y = 20000000.0 N/m, C_t = 50000.0 N/m, C_z = 50000.0 N/m, q = 2.4 kg/m, L = 600.0 m, D = 0.5 m, M0 = 440.0 N*m, F0 = 20000.0 N, F1 = 21760.0 N, F2 = 20000.0 N, mu = 0.2 1, alpha = 3.141592653589793 rad, F1_t = 1200.0 N, F2_t = 1200.0 N, F3_t = 600.0 N, F4_t = 600.0 N, K1 = 800.0 N, K2 = 800.0 N, K3 = 400.0 N, K4 = 400.0 N, t_3 = 3.0 s.
Equations: (21).
Printed by SymPy 1.14.0 with crane_sym 0.1.0; regenerate with `crane-sym generate --scene drum_drive_example --out <folder>`.

Functions and argument order:
    pulsating_force(t) -> [N]    eq (21)
"""

import math

import numpy as np

__all__ = ['pulsating_force']

SCENE_NAME = 'drum_drive_example'
SCENE_TITLE = 'Driving drum of a closed-rope installation: start under a pulsating load'


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


def pulsating_force(t, *, out=None):
    """Pulsating load F'(t) of (21), as printed. Specialized to scene 'drum_drive_example'. Eq (21).

    Parameters
    ----------
    t : array_like
        time from the start of the drive [s], >= 0; served from 0.0 to 2e7
    out : ndarray, optional
        float64 array of the broadcast shape; the result is written into it and returned.

    Returns
    -------
    ndarray
        [N], broadcast over the arguments.
    """
    if (out is None
            and (type(t) in (float, int) or type(t) is np.float64)):
        if (0.0 <= t <= 2e7):
            try:    # a failed check or a math error: the array path decides
                x0 = math.sin(1.0471975511965979*t)
                return np.float64(450*x0 - 150*abs(3*x0 - 2) + 300)
            except (ArithmeticError, ValueError):
                pass
    t = _checked('t', t, 'nonnegative', 'time from the start of the drive, s', (0.0, 2e7))
    shape = _broadcast(t=t)
    if out is None and not shape:
        x0 = np.sin(1.0471975511965979*t)
        return 450*x0 - 150*abs(3*x0 - 2) + 300
    out = _out(out, shape)
    for _o, (t,) in _spans(out, shape, t):
        x0 = np.sin(1.0471975511965979*t)
        np.multiply(x0, 3, out=_o)
        np.add(_o, -2, out=_o)
        np.abs(_o, out=_o)
        np.multiply(_o, -150, out=_o)
        _w0 = np.empty_like(_o)
        np.multiply(x0, 450, out=_w0)
        np.add(_o, _w0, out=_o)
        np.add(_o, 300, out=_o)
    return out
