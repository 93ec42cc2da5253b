"""Numeric functions for derivation 'portal_travel'. Generated; do not edit.

Source: crane_sym.derivations.portal_travel (paper 003_5e8a923a75d2f7ba.txt:
Travel mechanisms of rail-mounted portal cranes: gear geometry, start-up with backlash and support loads).
Equations: (3), (4), pointed tip, Form 1, d_a1, Form 1, s_a1, Form 1, x_sum, undercut limit, Form 1, alpha_tw, Form 1, epsilon_alpha, start-up, rated force, start-up, slope ratio, start-up, link damping, start-up, no-load speed, start-up, rigid break-away, start-up, backlash at the rim, start-up, first characteristic, start-up, motor mass at the rim, start-up, motor speed in the gap.
Printed by SymPy 1.14.0 with crane_sym 0.1.0; regenerate with `crane-sym generate`.

Functions and argument order:
    operating_pressure_angle(m, z1, z2, a_w, alpha) -> [rad]    eq Form 1, alpha_tw
    shift_sum(m, z1, z2, a_w, alpha) -> [1]    eq Form 1, x_sum
    centre_distance(m, z1, z2, x_sum, alpha) -> [m]    eq Form 1, x_sum, Form 1, alpha_tw
    tip_diameter(m, z, x, h_a, dy) -> [m]    eq Form 1, d_a1
    tip_thickness(m, z, x, alpha, h_a, dy) -> [m]    eq Form 1, s_a1
    contact_ratio(m, z1, z2, x1, x2, a_w, alpha, h_a, dy1, dy2) -> [1]    eq Form 1, epsilon_alpha
    tip_thickness_shift(z, alpha, h_a, dy, sigma) -> [1]    eq pointed tip
    pointed_tip_shift(z, alpha, h_a, dy) -> [1]    eq pointed tip
    undercut_limit(z, alpha, h_a) -> [1]    eq undercut limit
    startup_gap_motor_speed(t_s, lambda_p, P_m, J_r, v_n, omega_0, omega_n) -> [m/s]    eq start-up, motor speed in the gap
    startup_motor_mass(J_r, n_m, omega_n, v_n) -> [kg]    eq start-up, motor mass at the rim
    startup_rated_force(P_m, n_m, v_n) -> [N]    eq start-up, rated force
    startup_no_load_speed(v_n, omega_0, omega_n) -> [m/s]    eq start-up, no-load speed
    startup_backlash_at_rim(phi_b, v_n, omega_n) -> [m]    eq start-up, backlash at the rim
    startup_first_slope(lambda_p, P_m, n_m, v_n, omega_0, omega_n) -> [N*s/m]    eq start-up, first characteristic
    startup_slope_ratio(lambda_p, omega_0, omega_n) -> [1]    eq start-up, slope ratio
    startup_link_damping(zeta, c_l, J_r, n_m, omega_n, v_n) -> [N*s/m]    eq start-up, link damping
    startup_rigid_breakaway(lambda_p, P_m, n_m, v_n, m_k, J_r, omega_n, W_f, W_w) -> [m/s^2]    eq start-up, rigid break-away
    max_support_load(psi, G_g, G_pch, G_vs, L_max, x_o, c) -> [N]    eq (3), (4)
"""

import math

import numpy as np

__all__ = ['operating_pressure_angle', 'shift_sum', 'centre_distance', 'tip_diameter', 'tip_thickness', 'contact_ratio', 'tip_thickness_shift', 'pointed_tip_shift', 'undercut_limit', 'startup_gap_motor_speed', 'startup_motor_mass', 'startup_rated_force', 'startup_no_load_speed', 'startup_backlash_at_rim', 'startup_first_slope', 'startup_slope_ratio', 'startup_link_damping', 'startup_rigid_breakaway', 'max_support_load']


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


def _involute(a):
    """inv a = tan a - a, without the cancellation of tan a - a at small a.

    Below |a| = 0.6 the Taylor series a³·Σ c_k a^(2k) (28 terms, truncation
    < 1e-18 relative) is summed by Horner's rule; above, tan a - a has lost
    at most a factor a/(tan a - a) < 8 to cancellation."""
    a = np.asarray(a, dtype=float)
    coeffs = (0.3333333333333333, 0.13333333333333333, 0.05396825396825397,
              0.021869488536155203, 0.008863235529902197, 0.003592128036572481,
              0.0014558343870513183, 0.000590027440945586, 0.00023912911424355248,
              9.691537956929451e-05, 3.927832388331683e-05, 1.5918905069328964e-05,
              6.451689215655431e-06, 2.6147711512907546e-06, 1.0597268320104654e-06,
              4.294911078273806e-07, 1.7406618963571648e-07, 7.054636946400968e-08,
              2.859136662305254e-08, 1.1587644432798853e-08, 4.6962953982309016e-09,
              1.903336833931276e-09, 7.713933635359062e-10, 3.126339545892087e-10,
              1.26705769303054e-10, 5.135191408039368e-11, 2.0812146867700473e-11,
              8.434845419094337e-12)
    small = np.abs(a) < 0.6
    y = np.where(small, a * a, 0.0)
    total = np.zeros_like(y)
    for c in coeffs[::-1]:
        total = total * y + c
    series = a * y * total
    with np.errstate(invalid="ignore", over="ignore"):
        closed = np.tan(np.where(small, 1.0, a)) - np.where(small, 1.0, a)
    return np.where(small, series, closed)


def _inverse_involute(v, what):
    """The angle a in [0, pi/2) with tan a - a = v, for v >= 0.

    Initial guess from the series inversion a ≈ (3v)^(1/3)(1 - (3v)^(2/3)/5)
    for small v and a ≈ pi/2 - 1/(v + pi/2) for large v, then Newton steps
    kept inside a bracket [lo, hi] that every step narrows (bisection when
    Newton would leave it): no starting guess can fail. ValueError(what) for v < 0."""
    v = np.asarray(v, dtype=float)
    if np.any(v < 0):
        raise ValueError(what)
    half_pi = 0.5 * np.pi
    lo = np.zeros_like(v)
    hi = np.full_like(v, half_pi)
    t = np.cbrt(3.0 * v)
    a = np.where(v < 1.0, t * (1.0 - t * t / 5.0), half_pi - 1.0 / (v + half_pi))
    a = np.clip(a, 0.0, half_pi * (1.0 - 1e-16))
    for _ in range(100):
        f = _involute(a) - v
        lo = np.where(f <= 0, a, lo)
        hi = np.where(f > 0, a, hi)
        slope = np.tan(a) ** 2
        with np.errstate(divide="ignore", invalid="ignore"):
            step = np.where(slope > 0, f / slope, np.inf)
        nxt = a - step
        bad = ~((nxt >= lo) & (nxt <= hi))
        nxt = np.where(bad, 0.5 * (lo + hi), nxt)
        if np.all(np.abs(nxt - a) <= 4e-16 * np.maximum(np.abs(a), 1e-300)):
            return np.where(v == 0, 0.0, nxt)
        a = nxt
    return np.where(v == 0, 0.0, a)


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


