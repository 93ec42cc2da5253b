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
    q0 = _dd(Omega)
    k0 = 1/(Omega*t_n)
    return k0*(Omega*t - _sin_phase(t, q0))


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
    q0 = _dd(Omega)
    q1 = _dd_div(_dd(Omega), (2.0, 0.0))
    x0 = -theta
    return 2*(1 - (np.select([np.less_equal(t + x0, 0),True], [0,1], default=np.nan)))*_sin_phase(t, q1)**2 + (np.cos(Omega*(t + x0)) - _cos_phase(t, q0))*(np.select([np.less_equal(t + x0, 0),True], [0,1], default=np.nan))


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
    q0 = _dd(Omega)
    x0 = -theta
    x1 = -_sin_phase(t, q0)
    k2 = Omega*theta
    k4 = 1/(Omega*theta)
    return k4*((1 - (np.select([np.less_equal(t + x0, 0),True], [0,1], default=np.nan)))*(Omega*t + x1) + (k2 + x1 + np.sin(Omega*(t + x0)))*(np.select([np.less_equal(t + x0, 0),True], [0,1], default=np.nan)))


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
    q0 = _dd(Omega)
    q1 = _dd_div(_dd(Omega), (2.0, 0.0))
    x0 = -tau_0
    x1 = 1/(Omega)
    x2 = 1/(tau_0)
    x3 = x1*x2
    x4 = 1/(m1)
    x5 = g*m2
    x6 = -t_n
    x7 = v0*(m1 + m2)/t_n
    x8 = _sin_phase(t, q1)**2
    x9 = _sin_phase(t, q0)
    x10 = _diff_of_products(t, Omega, Omega, tau_0)
    k1 = (1/2)*Omega
    k3 = -x3
    k8 = -g
    k9 = 2*x4*x5
    k13 = -x4*x7
    k14 = m1/(x5 + x7)
    return k14*(k13*(-2*x8*(1 - (np.select([np.less_equal(t + x6, 0),True], [0,1], default=np.nan))) + (-np.cos(Omega*(t + x6)) + _cos_phase(t, q0))*(np.select([np.less_equal(t + x6, 0),True], [0,1], default=np.nan))) + k8*(x2*(1 - (np.select([np.less_equal(t + x0, 0),True], [0,1], default=np.nan)))*(-t + x1*x9) + (k3*np.sin(x10) + x3*x9 - 2*np.sin(k1*(t + x0))**2 - np.cos(x10))*(np.select([np.less_equal(t + x0, 0),True], [0,1], default=np.nan))) + k9*x8)


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
    q0 = _dd(Omega)
    q1 = _dd_div(_dd(Omega), (2.0, 0.0))
    x0 = -tau_0
    x1 = 1/(Omega)
    x2 = 1/(tau_0)
    x3 = x1*x2
    x4 = 1/(m1)
    x5 = g*m2
    x6 = -t_n
    x7 = 1/(t_n)
    x8 = v0*x7*(m1 + m2)
    x9 = _sin_phase(t, q1)**2
    x10 = -t
    x11 = _sin_phase(t, q0)
    x12 = _diff_of_products(t, Omega, Omega, tau_0)
    k1 = (1/2)*Omega
    k3 = -x3
    k8 = -g
    k9 = 2*x4*x5
    k16 = -x1
    k22 = x4*x8
    k23 = m1/(x5 + x8)
    return k23*(k22*(x7*((1 - (np.select([np.less_equal(t + x6, 0),True], [0,1], default=np.nan)))*(x1*x11 + x10) + (k16*np.sin(Omega*(t + x6)) + x1*x11 + x6*np.cos(Omega*(t + x6)))*(np.select([np.less_equal(t + x6, 0),True], [0,1], default=np.nan))) + 2*x9*(1 - (np.select([np.less_equal(t + x6, 0),True], [0,1], default=np.nan))) - (-np.cos(Omega*(t + x6)) + _cos_phase(t, q0))*(np.select([np.less_equal(t + x6, 0),True], [0,1], default=np.nan))) + k8*(x2*(1 - (np.select([np.less_equal(t + x0, 0),True], [0,1], default=np.nan)))*(x1*x11 + x10) + (k3*np.sin(x12) + x11*x3 - 2*np.sin(k1*(t + x0))**2 - np.cos(x12))*(np.select([np.less_equal(t + x0, 0),True], [0,1], default=np.nan))) + k9*x9)


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
    q0 = _dd(Omega)
    q1 = _dd_div(_dd(Omega), (2.0, 0.0))
    x0 = -tau_0
    x1 = 1/(Omega)
    x2 = 1/(tau_0)
    x3 = x1*x2
    x4 = 1/(m1)
    x5 = -t_n
    x6 = 6/Omega**3
    x7 = -x6
    x8 = Omega**(-2.0)
    x9 = 6*x8
    x10 = t_n**2
    x11 = 1/(x10)
    x12 = 2*x8
    x13 = _sin_phase(t, q1)**2
    x14 = -t
    x15 = _sin_phase(t, q0)
    x16 = _diff_of_products(t, Omega, Omega, tau_0)
    k1 = (1/2)*Omega
    k3 = -x3
    k8 = -g
    k9 = 2*g*m2*x4
    k14 = -t_n**3
    k19 = -3*x1*x10
    k21 = t_n*x9
    k23 = -x11
    k30 = -x1
    k33 = 4*x8
    k35 = -x10
    k36 = -x12
    k40 = -2*t_n*x1
    k42 = 2/t_n
    k43 = 12*v0*x11*x4*(m1 + m2)
    k44 = m1/(g*m2)
    return k44*(k43*(k23*((1 - (np.select([np.less_equal(t + x5, 0),True], [0,1], default=np.nan)))*(-t**3 + t*x9 + x15*x7) + (k14*np.cos(Omega*(t + x5)) + k19*np.sin(Omega*(t + x5)) + k21*np.cos(Omega*(t + x5)) + x15*x7 + x6*np.sin(Omega*(t + x5)))*(np.select([np.less_equal(t + x5, 0),True], [0,1], default=np.nan))) + k42*((1 - (np.select([np.less_equal(t + x5, 0),True], [0,1], default=np.nan)))*(k33*x13 - t**2) + (k35*np.cos(Omega*(t + x5)) + k36*_cos_phase(t, q0) + k40*np.sin(Omega*(t + x5)) + x12*np.cos(Omega*(t + x5)))*(np.select([np.less_equal(t + x5, 0),True], [0,1], default=np.nan))) - (1 - (np.select([np.less_equal(t + x5, 0),True], [0,1], default=np.nan)))*(x1*x15 + x14) - (k30*np.sin(Omega*(t + x5)) + x1*x15 + x5*np.cos(Omega*(t + x5)))*(np.select([np.less_equal(t + x5, 0),True], [0,1], default=np.nan))) + k8*(x2*(1 - (np.select([np.less_equal(t + x0, 0),True], [0,1], default=np.nan)))*(x1*x15 + x14) + (k3*np.sin(x16) + x15*x3 - 2*np.sin(k1*(t + x0))**2 - np.cos(x16))*(np.select([np.less_equal(t + x0, 0),True], [0,1], default=np.nan))) + k9*x13)


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
    q0 = _dd(Omega)
    q1 = _dd_div(_dd(Omega), (2.0, 0.0))
    x0 = -tau_0
    x1 = 1/(Omega)
    x2 = 1/(tau_0)
    x3 = x1*x2
    x4 = 1/(m1)
    x5 = -t_n
    x6 = Omega**(-4.0)
    x7 = 120*x6
    x8 = Omega**(-2.0)
    x9 = 20*x8
    x10 = 120/Omega**5
    x11 = t_n**4
    x12 = t_n**3
    x13 = Omega**(-3.0)
    x14 = t_n**2
    x15 = 1/(x12)
    x16 = 2*x8
    x17 = 12*x8
    x18 = 24*x6
    x19 = 6*x13
    x20 = -x19
    x21 = 6*x8
    x22 = _sin_phase(t, q1)**2
    x23 = _sin_phase(t, q0)
    x24 = _diff_of_products(t, Omega, Omega, tau_0)
    x25 = t**2
    x26 = _cos_phase(t, q0)
    x27 = t**3
    k1 = (1/2)*Omega
    k3 = -x3
    k8 = -g
    k9 = 2*g*m2*x4
    k11 = -x7
    k15 = -t_n**5
    k17 = -x10
    k20 = -t_n*x7
    k22 = -5*x1*x11
    k24 = x12*x9
    k26 = 60*x13*x14
    k30 = 4*x8
    k32 = -x14
    k33 = -x16
    k37 = -2*t_n*x1
    k40 = -48*x6
    k43 = -x11
    k45 = -x18
    k48 = -4*x1*x12
    k50 = x14*x17
    k52 = 24*t_n*x13
    k54 = -3/x14
    k59 = -x12
    k64 = -3*x1*x14
    k66 = t_n*x21
    k68 = 3/t_n
    k69 = 60*v0*x15*x4*(m1 + m2)
    k70 = m1/(g*m2)
    return k70*(k69*(k54*((1 - (np.select([np.less_equal(t + x5, 0),True], [0,1], default=np.nan)))*(k40*x22 - t**4 + x17*x25) + (k43*np.cos(Omega*(t + x5)) + k45*np.cos(Omega*(t + x5)) + k48*np.sin(Omega*(t + x5)) + k50*np.cos(Omega*(t + x5)) + k52*np.sin(Omega*(t + x5)) + x18*x26)*(np.select([np.less_equal(t + x5, 0),True], [0,1], default=np.nan))) + k68*((1 - (np.select([np.less_equal(t + x5, 0),True], [0,1], default=np.nan)))*(t*x21 + x20*x23 - x27) + (k59*np.cos(Omega*(t + x5)) + k64*np.sin(Omega*(t + x5)) + k66*np.cos(Omega*(t + x5)) + x19*np.sin(Omega*(t + x5)) + x20*x23)*(np.select([np.less_equal(t + x5, 0),True], [0,1], default=np.nan))) + x15*((1 - (np.select([np.less_equal(t + x5, 0),True], [0,1], default=np.nan)))*(k11*t - t**5 + x10*x23 + x27*x9) + (k15*np.cos(Omega*(t + x5)) + k17*np.sin(Omega*(t + x5)) + k20*np.cos(Omega*(t + x5)) + k22*np.sin(Omega*(t + x5)) + k24*np.cos(Omega*(t + x5)) + k26*np.sin(Omega*(t + x5)) + x10*x23)*(np.select([np.less_equal(t + x5, 0),True], [0,1], default=np.nan))) - (1 - (np.select([np.less_equal(t + x5, 0),True], [0,1], default=np.nan)))*(k30*x22 - x25) - (k32*np.cos(Omega*(t + x5)) + k33*x26 + k37*np.sin(Omega*(t + x5)) + x16*np.cos(Omega*(t + x5)))*(np.select([np.less_equal(t + x5, 0),True], [0,1], default=np.nan))) + k8*(x2*(1 - (np.select([np.less_equal(t + x0, 0),True], [0,1], default=np.nan)))*(-t + x1*x23) + (k3*np.sin(x24) + x23*x3 - 2*np.sin(k1*(t + x0))**2 - np.cos(x24))*(np.select([np.less_equal(t + x0, 0),True], [0,1], default=np.nan))) + k9*x22)


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
    q0 = _dd_div(_dd(Omega), (2.0, 0.0))
    q1 = _dd(Omega)
    x0 = 2*v0
    x1 = g*t_n
    x2 = -t_n
    x3 = _cos_phase(t, q1)
    x4 = _sin_phase(t, q0)**2
    k5 = -v0
    k7 = -x0
    k8 = 2*x1
    k9 = 1/(v0 + x1)
    return k9*(k5*x3*(np.select([np.less_equal(t + x2, 0),True], [0,1], default=np.nan)) + k7*x4*(np.select([np.less_equal(t + x2, 0),True], [0,1], default=np.nan)) + k8*x4 + v0*np.cos(Omega*(t + x2))*(np.select([np.less_equal(t + x2, 0),True], [0,1], default=np.nan)) + x0*x4 + x1*x3)


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
    x0 = Omega*v0
    x1 = -t_n
    x2 = Omega*g*t_n**2
    x3 = t_n*x0
    x4 = 2*x3
    x5 = _cos_phase(t, q0)
    x6 = _sin_phase(t, q1)**2
    k0 = -x0
    k3 = -v0
    k7 = 2*x2
    k10 = -x3
    k12 = -x4
    k13 = 1/(Omega*t_n*(g*t_n + v0))
    return k13*(k0*t + k10*x5*(np.select([np.less_equal(t + x1, 0),True], [0,1], default=np.nan)) + k12*x6*(np.select([np.less_equal(t + x1, 0),True], [0,1], default=np.nan)) + k3*np.sin(Omega*(t + x1))*(np.select([np.less_equal(t + x1, 0),True], [0,1], default=np.nan)) + k7*x6 + t*x0*(np.select([np.less_equal(t + x1, 0),True], [0,1], default=np.nan)) + v0*_sin_phase(t, q0) + x2*x5 + x4*x6)


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
    x0 = 72*v0
    x1 = Omega**3
    x2 = 12*v0
    x3 = x1*x2
    x4 = Omega*x0
    x5 = -t_n
    x6 = t_n**4
    x7 = g*x1*x6
    x8 = t_n*v0
    x9 = Omega*x8
    x10 = 96*x9
    x11 = t_n**2
    x12 = x11*x3
    x13 = 24*x1*x8
    x14 = _sin_phase(t, q0)
    x15 = t**3
    x16 = t**2
    x17 = _cos_phase(t, q0)
    x18 = _sin_phase(t, q1)**2
    k0 = -x0
    k1 = -x3
    k6 = -x7
    k7 = -x10
    k9 = -x4
    k10 = -x12
    k11 = -2*x7
    k14 = Omega**2*x11*x2
    k17 = -x13
    k22 = 24*x9
    k24 = 48*x9
    k27 = -1/(g*x1*x6)
    return k27*(k0*x14 + k1*x15 + k10*t + k11*x18 + k14*x14 + k17*x16*(np.select([np.less_equal(t + x5, 0),True], [0,1], default=np.nan)) + k22*np.cos(Omega*(t + x5))*(np.select([np.less_equal(t + x5, 0),True], [0,1], default=np.nan)) + k24*x17*(np.select([np.less_equal(t + x5, 0),True], [0,1], default=np.nan)) + k6*x17 + k7*x18 + k9*t*(np.select([np.less_equal(t + x5, 0),True], [0,1], default=np.nan)) + t*x12*(np.select([np.less_equal(t + x5, 0),True], [0,1], default=np.nan)) + t*x4 + x0*np.sin(Omega*(t + x5))*(np.select([np.less_equal(t + x5, 0),True], [0,1], default=np.nan)) + x10*x18*(np.select([np.less_equal(t + x5, 0),True], [0,1], default=np.nan)) + x13*x16 + x15*x3*(np.select([np.less_equal(t + x5, 0),True], [0,1], default=np.nan)))


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
    x0 = 7200*v0
    x1 = Omega*x0
    x2 = -t_n
    x3 = Omega**5
    x4 = v0*x3
    x5 = 60*x4
    x6 = Omega**3*v0
    x7 = 1200*x6
    x8 = t_n**6
    x9 = g*x3*x8
    x10 = 2160*t_n*x6
    x11 = t_n**2
    x12 = 1080*x11
    x13 = Omega**2*v0
    x14 = t_n**3
    x15 = x14*x6
    x16 = 240*x15
    x17 = 180*x4
    x18 = x11*x17
    x19 = x14*x5
    x20 = t_n*x17
    x21 = x12*x6
    x22 = Omega*t_n*v0
    x23 = 8640*x22
    x24 = _sin_phase(t, q0)
    x25 = t**3
    x26 = t**2
    x27 = t**4
    x28 = t**5
    x29 = _cos_phase(t, q0)
    x30 = _sin_phase(t, q1)**2
    k1 = -x1
    k4 = -x0
    k5 = -x5
    k8 = -x10
    k10 = -x7
    k11 = -x12*x13
    k12 = -x16
    k13 = -x18
    k14 = 2*x9
    k24 = -x23
    k26 = -4320*x22
    k29 = -2880*x22
    k31 = -x21
    k33 = -x20
    k35 = -x19
    k37 = 120*x15
    k44 = 360*x11*x13
    k47 = 1/(g*x3*x8)
    return k47*(k1*t + k10*x25*(np.select([np.less_equal(t + x2, 0),True], [0,1], default=np.nan)) + k11*x24 + k12*x30 + k13*x25 + k14*x30 + k24*x30*(np.select([np.less_equal(t + x2, 0),True], [0,1], default=np.nan)) + k26*x29*(np.select([np.less_equal(t + x2, 0),True], [0,1], default=np.nan)) + k29*np.cos(Omega*(t + x2))*(np.select([np.less_equal(t + x2, 0),True], [0,1], default=np.nan)) + k31*t*(np.select([np.less_equal(t + x2, 0),True], [0,1], default=np.nan)) + k33*x27*(np.select([np.less_equal(t + x2, 0),True], [0,1], default=np.nan)) + k35*x26*(np.select([np.less_equal(t + x2, 0),True], [0,1], default=np.nan)) + k37*x29*(np.select([np.less_equal(t + x2, 0),True], [0,1], default=np.nan)) + k4*np.sin(Omega*(t + x2))*(np.select([np.less_equal(t + x2, 0),True], [0,1], default=np.nan)) + k44*np.sin(Omega*(t + x2))*(np.select([np.less_equal(t + x2, 0),True], [0,1], default=np.nan)) + k5*x28 + k8*x26 + t*x1*(np.select([np.less_equal(t + x2, 0),True], [0,1], default=np.nan)) + t*x21 + x0*x24 + x10*x26*(np.select([np.less_equal(t + x2, 0),True], [0,1], default=np.nan)) + x16*x30*(np.select([np.less_equal(t + x2, 0),True], [0,1], default=np.nan)) + x18*x25*(np.select([np.less_equal(t + x2, 0),True], [0,1], default=np.nan)) + x19*x26 + x20*x27 + x23*x30 + x25*x7 + x28*x5*(np.select([np.less_equal(t + x2, 0),True], [0,1], default=np.nan)) + x29*x9)


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
    x0 = g*t_n**4
    x1 = tau_0*v0
    x2 = 12*x1
    k0 = -tau_0
    k1 = -x0
    k3 = -24*t_n*x1
    k4 = t_n**2*x2 + x0
    k5 = 1/(t_n**3*tau_0*v0)
    return k5*t*(k1*(np.select([np.less_equal(k0 + t, 0),True], [0,1], default=np.nan)) + k3*t + k4 + t**2*x2)


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
    x0 = g*t_n**6
    x1 = tau_0*v0
    x2 = 60*x1
    x3 = 180*x1
    k0 = -tau_0
    k3 = -t_n*x3
    k4 = -t_n**3*x2
    k5 = t_n**2*x3
    k6 = -x0
    k7 = -1/(t_n**5*tau_0*v0)
    return k7*t*(k3*t**3 + k4*t + k5*t**2 + k6 + t**4*x2 + x0*(np.select([np.less_equal(k0 + t, 0),True], [0,1], default=np.nan)))
