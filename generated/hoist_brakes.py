"""Numeric functions for derivation 'hoist_brakes'. Generated; do not edit.

Source: crane_sym.derivations.hoist_brakes (paper 001_544065b666a6bc39.txt:
Hoists with safety brakes: gearbox torque in an emergency stop).
Equations: (1), (2), (3), (4), (6), (7), Fig. 9.
Printed by SymPy 1.14.0 with crane_sym 0.1.0; regenerate with `crane-sym generate`.

Functions and argument order:
    relative_gearbox_torque_hoisting(MF, LF, BF_SB) -> [1]    eq (2), (4)
    relative_gearbox_torque_lowering(MF, LF, BF_SB) -> [1]    eq (2)
    peak_relative_gearbox_torque_hoisting(phi5, MF, LF, BF_SB) -> [1]    eq (2), (3)
    peak_relative_gearbox_torque_lowering(phi5, MF, LF, BF_SB) -> [1]    eq (2)
    service_brake_factor_hoisting(m_p, J1, J2, m_h, m_r, r, i_g, i_t, g, omega1, d_t) -> [1]    eq (6)
    service_brake_factor_lowering(m_p, J1, J2, m_h, m_r, r, i_g, i_t, g, omega1, d_t) -> [1]    eq (6)
    safety_brake_factor(m_p, J1, J2, m_h, m_r, r, i_g, i_t, g, omega1, d_t) -> [1]    eq (7)
    elastic_gearbox_torque_no_backlash(t, J1, J2, m_h, m_p, m_r, r, i_g, i_t, g, c, M_SB, t_SB) -> [1]    eq Fig. 9
    elastic_natural_frequency(J1, J2, m_h, m_p, r, i_g, i_t, c) -> [rad/s]    eq Fig. 9
    backlash_at_motor_shaft(delta, i_g) -> [rad]    eq Fig. 9
    rigid_hook_speed_hoisting(t, m_p, J1, J2, m_h, r, i_g, i_t, g, omega1, M_SB, M_BB, t_SB, t_BB) -> [m/s]    eq (1)
    rigid_stopping_time_hoisting(m_p, J1, J2, m_h, r, i_g, i_t, g, omega1, M_SB, M_BB, t_SB, t_BB) -> [s]    eq (1)
    rigid_hook_speed_lowering(t, m_p, J1, J2, m_h, r, i_g, i_t, g, omega1, M_SB, M_BB, t_SB, t_BB) -> [m/s]    eq (1)
    rigid_stopping_time_lowering(m_p, J1, J2, m_h, r, i_g, i_t, g, omega1, M_SB, M_BB, t_SB, t_BB) -> [s]    eq (1)
"""

import math

import numpy as np

__all__ = ['relative_gearbox_torque_hoisting', 'relative_gearbox_torque_lowering', 'peak_relative_gearbox_torque_hoisting', 'peak_relative_gearbox_torque_lowering', 'service_brake_factor_hoisting', 'service_brake_factor_lowering', 'safety_brake_factor', 'elastic_gearbox_torque_no_backlash', 'elastic_natural_frequency', 'backlash_at_motor_shaft', 'rigid_hook_speed_hoisting', 'rigid_stopping_time_hoisting', 'rigid_hook_speed_lowering', 'rigid_stopping_time_lowering']


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


def _required(value, what):
    """ValueError unless ``value`` > 0 at every point: a condition between
    arguments (``what``) without which the formula has no real value."""
    if not np.all(np.asarray(value) > 0):
        raise ValueError(f"the arguments must satisfy {what}")


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


def relative_gearbox_torque_hoisting(MF, LF, BF_SB, *, out=None):
    """Rigid drive, hoisting: gearbox-input torque over the rated static torque after the safety brakes act (motor torque lost). Eq (2), (4).

    Parameters
    ----------
    MF : array_like
        inertia factor J1/J [1], >= 0; served from 0.0 to 2e6
    LF : array_like
        load factor M_L/M_st [1], > 0; served from 5e-7 to 2e6
    BF_SB : array_like
        safety-brake factor M_SB/(i_g M_st) [1], > 0; served from 1e-6 to 4e6
    out : ndarray, optional
        float64 array of the broadcast shape; the result is written into it and returned.

    Returns
    -------
    ndarray
        [1], broadcast over the arguments.
    """
    if (out is None
            and (type(MF) in (float, int) or type(MF) is np.float64)
            and (type(LF) in (float, int) or type(LF) is np.float64)
            and (type(BF_SB) in (float, int) or type(BF_SB) is np.float64)):
        if (0.0 <= MF <= 2e6 and 5e-7 <= LF <= 2e6 and 1e-6 <= BF_SB <= 4e6):
            try:    # a failed check or a math error: the array path decides
                return np.float64(MF*(BF_SB + LF))
            except (ArithmeticError, ValueError):
                pass
    MF    = _checked('MF', MF, 'nonnegative', 'inertia factor J1/J, 1', (0.0, 2e6))
    LF    = _checked('LF', LF, 'positive', 'load factor M_L/M_st, 1', (5e-7, 2e6))
    BF_SB = _checked('BF_SB', BF_SB, 'positive', 'safety-brake factor M_SB/(i_g M_st), 1', (1e-6, 4e6))
    shape = _broadcast(MF=MF, LF=LF, BF_SB=BF_SB)
    return _into(out, shape, MF*(BF_SB + LF))


def relative_gearbox_torque_lowering(MF, LF, BF_SB, *, out=None):
    """Rigid drive, lowering: the same (negative when the brakes reverse it). Eq (2).

    Parameters
    ----------
    MF : array_like
        inertia factor J1/J [1], >= 0; served from 0.0 to 2e6
    LF : array_like
        load factor M_L/M_st [1], > 0; served from 5e-7 to 2e6
    BF_SB : array_like
        safety-brake factor M_SB/(i_g M_st) [1], > 0; served from 1e-6 to 4e6
    out : ndarray, optional
        float64 array of the broadcast shape; the result is written into it and returned.

    Returns
    -------
    ndarray
        [1], broadcast over the arguments.
    """
    if (out is None
            and (type(MF) in (float, int) or type(MF) is np.float64)
            and (type(LF) in (float, int) or type(LF) is np.float64)
            and (type(BF_SB) in (float, int) or type(BF_SB) is np.float64)):
        if (0.0 <= MF <= 2e6 and 5e-7 <= LF <= 2e6 and 1e-6 <= BF_SB <= 4e6):
            try:    # a failed check or a math error: the array path decides
                return np.float64(-MF*(BF_SB - LF))
            except (ArithmeticError, ValueError):
                pass
    MF    = _checked('MF', MF, 'nonnegative', 'inertia factor J1/J, 1', (0.0, 2e6))
    LF    = _checked('LF', LF, 'positive', 'load factor M_L/M_st, 1', (5e-7, 2e6))
    BF_SB = _checked('BF_SB', BF_SB, 'positive', 'safety-brake factor M_SB/(i_g M_st), 1', (1e-6, 4e6))
    shape = _broadcast(MF=MF, LF=LF, BF_SB=BF_SB)
    return _into(out, shape, -MF*(BF_SB - LF))


def peak_relative_gearbox_torque_hoisting(phi5, MF, LF, BF_SB, *, out=None):
    """Peak relative gearbox torque, hoisting, with the dynamic factor phi5. Eq (2), (3).

    Parameters
    ----------
    phi5 : array_like
        dynamic factor φ5 of EN 13001-2 [1], > 0; served from 1e-6 to 2e6
    MF : array_like
        inertia factor J1/J [1], >= 0; served from 0.0 to 2e6
    LF : array_like
        load factor M_L/M_st [1], > 0; served from 5e-7 to 2e6
    BF_SB : array_like
        safety-brake factor M_SB/(i_g M_st) [1], > 0; served from 1e-6 to 4e6
    out : ndarray, optional
        float64 array of the broadcast shape; the result is written into it and returned.

    Returns
    -------
    ndarray
        [1], broadcast over the arguments.
    """
    if (out is None
            and (type(phi5) in (float, int) or type(phi5) is np.float64)
            and (type(MF) in (float, int) or type(MF) is np.float64)
            and (type(LF) in (float, int) or type(LF) is np.float64)
            and (type(BF_SB) in (float, int) or type(BF_SB) is np.float64)):
        if (1e-6 <= phi5 <= 2e6 and 0.0 <= MF <= 2e6 and 5e-7 <= LF <= 2e6
                and 1e-6 <= BF_SB <= 4e6):
            try:    # a failed check or a math error: the array path decides
                x0 = LF*phi5
                return np.float64(BF_SB*MF*phi5 + LF + MF*x0 - x0)
            except (ArithmeticError, ValueError):
                pass
    phi5  = _checked('phi5', phi5, 'positive', 'dynamic factor φ5 of EN 13001-2, 1', (1e-6, 2e6))
    MF    = _checked('MF', MF, 'nonnegative', 'inertia factor J1/J, 1', (0.0, 2e6))
    LF    = _checked('LF', LF, 'positive', 'load factor M_L/M_st, 1', (5e-7, 2e6))
    BF_SB = _checked('BF_SB', BF_SB, 'positive', 'safety-brake factor M_SB/(i_g M_st), 1', (1e-6, 4e6))
    shape = _broadcast(phi5=phi5, MF=MF, LF=LF, BF_SB=BF_SB)
    x0 = LF*phi5
    return _into(out, shape, BF_SB*MF*phi5 + LF + MF*x0 - x0)


