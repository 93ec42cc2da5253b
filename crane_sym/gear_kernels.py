"""NumPy kernels of involute gear geometry that generated modules carry.

Ordinary functions, tested against mpmath (``tests/test_portal_travel.py``);
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


#: kernel -> kernels it calls, so a module carries only what it uses.
DEPENDS = {
    "_involute": (),
    "_inverse_involute": ("_involute",),
    "_acos_checked": (),
    "_angle_minus_sine": (),
    "_tip_half_angle": ("_angle_minus_sine",),
    "_tip_shift": ("_tip_half_angle", "_angle_minus_sine"),
}
