"""NumPy kernels of involute gear geometry that generated modules carry.

Ordinary functions, tested against mpmath in the test suite;
the code generator copies the source of the ones a module calls
(``DEPENDS`` lists what each calls), so generated modules need NumPy alone.
Every kernel is self-contained: no module-level constants.
"""
from __future__ import annotations

import numpy as np


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


#: kernel -> kernels it calls, so a module carries only what it uses.
DEPENDS = {
    "_involute": (),
    "_inverse_involute": ("_involute",),
    "_acos_checked": (),
    "_tip_half_angle": ("_tip_lift_excess",),
    "_tip_lift_excess": (),
    "_tip_shift": ("_tip_lift_excess",),
}