def peak_relative_gearbox_torque_lowering(phi5, MF, LF, BF_SB, *, out=None):
    """Peak relative gearbox torque, lowering, with the dynamic factor phi5. Eq (2).

    Parameters
    ----------
    phi5 : array_like
        dynamic factor φ5 of EN 13001-2 [1], > 0; served from 1e-6 to 2e6
    MF : array_like
        inertia factor J1/J [1], >= 0; served from 0.0 to 2e6
    LF : array_like
        load factor M_L/M_st [1], > 0; served from 5e-7 to 2e6
    BF_SB : array_like
        safety-brake factor M_SB/(i_g M_st) [1], > 0; served from 1e-6 to 4e6
    out : ndarray, optional
        float64 array of the broadcast shape; the result is written into it and returned.

    Returns
    -------
    ndarray
        [1], broadcast over the arguments.
    """
    if (out is None
            and (type(phi5) in (float, int) or type(phi5) is np.float64)
            and (type(MF) in (float, int) or type(MF) is np.float64)
            and (type(LF) in (float, int) or type(LF) is np.float64)
            and (type(BF_SB) in (float, int) or type(BF_SB) is np.float64)):
        if (1e-6 <= phi5 <= 2e6 and 0.0 <= MF <= 2e6 and 5e-7 <= LF <= 2e6
                and 1e-6 <= BF_SB <= 4e6):
            try:    # a failed check or a math error: the array path decides
                return np.float64(-BF_SB*MF*phi5 + LF*MF*phi5 - LF*phi5 + LF)
            except (ArithmeticError, ValueError):
                pass
    phi5  = _checked('phi5', phi5, 'positive', 'dynamic factor φ5 of EN 13001-2, 1', (1e-6, 2e6))
    MF    = _checked('MF', MF, 'nonnegative', 'inertia factor J1/J, 1', (0.0, 2e6))
    LF    = _checked('LF', LF, 'positive', 'load factor M_L/M_st, 1', (5e-7, 2e6))
    BF_SB = _checked('BF_SB', BF_SB, 'positive', 'safety-brake factor M_SB/(i_g M_st), 1', (1e-6, 4e6))
    shape = _broadcast(phi5=phi5, MF=MF, LF=LF, BF_SB=BF_SB)
    return _into(out, shape, -BF_SB*MF*phi5 + LF*MF*phi5 - LF*phi5 + LF)


def service_brake_factor_hoisting(m_p, J1, J2, m_h, m_r, r, i_g, i_t, g, omega1, d_t, *, out=None):
    """Coordinated brake factor (6) over the payload m_p, stopping from omega1 in d_t (hoisting). Eq (6).

    Parameters
    ----------
    m_p : array_like
        payload [kg], >= 0; served from 0.0 to 1e11
    J1 : array_like
        inertia of the motor shafts (rotors, brake discs, couplings), Table 1 [kg*m^2], > 0; served from 1e-6 to 2e8
    J2 : array_like
        inertia of the drum shafts, Table 1 [kg*m^2], > 0; served from 1e-12 to 5e9
    m_h : array_like
        mass of the hook (load-handling device) [kg], > 0; served from 1e-6 to 1e11
    m_r : array_like
        rated payload (Table 1: 52 t) [kg], > 0; served from 0.0001 to 1e11
    r : array_like
        drum radius [m], > 0; served from 1e-7 to 2e6
    i_g : array_like
        gear ratio of the gearbox [1], > 0; served from 5e-6 to 1e8
    i_t : array_like
        ratio of the rope tackle (8 falls, 2 drums: 4) [1], > 0; served from 1e-6 to 8e6
    g : array_like
        gravity [m/s^2], > 0; served from 9.8e-6 to 9.82e6
    omega1 : array_like
        motor angular speed before braking (Table 1: n1 = 1500 1/min) [rad/s], > 0; served from 1e-5 to 4e8
    d_t : array_like
        braking time [s], > 0; served from 1e-7 to 1e7
    out : ndarray, optional
        float64 array of the broadcast shape; the result is written into it and returned.

    Returns
    -------
    ndarray
        [1], broadcast over the arguments.
    """
    if (out is None
            and (type(m_p) in (float, int) or type(m_p) is np.float64)
            and (type(J1) in (float, int) or type(J1) is np.float64)
            and (type(J2) in (float, int) or type(J2) is np.float64)
            and (type(m_h) in (float, int) or type(m_h) is np.float64)
            and (type(m_r) in (float, int) or type(m_r) is np.float64)
            and (type(r) in (float, int) or type(r) is np.float64)
            and (type(i_g) in (float, int) or type(i_g) is np.float64)
            and (type(i_t) in (float, int) or type(i_t) is np.float64)
            and (type(g) in (float, int) or type(g) is np.float64)
            and (type(omega1) in (float, int) or type(omega1) is np.float64)
            and (type(d_t) in (float, int) or type(d_t) is np.float64)):
        if (0.0 <= m_p <= 1e11 and 1e-6 <= J1 <= 2e8 and 1e-12 <= J2 <= 5e9
                and 1e-6 <= m_h <= 1e11 and 0.0001 <= m_r <= 1e11 and 1e-7 <= r <= 2e6
                and 5e-6 <= i_g <= 1e8 and 1e-6 <= i_t <= 8e6 and 9.8e-6 <= g <= 9.82e6
                and 1e-5 <= omega1 <= 4e8 and 1e-7 <= d_t <= 1e7):
            try:    # a failed check or a math error: the array path decides
                x0 = d_t*g*r
                return np.float64(-(-J1*i_g*i_t*omega1 + m_h*x0 + m_p*x0)/(d_t*g*r*(m_h + m_r)))
            except (ArithmeticError, ValueError):
                pass
    m_p    = _checked('m_p', m_p, 'nonnegative', 'payload, kg', (0.0, 1e11))
    J1     = _checked('J1', J1, 'positive', 'inertia of the motor shafts (rotors, brake discs, couplings), Table 1, kg*m^2', (1e-6, 2e8))
    J2     = _checked('J2', J2, 'positive', 'inertia of the drum shafts, Table 1, kg*m^2', (1e-12, 5e9))
    m_h    = _checked('m_h', m_h, 'positive', 'mass of the hook (load-handling device), kg', (1e-6, 1e11))
    m_r    = _checked('m_r', m_r, 'positive', 'rated payload (Table 1: 52 t), kg', (0.0001, 1e11))
    r      = _checked('r', r, 'positive', 'drum radius, m', (1e-7, 2e6))
    i_g    = _checked('i_g', i_g, 'positive', 'gear ratio of the gearbox, 1', (5e-6, 1e8))
    i_t    = _checked('i_t', i_t, 'positive', 'ratio of the rope tackle (8 falls, 2 drums: 4), 1', (1e-6, 8e6))
    g      = _checked('g', g, 'positive', 'gravity, m/s^2', (9.8e-6, 9.82e6))
    omega1 = _checked('omega1', omega1, 'positive', 'motor angular speed before braking (Table 1: n1 = 1500 1/min), rad/s', (1e-5, 4e8))
    d_t    = _checked('d_t', d_t, 'positive', 'braking time, s', (1e-7, 1e7))
    shape = _broadcast(m_p=m_p, J1=J1, J2=J2, m_h=m_h, m_r=m_r, r=r, i_g=i_g, i_t=i_t, g=g,
                       omega1=omega1, d_t=d_t)
    x0 = d_t*g*r
    return _into(out, shape, -(-J1*i_g*i_t*omega1 + m_h*x0 + m_p*x0)/(d_t*g*r*(m_h + m_r)))


