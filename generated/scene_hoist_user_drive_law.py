"""Numeric functions for derivation 'hoist_startup'. Generated; do not edit.

Source: crane_sym.derivations.hoist_startup (paper 002_f8509f3826f601de.txt:
Duhamel's integral for the start-up of a crane hoist: rope loads and dynamic factors).
Drive law of scene 'hoist_user_drive_law' (Hoist start-up with a jerk-limited 3-piece drive law, lifting from weight), from_weight:
a(t) [m/s^2] = [0, 1/4): 2*t; [1/4, 1): 1/2; [1, 5/4): 5/2 - 2*t; 0 elsewhere.
Folded in (SI): m1 = 2000 kg, m2 = 8000 kg, C = 1000000 N/m, g = 981/100 m/s^2.
Equations: (1), (2), (15), (18), (23), (24), (25), (27), (28), (31), (57).
Printed by SymPy 1.14.0 with crane_sym 0.1.0; regenerate with `crane-sym generate --scene hoist_user_drive_law --out <folder>`.

Functions and argument order:
    drive_acceleration(t) -> [m/s^2]    eq (28), (31)
    drive_speed(t) -> [m/s]    eq (28), (31)
    relative_forcing(t) -> [m/s^2]    eq (2), (31)
    rope_stretch(t) -> [m]    eq (15), (23)
    rope_stretch_rate(t) -> [m/s]    eq (18), (23)
    rope_force(t) -> [N]    eq (24)
    dynamic_coefficient(t) -> [1]    eq (25), (27)
    load_acceleration(t) -> [m/s^2]    eq (1), (57)
"""

import numpy as np

__all__ = ['drive_acceleration', 'drive_speed', 'relative_forcing', 'rope_stretch', 'rope_stretch_rate', 'rope_force', 'dynamic_coefficient', 'load_acceleration']

SCENE_NAME = 'hoist_user_drive_law'
SCENE_TITLE = 'Hoist start-up with a jerk-limited 3-piece drive law, lifting from weight'


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


def _selector(mask):
    """The flat positions where ``mask`` (1-D bool) holds: None if none, a
    slice if they are contiguous, else an index array."""
    n = int(np.count_nonzero(mask))
    if n == 0:
        return None
    first = int(np.argmax(mask))
    if n == mask.size or mask[first:first + n].all():
        return slice(first, first + n)
    return np.flatnonzero(mask)


def _cells(shape, choices):
    """Selectors over the flattened broadcast ``shape``, one per combination of
    branches: ``choices`` lists, per piecewise, its conditions in order (the
    last branch, the rest, left out); a point takes the first branch whose
    condition holds. Combinations in row-major order (the first piecewise
    varies slowest)."""
    size = int(np.prod(shape, dtype=np.int64))
    cells = [np.ones(size, dtype=bool)]
    for conditions in choices:
        rest = np.ones(size, dtype=bool)
        branches = []
        for condition in conditions:
            mask = np.broadcast_to(condition, shape).reshape(-1) & rest
            rest &= ~mask
            branches.append(mask)
        branches.append(rest)
        cells = [cell & branch for cell in cells for branch in branches]
    return [_selector(cell) for cell in cells]


def _at(where, shape, *values):
    """``values`` on the points ``where`` (a selector of ``_cells``): arrays
    broadcast to ``shape``, flattened and selected; scalars as they are."""
    return tuple(v if np.ndim(v) == 0 else np.broadcast_to(v, shape).reshape(-1)[where]
                 for v in values)


def _put(out, where, value):
    """Write ``value`` into ``out`` at the flat positions ``where``."""
    if out.flags.c_contiguous:
        out.reshape(-1)[where] = value
    else:
        out.flat[where] = value


def _blocks(where, size=16384):
    """``where`` (a selector of ``_cells``) in pieces of at most ``size``
    points: a cell's temporaries then stay in the cache and below the
    allocator's mmap threshold, so a call does not page-fault on every new
    array; none for an empty cell."""
    if where is None:
        return ()
    if isinstance(where, slice):
        return [slice(i, min(i + size, where.stop)) for i in range(where.start, where.stop, size)]
    return [where[i:i + size] for i in range(0, where.size, size)]


