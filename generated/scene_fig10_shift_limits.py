"""Numeric functions for derivation 'portal_travel'. Generated; do not edit.

Source: crane_sym.derivations.portal_travel (paper 003_5e8a923a75d2f7ba.txt:
Travel mechanisms of rail-mounted portal cranes: gear geometry, start-up with backlash and support loads).
Specialized to scene 'fig10_shift_limits' (Paper 003, Fig. 10: shift coefficient limits against the number of teeth): outputs pointed_tip_shift, tip_thickness_shift, undercut_limit; folded in: h_a = 1.0 1, alpha = 0.3490658503988659 rad, dy = 0.0 1.
Inputs left as arguments: z, sigma.
Equations: pointed tip, undercut limit.
Printed by SymPy 1.14.0 with crane_sym 0.1.0; regenerate with `crane-sym generate --scene fig10_shift_limits --out <folder>`.

Functions and argument order:
    pointed_tip_shift(z) -> [1]    eq pointed tip
    tip_thickness_shift(z, sigma) -> [1]    eq pointed tip
    undercut_limit(z) -> [1]    eq undercut limit
"""

import numpy as np

__all__ = ['pointed_tip_shift', 'tip_thickness_shift', 'undercut_limit']

SCENE_NAME = 'fig10_shift_limits'
SCENE_TITLE = 'Paper 003, Fig. 10: shift coefficient limits against the number of teeth'


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


def _tip_lift_excess(delta, alpha):
    """H(delta) = inv(alpha + delta) - inv(alpha) - tan(alpha)(cos alpha /
    cos(alpha + delta) - 1), written as (cos alpha·(sin d - d cos d) +
    sin alpha·(d sin d - (1 - cos d)))/cos(alpha + d): both brackets by their
    Taylor series below |d| = 1 (they start at d³/3 and d²/2), so H ≈
    tan(alpha)·d²/2 keeps every digit at small d. Evaluated in the dtype of
    ``delta`` (the tip kernels pass NumPy's extended ``longdouble``); the
    series' coefficients 2k/(2k+1)! and (2k-1)/(2k)! are formed in that dtype."""
    d = np.asarray(delta)
    d = d.astype(np.result_type(d.dtype, np.float64))
    alpha = np.asarray(alpha).astype(d.dtype)
    one = d.dtype.type(1)
    small = np.abs(d) < 1.0
    y = np.where(small, d * d, 0.0).astype(d.dtype)
    p1, p2 = np.zeros_like(y), np.zeros_like(y)
    for k in range(12, 0, -1):                  # Horner from the 12th term down
        sign = one if k % 2 else -one
        fact_odd = float(np.prod(np.arange(1, 2 * k + 2, dtype=float)))   # (2k+1)!
        fact_even = fact_odd / (2 * k + 1)                                  # (2k)!
        p1 = p1 * y + sign * (d.dtype.type(2 * k) / d.dtype.type(fact_odd))
        p2 = p2 * y + sign * (d.dtype.type(2 * k - 1) / d.dtype.type(fact_even))
    f1 = np.where(small, d * y * p1, np.sin(d) - d * np.cos(d))
    f2 = np.where(small, y * p2, d * np.sin(d) - 2.0 * np.sin(0.5 * d) ** 2)
    return (np.cos(alpha) * f1 + np.sin(alpha) * f2) / np.cos(alpha + d)