def service_brake_factor_lowering(m_p, J1, J2, m_h, m_r, r, i_g, i_t, g, omega1, d_t, *, out=None):
    """Coordinated brake factor (6) over the payload m_p, stopping from omega1 in d_t (lowering). Eq (6).

    Parameters
    ----------
    m_p : array_like
        payload [kg], >= 0; served from 0.0 to 1e11
    J1 : array_like
        inertia of the motor shafts (rotors, brake discs, couplings), Table 1 [kg*m^2], > 0; served from 1e-6 to 2e8
    J2 : array_like
        inertia of the drum shafts, Table 1 [kg*m^2], > 0; served from 1e-12 to 5e9
    m_h : array_like
        mass of the hook (load-handling device) [kg], > 0; served from 1e-6 to 1e11
    m_r : array_like
        rated payload (Table 1: 52 t) [kg], > 0; served from 0.0001 to 1e11
    r : array_like
        drum radius [m], > 0; served from 1e-7 to 2e6
    i_g : array_like
        gear ratio of the gearbox [1], > 0; served from 5e-6 to 1e8
    i_t : array_like
        ratio of the rope tackle (8 falls, 2 drums: 4) [1], > 0; served from 1e-6 to 8e6
    g : array_like
        gravity [m/s^2], > 0; served from 9.8e-6 to 9.82e6
    omega1 : array_like
        motor angular speed before braking (Table 1: n1 = 1500 1/min) [rad/s], > 0; served from 1e-5 to 4e8
    d_t : array_like
        braking time [s], > 0; served from 1e-7 to 1e7
    out : ndarray, optional
        float64 array of the broadcast shape; the result is written into it and returned.

    Returns
    -------
    ndarray
        [1], broadcast over the arguments.
    """
    if (out is None
            and (type(m_p) in (float, int) or type(m_p) is np.float64)
            and (type(J1) in (float, int) or type(J1) is np.float64)
            and (type(J2) in (float, int) or type(J2) is np.float64)
            and (type(m_h) in (float, int) or type(m_h) is np.float64)
            and (type(m_r) in (float, int) or type(m_r) is np.float64)
            and (type(r) in (float, int) or type(r) is np.float64)
            and (type(i_g) in (float, int) or type(i_g) is np.float64)
            and (type(i_t) in (float, int) or type(i_t) is np.float64)
            and (type(g) in (float, int) or type(g) is np.float64)
            and (type(omega1) in (float, int) or type(omega1) is np.float64)
            and (type(d_t) in (float, int) or type(d_t) is np.float64)):
        if (0.0 <= m_p <= 1e11 and 1e-6 <= J1 <= 2e8 and 1e-12 <= J2 <= 5e9
                and 1e-6 <= m_h <= 1e11 and 0.0001 <= m_r <= 1e11 and 1e-7 <= r <= 2e6
                and 5e-6 <= i_g <= 1e8 and 1e-6 <= i_t <= 8e6 and 9.8e-6 <= g <= 9.82e6
                and 1e-5 <= omega1 <= 4e8 and 1e-7 <= d_t <= 1e7):
            try:    # a failed check or a math error: the array path decides
                x0 = d_t*g*r
                return np.float64((J1*i_g*i_t*omega1 + m_h*x0 + m_p*x0)/(d_t*g*r*(m_h + m_r)))
            except (ArithmeticError, ValueError):
                pass
    m_p    = _checked('m_p', m_p, 'nonnegative', 'payload, kg', (0.0, 1e11))
    J1     = _checked('J1', J1, 'positive', 'inertia of the motor shafts (rotors, brake discs, couplings), Table 1, kg*m^2', (1e-6, 2e8))
    J2     = _checked('J2', J2, 'positive', 'inertia of the drum shafts, Table 1, kg*m^2', (1e-12, 5e9))
    m_h    = _checked('m_h', m_h, 'positive', 'mass of the hook (load-handling device), kg', (1e-6, 1e11))
    m_r    = _checked('m_r', m_r, 'positive', 'rated payload (Table 1: 52 t), kg', (0.0001, 1e11))
    r      = _checked('r', r, 'positive', 'drum radius, m', (1e-7, 2e6))
    i_g    = _checked('i_g', i_g, 'positive', 'gear ratio of the gearbox, 1', (5e-6, 1e8))
    i_t    = _checked('i_t', i_t, 'positive', 'ratio of the rope tackle (8 falls, 2 drums: 4), 1', (1e-6, 8e6))
    g      = _checked('g', g, 'positive', 'gravity, m/s^2', (9.8e-6, 9.82e6))
    omega1 = _checked('omega1', omega1, 'positive', 'motor angular speed before braking (Table 1: n1 = 1500 1/min), rad/s', (1e-5, 4e8))
    d_t    = _checked('d_t', d_t, 'positive', 'braking time, s', (1e-7, 1e7))
    shape = _broadcast(m_p=m_p, J1=J1, J2=J2, m_h=m_h, m_r=m_r, r=r, i_g=i_g, i_t=i_t, g=g,
                       omega1=omega1, d_t=d_t)
    x0 = d_t*g*r
    return _into(out, shape, (J1*i_g*i_t*omega1 + m_h*x0 + m_p*x0)/(d_t*g*r*(m_h + m_r)))


def safety_brake_factor(m_p, J1, J2, m_h, m_r, r, i_g, i_t, g, omega1, d_t, *, out=None):
    """Coordinated brake factor (7) over the payload m_p, stopping from omega1 in d_t (hoisting). Eq (7).

    Parameters
    ----------
    m_p : array_like
        payload [kg], >= 0; served from 0.0 to 1e11
    J1 : array_like
        inertia of the motor shafts (rotors, brake discs, couplings), Table 1 [kg*m^2], > 0; served from 1e-6 to 2e8
    J2 : array_like
        inertia of the drum shafts, Table 1 [kg*m^2], > 0; served from 1e-12 to 5e9
    m_h : array_like
        mass of the hook (load-handling device) [kg], > 0; served from 1e-6 to 1e11
    m_r : array_like
        rated payload (Table 1: 52 t) [kg], > 0; served from 0.0001 to 1e11
    r : array_like
        drum radius [m], > 0; served from 1e-7 to 2e6
    i_g : array_like
        gear ratio of the gearbox [1], > 0; served from 5e-6 to 1e8
    i_t : array_like
        ratio of the rope tackle (8 falls, 2 drums: 4) [1], > 0; served from 1e-6 to 8e6
    g : array_like
        gravity [m/s^2], > 0; served from 9.8e-6 to 9.82e6
    omega1 : array_like
        motor angular speed before braking (Table 1: n1 = 1500 1/min) [rad/s], > 0; served from 1e-5 to 4e8
    d_t : array_like
        braking time [s], > 0; served from 1e-7 to 1e7
    out : ndarray, optional
        float64 array of the broadcast shape; the result is written into it and returned.

    Returns
    -------
    ndarray
        [1], broadcast over the arguments.
    """
    if (out is None
            and (type(m_p) in (float, int) or type(m_p) is np.float64)
            and (type(J1) in (float, int) or type(J1) is np.float64)
            and (type(J2) in (float, int) or type(J2) is np.float64)
            and (type(m_h) in (float, int) or type(m_h) is np.float64)
            and (type(m_r) in (float, int) or type(m_r) is np.float64)
            and (type(r) in (float, int) or type(r) is np.float64)
            and (type(i_g) in (float, int) or type(i_g) is np.float64)
            and (type(i_t) in (float, int) or type(i_t) is np.float64)
            and (type(g) in (float, int) or type(g) is np.float64)
            and (type(omega1) in (float, int) or type(omega1) is np.float64)
            and (type(d_t) in (float, int) or type(d_t) is np.float64)):
        if (0.0 <= m_p <= 1e11 and 1e-6 <= J1 <= 2e8 and 1e-12 <= J2 <= 5e9
                and 1e-6 <= m_h <= 1e11 and 0.0001 <= m_r <= 1e11 and 1e-7 <= r <= 2e6
                and 5e-6 <= i_g <= 1e8 and 1e-6 <= i_t <= 8e6 and 9.8e-6 <= g <= 9.82e6
                and 1e-5 <= omega1 <= 4e8 and 1e-7 <= d_t <= 1e7):
            try:    # a failed check or a math error: the array path decides
                x0 = r**2
                return np.float64(omega1*(J2*i_t**2 + m_h*x0 + m_p*x0)/(d_t*g*i_g*i_t*r*(m_h + m_r)))
            except (ArithmeticError, ValueError):
                pass
    m_p    = _checked('m_p', m_p, 'nonnegative', 'payload, kg', (0.0, 1e11))
    J1     = _checked('J1', J1, 'positive', 'inertia of the motor shafts (rotors, brake discs, couplings), Table 1, kg*m^2', (1e-6, 2e8))
    J2     = _checked('J2', J2, 'positive', 'inertia of the drum shafts, Table 1, kg*m^2', (1e-12, 5e9))
    m_h    = _checked('m_h', m_h, 'positive', 'mass of the hook (load-handling device), kg', (1e-6, 1e11))
    m_r    = _checked('m_r', m_r, 'positive', 'rated payload (Table 1: 52 t), kg', (0.0001, 1e11))
    r      = _checked('r', r, 'positive', 'drum radius, m', (1e-7, 2e6))
    i_g    = _checked('i_g', i_g, 'positive', 'gear ratio of the gearbox, 1', (5e-6, 1e8))
    i_t    = _checked('i_t', i_t, 'positive', 'ratio of the rope tackle (8 falls, 2 drums: 4), 1', (1e-6, 8e6))
    g      = _checked('g', g, 'positive', 'gravity, m/s^2', (9.8e-6, 9.82e6))
    omega1 = _checked('omega1', omega1, 'positive', 'motor angular speed before braking (Table 1: n1 = 1500 1/min), rad/s', (1e-5, 4e8))
    d_t    = _checked('d_t', d_t, 'positive', 'braking time, s', (1e-7, 1e7))
    shape = _broadcast(m_p=m_p, J1=J1, J2=J2, m_h=m_h, m_r=m_r, r=r, i_g=i_g, i_t=i_t, g=g,
                       omega1=omega1, d_t=d_t)
    x0 = r**2
    return _into(out, shape, omega1*(J2*i_t**2 + m_h*x0 + m_p*x0)/(d_t*g*i_g*i_t*r*(m_h + m_r)))


