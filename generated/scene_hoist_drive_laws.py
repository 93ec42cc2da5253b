"""Numeric functions for derivation 'hoist_startup'. Generated; do not edit.

Source: crane_sym.derivations.hoist_startup (paper 002_f8509f3826f601de.txt:
Duhamel's integral for the start-up of a crane hoist: rope loads and dynamic factors).
Specialized to scene 'hoist_drive_laws' (Paper 002: rope dynamic coefficient for the four drive laws of (30)): outputs dynamic_coefficient_pickup_a1, dynamic_coefficient_pickup_a2, dynamic_coefficient_pickup_a3, dynamic_coefficient_pickup_a4, dynamic_coefficient_from_weight_a1, dynamic_coefficient_from_weight_a2, dynamic_coefficient_from_weight_a3, dynamic_coefficient_from_weight_a4, optimal_coefficient_from_weight_a1, optimal_coefficient_from_weight_a2, optimal_coefficient_from_weight_a3, optimal_coefficient_from_weight_a4; folded in: m1 = 2000.0 kg, m2 = 8000.0 kg, C = 1000000.0 N/m, g = 9.81 m/s^2, v0 = 0.25 m/s, t_n = 1.0 s, Omega = 25.0 rad/s, tau_0 = 0.31392 s.
Equations: (26), (27), (28), (30), (63), (65).
Printed by SymPy 1.14.0 with crane_sym 0.1.0; regenerate with `crane-sym generate --scene hoist_drive_laws --out <folder>`.

Functions and argument order:
    dynamic_coefficient_pickup_a1(t) -> [1]    eq (26), (28), (30)
    dynamic_coefficient_pickup_a2(t) -> [1]    eq (26), (28), (30)
    dynamic_coefficient_pickup_a3(t) -> [1]    eq (26), (28), (30)
    dynamic_coefficient_pickup_a4(t) -> [1]    eq (26), (28), (30)
    dynamic_coefficient_from_weight_a1(t) -> [1]    eq (27), (28), (30)
    dynamic_coefficient_from_weight_a2(t) -> [1]    eq (27), (28), (30)
    dynamic_coefficient_from_weight_a3(t) -> [1]    eq (27), (28), (30)
    dynamic_coefficient_from_weight_a4(t) -> [1]    eq (27), (28), (30)
    optimal_coefficient_from_weight_a1(t) -> [1]    eq (63), (65)
    optimal_coefficient_from_weight_a2(t) -> [1]    eq (63), (65)
    optimal_coefficient_from_weight_a3(t) -> [1]    eq (63), (65)
    optimal_coefficient_from_weight_a4(t) -> [1]    eq (63), (65)
"""

import numpy as np

__all__ = ['dynamic_coefficient_pickup_a1', 'dynamic_coefficient_pickup_a2', 'dynamic_coefficient_pickup_a3', 'dynamic_coefficient_pickup_a4', 'dynamic_coefficient_from_weight_a1', 'dynamic_coefficient_from_weight_a2', 'dynamic_coefficient_from_weight_a3', 'dynamic_coefficient_from_weight_a4', 'optimal_coefficient_from_weight_a1', 'optimal_coefficient_from_weight_a2', 'optimal_coefficient_from_weight_a3', 'optimal_coefficient_from_weight_a4']

SCENE_NAME = 'hoist_drive_laws'
SCENE_TITLE = 'Paper 002: rope dynamic coefficient for the four drive laws of (30)'


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


def _two_sum(a, b):
    """a + b as an unevaluated sum s + e of two doubles, exactly (Knuth)."""
    s = a + b
    v = s - a
    return s, (a - (s - v)) + (b - v)


def _quick_two_sum(a, b):
    """a + b as s + e exactly, for |a| >= |b| (Dekker)."""
    s = a + b
    return s, b - (s - a)


def _two_product(a, b):
    """a*b as an unevaluated sum p + e of two doubles, exactly (Dekker)."""
    p = a * b
    a_hi = a * 134217729.0
    a_hi = a_hi - (a_hi - a)
    b_hi = b * 134217729.0
    b_hi = b_hi - (b_hi - b)
    a_lo, b_lo = a - a_hi, b - b_hi
    return p, ((a_hi * b_hi - p) + a_hi * b_lo + a_lo * b_hi) + a_lo * b_lo


def _taylor_where(values, small, z, power, step, coeffs):
    """``values`` with the entries where ``small`` replaced by
    z**power * sum_k coeffs[k] * z**(step*k) (Horner): an entire function by
    its Taylor series where its closed form cancels."""
    if not np.any(small):
        return np.asarray(values, dtype=float)
    values = np.array(values, dtype=float)
    zs = np.asarray(z, dtype=float)[small]
    zz = zs * zs if step == 2 else zs
    total = np.full_like(zs, coeffs[-1])
    for c in coeffs[-2::-1]:
        total = total * zz + c
    values[small] = total * zs ** power
    return values


def _cube(x):
    """x**3 as two products: NumPy's ``x**3`` calls ``pow`` per point."""
    return x * (x * x)


def _fourth(x):
    """x**4 as two squarings."""
    x2 = x * x
    return x2 * x2


class _Phase(tuple):
    """A phase pair (hi, lo) that keeps the sines and cosines taken of it, so
    the kernels one formula calls on the same phase share one np.sin and one
    np.cos of each multiple (``_sincos_pair``)."""

    def __new__(cls, hi, lo):
        phase = tuple.__new__(cls, (hi, lo))
        phase.taken = {}
        return phase


