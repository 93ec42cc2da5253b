"""Numeric functions for derivation 'portal_travel'. Generated; do not edit.

Source: crane_sym.derivations.portal_travel (paper 003_5e8a923a75d2f7ba.txt:
Travel mechanisms of rail-mounted portal cranes: gear geometry and support loads).
Specialized to scene 'fig10_shift_limits' (Paper 003, Fig. 10: shift coefficient limits against the number of teeth): outputs pointed_tip_shift, tip_thickness_shift, undercut_limit; folded in: h_a = 1.0 1, alpha = 0.3490658503988659 rad, dy = 0.0 1.
Inputs left as arguments: z, sigma.
Equations: pointed tip, undercut limit.
Printed by SymPy 1.14.0 with crane_sym 0.1.0; regenerate with `crane-sym generate`.

Functions and argument order:
    pointed_tip_shift(z) -> [1]    eq pointed tip
    tip_thickness_shift(z, sigma) -> [1]    eq pointed tip
    undercut_limit(z) -> [1]    eq undercut limit
"""

import numpy as np

__all__ = ['pointed_tip_shift', 'tip_thickness_shift', 'undercut_limit']


def _checked(name, value, sign, what):
    """``value`` as a float array; ValueError naming ``name`` if it is not a
    finite number of the required sign, TypeError if it is not a number."""
    if type(value) in (float, int, np.float64):  # a plain number: no array pass
        number = float(value) if abs(value) < 1e308 else float("inf")
        if number != number or abs(number) == float("inf"):
            raise ValueError(f"{name} must be finite ({what}), got a NaN or inf")
        if sign == "positive" and not number > 0:
            raise ValueError(f"{name} must be > 0 ({what}), got {number!r}")
        if sign == "nonnegative" and not number >= 0:
            raise ValueError(f"{name} must be >= 0 ({what}), got {number!r}")
        return np.float64(number)
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
    return array


def _angle_minus_sine(d):
    """d - sin d without cancellation: its Taylor series below |d| = 1.2."""
    d = np.asarray(d, dtype=float)
    coeffs = (0.16666666666666666, -0.008333333333333333, 0.0001984126984126984,
              -2.7557319223985893e-06, 2.505210838544172e-08, -1.6059043836821613e-10,
              7.647163731819816e-13, -2.8114572543455206e-15, 8.22063524662433e-18,
              -1.9572941063391263e-20)
    small = np.abs(d) < 1.2
    y = np.where(small, d * d, 0.0)
    total = np.zeros_like(y)
    for c in coeffs[::-1]:
        total = total * y + c
    return np.where(small, d * y * total, d - np.sin(d))


def _tip_half_angle(x, z, alpha, ha, dy, what):
    """Half the angle a tooth subtends on its tip circle, psi_a =
    (pi/2 + 2 x tan alpha)/z - (inv alpha_a - inv alpha), for a rack-cut gear.

    With e = 2(ha + x - dy)/D, D = z + 2(ha + x - dy) (the tip diameter over
    m) and cos alpha_a = cos(alpha)(1 - e), the difference of involutes is
    formed without cancellation: delta = alpha_a - alpha by atan2 of exact
    products, then inv alpha_a - inv alpha = (delta (sin² alpha + cos² alpha e)
    - (delta - sin delta)) / (cos alpha cos alpha_a). ValueError(what) when the
    tip circle lies inside the base circle (``what=None``: no check)."""
    lift = ha + x - dy
    d_a = z + 2.0 * lift
    e = 2.0 * lift / d_a
    c, s = np.cos(alpha), np.sin(alpha)
    c_a = c * (1.0 - e)
    one_minus = 2.0 * np.sin(0.5 * alpha) ** 2 + c * e          # 1 - c_a
    if what is not None and (np.any(one_minus < 0) or np.any(c_a < 0)):
        raise ValueError(what)
    one_minus = np.maximum(one_minus, 0.0)
    s_a = np.sqrt(one_minus * (1.0 + c_a))
    num = c * e * (c * c * (2.0 - e) / (s_a + s) + s)
    delta = np.arctan2(num, c * c_a + s * s_a)
    gap = (delta * (s * s + c * c * e) - _angle_minus_sine(delta)) / (c * c_a)
    return (0.5 * np.pi + 2.0 * x * np.tan(alpha)) / z - gap


