"""Numeric functions for derivation 'travel_braking'. Generated; do not edit.

Source: crane_sym.derivations.travel_braking (paper 000_4ef6efc8a81a3b06.txt:
Dynamic loads when the travel mechanism of an overhead crane brakes).
Equations: (1), (2), (6), (13), (14).
Printed by SymPy 1.14.0 with crane_sym 0.1.0; regenerate with `crane-sym generate`.

Functions and argument order:
    natural_frequency(m1, m2, c) -> [rad/s]    eq (6)
    relative_displacement(t, m1, m2, c, P_t, W) -> [m]    eq (13)
    elastic_force(t, m1, m2, c, P_t, W) -> [N]    eq (14)
    peak_elastic_force(m1, m2, P_t, W) -> [N]    eq (14)
    peak_time(m1, m2, c) -> [s]    eq (6), (14)
    rigid_link_force(m1, m2, P_t, W) -> [N]    eq (14)
    velocity_m1(t, m1, m2, c, P_t, W, v0) -> [m/s]    eq (1), (13)
    velocity_m2(t, m1, m2, c, P_t, W, v0) -> [m/s]    eq (2), (13)
"""

import math

import numpy as np

__all__ = ['natural_frequency', 'relative_displacement', 'elastic_force', 'peak_elastic_force', 'peak_time', 'rigid_link_force', 'velocity_m1', 'velocity_m2']


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


def _into(out, shape, result):
    """``result``, or copied into ``out`` when the caller gives a buffer."""
    if out is None:
        return result
    out = _out(out, shape)
    np.copyto(out, result)
    return out


def _two_product(a, b):
    """a*b as an unevaluated sum p + e of two doubles, exactly (Dekker)."""
    p = a * b
    a_hi = a * 134217729.0
    a_hi = a_hi - (a_hi - a)
    b_hi = b * 134217729.0
    b_hi = b_hi - (b_hi - b)
    a_lo, b_lo = a - a_hi, b - b_hi
    return p, ((a_hi * b_hi - p) + a_hi * b_lo + a_lo * b_hi) + a_lo * b_lo


def _diff_of_products(a, b, c, d):
    """a*b - c*d to within a few ulp, even when the products nearly cancel."""
    p, p_err = _two_product(a, b)
    q, q_err = _two_product(c, d)
    return (p - q) + (p_err - q_err)


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


def natural_frequency(m1, m2, c, *, out=None):
    """Natural frequency p of the relative motion. Eq (6).

    Parameters
    ----------
    m1 : array_like
        reduced mass of the rotating drive parts (rotor, motor and brake couplings) [kg], > 0; served from 0.0001 to 1e12
    m2 : array_like
        reduced mass of the crane or trolley (translating and rotating parts, wheels) [kg], > 0; served from 0.001 to 1e12
    c : array_like
        reduced stiffness of the transmission (mainly shafts) [N/m], > 0; served from 0.1 to 1e15
    out : ndarray, optional
        float64 array of the broadcast shape; the result is written into it and returned.

    Returns
    -------
    ndarray
        [rad/s], broadcast over the arguments.
    """
    if (out is None
            and (type(m1) in (float, int) or type(m1) is np.float64)
            and (type(m2) in (float, int) or type(m2) is np.float64)
            and (type(c) in (float, int) or type(c) is np.float64)):
        if (0.0001 <= m1 <= 1e12 and 0.001 <= m2 <= 1e12 and 0.1 <= c <= 1e15):
            try:    # a failed check or a math error: the array path decides
                return np.float64(math.sqrt(c)*math.sqrt(m1 + m2)/(math.sqrt(m1)*math.sqrt(m2)))
            except (ArithmeticError, ValueError):
                pass
    m1 = _checked('m1', m1, 'positive', 'reduced mass of the rotating drive parts (rotor, motor and brake couplings), kg', (0.0001, 1e12))
    m2 = _checked('m2', m2, 'positive', 'reduced mass of the crane or trolley (translating and rotating parts, wheels), kg', (0.001, 1e12))
    c  = _checked('c', c, 'positive', 'reduced stiffness of the transmission (mainly shafts), N/m', (0.1, 1e15))
    shape = _broadcast(m1=m1, m2=m2, c=c)
    return _into(out, shape, np.sqrt(c)*np.sqrt(m1 + m2)/(np.sqrt(m1)*np.sqrt(m2)))