def elastic_gearbox_torque_no_backlash(t, J1, J2, m_h, m_p, m_r, r, i_g, i_t, g, c, M_SB, t_SB, *, out=None):
    """Relative gearbox torque M_G/M_st of the elastic drive without backlash, lowering, motor torque lost at t = 0, safety brakes from t_SB; valid while the drum slides and the service brakes are off. Eq Fig. 9.

    Parameters
    ----------
    t : array_like
        time since the emergency stop [s], >= 0; served from 0.0 to 1e7
    J1 : array_like
        inertia of the motor shafts (rotors, brake discs, couplings), Table 1 [kg*m^2], > 0; served from 1e-6 to 2e8
    J2 : array_like
        inertia of the drum shafts, Table 1 [kg*m^2], > 0; served from 1e-12 to 5e9
    m_h : array_like
        mass of the hook (load-handling device) [kg], > 0; served from 1e-6 to 1e11
    m_p : array_like
        payload [kg], >= 0; served from 0.0 to 1e11
    m_r : array_like
        rated payload (Table 1: 52 t) [kg], > 0; served from 0.0001 to 1e11
    r : array_like
        drum radius [m], > 0; served from 1e-7 to 2e6
    i_g : array_like
        gear ratio of the gearbox [1], > 0; served from 5e-6 to 1e8
    i_t : array_like
        ratio of the rope tackle (8 falls, 2 drums: 4) [1], > 0; served from 1e-6 to 8e6
    g : array_like
        gravity [m/s^2], > 0; served from 9.8e-6 to 9.82e6
    c : array_like
        torsional stiffness of the gearbox, at the motor shaft [N*m/rad], > 0; served from 1e-6 to 1e13
    M_SB : array_like
        torque of the safety brakes on the drums [N*m], > 0; served from 0.001 to 1e12
    t_SB : array_like
        delay of the safety brakes [s], >= 0; served from 0.0 to 1e6
    out : ndarray, optional
        float64 array of the broadcast shape; the result is written into it and returned.

    Returns
    -------
    ndarray
        [1], broadcast over the arguments.
    """
    t    = _checked('t', t, 'nonnegative', 'time since the emergency stop, s', (0.0, 1e7))
    J1   = _checked('J1', J1, 'positive', 'inertia of the motor shafts (rotors, brake discs, couplings), Table 1, kg*m^2', (1e-6, 2e8))
    J2   = _checked('J2', J2, 'positive', 'inertia of the drum shafts, Table 1, kg*m^2', (1e-12, 5e9))
    m_h  = _checked('m_h', m_h, 'positive', 'mass of the hook (load-handling device), kg', (1e-6, 1e11))
    m_p  = _checked('m_p', m_p, 'nonnegative', 'payload, kg', (0.0, 1e11))
    m_r  = _checked('m_r', m_r, 'positive', 'rated payload (Table 1: 52 t), kg', (0.0001, 1e11))
    r    = _checked('r', r, 'positive', 'drum radius, m', (1e-7, 2e6))
    i_g  = _checked('i_g', i_g, 'positive', 'gear ratio of the gearbox, 1', (5e-6, 1e8))
    i_t  = _checked('i_t', i_t, 'positive', 'ratio of the rope tackle (8 falls, 2 drums: 4), 1', (1e-6, 8e6))
    g    = _checked('g', g, 'positive', 'gravity, m/s^2', (9.8e-6, 9.82e6))
    c    = _checked('c', c, 'positive', 'torsional stiffness of the gearbox, at the motor shaft, N*m/rad', (1e-6, 1e13))
    M_SB = _checked('M_SB', M_SB, 'positive', 'torque of the safety brakes on the drums, N*m', (0.001, 1e12))
    t_SB = _checked('t_SB', t_SB, 'nonnegative', 'delay of the safety brakes, s', (0.0, 1e6))
    shape = _broadcast(t=t, J1=J1, J2=J2, m_h=m_h, m_p=m_p, m_r=m_r, r=r, i_g=i_g, i_t=i_t, g=g, c=c,
                       M_SB=M_SB, t_SB=t_SB)
    x0 = r**2/i_t**2
    x1 = m_h*x0
    x2 = m_p*x0
    x3 = J2 + x1 + x2
    x4 = i_g**(-2.0)
    x5 = J1 + J2*x4 + x1*x4 + x2*x4
    x6 = i_g*np.sqrt(c*x5/(J1*x3))
    x7 = 1/(x5)
    x8 = J1*x7
    x9 = 2*x8
    x10 = m_h + m_p
    x11 = 1/(m_h + m_r)
    x12 = 1/(i_t)
    x13 = g*r*x10*x12
    x14 = np.sqrt(c)*i_g*t_SB*np.sqrt(x5)/(np.sqrt(J1)*np.sqrt(x3))
    k0 = (1/2)*x6
    k1 = x9 - 2
    k2 = x10*x11
    k3 = -t_SB
    k4 = 2*J1*g*r*x10*x12*x7 - M_SB*x9 - 2*x13
    k6 = np.sin(x14)
    k7 = 2*np.sin((1/2)*x14)**2
    k8 = -x13*(1 - x8)
    k10 = i_t*x11/(g*r)
    if out is None and not shape:      # one point: its own branch only
        return (k2*(k1*np.sin(k0*t)**2 + 1) if np.less(t, t_SB) else k10*(k4*np.sin(k0*(k3 + t))**2 + k8*(k6*np.sin(x6*(k3 + t)) + k7*np.cos(x6*(k3 + t))) + x13))
    out = _out(out, shape)
    cells = _cells(shape, [[np.less(t, t_SB)]])
    for part in _blocks(cells[0]):
        k0_, k1_, k2_, t_ = _at(part, shape, k0, k1, k2, t)
        _put(out, part, k2_*(k1_*np.sin(k0_*t_)**2 + 1))
    for part in _blocks(cells[1]):
        k0_, k10_, k3_, k4_, k6_, k7_, k8_, t_, x13_, x6_ = _at(part, shape, k0, k10, k3, k4, k6, k7, k8, t, x13, x6)
        v0 = k3_ + t_
        v1 = v0*x6_
        _put(out, part, k10_*(k4_*np.sin(k0_*v0)**2 + k8_*(k6_*np.sin(v1) + k7_*np.cos(v1)) + x13_))
    return out


def elastic_natural_frequency(J1, J2, m_h, m_p, r, i_g, i_t, c, *, out=None):
    """Natural frequency of the two-mass drive in contact (motor shafts J1 against everything beyond the gearbox input, stiffness c). Eq Fig. 9.

    Parameters
    ----------
    J1 : array_like
        inertia of the motor shafts (rotors, brake discs, couplings), Table 1 [kg*m^2], > 0; served from 1e-6 to 2e8
    J2 : array_like
        inertia of the drum shafts, Table 1 [kg*m^2], > 0; served from 1e-12 to 5e9
    m_h : array_like
        mass of the hook (load-handling device) [kg], > 0; served from 1e-6 to 1e11
    m_p : array_like
        payload [kg], >= 0; served from 0.0 to 1e11
    r : array_like
        drum radius [m], > 0; served from 1e-7 to 2e6
    i_g : array_like
        gear ratio of the gearbox [1], > 0; served from 5e-6 to 1e8
    i_t : array_like
        ratio of the rope tackle (8 falls, 2 drums: 4) [1], > 0; served from 1e-6 to 8e6
    c : array_like
        torsional stiffness of the gearbox, at the motor shaft [N*m/rad], > 0; served from 1e-6 to 1e13
    out : ndarray, optional
        float64 array of the broadcast shape; the result is written into it and returned.

    Returns
    -------
    ndarray
        [rad/s], broadcast over the arguments.
    """
    if (out is None
            and (type(J1) in (float, int) or type(J1) is np.float64)
            and (type(J2) in (float, int) or type(J2) is np.float64)
            and (type(m_h) in (float, int) or type(m_h) is np.float64)
            and (type(m_p) in (float, int) or type(m_p) is np.float64)
            and (type(r) in (float, int) or type(r) is np.float64)
            and (type(i_g) in (float, int) or type(i_g) is np.float64)
            and (type(i_t) in (float, int) or type(i_t) is np.float64)
            and (type(c) in (float, int) or type(c) is np.float64)):
        if (1e-6 <= J1 <= 2e8 and 1e-12 <= J2 <= 5e9 and 1e-6 <= m_h <= 1e11
                and 0.0 <= m_p <= 1e11 and 1e-7 <= r <= 2e6 and 5e-6 <= i_g <= 1e8
                and 1e-6 <= i_t <= 8e6 and 1e-6 <= c <= 1e13):
            try:    # a failed check or a math error: the array path decides
                x0 = r**2/i_t**2
                return np.float64(math.sqrt(c)*math.sqrt(i_g**2/(J2 + m_h*x0 + m_p*x0) + 1/J1))
            except (ArithmeticError, ValueError):
                pass
    J1  = _checked('J1', J1, 'positive', 'inertia of the motor shafts (rotors, brake discs, couplings), Table 1, kg*m^2', (1e-6, 2e8))
    J2  = _checked('J2', J2, 'positive', 'inertia of the drum shafts, Table 1, kg*m^2', (1e-12, 5e9))
    m_h = _checked('m_h', m_h, 'positive', 'mass of the hook (load-handling device), kg', (1e-6, 1e11))
    m_p = _checked('m_p', m_p, 'nonnegative', 'payload, kg', (0.0, 1e11))
    r   = _checked('r', r, 'positive', 'drum radius, m', (1e-7, 2e6))
    i_g = _checked('i_g', i_g, 'positive', 'gear ratio of the gearbox, 1', (5e-6, 1e8))
    i_t = _checked('i_t', i_t, 'positive', 'ratio of the rope tackle (8 falls, 2 drums: 4), 1', (1e-6, 8e6))
    c   = _checked('c', c, 'positive', 'torsional stiffness of the gearbox, at the motor shaft, N*m/rad', (1e-6, 1e13))
    shape = _broadcast(J1=J1, J2=J2, m_h=m_h, m_p=m_p, r=r, i_g=i_g, i_t=i_t, c=c)
    x0 = r**2/i_t**2
    return _into(out, shape, np.sqrt(c)*np.sqrt(i_g**2/(J2 + m_h*x0 + m_p*x0) + 1/(J1)))


