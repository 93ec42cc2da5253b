"""Involute spur-gear geometry of the rack-generating process, symbolic and numeric.

Symbolic side (for derivations): the involute function ``involute(a)`` =
tan a − a as an unevaluated SymPy function that rewrites to tan, evaluates in
mpmath and prints as the stable kernel ``_involute``; ``acos_checked`` (an
arccos whose argument must lie in [−1, 1], printed with a message that names
the parameter); ``tip_shift`` (the shift giving a tip thickness σ·m, an
implicit function evaluated by a bracketed mpmath solve); and the relations of
the rack-generating process, built from the geometry of the involute and the
rack (:func:`involute_point`, :func:`rack_space_width`,
:func:`thickness_at_radius`).

Numeric side: :func:`inverse_involute`, :func:`tip_shift_mp` (mpmath, for
references and derivation values) and the NumPy kernels of ``gear_kernels``.
"""
from __future__ import annotations

import mpmath
import numpy as np
import sympy as sp

from crane_sym.kernels import gears as gear_kernels

# --- Symbolic functions -----------------------------------------------------------


def _mpf(v) -> mpmath.mpf:
    try:
        return mpmath.mpf(v)
    except TypeError:  # a NumPy scalar
        return mpmath.mpf(float(v))


def _mp_involute(a):
    """tan a − a in mpmath, with the working precision raised by the bits that
    the cancellation of tan a and a costs (about 2·log2(1/|a|))."""
    a = _mpf(a)
    if a == 0:
        return mpmath.mpf(0)
    extra = max(0, -2 * int(mpmath.floor(mpmath.log(abs(a), 2)))) + 16
    with mpmath.workprec(mpmath.mp.prec + extra):
        value = mpmath.tan(a) - a
    return +value


class involute(sp.Function):  # noqa: N801  (a mathematical function)
    """inv a = tan a − a, the polar angle of the involute at pressure angle a."""

    nargs = 1
    _imp_ = staticmethod(_mp_involute)

    def fdiff(self, argindex: int = 1) -> sp.Expr:
        return sp.tan(self.args[0]) ** 2

    def _latex(self, printer) -> str:
        return rf"\operatorname{{inv}}\left({printer._print(self.args[0])}\right)"

    def _eval_rewrite_as_tan(self, a, **kwargs) -> sp.Expr:
        return sp.tan(a) - a

    def _eval_evalf(self, prec: int) -> sp.Expr | None:
        a = self.args[0].evalf(prec) if self.args[0].is_number else None
        if a is None or not a.is_real:
            return None
        return (sp.tan(a) - a)._eval_evalf(prec)


#: acos_checked code -> the message the generated code raises, naming the parameter.
ACOS_MESSAGES = {
    1: "a_w: the centre distance is too small for this mesh: it must exceed "
       "m*(z1 + z2)*cos(alpha)/2, the sum of the base radii",
    2: "x1: the tip circle lies inside the base circle (shift too negative)",
    3: "x2: the tip circle lies inside the base circle (shift too negative)",
    4: "x: the tip circle lies inside the base circle (shift too negative)",
    5: "x_sum: the shifts are too negative: inv(alpha) + 2*x_sum*tan(alpha)/(z1 + z2) "
       "must be >= 0",
}


def _mp_acos(x, code=0):
    return mpmath.acos(x)


class acos_checked(sp.Function):  # noqa: N801
    """acos(x) whose argument must lie in [−1, 1]; ``code`` picks the message
    of ``ACOS_MESSAGES`` generated code raises otherwise (and it stays
    unevaluated outside [−1, 1], so the error is raised where it is used)."""

    nargs = 2
    _imp_ = staticmethod(_mp_acos)

    def _eval_rewrite_as_acos(self, x, code, **kwargs) -> sp.Expr:
        return sp.acos(x)

    def _latex(self, printer) -> str:
        return rf"\arccos\left({printer._print(self.args[0])}\right)"

    def _eval_evalf(self, prec: int) -> sp.Expr | None:
        x = self.args[0]._eval_evalf(prec) if self.args[0].is_number else None
        if x is None or not x.is_real or abs(x) > 1:
            return None
        return sp.acos(x)._eval_evalf(prec)


def _mp_half_angle(x, z, alpha, ha, dy, code=0):
    d_a = z + 2 * (ha + x - dy)
    return ((mpmath.pi / 2 + 2 * x * mpmath.tan(alpha)) / z + _mp_involute(alpha)
            - _mp_involute(mpmath.acos(z * mpmath.cos(alpha) / d_a)))


