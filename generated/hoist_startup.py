"""Numeric functions for derivation 'hoist_startup'. Generated; do not edit.

Source: crane_sym.derivations.hoist_startup (paper 002_f8509f3826f601de.txt:
Duhamel's integral for the start-up of a crane hoist: rope loads and dynamic factors).
Equations: (2), (26), (27), (28), (29), (30), (38), (42), (45), (46), (47), (51), (52), (53), (63), (64), (65), (66).
Printed by SymPy 1.14.0 with crane_sym 0.1.0; regenerate with `crane-sym generate`.

Functions and argument order:
    natural_frequency(m1, m2, C) -> [rad/s]    eq (2)
    pickup_contact_time(m2, g, C, v0) -> [s]    eq (29)
    dynamic_coefficient_instant(t, Omega) -> [1]    eq (38)
    dynamic_coefficient_ramp(t, Omega, t_n) -> [1]    eq (42)
    dynamic_coefficient_pulse(t, Omega, theta) -> [1]    eq (45), (46)
    pulse_peak_factor(Omega, theta) -> [1]    eq (47)
    pulse_peak_time(Omega, theta) -> [s]    eq (47)
    dynamic_coefficient_ramp_hold(t, Omega, theta) -> [1]    eq (51), (52)
    ramp_hold_peak_factor(Omega, theta) -> [1]    eq (53)
    dynamic_coefficient_pickup_a1(t, Omega, tau_0, m1, m2, g, v0, t_n) -> [1]    eq (26), (28), (30)
    dynamic_coefficient_pickup_a2(t, Omega, tau_0, m1, m2, g, v0, t_n) -> [1]    eq (26), (28), (30)
    dynamic_coefficient_pickup_a3(t, Omega, tau_0, m1, m2, g, v0, t_n) -> [1]    eq (26), (28), (30)
    dynamic_coefficient_pickup_a4(t, Omega, tau_0, m1, m2, g, v0, t_n) -> [1]    eq (26), (28), (30)
    dynamic_coefficient_from_weight_a1(t, Omega, m1, m2, g, v0, t_n) -> [1]    eq (27), (28), (30)
    dynamic_coefficient_from_weight_a2(t, Omega, m1, m2, g, v0, t_n) -> [1]    eq (27), (28), (30)
    dynamic_coefficient_from_weight_a3(t, Omega, m1, m2, g, v0, t_n) -> [1]    eq (27), (28), (30)
    dynamic_coefficient_from_weight_a4(t, Omega, m1, m2, g, v0, t_n) -> [1]    eq (27), (28), (30)
    optimal_coefficient_from_weight_a1(t, t_n) -> [1]    eq (63), (65)
    optimal_coefficient_pickup_a1(t, t_n, v0, g, tau_0) -> [1]    eq (64), (65), (66)
    optimal_coefficient_from_weight_a2(t, t_n) -> [1]    eq (63), (65)
    optimal_coefficient_pickup_a2(t, t_n, v0, g, tau_0) -> [1]    eq (64), (65), (66)
    optimal_coefficient_from_weight_a3(t, t_n) -> [1]    eq (63), (65)
    optimal_coefficient_pickup_a3(t, t_n, v0, g, tau_0) -> [1]    eq (64), (65), (66)
    optimal_coefficient_from_weight_a4(t, t_n) -> [1]    eq (63), (65)
    optimal_coefficient_pickup_a4(t, t_n, v0, g, tau_0) -> [1]    eq (64), (65), (66)
"""

import math

import numpy as np

__all__ = ['natural_frequency', 'pickup_contact_time', 'dynamic_coefficient_instant', 'dynamic_coefficient_ramp', 'dynamic_coefficient_pulse', 'pulse_peak_factor', 'pulse_peak_time', 'dynamic_coefficient_ramp_hold', 'ramp_hold_peak_factor', 'dynamic_coefficient_pickup_a1', 'dynamic_coefficient_pickup_a2', 'dynamic_coefficient_pickup_a3', 'dynamic_coefficient_pickup_a4', 'dynamic_coefficient_from_weight_a1', 'dynamic_coefficient_from_weight_a2', 'dynamic_coefficient_from_weight_a3', 'dynamic_coefficient_from_weight_a4', 'optimal_coefficient_from_weight_a1', 'optimal_coefficient_pickup_a1', 'optimal_coefficient_from_weight_a2', 'optimal_coefficient_pickup_a2', 'optimal_coefficient_from_weight_a3', 'optimal_coefficient_pickup_a3', 'optimal_coefficient_from_weight_a4', 'optimal_coefficient_pickup_a4']


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


def _offset_back(level, gap, b, c, x):
    """level + b*cos(x) + c*sin(x) without cancellation where the wave swings
    back towards zero; x is a phase pair. Written level + a*cos(x - d)
    (|d| <= pi/2, a = ±hypot(b, c)); where level and a*cos(x - d) have
    opposite signs it is s*gap/(|level| + |a|) + s*|a|*(1 + q*cos(x - d)),
    s = sign(level), q = s*sign(a), the last factor as 2*cos(...)**2 or
    2*sin(...)**2."""
    hi, lo = _pair(x)
    sb = np.where(b < 0, -1.0, 1.0)
    r = np.hypot(b, c)
    theta, err = _two_sum(hi, -np.arctan2(c * sb, np.abs(b)))
    lo = err + lo
    s2, c2 = np.sin(0.5 * theta), np.cos(0.5 * theta)  # cos, sin of theta from these
    cos_theta = (c2 - s2) * (c2 + s2) - 2.0 * s2 * c2 * lo
    s = np.where(level < 0, -1.0, 1.0)
    q = s * sb
    if np.ndim(q) == 0:                                 # one side for every point
        half = c2 - s2 * (0.5 * lo) if q > 0 else s2 + c2 * (0.5 * lo)
    else:
        half = np.where(q > 0, c2 - s2 * (0.5 * lo), s2 + c2 * (0.5 * lo))
    back = s * (gap / (np.abs(level) + r) + 2.0 * r * half * half)
    return np.where(q * cos_theta >= 0, level + sb * r * cos_theta, back)


def _offset_wave(level, gap, b, c, x):
    """level + b*cos(x) + c*sin(x) for a phase pair x, as written where the
    level and the wave do not cancel (the sines shared with other kernels on
    x), and by _offset_back where they do (|sum| < |level|/2). The caller
    supplies gap = level**2 - b**2 - c**2 accurately."""
    s, co = _sincos_pair(x, 1.0)
    direct = level + (b * co + c * s)
    near = np.abs(direct) < 0.5 * np.abs(level)
    if not np.any(near):
        return direct
    direct = np.array(direct, dtype=float)
    pick = lambda v: np.broadcast_to(v, direct.shape)[near]   # noqa: E731
    direct[near] = _offset_back(*map(pick, (level, gap, b, c)), tuple(map(pick, _pair(x))))
    return direct


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
    """1 - 4*sin(z/2)**2/z**2:
    entire, ~z**2 at 0; its Taylor series where |z| < 4.0.
    z is a phase: a pair (hi, lo) or a double."""
    w = z
    z = _pair(w)[0]
    small = np.abs(z) < 4.0
    z_ = np.where(small, 4.0, z)
    h0 = _sin_half_squared(w)
    return _taylor_where(-4*h0/z_**2 + 1, small, z, 2, 2,
                         (0.08333333333333333, -0.002777777777777778, 4.96031746031746e-05, -5.511463844797178e-07, 4.17535139757362e-09, -2.294149119545945e-11, 9.55895466477477e-14, -3.123841393717245e-16, 8.22063524662433e-19, -1.779358278490115e-21, 3.2234751421922368e-24, -4.959192526449595e-27, 6.559778474139676e-30, -7.539975257631811e-33, 7.600781509709487e-36,))


def _entire_2(z):
    """-sin(z)/z:
    entire, ~1 at 0; its Taylor series where |z| < 0.42044820762685725.
    z is a phase: a pair (hi, lo) or a double."""
    w = z
    z = _pair(w)[0]
    small = np.abs(z) < 0.42044820762685725
    z_ = np.where(small, 0.42044820762685725, z)
    s0, c0 = _sincos_pair(w, 1.0)
    return _taylor_where(-s0/z_, small, z, 0, 2,
                         (-1.0, 0.16666666666666666, -0.008333333333333333, 0.0001984126984126984, -2.7557319223985893e-06, 2.505210838544172e-08, -1.6059043836821613e-10, 7.647163731819816e-13,))


def _entire_3(z):
    """2*sin(z/2)**2/z:
    entire, ~z**1 at 0; its Taylor series where |z| < 0.015625.
    z is a phase: a pair (hi, lo) or a double."""
    w = z
    z = _pair(w)[0]
    small = np.abs(z) < 0.015625
    z_ = np.where(small, 0.015625, z)
    h0 = _sin_half_squared(w)
    return _taylor_where(2*h0/z_, small, z, 1, 2,
                         (0.5, -0.041666666666666664, 0.001388888888888889, -2.48015873015873e-05,))


def _entire_4(z):
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


def _entire_5(z):
    """-cos(z) + sin(z)/z:
    entire, ~z**2 at 0; its Taylor series where |z| < 1.681792830507429.
    z is a phase: a pair (hi, lo) or a double."""
    w = z
    z = _pair(w)[0]
    small = np.abs(z) < 1.681792830507429
    z_ = np.where(small, 1.681792830507429, z)
    s0, c0 = _sincos_pair(w, 1.0)
    return _taylor_where(-c0 + s0/z_, small, z, 2, 2,
                         (0.3333333333333333, -0.03333333333333333, 0.0011904761904761906, -2.2045855379188714e-05, 2.505210838544172e-07, -1.9270852604185937e-09, 1.0706029224547743e-11, -4.498331606952833e-14, 1.4797143443923793e-16, -3.9145882126782523e-19, 8.509974375387505e-22,))


def _entire_6(z):
    """-sin(z) + 2*sin(z/2)**2/z:
    entire, ~z**1 at 0; its Taylor series where |z| < 2.8284271247461903.
    z is a phase: a pair (hi, lo) or a double."""
    w = z
    z = _pair(w)[0]
    small = np.abs(z) < 2.8284271247461903
    z_ = np.where(small, 2.8284271247461903, z)
    h0 = _sin_half_squared(w)
    s1, c1 = _sincos_pair(w, 1.0)
    return _taylor_where(2*h0/z_ - s1, small, z, 1, 2,
                         (-0.5, 0.125, -0.006944444444444444, 0.00017361111111111112, -2.48015873015873e-06, 2.296443268665491e-08, -1.4911969277048643e-10, 7.169215998581078e-13, -2.6552651846596585e-15, 7.809603484293113e-18, -1.8683261924146203e-20, 3.706996413521072e-23, -6.198990658061994e-26, 8.855700940088562e-29, -1.0932964123566126e-31,))


def _entire_7(z):
    """1 - sin(z)/z:
    entire, ~z**2 at 0; its Taylor series where |z| < 2.378414230005442.
    z is a phase: a pair (hi, lo) or a double."""
    w = z
    z = _pair(w)[0]
    small = np.abs(z) < 2.378414230005442
    z_ = np.where(small, 2.378414230005442, z)
    s0, c0 = _sincos_pair(w, 1.0)
    return _taylor_where(-s0/z_ + 1, small, z, 2, 2,
                         (0.16666666666666666, -0.008333333333333333, 0.0001984126984126984, -2.7557319223985893e-06, 2.505210838544172e-08, -1.6059043836821613e-10, 7.647163731819816e-13, -2.8114572543455206e-15, 8.22063524662433e-18, -1.9572941063391263e-20, 3.868170170630684e-23, -6.446950284384474e-26,))


def _entire_8(z):
    """sin(z)/(2*z) + 2*cos(z)/z**2 + z**(-2) - 3*sin(z)/z**3:
    entire, ~z**2 at 0; its Taylor series where |z| < 3.363585661014858.
    z is a phase: a pair (hi, lo) or a double."""
    w = z
    z = _pair(w)[0]
    small = np.abs(z) < 3.363585661014858
    z_ = np.where(small, 3.363585661014858, z)
    s0, c0 = _sincos_pair(w, 1.0)
    return _taylor_where(2*c0/z_**2 + (1/2)*s0/z_ - 3*s0/_cube(z_) + z_**(-2.0), small, z, 2, 2,
                         (-0.025, 0.001984126984126984, -5.787037037037037e-05, 9.018759018759019e-07, -8.832474110251888e-09, 5.964787710819457e-11, -2.952030117062797e-13, 1.118006393540909e-15, -3.3469729218399058e-18, 8.123157358324436e-21, -1.6310784219492718e-23, 2.755106959138664e-26, -3.969796973143149e-29, 4.937467668707283e-32, -5.355096063658957e-35,))


def _entire_9(z):
    """cos(z)/(6*z) - 2*sin(z)/(3*z**2) - cos(z)/z**3 + z**(-3):
    entire, ~z**1 at 0; its Taylor series where |z| < 3.363585661014858.
    z is a phase: a pair (hi, lo) or a double."""
    w = z
    z = _pair(w)[0]
    small = np.abs(z) < 3.363585661014858
    z_ = np.where(small, 3.363585661014858, z)
    s0, c0 = _sincos_pair(w, 1.0)
    return _taylor_where((1/6)*c0/z_ - c0/_cube(z_) - 2/3*s0/z_**2 + z_**(-3.0), small, z, 1, 2,
                         (-0.013888888888888888, 0.002777777777777778, -0.0001240079365079365, 2.57201646090535e-06, -3.131513548180215e-08, 2.5235640315005394e-10, -1.4497747908241734e-12, 6.24768278743449e-15, -2.0962619878892042e-17, 5.63463454855203e-20, -1.241037929744011e-22, 2.2812285621668135e-25, -3.553213340158991e-28, 4.750184412308041e-31, -5.510566594539378e-34,))