def _exact_phase(k, t, c=0.0):
    """k*(t - c) as a pair (hi, lo) with hi + lo correct to ~2**-104
    relative: t - c by TwoSum, the product by TwoProduct. A phase at long
    times or just after a switch, where one rounding is a large error of a
    sine near its zeros."""
    if np.ndim(c) == 0 and c == 0:   # t - 0 is exact: the product alone
        return _Phase(*_two_product(k, t))
    s, e = _two_sum(t, -c)
    p, pe = _two_product(k, s)
    return _Phase(*_quick_two_sum(p, pe + k * e))


def _pair(z):
    """A phase as (hi, lo): a pair from _exact_phase, or a double (lo = 0)."""
    return z if isinstance(z, tuple) else (z, 0.0)


def _sincos_pair(z, q):
    """(sin(q*z), cos(q*z)) for a phase pair z (q a power of two), each once;
    kept on a _Phase for the next kernel that asks."""
    taken = getattr(z, "taken", None)
    if taken is not None and q in taken:
        return taken[q]
    hi, lo = _pair(z)
    a = q * hi
    s, c = np.sin(a), np.cos(a)
    if not (np.ndim(lo) == 0 and lo == 0):
        d = q * lo
        s, c = s + c * d, c - s * d
    if taken is not None:
        taken[q] = (s, c)
    return s, c


def _sin_pair(z, q):
    """sin(q*z) for a phase pair z (q a power of two: q*hi is exact)."""
    return _sincos_pair(z, q)[0]


def _cos_pair(z, q):
    """cos(q*z) for a phase pair z (q a power of two)."""
    return _sincos_pair(z, q)[1]


def _sin_half_squared(z):
    """sin(z/2)**2 for a phase pair z, from its shared sine and cosine:
    (1 - cos z)/2 where cos z < 0, else sin(z)**2/(2 + 2 cos z); neither
    cancels (|cos z| in the unused branch: no division by zero)."""
    s, c = _sincos_pair(z, 1.0)
    return np.where(c < 0, 0.5 - 0.5 * c, s * s / (2.0 + 2.0 * np.abs(c)))


def _wave(b, c, x):
    """b*cos(x) + c*sin(x) for a phase pair x, the two products summed with
    one rounding (TwoProduct): the wave is accurate near its zeros."""
    s, co = _sincos_pair(x, 1.0)
    p, p_err = _two_product(b, co)
    q, q_err = _two_product(c, s)
    return (p + q) + (p_err + q_err)


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


def _cancelled(value, bound):
    """A selector of the points of the 1-D ``value`` below half its error
    scale ``bound``, where a fast sum cancels and the cell's own formula is
    evaluated again (``wave_sums``); None if there is none."""
    return _selector(np.abs(value) < 0.5 * bound)


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


def _entire_1(z):
    """z - sin(z):
    entire, ~z**3 at 0; its Taylor series where |z| < 2.378414230005442.
    z is a phase: a pair (hi, lo) or a double."""
    w = z
    z = _pair(w)[0]
    small = np.abs(z) < 2.378414230005442
    z_ = np.where(small, 2.378414230005442, z)
    s0, c0 = _sincos_pair(w, 1.0)
    return _taylor_where(-s0 + z_, small, z, 3, 2,
                         (0.16666666666666666, -0.008333333333333333, 0.0001984126984126984, -2.7557319223985893e-06, 2.505210838544172e-08, -1.6059043836821613e-10, 7.647163731819816e-13, -2.8114572543455206e-15, 8.22063524662433e-18, -1.9572941063391263e-20, 3.868170170630684e-23, -6.446950284384474e-26,))


def _entire_2(z):
    """-z/25 + 2*sin(z/2)**2 + sin(z)/25:
    entire, ~z**2 at 0; its Taylor series where |z| < 0.026278012976678578.
    z is a phase: a pair (hi, lo) or a double."""
    w = z
    z = _pair(w)[0]
    small = np.abs(z) < 0.026278012976678578
    z_ = np.where(small, 0.026278012976678578, z)
    h0 = _sin_half_squared(w)
    s1, c1 = _sincos_pair(w, 1.0)
    return _taylor_where(2*h0 + (1/25)*s1 - 1/25*z_, small, z, 2, 1,
                         (0.5, -0.006666666666666667, -0.041666666666666664, 0.0003333333333333333, 0.001388888888888889, -7.936507936507936e-06, -2.48015873015873e-05, 1.1022927689594356e-07,))


def _entire_3(z):
    """z**3/100 - z**2/2 + 619*z/100 + 2*sin(z/2)**2 - 619*sin(z)/100:
    entire, ~z**3 at 0; its Taylor series where |z| < 0.1767766952966369.
    z is a phase: a pair (hi, lo) or a double."""
    w = z
    z = _pair(w)[0]
    small = np.abs(z) < 0.1767766952966369
    z_ = np.where(small, 0.1767766952966369, z)
    h0 = _sin_half_squared(w)
    s1, c1 = _sincos_pair(w, 1.0)
    return _taylor_where(2*h0 - 619/100*s1 + (1/100)*_cube(z_) - 1/2*z_**2 + (619/100)*z_, small, z, 3, 1,
                         (1.0416666666666667, -0.041666666666666664, -0.051583333333333335, 0.001388888888888889, 0.0012281746031746032, -2.48015873015873e-05, -1.7057980599647265e-05, 2.755731922398589e-07, 1.5507255090588425e-07, -2.08767569878681e-09, -9.94054813499258e-10,))