class tip_half_angle(sp.Function):  # noqa: N801
    """psi_a(x, z, alpha, ha, dy, code): half the angle a rack-cut tooth subtends
    on its tip circle, (pi/2 + 2x tan alpha)/z + inv alpha - inv alpha_a; the
    kernel forms the difference of involutes without cancellation, and raises
    ``ACOS_MESSAGES[code]`` when the tip circle lies inside the base circle."""

    nargs = 6
    _imp_ = staticmethod(_mp_half_angle)

    def _eval_rewrite_as_tan(self, x, z, alpha, ha, dy, code, **kwargs) -> sp.Expr:
        alpha_a = sp.acos(z * sp.cos(alpha) / (z + 2 * (ha + x - dy)))
        return ((sp.pi / 2 + 2 * x * sp.tan(alpha)) / z + sp.tan(alpha) - alpha
                - sp.tan(alpha_a) + alpha_a)


class inverse_involute_fn(sp.Function):  # noqa: N801
    """The angle a in [0, pi/2) with tan a − a = v (the inverse of ``involute``);
    ``code`` picks the message of ``ACOS_MESSAGES`` raised for v < 0."""

    nargs = 2

    @staticmethod
    def _imp_(v, code=0):
        return inverse_involute_mp(v)

    def fdiff(self, argindex: int = 1) -> sp.Expr:
        return 1 / sp.tan(self) ** 2 if argindex == 1 else sp.S.Zero

    def _latex(self, printer) -> str:
        return rf"\operatorname{{inv}}^{{-1}}\left({printer._print(self.args[0])}\right)"

    def _eval_evalf(self, prec: int) -> sp.Expr:
        with mpmath.workprec(prec + 20):
            value = inverse_involute_mp(mpmath.mpf(sp.Float(self.args[0], prec + 20)))
        return sp.Float(value, mpmath.libmp.prec_to_dps(prec))


def _mp_thickness(x, z, alpha, ha, dy):
    d_a = z + 2 * (ha + x - dy)
    alpha_a = mpmath.acos(z * mpmath.cos(alpha) / d_a)
    return d_a * ((mpmath.pi / 2 + 2 * x * mpmath.tan(alpha)) / z
                  + _mp_involute(alpha) - _mp_involute(alpha_a))