def backlash_at_motor_shaft(delta, i_g, *, out=None):
    """The drum-coupling backlash seen at the motor shaft. Eq Fig. 9.

    Parameters
    ----------
    delta : array_like
        backlash of the drum coupling (at the drum) [rad], >= 0; served from 0.0 to 500000.0
    i_g : array_like
        gear ratio of the gearbox [1], > 0; served from 5e-6 to 1e8
    out : ndarray, optional
        float64 array of the broadcast shape; the result is written into it and returned.

    Returns
    -------
    ndarray
        [rad], broadcast over the arguments.
    """
    if (out is None
            and (type(delta) in (float, int) or type(delta) is np.float64)
            and (type(i_g) in (float, int) or type(i_g) is np.float64)):
        if (0.0 <= delta <= 500000.0 and 5e-6 <= i_g <= 1e8):
            try:    # a failed check or a math error: the array path decides
                return np.float64(delta*i_g)
            except (ArithmeticError, ValueError):
                pass
    delta = _checked('delta', delta, 'nonnegative', 'backlash of the drum coupling (at the drum), rad', (0.0, 500000.0))
    i_g   = _checked('i_g', i_g, 'positive', 'gear ratio of the gearbox, 1', (5e-6, 1e8))
    shape = _broadcast(delta=delta, i_g=i_g)
    return _into(out, shape, delta*i_g)


def rigid_hook_speed_hoisting(t, m_p, J1, J2, m_h, r, i_g, i_t, g, omega1, M_SB, M_BB, t_SB, t_BB, *, out=None):
    """Hook speed of the rigid drive, hoisting, after an emergency stop at t = 0: motor torque lost, brakes after their delays (Fig. 5). Eq (1).

    Parameters
    ----------
    t : array_like
        time since the emergency stop [s], >= 0; served from 0.0 to 1e7
    m_p : array_like
        payload [kg], >= 0; served from 0.0 to 1e11
    J1 : array_like
        inertia of the motor shafts (rotors, brake discs, couplings), Table 1 [kg*m^2], > 0; served from 1e-6 to 2e8
    J2 : array_like
        inertia of the drum shafts, Table 1 [kg*m^2], > 0; served from 1e-12 to 5e9
    m_h : array_like
        mass of the hook (load-handling device) [kg], > 0; served from 1e-6 to 1e11
    r : array_like
        drum radius [m], > 0; served from 1e-7 to 2e6
    i_g : array_like
        gear ratio of the gearbox [1], > 0; served from 5e-6 to 1e8
    i_t : array_like
        ratio of the rope tackle (8 falls, 2 drums: 4) [1], > 0; served from 1e-6 to 8e6
    g : array_like
        gravity [m/s^2], > 0; served from 9.8e-6 to 9.82e6
    omega1 : array_like
        motor angular speed before braking (Table 1: n1 = 1500 1/min) [rad/s], > 0; served from 1e-5 to 4e8
    M_SB : array_like
        torque of the safety brakes on the drums [N*m], > 0; served from 0.001 to 1e12
    M_BB : array_like
        torque of the service brakes on the motor shafts [N*m], > 0; served from 0.0001 to 1e11
    t_SB : array_like
        delay of the safety brakes [s], >= 0; served from 0.0 to 1e6
    t_BB : array_like
        delay of the service brakes [s], >= 0; served from 0.0 to 1e6
    out : ndarray, optional
        float64 array of the broadcast shape; the result is written into it and returned.

    Returns
    -------
    ndarray
        [m/s], broadcast over the arguments.
    """
    if (out is None
            and (type(t) in (float, int) or type(t) is np.float64)
            and (type(m_p) in (float, int) or type(m_p) is np.float64)
            and (type(J1) in (float, int) or type(J1) is np.float64)
            and (type(J2) in (float, int) or type(J2) is np.float64)
            and (type(m_h) in (float, int) or type(m_h) is np.float64)
            and (type(r) in (float, int) or type(r) is np.float64)
            and (type(i_g) in (float, int) or type(i_g) is np.float64)
            and (type(i_t) in (float, int) or type(i_t) is np.float64)
            and (type(g) in (float, int) or type(g) is np.float64)
            and (type(omega1) in (float, int) or type(omega1) is np.float64)
            and (type(M_SB) in (float, int) or type(M_SB) is np.float64)
            and (type(M_BB) in (float, int) or type(M_BB) is np.float64)
            and (type(t_SB) in (float, int) or type(t_SB) is np.float64)
            and (type(t_BB) in (float, int) or type(t_BB) is np.float64)):
        if (0.0 <= t <= 1e7 and 0.0 <= m_p <= 1e11 and 1e-6 <= J1 <= 2e8 and 1e-12 <= J2 <= 5e9
                and 1e-6 <= m_h <= 1e11 and 1e-7 <= r <= 2e6 and 5e-6 <= i_g <= 1e8
                and 1e-6 <= i_t <= 8e6 and 9.8e-6 <= g <= 9.82e6 and 1e-5 <= omega1 <= 4e8
                and 0.001 <= M_SB <= 1e12 and 0.0001 <= M_BB <= 1e11 and 0.0 <= t_SB <= 1e6
                and 0.0 <= t_BB <= 1e6):
            try:    # a failed check or a math error: the array path decides
                x0 = i_t**2
                x1 = r**2
                x2 = i_g**2*x0
                x3 = 1/(J1*x2 + J2*x0 + m_h*x1 + m_p*x1)
                x4 = i_g*x3
                x5 = g*i_t*r*x4
                x6 = m_p*x5
                x7 = m_h*x5
                x8 = -t_SB
                x9 = M_SB*x0*x4
                x10 = -t_BB
                x11 = M_BB*x2*x3
                x13 = (t <= t_SB)
                x15 = (t <= t_BB)
                x16 = -omega1 + t*x6 + t*x7
                x17 = x16 + x9*(t + x8)
                k0 = -x6
                k1 = -x7
                x12 = k0*t + k1*t + omega1
                k3 = -x9
                x14 = k3*(t + x8) + x12
                k5 = -x11
                k6 = r/(i_g*i_t)
                return np.float64(((k6*((x12) if x13 else (x14) if x15 else (k5*(t + x10) + x14))) if (((x16 < 0)) if x13 else ((((x17 < 0)) if x15 else ((x11*(t + x10) + x17 < 0))))) else (0)))
            except (ArithmeticError, ValueError):
                pass
    t      = _checked('t', t, 'nonnegative', 'time since the emergency stop, s', (0.0, 1e7))
    m_p    = _checked('m_p', m_p, 'nonnegative', 'payload, kg', (0.0, 1e11))
    J1     = _checked('J1', J1, 'positive', 'inertia of the motor shafts (rotors, brake discs, couplings), Table 1, kg*m^2', (1e-6, 2e8))
    J2     = _checked('J2', J2, 'positive', 'inertia of the drum shafts, Table 1, kg*m^2', (1e-12, 5e9))
    m_h    = _checked('m_h', m_h, 'positive', 'mass of the hook (load-handling device), kg', (1e-6, 1e11))
    r      = _checked('r', r, 'positive', 'drum radius, m', (1e-7, 2e6))
    i_g    = _checked('i_g', i_g, 'positive', 'gear ratio of the gearbox, 1', (5e-6, 1e8))
    i_t    = _checked('i_t', i_t, 'positive', 'ratio of the rope tackle (8 falls, 2 drums: 4), 1', (1e-6, 8e6))
    g      = _checked('g', g, 'positive', 'gravity, m/s^2', (9.8e-6, 9.82e6))
    omega1 = _checked('omega1', omega1, 'positive', 'motor angular speed before braking (Table 1: n1 = 1500 1/min), rad/s', (1e-5, 4e8))
    M_SB   = _checked('M_SB', M_SB, 'positive', 'torque of the safety brakes on the drums, N*m', (0.001, 1e12))
    M_BB   = _checked('M_BB', M_BB, 'positive', 'torque of the service brakes on the motor shafts, N*m', (0.0001, 1e11))
    t_SB   = _checked('t_SB', t_SB, 'nonnegative', 'delay of the safety brakes, s', (0.0, 1e6))
    t_BB   = _checked('t_BB', t_BB, 'nonnegative', 'delay of the service brakes, s', (0.0, 1e6))
    shape = _broadcast(t=t, m_p=m_p, J1=J1, J2=J2, m_h=m_h, r=r, i_g=i_g, i_t=i_t, g=g, omega1=omega1,
                       M_SB=M_SB, M_BB=M_BB, t_SB=t_SB, t_BB=t_BB)
    x0 = i_t**2
    x1 = r**2
    x2 = i_g**2*x0
    x3 = 1/(J1*x2 + J2*x0 + m_h*x1 + m_p*x1)
    x4 = i_g*x3
    x5 = g*i_t*r*x4
    x6 = m_p*x5
    x7 = m_h*x5
    x8 = -t_SB
    x9 = M_SB*x0*x4
    x10 = -t_BB
    x11 = M_BB*x2*x3
    k0 = -x6
    k1 = -x7
    k3 = -x9
    k5 = -x11
    k6 = r/(i_g*i_t)
    _one = out is None and not shape
    out = _out(out, shape)
    for _o, (t, omega1, t_SB, t_BB, x6, x7, x8, x9, x10, x11, k0, k1, k3, k5, k6) in _spans(
            out, shape, t, omega1, t_SB, t_BB, x6, x7, x8, x9, x10, x11, k0, k1, k3, k5, k6):
        x13 = np.less_equal(t, t_SB)
        x15 = np.less_equal(t, t_BB)
        x16 = -omega1 + t*x6 + t*x7
        x17 = x16 + x9*(t + x8)
        x12 = k0*t + k1*t + omega1
        x14 = k3*(t + x8) + x12
        _o[...] = np.select([np.logical_or.reduce((np.logical_and.reduce((x13,np.less(x16, 0))),np.logical_and.reduce((x15,np.logical_not(x13),np.less(x17, 0))),np.logical_and.reduce((np.logical_not(x13),np.logical_not(x15),np.less(x11*(t + x10) + x17, 0))))),True], [k6*np.select([x13,x15,True], [x12,x14,k5*(t + x10) + x14], default=np.nan),0], default=np.nan)
    return out[()] if _one else out


