"""Numeric kernels that generated modules carry with them.

These are ordinary functions, tested here against mpmath; the code generator
copies the source of the ones a module needs into it (``inspect.getsource``),
so generated modules depend on NumPy alone. Double-double numbers are pairs
``(hi, lo)`` of floats or arrays with ``hi + lo`` the value (Dekker, Knuth).
"""
from __future__ import annotations

import math

import numpy as np


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


def _cube(x):
    """x**3 as two products: NumPy's ``x**3`` calls ``pow`` per point."""
    return x * (x * x)


def _fourth(x):
    """x**4 as two squarings."""
    x2 = x * x
    return x2 * x2


def _diff_of_products(a, b, c, d):
    """a*b - c*d to within a few ulp, even when the products nearly cancel."""
    p, p_err = _two_product(a, b)
    q, q_err = _two_product(c, d)
    return (p - q) + (p_err - q_err)


def _dd(x):
    """A double as a double-double."""
    return x, 0.0 * x


def _dd_add(x, y):
    """Sum of two double-doubles."""
    s, e = _two_sum(x[0], y[0])
    return _quick_two_sum(s, e + (x[1] + y[1]))


def _dd_mul(x, y):
    """Product of two double-doubles."""
    p, e = _two_product(x[0], y[0])
    return _quick_two_sum(p, e + (x[0] * y[1] + x[1] * y[0]))


def _dd_div(x, y):
    """Quotient of two double-doubles."""
    q1 = x[0] / y[0]
    r = _dd_add(x, _dd_mul((-q1, 0.0 * q1), y))
    return _quick_two_sum(q1, r[0] / y[0])


def _dd_sqrt(x):
    """Square root of a positive double-double."""
    q = np.sqrt(x[0])
    p, e = _two_product(q, q)
    return _quick_two_sum(q, ((x[0] - p) - e + x[1]) / (2.0 * q))


def _phase(t, k):
    """t*k for a double t and a double-double k, as (hi, lo)."""
    hi, lo = _two_product(t, k[0])
    return hi, lo + t * k[1]


def _sin_phase(t, k):
    """sin(k*t), k a double-double: accurate where sin is near zero at large k*t."""
    hi, lo = _phase(t, k)
    return np.sin(hi) + np.cos(hi) * lo


def _cos_phase(t, k):
    """cos(k*t), k a double-double: accurate where cos is near zero at large k*t."""
    hi, lo = _phase(t, k)
    return np.cos(hi) - np.sin(hi) * lo


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


def _cos_remainder(x, n):
    """cos(x) - sum_{k<n} (-1)**k x**(2k)/(2k)!, accurate at small |x|."""
    return _taylor_remainder(x, n, 0)


def _sin_remainder(x, n):
    """sin(x) - sum_{k<n} (-1)**k x**(2k+1)/(2k+1)!, accurate at small |x|."""
    return _taylor_remainder(x, n, 1)


def _compensated_cumsum(a):
    """Prefix sums of a 1-D real or complex array, as accurate as sums formed in
    twice the working precision and rounded once, whatever the length: the
    prefix sums of ``np.cumsum``, the exact rounding error of each of its
    additions (Knuth's two-sum, in place), and the prefix sums of those errors
    added back (Ogita, Rump and Oishi's Sum2, as a prefix sum). Relies on
    ``np.cumsum`` adding left to right, as ``np.add.accumulate`` does."""
    s = np.cumsum(a)
    e = np.empty_like(s)
    e[:1] = 0.0
    err, before, after, term = e[1:], s[:-1], s[1:], a[1:]
    v = after - before                 # two-sum of before + term = after
    np.subtract(after, v, out=err)
    np.subtract(before, err, out=err)
    np.subtract(term, v, out=v)
    np.add(err, v, out=err)
    np.cumsum(e, out=e)
    np.add(s, e, out=s)
    return s


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


def _matrix(shape, elements):
    """Row-major ``elements`` as an array of ``shape`` followed by the
    broadcast shape of the elements (a matrix per input point)."""
    flat = np.broadcast_arrays(*[np.asarray(e, dtype=float) for e in elements])
    return np.stack(flat).reshape(tuple(shape) + flat[0].shape)


def _phase_sum(t, edges, first, powers, sigmas, omegas, cos_amps, sin_amps, consts):
    """A piecewise closed form tabulated per phase, at times ``t``.

    Phase i holds on [edges[i], edges[i + 1]) with τ = t − edges[i] and its
    terms j = first[i] … first[i + 1] − 1:
    consts[i] + Σ_j τ^k_j e^{σ_j τ} (a_j cos ω_j τ + b_j sin ω_j τ).
    Each phase is evaluated on its own points only (one partition of t).
    """
    flat = t.ravel()
    which = np.searchsorted(edges, flat, side="right") - 1
    np.clip(which, 0, consts.size - 1, out=which)
    order = np.argsort(which, kind="stable")
    cuts = np.searchsorted(which[order], np.arange(consts.size + 1))
    result = np.empty(flat.shape)
    for i in range(consts.size):
        points = order[cuts[i]:cuts[i + 1]]
        if not points.size:
            continue
        tau = flat[points] - edges[i]
        acc = np.full(tau.shape, consts[i])
        for j in range(first[i], first[i + 1]):
            if omegas[j]:
                angle = omegas[j] * tau
                term = cos_amps[j] * np.cos(angle) + sin_amps[j] * np.sin(angle)
            else:
                term = np.full(tau.shape, cos_amps[j])
            if sigmas[j]:
                term *= np.exp(sigmas[j] * tau)
            if powers[j]:
                term *= tau ** powers[j]
            acc += term
        result[points] = acc
    return result.reshape(t.shape)


def _required(value, what):
    """ValueError unless ``value`` > 0 at every point: a condition between
    arguments (``what``) without which the formula has no real value."""
    if not np.all(np.asarray(value) > 0):
        raise ValueError(f"the arguments must satisfy {what}")


#: kernel -> kernels it calls, so a module carries only what it uses.
DEPENDS = {
    "_checked": (), "_broadcast": (), "_out": (), "_into": ("_out",),
    "_two_sum": (), "_quick_two_sum": (), "_two_product": (),
    "_diff_of_products": ("_two_product",),
    "_dd": (),
    "_dd_add": ("_two_sum", "_quick_two_sum"),
    "_dd_mul": ("_two_product", "_quick_two_sum"),
    "_dd_div": ("_dd_add", "_dd_mul", "_quick_two_sum"),
    "_dd_sqrt": ("_two_product", "_quick_two_sum"),
    "_phase": ("_two_product",),
    "_sin_phase": ("_phase",), "_cos_phase": ("_phase",),
    "_compensated_cumsum": (),
    "_matrix": (),
    "_phase_sum": (), "_required": (),
    "_taylor_tail": (),
    "_taylor_remainder": ("_taylor_tail",),
    "_cos_remainder": ("_taylor_remainder",), "_sin_remainder": ("_taylor_remainder",),
    "_taylor_where": (), "_remainder_float": (), "_cube": (), "_fourth": (),
}


def closure(names: set[str], depends: dict | None = None) -> list[str]:
    """``names`` and every kernel they depend on, in the order of ``depends``
    (default: this module's ``DEPENDS``).

    Parameters
    ----------
    names : set of str
        Kernel names a module calls.
    depends : dict, optional
        Kernel name -> the kernels it calls.
    """
    depends = DEPENDS if depends is None else depends
    needed: set[str] = set()
    todo = list(names)
    while todo:
        name = todo.pop()
        if name not in needed:
            needed.add(name)
            todo.extend(depends[name])
    return [name for name in depends if name in needed]
