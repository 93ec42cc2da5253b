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

import numpy as np

__all__ = ['natural_frequency', 'pickup_contact_time', 'dynamic_coefficient_instant', 'dynamic_coefficient_ramp', 'dynamic_coefficient_pulse', 'pulse_peak_factor', 'pulse_peak_time', 'dynamic_coefficient_ramp_hold', 'ramp_hold_peak_factor', 'dynamic_coefficient_pickup_a1', 'dynamic_coefficient_pickup_a2', 'dynamic_coefficient_pickup_a3', 'dynamic_coefficient_pickup_a4', 'dynamic_coefficient_from_weight_a1', 'dynamic_coefficient_from_weight_a2', 'dynamic_coefficient_from_weight_a3', 'dynamic_coefficient_from_weight_a4', 'optimal_coefficient_from_weight_a1', 'optimal_coefficient_pickup_a1', 'optimal_coefficient_from_weight_a2', 'optimal_coefficient_pickup_a2', 'optimal_coefficient_from_weight_a3', 'optimal_coefficient_pickup_a3', 'optimal_coefficient_from_weight_a4', 'optimal_coefficient_pickup_a4']


def _checked(name, value, sign, what):
    """``value`` as a float array; ValueError naming ``name`` if it is not a
    finite number of the required sign, TypeError if it is not a number."""
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
    term x**(2n-2+odd): by the series where the direct difference cancels."""
    x = np.asarray(x, dtype=float)
    small = np.abs(x) < 2.0 * n + 2.0
    if small.all():  # no mask, no direct difference
        return _taylor_tail(x, n, odd)
    direct = np.cos(x) if odd == 0 else np.sin(x)
    term = np.ones_like(x) if odd == 0 else x.copy()
    for k in range(n):  # subtract the Taylor terms k = 0 .. n-1
        direct = direct - term
        m = 2 * k + odd
        term = term * (-x * x) / ((m + 1) * (m + 2))
    if np.any(small):
        direct = np.array(direct, dtype=float)
        direct[small] = _taylor_tail(x[small], n, odd)
    return direct


def _cos_remainder(x, n):
    """cos(x) - sum_{k<n} (-1)**k x**(2k)/(2k)!, accurate at small |x|."""
    return _taylor_remainder(x, n, 0)


def _sin_remainder(x, n):
    """sin(x) - sum_{k<n} (-1)**k x**(2k+1)/(2k+1)!, accurate at small |x|."""
    return _taylor_remainder(x, n, 1)


def natural_frequency(m1, m2, C):
    """Natural circular frequency Omega of the rope stretch. Eq (2).

    Parameters
    ----------
    m1 : array_like
        reduced mass of the drive (first mass) [kg], > 0
    m2 : array_like
        mass of the load (second mass) [kg], > 0
    C : array_like
        stiffness of the rope (elastic link) [N/m], > 0

    Returns
    -------
    ndarray
        [rad/s], broadcast over the arguments.
    """
    m1 = _checked('m1', m1, 'positive', 'reduced mass of the drive (first mass), kg')
    m2 = _checked('m2', m2, 'positive', 'mass of the load (second mass), kg')
    C  = _checked('C', C, 'positive', 'stiffness of the rope (elastic link), N/m')
    return np.sqrt(C)*np.sqrt(m1 + m2)/(np.sqrt(m1)*np.sqrt(m2))


def pickup_contact_time(m2, g, C, v0):
    """Duration tau_0 of the load's contact with the ground (pick-up). Eq (29).

    Parameters
    ----------
    m2 : array_like
        mass of the load (second mass) [kg], > 0
    g : array_like
        acceleration of gravity [m/s^2], > 0
    C : array_like
        stiffness of the rope (elastic link) [N/m], > 0
    v0 : array_like
        steady hoisting speed after the start [m/s], > 0

    Returns
    -------
    ndarray
        [s], broadcast over the arguments.
    """
    m2 = _checked('m2', m2, 'positive', 'mass of the load (second mass), kg')
    g  = _checked('g', g, 'positive', 'acceleration of gravity, m/s^2')
    C  = _checked('C', C, 'positive', 'stiffness of the rope (elastic link), N/m')
    v0 = _checked('v0', v0, 'positive', 'steady hoisting speed after the start, m/s')
    return g*m2/(C*v0)


def dynamic_coefficient_instant(t, Omega):
    """K_din(t) under a suddenly applied constant load. Eq (38).

    Parameters
    ----------
    t : array_like
        time from the start of the drive [s], >= 0
    Omega : array_like
        natural circular frequency Ω of the rope stretch [rad/s], > 0

    Returns
    -------
    ndarray
        [1], broadcast over the arguments.
    """
    t     = _checked('t', t, 'nonnegative', 'time from the start of the drive, s')
    Omega = _checked('Omega', Omega, 'positive', 'natural circular frequency Ω of the rope stretch, rad/s')
    q0 = _dd_div(_dd(Omega), (2.0, 0.0))
    return 2*_sin_phase(t, q0)**2


def dynamic_coefficient_ramp(t, Omega, t_n):
    """K_din(t) under a linearly growing load, over the static deflection at t_n. Eq (42).

    Parameters
    ----------
    t : array_like
        time from the start of the drive [s], >= 0
    Omega : array_like
        natural circular frequency Ω of the rope stretch [rad/s], > 0
    t_n : array_like
        duration of the start (transient) t_п [s], > 0

    Returns
    -------
    ndarray
        [1], broadcast over the arguments.
    """
    t     = _checked('t', t, 'nonnegative', 'time from the start of the drive, s')
    Omega = _checked('Omega', Omega, 'positive', 'natural circular frequency Ω of the rope stretch, rad/s')
    t_n   = _checked('t_n', t_n, 'positive', 'duration of the start (transient) t_п, s')
    k0 = -1/(Omega*t_n)
    return k0*_sin_remainder(Omega*t, 1)


def dynamic_coefficient_pulse(t, Omega, theta):
    """K_din(t) under a rectangular pulse of length theta. Eq (45), (46).

    Parameters
    ----------
    t : array_like
        time from the start of the drive [s], >= 0
    Omega : array_like
        natural circular frequency Ω of the rope stretch [rad/s], > 0
    theta : array_like
        duration θ of the pulse or of the load rise (43)–(53) [s], > 0

    Returns
    -------
    ndarray
        [1], broadcast over the arguments.
    """
    t     = _checked('t', t, 'nonnegative', 'time from the start of the drive, s')
    Omega = _checked('Omega', Omega, 'positive', 'natural circular frequency Ω of the rope stretch, rad/s')
    theta = _checked('theta', theta, 'positive', 'duration θ of the pulse or of the load rise (43)–(53), s')
    q0 = _dd_div(_dd(Omega), (2.0, 0.0))
    x0 = -theta
    x1 = (1/2)*Omega
    k4 = 2*np.sin(theta*x1)
    return k4*np.sin(x1*(2*t + x0))*(np.select([np.less_equal(t + x0, 0),True], [0,1], default=np.nan)) + 2*(1 - (np.select([np.less_equal(t + x0, 0),True], [0,1], default=np.nan)))*_sin_phase(t, q0)**2


def pulse_peak_factor(Omega, theta):
    """Largest x/x_st under a rectangular pulse of length theta. Eq (47).

    Parameters
    ----------
    Omega : array_like
        natural circular frequency Ω of the rope stretch [rad/s], > 0
    theta : array_like
        duration θ of the pulse or of the load rise (43)–(53) [s], > 0

    Returns
    -------
    ndarray
        [1], broadcast over the arguments.
    """
    Omega = _checked('Omega', Omega, 'positive', 'natural circular frequency Ω of the rope stretch, rad/s')
    theta = _checked('theta', theta, 'positive', 'duration θ of the pulse or of the load rise (43)–(53), s')
    return np.select([np.less(theta, 3.141592653589793/Omega),True], [2*np.sin((1/2)*Omega*theta),2], default=np.nan)


def pulse_peak_time(Omega, theta):
    """Time of the largest displacement under the pulse. Eq (47).

    Parameters
    ----------
    Omega : array_like
        natural circular frequency Ω of the rope stretch [rad/s], > 0
    theta : array_like
        duration θ of the pulse or of the load rise (43)–(53) [s], > 0

    Returns
    -------
    ndarray
        [s], broadcast over the arguments.
    """
    Omega = _checked('Omega', Omega, 'positive', 'natural circular frequency Ω of the rope stretch, rad/s')
    theta = _checked('theta', theta, 'positive', 'duration θ of the pulse or of the load rise (43)–(53), s')
    x0 = 1/(Omega)
    x1 = 3.141592653589793*x0
    return np.select([np.less(theta, x1),True], [(1/2)*theta + 1.5707963267948966*x0,x1], default=np.nan)


def dynamic_coefficient_ramp_hold(t, Omega, theta):
    """K_din(t) under a load rising over theta, then held. Eq (51), (52).

    Parameters
    ----------
    t : array_like
        time from the start of the drive [s], >= 0
    Omega : array_like
        natural circular frequency Ω of the rope stretch [rad/s], > 0
    theta : array_like
        duration θ of the pulse or of the load rise (43)–(53) [s], > 0

    Returns
    -------
    ndarray
        [1], broadcast over the arguments.
    """
    t     = _checked('t', t, 'nonnegative', 'time from the start of the drive, s')
    Omega = _checked('Omega', Omega, 'positive', 'natural circular frequency Ω of the rope stretch, rad/s')
    theta = _checked('theta', theta, 'positive', 'duration θ of the pulse or of the load rise (43)–(53), s')
    x0 = -theta
    x1 = (1/2)*Omega
    k2 = -2*np.sin(theta*x1)
    k3 = Omega*theta
    k6 = 1/(Omega*theta)
    return k6*(-(1 - (np.select([np.less_equal(t + x0, 0),True], [0,1], default=np.nan)))*_sin_remainder(Omega*t, 1) + (k2*np.cos(x1*(2*t + x0)) + k3)*(np.select([np.less_equal(t + x0, 0),True], [0,1], default=np.nan)))


def ramp_hold_peak_factor(Omega, theta):
    """Largest x/x_st under the rise-then-hold load. Eq (53).

    Parameters
    ----------
    Omega : array_like
        natural circular frequency Ω of the rope stretch [rad/s], > 0
    theta : array_like
        duration θ of the pulse or of the load rise (43)–(53) [s], > 0

    Returns
    -------
    ndarray
        [1], broadcast over the arguments.
    """
    Omega = _checked('Omega', Omega, 'positive', 'natural circular frequency Ω of the rope stretch, rad/s')
    theta = _checked('theta', theta, 'positive', 'duration θ of the pulse or of the load rise (43)–(53), s')
    return 1 + 2*abs(np.sin((1/2)*Omega*theta))/(Omega*theta)


def dynamic_coefficient_pickup_a1(t, Omega, tau_0, m1, m2, g, v0, t_n):
    """K_din^(1)(t) for the drive law a_1 of (30), lifting with pick-up (tau_0 from pickup_contact_time); Omega from natural_frequency. Eq (26), (28), (30).

    Parameters
    ----------
    t : array_like
        time from the start of the drive [s], >= 0
    Omega : array_like
        natural circular frequency Ω of the rope stretch [rad/s], > 0
    tau_0 : array_like
        duration τ_0 of the contact of the load with the ground when lifting with pick-up [s], > 0
    m1 : array_like
        reduced mass of the drive (first mass) [kg], > 0
    m2 : array_like
        mass of the load (second mass) [kg], > 0
    g : array_like
        acceleration of gravity [m/s^2], > 0
    v0 : array_like
        steady hoisting speed after the start [m/s], > 0
    t_n : array_like
        duration of the start (transient) t_п [s], > 0

    Returns
    -------
    ndarray
        [1], broadcast over the arguments.
    """
    t     = _checked('t', t, 'nonnegative', 'time from the start of the drive, s')
    Omega = _checked('Omega', Omega, 'positive', 'natural circular frequency Ω of the rope stretch, rad/s')
    tau_0 = _checked('tau_0', tau_0, 'positive', 'duration τ_0 of the contact of the load with the ground when lifting with pick-up, s')
    m1    = _checked('m1', m1, 'positive', 'reduced mass of the drive (first mass), kg')
    m2    = _checked('m2', m2, 'positive', 'mass of the load (second mass), kg')
    g     = _checked('g', g, 'positive', 'acceleration of gravity, m/s^2')
    v0    = _checked('v0', v0, 'positive', 'steady hoisting speed after the start, m/s')
    t_n   = _checked('t_n', t_n, 'positive', 'duration of the start (transient) t_п, s')
    q0 = _dd_div(_dd(Omega), (2.0, 0.0))
    x0 = -tau_0
    x1 = (1/2)*Omega
    x2 = 1/(Omega*tau_0)
    x3 = g*m2
    x4 = 2/m1
    x5 = -t_n
    x6 = v0*(m1 + m2)/t_n
    x7 = _sin_phase(t, q0)**2
    k2 = -1/2*tau_0
    k3 = 2*x2*np.sin(tau_0*x1)
    k7 = -g
    k8 = x3*x4
    k13 = np.sin(t_n*x1)
    k14 = x4*x6
    k15 = m1/(x3 + x6)
    return k15*(k14*(k13*np.sin(x1*(2*t + x5))*(np.select([np.less_equal(t + x5, 0),True], [0,1], default=np.nan)) + x7*(1 - (np.select([np.less_equal(t + x5, 0),True], [0,1], default=np.nan)))) + k7*(x2*(1 - (np.select([np.less_equal(t + x0, 0),True], [0,1], default=np.nan)))*_sin_remainder(Omega*t, 1) + (k3*np.cos(Omega*(k2 + t)) - 2*np.sin(x1*(t + x0))**2 - np.cos(_diff_of_products(t, Omega, Omega, tau_0)))*(np.select([np.less_equal(t + x0, 0),True], [0,1], default=np.nan))) + k8*x7)


def dynamic_coefficient_pickup_a2(t, Omega, tau_0, m1, m2, g, v0, t_n):
    """K_din^(1)(t) for the drive law a_2 of (30), lifting with pick-up (tau_0 from pickup_contact_time); Omega from natural_frequency. Eq (26), (28), (30).

    Parameters
    ----------
    t : array_like
        time from the start of the drive [s], >= 0
    Omega : array_like
        natural circular frequency Ω of the rope stretch [rad/s], > 0
    tau_0 : array_like
        duration τ_0 of the contact of the load with the ground when lifting with pick-up [s], > 0
    m1 : array_like
        reduced mass of the drive (first mass) [kg], > 0
    m2 : array_like
        mass of the load (second mass) [kg], > 0
    g : array_like
        acceleration of gravity [m/s^2], > 0
    v0 : array_like
        steady hoisting speed after the start [m/s], > 0
    t_n : array_like
        duration of the start (transient) t_п [s], > 0

    Returns
    -------
    ndarray
        [1], broadcast over the arguments.
    """
    t     = _checked('t', t, 'nonnegative', 'time from the start of the drive, s')
    Omega = _checked('Omega', Omega, 'positive', 'natural circular frequency Ω of the rope stretch, rad/s')
    tau_0 = _checked('tau_0', tau_0, 'positive', 'duration τ_0 of the contact of the load with the ground when lifting with pick-up, s')
    m1    = _checked('m1', m1, 'positive', 'reduced mass of the drive (first mass), kg')
    m2    = _checked('m2', m2, 'positive', 'mass of the load (second mass), kg')
    g     = _checked('g', g, 'positive', 'acceleration of gravity, m/s^2')
    v0    = _checked('v0', v0, 'positive', 'steady hoisting speed after the start, m/s')
    t_n   = _checked('t_n', t_n, 'positive', 'duration of the start (transient) t_п, s')
    q0 = _dd_div(_dd(Omega), (2.0, 0.0))
    x0 = -tau_0
    x1 = (1/2)*Omega
    x2 = 1/(Omega)
    x3 = x2/tau_0
    x4 = 1/(m1)
    x5 = g*m2
    x6 = -t_n
    x7 = 2*np.sin(t_n*x1)
    x8 = 1/(t_n)
    x9 = v0*x8*(m1 + m2)
    x10 = _sin_phase(t, q0)**2
    x11 = _sin_remainder(Omega*t, 1)
    x12 = 2*t
    k2 = -1/2*tau_0
    k3 = 2*x3*np.sin(tau_0*x1)
    k7 = -g
    k8 = 2*x4*x5
    k13 = x2*x7
    k23 = x4*x9
    k24 = m1/(x5 + x9)
    return k24*(k23*(2*x10*(1 - (np.select([np.less_equal(t + x6, 0),True], [0,1], default=np.nan))) + x7*np.sin(x1*(x12 + x6))*(np.select([np.less_equal(t + x6, 0),True], [0,1], default=np.nan)) + x8*(x11*x2*(1 - (np.select([np.less_equal(t + x6, 0),True], [0,1], default=np.nan))) + (k13*np.cos(x1*(x12 + x6)) + x6*np.cos(Omega*(t + x6)))*(np.select([np.less_equal(t + x6, 0),True], [0,1], default=np.nan)))) + k7*(x11*x3*(1 - (np.select([np.less_equal(t + x0, 0),True], [0,1], default=np.nan))) + (k3*np.cos(Omega*(k2 + t)) - 2*np.sin(x1*(t + x0))**2 - np.cos(_diff_of_products(t, Omega, Omega, tau_0)))*(np.select([np.less_equal(t + x0, 0),True], [0,1], default=np.nan))) + k8*x10)


def dynamic_coefficient_pickup_a3(t, Omega, tau_0, m1, m2, g, v0, t_n):
    """K_din^(1)(t) for the drive law a_3 of (30), lifting with pick-up (tau_0 from pickup_contact_time); Omega from natural_frequency. Eq (26), (28), (30).

    Parameters
    ----------
    t : array_like
        time from the start of the drive [s], >= 0
    Omega : array_like
        natural circular frequency Ω of the rope stretch [rad/s], > 0
    tau_0 : array_like
        duration τ_0 of the contact of the load with the ground when lifting with pick-up [s], > 0
    m1 : array_like
        reduced mass of the drive (first mass) [kg], > 0
    m2 : array_like
        mass of the load (second mass) [kg], > 0
    g : array_like
        acceleration of gravity [m/s^2], > 0
    v0 : array_like
        steady hoisting speed after the start [m/s], > 0
    t_n : array_like
        duration of the start (transient) t_п [s], > 0

    Returns
    -------
    ndarray
        [1], broadcast over the arguments.
    """
    t     = _checked('t', t, 'nonnegative', 'time from the start of the drive, s')
    Omega = _checked('Omega', Omega, 'positive', 'natural circular frequency Ω of the rope stretch, rad/s')
    tau_0 = _checked('tau_0', tau_0, 'positive', 'duration τ_0 of the contact of the load with the ground when lifting with pick-up, s')
    m1    = _checked('m1', m1, 'positive', 'reduced mass of the drive (first mass), kg')
    m2    = _checked('m2', m2, 'positive', 'mass of the load (second mass), kg')
    g     = _checked('g', g, 'positive', 'acceleration of gravity, m/s^2')
    v0    = _checked('v0', v0, 'positive', 'steady hoisting speed after the start, m/s')
    t_n   = _checked('t_n', t_n, 'positive', 'duration of the start (transient) t_п, s')
    q0 = _dd_div(_dd(Omega), (2.0, 0.0))
    x0 = -tau_0
    x1 = (1/2)*Omega
    x2 = 1/(Omega)
    x3 = x2/tau_0
    x4 = 1/(m1)
    x5 = -t_n
    x6 = Omega**(-3.0)
    x7 = np.sin(t_n*x1)
    x8 = t_n**2
    x9 = Omega**(-2.0)
    x10 = 1/(x8)
    x11 = 2*x2
    x12 = Omega*t
    x13 = _sin_remainder(x12, 1)
    x14 = 2*t
    k2 = -1/2*tau_0
    k3 = 2*x3*np.sin(tau_0*x1)
    k7 = -g
    k8 = 2*g*m2*x4
    k10 = -t_n**3
    k13 = -12*x6*x7
    k15 = -3*x2*x8
    k17 = 6*t_n*x9
    k20 = 6*x6
    k26 = x11*x7
    k29 = -x8
    k31 = -t_n*x11
    k34 = 4*x7*x9
    k37 = 2*x9
    k38 = -2/t_n
    k40 = -x2
    k41 = 12*v0*x10*x4*(m1 + m2)
    k42 = m1/(g*m2)
    return k42*(k41*(k38*(k37*(1 - (np.select([np.less_equal(t + x5, 0),True], [0,1], default=np.nan)))*_cos_remainder(x12, 2) - (k29*np.cos(Omega*(t + x5)) + k31*np.sin(Omega*(t + x5)) + k34*np.sin(x1*(x14 + x5)))*(np.select([np.less_equal(t + x5, 0),True], [0,1], default=np.nan))) + k40*x13*(1 - (np.select([np.less_equal(t + x5, 0),True], [0,1], default=np.nan))) + x10*(k20*(1 - (np.select([np.less_equal(t + x5, 0),True], [0,1], default=np.nan)))*_sin_remainder(x12, 2) - (k10*np.cos(Omega*(t + x5)) + k13*np.cos(x1*(x14 + x5)) + k15*np.sin(Omega*(t + x5)) + k17*np.cos(Omega*(t + x5)))*(np.select([np.less_equal(t + x5, 0),True], [0,1], default=np.nan))) - (k26*np.cos(x1*(x14 + x5)) + x5*np.cos(Omega*(t + x5)))*(np.select([np.less_equal(t + x5, 0),True], [0,1], default=np.nan))) + k7*(x13*x3*(1 - (np.select([np.less_equal(t + x0, 0),True], [0,1], default=np.nan))) + (k3*np.cos(Omega*(k2 + t)) - 2*np.sin(x1*(t + x0))**2 - np.cos(_diff_of_products(t, Omega, Omega, tau_0)))*(np.select([np.less_equal(t + x0, 0),True], [0,1], default=np.nan))) + k8*_sin_phase(t, q0)**2)


def dynamic_coefficient_pickup_a4(t, Omega, tau_0, m1, m2, g, v0, t_n):
    """K_din^(1)(t) for the drive law a_4 of (30), lifting with pick-up (tau_0 from pickup_contact_time); Omega from natural_frequency. Eq (26), (28), (30).

    Parameters
    ----------
    t : array_like
        time from the start of the drive [s], >= 0
    Omega : array_like
        natural circular frequency Ω of the rope stretch [rad/s], > 0
    tau_0 : array_like
        duration τ_0 of the contact of the load with the ground when lifting with pick-up [s], > 0
    m1 : array_like
        reduced mass of the drive (first mass) [kg], > 0
    m2 : array_like
        mass of the load (second mass) [kg], > 0
    g : array_like
        acceleration of gravity [m/s^2], > 0
    v0 : array_like
        steady hoisting speed after the start [m/s], > 0
    t_n : array_like
        duration of the start (transient) t_п [s], > 0

    Returns
    -------
    ndarray
        [1], broadcast over the arguments.
    """
    t     = _checked('t', t, 'nonnegative', 'time from the start of the drive, s')
    Omega = _checked('Omega', Omega, 'positive', 'natural circular frequency Ω of the rope stretch, rad/s')
    tau_0 = _checked('tau_0', tau_0, 'positive', 'duration τ_0 of the contact of the load with the ground when lifting with pick-up, s')
    m1    = _checked('m1', m1, 'positive', 'reduced mass of the drive (first mass), kg')
    m2    = _checked('m2', m2, 'positive', 'mass of the load (second mass), kg')
    g     = _checked('g', g, 'positive', 'acceleration of gravity, m/s^2')
    v0    = _checked('v0', v0, 'positive', 'steady hoisting speed after the start, m/s')
    t_n   = _checked('t_n', t_n, 'positive', 'duration of the start (transient) t_п, s')
    q0 = _dd_div(_dd(Omega), (2.0, 0.0))
    x0 = -tau_0
    x1 = (1/2)*Omega
    x2 = 1/(Omega)
    x3 = x2/tau_0
    x4 = 1/(m1)
    x5 = -t_n
    x6 = Omega**(-4.0)
    x7 = t_n**4
    x8 = Omega**(-2.0)
    x9 = t_n**3
    x10 = Omega**(-3.0)
    x11 = t_n**2
    x12 = Omega**(-5.0)
    x13 = np.sin(t_n*x1)
    x14 = 1/(x9)
    x15 = Omega*t
    x16 = 2*t
    k2 = -1/2*tau_0
    k3 = 2*x3*np.sin(tau_0*x1)
    k7 = -g
    k8 = 2*g*m2*x4
    k10 = -t_n**5
    k12 = -120*t_n*x6
    k14 = -5*x2*x7
    k16 = 20*x8*x9
    k18 = 60*x10*x11
    k21 = 240*x12*x13
    k24 = 120*x12
    k27 = -x11
    k29 = -2*t_n*x2
    k32 = 4*x13*x8
    k35 = -x9
    k38 = -12*x10*x13
    k40 = -3*x11*x2
    k42 = 6*t_n*x8
    k45 = 6*x10
    k46 = -3/t_n
    k48 = -x7
    k51 = -48*x13*x6
    k53 = -4*x2*x9
    k55 = 12*x11*x8
    k57 = 24*t_n*x10
    k60 = 24*x6
    k61 = -3/x11
    k63 = 2*x8
    k64 = 60*v0*x14*x4*(m1 + m2)
    k65 = m1/(g*m2)
    return k65*(k64*(k46*(k45*(1 - (np.select([np.less_equal(t + x5, 0),True], [0,1], default=np.nan)))*_sin_remainder(x15, 2) - (k35*np.cos(Omega*(t + x5)) + k38*np.cos(x1*(x16 + x5)) + k40*np.sin(Omega*(t + x5)) + k42*np.cos(Omega*(t + x5)))*(np.select([np.less_equal(t + x5, 0),True], [0,1], default=np.nan))) + k61*(k60*(1 - (np.select([np.less_equal(t + x5, 0),True], [0,1], default=np.nan)))*_cos_remainder(x15, 3) + (k48*np.cos(Omega*(t + x5)) + k51*np.sin(x1*(x16 + x5)) + k53*np.sin(Omega*(t + x5)) + k55*np.cos(Omega*(t + x5)) + k57*np.sin(Omega*(t + x5)))*(np.select([np.less_equal(t + x5, 0),True], [0,1], default=np.nan))) + k63*(1 - (np.select([np.less_equal(t + x5, 0),True], [0,1], default=np.nan)))*_cos_remainder(x15, 2) + x14*(k24*(1 - (np.select([np.less_equal(t + x5, 0),True], [0,1], default=np.nan)))*_sin_remainder(x15, 3) + (k10*np.cos(Omega*(t + x5)) + k12*np.cos(Omega*(t + x5)) + k14*np.sin(Omega*(t + x5)) + k16*np.cos(Omega*(t + x5)) + k18*np.sin(Omega*(t + x5)) + k21*np.cos(x1*(x16 + x5)))*(np.select([np.less_equal(t + x5, 0),True], [0,1], default=np.nan))) - (k27*np.cos(Omega*(t + x5)) + k29*np.sin(Omega*(t + x5)) + k32*np.sin(x1*(x16 + x5)))*(np.select([np.less_equal(t + x5, 0),True], [0,1], default=np.nan))) + k7*(x3*(1 - (np.select([np.less_equal(t + x0, 0),True], [0,1], default=np.nan)))*_sin_remainder(x15, 1) + (k3*np.cos(Omega*(k2 + t)) - 2*np.sin(x1*(t + x0))**2 - np.cos(_diff_of_products(t, Omega, Omega, tau_0)))*(np.select([np.less_equal(t + x0, 0),True], [0,1], default=np.nan))) + k8*_sin_phase(t, q0)**2)


def dynamic_coefficient_from_weight_a1(t, Omega, m1, m2, g, v0, t_n):
    """K_din^(2)(t) for the drive law a_1 of (30), lifting from weight; Omega from natural_frequency. Eq (27), (28), (30).

    Parameters
    ----------
    t : array_like
        time from the start of the drive [s], >= 0
    Omega : array_like
        natural circular frequency Ω of the rope stretch [rad/s], > 0
    m1 : array_like
        reduced mass of the drive (first mass) [kg], > 0
    m2 : array_like
        mass of the load (second mass) [kg], > 0
    g : array_like
        acceleration of gravity [m/s^2], > 0
    v0 : array_like
        steady hoisting speed after the start [m/s], > 0
    t_n : array_like
        duration of the start (transient) t_п [s], > 0

    Returns
    -------
    ndarray
        [1], broadcast over the arguments.
    """
    t     = _checked('t', t, 'nonnegative', 'time from the start of the drive, s')
    Omega = _checked('Omega', Omega, 'positive', 'natural circular frequency Ω of the rope stretch, rad/s')
    m1    = _checked('m1', m1, 'positive', 'reduced mass of the drive (first mass), kg')
    m2    = _checked('m2', m2, 'positive', 'mass of the load (second mass), kg')
    g     = _checked('g', g, 'positive', 'acceleration of gravity, m/s^2')
    v0    = _checked('v0', v0, 'positive', 'steady hoisting speed after the start, m/s')
    t_n   = _checked('t_n', t_n, 'positive', 'duration of the start (transient) t_п, s')
    q0 = _dd(Omega)
    q1 = _dd_div(_dd(Omega), (2.0, 0.0))
    x0 = 1/(m1)
    x1 = g*m2
    x2 = -t_n
    x3 = (1/2)*Omega
    x4 = m1 + m2
    x5 = v0*x4/t_n
    x6 = _sin_phase(t, q1)**2
    k0 = x0*x1
    k5 = np.sin(t_n*x3)
    k6 = x0*x5
    k7 = 2*m1/x4
    k8 = x4/(g*m1 + x1 + x5)
    return k8*(g*_cos_phase(t, q0) + k7*(g*x6 + k0*x6 + k6*(k5*np.sin(x3*(2*t + x2))*(np.select([np.less_equal(t + x2, 0),True], [0,1], default=np.nan)) + x6*(1 - (np.select([np.less_equal(t + x2, 0),True], [0,1], default=np.nan))))))


def dynamic_coefficient_from_weight_a2(t, Omega, m1, m2, g, v0, t_n):
    """K_din^(2)(t) for the drive law a_2 of (30), lifting from weight; Omega from natural_frequency. Eq (27), (28), (30).

    Parameters
    ----------
    t : array_like
        time from the start of the drive [s], >= 0
    Omega : array_like
        natural circular frequency Ω of the rope stretch [rad/s], > 0
    m1 : array_like
        reduced mass of the drive (first mass) [kg], > 0
    m2 : array_like
        mass of the load (second mass) [kg], > 0
    g : array_like
        acceleration of gravity [m/s^2], > 0
    v0 : array_like
        steady hoisting speed after the start [m/s], > 0
    t_n : array_like
        duration of the start (transient) t_п [s], > 0

    Returns
    -------
    ndarray
        [1], broadcast over the arguments.
    """
    t     = _checked('t', t, 'nonnegative', 'time from the start of the drive, s')
    Omega = _checked('Omega', Omega, 'positive', 'natural circular frequency Ω of the rope stretch, rad/s')
    m1    = _checked('m1', m1, 'positive', 'reduced mass of the drive (first mass), kg')
    m2    = _checked('m2', m2, 'positive', 'mass of the load (second mass), kg')
    g     = _checked('g', g, 'positive', 'acceleration of gravity, m/s^2')
    v0    = _checked('v0', v0, 'positive', 'steady hoisting speed after the start, m/s')
    t_n   = _checked('t_n', t_n, 'positive', 'duration of the start (transient) t_п, s')
    q0 = _dd(Omega)
    q1 = _dd_div(_dd(Omega), (2.0, 0.0))
    x0 = 2*g
    x1 = 1/(m1)
    x2 = -t_n
    x3 = (1/2)*Omega
    x4 = 1/(Omega)
    x5 = 2*np.sin(t_n*x3)
    x6 = 1/(t_n)
    x7 = m1 + m2
    x8 = v0*x6*x7
    x9 = _sin_phase(t, q1)**2
    x10 = 2*t
    k1 = m2*x0*x1
    k6 = x4*x5
    k16 = x1*x8
    k17 = m1/x7
    k18 = x7/(g*m1 + g*m2 + x8)
    return k18*(g*_cos_phase(t, q0) + k17*(k1*x9 + k16*(x5*np.sin(x3*(x10 + x2))*(np.select([np.less_equal(t + x2, 0),True], [0,1], default=np.nan)) + x6*(x4*(1 - (np.select([np.less_equal(t + x2, 0),True], [0,1], default=np.nan)))*_sin_remainder(Omega*t, 1) + (k6*np.cos(x3*(x10 + x2)) + x2*np.cos(Omega*(t + x2)))*(np.select([np.less_equal(t + x2, 0),True], [0,1], default=np.nan))) + 2*x9*(1 - (np.select([np.less_equal(t + x2, 0),True], [0,1], default=np.nan)))) + x0*x9))


def dynamic_coefficient_from_weight_a3(t, Omega, m1, m2, g, v0, t_n):
    """K_din^(2)(t) for the drive law a_3 of (30), lifting from weight; Omega from natural_frequency. Eq (27), (28), (30).

    Parameters
    ----------
    t : array_like
        time from the start of the drive [s], >= 0
    Omega : array_like
        natural circular frequency Ω of the rope stretch [rad/s], > 0
    m1 : array_like
        reduced mass of the drive (first mass) [kg], > 0
    m2 : array_like
        mass of the load (second mass) [kg], > 0
    g : array_like
        acceleration of gravity [m/s^2], > 0
    v0 : array_like
        steady hoisting speed after the start [m/s], > 0
    t_n : array_like
        duration of the start (transient) t_п [s], > 0

    Returns
    -------
    ndarray
        [1], broadcast over the arguments.
    """
    t     = _checked('t', t, 'nonnegative', 'time from the start of the drive, s')
    Omega = _checked('Omega', Omega, 'positive', 'natural circular frequency Ω of the rope stretch, rad/s')
    m1    = _checked('m1', m1, 'positive', 'reduced mass of the drive (first mass), kg')
    m2    = _checked('m2', m2, 'positive', 'mass of the load (second mass), kg')
    g     = _checked('g', g, 'positive', 'acceleration of gravity, m/s^2')
    v0    = _checked('v0', v0, 'positive', 'steady hoisting speed after the start, m/s')
    t_n   = _checked('t_n', t_n, 'positive', 'duration of the start (transient) t_п, s')
    q0 = _dd(Omega)
    q1 = _dd_div(_dd(Omega), (2.0, 0.0))
    x0 = 1/(m1)
    x1 = -t_n
    x2 = (1/2)*Omega
    x3 = Omega**(-3.0)
    x4 = np.sin(t_n*x2)
    x5 = 1/(Omega)
    x6 = t_n**2
    x7 = Omega**(-2.0)
    x8 = 1/(x6)
    x9 = 2*x5
    x10 = m1 + m2
    x11 = _sin_phase(t, q1)**2
    x12 = Omega*t
    x13 = 2*t
    k0 = g*m2*x0
    k2 = -t_n**3
    k5 = -12*x3*x4
    k7 = -3*x5*x6
    k9 = 6*t_n*x7
    k12 = 6*x3
    k18 = x4*x9
    k21 = -x6
    k23 = -t_n*x9
    k26 = 4*x4*x7
    k29 = 2*x7
    k30 = -2/t_n
    k32 = -x5
    k33 = 6*v0*x0*x10*x8
    k34 = 2*m1/x10
    k35 = 1/(g)
    return k35*(g*_cos_phase(t, q0) + k34*(g*x11 + k0*x11 + k33*(k30*(k29*(1 - (np.select([np.less_equal(t + x1, 0),True], [0,1], default=np.nan)))*_cos_remainder(x12, 2) - (k21*np.cos(Omega*(t + x1)) + k23*np.sin(Omega*(t + x1)) + k26*np.sin(x2*(x1 + x13)))*(np.select([np.less_equal(t + x1, 0),True], [0,1], default=np.nan))) + k32*(1 - (np.select([np.less_equal(t + x1, 0),True], [0,1], default=np.nan)))*_sin_remainder(x12, 1) + x8*(k12*(1 - (np.select([np.less_equal(t + x1, 0),True], [0,1], default=np.nan)))*_sin_remainder(x12, 2) - (k2*np.cos(Omega*(t + x1)) + k5*np.cos(x2*(x1 + x13)) + k7*np.sin(Omega*(t + x1)) + k9*np.cos(Omega*(t + x1)))*(np.select([np.less_equal(t + x1, 0),True], [0,1], default=np.nan))) - (k18*np.cos(x2*(x1 + x13)) + x1*np.cos(Omega*(t + x1)))*(np.select([np.less_equal(t + x1, 0),True], [0,1], default=np.nan)))))


def dynamic_coefficient_from_weight_a4(t, Omega, m1, m2, g, v0, t_n):
    """K_din^(2)(t) for the drive law a_4 of (30), lifting from weight; Omega from natural_frequency. Eq (27), (28), (30).

    Parameters
    ----------
    t : array_like
        time from the start of the drive [s], >= 0
    Omega : array_like
        natural circular frequency Ω of the rope stretch [rad/s], > 0
    m1 : array_like
        reduced mass of the drive (first mass) [kg], > 0
    m2 : array_like
        mass of the load (second mass) [kg], > 0
    g : array_like
        acceleration of gravity [m/s^2], > 0
    v0 : array_like
        steady hoisting speed after the start [m/s], > 0
    t_n : array_like
        duration of the start (transient) t_п [s], > 0

    Returns
    -------
    ndarray
        [1], broadcast over the arguments.
    """
    t     = _checked('t', t, 'nonnegative', 'time from the start of the drive, s')
    Omega = _checked('Omega', Omega, 'positive', 'natural circular frequency Ω of the rope stretch, rad/s')
    m1    = _checked('m1', m1, 'positive', 'reduced mass of the drive (first mass), kg')
    m2    = _checked('m2', m2, 'positive', 'mass of the load (second mass), kg')
    g     = _checked('g', g, 'positive', 'acceleration of gravity, m/s^2')
    v0    = _checked('v0', v0, 'positive', 'steady hoisting speed after the start, m/s')
    t_n   = _checked('t_n', t_n, 'positive', 'duration of the start (transient) t_п, s')
    q0 = _dd(Omega)
    q1 = _dd_div(_dd(Omega), (2.0, 0.0))
    x0 = 1/(m1)
    x1 = -t_n
    x2 = Omega**(-4.0)
    x3 = 1/(Omega)
    x4 = t_n**4
    x5 = Omega**(-2.0)
    x6 = t_n**3
    x7 = Omega**(-3.0)
    x8 = t_n**2
    x9 = (1/2)*Omega
    x10 = Omega**(-5.0)
    x11 = np.sin(t_n*x9)
    x12 = 1/(x6)
    x13 = m1 + m2
    x14 = _sin_phase(t, q1)**2
    x15 = Omega*t
    x16 = 2*t
    k0 = g*m2*x0
    k2 = -t_n**5
    k4 = -120*t_n*x2
    k6 = -5*x3*x4
    k8 = 20*x5*x6
    k10 = 60*x7*x8
    k13 = 240*x10*x11
    k16 = 120*x10
    k19 = -x8
    k21 = -2*t_n*x3
    k24 = 4*x11*x5
    k27 = -x6
    k30 = -12*x11*x7
    k32 = -3*x3*x8
    k34 = 6*t_n*x5
    k37 = 6*x7
    k38 = -3/t_n
    k40 = -x4
    k43 = -48*x11*x2
    k45 = -4*x3*x6
    k47 = 12*x5*x8
    k49 = 24*t_n*x7
    k52 = 24*x2
    k53 = -3/x8
    k55 = 2*x5
    k56 = 30*v0*x0*x12*x13
    k57 = 2*m1/x13
    k58 = 1/(g)
    return k58*(g*_cos_phase(t, q0) + k57*(g*x14 + k0*x14 + k56*(k38*(k37*(1 - (np.select([np.less_equal(t + x1, 0),True], [0,1], default=np.nan)))*_sin_remainder(x15, 2) - (k27*np.cos(Omega*(t + x1)) + k30*np.cos(x9*(x1 + x16)) + k32*np.sin(Omega*(t + x1)) + k34*np.cos(Omega*(t + x1)))*(np.select([np.less_equal(t + x1, 0),True], [0,1], default=np.nan))) + k53*(k52*(1 - (np.select([np.less_equal(t + x1, 0),True], [0,1], default=np.nan)))*_cos_remainder(x15, 3) + (k40*np.cos(Omega*(t + x1)) + k43*np.sin(x9*(x1 + x16)) + k45*np.sin(Omega*(t + x1)) + k47*np.cos(Omega*(t + x1)) + k49*np.sin(Omega*(t + x1)))*(np.select([np.less_equal(t + x1, 0),True], [0,1], default=np.nan))) + k55*(1 - (np.select([np.less_equal(t + x1, 0),True], [0,1], default=np.nan)))*_cos_remainder(x15, 2) + x12*(k16*(1 - (np.select([np.less_equal(t + x1, 0),True], [0,1], default=np.nan)))*_sin_remainder(x15, 3) + (k10*np.sin(Omega*(t + x1)) + k13*np.cos(x9*(x1 + x16)) + k2*np.cos(Omega*(t + x1)) + k4*np.cos(Omega*(t + x1)) + k6*np.sin(Omega*(t + x1)) + k8*np.cos(Omega*(t + x1)))*(np.select([np.less_equal(t + x1, 0),True], [0,1], default=np.nan))) - (k19*np.cos(Omega*(t + x1)) + k21*np.sin(Omega*(t + x1)) + k24*np.sin(x9*(x1 + x16)))*(np.select([np.less_equal(t + x1, 0),True], [0,1], default=np.nan)))))


def optimal_coefficient_from_weight_a1(t, t_n):
    """k~_din1^(opt)(t) from weight, 0 <= t <= t_n. Eq (63), (65).

    Parameters
    ----------
    t : array_like
        time from the start of the drive [s], >= 0
    t_n : array_like
        duration of the start (transient) t_п [s], > 0

    Returns
    -------
    ndarray
        [1], broadcast over the arguments.
    """
    t   = _checked('t', t, 'nonnegative', 'time from the start of the drive, s')
    t_n = _checked('t_n', t_n, 'positive', 'duration of the start (transient) t_п, s')
    return 1


def optimal_coefficient_pickup_a1(t, t_n, v0, g, tau_0):
    """k~_din1^(opt)(t) with pick-up, 0 <= t <= t_n. Eq (64), (65), (66).

    Parameters
    ----------
    t : array_like
        time from the start of the drive [s], >= 0
    t_n : array_like
        duration of the start (transient) t_п [s], > 0
    v0 : array_like
        steady hoisting speed after the start [m/s], > 0
    g : array_like
        acceleration of gravity [m/s^2], > 0
    tau_0 : array_like
        duration τ_0 of the contact of the load with the ground when lifting with pick-up [s], > 0

    Returns
    -------
    ndarray
        [1], broadcast over the arguments.
    """
    t     = _checked('t', t, 'nonnegative', 'time from the start of the drive, s')
    t_n   = _checked('t_n', t_n, 'positive', 'duration of the start (transient) t_п, s')
    v0    = _checked('v0', v0, 'positive', 'steady hoisting speed after the start, m/s')
    g     = _checked('g', g, 'positive', 'acceleration of gravity, m/s^2')
    tau_0 = _checked('tau_0', tau_0, 'positive', 'duration τ_0 of the contact of the load with the ground when lifting with pick-up, s')
    x0 = -tau_0
    k1 = g*t_n/(tau_0*v0)
    return (1 - (np.select([np.less_equal(t + x0, 0),True], [0,1], default=np.nan)))*(k1*t + 1) + (np.select([np.less_equal(t + x0, 0),True], [0,1], default=np.nan))


def optimal_coefficient_from_weight_a2(t, t_n):
    """k~_din2^(opt)(t) from weight, 0 <= t <= t_n. Eq (63), (65).

    Parameters
    ----------
    t : array_like
        time from the start of the drive [s], >= 0
    t_n : array_like
        duration of the start (transient) t_п [s], > 0

    Returns
    -------
    ndarray
        [1], broadcast over the arguments.
    """
    t   = _checked('t', t, 'nonnegative', 'time from the start of the drive, s')
    t_n = _checked('t_n', t_n, 'positive', 'duration of the start (transient) t_п, s')
    k0 = -1/t_n
    return k0*t + 1


def optimal_coefficient_pickup_a2(t, t_n, v0, g, tau_0):
    """k~_din2^(opt)(t) with pick-up, 0 <= t <= t_n. Eq (64), (65), (66).

    Parameters
    ----------
    t : array_like
        time from the start of the drive [s], >= 0
    t_n : array_like
        duration of the start (transient) t_п [s], > 0
    v0 : array_like
        steady hoisting speed after the start [m/s], > 0
    g : array_like
        acceleration of gravity [m/s^2], > 0
    tau_0 : array_like
        duration τ_0 of the contact of the load with the ground when lifting with pick-up [s], > 0

    Returns
    -------
    ndarray
        [1], broadcast over the arguments.
    """
    t     = _checked('t', t, 'nonnegative', 'time from the start of the drive, s')
    t_n   = _checked('t_n', t_n, 'positive', 'duration of the start (transient) t_п, s')
    v0    = _checked('v0', v0, 'positive', 'steady hoisting speed after the start, m/s')
    g     = _checked('g', g, 'positive', 'acceleration of gravity, m/s^2')
    tau_0 = _checked('tau_0', tau_0, 'positive', 'duration τ_0 of the contact of the load with the ground when lifting with pick-up, s')
    x0 = -tau_0
    x1 = -1/t_n
    k2 = g*t_n/(tau_0*v0)
    return (1 - (np.select([np.less_equal(t + x0, 0),True], [0,1], default=np.nan)))*(k2*t + t*x1 + 1) + (t*x1 + 1)*(np.select([np.less_equal(t + x0, 0),True], [0,1], default=np.nan))


def optimal_coefficient_from_weight_a3(t, t_n):
    """k~_din3^(opt)(t) from weight, 0 <= t <= t_n. Eq (63), (65).

    Parameters
    ----------
    t : array_like
        time from the start of the drive [s], >= 0
    t_n : array_like
        duration of the start (transient) t_п [s], > 0

    Returns
    -------
    ndarray
        [1], broadcast over the arguments.
    """
    t   = _checked('t', t, 'nonnegative', 'time from the start of the drive, s')
    t_n = _checked('t_n', t_n, 'positive', 'duration of the start (transient) t_п, s')
    k0 = -t_n
    k1 = 12/t_n**3
    return k1*t*(k0 + t)**2


def optimal_coefficient_pickup_a3(t, t_n, v0, g, tau_0):
    """k~_din3^(opt)(t) with pick-up, 0 <= t <= t_n. Eq (64), (65), (66).

    Parameters
    ----------
    t : array_like
        time from the start of the drive [s], >= 0
    t_n : array_like
        duration of the start (transient) t_п [s], > 0
    v0 : array_like
        steady hoisting speed after the start [m/s], > 0
    g : array_like
        acceleration of gravity [m/s^2], > 0
    tau_0 : array_like
        duration τ_0 of the contact of the load with the ground when lifting with pick-up [s], > 0

    Returns
    -------
    ndarray
        [1], broadcast over the arguments.
    """
    t     = _checked('t', t, 'nonnegative', 'time from the start of the drive, s')
    t_n   = _checked('t_n', t_n, 'positive', 'duration of the start (transient) t_п, s')
    v0    = _checked('v0', v0, 'positive', 'steady hoisting speed after the start, m/s')
    g     = _checked('g', g, 'positive', 'acceleration of gravity, m/s^2')
    tau_0 = _checked('tau_0', tau_0, 'positive', 'duration τ_0 of the contact of the load with the ground when lifting with pick-up, s')
    x0 = -tau_0
    x1 = tau_0*v0
    x2 = 12*x1
    k0 = -t_n
    k4 = -24*t_n*x1
    k5 = g*t_n**4 + t_n**2*x2
    k6 = 1/(tau_0*v0)
    k7 = t_n**(-3.0)
    return k7*t*(k6*(1 - (np.select([np.less_equal(t + x0, 0),True], [0,1], default=np.nan)))*(k4*t + k5 + t**2*x2) + 12*(k0 + t)**2*(np.select([np.less_equal(t + x0, 0),True], [0,1], default=np.nan)))


def optimal_coefficient_from_weight_a4(t, t_n):
    """k~_din4^(opt)(t) from weight, 0 <= t <= t_n. Eq (63), (65).

    Parameters
    ----------
    t : array_like
        time from the start of the drive [s], >= 0
    t_n : array_like
        duration of the start (transient) t_п [s], > 0

    Returns
    -------
    ndarray
        [1], broadcast over the arguments.
    """
    t   = _checked('t', t, 'nonnegative', 'time from the start of the drive, s')
    t_n = _checked('t_n', t_n, 'positive', 'duration of the start (transient) t_п, s')
    k0 = -t_n
    k1 = -60/t_n**5
    return k1*t**2*(k0 + t)**3


def optimal_coefficient_pickup_a4(t, t_n, v0, g, tau_0):
    """k~_din4^(opt)(t) with pick-up, 0 <= t <= t_n. Eq (64), (65), (66).

    Parameters
    ----------
    t : array_like
        time from the start of the drive [s], >= 0
    t_n : array_like
        duration of the start (transient) t_п [s], > 0
    v0 : array_like
        steady hoisting speed after the start [m/s], > 0
    g : array_like
        acceleration of gravity [m/s^2], > 0
    tau_0 : array_like
        duration τ_0 of the contact of the load with the ground when lifting with pick-up [s], > 0

    Returns
    -------
    ndarray
        [1], broadcast over the arguments.
    """
    t     = _checked('t', t, 'nonnegative', 'time from the start of the drive, s')
    t_n   = _checked('t_n', t_n, 'positive', 'duration of the start (transient) t_п, s')
    v0    = _checked('v0', v0, 'positive', 'steady hoisting speed after the start, m/s')
    g     = _checked('g', g, 'positive', 'acceleration of gravity, m/s^2')
    tau_0 = _checked('tau_0', tau_0, 'positive', 'duration τ_0 of the contact of the load with the ground when lifting with pick-up, s')
    x0 = -tau_0
    x1 = tau_0*v0
    x2 = 60*x1
    x3 = 180*x1
    k0 = -t_n
    k4 = -t_n*x3
    k5 = -t_n**3*x2
    k6 = t_n**2*x3
    k7 = -g*t_n**6
    k8 = 1/(tau_0*v0)
    k9 = -1/t_n**5
    return k9*t*(k8*(1 - (np.select([np.less_equal(t + x0, 0),True], [0,1], default=np.nan)))*(k4*t**3 + k5*t + k6*t**2 + k7 + t**4*x2) + 60*t*(k0 + t)**3*(np.select([np.less_equal(t + x0, 0),True], [0,1], default=np.nan)))