def _entire_4(z):
    """z**5/29450 - 3*z**4/1178 + 371*z**3/5890 - z**2/2 - 1113*z/2945 + 2*sin(z/2)**2 + 1113*sin(z)/2945:
    entire, ~z**4 at 0; its Taylor series where |z| < 0.125.
    z is a phase: a pair (hi, lo) or a double."""
    w = z
    z = _pair(w)[0]
    small = np.abs(z) < 0.125
    z_ = np.where(small, 0.125, z)
    h0 = _sin_half_squared(w)
    s1, c1 = _sincos_pair(w, 1.0)
    return _taylor_where(2*h0 + (1113/2945)*s1 + (1/29450)*z_**5 - 3/1178*_fourth(z_) + (371/5890)*_cube(z_) - 1/2*z_**2 - 1113/2945*z_, small, z, 4, 1,
                         (-0.04421335597057159, 0.0031833616298811546, 0.001388888888888889, -7.498585172608941e-05, -2.48015873015873e-05, 1.041470162862353e-06, 2.755731922398589e-07, -9.467910571475936e-09, -2.08767569878681e-09, 6.069173443253806e-11,))


def dynamic_coefficient_pickup_a1(t, *, out=None):
    """K_din^(1)(t) for the drive law a_1 of (30), lifting with pick-up (tau_0 from pickup_contact_time); Omega from natural_frequency. Specialized to scene 'hoist_drive_laws'. Eq (26), (28), (30).

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
    t = _checked('t', t, 'nonnegative', 'time from the start of the drive, s', (0.0, 1e7))
    shape = _broadcast(t=t)
    if out is None and not shape:      # one point: its own branch only
        return ((3108913097059732764796651569152/100703913039958856128874132496575)*_entire_1(_exact_phase(25, t)) if np.less_equal(t, 706884997512073/2251799813685248) else 0.06174253581630276*_sin_half_squared(_exact_phase(25, t, 706884997512073/2251799813685248)) + 0.0306871573751505*_sin_pair(_exact_phase(25, t, 706884997512073/2251799813685248), 1.0) + 0.21141077704121883) + ((351843720888320/5698460903507231)*_sin_half_squared(_exact_phase(25, t)) if np.less_equal(t, 1) else _wave(0.00027158521043857745, -0.0040859394325071935, _exact_phase(25, t, 1))) + (11045078086126142/5698460903507231)*_sin_half_squared(_exact_phase(25, t))
    out = _out(out, shape)
    cells = _cells(shape, [[np.less_equal(t, 706884997512073/2251799813685248)], [np.less_equal(t, 1)]])
    for part in _blocks(cells[0]):
        t_, = _at(part, shape, t)
        v0 = _exact_phase(25, t_)
        _put(out, part, (3108913097059732764796651569152/100703913039958856128874132496575)*_entire_1(v0) + 2*_sin_half_squared(v0))
    for part in _blocks(cells[1]):
        t_, = _at(part, shape, t)
        v0 = _exact_phase(25, t_)
        v1 = _exact_phase(25, 1)
        v2 = _cos_pair(v1, 1.0)
        v3 = _sin_pair(v1, 1.0)
        v_sum = (-0.0040859394325071935*v2 + 0.00027158521043857745*v3)*_sin_pair(v0, 1.0) + (0.00027158521043857745*v2 + 0.0040859394325071935*v3)*_cos_pair(v0, 1.0) + (3108913097059732764796651569152/100703913039958856128874132496575)*_entire_1(v0) + (11045078086126142/5698460903507231)*_sin_half_squared(v0)
        v_redo = _cancelled(v_sum, 0.004357524642945771)
        if v_redo is not None:      # where the fast sum cancels
            t_, = _at(v_redo, v_sum.shape, t_,)
            v0 = _exact_phase(25, t_)
            v_sum[v_redo] = (3108913097059732764796651569152/100703913039958856128874132496575)*_entire_1(v0) + (11045078086126142/5698460903507231)*_sin_half_squared(v0) + _wave(0.00027158521043857745, -0.0040859394325071935, _exact_phase(25, t_, 1))
        _put(out, part, v_sum)
    for part in _blocks(cells[2]):
        t_, = _at(part, shape, t)
        v0 = _exact_phase(25, t_)
        v1 = _exact_phase(25, 706884997512073/2251799813685248)
        v_sum = -0.0306871573751505*_cos_pair(v0, 1.0)*_sin_pair(v1, 1.0) + 0.0306871573751505*_cos_pair(v1, 1.0)*_sin_pair(v0, 1.0) + 2*_sin_half_squared(v0) + 0.06174253581630276*_sin_half_squared(_exact_phase(25, t_, 706884997512073/2251799813685248)) + 0.21141077704121883
        v_redo = _cancelled(v_sum, 0.24209793441636934)
        if v_redo is not None:      # where the fast sum cancels
            t_, = _at(v_redo, v_sum.shape, t_,)
            v0 = _exact_phase(25, t_, 706884997512073/2251799813685248)
            v_sum[v_redo] = 0.06174253581630276*_sin_half_squared(v0) + 0.0306871573751505*_sin_pair(v0, 1.0) + 2*_sin_half_squared(_exact_phase(25, t_)) + 0.21141077704121883
        _put(out, part, v_sum)
    for part in _blocks(cells[3]):
        t_, = _at(part, shape, t)
        v0 = _exact_phase(25, t_)
        v1 = _exact_phase(25, 706884997512073/2251799813685248)
        v2 = _exact_phase(25, 1)
        v3 = _cos_pair(v2, 1.0)
        v4 = _sin_pair(v2, 1.0)
        v_sum = (-0.0040859394325071935*v3 + 0.00027158521043857745*v4 + 0.0306871573751505*_cos_pair(v1, 1.0))*_sin_pair(v0, 1.0) + (0.00027158521043857745*v3 + 0.0040859394325071935*v4 - 0.0306871573751505*_sin_pair(v1, 1.0))*_cos_pair(v0, 1.0) + (11045078086126142/5698460903507231)*_sin_half_squared(v0) + 0.06174253581630276*_sin_half_squared(_exact_phase(25, t_, 706884997512073/2251799813685248)) + 0.21141077704121883
        v_redo = _cancelled(v_sum, 0.2464554590593151)
        if v_redo is not None:      # where the fast sum cancels
            t_, = _at(v_redo, v_sum.shape, t_,)
            v0 = _exact_phase(25, t_, 706884997512073/2251799813685248)
            v_sum[v_redo] = 0.06174253581630276*_sin_half_squared(v0) + 0.0306871573751505*_sin_pair(v0, 1.0) + (11045078086126142/5698460903507231)*_sin_half_squared(_exact_phase(25, t_)) + _wave(0.00027158521043857745, -0.0040859394325071935, _exact_phase(25, t_, 1)) + 0.21141077704121883
        _put(out, part, v_sum)
    return out


def dynamic_coefficient_pickup_a2(t, *, out=None):
    """K_din^(1)(t) for the drive law a_2 of (30), lifting with pick-up (tau_0 from pickup_contact_time); Omega from natural_frequency. Specialized to scene 'hoist_drive_laws'. Eq (26), (28), (30).

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
    t = _checked('t', t, 'nonnegative', 'time from the start of the drive, s', (0.0, 1e7))
    shape = _broadcast(t=t)
    if out is None and not shape:      # one point: its own branch only
        return ((175921860444160/5698460903507231)*_entire_2(_exact_phase(25, t)) if np.less_equal(t, 1) else _wave(-0.03076367256938085, -0.004096802840924737, _exact_phase(25, t, 1))) + ((3108913097059732764796651569152/100703913039958856128874132496575)*_entire_1(_exact_phase(25, t)) if np.less_equal(t, 706884997512073/2251799813685248) else 0.06174253581630276*_sin_half_squared(_exact_phase(25, t, 706884997512073/2251799813685248)) + 0.0306871573751505*_sin_pair(_exact_phase(25, t, 706884997512073/2251799813685248), 1.0) + 0.21141077704121883) + (11045078086126142/5698460903507231)*_sin_half_squared(_exact_phase(25, t))
    out = _out(out, shape)
    cells = _cells(shape, [[np.less_equal(t, 1)], [np.less_equal(t, 706884997512073/2251799813685248)]])
    for part in _blocks(cells[0]):
        t_, = _at(part, shape, t)
        v0 = _exact_phase(25, t_)
        _put(out, part, (175921860444160/5698460903507231)*_entire_2(v0) + (3108913097059732764796651569152/100703913039958856128874132496575)*_entire_1(v0) + (11045078086126142/5698460903507231)*_sin_half_squared(v0))
    for part in _blocks(cells[1]):
        t_, = _at(part, shape, t)
        v0 = _exact_phase(25, t_)
        v1 = _exact_phase(25, 706884997512073/2251799813685248)
        v_sum = (175921860444160/5698460903507231)*_entire_2(v0) - 0.0306871573751505*_cos_pair(v0, 1.0)*_sin_pair(v1, 1.0) + 0.0306871573751505*_cos_pair(v1, 1.0)*_sin_pair(v0, 1.0) + (11045078086126142/5698460903507231)*_sin_half_squared(v0) + 0.06174253581630276*_sin_half_squared(_exact_phase(25, t_, 706884997512073/2251799813685248)) + 0.21141077704121883
        v_redo = _cancelled(v_sum, 0.24209793441636934)
        if v_redo is not None:      # where the fast sum cancels
            t_, = _at(v_redo, v_sum.shape, t_,)
            v0 = _exact_phase(25, t_, 706884997512073/2251799813685248)
            v1 = _exact_phase(25, t_)
            v_sum[v_redo] = (175921860444160/5698460903507231)*_entire_2(v1) + 0.06174253581630276*_sin_half_squared(v0) + 0.0306871573751505*_sin_pair(v0, 1.0) + (11045078086126142/5698460903507231)*_sin_half_squared(v1) + 0.21141077704121883
        _put(out, part, v_sum)
    for part in _blocks(cells[2]):
        t_, = _at(part, shape, t)
        v0 = _exact_phase(25, t_)
        v1 = _exact_phase(25, 1)
        v2 = _cos_pair(v1, 1.0)
        v3 = _sin_pair(v1, 1.0)
        v_sum = (-0.03076367256938085*v2 + 0.004096802840924737*v3)*_cos_pair(v0, 1.0) + (-0.004096802840924737*v2 - 0.03076367256938085*v3)*_sin_pair(v0, 1.0) + (3108913097059732764796651569152/100703913039958856128874132496575)*_entire_1(v0) + (11045078086126142/5698460903507231)*_sin_half_squared(v0)
        v_redo = _cancelled(v_sum, 0.03486047541030558)
        if v_redo is not None:      # where the fast sum cancels
            t_, = _at(v_redo, v_sum.shape, t_,)
            v0 = _exact_phase(25, t_)
            v_sum[v_redo] = (3108913097059732764796651569152/100703913039958856128874132496575)*_entire_1(v0) + (11045078086126142/5698460903507231)*_sin_half_squared(v0) + _wave(-0.03076367256938085, -0.004096802840924737, _exact_phase(25, t_, 1))
        _put(out, part, v_sum)
    for part in _blocks(cells[3]):
        t_, = _at(part, shape, t)
        v0 = _exact_phase(25, t_)
        v1 = _exact_phase(25, 706884997512073/2251799813685248)
        v2 = _exact_phase(25, 1)
        v3 = _cos_pair(v2, 1.0)
        v4 = _sin_pair(v2, 1.0)
        v_sum = (-0.03076367256938085*v3 + 0.004096802840924737*v4 - 0.0306871573751505*_sin_pair(v1, 1.0))*_cos_pair(v0, 1.0) + (-0.004096802840924737*v3 - 0.03076367256938085*v4 + 0.0306871573751505*_cos_pair(v1, 1.0))*_sin_pair(v0, 1.0) + (11045078086126142/5698460903507231)*_sin_half_squared(v0) + 0.06174253581630276*_sin_half_squared(_exact_phase(25, t_, 706884997512073/2251799813685248)) + 0.21141077704121883
        v_redo = _cancelled(v_sum, 0.2769584098266749)
        if v_redo is not None:      # where the fast sum cancels
            t_, = _at(v_redo, v_sum.shape, t_,)
            v0 = _exact_phase(25, t_, 706884997512073/2251799813685248)
            v_sum[v_redo] = 0.06174253581630276*_sin_half_squared(v0) + 0.0306871573751505*_sin_pair(v0, 1.0) + (11045078086126142/5698460903507231)*_sin_half_squared(_exact_phase(25, t_)) + _wave(-0.03076367256938085, -0.004096802840924737, _exact_phase(25, t_, 1)) + 0.21141077704121883
        _put(out, part, v_sum)
    return out