def relative_displacement(t, m1, m2, c, P_t, W, *, out=None):
    """Stretch x2 - x1 of the elastic link. Eq (13).

    Parameters
    ----------
    t : array_like
        time since the brake was applied [s], >= 0; served from 0.0 to 1e7
    m1 : array_like
        reduced mass of the rotating drive parts (rotor, motor and brake couplings) [kg], > 0; served from 0.0001 to 1e12
    m2 : array_like
        reduced mass of the crane or trolley (translating and rotating parts, wheels) [kg], > 0; served from 0.001 to 1e12
    c : array_like
        reduced stiffness of the transmission (mainly shafts) [N/m], > 0; served from 0.1 to 1e15
    P_t : array_like
        braking force [N], > 0; served from 0.001 to 1e12
    W : array_like
        static travel resistance [N], >= 0; served from 0.0 to 1e11
    out : ndarray, optional
        float64 array of the broadcast shape; the result is written into it and returned.

    Returns
    -------
    ndarray
        [m], broadcast over the arguments.
    """
    if (out is None
            and (type(t) in (float, int) or type(t) is np.float64)
            and (type(m1) in (float, int) or type(m1) is np.float64)
            and (type(m2) in (float, int) or type(m2) is np.float64)
            and (type(c) in (float, int) or type(c) is np.float64)
            and (type(P_t) in (float, int) or type(P_t) is np.float64)
            and (type(W) in (float, int) or type(W) is np.float64)):
        if (0.0 <= t <= 1e7 and 0.0001 <= m1 <= 1e12 and 0.001 <= m2 <= 1e12 and 0.1 <= c <= 1e15
                and 0.001 <= P_t <= 1e12 and 0.0 <= W <= 1e11):
            try:    # a failed check or a math error: the array path decides
                x0 = m1 + m2
                k0 = (1/2)*math.sqrt(c*x0/(m1*m2))
                k1 = -2*_diff_of_products(W, m1, P_t, m2)/(c*x0)
                return np.float64(k1*math.sin(k0*t)**2)
            except (ArithmeticError, ValueError):
                pass
    t   = _checked('t', t, 'nonnegative', 'time since the brake was applied, s', (0.0, 1e7))
    m1  = _checked('m1', m1, 'positive', 'reduced mass of the rotating drive parts (rotor, motor and brake couplings), kg', (0.0001, 1e12))
    m2  = _checked('m2', m2, 'positive', 'reduced mass of the crane or trolley (translating and rotating parts, wheels), kg', (0.001, 1e12))
    c   = _checked('c', c, 'positive', 'reduced stiffness of the transmission (mainly shafts), N/m', (0.1, 1e15))
    P_t = _checked('P_t', P_t, 'positive', 'braking force, N', (0.001, 1e12))
    W   = _checked('W', W, 'nonnegative', 'static travel resistance, N', (0.0, 1e11))
    shape = _broadcast(t=t, m1=m1, m2=m2, c=c, P_t=P_t, W=W)
    x0 = m1 + m2
    k0 = (1/2)*np.sqrt(c*x0/(m1*m2))
    k1 = -2*_diff_of_products(W, m1, P_t, m2)/(c*x0)
    if out is None and not shape:
        return k1*np.sin(k0*t)**2
    out = _out(out, shape)
    for _o, (t, k0, k1) in _spans(out, shape, t, k0, k1):
        np.multiply(t, k0, out=_o)
        np.sin(_o, out=_o)
        np.square(_o, out=_o)
        np.multiply(_o, k1, out=_o)
    return out