def drive_acceleration(t, *, out=None):
    """Drive acceleration a(t) of the scene's law. Eq (28), (31).

    Parameters
    ----------
    t : array_like
        time from the start of the drive [s], >= 0; served from 0.0 to 2e6
    out : ndarray, optional
        float64 array of the broadcast shape; the result is written into it and returned.

    Returns
    -------
    ndarray
        [m/s^2], broadcast over the arguments.
    """
    t = _checked('t', t, 'nonnegative', 'time from the start of the drive, s', (0.0, 2e6))
    shape = _broadcast(t=t)
    if out is None and not shape:      # one point: its own branch only
        return (2*t if np.less(t, 1/4) else 1/2 if np.less(t, 1) else 5/2 - 2*t if np.less(t, 5/4) else 0)
    out = _out(out, shape)
    cells = _cells(shape, [[np.less(t, 1/4), np.less(t, 1), np.less(t, 5/4)]])
    for part in _blocks(cells[0]):
        t_, = _at(part, shape, t)
        _put(out, part, 2*t_)
    for part in _blocks(cells[1]):
        _put(out, part, 1/2)
    for part in _blocks(cells[2]):
        t_, = _at(part, shape, t)
        _put(out, part, 5/2 - 2*t_)
    for part in _blocks(cells[3]):
        _put(out, part, 0)
    return out


def drive_speed(t, *, out=None):
    """Drive speed v(t), the integral of a(t) (rigid hoist). Eq (28), (31).

    Parameters
    ----------
    t : array_like
        time from the start of the drive [s], >= 0; served from 0.0 to 2e6
    out : ndarray, optional
        float64 array of the broadcast shape; the result is written into it and returned.

    Returns
    -------
    ndarray
        [m/s], broadcast over the arguments.
    """
    t = _checked('t', t, 'nonnegative', 'time from the start of the drive, s', (0.0, 2e6))
    shape = _broadcast(t=t)
    if out is None and not shape:      # one point: its own branch only
        return (t**2 if np.less(t, 1/4) else (1/2)*t - 1/16 if np.less(t, 1) else -t**2 + (5/2)*t - 17/16 if np.less(t, 5/4) else 1/2)
    out = _out(out, shape)
    cells = _cells(shape, [[np.less(t, 1/4), np.less(t, 1), np.less(t, 5/4)]])
    for part in _blocks(cells[0]):
        t_, = _at(part, shape, t)
        _put(out, part, t_**2)
    for part in _blocks(cells[1]):
        t_, = _at(part, shape, t)
        _put(out, part, (1/2)*t_ - 1/16)
    for part in _blocks(cells[2]):
        t_, = _at(part, shape, t)
        _put(out, part, -t_**2 + (5/2)*t_ - 17/16)
    for part in _blocks(cells[3]):
        _put(out, part, 1/2)
    return out


def relative_forcing(t, *, out=None):
    """Load S(t) = P/m1 + Q/m2 of the stretch equation, lifting from weight. Eq (2), (31).

    Parameters
    ----------
    t : array_like
        time from the start of the drive [s], >= 0; served from 0.0 to 2e6
    out : ndarray, optional
        float64 array of the broadcast shape; the result is written into it and returned.

    Returns
    -------
    ndarray
        [m/s^2], broadcast over the arguments.
    """
    t = _checked('t', t, 'nonnegative', 'time from the start of the drive, s', (0.0, 2e6))
    shape = _broadcast(t=t)
    if out is None and not shape:      # one point: its own branch only
        return (10*t + 981/20 if np.less(t, 1/4) else 1031/20 if np.less(t, 1) else 1231/20 - 10*t if np.less(t, 5/4) else 981/20)
    out = _out(out, shape)
    cells = _cells(shape, [[np.less(t, 1/4), np.less(t, 1), np.less(t, 5/4)]])
    for part in _blocks(cells[0]):
        t_, = _at(part, shape, t)
        _put(out, part, 10*t_ + 981/20)
    for part in _blocks(cells[1]):
        _put(out, part, 1031/20)
    for part in _blocks(cells[2]):
        t_, = _at(part, shape, t)
        _put(out, part, 1231/20 - 10*t_)
    for part in _blocks(cells[3]):
        _put(out, part, 981/20)
    return out