def dynamic_coefficient_pickup_a3(t, *, out=None):
    """K_din^(1)(t) for the drive law a_3 of (30), lifting with pick-up (tau_0 from pickup_contact_time); Omega from natural_frequency. Specialized to scene 'hoist_drive_laws'. Eq (26), (28), (30).

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
    t = _checked('t', t, 'nonnegative', 'time from the start of the drive, s', (0.0, 1e7))
    shape = _broadcast(t=t)
    if out is None and not shape:      # one point: its own branch only
        return ((1688849860263936/690317380382883875)*_entire_3(_exact_phase(25, t)) if np.less_equal(t, 1) else _wave(-0.00164390331194681, -0.015481093958489723, _exact_phase(25, t, 1))) + ((562949953421312/17672124937801825)*_entire_1(_exact_phase(25, t)) if np.less_equal(t, 706884997512073/2251799813685248) else 0.06370935971463045*_sin_half_squared(_exact_phase(25, t, 706884997512073/2251799813685248)) + 0.03166470443730489*_sin_pair(_exact_phase(25, t, 706884997512073/2251799813685248), 1.0) + 0.21814532014268478) + 2*_sin_half_squared(_exact_phase(25, t))
    out = _out(out, shape)
    cells = _cells(shape, [[np.less_equal(t, 1)], [np.less_equal(t, 706884997512073/2251799813685248)]])
    for part in _blocks(cells[0]):
        t_, = _at(part, shape, t)
        v0 = _exact_phase(25, t_)
        _put(out, part, (1688849860263936/690317380382883875)*_entire_3(v0) + (562949953421312/17672124937801825)*_entire_1(v0) + 2*_sin_half_squared(v0))
    for part in _blocks(cells[1]):
        t_, = _at(part, shape, t)
        v0 = _exact_phase(25, t_)
        v1 = _exact_phase(25, 706884997512073/2251799813685248)
        v_sum = (1688849860263936/690317380382883875)*_entire_3(v0) - 0.03166470443730489*_cos_pair(v0, 1.0)*_sin_pair(v1, 1.0) + 0.03166470443730489*_cos_pair(v1, 1.0)*_sin_pair(v0, 1.0) + 2*_sin_half_squared(v0) + 0.06370935971463045*_sin_half_squared(_exact_phase(25, t_, 706884997512073/2251799813685248)) + 0.21814532014268478
        v_redo = _cancelled(v_sum, 0.24981002457998966)
        if v_redo is not None:      # where the fast sum cancels
            t_, = _at(v_redo, v_sum.shape, t_,)
            v0 = _exact_phase(25, t_, 706884997512073/2251799813685248)
            v1 = _exact_phase(25, t_)
            v_sum[v_redo] = (1688849860263936/690317380382883875)*_entire_3(v1) + 0.06370935971463045*_sin_half_squared(v0) + 0.03166470443730489*_sin_pair(v0, 1.0) + 2*_sin_half_squared(v1) + 0.21814532014268478
        _put(out, part, v_sum)
    for part in _blocks(cells[2]):
        t_, = _at(part, shape, t)
        v0 = _exact_phase(25, t_)
        v1 = _exact_phase(25, 1)
        v2 = _cos_pair(v1, 1.0)
        v3 = _sin_pair(v1, 1.0)
        v_sum = (-0.015481093958489723*v2 - 0.00164390331194681*v3)*_sin_pair(v0, 1.0) + (-0.00164390331194681*v2 + 0.015481093958489723*v3)*_cos_pair(v0, 1.0) + (562949953421312/17672124937801825)*_entire_1(v0) + 2*_sin_half_squared(v0)
        v_redo = _cancelled(v_sum, 0.017124997270436534)
        if v_redo is not None:      # where the fast sum cancels
            t_, = _at(v_redo, v_sum.shape, t_,)
            v0 = _exact_phase(25, t_)
            v_sum[v_redo] = (562949953421312/17672124937801825)*_entire_1(v0) + 2*_sin_half_squared(v0) + _wave(-0.00164390331194681, -0.015481093958489723, _exact_phase(25, t_, 1))
        _put(out, part, v_sum)
    for part in _blocks(cells[3]):
        t_, = _at(part, shape, t)
        v0 = _exact_phase(25, t_)
        v1 = _exact_phase(25, 706884997512073/2251799813685248)
        v2 = _exact_phase(25, 1)
        v3 = _cos_pair(v2, 1.0)
        v4 = _sin_pair(v2, 1.0)
        v_sum = (-0.015481093958489723*v3 - 0.00164390331194681*v4 + 0.03166470443730489*_cos_pair(v1, 1.0))*_sin_pair(v0, 1.0) + (-0.00164390331194681*v3 + 0.015481093958489723*v4 - 0.03166470443730489*_sin_pair(v1, 1.0))*_cos_pair(v0, 1.0) + 2*_sin_half_squared(v0) + 0.06370935971463045*_sin_half_squared(_exact_phase(25, t_, 706884997512073/2251799813685248)) + 0.21814532014268478
        v_redo = _cancelled(v_sum, 0.26693502185042617)
        if v_redo is not None:      # where the fast sum cancels
            t_, = _at(v_redo, v_sum.shape, t_,)
            v0 = _exact_phase(25, t_, 706884997512073/2251799813685248)
            v_sum[v_redo] = 0.06370935971463045*_sin_half_squared(v0) + 0.03166470443730489*_sin_pair(v0, 1.0) + 2*_sin_half_squared(_exact_phase(25, t_)) + _wave(-0.00164390331194681, -0.015481093958489723, _exact_phase(25, t_, 1)) + 0.21814532014268478
        _put(out, part, v_sum)
    return out


def dynamic_coefficient_pickup_a4(t, *, out=None):
    """K_din^(1)(t) for the drive law a_4 of (30), lifting with pick-up (tau_0 from pickup_contact_time); Omega from natural_frequency. Specialized to scene 'hoist_drive_laws'. Eq (26), (28), (30).

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
    t = _checked('t', t, 'nonnegative', 'time from the start of the drive, s', (0.0, 1e7))
    shape = _broadcast(t=t)
    if out is None and not shape:      # one point: its own branch only
        return (-497366283847729152/86289672547860484375*_entire_4(_exact_phase(25, t)) if np.less_equal(t, 1) else _wave(0.005766654001314742, -0.0006858624108939049, _exact_phase(25, t, 1))) + ((562949953421312/17672124937801825)*_entire_1(_exact_phase(25, t)) if np.less_equal(t, 706884997512073/2251799813685248) else 0.06370935971463045*_sin_half_squared(_exact_phase(25, t, 706884997512073/2251799813685248)) + 0.03166470443730489*_sin_pair(_exact_phase(25, t, 706884997512073/2251799813685248), 1.0) + 0.21814532014268478) + 2*_sin_half_squared(_exact_phase(25, t))
    out = _out(out, shape)
    cells = _cells(shape, [[np.less_equal(t, 1)], [np.less_equal(t, 706884997512073/2251799813685248)]])
    for part in _blocks(cells[0]):
        t_, = _at(part, shape, t)
        v0 = _exact_phase(25, t_)
        _put(out, part, -497366283847729152/86289672547860484375*_entire_4(v0) + (562949953421312/17672124937801825)*_entire_1(v0) + 2*_sin_half_squared(v0))
    for part in _blocks(cells[1]):
        t_, = _at(part, shape, t)
        v0 = _exact_phase(25, t_)
        v1 = _exact_phase(25, 706884997512073/2251799813685248)
        v_sum = -497366283847729152/86289672547860484375*_entire_4(v0) - 0.03166470443730489*_cos_pair(v0, 1.0)*_sin_pair(v1, 1.0) + 0.03166470443730489*_cos_pair(v1, 1.0)*_sin_pair(v0, 1.0) + 2*_sin_half_squared(v0) + 0.06370935971463045*_sin_half_squared(_exact_phase(25, t_, 706884997512073/2251799813685248)) + 0.21814532014268478
        v_redo = _cancelled(v_sum, 0.24981002457998966)
        if v_redo is not None:      # where the fast sum cancels
            t_, = _at(v_redo, v_sum.shape, t_,)
            v0 = _exact_phase(25, t_, 706884997512073/2251799813685248)
            v1 = _exact_phase(25, t_)
            v_sum[v_redo] = -497366283847729152/86289672547860484375*_entire_4(v1) + 0.06370935971463045*_sin_half_squared(v0) + 0.03166470443730489*_sin_pair(v0, 1.0) + 2*_sin_half_squared(v1) + 0.21814532014268478
        _put(out, part, v_sum)
    for part in _blocks(cells[2]):
        t_, = _at(part, shape, t)
        v0 = _exact_phase(25, t_)
        v1 = _exact_phase(25, 1)
        v2 = _cos_pair(v1, 1.0)
        v3 = _sin_pair(v1, 1.0)
        v_sum = (-0.0006858624108939049*v2 + 0.005766654001314742*v3)*_sin_pair(v0, 1.0) + (0.005766654001314742*v2 + 0.0006858624108939049*v3)*_cos_pair(v0, 1.0) + (562949953421312/17672124937801825)*_entire_1(v0) + 2*_sin_half_squared(v0)
        v_redo = _cancelled(v_sum, 0.006452516412208647)
        if v_redo is not None:      # where the fast sum cancels
            t_, = _at(v_redo, v_sum.shape, t_,)
            v0 = _exact_phase(25, t_)
            v_sum[v_redo] = (562949953421312/17672124937801825)*_entire_1(v0) + 2*_sin_half_squared(v0) + _wave(0.005766654001314742, -0.0006858624108939049, _exact_phase(25, t_, 1))
        _put(out, part, v_sum)
    for part in _blocks(cells[3]):
        t_, = _at(part, shape, t)
        v0 = _exact_phase(25, t_)
        v1 = _exact_phase(25, 706884997512073/2251799813685248)
        v2 = _exact_phase(25, 1)
        v3 = _cos_pair(v2, 1.0)
        v4 = _sin_pair(v2, 1.0)
        v_sum = (-0.0006858624108939049*v3 + 0.005766654001314742*v4 + 0.03166470443730489*_cos_pair(v1, 1.0))*_sin_pair(v0, 1.0) + (0.005766654001314742*v3 + 0.0006858624108939049*v4 - 0.03166470443730489*_sin_pair(v1, 1.0))*_cos_pair(v0, 1.0) + 2*_sin_half_squared(v0) + 0.06370935971463045*_sin_half_squared(_exact_phase(25, t_, 706884997512073/2251799813685248)) + 0.21814532014268478
        v_redo = _cancelled(v_sum, 0.2562625409921983)
        if v_redo is not None:      # where the fast sum cancels
            t_, = _at(v_redo, v_sum.shape, t_,)
            v0 = _exact_phase(25, t_, 706884997512073/2251799813685248)
            v_sum[v_redo] = 0.06370935971463045*_sin_half_squared(v0) + 0.03166470443730489*_sin_pair(v0, 1.0) + 2*_sin_half_squared(_exact_phase(25, t_)) + _wave(0.005766654001314742, -0.0006858624108939049, _exact_phase(25, t_, 1)) + 0.21814532014268478
        _put(out, part, v_sum)
    return out