def operating_pressure_angle(m, z1, z2, a_w, alpha, *, out=None):
    """Operating pressure angle alpha_tw of the pair at centre distance a_w. Eq Form 1, alpha_tw.

    Parameters
    ----------
    m : array_like
        module of the teeth [m], > 0; served from 1e-9 to 50000.0
    z1 : array_like
        number of teeth of the pinion [1], > 0; served from 8e-6 to 1.5e8
    z2 : array_like
        number of teeth of the wheel [1], > 0; served from 8e-6 to 1.5e8
    a_w : array_like
        centre distance [m], > 0; served from 5e-8 to 5e6
    alpha : array_like
        profile angle of the basic rack [rad], > 0; served from 2e-7 to 1.4
    out : ndarray, optional
        float64 array of the broadcast shape; the result is written into it and returned.

    Returns
    -------
    ndarray
        [rad], broadcast over the arguments.
    """
    m     = _checked('m', m, 'positive', 'module of the teeth, m', (1e-9, 50000.0))
    z1    = _checked('z1', z1, 'positive', 'number of teeth of the pinion, 1', (8e-6, 1.5e8))
    z2    = _checked('z2', z2, 'positive', 'number of teeth of the wheel, 1', (8e-6, 1.5e8))
    a_w   = _checked('a_w', a_w, 'positive', 'centre distance, m', (5e-8, 5e6))
    alpha = _checked('alpha', alpha, 'positive', 'profile angle of the basic rack, rad', (2e-7, 1.4))
    shape = _broadcast(m=m, z1=z1, z2=z2, a_w=a_w, alpha=alpha)
    return _into(out, shape, _acos_checked((1/2)*m*(z1 + z2)*np.cos(alpha)/a_w, 'a_w: the centre distance is too small for this mesh: it must exceed m*(z1 + z2)*cos(alpha)/2, the sum of the base radii'))


def shift_sum(m, z1, z2, a_w, alpha, *, out=None):
    """Sum of shift coefficients x1 + x2 from the meshing equation. Eq Form 1, x_sum.

    Parameters
    ----------
    m : array_like
        module of the teeth [m], > 0; served from 1e-9 to 50000.0
    z1 : array_like
        number of teeth of the pinion [1], > 0; served from 8e-6 to 1.5e8
    z2 : array_like
        number of teeth of the wheel [1], > 0; served from 8e-6 to 1.5e8
    a_w : array_like
        centre distance [m], > 0; served from 5e-8 to 5e6
    alpha : array_like
        profile angle of the basic rack [rad], > 0; served from 2e-7 to 1.4
    out : ndarray, optional
        float64 array of the broadcast shape; the result is written into it and returned.

    Returns
    -------
    ndarray
        [1], broadcast over the arguments.
    """
    m     = _checked('m', m, 'positive', 'module of the teeth, m', (1e-9, 50000.0))
    z1    = _checked('z1', z1, 'positive', 'number of teeth of the pinion, 1', (8e-6, 1.5e8))
    z2    = _checked('z2', z2, 'positive', 'number of teeth of the wheel, 1', (8e-6, 1.5e8))
    a_w   = _checked('a_w', a_w, 'positive', 'centre distance, m', (5e-8, 5e6))
    alpha = _checked('alpha', alpha, 'positive', 'profile angle of the basic rack, rad', (2e-7, 1.4))
    shape = _broadcast(m=m, z1=z1, z2=z2, a_w=a_w, alpha=alpha)
    x0 = (1/2)*z1 + (1/2)*z2
    return _into(out, shape, x0*(-_involute(alpha) + _involute(_acos_checked(m*x0*np.cos(alpha)/a_w, 'a_w: the centre distance is too small for this mesh: it must exceed m*(z1 + z2)*cos(alpha)/2, the sum of the base radii')))/np.tan(alpha))


def centre_distance(m, z1, z2, x_sum, alpha, *, out=None):
    """Centre distance a_w at which the pair meshes without backlash with the sum of shifts x_sum (inverse involute). Eq Form 1, x_sum, Form 1, alpha_tw.

    Parameters
    ----------
    m : array_like
        module of the teeth [m], > 0; served from 1e-9 to 50000.0
    z1 : array_like
        number of teeth of the pinion [1], > 0; served from 8e-6 to 1.5e8
    z2 : array_like
        number of teeth of the wheel [1], > 0; served from 8e-6 to 1.5e8
    x_sum : array_like
        sum of shift coefficients x1 + x2 [1]; served from -2e6 to 2e6
    alpha : array_like
        profile angle of the basic rack [rad], > 0; served from 2e-7 to 1.4
    out : ndarray, optional
        float64 array of the broadcast shape; the result is written into it and returned.

    Returns
    -------
    ndarray
        [m], broadcast over the arguments.
    """
    m     = _checked('m', m, 'positive', 'module of the teeth, m', (1e-9, 50000.0))
    z1    = _checked('z1', z1, 'positive', 'number of teeth of the pinion, 1', (8e-6, 1.5e8))
    z2    = _checked('z2', z2, 'positive', 'number of teeth of the wheel, 1', (8e-6, 1.5e8))
    x_sum = _checked('x_sum', x_sum, 'real', 'sum of shift coefficients x1 + x2, 1', (-2e6, 2e6))
    alpha = _checked('alpha', alpha, 'positive', 'profile angle of the basic rack, rad', (2e-7, 1.4))
    shape = _broadcast(m=m, z1=z1, z2=z2, x_sum=x_sum, alpha=alpha)
    x0 = z1 + z2
    return _into(out, shape, (1/2)*m*x0*np.cos(alpha)/np.cos(_inverse_involute(_involute(alpha) + 2*x_sum*np.tan(alpha)/x0, 'x_sum: the shifts are too negative: inv(alpha) + 2*x_sum*tan(alpha)/(z1 + z2) must be >= 0')))