def rope_stretch(t, *, out=None):
    """Rope stretch x(t) = x1 - x2 by Duhamel's integral, lifting from weight. Eq (15), (23).

    Parameters
    ----------
    t : array_like
        time from the start of the drive [s], >= 0; served from 0.0 to 2e6
    out : ndarray, optional
        float64 array of the broadcast shape; the result is written into it and returned.

    Returns
    -------
    ndarray
        [m], broadcast over the arguments.
    """
    t = _checked('t', t, 'nonnegative', 'time from the start of the drive, s', (0.0, 2e6))
    shape = _broadcast(t=t)
    if out is None and not shape:      # one point: its own branch only
        return (981/12500 - 2/3125*_sin_remainder(25*t, 1) if np.less(t, 1/4) else 1031/12500 - 2.1237622053565318e-05*np.cos(25*t - 25/8) if np.less(t, 1) else -2.1237622053565318e-05*np.cos(25*t - 25/8) + (2/3125)*_sin_remainder(25*t - 25, 1) + 1031/12500 if np.less(t, 5/4) else 981/12500 - 2.81703877964031e-06*np.sin(25*t - 125/8))
    out = _out(out, shape)
    cells = _cells(shape, [[np.less(t, 1/4), np.less(t, 1), np.less(t, 5/4)]])
    for part in _blocks(cells[0]):
        t_, = _at(part, shape, t)
        _put(out, part, 981/12500 - 2/3125*_sin_remainder(25*t_, 1))
    for part in _blocks(cells[1]):
        t_, = _at(part, shape, t)
        _put(out, part, 1031/12500 - 2.1237622053565318e-05*np.cos(25*t_ - 25/8))
    for part in _blocks(cells[2]):
        t_, = _at(part, shape, t)
        v0 = 25*t_
        _put(out, part, -2.1237622053565318e-05*np.cos(v0 - 25/8) + (2/3125)*_sin_remainder(v0 - 25, 1) + 1031/12500)
    for part in _blocks(cells[3]):
        t_, = _at(part, shape, t)
        _put(out, part, 981/12500 - 2.81703877964031e-06*np.sin(25*t_ - 125/8))
    return out


def rope_stretch_rate(t, *, out=None):
    """Stretch rate dx/dt, lifting from weight. Eq (18), (23).

    Parameters
    ----------
    t : array_like
        time from the start of the drive [s], >= 0; served from 0.0 to 2e6
    out : ndarray, optional
        float64 array of the broadcast shape; the result is written into it and returned.

    Returns
    -------
    ndarray
        [m/s], broadcast over the arguments.
    """
    t = _checked('t', t, 'nonnegative', 'time from the start of the drive, s', (0.0, 2e6))
    shape = _broadcast(t=t)
    if out is None and not shape:      # one point: its own branch only
        return ((4/125)*np.sin((25/2)*t)**2 if np.less(t, 1/4) else 0.0005309405513391329*np.sin(25*t - 25/8) if np.less(t, 1) else -4/125*np.sin((25/2)*t - 25/2)**2 + 0.0005309405513391329*np.sin(25*t - 25/8) if np.less(t, 5/4) else -7.042596949100774e-05*np.cos(25*t - 125/8))
    out = _out(out, shape)
    cells = _cells(shape, [[np.less(t, 1/4), np.less(t, 1), np.less(t, 5/4)]])
    for part in _blocks(cells[0]):
        t_, = _at(part, shape, t)
        _put(out, part, (4/125)*np.sin((25/2)*t_)**2)
    for part in _blocks(cells[1]):
        t_, = _at(part, shape, t)
        _put(out, part, 0.0005309405513391329*np.sin(25*t_ - 25/8))
    for part in _blocks(cells[2]):
        t_, = _at(part, shape, t)
        _put(out, part, -4/125*np.sin((25/2)*t_ - 25/2)**2 + 0.0005309405513391329*np.sin(25*t_ - 25/8))
    for part in _blocks(cells[3]):
        t_, = _at(part, shape, t)
        _put(out, part, -7.042596949100774e-05*np.cos(25*t_ - 125/8))
    return out


def rope_force(t, *, out=None):
    """Rope force C x(t), lifting from weight. Eq (24).

    Parameters
    ----------
    t : array_like
        time from the start of the drive [s], >= 0; served from 0.0 to 2e6
    out : ndarray, optional
        float64 array of the broadcast shape; the result is written into it and returned.

    Returns
    -------
    ndarray
        [N], broadcast over the arguments.
    """
    t = _checked('t', t, 'nonnegative', 'time from the start of the drive, s', (0.0, 2e6))
    shape = _broadcast(t=t)
    if out is None and not shape:      # one point: its own branch only
        return (78480 - 640*_sin_remainder(25*t, 1) if np.less(t, 1/4) else 82480 - 21.237622053565318*np.cos(25*t - 25/8) if np.less(t, 1) else -21.237622053565318*np.cos(25*t - 25/8) + 640*_sin_remainder(25*t - 25, 1) + 82480 if np.less(t, 5/4) else 78480 - 2.81703877964031*np.sin(25*t - 125/8))
    out = _out(out, shape)
    cells = _cells(shape, [[np.less(t, 1/4), np.less(t, 1), np.less(t, 5/4)]])
    for part in _blocks(cells[0]):
        t_, = _at(part, shape, t)
        _put(out, part, 78480 - 640*_sin_remainder(25*t_, 1))
    for part in _blocks(cells[1]):
        t_, = _at(part, shape, t)
        _put(out, part, 82480 - 21.237622053565318*np.cos(25*t_ - 25/8))
    for part in _blocks(cells[2]):
        t_, = _at(part, shape, t)
        v0 = 25*t_
        _put(out, part, -21.237622053565318*np.cos(v0 - 25/8) + 640*_sin_remainder(v0 - 25, 1) + 82480)
    for part in _blocks(cells[3]):
        t_, = _at(part, shape, t)
        _put(out, part, 78480 - 2.81703877964031*np.sin(25*t_ - 125/8))
    return out