def _tip_shift(z, alpha, ha, dy, sigma):
    """The shift x at which the tooth tip thickness is sigma·m (0: pointed tip).

    Bracketed in the tip pressure angle u in (0, pi/2), x(u) = z(cos alpha /
    cos u - 1)/2 - ha + dy increasing: from u = alpha (tip on the reference
    circle) or, when the tooth is already thinner there, from the base circle,
    up to pi/2, where the thickness is -inf. Bisection in u, then Newton steps
    in x with the exact slope 2 psi_a + 2(z + 2(ha + x - dy)) tan(alpha)/z -
    2 tan(u). ValueError when no shift gives the thickness."""
    z, alpha, ha, dy, sigma = np.broadcast_arrays(*(np.asarray(a, dtype=float)
                                                    for a in (z, alpha, ha, dy, sigma)))

    def shift(u):
        return 0.5 * z * (np.cos(alpha) / np.cos(u) - 1.0) - ha + dy

    def excess(u):
        x = shift(u)
        return (z + 2.0 * (ha + x - dy)) * _tip_half_angle(x, z, alpha, ha, dy, what) - sigma

    what = None

    lo = np.where(excess(alpha) > 0, alpha, 1e-6)
    if np.any(excess(lo) <= 0):
        raise ValueError("sigma: no shift gives this tip thickness (the tooth is "
                         "thinner even with its tip on the base circle)")
    hi = np.full_like(lo, 0.5 * np.pi * (1.0 - 1e-12))
    for _ in range(80):
        mid = 0.5 * (lo + hi)
        up = excess(mid) > 0
        lo = np.where(up, mid, lo)
        hi = np.where(up, hi, mid)
    x = shift(0.5 * (lo + hi))
    for _ in range(3):
        d_a = z + 2.0 * (ha + x - dy)
        alpha_a = np.arccos(np.clip(z * np.cos(alpha) / d_a, -1.0, 1.0))
        psi = _tip_half_angle(x, z, alpha, ha, dy, what)
        slope = 2.0 * psi + 2.0 * d_a * np.tan(alpha) / z - 2.0 * np.tan(alpha_a)
        x = x - (d_a * psi - sigma) / slope
    return x


def pointed_tip_shift(z):
    """Shift coefficient at which the tooth tip is pointed (Fig. 10, curve 1). Specialized to scene 'fig10_shift_limits'. Eq pointed tip.

    Parameters
    ----------
    z : array_like
        number of teeth [1], > 0

    Returns
    -------
    ndarray
        [1], broadcast over the arguments.
    """
    z = _checked('z', z, 'positive', 'number of teeth, 1')
    return _tip_shift(z, 6288211335136391/18014398509481984, 1, 0, 0)


def tip_thickness_shift(z, sigma):
    """Shift coefficient at which the tip thickness is sigma*m (Fig. 10, curves 2-3). Specialized to scene 'fig10_shift_limits'. Eq pointed tip.

    Parameters
    ----------
    z : array_like
        number of teeth [1], > 0
    sigma : array_like
        tip tooth thickness over the module, s_a/m [1], >= 0

    Returns
    -------
    ndarray
        [1], broadcast over the arguments.
    """
    z     = _checked('z', z, 'positive', 'number of teeth, 1')
    sigma = _checked('sigma', sigma, 'nonnegative', 'tip tooth thickness over the module, s_a/m, 1')
    return _tip_shift(z, 6288211335136391/18014398509481984, 1, 0, sigma)


def undercut_limit(z):
    """Least shift coefficient free of undercut (Fig. 10, curve 4). Specialized to scene 'fig10_shift_limits'. Eq undercut limit.

    Parameters
    ----------
    z : array_like
        number of teeth [1], > 0

    Returns
    -------
    ndarray
        [1], broadcast over the arguments.
    """
    z = _checked('z', z, 'positive', 'number of teeth, 1')
    return 1 - 0.05848888922025548*z