def tip_diameter(m, z, x, h_a, dy, *, out=None):
    """Tip diameter m*z + 2*(h_a + x - dy)*m. Eq Form 1, d_a1.

    Parameters
    ----------
    m : array_like
        module of the teeth [m], > 0; served from 1e-9 to 50000.0
    z : array_like
        number of teeth [1], > 0; served from 8e-6 to 1.5e8
    x : array_like
        shift coefficient of the gear [1]; served from -1e6 to 1e6
    h_a : array_like
        addendum coefficient of the basic rack h_a* [1], > 0; served from 8e-7 to 1.25e6
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
            and (type(m) in (float, int) or type(m) is np.float64)
            and (type(z) in (float, int) or type(z) is np.float64)
            and (type(x) in (float, int) or type(x) is np.float64)
            and (type(h_a) in (float, int) or type(h_a) is np.float64)
            and (type(dy) in (float, int) or type(dy) is np.float64)):
        if (1e-9 <= m <= 50000.0 and 8e-6 <= z <= 1.5e8 and -1e6 <= x <= 1e6
                and 8e-7 <= h_a <= 1.25e6 and 0.0 <= dy <= 300000.0):
            try:    # a failed check or a math error: the array path decides
                return np.float64(m*(-2*dy + 2*h_a + 2*x + z))
            except (ArithmeticError, ValueError):
                pass
    m   = _checked('m', m, 'positive', 'module of the teeth, m', (1e-9, 50000.0))
    z   = _checked('z', z, 'positive', 'number of teeth, 1', (8e-6, 1.5e8))
    x   = _checked('x', x, 'real', 'shift coefficient of the gear, 1', (-1e6, 1e6))
    h_a = _checked('h_a', h_a, 'positive', 'addendum coefficient of the basic rack h_a*, 1', (8e-7, 1.25e6))
    dy  = _checked('dy', dy, 'nonnegative', 'tip shortening coefficient Δy (>= 0), 1', (0.0, 300000.0))
    shape = _broadcast(m=m, z=z, x=x, h_a=h_a, dy=dy)
    return _into(out, shape, m*(-2*dy + 2*h_a + 2*x + z))


def tip_thickness(m, z, x, alpha, h_a, dy, *, out=None):
    """Tooth thickness on the tip circle (negative: the tooth is pointed below the tip). Eq Form 1, s_a1.

    Parameters
    ----------
    m : array_like
        module of the teeth [m], > 0; served from 1e-9 to 50000.0
    z : array_like
        number of teeth [1], > 0; served from 8e-6 to 1.5e8
    x : array_like
        shift coefficient of the gear [1]; served from -1e6 to 1e6
    alpha : array_like
        profile angle of the basic rack [rad], > 0; served from 2e-7 to 1.4
    h_a : array_like
        addendum coefficient of the basic rack h_a* [1], > 0; served from 8e-7 to 1.25e6
    dy : array_like
        tip shortening coefficient Δy (>= 0) [1], >= 0; served from 0.0 to 300000.0
    out : ndarray, optional
        float64 array of the broadcast shape; the result is written into it and returned.

    Returns
    -------
    ndarray
        [m], broadcast over the arguments.
    """
    m     = _checked('m', m, 'positive', 'module of the teeth, m', (1e-9, 50000.0))
    z     = _checked('z', z, 'positive', 'number of teeth, 1', (8e-6, 1.5e8))
    x     = _checked('x', x, 'real', 'shift coefficient of the gear, 1', (-1e6, 1e6))
    alpha = _checked('alpha', alpha, 'positive', 'profile angle of the basic rack, rad', (2e-7, 1.4))
    h_a   = _checked('h_a', h_a, 'positive', 'addendum coefficient of the basic rack h_a*, 1', (8e-7, 1.25e6))
    dy    = _checked('dy', dy, 'nonnegative', 'tip shortening coefficient Δy (>= 0), 1', (0.0, 300000.0))
    shape = _broadcast(m=m, z=z, x=x, alpha=alpha, h_a=h_a, dy=dy)
    return _into(out, shape, m*(-2*dy + 2*h_a + 2*x + z)*_tip_half_angle(x, z, alpha, h_a, dy, 'x: the tip circle lies inside the base circle (shift too negative)'))


def contact_ratio(m, z1, z2, x1, x2, a_w, alpha, h_a, dy1, dy2, *, out=None):
    """Transverse contact ratio epsilon_alpha. Eq Form 1, epsilon_alpha.

    Parameters
    ----------
    m : array_like
        module of the teeth [m], > 0; served from 1e-9 to 50000.0
    z1 : array_like
        number of teeth of the pinion [1], > 0; served from 8e-6 to 1.5e8
    z2 : array_like
        number of teeth of the wheel [1], > 0; served from 8e-6 to 1.5e8
    x1 : array_like
        shift coefficient of the pinion [1]; served from -1e6 to 1e6
    x2 : array_like
        shift coefficient of the wheel [1]; served from -1e6 to 1e6
    a_w : array_like
        centre distance [m], > 0; served from 5e-8 to 5e6
    alpha : array_like
        profile angle of the basic rack [rad], > 0; served from 2e-7 to 1.4
    h_a : array_like
        addendum coefficient of the basic rack h_a* [1], > 0; served from 8e-7 to 1.25e6
    dy1 : array_like
        tip shortening coefficient Δy of the pinion (>= 0) [1], >= 0; served from 0.0 to 300000.0
    dy2 : array_like
        tip shortening coefficient Δy of the wheel (>= 0) [1], >= 0; served from 0.0 to 300000.0
    out : ndarray, optional
        float64 array of the broadcast shape; the result is written into it and returned.

    Returns
    -------
    ndarray
        [1], broadcast over the arguments.
    """
    m     = _checked('m', m, 'positive', 'module of the teeth, m', (1e-9, 50000.0))
    z1    = _checked('z1', z1, 'positive', 'number of teeth of the pinion, 1', (8e-6, 1.5e8))
    z2    = _checked('z2', z2, 'positive', 'number of teeth of the wheel, 1', (8e-6, 1.5e8))
    x1    = _checked('x1', x1, 'real', 'shift coefficient of the pinion, 1', (-1e6, 1e6))
    x2    = _checked('x2', x2, 'real', 'shift coefficient of the wheel, 1', (-1e6, 1e6))
    a_w   = _checked('a_w', a_w, 'positive', 'centre distance, m', (5e-8, 5e6))
    alpha = _checked('alpha', alpha, 'positive', 'profile angle of the basic rack, rad', (2e-7, 1.4))
    h_a   = _checked('h_a', h_a, 'positive', 'addendum coefficient of the basic rack h_a*, 1', (8e-7, 1.25e6))
    dy1   = _checked('dy1', dy1, 'nonnegative', 'tip shortening coefficient Δy of the pinion (>= 0), 1', (0.0, 300000.0))
    dy2   = _checked('dy2', dy2, 'nonnegative', 'tip shortening coefficient Δy of the wheel (>= 0), 1', (0.0, 300000.0))
    shape = _broadcast(m=m, z1=z1, z2=z2, x1=x1, x2=x2, a_w=a_w, alpha=alpha, h_a=h_a, dy1=dy1,
                       dy2=dy2)
    x0 = z1 + z2
    x3 = np.cos(alpha)
    x4 = 2*h_a
    return _into(out, shape, -0.15915494309189535*x0*np.tan(_acos_checked((1/2)*m*x0*x3/a_w, 'a_w: the centre distance is too small for this mesh: it must exceed m*(z1 + z2)*cos(alpha)/2, the sum of the base radii')) + 0.15915494309189535*z1*np.tan(_acos_checked(x3*z1/(-2*dy1 + 2*x1 + x4 + z1), 'x1: the tip circle lies inside the base circle (shift too negative)')) + 0.15915494309189535*z2*np.tan(_acos_checked(x3*z2/(-2*dy2 + 2*x2 + x4 + z2), 'x2: the tip circle lies inside the base circle (shift too negative)')))


def tip_thickness_shift(z, alpha, h_a, dy, sigma, *, out=None):
    """Shift coefficient at which the tip thickness is sigma*m (Fig. 10, curves 2-3). Eq pointed tip.

    Parameters
    ----------
    z : array_like
        number of teeth [1], > 0; served from 8e-6 to 1.5e8
    alpha : array_like
        profile angle of the basic rack [rad], > 0; served from 2e-7 to 1.4
    h_a : array_like
        addendum coefficient of the basic rack h_a* [1], > 0; served from 8e-7 to 1.25e6
    dy : array_like
        tip shortening coefficient Δy (>= 0) [1], >= 0; served from 0.0 to 300000.0
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
    alpha = _checked('alpha', alpha, 'positive', 'profile angle of the basic rack, rad', (2e-7, 1.4))
    h_a   = _checked('h_a', h_a, 'positive', 'addendum coefficient of the basic rack h_a*, 1', (8e-7, 1.25e6))
    dy    = _checked('dy', dy, 'nonnegative', 'tip shortening coefficient Δy (>= 0), 1', (0.0, 300000.0))
    sigma = _checked('sigma', sigma, 'nonnegative', 'tip tooth thickness over the module, s_a/m, 1', (0.0, 500000.0))
    shape = _broadcast(z=z, alpha=alpha, h_a=h_a, dy=dy, sigma=sigma)
    return _into(out, shape, _tip_shift(z, alpha, h_a, dy, sigma))