def dynamic_coefficient_from_weight_a1(t, *, out=None):
    """K_din^(2)(t) for the drive law a_1 of (30), lifting from weight; Omega from natural_frequency. Specialized to scene 'hoist_drive_laws'. Eq (27), (28), (30).

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
    t = _checked('t', t, 'nonnegative', 'time from the start of the drive, s', (0.0, 1e7))
    shape = _broadcast(t=t)
    if out is None and not shape:      # one point: its own branch only
        return ((281474976710656/5663276531418399)*_sin_half_squared(_exact_phase(25, t)) if np.less_equal(t, 1) else _wave(0.00021861799544051693, -0.003289059396067918, _exact_phase(25, t, 1))) + 5522539043063071/5663276531418399
    out = _out(out, shape)
    cells = _cells(shape, [[np.less_equal(t, 1)]])
    for part in _blocks(cells[0]):
        t_, = _at(part, shape, t)
        _put(out, part, (281474976710656/5663276531418399)*_sin_half_squared(_exact_phase(25, t_)) + 5522539043063071/5663276531418399)
    for part in _blocks(cells[1]):
        t_, = _at(part, shape, t)
        _put(out, part, _wave(0.00021861799544051693, -0.003289059396067918, _exact_phase(25, t_, 1)) + 5522539043063071/5663276531418399)
    return out


def dynamic_coefficient_from_weight_a2(t, *, out=None):
    """K_din^(2)(t) for the drive law a_2 of (30), lifting from weight; Omega from natural_frequency. Specialized to scene 'hoist_drive_laws'. Eq (27), (28), (30).

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
    t = _checked('t', t, 'nonnegative', 'time from the start of the drive, s', (0.0, 1e7))
    shape = _broadcast(t=t)
    if out is None and not shape:      # one point: its own branch only
        return ((140737488355328/5663276531418399)*_entire_2(_exact_phase(25, t)) if np.less_equal(t, 1) else _wave(-0.02476383901260896, -0.0032978041158855387, _exact_phase(25, t, 1))) + 5522539043063071/5663276531418399
    out = _out(out, shape)
    cells = _cells(shape, [[np.less_equal(t, 1)]])
    for part in _blocks(cells[0]):
        t_, = _at(part, shape, t)
        _put(out, part, (140737488355328/5663276531418399)*_entire_2(_exact_phase(25, t_)) + 5522539043063071/5663276531418399)
    for part in _blocks(cells[1]):
        t_, = _at(part, shape, t)
        _put(out, part, _wave(-0.02476383901260896, -0.0032978041158855387, _exact_phase(25, t_, 1)) + 5522539043063071/5663276531418399)
    return out