def elastic_force(t, m1, m2, c, P_t, W, *, out=None):
    """Force F(t) in the elastic link. Eq (14).

    Parameters
    ----------
    t : array_like
        time since the brake was applied [s], >= 0; served from 0.0 to 1e7
    m1 : array_like
        reduced mass of the rotating drive parts (rotor, motor and brake couplings) [kg], > 0; served from 0.0001 to 1e12
    m2 : array_like
        reduced mass of the crane or trolley (translating and rotating parts, wheels) [kg], > 0; served from 0.001 to 1e12
    c : array_like
        reduced stiffness of the transmission (mainly shafts) [N/m], > 0; served from 0.1 to 1e15
    P_t : array_like
        braking force [N], > 0; served from 0.001 to 1e12
    W : array_like
        static travel resistance [N], >= 0; served from 0.0 to 1e11
    out : ndarray, optional
        float64 array of the broadcast shape; the result is written into it and returned.

    Returns
    -------
    ndarray
        [N], broadcast over the arguments.
    """
    if (out is None
            and (type(t) in (float, int) or type(t) is np.float64)
            and (type(m1) in (float, int) or type(m1) is np.float64)
            and (type(m2) in (float, int) or type(m2) is np.float64)
            and (type(c) in (float, int) or type(c) is np.float64)
            and (type(P_t) in (float, int) or type(P_t) is np.float64)
            and (type(W) in (float, int) or type(W) is np.float64)):
        if (0.0 <= t <= 1e7 and 0.0001 <= m1 <= 1e12 and 0.001 <= m2 <= 1e12 and 0.1 <= c <= 1e15
                and 0.001 <= P_t <= 1e12 and 0.0 <= W <= 1e11):
            try:    # a failed check or a math error: the array path decides
                x0 = m1 + m2
                k0 = (1/2)*math.sqrt(c*x0/(m1*m2))
                k1 = -2*_diff_of_products(W, m1, P_t, m2)/x0
                return np.float64(k1*math.sin(k0*t)**2)
            except (ArithmeticError, ValueError):
                pass
    t   = _checked('t', t, 'nonnegative', 'time since the brake was applied, s', (0.0, 1e7))
    m1  = _checked('m1', m1, 'positive', 'reduced mass of the rotating drive parts (rotor, motor and brake couplings), kg', (0.0001, 1e12))
    m2  = _checked('m2', m2, 'positive', 'reduced mass of the crane or trolley (translating and rotating parts, wheels), kg', (0.001, 1e12))
    c   = _checked('c', c, 'positive', 'reduced stiffness of the transmission (mainly shafts), N/m', (0.1, 1e15))
    P_t = _checked('P_t', P_t, 'positive', 'braking force, N', (0.001, 1e12))
    W   = _checked('W', W, 'nonnegative', 'static travel resistance, N', (0.0, 1e11))
    shape = _broadcast(t=t, m1=m1, m2=m2, c=c, P_t=P_t, W=W)
    x0 = m1 + m2
    k0 = (1/2)*np.sqrt(c*x0/(m1*m2))
    k1 = -2*_diff_of_products(W, m1, P_t, m2)/x0
    if out is None and not shape:
        return k1*np.sin(k0*t)**2
    out = _out(out, shape)
    for _o, (t, k0, k1) in _spans(out, shape, t, k0, k1):
        np.multiply(t, k0, out=_o)
        np.sin(_o, out=_o)
        np.square(_o, out=_o)
        np.multiply(_o, k1, out=_o)
    return out


def peak_elastic_force(m1, m2, P_t, W, *, out=None):
    """Extreme link force F_max = F(pi/p); a maximum when P_t*m2 > W*m1. Eq (14).

    Parameters
    ----------
    m1 : array_like
        reduced mass of the rotating drive parts (rotor, motor and brake couplings) [kg], > 0; served from 0.0001 to 1e12
    m2 : array_like
        reduced mass of the crane or trolley (translating and rotating parts, wheels) [kg], > 0; served from 0.001 to 1e12
    P_t : array_like
        braking force [N], > 0; served from 0.001 to 1e12
    W : array_like
        static travel resistance [N], >= 0; served from 0.0 to 1e11
    out : ndarray, optional
        float64 array of the broadcast shape; the result is written into it and returned.

    Returns
    -------
    ndarray
        [N], broadcast over the arguments.
    """
    if (out is None
            and (type(m1) in (float, int) or type(m1) is np.float64)
            and (type(m2) in (float, int) or type(m2) is np.float64)
            and (type(P_t) in (float, int) or type(P_t) is np.float64)
            and (type(W) in (float, int) or type(W) is np.float64)):
        if (0.0001 <= m1 <= 1e12 and 0.001 <= m2 <= 1e12 and 0.001 <= P_t <= 1e12
                and 0.0 <= W <= 1e11):
            try:    # a failed check or a math error: the array path decides
                return np.float64(2*_diff_of_products(P_t, m2, W, m1)/(m1 + m2))
            except (ArithmeticError, ValueError):
                pass
    m1  = _checked('m1', m1, 'positive', 'reduced mass of the rotating drive parts (rotor, motor and brake couplings), kg', (0.0001, 1e12))
    m2  = _checked('m2', m2, 'positive', 'reduced mass of the crane or trolley (translating and rotating parts, wheels), kg', (0.001, 1e12))
    P_t = _checked('P_t', P_t, 'positive', 'braking force, N', (0.001, 1e12))
    W   = _checked('W', W, 'nonnegative', 'static travel resistance, N', (0.0, 1e11))
    shape = _broadcast(m1=m1, m2=m2, P_t=P_t, W=W)
    return _into(out, shape, 2*_diff_of_products(P_t, m2, W, m1)/(m1 + m2))