def pointed_tip_shift(z, alpha, h_a, dy, *, out=None):
    """Shift coefficient at which the tooth tip is pointed (Fig. 10, curve 1). Eq pointed tip.

    Parameters
    ----------
    z : array_like
        number of teeth [1], > 0; served from 8e-6 to 1.5e8
    alpha : array_like
        profile angle of the basic rack [rad], > 0; served from 2e-7 to 1.4
    h_a : array_like
        addendum coefficient of the basic rack h_a* [1], > 0; served from 8e-7 to 1.25e6
    dy : array_like
        tip shortening coefficient Δy (>= 0) [1], >= 0; served from 0.0 to 300000.0
    out : ndarray, optional
        float64 array of the broadcast shape; the result is written into it and returned.

    Returns
    -------
    ndarray
        [1], broadcast over the arguments.
    """
    z     = _checked('z', z, 'positive', 'number of teeth, 1', (8e-6, 1.5e8))
    alpha = _checked('alpha', alpha, 'positive', 'profile angle of the basic rack, rad', (2e-7, 1.4))
    h_a   = _checked('h_a', h_a, 'positive', 'addendum coefficient of the basic rack h_a*, 1', (8e-7, 1.25e6))
    dy    = _checked('dy', dy, 'nonnegative', 'tip shortening coefficient Δy (>= 0), 1', (0.0, 300000.0))
    shape = _broadcast(z=z, alpha=alpha, h_a=h_a, dy=dy)
    return _into(out, shape, _tip_shift(z, alpha, h_a, dy, 0))


def undercut_limit(z, alpha, h_a, *, out=None):
    """Least shift coefficient free of undercut (Fig. 10, curve 4). Eq undercut limit.

    Parameters
    ----------
    z : array_like
        number of teeth [1], > 0; served from 8e-6 to 1.5e8
    alpha : array_like
        profile angle of the basic rack [rad], > 0; served from 2e-7 to 1.4
    h_a : array_like
        addendum coefficient of the basic rack h_a* [1], > 0; served from 8e-7 to 1.25e6
    out : ndarray, optional
        float64 array of the broadcast shape; the result is written into it and returned.

    Returns
    -------
    ndarray
        [1], broadcast over the arguments.
    """
    if (out is None
            and (type(z) in (float, int) or type(z) is np.float64)
            and (type(alpha) in (float, int) or type(alpha) is np.float64)
            and (type(h_a) in (float, int) or type(h_a) is np.float64)):
        if (8e-6 <= z <= 1.5e8 and 2e-7 <= alpha <= 1.4 and 8e-7 <= h_a <= 1.25e6):
            try:    # a failed check or a math error: the array path decides
                return np.float64(h_a - 1/2*z*math.sin(alpha)**2)
            except (ArithmeticError, ValueError):
                pass
    z     = _checked('z', z, 'positive', 'number of teeth, 1', (8e-6, 1.5e8))
    alpha = _checked('alpha', alpha, 'positive', 'profile angle of the basic rack, rad', (2e-7, 1.4))
    h_a   = _checked('h_a', h_a, 'positive', 'addendum coefficient of the basic rack h_a*, 1', (8e-7, 1.25e6))
    shape = _broadcast(z=z, alpha=alpha, h_a=h_a)
    return _into(out, shape, h_a - 1/2*z*np.sin(alpha)**2)