def dynamic_coefficient_from_weight_a3(t, *, out=None):
    """K_din^(2)(t) for the drive law a_3 of (30), lifting from weight; Omega from natural_frequency. Specialized to scene 'hoist_drive_laws'. Eq (27), (28), (30).

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
    t = _checked('t', t, 'nonnegative', 'time from the start of the drive, s', (0.0, 1e7))
    shape = _broadcast(t=t)
    if out is None and not shape:      # one point: its own branch only
        return ((6755399441055744/3451586901914419375)*_entire_3(_exact_phase(25, t)) if np.less_equal(t, 1) else _wave(-0.001315122649557448, -0.012384875166791778, _exact_phase(25, t, 1))) + 1
    out = _out(out, shape)
    cells = _cells(shape, [[np.less_equal(t, 1)]])
    for part in _blocks(cells[0]):
        t_, = _at(part, shape, t)
        _put(out, part, (6755399441055744/3451586901914419375)*_entire_3(_exact_phase(25, t_)) + 1)
    for part in _blocks(cells[1]):
        t_, = _at(part, shape, t)
        _put(out, part, _wave(-0.001315122649557448, -0.012384875166791778, _exact_phase(25, t_, 1)) + 1)
    return out


def dynamic_coefficient_from_weight_a4(t, *, out=None):
    """K_din^(2)(t) for the drive law a_4 of (30), lifting from weight; Omega from natural_frequency. Specialized to scene 'hoist_drive_laws'. Eq (27), (28), (30).

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
    t = _checked('t', t, 'nonnegative', 'time from the start of the drive, s', (0.0, 1e7))
    shape = _broadcast(t=t)
    if out is None and not shape:      # one point: its own branch only
        return (-1989465135390916608/431448362739302421875*_entire_4(_exact_phase(25, t)) if np.less_equal(t, 1) else _wave(0.004613323201051793, -0.0005486899287151239, _exact_phase(25, t, 1))) + 1
    out = _out(out, shape)
    cells = _cells(shape, [[np.less_equal(t, 1)]])
    for part in _blocks(cells[0]):
        t_, = _at(part, shape, t)
        _put(out, part, 1 - 1989465135390916608/431448362739302421875*_entire_4(_exact_phase(25, t_)))
    for part in _blocks(cells[1]):
        t_, = _at(part, shape, t)
        _put(out, part, _wave(0.004613323201051793, -0.0005486899287151239, _exact_phase(25, t_, 1)) + 1)
    return out