def rigid_stopping_time_hoisting(m_p, J1, J2, m_h, r, i_g, i_t, g, omega1, M_SB, M_BB, t_SB, t_BB, *, out=None):
    """Time the rigid drive takes to stop, hoisting. Eq (1).

    Parameters
    ----------
    m_p : array_like
        payload [kg], >= 0; served from 0.0 to 1e11
    J1 : array_like
        inertia of the motor shafts (rotors, brake discs, couplings), Table 1 [kg*m^2], > 0; served from 1e-6 to 2e8
    J2 : array_like
        inertia of the drum shafts, Table 1 [kg*m^2], > 0; served from 1e-12 to 5e9
    m_h : array_like
        mass of the hook (load-handling device) [kg], > 0; served from 1e-6 to 1e11
    r : array_like
        drum radius [m], > 0; served from 1e-7 to 2e6
    i_g : array_like
        gear ratio of the gearbox [1], > 0; served from 5e-6 to 1e8
    i_t : array_like
        ratio of the rope tackle (8 falls, 2 drums: 4) [1], > 0; served from 1e-6 to 8e6
    g : array_like
        gravity [m/s^2], > 0; served from 9.8e-6 to 9.82e6
    omega1 : array_like
        motor angular speed before braking (Table 1: n1 = 1500 1/min) [rad/s], > 0; served from 1e-5 to 4e8
    M_SB : array_like
        torque of the safety brakes on the drums [N*m], > 0; served from 0.001 to 1e12
    M_BB : array_like
        torque of the service brakes on the motor shafts [N*m], > 0; served from 0.0001 to 1e11
    t_SB : array_like
        delay of the safety brakes [s], >= 0; served from 0.0 to 1e6
    t_BB : array_like
        delay of the service brakes [s], >= 0; served from 0.0 to 1e6
    out : ndarray, optional
        float64 array of the broadcast shape; the result is written into it and returned.

    Returns
    -------
    ndarray
        [s], broadcast over the arguments.

    Raises
    ------
    ValueError
        unless the brakes together decelerate the drive (M_BB + M_SB/i_g above the load torque): else it never stops.
    """
    if (out is None
            and (type(m_p) in (float, int) or type(m_p) is np.float64)
            and (type(J1) in (float, int) or type(J1) is np.float64)
            and (type(J2) in (float, int) or type(J2) is np.float64)
            and (type(m_h) in (float, int) or type(m_h) is np.float64)
            and (type(r) in (float, int) or type(r) is np.float64)
            and (type(i_g) in (float, int) or type(i_g) is np.float64)
            and (type(i_t) in (float, int) or type(i_t) is np.float64)
            and (type(g) in (float, int) or type(g) is np.float64)
            and (type(omega1) in (float, int) or type(omega1) is np.float64)
            and (type(M_SB) in (float, int) or type(M_SB) is np.float64)
            and (type(M_BB) in (float, int) or type(M_BB) is np.float64)
            and (type(t_SB) in (float, int) or type(t_SB) is np.float64)
            and (type(t_BB) in (float, int) or type(t_BB) is np.float64)):
        if (0.0 <= m_p <= 1e11 and 1e-6 <= J1 <= 2e8 and 1e-12 <= J2 <= 5e9
                and 1e-6 <= m_h <= 1e11 and 1e-7 <= r <= 2e6 and 5e-6 <= i_g <= 1e8
                and 1e-6 <= i_t <= 8e6 and 9.8e-6 <= g <= 9.82e6 and 1e-5 <= omega1 <= 4e8
                and 0.001 <= M_SB <= 1e12 and 0.0001 <= M_BB <= 1e11 and 0.0 <= t_SB <= 1e6
                and 0.0 <= t_BB <= 1e6
                and -(-M_BB - M_SB/i_g - g*r*(m_h + m_p)/(i_g*i_t))/(J1 + J2/i_g**2 + m_h*r**2/(i_g**2*i_t**2) + m_p*r**2/(i_g**2*i_t**2)) > 0):
            try:    # a failed check or a math error: the array path decides
                x0 = m_h + m_p
                x1 = i_g**(-2)
                x2 = r**2*x1/i_t**2
                x3 = J1 + J2*x1 + m_h*x2 + m_p*x2
                x4 = i_g*x3
                x5 = g*r*x0/i_t
                x6 = 1/i_g
                x7 = x6/x3
                x8 = -omega1 + t_SB*x5*x7
                x9 = M_SB + x5
                x10 = x7*x9*(t_BB - t_SB) + x8
                return np.float64(((i_t*omega1*x4/(g*r*x0)) if (x8 >= 0) else (t_SB - x4*x8/x9) if (x10 >= 0) else (t_BB - x10*x3/(M_BB + M_SB*x6 + x5*x6))))
            except (ArithmeticError, ValueError):
                pass
    m_p    = _checked('m_p', m_p, 'nonnegative', 'payload, kg', (0.0, 1e11))
    J1     = _checked('J1', J1, 'positive', 'inertia of the motor shafts (rotors, brake discs, couplings), Table 1, kg*m^2', (1e-6, 2e8))
    J2     = _checked('J2', J2, 'positive', 'inertia of the drum shafts, Table 1, kg*m^2', (1e-12, 5e9))
    m_h    = _checked('m_h', m_h, 'positive', 'mass of the hook (load-handling device), kg', (1e-6, 1e11))
    r      = _checked('r', r, 'positive', 'drum radius, m', (1e-7, 2e6))
    i_g    = _checked('i_g', i_g, 'positive', 'gear ratio of the gearbox, 1', (5e-6, 1e8))
    i_t    = _checked('i_t', i_t, 'positive', 'ratio of the rope tackle (8 falls, 2 drums: 4), 1', (1e-6, 8e6))
    g      = _checked('g', g, 'positive', 'gravity, m/s^2', (9.8e-6, 9.82e6))
    omega1 = _checked('omega1', omega1, 'positive', 'motor angular speed before braking (Table 1: n1 = 1500 1/min), rad/s', (1e-5, 4e8))
    M_SB   = _checked('M_SB', M_SB, 'positive', 'torque of the safety brakes on the drums, N*m', (0.001, 1e12))
    M_BB   = _checked('M_BB', M_BB, 'positive', 'torque of the service brakes on the motor shafts, N*m', (0.0001, 1e11))
    t_SB   = _checked('t_SB', t_SB, 'nonnegative', 'delay of the safety brakes, s', (0.0, 1e6))
    t_BB   = _checked('t_BB', t_BB, 'nonnegative', 'delay of the service brakes, s', (0.0, 1e6))
    shape = _broadcast(m_p=m_p, J1=J1, J2=J2, m_h=m_h, r=r, i_g=i_g, i_t=i_t, g=g, omega1=omega1,
                       M_SB=M_SB, M_BB=M_BB, t_SB=t_SB, t_BB=t_BB)
    _required(-(-M_BB - M_SB/i_g - g*r*(m_h + m_p)/(i_g*i_t))/(J1 + J2/i_g**2 + m_h*r**2/(i_g**2*i_t**2) + m_p*r**2/(i_g**2*i_t**2)), 'the brakes together decelerate the drive (M_BB + M_SB/i_g above the load torque): else it never stops')
    x0 = m_h + m_p
    x1 = i_g**(-2.0)
    x2 = r**2*x1/i_t**2
    x3 = J1 + J2*x1 + m_h*x2 + m_p*x2
    x4 = i_g*x3
    x5 = g*r*x0/i_t
    x6 = 1/(i_g)
    x7 = x6/x3
    x8 = -omega1 + t_SB*x5*x7
    x9 = M_SB + x5
    x10 = x7*x9*(t_BB - t_SB) + x8
    return _into(out, shape, np.select([np.greater_equal(x8, 0),np.greater_equal(x10, 0),True], [i_t*omega1*x4/(g*r*x0),t_SB - x4*x8/x9,t_BB - x10*x3/(M_BB + M_SB*x6 + x5*x6)], default=np.nan))


