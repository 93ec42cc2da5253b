"""Numeric functions for derivation 'portal_travel'. Generated; do not edit.

Source: crane_sym.derivations.portal_travel (paper 003_5e8a923a75d2f7ba.txt:
Travel mechanisms of rail-mounted portal cranes: gear geometry, start-up with backlash and support loads).
Specialized to scene 'form1_gear_pair' (Paper 003, Form 1: the travel bogie's open gear pair): outputs operating_pressure_angle, shift_sum, tip_diameter, tip_thickness, contact_ratio, undercut_limit; folded in: m = 0.01 m, z1 = 25.0 1, z2 = 42.0 1, a_w = 0.34 m, h_a = 1.0 1, alpha = 0.3490658503988659 rad, dy1 = 0.0 1, dy2 = 0.0 1.
Inputs left as arguments: z, x, dy, x1, x2.
Equations: Form 1, d_a1, Form 1, s_a1, Form 1, x_sum, undercut limit, Form 1, alpha_tw, Form 1, epsilon_alpha.
Printed by SymPy 1.14.0 with crane_sym 0.1.0; regenerate with `crane-sym generate --scene form1_gear_pair --out <folder>`.

Functions and argument order:
    operating_pressure_angle() -> [rad]    eq Form 1, alpha_tw
    shift_sum() -> [1]    eq Form 1, x_sum
    tip_diameter(z, x, dy) -> [m]    eq Form 1, d_a1
    tip_thickness(z, x, dy) -> [m]    eq Form 1, s_a1
    contact_ratio(x1, x2) -> [1]    eq Form 1, epsilon_alpha
    undercut_limit(z) -> [1]    eq undercut limit
"""

import numpy as np

__all__ = ['operating_pressure_angle', 'shift_sum', 'tip_diameter', 'tip_thickness', 'contact_ratio', 'undercut_limit']

SCENE_NAME = 'form1_gear_pair'
SCENE_TITLE = "Paper 003, Form 1: the travel bogie's open gear pair"


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


def _acos_checked(x, what):
    """arccos x, or ValueError(what) when |x| > 1 (an impossible geometry)."""
    x = np.asarray(x, dtype=float)
    if np.any(np.abs(x) > 1.0):
        worst = float(x.flat[int(np.argmax(np.abs(x)))])
        raise ValueError(f"{what} (the cosine would be {worst!r})")
    return np.arccos(x)


def _tip_half_angle(x, z, alpha, ha, dy, what):
    """Half the angle a tooth subtends on its tip circle, psi_a =
    (pi/2 + 2 x tan alpha)/z - (inv alpha_a - inv alpha), for a rack-cut gear.

    With e = 2(ha + x - dy)/D, D = z + 2(ha + x - dy) (the tip diameter over
    m) and cos alpha_a = cos(alpha)(1 - e), the difference of involutes is
    formed without cancellation: delta = alpha_a - alpha by atan2 of exact
    products, then psi_a = (pi/2 + 2 tan(alpha)(dy - ha))/z - H(delta) with H of
    ``_tip_lift_excess`` (the shift's share of the half angle cancels exactly).
    Near a pointed tip psi_a is a small difference of two O(1/z) terms, so the
    chain runs in NumPy's ``longdouble`` (64-bit significand on x86) and is
    rounded to float once: the rounding of delta no longer shows through the
    cancellation. ValueError(what) when the tip circle lies inside the base
    circle (``what=None``: no check)."""
    ld = np.longdouble
    x, z, alpha, ha, dy = (np.asarray(v, dtype=float).astype(ld) for v in (x, z, alpha, ha, dy))
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
    half = ld(np.pi) / 2 + ld(1.2246467991473532e-16) / 2     # pi/2 to longdouble
    out = (half + 2.0 * np.tan(alpha) * (dy - ha)) / z - _tip_lift_excess(delta, alpha)
    return np.asarray(out, dtype=float)


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


def operating_pressure_angle(*, out=None):
    """Operating pressure angle alpha_tw of the pair at centre distance a_w. Specialized to scene 'form1_gear_pair'. Eq Form 1, alpha_tw.

    Parameters
    ----------

    out : ndarray, optional
        float64 array of the broadcast shape; the result is written into it and returned.

    Returns
    -------
    ndarray
        [rad], broadcast over the arguments.
    """
    shape = _broadcast()
    return _into(out, shape, 0.38745508295895126)


def shift_sum(*, out=None):
    """Sum of shift coefficients x1 + x2 from the meshing equation. Specialized to scene 'form1_gear_pair'. Eq Form 1, x_sum.

    Parameters
    ----------

    out : ndarray, optional
        float64 array of the broadcast shape; the result is written into it and returned.

    Returns
    -------
    ndarray
        [1], broadcast over the arguments.
    """
    shape = _broadcast()
    return _into(out, shape, 0.5268056264721714)