def optimal_coefficient_from_weight_a1(t, *, out=None):
    """k~_din1^(opt)(t) from weight, 0 <= t <= t_n. Specialized to scene 'hoist_drive_laws'. Eq (63), (65).

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
                return np.float64(1)
            except (ArithmeticError, ValueError):
                pass
    t = _checked('t', t, 'nonnegative', 'time from the start of the drive, s', (0.0, 1e7))
    shape = _broadcast(t=t)
    return _into(out, shape, 1)


def optimal_coefficient_from_weight_a2(t, *, out=None):
    """k~_din2^(opt)(t) from weight, 0 <= t <= t_n. Specialized to scene 'hoist_drive_laws'. Eq (63), (65).

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
                return np.float64(1 - t)
            except (ArithmeticError, ValueError):
                pass
    t = _checked('t', t, 'nonnegative', 'time from the start of the drive, s', (0.0, 1e7))
    shape = _broadcast(t=t)
    if out is None and not shape:
        return 1 - t
    out = _out(out, shape)
    for _o, (t,) in _spans(out, shape, t):
        np.negative(t, out=_o)
        np.add(_o, 1, out=_o)
    return out


def optimal_coefficient_from_weight_a3(t, *, out=None):
    """k~_din3^(opt)(t) from weight, 0 <= t <= t_n. Specialized to scene 'hoist_drive_laws'. Eq (63), (65).

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
                return np.float64(12*t*(t - 1)**2)
            except (ArithmeticError, ValueError):
                pass
    t = _checked('t', t, 'nonnegative', 'time from the start of the drive, s', (0.0, 1e7))
    shape = _broadcast(t=t)
    if out is None and not shape:
        return 12*t*(t - 1)**2
    out = _out(out, shape)
    for _o, (t,) in _spans(out, shape, t):
        _w0 = np.empty_like(_o)
        np.add(t, -1, out=_w0)
        np.square(_w0, out=_w0)
        np.multiply(t, _w0, out=_o)
        np.multiply(_o, 12, out=_o)
    return out


def optimal_coefficient_from_weight_a4(t, *, out=None):
    """k~_din4^(opt)(t) from weight, 0 <= t <= t_n. Specialized to scene 'hoist_drive_laws'. Eq (63), (65).

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
                return np.float64(-60*t**2*(t - 1)**3)
            except (ArithmeticError, ValueError):
                pass
    t = _checked('t', t, 'nonnegative', 'time from the start of the drive, s', (0.0, 1e7))
    shape = _broadcast(t=t)
    if out is None and not shape:
        return -60*t**2*_cube(t - 1)
    out = _out(out, shape)
    for _o, (t,) in _spans(out, shape, t):
        np.square(t, out=_o)
        _w0 = np.empty_like(_o)
        np.add(t, -1, out=_w0)
        _w1 = np.empty_like(_o)
        np.square(_w0, out=_w1)
        np.multiply(_w0, _w1, out=_w0)
        np.multiply(_o, _w0, out=_o)
        np.multiply(_o, -60, out=_o)
    return out