def tip_shift_mp(z, alpha, ha, dy, sigma):
    """The shift x with tip thickness sigma·m, in mpmath at the working precision.

    Independent of the NumPy kernel: bracketed in x itself, from the shift
    that puts the tip on the reference circle (or just above the base circle)
    up to a shift found by doubling, then mpmath's Anderson–Björk solver.

    Parameters
    ----------
    z : number
        Number of teeth.
    alpha : number
        Profile angle [rad].
    ha : number
        Addendum coefficient.
    dy : number
        Tip shortening coefficient.
    sigma : number
        Tip thickness over the module.
    """
    z, alpha, ha, dy, sigma = (_mpf(v) for v in (z, alpha, ha, dy, sigma))

    def f(x):
        return _mp_thickness(x, z, alpha, ha, dy) - sigma

    x_base = z * (mpmath.cos(alpha) - 1) / 2 - ha + dy
    lo = dy - ha
    if f(lo) <= 0:
        lo = x_base + mpmath.mpf(10) ** (-mpmath.mp.dps // 2) * (1 + abs(x_base))
        if f(lo) <= 0:
            raise ValueError("sigma: no shift gives this tip thickness")
    step = mpmath.mpf(1)
    hi = lo + step
    while f(hi) > 0:
        step *= 2
        hi = lo + step
    return mpmath.findroot(f, (lo, hi), solver="anderson")


class tip_shift(sp.Function):  # noqa: N801
    """x(z, alpha, ha, dy, sigma): the shift at which s_a = sigma·m."""

    nargs = 5
    _imp_ = staticmethod(tip_shift_mp)

    def _eval_evalf(self, prec: int) -> sp.Expr:
        with mpmath.workprec(prec + 20):
            value = tip_shift_mp(*(mpmath.mpf(sp.Float(a, prec + 20)) for a in self.args))
        return sp.Float(value, mpmath.libmp.prec_to_dps(prec))


# --- The rack-generating process, symbolically ------------------------------------


def involute_point(r_b: sp.Expr, phi: sp.Expr) -> tuple[sp.Expr, sp.Expr]:
    """A point of the involute of the base circle r_b at roll angle phi: the
    end of a string of length r_b·phi unwound from the circle.

    Parameters
    ----------
    r_b : sympy.Expr
        Base circle radius.
    phi : sympy.Expr
        Roll angle [rad].
    """
    return (r_b * (sp.cos(phi) + phi * sp.sin(phi)),
            r_b * (sp.sin(phi) - phi * sp.cos(phi)))


def rack_space_width(m: sp.Expr, alpha: sp.Expr, height: sp.Expr) -> sp.Expr:
    """Width of the rack's tooth space at ``height`` above its datum line
    (towards its tips): the space is πm/2 wide on the datum and each flank,
    inclined at alpha to the normal of the datum, opens it by height·tan alpha.

    Parameters
    ----------
    m : sympy.Expr
        Module.
    alpha : sympy.Expr
        Profile angle of the rack [rad].
    height : sympy.Expr
        Height above the datum line.
    """
    right = sp.pi * m / 4 + height * sp.tan(alpha)
    left = -sp.pi * m / 4 - height * sp.tan(alpha)
    return right - left


def thickness_at_radius(s: sp.Expr, r: sp.Expr, r_y: sp.Expr, alpha: sp.Expr,
                        alpha_y: sp.Expr) -> sp.Expr:
    """Tooth thickness at radius r_y from the thickness s at radius r: the half
    angle grows by the involute's polar angle from alpha_y down to alpha.

    Parameters
    ----------
    s : sympy.Expr
        Tooth thickness at radius ``r``.
    r : sympy.Expr
        Radius where the thickness is known.
    r_y : sympy.Expr
        Radius where it is wanted.
    alpha, alpha_y : sympy.Expr
        Pressure angles at ``r`` and ``r_y`` [rad].
    """
    return 2 * r_y * (s / (2 * r) + (sp.tan(alpha) - alpha) - (sp.tan(alpha_y) - alpha_y))


# --- Numeric API ------------------------------------------------------------------


def involute_np(a: np.ndarray | float) -> np.ndarray:
    """tan a − a, stable at small a (NumPy).

    Parameters
    ----------
    a : float or ndarray
        Pressure angle [rad].
    """
    return gear_kernels._involute(a)


def inverse_involute(v: np.ndarray | float) -> np.ndarray:
    """The angle a in [0, pi/2) with tan a − a = v (NumPy, bracketed Newton)."""
    return gear_kernels._inverse_involute(v, "v: the involute value must be >= 0")


def inverse_involute_mp(v) -> mpmath.mpf:
    """The angle a in [0, pi/2) with tan a − a = v, in mpmath at the working
    precision: Newton steps kept inside a shrinking bracket (bisection when a
    step would leave it), so it converges from any start."""
    v = _mpf(v)
    if v < 0:
        raise ValueError("v: the involute value must be >= 0")
    if v == 0:
        return mpmath.mpf(0)
    lo, hi = mpmath.mpf(0), mpmath.pi / 2
    a = mpmath.cbrt(3 * v) if v < 1 else hi - 1 / (v + hi)
    eps = mpmath.mpf(2) ** (-mpmath.mp.prec + 4)
    for _ in range(20 * mpmath.mp.prec):
        f = _mp_involute(a) - v
        if f > 0:
            hi = a
        else:
            lo = a
        step = f / mpmath.tan(a) ** 2 if a > 0 else mpmath.inf
        nxt = a - step
        if not lo <= nxt <= hi:
            nxt = (lo + hi) / 2
        if abs(nxt - a) <= eps * abs(nxt) or hi - lo <= eps * hi:
            return nxt
        a = nxt
    return a


def tip_shift_np(z, alpha, ha=1.0, dy=0.0, sigma=0.0) -> np.ndarray:
    """The shift giving tip thickness sigma·m (NumPy kernel).

    Parameters
    ----------
    z : float or ndarray
        Number of teeth.
    alpha : float or ndarray
        Profile angle [rad].
    ha : float or ndarray, optional
        Addendum coefficient.
    dy : float or ndarray, optional
        Tip shortening coefficient.
    sigma : float or ndarray, optional
        Tip thickness over the module.
    """
    return gear_kernels._tip_shift(z, alpha, ha, dy, sigma)


__all__ = ["ACOS_MESSAGES", "acos_checked", "inverse_involute", "inverse_involute_mp",
           "involute", "inverse_involute_fn", "involute_np", "involute_point", "rack_space_width",
           "thickness_at_radius", "tip_half_angle", "tip_shift", "tip_shift_mp", "tip_shift_np"]