def startup_gap_motor_speed(t_s, lambda_p, P_m, J_r, v_n, omega_0, omega_n, *, out=None):
    """Motor speed at the rim in the first stage while the gap is open (from rest, first characteristic). Eq start-up, motor speed in the gap.

    Parameters
    ----------
    t_s : array_like
        time from the start (first stage) [s], >= 0; served from 0.0 to 500000.0
    lambda_p : array_like
        starting-force multiple λ: force of the first characteristic at standstill over the rated force [1], > 0; served from 1.2e-6 to 2.5e6
    P_m : array_like
        rated power of one motor [W], > 0; served from 0.005 to 5e10
    J_r : array_like
        moment of inertia of one motor rotor [kg*m^2], > 0; served from 5e-8 to 1e6
    v_n : array_like
        rated travel speed of the crane [m/s], > 0; served from 2e-7 to 1e6
    omega_0 : array_like
        no-load (synchronous) motor speed [rad/s], > 0; served from 6e-5 to 1.7e8
    omega_n : array_like
        rated motor speed [rad/s], > 0; served from 5e-5 to 1.6e8
    out : ndarray, optional
        float64 array of the broadcast shape; the result is written into it and returned.

    Returns
    -------
    ndarray
        [m/s], broadcast over the arguments.
    """
    if (out is None
            and (type(t_s) in (float, int) or type(t_s) is np.float64)
            and (type(lambda_p) in (float, int) or type(lambda_p) is np.float64)
            and (type(P_m) in (float, int) or type(P_m) is np.float64)
            and (type(J_r) in (float, int) or type(J_r) is np.float64)
            and (type(v_n) in (float, int) or type(v_n) is np.float64)
            and (type(omega_0) in (float, int) or type(omega_0) is np.float64)
            and (type(omega_n) in (float, int) or type(omega_n) is np.float64)):
        if (0.0 <= t_s <= 500000.0 and 1.2e-6 <= lambda_p <= 2.5e6 and 0.005 <= P_m <= 5e10
                and 5e-8 <= J_r <= 1e6 and 2e-7 <= v_n <= 1e6 and 6e-5 <= omega_0 <= 1.7e8
                and 5e-5 <= omega_n <= 1.6e8):
            try:    # a failed check or a math error: the array path decides
                x0 = 1/omega_n
                return np.float64(-omega_0*v_n*x0*math.expm1(-P_m*lambda_p*t_s*x0/(J_r*omega_0)))
            except (ArithmeticError, ValueError):
                pass
    t_s      = _checked('t_s', t_s, 'nonnegative', 'time from the start (first stage), s', (0.0, 500000.0))
    lambda_p = _checked('lambda_p', lambda_p, 'positive', 'starting-force multiple λ: force of the first characteristic at standstill over the rated force, 1', (1.2e-6, 2.5e6))
    P_m      = _checked('P_m', P_m, 'positive', 'rated power of one motor, W', (0.005, 5e10))
    J_r      = _checked('J_r', J_r, 'positive', 'moment of inertia of one motor rotor, kg*m^2', (5e-8, 1e6))
    v_n      = _checked('v_n', v_n, 'positive', 'rated travel speed of the crane, m/s', (2e-7, 1e6))
    omega_0  = _checked('omega_0', omega_0, 'positive', 'no-load (synchronous) motor speed, rad/s', (6e-5, 1.7e8))
    omega_n  = _checked('omega_n', omega_n, 'positive', 'rated motor speed, rad/s', (5e-5, 1.6e8))
    shape = _broadcast(t_s=t_s, lambda_p=lambda_p, P_m=P_m, J_r=J_r, v_n=v_n, omega_0=omega_0,
                       omega_n=omega_n)
    x0 = 1/(omega_n)
    return _into(out, shape, -omega_0*v_n*x0*np.expm1(-P_m*lambda_p*t_s*x0/(J_r*omega_0)))


def startup_motor_mass(J_r, n_m, omega_n, v_n, *, out=None):
    """Motor rotors of one side reduced to the wheel rim. Eq start-up, motor mass at the rim.

    Parameters
    ----------
    J_r : array_like
        moment of inertia of one motor rotor [kg*m^2], > 0; served from 5e-8 to 1e6
    n_m : array_like
        number of motors on one side of the portal [1], > 0; served from 1e-6 to 4e6
    omega_n : array_like
        rated motor speed [rad/s], > 0; served from 5e-5 to 1.6e8
    v_n : array_like
        rated travel speed of the crane [m/s], > 0; served from 2e-7 to 1e6
    out : ndarray, optional
        float64 array of the broadcast shape; the result is written into it and returned.

    Returns
    -------
    ndarray
        [kg], broadcast over the arguments.
    """
    if (out is None
            and (type(J_r) in (float, int) or type(J_r) is np.float64)
            and (type(n_m) in (float, int) or type(n_m) is np.float64)
            and (type(omega_n) in (float, int) or type(omega_n) is np.float64)
            and (type(v_n) in (float, int) or type(v_n) is np.float64)):
        if (5e-8 <= J_r <= 1e6 and 1e-6 <= n_m <= 4e6 and 5e-5 <= omega_n <= 1.6e8
                and 2e-7 <= v_n <= 1e6):
            try:    # a failed check or a math error: the array path decides
                return np.float64(J_r*n_m*omega_n**2/v_n**2)
            except (ArithmeticError, ValueError):
                pass
    J_r     = _checked('J_r', J_r, 'positive', 'moment of inertia of one motor rotor, kg*m^2', (5e-8, 1e6))
    n_m     = _checked('n_m', n_m, 'positive', 'number of motors on one side of the portal, 1', (1e-6, 4e6))
    omega_n = _checked('omega_n', omega_n, 'positive', 'rated motor speed, rad/s', (5e-5, 1.6e8))
    v_n     = _checked('v_n', v_n, 'positive', 'rated travel speed of the crane, m/s', (2e-7, 1e6))
    shape = _broadcast(J_r=J_r, n_m=n_m, omega_n=omega_n, v_n=v_n)
    return _into(out, shape, J_r*n_m*omega_n**2/v_n**2)


def startup_rated_force(P_m, n_m, v_n, *, out=None):
    """Rated force of one side at the rim. Eq start-up, rated force.

    Parameters
    ----------
    P_m : array_like
        rated power of one motor [W], > 0; served from 0.005 to 5e10
    n_m : array_like
        number of motors on one side of the portal [1], > 0; served from 1e-6 to 4e6
    v_n : array_like
        rated travel speed of the crane [m/s], > 0; served from 2e-7 to 1e6
    out : ndarray, optional
        float64 array of the broadcast shape; the result is written into it and returned.

    Returns
    -------
    ndarray
        [N], broadcast over the arguments.
    """
    if (out is None
            and (type(P_m) in (float, int) or type(P_m) is np.float64)
            and (type(n_m) in (float, int) or type(n_m) is np.float64)
            and (type(v_n) in (float, int) or type(v_n) is np.float64)):
        if (0.005 <= P_m <= 5e10 and 1e-6 <= n_m <= 4e6 and 2e-7 <= v_n <= 1e6):
            try:    # a failed check or a math error: the array path decides
                return np.float64(P_m*n_m/v_n)
            except (ArithmeticError, ValueError):
                pass
    P_m = _checked('P_m', P_m, 'positive', 'rated power of one motor, W', (0.005, 5e10))
    n_m = _checked('n_m', n_m, 'positive', 'number of motors on one side of the portal, 1', (1e-6, 4e6))
    v_n = _checked('v_n', v_n, 'positive', 'rated travel speed of the crane, m/s', (2e-7, 1e6))
    shape = _broadcast(P_m=P_m, n_m=n_m, v_n=v_n)
    return _into(out, shape, P_m*n_m/v_n)