def rigid_hook_speed_lowering(t, m_p, J1, J2, m_h, r, i_g, i_t, g, omega1, M_SB, M_BB, t_SB, t_BB, *, out=None):
    """Hook speed of the rigid drive, lowering, after an emergency stop at t = 0: motor torque lost, brakes after their delays (Fig. 5). Eq (1).

    Parameters
    ----------
    t : array_like
        time since the emergency stop [s], >= 0; served from 0.0 to 1e7
    m_p : array_like
        payload [kg], >= 0; served from 0.0 to 1e11
    J1 : array_like
        inertia of the motor shafts (rotors, brake discs, couplings), Table 1 [kg*m^2], > 0; served from 1e-6 to 2e8
    J2 : array_like
        inertia of the drum shafts, Table 1 [kg*m^2], > 0; served from 1e-12 to 5e9
    m_h : array_like
        mass of the hook (load-handling device) [kg], > 0; served from 1e-6 to 1e11
    r : array_like
        drum radius [m], > 0; served from 1e-7 to 2e6
    i_g : array_like
        gear ratio of the gearbox [1], > 0; served from 5e-6 to 1e8
    i_t : array_like
        ratio of the rope tackle (8 falls, 2 drums: 4) [1], > 0; served from 1e-6 to 8e6
    g : array_like
        gravity [m/s^2], > 0; served from 9.8e-6 to 9.82e6
    omega1 : array_like
        motor angular speed before braking (Table 1: n1 = 1500 1/min) [rad/s], > 0; served from 1e-5 to 4e8
    M_SB : array_like
        torque of the safety brakes on the drums [N*m], > 0; served from 0.001 to 1e12
    M_BB : array_like
        torque of the service brakes on the motor shafts [N*m], > 0; served from 0.0001 to 1e11
    t_SB : array_like
        delay of the safety brakes [s], >= 0; served from 0.0 to 1e6
    t_BB : array_like
        delay of the service brakes [s], >= 0; served from 0.0 to 1e6
    out : ndarray, optional
        float64 array of the broadcast shape; the result is written into it and returned.

    Returns
    -------
    ndarray
        [m/s], broadcast over the arguments.
    """
    if (out is None
            and (type(t) in (float, int) or type(t) is np.float64)
            and (type(m_p) in (float, int) or type(m_p) is np.float64)
            and (type(J1) in (float, int) or type(J1) is np.float64)
            and (type(J2) in (float, int) or type(J2) is np.float64)
            and (type(m_h) in (float, int) or type(m_h) is np.float64)
            and (type(r) in (float, int) or type(r) is np.float64)
            and (type(i_g) in (float, int) or type(i_g) is np.float64)
            and (type(i_t) in (float, int) or type(i_t) is np.float64)
            and (type(g) in (float, int) or type(g) is np.float64)
            and (type(omega1) in (float, int) or type(omega1) is np.float64)
            and (type(M_SB) in (float, int) or type(M_SB) is np.float64)
            and (type(M_BB) in (float, int) or type(M_BB) is np.float64)
            and (type(t_SB) in (float, int) or type(t_SB) is np.float64)
            and (type(t_BB) in (float, int) or type(t_BB) is np.float64)):
        if (0.0 <= t <= 1e7 and 0.0 <= m_p <= 1e11 and 1e-6 <= J1 <= 2e8 and 1e-12 <= J2 <= 5e9
                and 1e-6 <= m_h <= 1e11 and 1e-7 <= r <= 2e6 and 5e-6 <= i_g <= 1e8
                and 1e-6 <= i_t <= 8e6 and 9.8e-6 <= g <= 9.82e6 and 1e-5 <= omega1 <= 4e8
                and 0.001 <= M_SB <= 1e12 and 0.0001 <= M_BB <= 1e11 and 0.0 <= t_SB <= 1e6
                and 0.0 <= t_BB <= 1e6):
            try:    # a failed check or a math error: the array path decides
                x0 = i_t**2
                x1 = r**2
                x2 = i_g**2*x0
                x3 = 1/(J1*x2 + J2*x0 + m_h*x1 + m_p*x1)
                x4 = i_g*x3
                x5 = g*i_t*r*x4
                x6 = m_p*x5
                x7 = m_h*x5
                x8 = -t_SB
                x9 = M_SB*x0*x4
                x10 = -t_BB
                x11 = M_BB*x2*x3
                x12 = omega1 + t*x6 + t*x7
                x13 = (t <= t_SB)
                x15 = (t <= t_BB)
                x16 = omega1 + t*x6 + t*x7 - x9*(t + x8)
                k3 = -x9
                x14 = k3*(t + x8) + x12
                k5 = -x11
                k6 = r/(i_g*i_t)
                return np.float64(((k6*((x12) if x13 else (x14) if x15 else (k5*(t + x10) + x14))) if ((True) if x13 else ((((x16 > 0)) if x15 else ((x11*(t + x10) - x16 < 0))))) else (0)))
            except (ArithmeticError, ValueError):
                pass
    t      = _checked('t', t, 'nonnegative', 'time since the emergency stop, s', (0.0, 1e7))
    m_p    = _checked('m_p', m_p, 'nonnegative', 'payload, kg', (0.0, 1e11))
    J1     = _checked('J1', J1, 'positive', 'inertia of the motor shafts (rotors, brake discs, couplings), Table 1, kg*m^2', (1e-6, 2e8))
    J2     = _checked('J2', J2, 'positive', 'inertia of the drum shafts, Table 1, kg*m^2', (1e-12, 5e9))
    m_h    = _checked('m_h', m_h, 'positive', 'mass of the hook (load-handling device), kg', (1e-6, 1e11))
    r      = _checked('r', r, 'positive', 'drum radius, m', (1e-7, 2e6))
    i_g    = _checked('i_g', i_g, 'positive', 'gear ratio of the gearbox, 1', (5e-6, 1e8))
    i_t    = _checked('i_t', i_t, 'positive', 'ratio of the rope tackle (8 falls, 2 drums: 4), 1', (1e-6, 8e6))
    g      = _checked('g', g, 'positive', 'gravity, m/s^2', (9.8e-6, 9.82e6))
    omega1 = _checked('omega1', omega1, 'positive', 'motor angular speed before braking (Table 1: n1 = 1500 1/min), rad/s', (1e-5, 4e8))
    M_SB   = _checked('M_SB', M_SB, 'positive', 'torque of the safety brakes on the drums, N*m', (0.001, 1e12))
    M_BB   = _checked('M_BB', M_BB, 'positive', 'torque of the service brakes on the motor shafts, N*m', (0.0001, 1e11))
    t_SB   = _checked('t_SB', t_SB, 'nonnegative', 'delay of the safety brakes, s', (0.0, 1e6))
    t_BB   = _checked('t_BB', t_BB, 'nonnegative', 'delay of the service brakes, s', (0.0, 1e6))
    shape = _broadcast(t=t, m_p=m_p, J1=J1, J2=J2, m_h=m_h, r=r, i_g=i_g, i_t=i_t, g=g, omega1=omega1,
                       M_SB=M_SB, M_BB=M_BB, t_SB=t_SB, t_BB=t_BB)
    x0 = i_t**2
    x1 = r**2
    x2 = i_g**2*x0
    x3 = 1/(J1*x2 + J2*x0 + m_h*x1 + m_p*x1)
    x4 = i_g*x3
    x5 = g*i_t*r*x4
    x6 = m_p*x5
    x7 = m_h*x5
    x8 = -t_SB
    x9 = M_SB*x0*x4
    x10 = -t_BB
    x11 = M_BB*x2*x3
    k3 = -x9
    k5 = -x11
    k6 = r/(i_g*i_t)
    _one = out is None and not shape
    out = _out(out, shape)
    for _o, (t, omega1, t_SB, t_BB, x6, x7, x8, x9, x10, x11, k3, k5, k6) in _spans(
            out, shape, t, omega1, t_SB, t_BB, x6, x7, x8, x9, x10, x11, k3, k5, k6):
        x12 = omega1 + t*x6 + t*x7
        x13 = np.less_equal(t, t_SB)
        x15 = np.less_equal(t, t_BB)
        x16 = omega1 + t*x6 + t*x7 - x9*(t + x8)
        x14 = k3*(t + x8) + x12
        _o[...] = np.select([np.logical_and.reduce((np.logical_or.reduce((x13,np.logical_not(x15),np.greater(x16, 0))),np.logical_or.reduce((x13,x15,np.less(x11*(t + x10) - x16, 0))))),True], [k6*np.select([x13,x15,True], [x12,x14,k5*(t + x10) + x14], default=np.nan),0], default=np.nan)
    return out[()] if _one else out