def tip_diameter(z, x, dy, *, out=None):
    """Tip diameter m*z + 2*(h_a + x - dy)*m. Specialized to scene 'form1_gear_pair'. Eq Form 1, d_a1.

    Parameters
    ----------
    z : array_like
        number of teeth [1], > 0; served from 8e-6 to 1.5e8
    x : array_like
        shift coefficient of the gear [1]; served from -1e6 to 1e6
    dy : array_like
        tip shortening coefficient Δy (>= 0) [1], >= 0; served from 0.0 to 300000.0
    out : ndarray, optional
        float64 array of the broadcast shape; the result is written into it and returned.

    Returns
    -------
    ndarray
        [m], broadcast over the arguments.
    """
    if (out is None
            and (type(z) in (float, int) or type(z) is np.float64)
            and (type(x) in (float, int) or type(x) is np.float64)
            and (type(dy) in (float, int) or type(dy) is np.float64)):
        if (8e-6 <= z <= 1.5e8 and -1e6 <= x <= 1e6 and 0.0 <= dy <= 300000.0):
            try:    # a failed check or a math error: the array path decides
                return np.float64(-5764607523034235/288230376151711744*dy + (5764607523034235/288230376151711744)*x + (5764607523034235/576460752303423488)*z + 5764607523034235/288230376151711744)
            except (ArithmeticError, ValueError):
                pass
    z  = _checked('z', z, 'positive', 'number of teeth, 1', (8e-6, 1.5e8))
    x  = _checked('x', x, 'real', 'shift coefficient of the gear, 1', (-1e6, 1e6))
    dy = _checked('dy', dy, 'nonnegative', 'tip shortening coefficient Δy (>= 0), 1', (0.0, 300000.0))
    shape = _broadcast(z=z, x=x, dy=dy)
    return _into(out, shape, -5764607523034235/288230376151711744*dy + (5764607523034235/288230376151711744)*x + (5764607523034235/576460752303423488)*z + 5764607523034235/288230376151711744)


def tip_thickness(z, x, dy, *, out=None):
    """Tooth thickness on the tip circle (negative: the tooth is pointed below the tip). Specialized to scene 'form1_gear_pair'. Eq Form 1, s_a1.

    Parameters
    ----------
    z : array_like
        number of teeth [1], > 0; served from 8e-6 to 1.5e8
    x : array_like
        shift coefficient of the gear [1]; served from -1e6 to 1e6
    dy : array_like
        tip shortening coefficient Δy (>= 0) [1], >= 0; served from 0.0 to 300000.0
    out : ndarray, optional
        float64 array of the broadcast shape; the result is written into it and returned.

    Returns
    -------
    ndarray
        [m], broadcast over the arguments.
    """
    z  = _checked('z', z, 'positive', 'number of teeth, 1', (8e-6, 1.5e8))
    x  = _checked('x', x, 'real', 'shift coefficient of the gear, 1', (-1e6, 1e6))
    dy = _checked('dy', dy, 'nonnegative', 'tip shortening coefficient Δy (>= 0), 1', (0.0, 300000.0))
    shape = _broadcast(z=z, x=x, dy=dy)
    return _into(out, shape, (5764607523034235/576460752303423488)*(-2*dy + 2*x + z + 2)*_tip_half_angle(x, z, 6288211335136391/18014398509481984, 1, dy, 'x: the tip circle lies inside the base circle (shift too negative)'))


def contact_ratio(x1, x2, *, out=None):
    """Transverse contact ratio epsilon_alpha. Specialized to scene 'form1_gear_pair'. Eq Form 1, epsilon_alpha.

    Parameters
    ----------
    x1 : array_like
        shift coefficient of the pinion [1]; served from -1e6 to 1e6
    x2 : array_like
        shift coefficient of the wheel [1]; served from -1e6 to 1e6
    out : ndarray, optional
        float64 array of the broadcast shape; the result is written into it and returned.

    Returns
    -------
    ndarray
        [1], broadcast over the arguments.
    """
    x1 = _checked('x1', x1, 'real', 'shift coefficient of the pinion, 1', (-1e6, 1e6))
    x2 = _checked('x2', x2, 'real', 'shift coefficient of the wheel, 1', (-1e6, 1e6))
    shape = _broadcast(x1=x1, x2=x2)
    return _into(out, shape, 3.9788735772973833*np.tan(_acos_checked(23.49231551964771/(2*x1 + 27), 'x1: the tip circle lies inside the base circle (shift too negative)')) + 6.684507609859604*np.tan(_acos_checked(19.733545036504076/(x2 + 22), 'x2: the tip circle lies inside the base circle (shift too negative)')) - 4.351545605487496)


def undercut_limit(z, *, out=None):
    """Least shift coefficient free of undercut (Fig. 10, curve 4). Specialized to scene 'form1_gear_pair'. Eq undercut limit.

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