def _entire_10(z):
    """z/4 - 3/(2*z) + 3*sin(z)/(2*z**2):
    entire, ~z**3 at 0; its Taylor series where |z| < 4.756828460010884.
    z is a phase: a pair (hi, lo) or a double."""
    w = z
    z = _pair(w)[0]
    small = np.abs(z) < 4.756828460010884
    z_ = np.where(small, 4.756828460010884, z)
    s0, c0 = _sincos_pair(w, 1.0)
    return _taylor_where((3/2)*s0/z_**2 + (1/4)*z_ - (3/2)/z_, small, z, 3, 2,
                         (0.0125, -0.00029761904761904765, 4.133597883597884e-06, -3.757816257816258e-08, 2.408856575523242e-10, -1.1470745597729724e-12, 4.217185881518281e-15, -1.2330952869936495e-17, 2.935941159508689e-20, -5.802255255946026e-23, 9.67042542657671e-26, -1.3775534795693318e-28, 1.6964944329671575e-31, -1.8241875623302768e-34, 1.7274503431157926e-37, -1.4516389437947837e-40,))


def _entire_11(z):
    """cos(z)/z + 2/z - 3*sin(z)/z**2:
    entire, ~z**3 at 0; its Taylor series where |z| < 3.363585661014858.
    z is a phase: a pair (hi, lo) or a double."""
    w = z
    z = _pair(w)[0]
    small = np.abs(z) < 3.363585661014858
    z_ = np.where(small, 3.363585661014858, z)
    s0, c0 = _sincos_pair(w, 1.0)
    return _taylor_where(c0/z_ - 3*s0/z_**2 + 2/z_, small, z, 3, 2,
                         (0.016666666666666666, -0.0007936507936507937, 1.6534391534391536e-05, -2.0041686708353376e-07, 1.6059043836821615e-09, -9.17659647818378e-12, 3.936040156083729e-14, -1.3153016394598927e-16, 3.523129391410427e-19, -7.736340341261368e-22, 1.4183290625645841e-24, -2.204085567310931e-27, 2.9405903504764064e-30, -3.4051501163498504e-33,))


def _entire_12(z):
    """-sin(z)/4 - cos(z)/z - 1/(2*z) + 3*sin(z)/(2*z**2):
    entire, ~z**3 at 0; its Taylor series where |z| < 3.363585661014858.
    z is a phase: a pair (hi, lo) or a double."""
    w = z
    z = _pair(w)[0]
    small = np.abs(z) < 3.363585661014858
    z_ = np.where(small, 3.363585661014858, z)
    s0, c0 = _sincos_pair(w, 1.0)
    return _taylor_where(-c0/z_ - 1/4*s0 + (3/2)*s0/z_**2 - (1/2)/z_, small, z, 3, 2,
                         (0.0125, -0.000992063492063492, 2.8935185185185186e-05, -4.5093795093795094e-07, 4.416237055125944e-09, -2.9823938554097285e-11, 1.4760150585313984e-13, -5.590031967704545e-16, 1.6734864609199529e-18, -4.061578679162218e-21, 8.155392109746359e-24, -1.377553479569332e-26, 1.9848984865715744e-29, -2.4687338343536413e-32, 2.6775480318294786e-35,))


def _entire_13(z):
    """-cos(z)/(24*z**2) + 3*sin(z)/(8*z**3) + 3*cos(z)/(2*z**4) + z**(-4) - 5*sin(z)/(2*z**5):
    entire, ~z**2 at 0; its Taylor series where |z| < 4.756828460010884.
    z is a phase: a pair (hi, lo) or a double."""
    w = z
    z = _pair(w)[0]
    small = np.abs(z) < 4.756828460010884
    z_ = np.where(small, 4.756828460010884, z)
    s0, c0 = _sincos_pair(w, 1.0)
    return _taylor_where(-1/24*c0/z_**2 + (3/2)*c0/_fourth(z_) + (3/8)*s0/_cube(z_) - 5/2*s0/z_**5 + z_**(-4.0), small, z, 2, 2,
                         (-0.0001984126984126984, 1.3778659611992945e-05, -3.5072951739618406e-07, 4.8177131510464845e-09, -4.205940052500899e-11, 2.558426101454424e-13, -1.150888934527406e-15, 3.992879976931817e-18, -1.102428498629745e-20, 2.4820758594880223e-23, -4.646947071080546e-26, 7.351475876191016e-29, -9.960064090323311e-32, 1.168908065508353e-34, -1.2000215268703545e-37, 1.0869128428012994e-40, -8.750908515376675e-44,))


def _entire_14(z):
    """-(3/(10*z**3) - 2/z**5)*sin(z/2)**2 + sin(z)/(60*z**2) + 1/(10*z**3) - 3*sin(z)/(5*z**4):
    entire, ~z**1 at 0; its Taylor series where |z| < 5.656854249492381.
    z is a phase: a pair (hi, lo) or a double."""
    w = z
    z = _pair(w)[0]
    small = np.abs(z) < 5.656854249492381
    z_ = np.where(small, 5.656854249492381, z)
    h0 = _sin_half_squared(w)
    s1, c1 = _sincos_pair(w, 1.0)
    return _taylor_where(-h0*((3/10)/_cube(z_) - 2/z_**5) + (1/60)*s1/z_**2 - 3/5*s1/_fourth(z_) + (1/10)/_cube(z_), small, z, 1, 2,
                         (-0.0001388888888888889, 2.48015873015873e-05, -9.645061728395062e-07, 1.75364758698092e-08, -1.8926730236254046e-10, 1.3669305170627923e-12, -7.106739170706734e-15, 2.795015983852272e-17, -8.620990859284605e-20, 2.1436109695578373e-22, -4.391364982171116e-25, 7.543745245260627e-28, -1.1027213814286523e-30, 1.3886627818239233e-33, -1.5225273122167623e-36, 1.4666929772859888e-39, -1.2513799176988645e-42, 9.523047502027558e-46, -6.504598011727247e-49,))


def _entire_15(z):
    """-z**2/2 + 10 - 60/z**2 + 60*sin(z)/z**3:
    entire, ~z**4 at 0; its Taylor series where |z| < 4.756828460010884.
    z is a phase: a pair (hi, lo) or a double."""
    w = z
    z = _pair(w)[0]
    small = np.abs(z) < 4.756828460010884
    z_ = np.where(small, 4.756828460010884, z)
    s0, c0 = _sincos_pair(w, 1.0)
    return _taylor_where(60*s0/_cube(z_) - 1/2*z_**2 + 10 - 60/z_**2, small, z, 4, 2,
                         (-0.011904761904761904, 0.00016534391534391533, -1.503126503126503e-06, 9.635426302092969e-09, -4.58829823909189e-11, 1.6868743526073125e-13, -4.932381147974598e-16, 1.1743764638034756e-18, -2.3209021023784103e-21, 3.868170170630684e-24, -5.510213918277328e-27, 6.78597773186863e-30, -7.296750249321107e-33, 6.909801372463171e-36, -5.806555775179134e-39,))


def _entire_16(z):
    """-12 + 36*cos(z)/z**2 + 144/z**2 - 180*sin(z)/z**3:
    entire, ~z**4 at 0; its Taylor series where |z| < 4.756828460010884.
    z is a phase: a pair (hi, lo) or a double."""
    w = z
    z = _pair(w)[0]
    small = np.abs(z) < 4.756828460010884
    z_ = np.where(small, 4.756828460010884, z)
    s0, c0 = _sincos_pair(w, 1.0)
    return _taylor_where(36*c0/z_**2 - 180*s0/_cube(z_) - 12 + 144/z_**2, small, z, 4, 2,
                         (-0.014285714285714285, 0.0003968253968253968, -5.411255411255411e-06, 4.625004625004625e-08, -2.752978943455134e-10, 1.214549533877265e-12, -4.143200164298662e-15, 1.1274014052513367e-17, -2.5065742705686833e-20, 4.6418042047568206e-23, -7.273482372126072e-26, 9.771807933890828e-29, -1.1382930388940928e-31, 1.1608466305738125e-34, -1.0451800395322443e-37, 8.369810126384338e-41,))


def _entire_17(z):
    """3 - 9*sin(z)/z - 72*cos(z)/z**2 - 108/z**2 + 180*sin(z)/z**3:
    entire, ~z**4 at 0; its Taylor series where |z| < 4.756828460010884.
    z is a phase: a pair (hi, lo) or a double."""
    w = z
    z = _pair(w)[0]
    small = np.abs(z) < 4.756828460010884
    z_ = np.where(small, 4.756828460010884, z)
    s0, c0 = _sincos_pair(w, 1.0)
    return _taylor_where(-72*c0/z_**2 - 9*s0/z_ + 180*s0/_cube(z_) + 3 - 108/z_**2, small, z, 4, 2,
                         (-0.010714285714285714, 0.000496031746031746, -9.46969696969697e-06, 1.0406260406260406e-07, -7.570692094501618e-10, 3.9472859851011115e-12, -1.5537000616119984e-14, 4.791455972318181e-17, -1.1906227785201244e-19, 2.436947207497331e-22, -4.182252363972492e-25, 6.107379958681767e-28, -7.683478012535127e-31, 8.416138071660142e-34, -8.100145306374893e-37, 6.905093354267079e-40,))


def _entire_18(z):
    """-cos(z) + 9*sin(z)/z + 36*cos(z)/z**2 + 24/z**2 - 60*sin(z)/z**3:
    entire, ~z**4 at 0; its Taylor series where |z| < 4.756828460010884.
    z is a phase: a pair (hi, lo) or a double."""
    w = z
    z = _pair(w)[0]
    small = np.abs(z) < 4.756828460010884
    z_ = np.where(small, 4.756828460010884, z)
    s0, c0 = _sincos_pair(w, 1.0)
    return _taylor_where(-c0 + 36*c0/z_**2 + 9*s0/z_ - 60*s0/_cube(z_) + 24/z_**2, small, z, 4, 2,
                         (-0.004761904761904762, 0.00033068783068783067, -8.417508417508417e-06, 1.1562511562511562e-07, -1.0094256126002158e-09, 6.140222643490617e-12, -2.7621334428657748e-14, 9.582911944636362e-17, -2.645828396711388e-19, 5.956982062771254e-22, -1.115267297059331e-24, 1.7643542102858438e-27, -2.3904153816775947e-30, 2.8053793572200472e-33, -2.880051664488851e-36, 2.6085908227231188e-39, -2.100218043690402e-42,))