def peak_time(m1, m2, c, *, out=None):
    """Time t_max = pi/p of the extreme link force. Eq (6), (14).

    Parameters
    ----------
    m1 : array_like
        reduced mass of the rotating drive parts (rotor, motor and brake couplings) [kg], > 0; served from 0.0001 to 1e12
    m2 : array_like
        reduced mass of the crane or trolley (translating and rotating parts, wheels) [kg], > 0; served from 0.001 to 1e12
    c : array_like
        reduced stiffness of the transmission (mainly shafts) [N/m], > 0; served from 0.1 to 1e15
    out : ndarray, optional
        float64 array of the broadcast shape; the result is written into it and returned.

    Returns
    -------
    ndarray
        [s], broadcast over the arguments.
    """
    if (out is None
            and (type(m1) in (float, int) or type(m1) is np.float64)
            and (type(m2) in (float, int) or type(m2) is np.float64)
            and (type(c) in (float, int) or type(c) is np.float64)):
        if (0.0001 <= m1 <= 1e12 and 0.001 <= m2 <= 1e12 and 0.1 <= c <= 1e15):
            try:    # a failed check or a math error: the array path decides
                return np.float64(3.141592653589793*math.sqrt(m1)*math.sqrt(m2)/(math.sqrt(c)*math.sqrt(m1 + m2)))
            except (ArithmeticError, ValueError):
                pass
    m1 = _checked('m1', m1, 'positive', 'reduced mass of the rotating drive parts (rotor, motor and brake couplings), kg', (0.0001, 1e12))
    m2 = _checked('m2', m2, 'positive', 'reduced mass of the crane or trolley (translating and rotating parts, wheels), kg', (0.001, 1e12))
    c  = _checked('c', c, 'positive', 'reduced stiffness of the transmission (mainly shafts), N/m', (0.1, 1e15))
    shape = _broadcast(m1=m1, m2=m2, c=c)
    return _into(out, shape, 3.141592653589793*np.sqrt(m1)*np.sqrt(m2)/(np.sqrt(c)*np.sqrt(m1 + m2)))


def rigid_link_force(m1, m2, P_t, W, *, out=None):
    """Link force of a rigid drive (c -> oo), the static reference. Eq (14).

    Parameters
    ----------
    m1 : array_like
        reduced mass of the rotating drive parts (rotor, motor and brake couplings) [kg], > 0; served from 0.0001 to 1e12
    m2 : array_like
        reduced mass of the crane or trolley (translating and rotating parts, wheels) [kg], > 0; served from 0.001 to 1e12
    P_t : array_like
        braking force [N], > 0; served from 0.001 to 1e12
    W : array_like
        static travel resistance [N], >= 0; served from 0.0 to 1e11
    out : ndarray, optional
        float64 array of the broadcast shape; the result is written into it and returned.

    Returns
    -------
    ndarray
        [N], broadcast over the arguments.
    """
    if (out is None
            and (type(m1) in (float, int) or type(m1) is np.float64)
            and (type(m2) in (float, int) or type(m2) is np.float64)
            and (type(P_t) in (float, int) or type(P_t) is np.float64)
            and (type(W) in (float, int) or type(W) is np.float64)):
        if (0.0001 <= m1 <= 1e12 and 0.001 <= m2 <= 1e12 and 0.001 <= P_t <= 1e12
                and 0.0 <= W <= 1e11):
            try:    # a failed check or a math error: the array path decides
                return np.float64(-_diff_of_products(W, m1, P_t, m2)/(m1 + m2))
            except (ArithmeticError, ValueError):
                pass
    m1  = _checked('m1', m1, 'positive', 'reduced mass of the rotating drive parts (rotor, motor and brake couplings), kg', (0.0001, 1e12))
    m2  = _checked('m2', m2, 'positive', 'reduced mass of the crane or trolley (translating and rotating parts, wheels), kg', (0.001, 1e12))
    P_t = _checked('P_t', P_t, 'positive', 'braking force, N', (0.001, 1e12))
    W   = _checked('W', W, 'nonnegative', 'static travel resistance, N', (0.0, 1e11))
    shape = _broadcast(m1=m1, m2=m2, P_t=P_t, W=W)
    return _into(out, shape, -_diff_of_products(W, m1, P_t, m2)/(m1 + m2))