def rigid_stopping_time_lowering(m_p, J1, J2, m_h, r, i_g, i_t, g, omega1, M_SB, M_BB, t_SB, t_BB, *, out=None):
    """Time the rigid drive takes to stop, lowering. Eq (1).

    Parameters
    ----------
    m_p : array_like
        payload [kg], >= 0; served from 0.0 to 1e11
    J1 : array_like
        inertia of the motor shafts (rotors, brake discs, couplings), Table 1 [kg*m^2], > 0; served from 1e-6 to 2e8
    J2 : array_like
        inertia of the drum shafts, Table 1 [kg*m^2], > 0; served from 1e-12 to 5e9
    m_h : array_like
        mass of the hook (load-handling device) [kg], > 0; served from 1e-6 to 1e11
    r : array_like
        drum radius [m], > 0; served from 1e-7 to 2e6
    i_g : array_like
        gear ratio of the gearbox [1], > 0; served from 5e-6 to 1e8
    i_t : array_like
        ratio of the rope tackle (8 falls, 2 drums: 4) [1], > 0; served from 1e-6 to 8e6
    g : array_like
        gravity [m/s^2], > 0; served from 9.8e-6 to 9.82e6
    omega1 : array_like
        motor angular speed before braking (Table 1: n1 = 1500 1/min) [rad/s], > 0; served from 1e-5 to 4e8
    M_SB : array_like
        torque of the safety brakes on the drums [N*m], > 0; served from 0.001 to 1e12
    M_BB : array_like
        torque of the service brakes on the motor shafts [N*m], > 0; served from 0.0001 to 1e11
    t_SB : array_like
        delay of the safety brakes [s], >= 0; served from 0.0 to 1e6
    t_BB : array_like
        delay of the service brakes [s], >= 0; served from 0.0 to 1e6
    out : ndarray, optional
        float64 array of the broadcast shape; the result is written into it and returned.

    Returns
    -------
    ndarray
        [s], broadcast over the arguments.

    Raises
    ------
    ValueError
        unless the brakes together decelerate the drive (M_BB + M_SB/i_g above the load torque): else it never stops.
    """
    if (out is None
            and (type(m_p) in (float, int) or type(m_p) is np.float64)
            and (type(J1) in (float, int) or type(J1) is np.float64)
            and (type(J2) in (float, int) or type(J2) is np.float64)
            and (type(m_h) in (float, int) or type(m_h) is np.float64)
            and (type(r) in (float, int) or type(r) is np.float64)
            and (type(i_g) in (float, int) or type(i_g) is np.float64)
            and (type(i_t) in (float, int) or type(i_t) is np.float64)
            and (type(g) in (float, int) or type(g) is np.float64)
            and (type(omega1) in (float, int) or type(omega1) is np.float64)
            and (type(M_SB) in (float, int) or type(M_SB) is np.float64)
            and (type(M_BB) in (float, int) or type(M_BB) is np.float64)
            and (type(t_SB) in (float, int) or type(t_SB) is np.float64)
            and (type(t_BB) in (float, int) or type(t_BB) is np.float64)):
        if (0.0 <= m_p <= 1e11 and 1e-6 <= J1 <= 2e8 and 1e-12 <= J2 <= 5e9
                and 1e-6 <= m_h <= 1e11 and 1e-7 <= r <= 2e6 and 5e-6 <= i_g <= 1e8
                and 1e-6 <= i_t <= 8e6 and 9.8e-6 <= g <= 9.82e6 and 1e-5 <= omega1 <= 4e8
                and 0.001 <= M_SB <= 1e12 and 0.0001 <= M_BB <= 1e11 and 0.0 <= t_SB <= 1e6
                and 0.0 <= t_BB <= 1e6
                and (M_BB + M_SB/i_g - g*r*(m_h + m_p)/(i_g*i_t))/(J1 + J2/i_g**2 + m_h*r**2/(i_g**2*i_t**2) + m_p*r**2/(i_g**2*i_t**2)) > 0):
            try:    # a failed check or a math error: the array path decides
                x0 = g*r*(m_h + m_p)/i_t
                x1 = M_SB - x0
                x2 = i_g**(-2)
                x3 = r**2*x2/i_t**2
                x4 = J1 + J2*x2 + m_h*x3 + m_p*x3
                x5 = 1/i_g
                x6 = x5/x4
                x7 = omega1 + t_SB*x0*x6
                x8 = -x1*x6*(t_BB - t_SB) + x7
                return np.float64(((i_g*x4*x7/x1 + t_SB) if (x8 <= 0) else (t_BB + x4*x8/(M_BB + M_SB*x5 - x0*x5))))
            except (ArithmeticError, ValueError):
                pass
    m_p    = _checked('m_p', m_p, 'nonnegative', 'payload, kg', (0.0, 1e11))
    J1     = _checked('J1', J1, 'positive', 'inertia of the motor shafts (rotors, brake discs, couplings), Table 1, kg*m^2', (1e-6, 2e8))
    J2     = _checked('J2', J2, 'positive', 'inertia of the drum shafts, Table 1, kg*m^2', (1e-12, 5e9))
    m_h    = _checked('m_h', m_h, 'positive', 'mass of the hook (load-handling device), kg', (1e-6, 1e11))
    r      = _checked('r', r, 'positive', 'drum radius, m', (1e-7, 2e6))
    i_g    = _checked('i_g', i_g, 'positive', 'gear ratio of the gearbox, 1', (5e-6, 1e8))
    i_t    = _checked('i_t', i_t, 'positive', 'ratio of the rope tackle (8 falls, 2 drums: 4), 1', (1e-6, 8e6))
    g      = _checked('g', g, 'positive', 'gravity, m/s^2', (9.8e-6, 9.82e6))
    omega1 = _checked('omega1', omega1, 'positive', 'motor angular speed before braking (Table 1: n1 = 1500 1/min), rad/s', (1e-5, 4e8))
    M_SB   = _checked('M_SB', M_SB, 'positive', 'torque of the safety brakes on the drums, N*m', (0.001, 1e12))
    M_BB   = _checked('M_BB', M_BB, 'positive', 'torque of the service brakes on the motor shafts, N*m', (0.0001, 1e11))
    t_SB   = _checked('t_SB', t_SB, 'nonnegative', 'delay of the safety brakes, s', (0.0, 1e6))
    t_BB   = _checked('t_BB', t_BB, 'nonnegative', 'delay of the service brakes, s', (0.0, 1e6))
    shape = _broadcast(m_p=m_p, J1=J1, J2=J2, m_h=m_h, r=r, i_g=i_g, i_t=i_t, g=g, omega1=omega1,
                       M_SB=M_SB, M_BB=M_BB, t_SB=t_SB, t_BB=t_BB)
    _required((M_BB + M_SB/i_g - g*r*(m_h + m_p)/(i_g*i_t))/(J1 + J2/i_g**2 + m_h*r**2/(i_g**2*i_t**2) + m_p*r**2/(i_g**2*i_t**2)), 'the brakes together decelerate the drive (M_BB + M_SB/i_g above the load torque): else it never stops')
    x0 = g*r*(m_h + m_p)/i_t
    x1 = M_SB - x0
    x2 = i_g**(-2.0)
    x3 = r**2*x2/i_t**2
    x4 = J1 + J2*x2 + m_h*x3 + m_p*x3
    x5 = 1/(i_g)
    x6 = x5/x4
    x7 = omega1 + t_SB*x0*x6
    x8 = -x1*x6*(t_BB - t_SB) + x7
    return _into(out, shape, np.select([np.less_equal(x8, 0),True], [i_g*x4*x7/x1 + t_SB,t_BB + x4*x8/(M_BB + M_SB*x5 - x0*x5)], default=np.nan))