def natural_frequency(m1, m2, C, *, out=None):
    """Natural circular frequency Omega of the rope stretch. Eq (2).

    Parameters
    ----------
    m1 : array_like
        reduced mass of the drive (first mass) [kg], > 0; served from 1e-9 to 1e17
    m2 : array_like
        mass of the load (second mass) [kg], > 0; served from 0.001 to 5e10
    C : array_like
        stiffness of the rope (elastic link) [N/m], > 0; served from 0.1 to 1e14
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
            and (type(C) in (float, int) or type(C) is np.float64)):
        if (1e-9 <= m1 <= 1e17 and 0.001 <= m2 <= 5e10 and 0.1 <= C <= 1e14):
            try:    # a failed check or a math error: the array path decides
                return np.float64(math.sqrt(C)*math.sqrt(m1 + m2)/(math.sqrt(m1)*math.sqrt(m2)))
            except (ArithmeticError, ValueError):
                pass
    m1 = _checked('m1', m1, 'positive', 'reduced mass of the drive (first mass), kg', (1e-9, 1e17))
    m2 = _checked('m2', m2, 'positive', 'mass of the load (second mass), kg', (0.001, 5e10))
    C  = _checked('C', C, 'positive', 'stiffness of the rope (elastic link), N/m', (0.1, 1e14))
    shape = _broadcast(m1=m1, m2=m2, C=C)
    return _into(out, shape, np.sqrt(C)*np.sqrt(m1 + m2)/(np.sqrt(m1)*np.sqrt(m2)))


def pickup_contact_time(m2, g, C, v0, *, out=None):
    """Duration tau_0 of the load's contact with the ground (pick-up). Eq (29).

    Parameters
    ----------
    m2 : array_like
        mass of the load (second mass) [kg], > 0; served from 0.001 to 5e10
    g : array_like
        acceleration of gravity [m/s^2], > 0; served from 9.8e-6 to 9.82e6
    C : array_like
        stiffness of the rope (elastic link) [N/m], > 0; served from 0.1 to 1e14
    v0 : array_like
        steady hoisting speed after the start [m/s], > 0; served from 1e-7 to 1e6
    out : ndarray, optional
        float64 array of the broadcast shape; the result is written into it and returned.

    Returns
    -------
    ndarray
        [s], broadcast over the arguments.
    """
    if (out is None
            and (type(m2) in (float, int) or type(m2) is np.float64)
            and (type(g) in (float, int) or type(g) is np.float64)
            and (type(C) in (float, int) or type(C) is np.float64)
            and (type(v0) in (float, int) or type(v0) is np.float64)):
        if (0.001 <= m2 <= 5e10 and 9.8e-6 <= g <= 9.82e6 and 0.1 <= C <= 1e14
                and 1e-7 <= v0 <= 1e6):
            try:    # a failed check or a math error: the array path decides
                return np.float64(g*m2/(C*v0))
            except (ArithmeticError, ValueError):
                pass
    m2 = _checked('m2', m2, 'positive', 'mass of the load (second mass), kg', (0.001, 5e10))
    g  = _checked('g', g, 'positive', 'acceleration of gravity, m/s^2', (9.8e-6, 9.82e6))
    C  = _checked('C', C, 'positive', 'stiffness of the rope (elastic link), N/m', (0.1, 1e14))
    v0 = _checked('v0', v0, 'positive', 'steady hoisting speed after the start, m/s', (1e-7, 1e6))
    shape = _broadcast(m2=m2, g=g, C=C, v0=v0)
    return _into(out, shape, g*m2/(C*v0))


def dynamic_coefficient_instant(t, Omega, *, out=None):
    """K_din(t) under a suddenly applied constant load. Eq (38).

    Parameters
    ----------
    t : array_like
        time from the start of the drive [s], >= 0; served from 0.0 to 1e7
    Omega : array_like
        natural circular frequency Ω of the rope stretch [rad/s], > 0; served from 2e-6 to 6e7
    out : ndarray, optional
        float64 array of the broadcast shape; the result is written into it and returned.

    Returns
    -------
    ndarray
        [1], broadcast over the arguments.
    """
    if (out is None
            and (type(t) in (float, int) or type(t) is np.float64)
            and (type(Omega) in (float, int) or type(Omega) is np.float64)):
        if (0.0 <= t <= 1e7 and 2e-6 <= Omega <= 6e7):
            try:    # a failed check or a math error: the array path decides
                k0 = (1/2)*Omega
                return np.float64(2*math.sin(k0*t)**2)
            except (ArithmeticError, ValueError):
                pass
    t     = _checked('t', t, 'nonnegative', 'time from the start of the drive, s', (0.0, 1e7))
    Omega = _checked('Omega', Omega, 'positive', 'natural circular frequency Ω of the rope stretch, rad/s', (2e-6, 6e7))
    shape = _broadcast(t=t, Omega=Omega)
    k0 = (1/2)*Omega
    if out is None and not shape:
        return 2*np.sin(k0*t)**2
    out = _out(out, shape)
    for _o, (t, k0) in _spans(out, shape, t, k0):
        np.multiply(t, k0, out=_o)
        np.sin(_o, out=_o)
        np.square(_o, out=_o)
        np.multiply(_o, 2, out=_o)
    return out


def dynamic_coefficient_ramp(t, Omega, t_n, *, out=None):
    """K_din(t) under a linearly growing load, over the static deflection at t_n. Eq (42).

    Parameters
    ----------
    t : array_like
        time from the start of the drive [s], >= 0; served from 0.0 to 1e7
    Omega : array_like
        natural circular frequency Ω of the rope stretch [rad/s], > 0; served from 2e-6 to 6e7
    t_n : array_like
        duration of the start (transient) t_п [s], > 0; served from 1e-17 to 1e7
    out : ndarray, optional
        float64 array of the broadcast shape; the result is written into it and returned.

    Returns
    -------
    ndarray
        [1], broadcast over the arguments.
    """
    if (out is None
            and (type(t) in (float, int) or type(t) is np.float64)
            and (type(Omega) in (float, int) or type(Omega) is np.float64)
            and (type(t_n) in (float, int) or type(t_n) is np.float64)):
        if (0.0 <= t <= 1e7 and 2e-6 <= Omega <= 6e7 and 1e-17 <= t_n <= 1e7):
            try:    # a failed check or a math error: the array path decides
                k0 = -1/(Omega*t_n)
                return np.float64(k0*_remainder_float(Omega*t, 1, 1))
            except (ArithmeticError, ValueError):
                pass
    t     = _checked('t', t, 'nonnegative', 'time from the start of the drive, s', (0.0, 1e7))
    Omega = _checked('Omega', Omega, 'positive', 'natural circular frequency Ω of the rope stretch, rad/s', (2e-6, 6e7))
    t_n   = _checked('t_n', t_n, 'positive', 'duration of the start (transient) t_п, s', (1e-17, 1e7))
    shape = _broadcast(t=t, Omega=Omega, t_n=t_n)
    k0 = -1/(Omega*t_n)
    _one = out is None and not shape
    out = _out(out, shape)
    for _o, (t, Omega, k0) in _spans(out, shape, t, Omega, k0):
        _o[...] = k0*_sin_remainder(Omega*t, 1)
    return out[()] if _one else out


def dynamic_coefficient_pulse(t, Omega, theta, *, out=None):
    """K_din(t) under a rectangular pulse of length theta. Eq (45), (46).

    Parameters
    ----------
    t : array_like
        time from the start of the drive [s], >= 0; served from 0.0 to 1e7
    Omega : array_like
        natural circular frequency Ω of the rope stretch [rad/s], > 0; served from 2e-6 to 6e7
    theta : array_like
        duration θ of the pulse or of the load rise (43)–(53) [s], > 0; served from 1e-17 to 1e7
    out : ndarray, optional
        float64 array of the broadcast shape; the result is written into it and returned.

    Returns
    -------
    ndarray
        [1], broadcast over the arguments.
    """
    t     = _checked('t', t, 'nonnegative', 'time from the start of the drive, s', (0.0, 1e7))
    Omega = _checked('Omega', Omega, 'positive', 'natural circular frequency Ω of the rope stretch, rad/s', (2e-6, 6e7))
    theta = _checked('theta', theta, 'positive', 'duration θ of the pulse or of the load rise (43)–(53), s', (1e-17, 1e7))
    shape = _broadcast(t=t, Omega=Omega, theta=theta)
    x0 = Omega*theta
    k0 = 2*np.sin((1/2)*x0)**2
    k1 = np.sin(x0)
    if out is None and not shape:      # one point: its own branch only
        return (2*_sin_half_squared(_exact_phase(Omega, t)) if np.less_equal(t, theta) else _wave(k0, k1, _exact_phase(Omega, t, theta)))
    out = _out(out, shape)
    cells = _cells(shape, [[np.less_equal(t, theta)]])
    for part in _blocks(cells[0]):
        Omega_, t_ = _at(part, shape, Omega, t)
        _put(out, part, 2*_sin_half_squared(_exact_phase(Omega_, t_)))
    for part in _blocks(cells[1]):
        Omega_, k0_, k1_, t_, theta_ = _at(part, shape, Omega, k0, k1, t, theta)
        _put(out, part, _wave(k0_, k1_, _exact_phase(Omega_, t_, theta_)))
    return out


def pulse_peak_factor(Omega, theta, *, out=None):
    """Largest x/x_st under a rectangular pulse of length theta. Eq (47).

    Parameters
    ----------
    Omega : array_like
        natural circular frequency Ω of the rope stretch [rad/s], > 0; served from 2e-6 to 6e7
    theta : array_like
        duration θ of the pulse or of the load rise (43)–(53) [s], > 0; served from 1e-17 to 1e7
    out : ndarray, optional
        float64 array of the broadcast shape; the result is written into it and returned.

    Returns
    -------
    ndarray
        [1], broadcast over the arguments.
    """
    if (out is None
            and (type(Omega) in (float, int) or type(Omega) is np.float64)
            and (type(theta) in (float, int) or type(theta) is np.float64)):
        if (2e-6 <= Omega <= 6e7 and 1e-17 <= theta <= 1e7):
            try:    # a failed check or a math error: the array path decides
                return np.float64(((2*math.sin((1/2)*Omega*theta)) if (theta < 3.141592653589793/Omega) else (2)))
            except (ArithmeticError, ValueError):
                pass
    Omega = _checked('Omega', Omega, 'positive', 'natural circular frequency Ω of the rope stretch, rad/s', (2e-6, 6e7))
    theta = _checked('theta', theta, 'positive', 'duration θ of the pulse or of the load rise (43)–(53), s', (1e-17, 1e7))
    shape = _broadcast(Omega=Omega, theta=theta)
    return _into(out, shape, np.select([np.less(theta, 3.141592653589793/Omega),True], [2*np.sin((1/2)*Omega*theta),2], default=np.nan))


def pulse_peak_time(Omega, theta, *, out=None):
    """Time of the largest displacement under the pulse. Eq (47).

    Parameters
    ----------
    Omega : array_like
        natural circular frequency Ω of the rope stretch [rad/s], > 0; served from 2e-6 to 6e7
    theta : array_like
        duration θ of the pulse or of the load rise (43)–(53) [s], > 0; served from 1e-17 to 1e7
    out : ndarray, optional
        float64 array of the broadcast shape; the result is written into it and returned.

    Returns
    -------
    ndarray
        [s], broadcast over the arguments.
    """
    if (out is None
            and (type(Omega) in (float, int) or type(Omega) is np.float64)
            and (type(theta) in (float, int) or type(theta) is np.float64)):
        if (2e-6 <= Omega <= 6e7 and 1e-17 <= theta <= 1e7):
            try:    # a failed check or a math error: the array path decides
                x0 = 1/Omega
                x1 = 3.141592653589793*x0
                return np.float64((((1/2)*theta + 1.5707963267948966*x0) if (theta < x1) else (x1)))
            except (ArithmeticError, ValueError):
                pass
    Omega = _checked('Omega', Omega, 'positive', 'natural circular frequency Ω of the rope stretch, rad/s', (2e-6, 6e7))
    theta = _checked('theta', theta, 'positive', 'duration θ of the pulse or of the load rise (43)–(53), s', (1e-17, 1e7))
    shape = _broadcast(Omega=Omega, theta=theta)
    x0 = 1/(Omega)
    x1 = 3.141592653589793*x0
    return _into(out, shape, np.select([np.less(theta, x1),True], [(1/2)*theta + 1.5707963267948966*x0,x1], default=np.nan))


def dynamic_coefficient_ramp_hold(t, Omega, theta, *, out=None):
    """K_din(t) under a load rising over theta, then held. Eq (51), (52).

    Parameters
    ----------
    t : array_like
        time from the start of the drive [s], >= 0; served from 0.0 to 1e7
    Omega : array_like
        natural circular frequency Ω of the rope stretch [rad/s], > 0; served from 2e-6 to 6e7
    theta : array_like
        duration θ of the pulse or of the load rise (43)–(53) [s], > 0; served from 1e-17 to 1e7
    out : ndarray, optional
        float64 array of the broadcast shape; the result is written into it and returned.

    Returns
    -------
    ndarray
        [1], broadcast over the arguments.
    """
    t     = _checked('t', t, 'nonnegative', 'time from the start of the drive, s', (0.0, 1e7))
    Omega = _checked('Omega', Omega, 'positive', 'natural circular frequency Ω of the rope stretch, rad/s', (2e-6, 6e7))
    theta = _checked('theta', theta, 'positive', 'duration θ of the pulse or of the load rise (43)–(53), s', (1e-17, 1e7))
    shape = _broadcast(t=t, Omega=Omega, theta=theta)
    x0 = Omega*theta
    k0 = 1/(Omega*theta)
    k1 = _entire_1(x0)
    k2 = _entire_2(x0)
    k3 = _entire_3(x0)
    if out is None and not shape:      # one point: its own branch only
        return (k0*_entire_4(_exact_phase(Omega, t)) if np.less_equal(t, theta) else _offset_wave(1, k1, k2, k3, _exact_phase(Omega, t, theta)))
    out = _out(out, shape)
    cells = _cells(shape, [[np.less_equal(t, theta)]])
    for part in _blocks(cells[0]):
        Omega_, k0_, t_ = _at(part, shape, Omega, k0, t)
        _put(out, part, k0_*_entire_4(_exact_phase(Omega_, t_)))
    for part in _blocks(cells[1]):
        Omega_, k1_, k2_, k3_, t_, theta_ = _at(part, shape, Omega, k1, k2, k3, t, theta)
        _put(out, part, _offset_wave(1, k1_, k2_, k3_, _exact_phase(Omega_, t_, theta_)))
    return out


def ramp_hold_peak_factor(Omega, theta, *, out=None):
    """Largest x/x_st under the rise-then-hold load. Eq (53).

    Parameters
    ----------
    Omega : array_like
        natural circular frequency Ω of the rope stretch [rad/s], > 0; served from 2e-6 to 6e7
    theta : array_like
        duration θ of the pulse or of the load rise (43)–(53) [s], > 0; served from 1e-17 to 1e7
    out : ndarray, optional
        float64 array of the broadcast shape; the result is written into it and returned.

    Returns
    -------
    ndarray
        [1], broadcast over the arguments.
    """
    if (out is None
            and (type(Omega) in (float, int) or type(Omega) is np.float64)
            and (type(theta) in (float, int) or type(theta) is np.float64)):
        if (2e-6 <= Omega <= 6e7 and 1e-17 <= theta <= 1e7):
            try:    # a failed check or a math error: the array path decides
                return np.float64(1 + 2*abs(math.sin((1/2)*Omega*theta))/(Omega*theta))
            except (ArithmeticError, ValueError):
                pass
    Omega = _checked('Omega', Omega, 'positive', 'natural circular frequency Ω of the rope stretch, rad/s', (2e-6, 6e7))
    theta = _checked('theta', theta, 'positive', 'duration θ of the pulse or of the load rise (43)–(53), s', (1e-17, 1e7))
    shape = _broadcast(Omega=Omega, theta=theta)
    return _into(out, shape, 1 + 2*abs(np.sin((1/2)*Omega*theta))/(Omega*theta))


def dynamic_coefficient_pickup_a1(t, Omega, tau_0, m1, m2, g, v0, t_n, *, out=None):
    """K_din^(1)(t) for the drive law a_1 of (30), lifting with pick-up (tau_0 from pickup_contact_time); Omega from natural_frequency. Eq (26), (28), (30).

    Parameters
    ----------
    t : array_like
        time from the start of the drive [s], >= 0; served from 0.0 to 1e7
    Omega : array_like
        natural circular frequency Ω of the rope stretch [rad/s], > 0; served from 2e-6 to 6e7
    tau_0 : array_like
        duration τ_0 of the contact of the load with the ground when lifting with pick-up [s], > 0; served from 1e-17 to 1e7
    m1 : array_like
        reduced mass of the drive (first mass) [kg], > 0; served from 1e-9 to 1e17
    m2 : array_like
        mass of the load (second mass) [kg], > 0; served from 0.001 to 5e10
    g : array_like
        acceleration of gravity [m/s^2], > 0; served from 9.8e-6 to 9.82e6
    v0 : array_like
        steady hoisting speed after the start [m/s], > 0; served from 1e-7 to 1e6
    t_n : array_like
        duration of the start (transient) t_п [s], > 0; served from 1e-17 to 1e7
    out : ndarray, optional
        float64 array of the broadcast shape; the result is written into it and returned.

    Returns
    -------
    ndarray
        [1], broadcast over the arguments.
    """
    t     = _checked('t', t, 'nonnegative', 'time from the start of the drive, s', (0.0, 1e7))
    Omega = _checked('Omega', Omega, 'positive', 'natural circular frequency Ω of the rope stretch, rad/s', (2e-6, 6e7))
    tau_0 = _checked('tau_0', tau_0, 'positive', 'duration τ_0 of the contact of the load with the ground when lifting with pick-up, s', (1e-17, 1e7))
    m1    = _checked('m1', m1, 'positive', 'reduced mass of the drive (first mass), kg', (1e-9, 1e17))
    m2    = _checked('m2', m2, 'positive', 'mass of the load (second mass), kg', (0.001, 5e10))
    g     = _checked('g', g, 'positive', 'acceleration of gravity, m/s^2', (9.8e-6, 9.82e6))
    v0    = _checked('v0', v0, 'positive', 'steady hoisting speed after the start, m/s', (1e-7, 1e6))
    t_n   = _checked('t_n', t_n, 'positive', 'duration of the start (transient) t_п, s', (1e-17, 1e7))
    shape = _broadcast(t=t, Omega=Omega, tau_0=tau_0, m1=m1, m2=m2, g=g, v0=v0, t_n=t_n)
    x0 = g*t_n
    x1 = m2*x0
    x2 = 1/(m1*v0 + m2*v0 + x1)
    x3 = 2*x2
    x4 = v0*(m1 + m2)
    x5 = x3*x4
    x6 = Omega*t_n
    x7 = m1*x0*x2
    x8 = Omega*tau_0
    k0 = x1*x3
    k2 = x5*np.sin((1/2)*x6)**2
    k3 = x2*x4*np.sin(x6)
    k4 = x7/(Omega*tau_0)
    k5 = _entire_1(x8)
    k6 = _entire_2(x8)
    k7 = _entire_3(x8)
    if out is None and not shape:      # one point: its own branch only
        return k0*_sin_half_squared(_exact_phase(Omega, t)) + (k4*_entire_4(_exact_phase(Omega, t)) if np.less_equal(t, tau_0) else x7*_offset_wave(1, k5, k6, k7, _exact_phase(Omega, t, tau_0))) + (x5*_sin_half_squared(_exact_phase(Omega, t)) if np.less_equal(t, t_n) else _wave(k2, k3, _exact_phase(Omega, t, t_n)))
    out = _out(out, shape)
    cells = _cells(shape, [[np.less_equal(t, tau_0)], [np.less_equal(t, t_n)]])
    for part in _blocks(cells[0]):
        Omega_, k0_, k4_, t_, x5_ = _at(part, shape, Omega, k0, k4, t, x5)
        w0 = _exact_phase(Omega_, t_)
        w1 = _sin_half_squared(w0)
        _put(out, part, k0_*w1 + k4_*_entire_4(w0) + w1*x5_)
    for part in _blocks(cells[1]):
        Omega_, k0_, k2_, k3_, k4_, t_, t_n_ = _at(part, shape, Omega, k0, k2, k3, k4, t, t_n)
        w0 = _exact_phase(Omega_, t_)
        w1 = _exact_phase(Omega_, t_n_)
        w2 = _sin_pair(w1, 1.0)
        w3 = _cos_pair(w1, 1.0)
        w_sum = k0_*_sin_half_squared(w0) + k4_*_entire_4(w0) + (k2_*w2 + k3_*w3)*_sin_pair(w0, 1.0) + (k2_*w3 - k3_*w2)*_cos_pair(w0, 1.0)
        w_redo = _cancelled(w_sum, abs(k2_) + abs(k3_))
        if w_redo is not None:      # where the fast sum cancels
            Omega_, k0_, k2_, k3_, k4_, t_, t_n_ = _at(w_redo, w_sum.shape, Omega_, k0_, k2_, k3_, k4_, t_, t_n_)
            w0 = _exact_phase(Omega_, t_)
            w_sum[w_redo] = k0_*_sin_half_squared(w0) + k4_*_entire_4(w0) + _wave(k2_, k3_, _exact_phase(Omega_, t_, t_n_))
        _put(out, part, w_sum)
    for part in _blocks(cells[2]):
        Omega_, k0_, k5_, k6_, k7_, t_, tau_0_, x5_, x7_ = _at(part, shape, Omega, k0, k5, k6, k7, t, tau_0, x5, x7)
        w0 = _exact_phase(Omega_, t_)
        w1 = _sin_half_squared(w0)
        w2 = _exact_phase(Omega_, tau_0_)
        w3 = _sin_pair(w2, 1.0)
        w4 = k6_*x7_
        w5 = _cos_pair(w2, 1.0)
        w6 = k7_*x7_
        w_sum = k0_*w1 + w1*x5_ + x7_ + (w3*w4 + w5*w6)*_sin_pair(w0, 1.0) + (-w3*w6 + w4*w5)*_cos_pair(w0, 1.0)
        w_redo = _cancelled(w_sum, abs(w4) + abs(w6) + abs(x7_))
        if w_redo is not None:      # where the fast sum cancels
            Omega_, k0_, k5_, k6_, k7_, t_, tau_0_, x5_, x7_ = _at(w_redo, w_sum.shape, Omega_, k0_, k5_, k6_, k7_, t_, tau_0_, x5_, x7_)
            w0 = _sin_half_squared(_exact_phase(Omega_, t_))
            w_sum[w_redo] = k0_*w0 + w0*x5_ + x7_*_offset_wave(1, k5_, k6_, k7_, _exact_phase(Omega_, t_, tau_0_))
        _put(out, part, w_sum)
    for part in _blocks(cells[3]):
        Omega_, k0_, k2_, k3_, k5_, k6_, k7_, t_, t_n_, tau_0_, x7_ = _at(part, shape, Omega, k0, k2, k3, k5, k6, k7, t, t_n, tau_0, x7)
        w0 = _exact_phase(Omega_, t_)
        w1 = _exact_phase(Omega_, t_n_)
        w2 = _sin_pair(w1, 1.0)
        w3 = _cos_pair(w1, 1.0)
        w4 = _exact_phase(Omega_, tau_0_)
        w5 = _sin_pair(w4, 1.0)
        w6 = k6_*x7_
        w7 = _cos_pair(w4, 1.0)
        w8 = k7_*x7_
        w_sum = k0_*_sin_half_squared(w0) + x7_ + (k2_*w2 + k3_*w3 + w5*w6 + w7*w8)*_sin_pair(w0, 1.0) + (k2_*w3 - k3_*w2 - w5*w8 + w6*w7)*_cos_pair(w0, 1.0)
        w_redo = _cancelled(w_sum, abs(k2_) + abs(k3_) + abs(w6) + abs(w8) + abs(x7_))
        if w_redo is not None:      # where the fast sum cancels
            Omega_, k0_, k2_, k3_, k5_, k6_, k7_, t_, t_n_, tau_0_, x7_ = _at(w_redo, w_sum.shape, Omega_, k0_, k2_, k3_, k5_, k6_, k7_, t_, t_n_, tau_0_, x7_)
            w_sum[w_redo] = k0_*_sin_half_squared(_exact_phase(Omega_, t_)) + x7_*_offset_wave(1, k5_, k6_, k7_, _exact_phase(Omega_, t_, tau_0_)) + _wave(k2_, k3_, _exact_phase(Omega_, t_, t_n_))
        _put(out, part, w_sum)
    return out


def dynamic_coefficient_pickup_a2(t, Omega, tau_0, m1, m2, g, v0, t_n, *, out=None):
    """K_din^(1)(t) for the drive law a_2 of (30), lifting with pick-up (tau_0 from pickup_contact_time); Omega from natural_frequency. Eq (26), (28), (30).

    Parameters
    ----------
    t : array_like
        time from the start of the drive [s], >= 0; served from 0.0 to 1e7
    Omega : array_like
        natural circular frequency Ω of the rope stretch [rad/s], > 0; served from 2e-6 to 6e7
    tau_0 : array_like
        duration τ_0 of the contact of the load with the ground when lifting with pick-up [s], > 0; served from 1e-17 to 1e7
    m1 : array_like
        reduced mass of the drive (first mass) [kg], > 0; served from 1e-9 to 1e17
    m2 : array_like
        mass of the load (second mass) [kg], > 0; served from 0.001 to 5e10
    g : array_like
        acceleration of gravity [m/s^2], > 0; served from 9.8e-6 to 9.82e6
    v0 : array_like
        steady hoisting speed after the start [m/s], > 0; served from 1e-7 to 1e6
    t_n : array_like
        duration of the start (transient) t_п [s], > 0; served from 1e-17 to 1e7
    out : ndarray, optional
        float64 array of the broadcast shape; the result is written into it and returned.

    Returns
    -------
    ndarray
        [1], broadcast over the arguments.
    """
    t     = _checked('t', t, 'nonnegative', 'time from the start of the drive, s', (0.0, 1e7))
    Omega = _checked('Omega', Omega, 'positive', 'natural circular frequency Ω of the rope stretch, rad/s', (2e-6, 6e7))
    tau_0 = _checked('tau_0', tau_0, 'positive', 'duration τ_0 of the contact of the load with the ground when lifting with pick-up, s', (1e-17, 1e7))
    m1    = _checked('m1', m1, 'positive', 'reduced mass of the drive (first mass), kg', (1e-9, 1e17))
    m2    = _checked('m2', m2, 'positive', 'mass of the load (second mass), kg', (0.001, 5e10))
    g     = _checked('g', g, 'positive', 'acceleration of gravity, m/s^2', (9.8e-6, 9.82e6))
    v0    = _checked('v0', v0, 'positive', 'steady hoisting speed after the start, m/s', (1e-7, 1e6))
    t_n   = _checked('t_n', t_n, 'positive', 'duration of the start (transient) t_п, s', (1e-17, 1e7))
    shape = _broadcast(t=t, Omega=Omega, tau_0=tau_0, m1=m1, m2=m2, g=g, v0=v0, t_n=t_n)
    x0 = g*t_n
    x1 = m2*x0
    x2 = 1/(m1*v0 + m2*v0 + x1)
    x3 = v0*x2*(m1 + m2)
    x4 = Omega*t_n
    x5 = m1*x0*x2
    x6 = Omega*tau_0
    k0 = 2*x1*x2
    k1 = 1/(t_n)
    k3 = x3*_entire_5(x4)
    k4 = -x3*_entire_6(x4)
    k5 = x5/(Omega*tau_0)
    k6 = _entire_1(x6)
    k7 = _entire_2(x6)
    k8 = _entire_3(x6)
    if out is None and not shape:      # one point: its own branch only
        return k0*_sin_half_squared(_exact_phase(Omega, t)) + (k5*_entire_4(_exact_phase(Omega, t)) if np.less_equal(t, tau_0) else x5*_offset_wave(1, k6, k7, k8, _exact_phase(Omega, t, tau_0))) + (x3*(k1*(-t + t_n)*_entire_7(_exact_phase(Omega, t)) + _entire_5(_exact_phase(Omega, t))) if np.less_equal(t, t_n) else _wave(k3, k4, _exact_phase(Omega, t, t_n)))
    out = _out(out, shape)
    cells = _cells(shape, [[np.less_equal(t, tau_0)], [np.less_equal(t, t_n)]])
    for part in _blocks(cells[0]):
        Omega_, k0_, k1_, k5_, t_, t_n_, x3_ = _at(part, shape, Omega, k0, k1, k5, t, t_n, x3)
        w0 = _exact_phase(Omega_, t_)
        _put(out, part, k0_*_sin_half_squared(w0) + k5_*_entire_4(w0) + x3_*(k1_*(-t_ + t_n_)*_entire_7(w0) + _entire_5(w0)))
    for part in _blocks(cells[1]):
        Omega_, k0_, k3_, k4_, k5_, t_, t_n_ = _at(part, shape, Omega, k0, k3, k4, k5, t, t_n)
        w0 = _exact_phase(Omega_, t_)
        w1 = _exact_phase(Omega_, t_n_)
        w2 = _sin_pair(w1, 1.0)
        w3 = _cos_pair(w1, 1.0)
        w_sum = k0_*_sin_half_squared(w0) + k5_*_entire_4(w0) + (k3_*w2 + k4_*w3)*_sin_pair(w0, 1.0) + (k3_*w3 - k4_*w2)*_cos_pair(w0, 1.0)
        w_redo = _cancelled(w_sum, abs(k3_) + abs(k4_))
        if w_redo is not None:      # where the fast sum cancels
            Omega_, k0_, k3_, k4_, k5_, t_, t_n_ = _at(w_redo, w_sum.shape, Omega_, k0_, k3_, k4_, k5_, t_, t_n_)
            w0 = _exact_phase(Omega_, t_)
            w_sum[w_redo] = k0_*_sin_half_squared(w0) + k5_*_entire_4(w0) + _wave(k3_, k4_, _exact_phase(Omega_, t_, t_n_))
        _put(out, part, w_sum)
    for part in _blocks(cells[2]):
        Omega_, k0_, k1_, k6_, k7_, k8_, t_, t_n_, tau_0_, x3_, x5_ = _at(part, shape, Omega, k0, k1, k6, k7, k8, t, t_n, tau_0, x3, x5)
        w0 = _exact_phase(Omega_, t_)
        w1 = _exact_phase(Omega_, tau_0_)
        w2 = _sin_pair(w1, 1.0)
        w3 = k7_*x5_
        w4 = _cos_pair(w1, 1.0)
        w5 = k8_*x5_
        w_sum = k0_*_sin_half_squared(w0) + x3_*(k1_*(-t_ + t_n_)*_entire_7(w0) + _entire_5(w0)) + x5_ + (w2*w3 + w4*w5)*_sin_pair(w0, 1.0) + (-w2*w5 + w3*w4)*_cos_pair(w0, 1.0)
        w_redo = _cancelled(w_sum, abs(w3) + abs(w5) + abs(x5_))
        if w_redo is not None:      # where the fast sum cancels
            Omega_, k0_, k1_, k6_, k7_, k8_, t_, t_n_, tau_0_, x3_, x5_ = _at(w_redo, w_sum.shape, Omega_, k0_, k1_, k6_, k7_, k8_, t_, t_n_, tau_0_, x3_, x5_)
            w0 = _exact_phase(Omega_, t_)
            w_sum[w_redo] = k0_*_sin_half_squared(w0) + x3_*(k1_*(-t_ + t_n_)*_entire_7(w0) + _entire_5(w0)) + x5_*_offset_wave(1, k6_, k7_, k8_, _exact_phase(Omega_, t_, tau_0_))
        _put(out, part, w_sum)
    for part in _blocks(cells[3]):
        Omega_, k0_, k3_, k4_, k6_, k7_, k8_, t_, t_n_, tau_0_, x5_ = _at(part, shape, Omega, k0, k3, k4, k6, k7, k8, t, t_n, tau_0, x5)
        w0 = _exact_phase(Omega_, t_)
        w1 = _exact_phase(Omega_, t_n_)
        w2 = _sin_pair(w1, 1.0)
        w3 = _cos_pair(w1, 1.0)
        w4 = _exact_phase(Omega_, tau_0_)
        w5 = _sin_pair(w4, 1.0)
        w6 = k7_*x5_
        w7 = _cos_pair(w4, 1.0)
        w8 = k8_*x5_
        w_sum = k0_*_sin_half_squared(w0) + x5_ + (k3_*w2 + k4_*w3 + w5*w6 + w7*w8)*_sin_pair(w0, 1.0) + (k3_*w3 - k4_*w2 - w5*w8 + w6*w7)*_cos_pair(w0, 1.0)
        w_redo = _cancelled(w_sum, abs(k3_) + abs(k4_) + abs(w6) + abs(w8) + abs(x5_))
        if w_redo is not None:      # where the fast sum cancels
            Omega_, k0_, k3_, k4_, k6_, k7_, k8_, t_, t_n_, tau_0_, x5_ = _at(w_redo, w_sum.shape, Omega_, k0_, k3_, k4_, k6_, k7_, k8_, t_, t_n_, tau_0_, x5_)
            w_sum[w_redo] = k0_*_sin_half_squared(_exact_phase(Omega_, t_)) + x5_*_offset_wave(1, k6_, k7_, k8_, _exact_phase(Omega_, t_, tau_0_)) + _wave(k3_, k4_, _exact_phase(Omega_, t_, t_n_))
        _put(out, part, w_sum)
    return out


def dynamic_coefficient_pickup_a3(t, Omega, tau_0, m1, m2, g, v0, t_n, *, out=None):
    """K_din^(1)(t) for the drive law a_3 of (30), lifting with pick-up (tau_0 from pickup_contact_time); Omega from natural_frequency. Eq (26), (28), (30).

    Parameters
    ----------
    t : array_like
        time from the start of the drive [s], >= 0; served from 0.0 to 1e7
    Omega : array_like
        natural circular frequency Ω of the rope stretch [rad/s], > 0; served from 2e-6 to 6e7
    tau_0 : array_like
        duration τ_0 of the contact of the load with the ground when lifting with pick-up [s], > 0; served from 1e-17 to 1e7
    m1 : array_like
        reduced mass of the drive (first mass) [kg], > 0; served from 1e-9 to 1e17
    m2 : array_like
        mass of the load (second mass) [kg], > 0; served from 0.001 to 5e10
    g : array_like
        acceleration of gravity [m/s^2], > 0; served from 9.8e-6 to 9.82e6
    v0 : array_like
        steady hoisting speed after the start [m/s], > 0; served from 1e-7 to 1e6
    t_n : array_like
        duration of the start (transient) t_п [s], > 0; served from 1e-17 to 1e7
    out : ndarray, optional
        float64 array of the broadcast shape; the result is written into it and returned.

    Returns
    -------
    ndarray
        [1], broadcast over the arguments.
    """
    t     = _checked('t', t, 'nonnegative', 'time from the start of the drive, s', (0.0, 1e7))
    Omega = _checked('Omega', Omega, 'positive', 'natural circular frequency Ω of the rope stretch, rad/s', (2e-6, 6e7))
    tau_0 = _checked('tau_0', tau_0, 'positive', 'duration τ_0 of the contact of the load with the ground when lifting with pick-up, s', (1e-17, 1e7))
    m1    = _checked('m1', m1, 'positive', 'reduced mass of the drive (first mass), kg', (1e-9, 1e17))
    m2    = _checked('m2', m2, 'positive', 'mass of the load (second mass), kg', (0.001, 5e10))
    g     = _checked('g', g, 'positive', 'acceleration of gravity, m/s^2', (9.8e-6, 9.82e6))
    v0    = _checked('v0', v0, 'positive', 'steady hoisting speed after the start, m/s', (1e-7, 1e6))
    t_n   = _checked('t_n', t_n, 'positive', 'duration of the start (transient) t_п, s', (1e-17, 1e7))
    shape = _broadcast(t=t, Omega=Omega, tau_0=tau_0, m1=m1, m2=m2, g=g, v0=v0, t_n=t_n)
    x0 = 1/(Omega)
    x1 = 1/(m2)
    x2 = m1*x1
    x3 = Omega*tau_0
    x4 = 1/(t_n)
    x5 = v0*x1*(m1 + m2)/g
    x6 = Omega*t_n
    x7 = x4*x5
    k0 = x0*x2/tau_0
    k1 = _entire_1(x3)
    k2 = _entire_2(x3)
    k3 = _entire_3(x3)
    k6 = 48*x0*x5/t_n**2
    k7 = -24*x7*_entire_8(x6)
    k8 = -72*x7*_entire_9(x6)
    if out is None and not shape:      # one point: its own branch only
        return (k0*_entire_4(_exact_phase(Omega, t)) if np.less_equal(t, tau_0) else x2*_offset_wave(1, k1, k2, k3, _exact_phase(Omega, t, tau_0))) + (k6*(x4*(-t + t_n)*(x4*(-t + t_n)*_entire_10(_exact_phase(Omega, t)) + _entire_11(_exact_phase(Omega, t))) + _entire_12(_exact_phase(Omega, t))) if np.less_equal(t, t_n) else _wave(k7, k8, _exact_phase(Omega, t, t_n))) + 2*_sin_half_squared(_exact_phase(Omega, t))
    out = _out(out, shape)
    cells = _cells(shape, [[np.less_equal(t, tau_0)], [np.less_equal(t, t_n)]])
    for part in _blocks(cells[0]):
        Omega_, k0_, k6_, t_, t_n_, x4_ = _at(part, shape, Omega, k0, k6, t, t_n, x4)
        w0 = _exact_phase(Omega_, t_)
        w1 = x4_*(-t_ + t_n_)
        _put(out, part, k0_*_entire_4(w0) + k6_*(w1*(w1*_entire_10(w0) + _entire_11(w0)) + _entire_12(w0)) + 2*_sin_half_squared(w0))
    for part in _blocks(cells[1]):
        Omega_, k0_, k7_, k8_, t_, t_n_ = _at(part, shape, Omega, k0, k7, k8, t, t_n)
        w0 = _exact_phase(Omega_, t_)
        w1 = _exact_phase(Omega_, t_n_)
        w2 = _sin_pair(w1, 1.0)
        w3 = _cos_pair(w1, 1.0)
        w_sum = k0_*_entire_4(w0) + (k7_*w2 + k8_*w3)*_sin_pair(w0, 1.0) + (k7_*w3 - k8_*w2)*_cos_pair(w0, 1.0) + 2*_sin_half_squared(w0)
        w_redo = _cancelled(w_sum, abs(k7_) + abs(k8_))
        if w_redo is not None:      # where the fast sum cancels
            Omega_, k0_, k7_, k8_, t_, t_n_ = _at(w_redo, w_sum.shape, Omega_, k0_, k7_, k8_, t_, t_n_)
            w0 = _exact_phase(Omega_, t_)
            w_sum[w_redo] = k0_*_entire_4(w0) + 2*_sin_half_squared(w0) + _wave(k7_, k8_, _exact_phase(Omega_, t_, t_n_))
        _put(out, part, w_sum)
    for part in _blocks(cells[2]):
        Omega_, k1_, k2_, k3_, k6_, t_, t_n_, tau_0_, x2_, x4_ = _at(part, shape, Omega, k1, k2, k3, k6, t, t_n, tau_0, x2, x4)
        w0 = _exact_phase(Omega_, t_)
        w1 = _exact_phase(Omega_, tau_0_)
        w2 = _sin_pair(w1, 1.0)
        w3 = k2_*x2_
        w4 = _cos_pair(w1, 1.0)
        w5 = k3_*x2_
        w6 = x4_*(-t_ + t_n_)
        w_sum = k6_*(w6*(w6*_entire_10(w0) + _entire_11(w0)) + _entire_12(w0)) + x2_ + (w2*w3 + w4*w5)*_sin_pair(w0, 1.0) + (-w2*w5 + w3*w4)*_cos_pair(w0, 1.0) + 2*_sin_half_squared(w0)
        w_redo = _cancelled(w_sum, abs(w3) + abs(w5) + abs(x2_))
        if w_redo is not None:      # where the fast sum cancels
            Omega_, k1_, k2_, k3_, k6_, t_, t_n_, tau_0_, x2_, x4_ = _at(w_redo, w_sum.shape, Omega_, k1_, k2_, k3_, k6_, t_, t_n_, tau_0_, x2_, x4_)
            w0 = _exact_phase(Omega_, t_)
            w1 = x4_*(-t_ + t_n_)
            w_sum[w_redo] = k6_*(w1*(w1*_entire_10(w0) + _entire_11(w0)) + _entire_12(w0)) + x2_*_offset_wave(1, k1_, k2_, k3_, _exact_phase(Omega_, t_, tau_0_)) + 2*_sin_half_squared(w0)
        _put(out, part, w_sum)
    for part in _blocks(cells[3]):
        Omega_, k1_, k2_, k3_, k7_, k8_, t_, t_n_, tau_0_, x2_ = _at(part, shape, Omega, k1, k2, k3, k7, k8, t, t_n, tau_0, x2)
        w0 = _exact_phase(Omega_, t_)
        w1 = _exact_phase(Omega_, t_n_)
        w2 = _sin_pair(w1, 1.0)
        w3 = _cos_pair(w1, 1.0)
        w4 = _exact_phase(Omega_, tau_0_)
        w5 = _sin_pair(w4, 1.0)
        w6 = k2_*x2_
        w7 = _cos_pair(w4, 1.0)
        w8 = k3_*x2_
        w_sum = x2_ + (k7_*w2 + k8_*w3 + w5*w6 + w7*w8)*_sin_pair(w0, 1.0) + (k7_*w3 - k8_*w2 - w5*w8 + w6*w7)*_cos_pair(w0, 1.0) + 2*_sin_half_squared(w0)
        w_redo = _cancelled(w_sum, abs(k7_) + abs(k8_) + abs(w6) + abs(w8) + abs(x2_))
        if w_redo is not None:      # where the fast sum cancels
            Omega_, k1_, k2_, k3_, k7_, k8_, t_, t_n_, tau_0_, x2_ = _at(w_redo, w_sum.shape, Omega_, k1_, k2_, k3_, k7_, k8_, t_, t_n_, tau_0_, x2_)
            w_sum[w_redo] = x2_*_offset_wave(1, k1_, k2_, k3_, _exact_phase(Omega_, t_, tau_0_)) + 2*_sin_half_squared(_exact_phase(Omega_, t_)) + _wave(k7_, k8_, _exact_phase(Omega_, t_, t_n_))
        _put(out, part, w_sum)
    return out


def dynamic_coefficient_pickup_a4(t, Omega, tau_0, m1, m2, g, v0, t_n, *, out=None):
    """K_din^(1)(t) for the drive law a_4 of (30), lifting with pick-up (tau_0 from pickup_contact_time); Omega from natural_frequency. Eq (26), (28), (30).

    Parameters
    ----------
    t : array_like
        time from the start of the drive [s], >= 0; served from 0.0 to 1e7
    Omega : array_like
        natural circular frequency Ω of the rope stretch [rad/s], > 0; served from 2e-6 to 6e7
    tau_0 : array_like
        duration τ_0 of the contact of the load with the ground when lifting with pick-up [s], > 0; served from 1e-17 to 1e7
    m1 : array_like
        reduced mass of the drive (first mass) [kg], > 0; served from 1e-9 to 1e17
    m2 : array_like
        mass of the load (second mass) [kg], > 0; served from 0.001 to 5e10
    g : array_like
        acceleration of gravity [m/s^2], > 0; served from 9.8e-6 to 9.82e6
    v0 : array_like
        steady hoisting speed after the start [m/s], > 0; served from 1e-7 to 1e6
    t_n : array_like
        duration of the start (transient) t_п [s], > 0; served from 1e-17 to 1e7
    out : ndarray, optional
        float64 array of the broadcast shape; the result is written into it and returned.

    Returns
    -------
    ndarray
        [1], broadcast over the arguments.
    """
    t     = _checked('t', t, 'nonnegative', 'time from the start of the drive, s', (0.0, 1e7))
    Omega = _checked('Omega', Omega, 'positive', 'natural circular frequency Ω of the rope stretch, rad/s', (2e-6, 6e7))
    tau_0 = _checked('tau_0', tau_0, 'positive', 'duration τ_0 of the contact of the load with the ground when lifting with pick-up, s', (1e-17, 1e7))
    m1    = _checked('m1', m1, 'positive', 'reduced mass of the drive (first mass), kg', (1e-9, 1e17))
    m2    = _checked('m2', m2, 'positive', 'mass of the load (second mass), kg', (0.001, 5e10))
    g     = _checked('g', g, 'positive', 'acceleration of gravity, m/s^2', (9.8e-6, 9.82e6))
    v0    = _checked('v0', v0, 'positive', 'steady hoisting speed after the start, m/s', (1e-7, 1e6))
    t_n   = _checked('t_n', t_n, 'positive', 'duration of the start (transient) t_п, s', (1e-17, 1e7))
    shape = _broadcast(t=t, Omega=Omega, tau_0=tau_0, m1=m1, m2=m2, g=g, v0=v0, t_n=t_n)
    x0 = 1/(m2)
    x1 = m1*x0
    x2 = Omega*tau_0
    x3 = 1/(t_n)
    x4 = v0*x0*(m1 + m2)/g
    x5 = Omega*t_n
    x6 = x3*x4
    k0 = x1/(Omega*tau_0)
    k1 = _entire_1(x2)
    k2 = _entire_2(x2)
    k3 = _entire_3(x2)
    k6 = -120*x4/(Omega**2*_cube(t_n))
    k7 = -2880*x6*_entire_13(x5)
    k8 = -7200*x6*_entire_14(x5)
    if out is None and not shape:      # one point: its own branch only
        return (k0*_entire_4(_exact_phase(Omega, t)) if np.less_equal(t, tau_0) else x1*_offset_wave(1, k1, k2, k3, _exact_phase(Omega, t, tau_0))) + (k6*(x3*(-t + t_n)*(x3*(-t + t_n)*(x3*(-t + t_n)*_entire_15(_exact_phase(Omega, t)) + _entire_16(_exact_phase(Omega, t))) + _entire_17(_exact_phase(Omega, t))) + _entire_18(_exact_phase(Omega, t))) if np.less_equal(t, t_n) else _wave(k7, k8, _exact_phase(Omega, t, t_n))) + 2*_sin_half_squared(_exact_phase(Omega, t))
    out = _out(out, shape)
    cells = _cells(shape, [[np.less_equal(t, tau_0)], [np.less_equal(t, t_n)]])
    for part in _blocks(cells[0]):
        Omega_, k0_, k6_, t_, t_n_, x3_ = _at(part, shape, Omega, k0, k6, t, t_n, x3)
        w0 = _exact_phase(Omega_, t_)
        w1 = x3_*(-t_ + t_n_)
        _put(out, part, k0_*_entire_4(w0) + k6_*(w1*(w1*(w1*_entire_15(w0) + _entire_16(w0)) + _entire_17(w0)) + _entire_18(w0)) + 2*_sin_half_squared(w0))
    for part in _blocks(cells[1]):
        Omega_, k0_, k7_, k8_, t_, t_n_ = _at(part, shape, Omega, k0, k7, k8, t, t_n)
        w0 = _exact_phase(Omega_, t_)
        w1 = _exact_phase(Omega_, t_n_)
        w2 = _sin_pair(w1, 1.0)
        w3 = _cos_pair(w1, 1.0)
        w_sum = k0_*_entire_4(w0) + (k7_*w2 + k8_*w3)*_sin_pair(w0, 1.0) + (k7_*w3 - k8_*w2)*_cos_pair(w0, 1.0) + 2*_sin_half_squared(w0)
        w_redo = _cancelled(w_sum, abs(k7_) + abs(k8_))
        if w_redo is not None:      # where the fast sum cancels
            Omega_, k0_, k7_, k8_, t_, t_n_ = _at(w_redo, w_sum.shape, Omega_, k0_, k7_, k8_, t_, t_n_)
            w0 = _exact_phase(Omega_, t_)
            w_sum[w_redo] = k0_*_entire_4(w0) + 2*_sin_half_squared(w0) + _wave(k7_, k8_, _exact_phase(Omega_, t_, t_n_))
        _put(out, part, w_sum)
    for part in _blocks(cells[2]):
        Omega_, k1_, k2_, k3_, k6_, t_, t_n_, tau_0_, x1_, x3_ = _at(part, shape, Omega, k1, k2, k3, k6, t, t_n, tau_0, x1, x3)
        w0 = _exact_phase(Omega_, t_)
        w1 = _exact_phase(Omega_, tau_0_)
        w2 = _sin_pair(w1, 1.0)
        w3 = k2_*x1_
        w4 = _cos_pair(w1, 1.0)
        w5 = k3_*x1_
        w6 = x3_*(-t_ + t_n_)
        w_sum = k6_*(w6*(w6*(w6*_entire_15(w0) + _entire_16(w0)) + _entire_17(w0)) + _entire_18(w0)) + x1_ + (w2*w3 + w4*w5)*_sin_pair(w0, 1.0) + (-w2*w5 + w3*w4)*_cos_pair(w0, 1.0) + 2*_sin_half_squared(w0)
        w_redo = _cancelled(w_sum, abs(w3) + abs(w5) + abs(x1_))
        if w_redo is not None:      # where the fast sum cancels
            Omega_, k1_, k2_, k3_, k6_, t_, t_n_, tau_0_, x1_, x3_ = _at(w_redo, w_sum.shape, Omega_, k1_, k2_, k3_, k6_, t_, t_n_, tau_0_, x1_, x3_)
            w0 = _exact_phase(Omega_, t_)
            w1 = x3_*(-t_ + t_n_)
            w_sum[w_redo] = k6_*(w1*(w1*(w1*_entire_15(w0) + _entire_16(w0)) + _entire_17(w0)) + _entire_18(w0)) + x1_*_offset_wave(1, k1_, k2_, k3_, _exact_phase(Omega_, t_, tau_0_)) + 2*_sin_half_squared(w0)
        _put(out, part, w_sum)
    for part in _blocks(cells[3]):
        Omega_, k1_, k2_, k3_, k7_, k8_, t_, t_n_, tau_0_, x1_ = _at(part, shape, Omega, k1, k2, k3, k7, k8, t, t_n, tau_0, x1)
        w0 = _exact_phase(Omega_, t_)
        w1 = _exact_phase(Omega_, t_n_)
        w2 = _sin_pair(w1, 1.0)
        w3 = _cos_pair(w1, 1.0)
        w4 = _exact_phase(Omega_, tau_0_)
        w5 = _sin_pair(w4, 1.0)
        w6 = k2_*x1_
        w7 = _cos_pair(w4, 1.0)
        w8 = k3_*x1_
        w_sum = x1_ + (k7_*w2 + k8_*w3 + w5*w6 + w7*w8)*_sin_pair(w0, 1.0) + (k7_*w3 - k8_*w2 - w5*w8 + w6*w7)*_cos_pair(w0, 1.0) + 2*_sin_half_squared(w0)
        w_redo = _cancelled(w_sum, abs(k7_) + abs(k8_) + abs(w6) + abs(w8) + abs(x1_))
        if w_redo is not None:      # where the fast sum cancels
            Omega_, k1_, k2_, k3_, k7_, k8_, t_, t_n_, tau_0_, x1_ = _at(w_redo, w_sum.shape, Omega_, k1_, k2_, k3_, k7_, k8_, t_, t_n_, tau_0_, x1_)
            w_sum[w_redo] = x1_*_offset_wave(1, k1_, k2_, k3_, _exact_phase(Omega_, t_, tau_0_)) + 2*_sin_half_squared(_exact_phase(Omega_, t_)) + _wave(k7_, k8_, _exact_phase(Omega_, t_, t_n_))
        _put(out, part, w_sum)
    return out


def dynamic_coefficient_from_weight_a1(t, Omega, m1, m2, g, v0, t_n, *, out=None):
    """K_din^(2)(t) for the drive law a_1 of (30), lifting from weight; Omega from natural_frequency. Eq (27), (28), (30).

    Parameters
    ----------
    t : array_like
        time from the start of the drive [s], >= 0; served from 0.0 to 1e7
    Omega : array_like
        natural circular frequency Ω of the rope stretch [rad/s], > 0; served from 2e-6 to 6e7
    m1 : array_like
        reduced mass of the drive (first mass) [kg], > 0; served from 1e-9 to 1e17
    m2 : array_like
        mass of the load (second mass) [kg], > 0; served from 0.001 to 5e10
    g : array_like
        acceleration of gravity [m/s^2], > 0; served from 9.8e-6 to 9.82e6
    v0 : array_like
        steady hoisting speed after the start [m/s], > 0; served from 1e-7 to 1e6
    t_n : array_like
        duration of the start (transient) t_п [s], > 0; served from 1e-17 to 1e7
    out : ndarray, optional
        float64 array of the broadcast shape; the result is written into it and returned.

    Returns
    -------
    ndarray
        [1], broadcast over the arguments.
    """
    t     = _checked('t', t, 'nonnegative', 'time from the start of the drive, s', (0.0, 1e7))
    Omega = _checked('Omega', Omega, 'positive', 'natural circular frequency Ω of the rope stretch, rad/s', (2e-6, 6e7))
    m1    = _checked('m1', m1, 'positive', 'reduced mass of the drive (first mass), kg', (1e-9, 1e17))
    m2    = _checked('m2', m2, 'positive', 'mass of the load (second mass), kg', (0.001, 5e10))
    g     = _checked('g', g, 'positive', 'acceleration of gravity, m/s^2', (9.8e-6, 9.82e6))
    v0    = _checked('v0', v0, 'positive', 'steady hoisting speed after the start, m/s', (1e-7, 1e6))
    t_n   = _checked('t_n', t_n, 'positive', 'duration of the start (transient) t_п, s', (1e-17, 1e7))
    shape = _broadcast(t=t, Omega=Omega, m1=m1, m2=m2, g=g, v0=v0, t_n=t_n)
    x0 = g*t_n
    x1 = 1/(v0 + x0)
    x2 = v0*x1
    x3 = 2*x2
    x4 = Omega*t_n
    k1 = x3*np.sin((1/2)*x4)**2
    k2 = x2*np.sin(x4)
    k3 = x0*x1
    if out is None and not shape:      # one point: its own branch only
        return k3 + (x3*_sin_half_squared(_exact_phase(Omega, t)) if np.less_equal(t, t_n) else _wave(k1, k2, _exact_phase(Omega, t, t_n)))
    out = _out(out, shape)
    cells = _cells(shape, [[np.less_equal(t, t_n)]])
    for part in _blocks(cells[0]):
        Omega_, k3_, t_, x3_ = _at(part, shape, Omega, k3, t, x3)
        _put(out, part, k3_ + x3_*_sin_half_squared(_exact_phase(Omega_, t_)))
    for part in _blocks(cells[1]):
        Omega_, k1_, k2_, k3_, t_, t_n_ = _at(part, shape, Omega, k1, k2, k3, t, t_n)
        _put(out, part, k3_ + _wave(k1_, k2_, _exact_phase(Omega_, t_, t_n_)))
    return out


def dynamic_coefficient_from_weight_a2(t, Omega, m1, m2, g, v0, t_n, *, out=None):
    """K_din^(2)(t) for the drive law a_2 of (30), lifting from weight; Omega from natural_frequency. Eq (27), (28), (30).

    Parameters
    ----------
    t : array_like
        time from the start of the drive [s], >= 0; served from 0.0 to 1e7
    Omega : array_like
        natural circular frequency Ω of the rope stretch [rad/s], > 0; served from 2e-6 to 6e7
    m1 : array_like
        reduced mass of the drive (first mass) [kg], > 0; served from 1e-9 to 1e17
    m2 : array_like
        mass of the load (second mass) [kg], > 0; served from 0.001 to 5e10
    g : array_like
        acceleration of gravity [m/s^2], > 0; served from 9.8e-6 to 9.82e6
    v0 : array_like
        steady hoisting speed after the start [m/s], > 0; served from 1e-7 to 1e6
    t_n : array_like
        duration of the start (transient) t_п [s], > 0; served from 1e-17 to 1e7
    out : ndarray, optional
        float64 array of the broadcast shape; the result is written into it and returned.

    Returns
    -------
    ndarray
        [1], broadcast over the arguments.
    """
    t     = _checked('t', t, 'nonnegative', 'time from the start of the drive, s', (0.0, 1e7))
    Omega = _checked('Omega', Omega, 'positive', 'natural circular frequency Ω of the rope stretch, rad/s', (2e-6, 6e7))
    m1    = _checked('m1', m1, 'positive', 'reduced mass of the drive (first mass), kg', (1e-9, 1e17))
    m2    = _checked('m2', m2, 'positive', 'mass of the load (second mass), kg', (0.001, 5e10))
    g     = _checked('g', g, 'positive', 'acceleration of gravity, m/s^2', (9.8e-6, 9.82e6))
    v0    = _checked('v0', v0, 'positive', 'steady hoisting speed after the start, m/s', (1e-7, 1e6))
    t_n   = _checked('t_n', t_n, 'positive', 'duration of the start (transient) t_п, s', (1e-17, 1e7))
    shape = _broadcast(t=t, Omega=Omega, m1=m1, m2=m2, g=g, v0=v0, t_n=t_n)
    x0 = g*t_n
    x1 = 1/(v0 + x0)
    x2 = v0*x1
    x3 = Omega*t_n
    k0 = 1/(t_n)
    k2 = x2*_entire_5(x3)
    k3 = -x2*_entire_6(x3)
    k4 = x0*x1
    if out is None and not shape:      # one point: its own branch only
        return k4 + (x2*(k0*(-t + t_n)*_entire_7(_exact_phase(Omega, t)) + _entire_5(_exact_phase(Omega, t))) if np.less_equal(t, t_n) else _wave(k2, k3, _exact_phase(Omega, t, t_n)))
    out = _out(out, shape)
    cells = _cells(shape, [[np.less_equal(t, t_n)]])
    for part in _blocks(cells[0]):
        Omega_, k0_, k4_, t_, t_n_, x2_ = _at(part, shape, Omega, k0, k4, t, t_n, x2)
        w0 = _exact_phase(Omega_, t_)
        _put(out, part, k4_ + x2_*(k0_*(-t_ + t_n_)*_entire_7(w0) + _entire_5(w0)))
    for part in _blocks(cells[1]):
        Omega_, k2_, k3_, k4_, t_, t_n_ = _at(part, shape, Omega, k2, k3, k4, t, t_n)
        _put(out, part, k4_ + _wave(k2_, k3_, _exact_phase(Omega_, t_, t_n_)))
    return out


def dynamic_coefficient_from_weight_a3(t, Omega, m1, m2, g, v0, t_n, *, out=None):
    """K_din^(2)(t) for the drive law a_3 of (30), lifting from weight; Omega from natural_frequency. Eq (27), (28), (30).

    Parameters
    ----------
    t : array_like
        time from the start of the drive [s], >= 0; served from 0.0 to 1e7
    Omega : array_like
        natural circular frequency Ω of the rope stretch [rad/s], > 0; served from 2e-6 to 6e7
    m1 : array_like
        reduced mass of the drive (first mass) [kg], > 0; served from 1e-9 to 1e17
    m2 : array_like
        mass of the load (second mass) [kg], > 0; served from 0.001 to 5e10
    g : array_like
        acceleration of gravity [m/s^2], > 0; served from 9.8e-6 to 9.82e6
    v0 : array_like
        steady hoisting speed after the start [m/s], > 0; served from 1e-7 to 1e6
    t_n : array_like
        duration of the start (transient) t_п [s], > 0; served from 1e-17 to 1e7
    out : ndarray, optional
        float64 array of the broadcast shape; the result is written into it and returned.

    Returns
    -------
    ndarray
        [1], broadcast over the arguments.
    """
    t     = _checked('t', t, 'nonnegative', 'time from the start of the drive, s', (0.0, 1e7))
    Omega = _checked('Omega', Omega, 'positive', 'natural circular frequency Ω of the rope stretch, rad/s', (2e-6, 6e7))
    m1    = _checked('m1', m1, 'positive', 'reduced mass of the drive (first mass), kg', (1e-9, 1e17))
    m2    = _checked('m2', m2, 'positive', 'mass of the load (second mass), kg', (0.001, 5e10))
    g     = _checked('g', g, 'positive', 'acceleration of gravity, m/s^2', (9.8e-6, 9.82e6))
    v0    = _checked('v0', v0, 'positive', 'steady hoisting speed after the start, m/s', (1e-7, 1e6))
    t_n   = _checked('t_n', t_n, 'positive', 'duration of the start (transient) t_п, s', (1e-17, 1e7))
    shape = _broadcast(t=t, Omega=Omega, m1=m1, m2=m2, g=g, v0=v0, t_n=t_n)
    x0 = 1/(t_n)
    x1 = v0/g
    x2 = Omega*t_n
    x3 = x0*x1
    k1 = 48*x1/(Omega*t_n**2)
    k2 = -24*x3*_entire_8(x2)
    k3 = -72*x3*_entire_9(x2)
    if out is None and not shape:      # one point: its own branch only
        return (k1*(x0*(-t + t_n)*(x0*(-t + t_n)*_entire_10(_exact_phase(Omega, t)) + _entire_11(_exact_phase(Omega, t))) + _entire_12(_exact_phase(Omega, t))) if np.less_equal(t, t_n) else _wave(k2, k3, _exact_phase(Omega, t, t_n))) + 1
    out = _out(out, shape)
    cells = _cells(shape, [[np.less_equal(t, t_n)]])
    for part in _blocks(cells[0]):
        Omega_, k1_, t_, t_n_, x0_ = _at(part, shape, Omega, k1, t, t_n, x0)
        w0 = _exact_phase(Omega_, t_)
        w1 = x0_*(-t_ + t_n_)
        _put(out, part, k1_*(w1*(w1*_entire_10(w0) + _entire_11(w0)) + _entire_12(w0)) + 1)
    for part in _blocks(cells[1]):
        Omega_, k2_, k3_, t_, t_n_ = _at(part, shape, Omega, k2, k3, t, t_n)
        _put(out, part, _wave(k2_, k3_, _exact_phase(Omega_, t_, t_n_)) + 1)
    return out


def dynamic_coefficient_from_weight_a4(t, Omega, m1, m2, g, v0, t_n, *, out=None):
    """K_din^(2)(t) for the drive law a_4 of (30), lifting from weight; Omega from natural_frequency. Eq (27), (28), (30).

    Parameters
    ----------
    t : array_like
        time from the start of the drive [s], >= 0; served from 0.0 to 1e7
    Omega : array_like
        natural circular frequency Ω of the rope stretch [rad/s], > 0; served from 2e-6 to 6e7
    m1 : array_like
        reduced mass of the drive (first mass) [kg], > 0; served from 1e-9 to 1e17
    m2 : array_like
        mass of the load (second mass) [kg], > 0; served from 0.001 to 5e10
    g : array_like
        acceleration of gravity [m/s^2], > 0; served from 9.8e-6 to 9.82e6
    v0 : array_like
        steady hoisting speed after the start [m/s], > 0; served from 1e-7 to 1e6
    t_n : array_like
        duration of the start (transient) t_п [s], > 0; served from 1e-17 to 1e7
    out : ndarray, optional
        float64 array of the broadcast shape; the result is written into it and returned.

    Returns
    -------
    ndarray
        [1], broadcast over the arguments.
    """
    t     = _checked('t', t, 'nonnegative', 'time from the start of the drive, s', (0.0, 1e7))
    Omega = _checked('Omega', Omega, 'positive', 'natural circular frequency Ω of the rope stretch, rad/s', (2e-6, 6e7))
    m1    = _checked('m1', m1, 'positive', 'reduced mass of the drive (first mass), kg', (1e-9, 1e17))
    m2    = _checked('m2', m2, 'positive', 'mass of the load (second mass), kg', (0.001, 5e10))
    g     = _checked('g', g, 'positive', 'acceleration of gravity, m/s^2', (9.8e-6, 9.82e6))
    v0    = _checked('v0', v0, 'positive', 'steady hoisting speed after the start, m/s', (1e-7, 1e6))
    t_n   = _checked('t_n', t_n, 'positive', 'duration of the start (transient) t_п, s', (1e-17, 1e7))
    shape = _broadcast(t=t, Omega=Omega, m1=m1, m2=m2, g=g, v0=v0, t_n=t_n)
    x0 = 1/(t_n)
    x1 = v0/g
    x2 = Omega*t_n
    x3 = x0*x1
    k1 = -120*x1/(Omega**2*_cube(t_n))
    k2 = -2880*x3*_entire_13(x2)
    k3 = -7200*x3*_entire_14(x2)
    if out is None and not shape:      # one point: its own branch only
        return (k1*(x0*(-t + t_n)*(x0*(-t + t_n)*(x0*(-t + t_n)*_entire_15(_exact_phase(Omega, t)) + _entire_16(_exact_phase(Omega, t))) + _entire_17(_exact_phase(Omega, t))) + _entire_18(_exact_phase(Omega, t))) if np.less_equal(t, t_n) else _wave(k2, k3, _exact_phase(Omega, t, t_n))) + 1
    out = _out(out, shape)
    cells = _cells(shape, [[np.less_equal(t, t_n)]])
    for part in _blocks(cells[0]):
        Omega_, k1_, t_, t_n_, x0_ = _at(part, shape, Omega, k1, t, t_n, x0)
        w0 = _exact_phase(Omega_, t_)
        w1 = x0_*(-t_ + t_n_)
        _put(out, part, k1_*(w1*(w1*(w1*_entire_15(w0) + _entire_16(w0)) + _entire_17(w0)) + _entire_18(w0)) + 1)
    for part in _blocks(cells[1]):
        Omega_, k2_, k3_, t_, t_n_ = _at(part, shape, Omega, k2, k3, t, t_n)
        _put(out, part, _wave(k2_, k3_, _exact_phase(Omega_, t_, t_n_)) + 1)
    return out


def optimal_coefficient_from_weight_a1(t, t_n, *, out=None):
    """k~_din1^(opt)(t) from weight, 0 <= t <= t_n. Eq (63), (65).

    Parameters
    ----------
    t : array_like
        time from the start of the drive [s], >= 0; served from 0.0 to 1e7
    t_n : array_like
        duration of the start (transient) t_п [s], > 0; served from 1e-17 to 1e7
    out : ndarray, optional
        float64 array of the broadcast shape; the result is written into it and returned.

    Returns
    -------
    ndarray
        [1], broadcast over the arguments.
    """
    if (out is None
            and (type(t) in (float, int) or type(t) is np.float64)
            and (type(t_n) in (float, int) or type(t_n) is np.float64)):
        if (0.0 <= t <= 1e7 and 1e-17 <= t_n <= 1e7):
            try:    # a failed check or a math error: the array path decides
                return np.float64(1)
            except (ArithmeticError, ValueError):
                pass
    t   = _checked('t', t, 'nonnegative', 'time from the start of the drive, s', (0.0, 1e7))
    t_n = _checked('t_n', t_n, 'positive', 'duration of the start (transient) t_п, s', (1e-17, 1e7))
    shape = _broadcast(t=t, t_n=t_n)
    return _into(out, shape, 1)


def optimal_coefficient_pickup_a1(t, t_n, v0, g, tau_0, *, out=None):
    """k~_din1^(opt)(t) with pick-up, 0 <= t <= t_n. Eq (64), (65), (66).

    Parameters
    ----------
    t : array_like
        time from the start of the drive [s], >= 0; served from 0.0 to 1e7
    t_n : array_like
        duration of the start (transient) t_п [s], > 0; served from 1e-17 to 1e7
    v0 : array_like
        steady hoisting speed after the start [m/s], > 0; served from 1e-7 to 1e6
    g : array_like
        acceleration of gravity [m/s^2], > 0; served from 9.8e-6 to 9.82e6
    tau_0 : array_like
        duration τ_0 of the contact of the load with the ground when lifting with pick-up [s], > 0; served from 1e-17 to 1e7
    out : ndarray, optional
        float64 array of the broadcast shape; the result is written into it and returned.

    Returns
    -------
    ndarray
        [1], broadcast over the arguments.
    """
    t     = _checked('t', t, 'nonnegative', 'time from the start of the drive, s', (0.0, 1e7))
    t_n   = _checked('t_n', t_n, 'positive', 'duration of the start (transient) t_п, s', (1e-17, 1e7))
    v0    = _checked('v0', v0, 'positive', 'steady hoisting speed after the start, m/s', (1e-7, 1e6))
    g     = _checked('g', g, 'positive', 'acceleration of gravity, m/s^2', (9.8e-6, 9.82e6))
    tau_0 = _checked('tau_0', tau_0, 'positive', 'duration τ_0 of the contact of the load with the ground when lifting with pick-up, s', (1e-17, 1e7))
    shape = _broadcast(t=t, t_n=t_n, v0=v0, g=g, tau_0=tau_0)
    k0 = g*t_n/(tau_0*v0)
    if out is None and not shape:      # one point: its own branch only
        return (k0*t + 1 if np.less_equal(t, tau_0) else 1)
    out = _out(out, shape)
    cells = _cells(shape, [[np.less_equal(t, tau_0)]])
    for part in _blocks(cells[0]):
        k0_, t_ = _at(part, shape, k0, t)
        _put(out, part, k0_*t_ + 1)
    for part in _blocks(cells[1]):
        _put(out, part, 1)
    return out


def optimal_coefficient_from_weight_a2(t, t_n, *, out=None):
    """k~_din2^(opt)(t) from weight, 0 <= t <= t_n. Eq (63), (65).

    Parameters
    ----------
    t : array_like
        time from the start of the drive [s], >= 0; served from 0.0 to 1e7
    t_n : array_like
        duration of the start (transient) t_п [s], > 0; served from 1e-17 to 1e7
    out : ndarray, optional
        float64 array of the broadcast shape; the result is written into it and returned.

    Returns
    -------
    ndarray
        [1], broadcast over the arguments.
    """
    if (out is None
            and (type(t) in (float, int) or type(t) is np.float64)
            and (type(t_n) in (float, int) or type(t_n) is np.float64)):
        if (0.0 <= t <= 1e7 and 1e-17 <= t_n <= 1e7):
            try:    # a failed check or a math error: the array path decides
                k0 = -t_n
                k1 = -1/t_n
                return np.float64(k1*(k0 + t))
            except (ArithmeticError, ValueError):
                pass
    t   = _checked('t', t, 'nonnegative', 'time from the start of the drive, s', (0.0, 1e7))
    t_n = _checked('t_n', t_n, 'positive', 'duration of the start (transient) t_п, s', (1e-17, 1e7))
    shape = _broadcast(t=t, t_n=t_n)
    k0 = -t_n
    k1 = -1/t_n
    if out is None and not shape:
        return k1*(k0 + t)
    out = _out(out, shape)
    for _o, (t, k0, k1) in _spans(out, shape, t, k0, k1):
        np.add(t, k0, out=_o)
        np.multiply(_o, k1, out=_o)
    return out


def optimal_coefficient_pickup_a2(t, t_n, v0, g, tau_0, *, out=None):
    """k~_din2^(opt)(t) with pick-up, 0 <= t <= t_n. Eq (64), (65), (66).

    Parameters
    ----------
    t : array_like
        time from the start of the drive [s], >= 0; served from 0.0 to 1e7
    t_n : array_like
        duration of the start (transient) t_п [s], > 0; served from 1e-17 to 1e7
    v0 : array_like
        steady hoisting speed after the start [m/s], > 0; served from 1e-7 to 1e6
    g : array_like
        acceleration of gravity [m/s^2], > 0; served from 9.8e-6 to 9.82e6
    tau_0 : array_like
        duration τ_0 of the contact of the load with the ground when lifting with pick-up [s], > 0; served from 1e-17 to 1e7
    out : ndarray, optional
        float64 array of the broadcast shape; the result is written into it and returned.

    Returns
    -------
    ndarray
        [1], broadcast over the arguments.
    """
    t     = _checked('t', t, 'nonnegative', 'time from the start of the drive, s', (0.0, 1e7))
    t_n   = _checked('t_n', t_n, 'positive', 'duration of the start (transient) t_п, s', (1e-17, 1e7))
    v0    = _checked('v0', v0, 'positive', 'steady hoisting speed after the start, m/s', (1e-7, 1e6))
    g     = _checked('g', g, 'positive', 'acceleration of gravity, m/s^2', (9.8e-6, 9.82e6))
    tau_0 = _checked('tau_0', tau_0, 'positive', 'duration τ_0 of the contact of the load with the ground when lifting with pick-up, s', (1e-17, 1e7))
    shape = _broadcast(t=t, t_n=t_n, v0=v0, g=g, tau_0=tau_0)
    k0 = -t_n
    k1 = -1/t_n
    k2 = g*t_n/(tau_0*v0)
    if out is None and not shape:      # one point: its own branch only
        return (k1*(k0 + t) + k2*t if np.less_equal(t, tau_0) else k1*(k0 + t))
    out = _out(out, shape)
    cells = _cells(shape, [[np.less_equal(t, tau_0)]])
    for part in _blocks(cells[0]):
        k0_, k1_, k2_, t_ = _at(part, shape, k0, k1, k2, t)
        _put(out, part, k1_*(k0_ + t_) + k2_*t_)
    for part in _blocks(cells[1]):
        k0_, k1_, t_ = _at(part, shape, k0, k1, t)
        _put(out, part, k1_*(k0_ + t_))
    return out


def optimal_coefficient_from_weight_a3(t, t_n, *, out=None):
    """k~_din3^(opt)(t) from weight, 0 <= t <= t_n. Eq (63), (65).

    Parameters
    ----------
    t : array_like
        time from the start of the drive [s], >= 0; served from 0.0 to 1e7
    t_n : array_like
        duration of the start (transient) t_п [s], > 0; served from 1e-17 to 1e7
    out : ndarray, optional
        float64 array of the broadcast shape; the result is written into it and returned.

    Returns
    -------
    ndarray
        [1], broadcast over the arguments.
    """
    if (out is None
            and (type(t) in (float, int) or type(t) is np.float64)
            and (type(t_n) in (float, int) or type(t_n) is np.float64)):
        if (0.0 <= t <= 1e7 and 1e-17 <= t_n <= 1e7):
            try:    # a failed check or a math error: the array path decides
                k0 = -t_n
                k1 = 12/t_n**3
                return np.float64(k1*t*(k0 + t)**2)
            except (ArithmeticError, ValueError):
                pass
    t   = _checked('t', t, 'nonnegative', 'time from the start of the drive, s', (0.0, 1e7))
    t_n = _checked('t_n', t_n, 'positive', 'duration of the start (transient) t_п, s', (1e-17, 1e7))
    shape = _broadcast(t=t, t_n=t_n)
    k0 = -t_n
    k1 = 12/_cube(t_n)
    if out is None and not shape:
        return k1*t*(k0 + t)**2
    out = _out(out, shape)
    for _o, (t, k0, k1) in _spans(out, shape, t, k0, k1):
        _w0 = np.empty_like(_o)
        np.add(t, k0, out=_w0)
        np.square(_w0, out=_w0)
        np.multiply(t, _w0, out=_o)
        np.multiply(_o, k1, out=_o)
    return out


def optimal_coefficient_pickup_a3(t, t_n, v0, g, tau_0, *, out=None):
    """k~_din3^(opt)(t) with pick-up, 0 <= t <= t_n. Eq (64), (65), (66).

    Parameters
    ----------
    t : array_like
        time from the start of the drive [s], >= 0; served from 0.0 to 1e7
    t_n : array_like
        duration of the start (transient) t_п [s], > 0; served from 1e-17 to 1e7
    v0 : array_like
        steady hoisting speed after the start [m/s], > 0; served from 1e-7 to 1e6
    g : array_like
        acceleration of gravity [m/s^2], > 0; served from 9.8e-6 to 9.82e6
    tau_0 : array_like
        duration τ_0 of the contact of the load with the ground when lifting with pick-up [s], > 0; served from 1e-17 to 1e7
    out : ndarray, optional
        float64 array of the broadcast shape; the result is written into it and returned.

    Returns
    -------
    ndarray
        [1], broadcast over the arguments.
    """
    t     = _checked('t', t, 'nonnegative', 'time from the start of the drive, s', (0.0, 1e7))
    t_n   = _checked('t_n', t_n, 'positive', 'duration of the start (transient) t_п, s', (1e-17, 1e7))
    v0    = _checked('v0', v0, 'positive', 'steady hoisting speed after the start, m/s', (1e-7, 1e6))
    g     = _checked('g', g, 'positive', 'acceleration of gravity, m/s^2', (9.8e-6, 9.82e6))
    tau_0 = _checked('tau_0', tau_0, 'positive', 'duration τ_0 of the contact of the load with the ground when lifting with pick-up, s', (1e-17, 1e7))
    shape = _broadcast(t=t, t_n=t_n, v0=v0, g=g, tau_0=tau_0)
    k0 = -t_n
    k1 = 12/_cube(t_n)
    k2 = g*t_n/(tau_0*v0)
    if out is None and not shape:      # one point: its own branch only
        return (t*(k1*(k0 + t)**2 + k2) if np.less_equal(t, tau_0) else k1*t*(k0 + t)**2)
    out = _out(out, shape)
    cells = _cells(shape, [[np.less_equal(t, tau_0)]])
    for part in _blocks(cells[0]):
        k0_, k1_, k2_, t_ = _at(part, shape, k0, k1, k2, t)
        _put(out, part, t_*(k1_*(k0_ + t_)**2 + k2_))
    for part in _blocks(cells[1]):
        k0_, k1_, t_ = _at(part, shape, k0, k1, t)
        _put(out, part, k1_*t_*(k0_ + t_)**2)
    return out


def optimal_coefficient_from_weight_a4(t, t_n, *, out=None):
    """k~_din4^(opt)(t) from weight, 0 <= t <= t_n. Eq (63), (65).

    Parameters
    ----------
    t : array_like
        time from the start of the drive [s], >= 0; served from 0.0 to 1e7
    t_n : array_like
        duration of the start (transient) t_п [s], > 0; served from 1e-17 to 1e7
    out : ndarray, optional
        float64 array of the broadcast shape; the result is written into it and returned.

    Returns
    -------
    ndarray
        [1], broadcast over the arguments.
    """
    if (out is None
            and (type(t) in (float, int) or type(t) is np.float64)
            and (type(t_n) in (float, int) or type(t_n) is np.float64)):
        if (0.0 <= t <= 1e7 and 1e-17 <= t_n <= 1e7):
            try:    # a failed check or a math error: the array path decides
                k0 = -t_n
                k1 = -60/t_n**5
                return np.float64(k1*t**2*(k0 + t)**3)
            except (ArithmeticError, ValueError):
                pass
    t   = _checked('t', t, 'nonnegative', 'time from the start of the drive, s', (0.0, 1e7))
    t_n = _checked('t_n', t_n, 'positive', 'duration of the start (transient) t_п, s', (1e-17, 1e7))
    shape = _broadcast(t=t, t_n=t_n)
    k0 = -t_n
    k1 = -60/t_n**5
    if out is None and not shape:
        return k1*t**2*_cube(k0 + t)
    out = _out(out, shape)
    for _o, (t, k0, k1) in _spans(out, shape, t, k0, k1):
        np.square(t, out=_o)
        _w0 = np.empty_like(_o)
        np.add(t, k0, out=_w0)
        _w1 = np.empty_like(_o)
        np.square(_w0, out=_w1)
        np.multiply(_w0, _w1, out=_w0)
        np.multiply(_o, _w0, out=_o)
        np.multiply(_o, k1, out=_o)
    return out


def optimal_coefficient_pickup_a4(t, t_n, v0, g, tau_0, *, out=None):
    """k~_din4^(opt)(t) with pick-up, 0 <= t <= t_n. Eq (64), (65), (66).

    Parameters
    ----------
    t : array_like
        time from the start of the drive [s], >= 0; served from 0.0 to 1e7
    t_n : array_like
        duration of the start (transient) t_п [s], > 0; served from 1e-17 to 1e7
    v0 : array_like
        steady hoisting speed after the start [m/s], > 0; served from 1e-7 to 1e6
    g : array_like
        acceleration of gravity [m/s^2], > 0; served from 9.8e-6 to 9.82e6
    tau_0 : array_like
        duration τ_0 of the contact of the load with the ground when lifting with pick-up [s], > 0; served from 1e-17 to 1e7
    out : ndarray, optional
        float64 array of the broadcast shape; the result is written into it and returned.

    Returns
    -------
    ndarray
        [1], broadcast over the arguments.
    """
    t     = _checked('t', t, 'nonnegative', 'time from the start of the drive, s', (0.0, 1e7))
    t_n   = _checked('t_n', t_n, 'positive', 'duration of the start (transient) t_п, s', (1e-17, 1e7))
    v0    = _checked('v0', v0, 'positive', 'steady hoisting speed after the start, m/s', (1e-7, 1e6))
    g     = _checked('g', g, 'positive', 'acceleration of gravity, m/s^2', (9.8e-6, 9.82e6))
    tau_0 = _checked('tau_0', tau_0, 'positive', 'duration τ_0 of the contact of the load with the ground when lifting with pick-up, s', (1e-17, 1e7))
    shape = _broadcast(t=t, t_n=t_n, v0=v0, g=g, tau_0=tau_0)
    k0 = -t_n
    k1 = -60/t_n**5
    k2 = g*t_n/(tau_0*v0)
    if out is None and not shape:      # one point: its own branch only
        return (t*(k1*t*_cube(k0 + t) + k2) if np.less_equal(t, tau_0) else k1*t**2*_cube(k0 + t))
    out = _out(out, shape)
    cells = _cells(shape, [[np.less_equal(t, tau_0)]])
    for part in _blocks(cells[0]):
        k0_, k1_, k2_, t_ = _at(part, shape, k0, k1, k2, t)
        _put(out, part, t_*(k1_*t_*_cube(k0_ + t_) + k2_))
    for part in _blocks(cells[1]):
        k0_, k1_, t_ = _at(part, shape, k0, k1, t)
        _put(out, part, k1_*t_**2*_cube(k0_ + t_))
    return out