def _tip_shift(z, alpha, ha, dy, sigma):
    """The shift x at which the tooth tip thickness is sigma·m (0: pointed tip).

    With the tip pressure angle alpha + delta, x = z sin(alpha + delta/2)
    sin(delta/2)/cos(alpha + delta) - ha + dy, and the condition s_a = sigma·m
    becomes Phi(delta) = z·H(delta) + sigma cos(alpha + delta)/cos(alpha) - K
    = 0 with K = pi/2 + 2 tan(alpha)(dy - ha) (the thickness over m on the
    reference circle when the tip is there) and H of ``_tip_lift_excess``:
    no cancellation. Phi(0) = sigma - K < 0 and Phi -> +inf at alpha + delta
    -> pi/2: bisection on that bracket, then Newton steps with Phi' = z
    sin u (sin u - sin alpha)/cos² u - sigma sin u/cos alpha. The Newton
    steps and the final x (a difference when x is small) run in NumPy's
    ``longdouble``. ValueError when sigma >= K (no shift gives the thickness)."""
    z, alpha, ha, dy, sigma = np.broadcast_arrays(*(np.asarray(a, dtype=float)
                                                    for a in (z, alpha, ha, dy, sigma)))
    K = 0.5 * np.pi + 2.0 * np.tan(alpha) * (dy - ha)
    if np.any(sigma >= K):
        raise ValueError("sigma: no shift gives this tip thickness: sigma must stay "
                         "below pi/2 + 2*tan(alpha)*(dy - h_a)")
    c = np.cos(alpha)

    def phi(d):
        return z * _tip_lift_excess(d, alpha) + sigma * np.cos(alpha + d) / c - K

    lo = np.zeros_like(K)
    hi = 0.5 * np.pi - alpha
    for _ in range(110):
        mid = 0.5 * (lo + hi)
        up = phi(mid) > 0
        lo = np.where(up, lo, mid)
        hi = np.where(up, mid, hi)
    ld = np.longdouble
    z, alpha, ha, dy, sigma = (v.astype(ld) for v in (z, alpha, ha, dy, sigma))
    half = ld(np.pi) / 2 + ld(1.2246467991473532e-16) / 2     # pi/2 to longdouble
    K = half + 2.0 * np.tan(alpha) * (dy - ha)
    c = np.cos(alpha)
    d = 0.5 * (lo.astype(ld) + hi.astype(ld))
    for _ in range(3):
        u = alpha + d
        gap = 2.0 * np.cos(alpha + 0.5 * d) * np.sin(0.5 * d)        # sin u - sin alpha
        slope = z * np.sin(u) * gap / np.cos(u) ** 2 - sigma * np.sin(u) / c
        value = z * _tip_lift_excess(d, alpha) + sigma * np.cos(u) / c - K
        with np.errstate(divide="ignore", invalid="ignore"):
            step = np.where(slope > 0, value / slope, 0.0)
        d = np.clip(d - step, lo.astype(ld), hi.astype(ld))
    out = z * np.sin(alpha + 0.5 * d) * np.sin(0.5 * d) / np.cos(alpha + d) - ha + dy
    return np.asarray(out, dtype=float)


def pointed_tip_shift(z, *, out=None):
    """Shift coefficient at which the tooth tip is pointed (Fig. 10, curve 1). Specialized to scene 'fig10_shift_limits'. Eq pointed tip.

    Parameters
    ----------
    z : array_like
        number of teeth [1], > 0; served from 8e-6 to 1.5e8
    out : ndarray, optional
        float64 array of the broadcast shape; the result is written into it and returned.

    Returns
    -------
    ndarray
        [1], broadcast over the arguments.
    """
    z = _checked('z', z, 'positive', 'number of teeth, 1', (8e-6, 1.5e8))
    shape = _broadcast(z=z)
    return _into(out, shape, _tip_shift(z, 6288211335136391/18014398509481984, 1, 0, 0))


def tip_thickness_shift(z, sigma, *, out=None):
    """Shift coefficient at which the tip thickness is sigma*m (Fig. 10, curves 2-3). Specialized to scene 'fig10_shift_limits'. Eq pointed tip.

    Parameters
    ----------
    z : array_like
        number of teeth [1], > 0; served from 8e-6 to 1.5e8
    sigma : array_like
        tip tooth thickness over the module, s_a/m [1], >= 0; served from 0.0 to 500000.0
    out : ndarray, optional
        float64 array of the broadcast shape; the result is written into it and returned.

    Returns
    -------
    ndarray
        [1], broadcast over the arguments.
    """
    z     = _checked('z', z, 'positive', 'number of teeth, 1', (8e-6, 1.5e8))
    sigma = _checked('sigma', sigma, 'nonnegative', 'tip tooth thickness over the module, s_a/m, 1', (0.0, 500000.0))
    shape = _broadcast(z=z, sigma=sigma)
    return _into(out, shape, _tip_shift(z, 6288211335136391/18014398509481984, 1, 0, sigma))


def undercut_limit(z, *, out=None):
    """Least shift coefficient free of undercut (Fig. 10, curve 4). Specialized to scene 'fig10_shift_limits'. Eq undercut limit.

    Parameters
    ----------
    z : array_like
        number of teeth [1], > 0; served from 8e-6 to 1.5e8
    out : ndarray, optional
        float64 array of the broadcast shape; the result is written into it and returned.

    Returns
    -------
    ndarray
        [1], broadcast over the arguments.
    """
    if (out is None
            and (type(z) in (float, int) or type(z) is np.float64)):
        if (8e-6 <= z <= 1.5e8):
            try:    # a failed check or a math error: the array path decides
                return np.float64(1 - 0.05848888922025548*z)
            except (ArithmeticError, ValueError):
                pass
    z = _checked('z', z, 'positive', 'number of teeth, 1', (8e-6, 1.5e8))
    shape = _broadcast(z=z)
    return _into(out, shape, 1 - 0.05848888922025548*z)