def velocity_m1(t, m1, m2, c, P_t, W, v0, *, out=None):
    """Velocity of the motor-side mass m1. Eq (1), (13).

    Parameters
    ----------
    t : array_like
        time since the brake was applied [s], >= 0; served from 0.0 to 1e7
    m1 : array_like
        reduced mass of the rotating drive parts (rotor, motor and brake couplings) [kg], > 0; served from 0.0001 to 1e12
    m2 : array_like
        reduced mass of the crane or trolley (translating and rotating parts, wheels) [kg], > 0; served from 0.001 to 1e12
    c : array_like
        reduced stiffness of the transmission (mainly shafts) [N/m], > 0; served from 0.1 to 1e15
    P_t : array_like
        braking force [N], > 0; served from 0.001 to 1e12
    W : array_like
        static travel resistance [N], >= 0; served from 0.0 to 1e11
    v0 : array_like
        travel speed when braking begins [m/s], > 0; served from 1e-7 to 5e6
    out : ndarray, optional
        float64 array of the broadcast shape; the result is written into it and returned.

    Returns
    -------
    ndarray
        [m/s], broadcast over the arguments.
    """
    if (out is None
            and (type(t) in (float, int) or type(t) is np.float64)
            and (type(m1) in (float, int) or type(m1) is np.float64)
            and (type(m2) in (float, int) or type(m2) is np.float64)
            and (type(c) in (float, int) or type(c) is np.float64)
            and (type(P_t) in (float, int) or type(P_t) is np.float64)
            and (type(W) in (float, int) or type(W) is np.float64)
            and (type(v0) in (float, int) or type(v0) is np.float64)):
        if (0.0 <= t <= 1e7 and 0.0001 <= m1 <= 1e12 and 0.001 <= m2 <= 1e12 and 0.1 <= c <= 1e15
                and 0.001 <= P_t <= 1e12 and 0.0 <= W <= 1e11 and 1e-7 <= v0 <= 5e6):
            try:    # a failed check or a math error: the array path decides
                x0 = m1 + m2
                x1 = 1/m1
                k0 = -(P_t + W)/x0
                k1 = math.sqrt(c*x0*x1/m2)
                k2 = _diff_of_products(W, m1, P_t, m2)*math.sqrt(m2*x1/c)/x0**(3/2)
                return np.float64(k0*t + k2*math.sin(k1*t) + v0)
            except (ArithmeticError, ValueError):
                pass
    t   = _checked('t', t, 'nonnegative', 'time since the brake was applied, s', (0.0, 1e7))
    m1  = _checked('m1', m1, 'positive', 'reduced mass of the rotating drive parts (rotor, motor and brake couplings), kg', (0.0001, 1e12))
    m2  = _checked('m2', m2, 'positive', 'reduced mass of the crane or trolley (translating and rotating parts, wheels), kg', (0.001, 1e12))
    c   = _checked('c', c, 'positive', 'reduced stiffness of the transmission (mainly shafts), N/m', (0.1, 1e15))
    P_t = _checked('P_t', P_t, 'positive', 'braking force, N', (0.001, 1e12))
    W   = _checked('W', W, 'nonnegative', 'static travel resistance, N', (0.0, 1e11))
    v0  = _checked('v0', v0, 'positive', 'travel speed when braking begins, m/s', (1e-7, 5e6))
    shape = _broadcast(t=t, m1=m1, m2=m2, c=c, P_t=P_t, W=W, v0=v0)
    x0 = m1 + m2
    x1 = 1/(m1)
    k0 = -(P_t + W)/x0
    k1 = np.sqrt(c*x0*x1/m2)
    k2 = _diff_of_products(W, m1, P_t, m2)*np.sqrt(m2*x1/c)/x0**(3/2)
    if out is None and not shape:
        return k0*t + k2*np.sin(k1*t) + v0
    out = _out(out, shape)
    for _o, (t, v0, k0, k1, k2) in _spans(out, shape, t, v0, k0, k1, k2):
        np.multiply(t, k0, out=_o)
        _w0 = np.empty_like(_o)
        np.multiply(t, k1, out=_w0)
        np.sin(_w0, out=_w0)
        np.multiply(_w0, k2, out=_w0)
        np.add(_o, _w0, out=_o)
        np.add(_o, v0, out=_o)
    return out