def dynamic_coefficient(t, *, out=None):
    """Dynamic coefficient K_din(t), lifting from weight. Eq (25), (27).

    Parameters
    ----------
    t : array_like
        time from the start of the drive [s], >= 0; served from 0.0 to 2e6
    out : ndarray, optional
        float64 array of the broadcast shape; the result is written into it and returned.

    Returns
    -------
    ndarray
        [1], broadcast over the arguments.
    """
    t = _checked('t', t, 'nonnegative', 'time from the start of the drive, s', (0.0, 2e6))
    shape = _broadcast(t=t)
    if out is None and not shape:      # one point: its own branch only
        return (1 - 8/981*_sin_remainder(25*t, 1) if np.less(t, 1/4) else 1031/981 - 0.0002706119018038394*np.cos(25*t - 25/8) if np.less(t, 1) else -0.0002706119018038394*np.cos(25*t - 25/8) + (8/981)*_sin_remainder(25*t - 25, 1) + 1031/981 if np.less(t, 5/4) else 1 - 3.589498954689488e-05*np.sin(25*t - 125/8))
    out = _out(out, shape)
    cells = _cells(shape, [[np.less(t, 1/4), np.less(t, 1), np.less(t, 5/4)]])
    for part in _blocks(cells[0]):
        t_, = _at(part, shape, t)
        _put(out, part, 1 - 8/981*_sin_remainder(25*t_, 1))
    for part in _blocks(cells[1]):
        t_, = _at(part, shape, t)
        _put(out, part, 1031/981 - 0.0002706119018038394*np.cos(25*t_ - 25/8))
    for part in _blocks(cells[2]):
        t_, = _at(part, shape, t)
        v0 = 25*t_
        _put(out, part, -0.0002706119018038394*np.cos(v0 - 25/8) + (8/981)*_sin_remainder(v0 - 25, 1) + 1031/981)
    for part in _blocks(cells[3]):
        t_, = _at(part, shape, t)
        _put(out, part, 1 - 3.589498954689488e-05*np.sin(25*t_ - 125/8))
    return out


def load_acceleration(t, *, out=None):
    """Load acceleration (C x - Q)/m2, lifting from weight. Eq (1), (57).

    Parameters
    ----------
    t : array_like
        time from the start of the drive [s], >= 0; served from 0.0 to 2e6
    out : ndarray, optional
        float64 array of the broadcast shape; the result is written into it and returned.

    Returns
    -------
    ndarray
        [m/s^2], broadcast over the arguments.
    """
    t = _checked('t', t, 'nonnegative', 'time from the start of the drive, s', (0.0, 2e6))
    shape = _broadcast(t=t)
    if out is None and not shape:      # one point: its own branch only
        return (-2/25*_sin_remainder(25*t, 1) if np.less(t, 1/4) else 1/2 - 0.0026547027566956646*np.cos(25*t - 25/8) if np.less(t, 1) else -0.0026547027566956646*np.cos(25*t - 25/8) + (2/25)*_sin_remainder(25*t - 25, 1) + 1/2 if np.less(t, 5/4) else -0.0003521298474550387*np.sin(25*t - 125/8))
    out = _out(out, shape)
    cells = _cells(shape, [[np.less(t, 1/4), np.less(t, 1), np.less(t, 5/4)]])
    for part in _blocks(cells[0]):
        t_, = _at(part, shape, t)
        _put(out, part, -2/25*_sin_remainder(25*t_, 1))
    for part in _blocks(cells[1]):
        t_, = _at(part, shape, t)
        _put(out, part, 1/2 - 0.0026547027566956646*np.cos(25*t_ - 25/8))
    for part in _blocks(cells[2]):
        t_, = _at(part, shape, t)
        v0 = 25*t_
        _put(out, part, -0.0026547027566956646*np.cos(v0 - 25/8) + (2/25)*_sin_remainder(v0 - 25, 1) + 1/2)
    for part in _blocks(cells[3]):
        t_, = _at(part, shape, t)
        _put(out, part, -0.0003521298474550387*np.sin(25*t_ - 125/8))
    return out