def startup_no_load_speed(v_n, omega_0, omega_n, *, out=None):
    """No-load speed at the rim. Eq start-up, no-load speed.

    Parameters
    ----------
    v_n : array_like
        rated travel speed of the crane [m/s], > 0; served from 2e-7 to 1e6
    omega_0 : array_like
        no-load (synchronous) motor speed [rad/s], > 0; served from 6e-5 to 1.7e8
    omega_n : array_like
        rated motor speed [rad/s], > 0; served from 5e-5 to 1.6e8
    out : ndarray, optional
        float64 array of the broadcast shape; the result is written into it and returned.

    Returns
    -------
    ndarray
        [m/s], broadcast over the arguments.
    """
    if (out is None
            and (type(v_n) in (float, int) or type(v_n) is np.float64)
            and (type(omega_0) in (float, int) or type(omega_0) is np.float64)
            and (type(omega_n) in (float, int) or type(omega_n) is np.float64)):
        if (2e-7 <= v_n <= 1e6 and 6e-5 <= omega_0 <= 1.7e8 and 5e-5 <= omega_n <= 1.6e8):
            try:    # a failed check or a math error: the array path decides
                return np.float64(omega_0*v_n/omega_n)
            except (ArithmeticError, ValueError):
                pass
    v_n     = _checked('v_n', v_n, 'positive', 'rated travel speed of the crane, m/s', (2e-7, 1e6))
    omega_0 = _checked('omega_0', omega_0, 'positive', 'no-load (synchronous) motor speed, rad/s', (6e-5, 1.7e8))
    omega_n = _checked('omega_n', omega_n, 'positive', 'rated motor speed, rad/s', (5e-5, 1.6e8))
    shape = _broadcast(v_n=v_n, omega_0=omega_0, omega_n=omega_n)
    return _into(out, shape, omega_0*v_n/omega_n)


def startup_backlash_at_rim(phi_b, v_n, omega_n, *, out=None):
    """Backlash phi_b of the fast shaft as a gap at the rim. Eq start-up, backlash at the rim.

    Parameters
    ----------
    phi_b : array_like
        backlash of one drive, on its fast shaft [rad], >= 0; served from 0.0 to 6.3e6
    v_n : array_like
        rated travel speed of the crane [m/s], > 0; served from 2e-7 to 1e6
    omega_n : array_like
        rated motor speed [rad/s], > 0; served from 5e-5 to 1.6e8
    out : ndarray, optional
        float64 array of the broadcast shape; the result is written into it and returned.

    Returns
    -------
    ndarray
        [m], broadcast over the arguments.
    """
    if (out is None
            and (type(phi_b) in (float, int) or type(phi_b) is np.float64)
            and (type(v_n) in (float, int) or type(v_n) is np.float64)
            and (type(omega_n) in (float, int) or type(omega_n) is np.float64)):
        if (0.0 <= phi_b <= 6.3e6 and 2e-7 <= v_n <= 1e6 and 5e-5 <= omega_n <= 1.6e8):
            try:    # a failed check or a math error: the array path decides
                return np.float64(phi_b*v_n/omega_n)
            except (ArithmeticError, ValueError):
                pass
    phi_b   = _checked('phi_b', phi_b, 'nonnegative', 'backlash of one drive, on its fast shaft, rad', (0.0, 6.3e6))
    v_n     = _checked('v_n', v_n, 'positive', 'rated travel speed of the crane, m/s', (2e-7, 1e6))
    omega_n = _checked('omega_n', omega_n, 'positive', 'rated motor speed, rad/s', (5e-5, 1.6e8))
    shape = _broadcast(phi_b=phi_b, v_n=v_n, omega_n=omega_n)
    return _into(out, shape, phi_b*v_n/omega_n)


def startup_first_slope(lambda_p, P_m, n_m, v_n, omega_0, omega_n, *, out=None):
    """Slope beta_1 of the first start characteristic of one side. Eq start-up, first characteristic.

    Parameters
    ----------
    lambda_p : array_like
        starting-force multiple λ: force of the first characteristic at standstill over the rated force [1], > 0; served from 1.2e-6 to 2.5e6
    P_m : array_like
        rated power of one motor [W], > 0; served from 0.005 to 5e10
    n_m : array_like
        number of motors on one side of the portal [1], > 0; served from 1e-6 to 4e6
    v_n : array_like
        rated travel speed of the crane [m/s], > 0; served from 2e-7 to 1e6
    omega_0 : array_like
        no-load (synchronous) motor speed [rad/s], > 0; served from 6e-5 to 1.7e8
    omega_n : array_like
        rated motor speed [rad/s], > 0; served from 5e-5 to 1.6e8
    out : ndarray, optional
        float64 array of the broadcast shape; the result is written into it and returned.

    Returns
    -------
    ndarray
        [N*s/m], broadcast over the arguments.
    """
    if (out is None
            and (type(lambda_p) in (float, int) or type(lambda_p) is np.float64)
            and (type(P_m) in (float, int) or type(P_m) is np.float64)
            and (type(n_m) in (float, int) or type(n_m) is np.float64)
            and (type(v_n) in (float, int) or type(v_n) is np.float64)
            and (type(omega_0) in (float, int) or type(omega_0) is np.float64)
            and (type(omega_n) in (float, int) or type(omega_n) is np.float64)):
        if (1.2e-6 <= lambda_p <= 2.5e6 and 0.005 <= P_m <= 5e10 and 1e-6 <= n_m <= 4e6
                and 2e-7 <= v_n <= 1e6 and 6e-5 <= omega_0 <= 1.7e8 and 5e-5 <= omega_n <= 1.6e8):
            try:    # a failed check or a math error: the array path decides
                return np.float64(P_m*lambda_p*n_m*omega_n/(omega_0*v_n**2))
            except (ArithmeticError, ValueError):
                pass
    lambda_p = _checked('lambda_p', lambda_p, 'positive', 'starting-force multiple λ: force of the first characteristic at standstill over the rated force, 1', (1.2e-6, 2.5e6))
    P_m      = _checked('P_m', P_m, 'positive', 'rated power of one motor, W', (0.005, 5e10))
    n_m      = _checked('n_m', n_m, 'positive', 'number of motors on one side of the portal, 1', (1e-6, 4e6))
    v_n      = _checked('v_n', v_n, 'positive', 'rated travel speed of the crane, m/s', (2e-7, 1e6))
    omega_0  = _checked('omega_0', omega_0, 'positive', 'no-load (synchronous) motor speed, rad/s', (6e-5, 1.7e8))
    omega_n  = _checked('omega_n', omega_n, 'positive', 'rated motor speed, rad/s', (5e-5, 1.6e8))
    shape = _broadcast(lambda_p=lambda_p, P_m=P_m, n_m=n_m, v_n=v_n, omega_0=omega_0, omega_n=omega_n)
    return _into(out, shape, P_m*lambda_p*n_m*omega_n/(omega_0*v_n**2))