def velocity_m2(t, m1, m2, c, P_t, W, v0, *, out=None):
    """Velocity of the crane-side mass m2. Eq (2), (13).

    Parameters
    ----------
    t : array_like
        time since the brake was applied [s], >= 0; served from 0.0 to 1e7
    m1 : array_like
        reduced mass of the rotating drive parts (rotor, motor and brake couplings) [kg], > 0; served from 0.0001 to 1e12
    m2 : array_like
        reduced mass of the crane or trolley (translating and rotating parts, wheels) [kg], > 0; served from 0.001 to 1e12
    c : array_like
        reduced stiffness of the transmission (mainly shafts) [N/m], > 0; served from 0.1 to 1e15
    P_t : array_like
        braking force [N], > 0; served from 0.001 to 1e12
    W : array_like
        static travel resistance [N], >= 0; served from 0.0 to 1e11
    v0 : array_like
        travel speed when braking begins [m/s], > 0; served from 1e-7 to 5e6
    out : ndarray, optional
        float64 array of the broadcast shape; the result is written into it and returned.

    Returns
    -------
    ndarray
        [m/s], broadcast over the arguments.
    """
    if (out is None
            and (type(t) in (float, int) or type(t) is np.float64)
            and (type(m1) in (float, int) or type(m1) is np.float64)
            and (type(m2) in (float, int) or type(m2) is np.float64)
            and (type(c) in (float, int) or type(c) is np.float64)
            and (type(P_t) in (float, int) or type(P_t) is np.float64)
            and (type(W) in (float, int) or type(W) is np.float64)
            and (type(v0) in (float, int) or type(v0) is np.float64)):
        if (0.0 <= t <= 1e7 and 0.0001 <= m1 <= 1e12 and 0.001 <= m2 <= 1e12 and 0.1 <= c <= 1e15
                and 0.001 <= P_t <= 1e12 and 0.0 <= W <= 1e11 and 1e-7 <= v0 <= 5e6):
            try:    # a failed check or a math error: the array path decides
                x0 = m1 + m2
                x1 = 1/m2
                k0 = -(P_t + W)/x0
                k1 = math.sqrt(c*x0*x1/m1)
                k2 = -_diff_of_products(W, m1, P_t, m2)*math.sqrt(m1*x1/c)/x0**(3/2)
                return np.float64(k0*t + k2*math.sin(k1*t) + v0)
            except (ArithmeticError, ValueError):
                pass
    t   = _checked('t', t, 'nonnegative', 'time since the brake was applied, s', (0.0, 1e7))
    m1  = _checked('m1', m1, 'positive', 'reduced mass of the rotating drive parts (rotor, motor and brake couplings), kg', (0.0001, 1e12))
    m2  = _checked('m2', m2, 'positive', 'reduced mass of the crane or trolley (translating and rotating parts, wheels), kg', (0.001, 1e12))
    c   = _checked('c', c, 'positive', 'reduced stiffness of the transmission (mainly shafts), N/m', (0.1, 1e15))
    P_t = _checked('P_t', P_t, 'positive', 'braking force, N', (0.001, 1e12))
    W   = _checked('W', W, 'nonnegative', 'static travel resistance, N', (0.0, 1e11))
    v0  = _checked('v0', v0, 'positive', 'travel speed when braking begins, m/s', (1e-7, 5e6))
    shape = _broadcast(t=t, m1=m1, m2=m2, c=c, P_t=P_t, W=W, v0=v0)
    x0 = m1 + m2
    x1 = 1/(m2)
    k0 = -(P_t + W)/x0
    k1 = np.sqrt(c*x0*x1/m1)
    k2 = -_diff_of_products(W, m1, P_t, m2)*np.sqrt(m1*x1/c)/x0**(3/2)
    if out is None and not shape:
        return k0*t + k2*np.sin(k1*t) + v0
    out = _out(out, shape)
    for _o, (t, v0, k0, k1, k2) in _spans(out, shape, t, v0, k0, k1, k2):
        np.multiply(t, k0, out=_o)
        _w0 = np.empty_like(_o)
        np.multiply(t, k1, out=_w0)
        np.sin(_w0, out=_w0)
        np.multiply(_w0, k2, out=_w0)
        np.add(_o, _w0, out=_o)
        np.add(_o, v0, out=_o)
    return out