def startup_slope_ratio(lambda_p, omega_0, omega_n, *, out=None):
    """Ratio q of the slopes of consecutive characteristics (three steps to the natural one). Eq start-up, slope ratio.

    Parameters
    ----------
    lambda_p : array_like
        starting-force multiple λ: force of the first characteristic at standstill over the rated force [1], > 0; served from 1.2e-6 to 2.5e6
    omega_0 : array_like
        no-load (synchronous) motor speed [rad/s], > 0; served from 6e-5 to 1.7e8
    omega_n : array_like
        rated motor speed [rad/s], > 0; served from 5e-5 to 1.6e8
    out : ndarray, optional
        float64 array of the broadcast shape; the result is written into it and returned.

    Returns
    -------
    ndarray
        [1], broadcast over the arguments.

    Raises
    ------
    ValueError
        unless omega_0 > omega_n (the no-load speed above the rated one).
    """
    if (out is None
            and (type(lambda_p) in (float, int) or type(lambda_p) is np.float64)
            and (type(omega_0) in (float, int) or type(omega_0) is np.float64)
            and (type(omega_n) in (float, int) or type(omega_n) is np.float64)):
        if (1.2e-6 <= lambda_p <= 2.5e6 and 6e-5 <= omega_0 <= 1.7e8 and 5e-5 <= omega_n <= 1.6e8
                and omega_0 - omega_n > 0):
            try:    # a failed check or a math error: the array path decides
                return np.float64(omega_0**(1/3)*(1/(omega_0 - omega_n))**(1/3)/lambda_p**(1/3))
            except (ArithmeticError, ValueError):
                pass
    lambda_p = _checked('lambda_p', lambda_p, 'positive', 'starting-force multiple λ: force of the first characteristic at standstill over the rated force, 1', (1.2e-6, 2.5e6))
    omega_0  = _checked('omega_0', omega_0, 'positive', 'no-load (synchronous) motor speed, rad/s', (6e-5, 1.7e8))
    omega_n  = _checked('omega_n', omega_n, 'positive', 'rated motor speed, rad/s', (5e-5, 1.6e8))
    shape = _broadcast(lambda_p=lambda_p, omega_0=omega_0, omega_n=omega_n)
    _required(omega_0 - omega_n, 'omega_0 > omega_n (the no-load speed above the rated one)')
    return _into(out, shape, omega_0**(1/3)*(1/(omega_0 - omega_n))**(1/3)/lambda_p**(1/3))


def startup_link_damping(zeta, c_l, J_r, n_m, omega_n, v_n, *, out=None):
    """Damping coefficient b of a link. Eq start-up, link damping.

    Parameters
    ----------
    zeta : array_like
        damping ratio of a link against its motors [1], > 0; served from 1e-8 to 200000.0
    c_l : array_like
        stiffness of one elastic link (portal side and drive, at the rim) [N/m], > 0; served from 1.0 to 2e13
    J_r : array_like
        moment of inertia of one motor rotor [kg*m^2], > 0; served from 5e-8 to 1e6
    n_m : array_like
        number of motors on one side of the portal [1], > 0; served from 1e-6 to 4e6
    omega_n : array_like
        rated motor speed [rad/s], > 0; served from 5e-5 to 1.6e8
    v_n : array_like
        rated travel speed of the crane [m/s], > 0; served from 2e-7 to 1e6
    out : ndarray, optional
        float64 array of the broadcast shape; the result is written into it and returned.

    Returns
    -------
    ndarray
        [N*s/m], broadcast over the arguments.
    """
    if (out is None
            and (type(zeta) in (float, int) or type(zeta) is np.float64)
            and (type(c_l) in (float, int) or type(c_l) is np.float64)
            and (type(J_r) in (float, int) or type(J_r) is np.float64)
            and (type(n_m) in (float, int) or type(n_m) is np.float64)
            and (type(omega_n) in (float, int) or type(omega_n) is np.float64)
            and (type(v_n) in (float, int) or type(v_n) is np.float64)):
        if (1e-8 <= zeta <= 200000.0 and 1.0 <= c_l <= 2e13 and 5e-8 <= J_r <= 1e6
                and 1e-6 <= n_m <= 4e6 and 5e-5 <= omega_n <= 1.6e8 and 2e-7 <= v_n <= 1e6):
            try:    # a failed check or a math error: the array path decides
                return np.float64(2*math.sqrt(J_r)*math.sqrt(c_l)*math.sqrt(n_m)*omega_n*zeta/v_n)
            except (ArithmeticError, ValueError):
                pass
    zeta    = _checked('zeta', zeta, 'positive', 'damping ratio of a link against its motors, 1', (1e-8, 200000.0))
    c_l     = _checked('c_l', c_l, 'positive', 'stiffness of one elastic link (portal side and drive, at the rim), N/m', (1.0, 2e13))
    J_r     = _checked('J_r', J_r, 'positive', 'moment of inertia of one motor rotor, kg*m^2', (5e-8, 1e6))
    n_m     = _checked('n_m', n_m, 'positive', 'number of motors on one side of the portal, 1', (1e-6, 4e6))
    omega_n = _checked('omega_n', omega_n, 'positive', 'rated motor speed, rad/s', (5e-5, 1.6e8))
    v_n     = _checked('v_n', v_n, 'positive', 'rated travel speed of the crane, m/s', (2e-7, 1e6))
    shape = _broadcast(zeta=zeta, c_l=c_l, J_r=J_r, n_m=n_m, omega_n=omega_n, v_n=v_n)
    return _into(out, shape, 2*np.sqrt(J_r)*np.sqrt(c_l)*np.sqrt(n_m)*omega_n*zeta/v_n)


def startup_rigid_breakaway(lambda_p, P_m, n_m, v_n, m_k, J_r, omega_n, W_f, W_w, *, out=None):
    """Acceleration of the rigid drive at break-away on the first characteristic. Eq start-up, rigid break-away.

    Parameters
    ----------
    lambda_p : array_like
        starting-force multiple λ: force of the first characteristic at standstill over the rated force [1], > 0; served from 1.2e-6 to 2.5e6
    P_m : array_like
        rated power of one motor [W], > 0; served from 0.005 to 5e10
    n_m : array_like
        number of motors on one side of the portal [1], > 0; served from 1e-6 to 4e6
    v_n : array_like
        rated travel speed of the crane [m/s], > 0; served from 2e-7 to 1e6
    m_k : array_like
        mass of the crane [kg], > 0; served from 0.1 to 5e11
    J_r : array_like
        moment of inertia of one motor rotor [kg*m^2], > 0; served from 5e-8 to 1e6
    omega_n : array_like
        rated motor speed [rad/s], > 0; served from 5e-5 to 1.6e8
    W_f : array_like
        friction resistance to travel [N], > 0; served from 0.01 to 6e10
    W_w : array_like
        wind resistance to travel [N], >= 0; served from 0.0 to 6e10
    out : ndarray, optional
        float64 array of the broadcast shape; the result is written into it and returned.

    Returns
    -------
    ndarray
        [m/s^2], broadcast over the arguments.
    """
    if (out is None
            and (type(lambda_p) in (float, int) or type(lambda_p) is np.float64)
            and (type(P_m) in (float, int) or type(P_m) is np.float64)
            and (type(n_m) in (float, int) or type(n_m) is np.float64)
            and (type(v_n) in (float, int) or type(v_n) is np.float64)
            and (type(m_k) in (float, int) or type(m_k) is np.float64)
            and (type(J_r) in (float, int) or type(J_r) is np.float64)
            and (type(omega_n) in (float, int) or type(omega_n) is np.float64)
            and (type(W_f) in (float, int) or type(W_f) is np.float64)
            and (type(W_w) in (float, int) or type(W_w) is np.float64)):
        if (1.2e-6 <= lambda_p <= 2.5e6 and 0.005 <= P_m <= 5e10 and 1e-6 <= n_m <= 4e6
                and 2e-7 <= v_n <= 1e6 and 0.1 <= m_k <= 5e11 and 5e-8 <= J_r <= 1e6
                and 5e-5 <= omega_n <= 1.6e8 and 0.01 <= W_f <= 6e10 and 0.0 <= W_w <= 6e10):
            try:    # a failed check or a math error: the array path decides
                return np.float64((2*P_m*lambda_p*n_m/v_n - W_f - W_w)/(2*J_r*n_m*omega_n**2/v_n**2 + m_k))
            except (ArithmeticError, ValueError):
                pass
    lambda_p = _checked('lambda_p', lambda_p, 'positive', 'starting-force multiple λ: force of the first characteristic at standstill over the rated force, 1', (1.2e-6, 2.5e6))
    P_m      = _checked('P_m', P_m, 'positive', 'rated power of one motor, W', (0.005, 5e10))
    n_m      = _checked('n_m', n_m, 'positive', 'number of motors on one side of the portal, 1', (1e-6, 4e6))
    v_n      = _checked('v_n', v_n, 'positive', 'rated travel speed of the crane, m/s', (2e-7, 1e6))
    m_k      = _checked('m_k', m_k, 'positive', 'mass of the crane, kg', (0.1, 5e11))
    J_r      = _checked('J_r', J_r, 'positive', 'moment of inertia of one motor rotor, kg*m^2', (5e-8, 1e6))
    omega_n  = _checked('omega_n', omega_n, 'positive', 'rated motor speed, rad/s', (5e-5, 1.6e8))
    W_f      = _checked('W_f', W_f, 'positive', 'friction resistance to travel, N', (0.01, 6e10))
    W_w      = _checked('W_w', W_w, 'nonnegative', 'wind resistance to travel, N', (0.0, 6e10))
    shape = _broadcast(lambda_p=lambda_p, P_m=P_m, n_m=n_m, v_n=v_n, m_k=m_k, J_r=J_r, omega_n=omega_n,
                       W_f=W_f, W_w=W_w)
    return _into(out, shape, (2*P_m*lambda_p*n_m/v_n - W_f - W_w)/(2*J_r*n_m*omega_n**2/v_n**2 + m_k))


def max_support_load(psi, G_g, G_pch, G_vs, L_max, x_o, c, *, out=None):
    """Largest vertical load on one portal leg, load case 2v (reconstructed portal: see the derivation). Eq (3), (4).

    Parameters
    ----------
    psi : array_like
        dynamic coefficient of the hoisted load (printed у) [1], > 0; served from 1e-6 to 2e6
    G_g : array_like
        rated weight of the load G_г [N], > 0; served from 0.05 to 5e11
    G_pch : array_like
        weight of the slewing part G_пч [N], > 0; served from 0.5 to 3e12
    G_vs : array_like
        weight of the portal's upper structure G_вс [N], > 0; served from 0.1 to 1e12
    L_max : array_like
        maximum reach [m], > 0; served from 1.5e-5 to 4e7
    x_o : array_like
        distance of the slewing part's centre of gravity from the slewing axis [m], > 0; served from 5e-7 to 5e6
    c : array_like
        arm of the couple by which the slewing part bears on the circular rail [m], > 0; served from 3e-6 to 1e7
    out : ndarray, optional
        float64 array of the broadcast shape; the result is written into it and returned.

    Returns
    -------
    ndarray
        [N], broadcast over the arguments.
    """
    if (out is None
            and (type(psi) in (float, int) or type(psi) is np.float64)
            and (type(G_g) in (float, int) or type(G_g) is np.float64)
            and (type(G_pch) in (float, int) or type(G_pch) is np.float64)
            and (type(G_vs) in (float, int) or type(G_vs) is np.float64)
            and (type(L_max) in (float, int) or type(L_max) is np.float64)
            and (type(x_o) in (float, int) or type(x_o) is np.float64)
            and (type(c) in (float, int) or type(c) is np.float64)):
        if (1e-6 <= psi <= 2e6 and 0.05 <= G_g <= 5e11 and 0.5 <= G_pch <= 3e12
                and 0.1 <= G_vs <= 1e12 and 1.5e-5 <= L_max <= 4e7 and 5e-7 <= x_o <= 5e6
                and 3e-6 <= c <= 1e7):
            try:    # a failed check or a math error: the array path decides
                x0 = G_g*psi
                return np.float64((1/4)*G_pch + (1/4)*G_vs + (1/4)*x0 + (1/2)*(-G_pch*x_o + L_max*x0)/c)
            except (ArithmeticError, ValueError):
                pass
    psi   = _checked('psi', psi, 'positive', 'dynamic coefficient of the hoisted load (printed у), 1', (1e-6, 2e6))
    G_g   = _checked('G_g', G_g, 'positive', 'rated weight of the load G_г, N', (0.05, 5e11))
    G_pch = _checked('G_pch', G_pch, 'positive', 'weight of the slewing part G_пч, N', (0.5, 3e12))
    G_vs  = _checked('G_vs', G_vs, 'positive', "weight of the portal's upper structure G_вс, N", (0.1, 1e12))
    L_max = _checked('L_max', L_max, 'positive', 'maximum reach, m', (1.5e-5, 4e7))
    x_o   = _checked('x_o', x_o, 'positive', "distance of the slewing part's centre of gravity from the slewing axis, m", (5e-7, 5e6))
    c     = _checked('c', c, 'positive', 'arm of the couple by which the slewing part bears on the circular rail, m', (3e-6, 1e7))
    shape = _broadcast(psi=psi, G_g=G_g, G_pch=G_pch, G_vs=G_vs, L_max=L_max, x_o=x_o, c=c)
    x0 = G_g*psi
    return _into(out, shape, (1/4)*G_pch + (1/4)*G_vs + (1/4)*x0 + (1/2)*(-G_pch*x_o + L_max*x0)/c)
