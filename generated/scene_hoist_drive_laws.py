"""Numeric functions for derivation 'hoist_startup'. Generated; do not edit.

Source: crane_sym.derivations.hoist_startup (paper 002_f8509f3826f601de.txt:
Duhamel's integral for the start-up of a crane hoist: rope loads and dynamic factors).
Specialized to scene 'hoist_drive_laws' (Paper 002: rope dynamic coefficient for the drive laws a_1 ... a_4): outputs dynamic_coefficient_pickup_a1, dynamic_coefficient_pickup_a2, dynamic_coefficient_pickup_a3, dynamic_coefficient_pickup_a4, dynamic_coefficient_from_weight_a1, dynamic_coefficient_from_weight_a2, dynamic_coefficient_from_weight_a3, dynamic_coefficient_from_weight_a4, optimal_coefficient_from_weight_a1, optimal_coefficient_from_weight_a2, optimal_coefficient_from_weight_a3, optimal_coefficient_from_weight_a4; folded in: m1 = 2000.0 kg, m2 = 8000.0 kg, C = 1000000.0 N/m, g = 9.81 m/s^2, v0 = 0.25 m/s, t_n = 1.0 s, Omega = 25.0 rad/s, tau_0 = 0.31392 s.
Equations: (26), (27), (28), (30), (63), (65).
Printed by SymPy 1.14.0 with crane_sym 0.1.0; regenerate with `crane-sym generate`.

Functions and argument order:
    dynamic_coefficient_pickup_a1(t) -> [1]    eq (26), (28), (30)
    dynamic_coefficient_pickup_a2(t) -> [1]    eq (26), (28), (30)
    dynamic_coefficient_pickup_a3(t) -> [1]    eq (26), (28), (30)
    dynamic_coefficient_pickup_a4(t) -> [1]    eq (26), (28), (30)
    dynamic_coefficient_from_weight_a1(t) -> [1]    eq (27), (28), (30)
    dynamic_coefficient_from_weight_a2(t) -> [1]    eq (27), (28), (30)
    dynamic_coefficient_from_weight_a3(t) -> [1]    eq (27), (28), (30)
    dynamic_coefficient_from_weight_a4(t) -> [1]    eq (27), (28), (30)
    optimal_coefficient_from_weight_a1(t) -> [1]    eq (63), (65)
    optimal_coefficient_from_weight_a2(t) -> [1]    eq (63), (65)
    optimal_coefficient_from_weight_a3(t) -> [1]    eq (63), (65)
    optimal_coefficient_from_weight_a4(t) -> [1]    eq (63), (65)
"""

import numpy as np

__all__ = ['dynamic_coefficient_pickup_a1', 'dynamic_coefficient_pickup_a2', 'dynamic_coefficient_pickup_a3', 'dynamic_coefficient_pickup_a4', 'dynamic_coefficient_from_weight_a1', 'dynamic_coefficient_from_weight_a2', 'dynamic_coefficient_from_weight_a3', 'dynamic_coefficient_from_weight_a4', 'optimal_coefficient_from_weight_a1', 'optimal_coefficient_from_weight_a2', 'optimal_coefficient_from_weight_a3', 'optimal_coefficient_from_weight_a4']


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


def _two_product(a, b):
    """a*b as an unevaluated sum p + e of two doubles, exactly (Dekker)."""
    p = a * b
    a_hi = a * 134217729.0
    a_hi = a_hi - (a_hi - a)
    b_hi = b * 134217729.0
    b_hi = b_hi - (b_hi - b)
    a_lo, b_lo = a - a_hi, b - b_hi
    return p, ((a_hi * b_hi - p) + a_hi * b_lo + a_lo * b_hi) + a_lo * b_lo


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


def dynamic_coefficient_pickup_a1(t):
    """K_din^(1)(t) for the drive law a_1 of (30), lifting with pick-up (tau_0 from pickup_contact_time); Omega from natural_frequency. Specialized to scene 'hoist_drive_laws'. Eq (26), (28), (30).

    Parameters
    ----------
    t : array_like
        time from the start of the drive [s], >= 0

    Returns
    -------
    ndarray
        [1], broadcast over the arguments.
    """
    t = _checked('t', t, 'nonnegative', 'time from the start of the drive, s')
    q0 = (12.5, 0.0)
    q1 = (25.0, 0.0)
    x0 = (np.select([np.less_equal(t, 706884997512073/2251799813685248),True], [0,1], default=np.nan))
    x1 = _sin_phase(t, q0)**2
    x2 = 25*t
    x3 = _sin_remainder(x2, 1)
    x4 = (np.select([np.less_equal(t, 1),True], [0,1], default=np.nan))
    return (3108913097059732764796651569152/100703913039958856128874132496575)*x0*x3 - 0.0870571492761878*x0*np.sin((25/2)*t - 17672124937801825/9007199254740992)**2 + 0.2858106195874641*x0 - 351843720888320/5698460903507231*x1*x4 + 2*x1 - 3108913097059732764796651569152/100703913039958856128874132496575*x3 + (175921860444160/5698460903507231)*x4*np.cos(x2 - 25) - 175921860444160/5698460903507231*x4*_cos_phase(t, q1)


def dynamic_coefficient_pickup_a2(t):
    """K_din^(1)(t) for the drive law a_2 of (30), lifting with pick-up (tau_0 from pickup_contact_time); Omega from natural_frequency. Specialized to scene 'hoist_drive_laws'. Eq (26), (28), (30).

    Parameters
    ----------
    t : array_like
        time from the start of the drive [s], >= 0

    Returns
    -------
    ndarray
        [1], broadcast over the arguments.
    """
    t = _checked('t', t, 'nonnegative', 'time from the start of the drive, s')
    q0 = (12.5, 0.0)
    q1 = (25.0, 0.0)
    x0 = (np.select([np.less_equal(t, 706884997512073/2251799813685248),True], [0,1], default=np.nan))
    x1 = _sin_phase(t, q0)**2
    x2 = 25*t
    x3 = _sin_remainder(x2, 1)
    x4 = (np.select([np.less_equal(t, 1),True], [0,1], default=np.nan))
    x5 = (35184372088832/28492304517536155)*x4
    return (3108913097059732764796651569152/100703913039958856128874132496575)*x0*x3 - 0.0870571492761878*x0*np.sin((25/2)*t - 17672124937801825/9007199254740992)**2 + 0.2858106195874641*x0 - 351843720888320/5698460903507231*x1*x4 + 2*x1 - x3*x5 - 2984556573177343469685909225472/100703913039958856128874132496575*x3 - 175921860444160/5698460903507231*x4*_cos_phase(t, q1) + (35184372088832/28492304517536155)*x4*_sin_phase(t, q1) - x5*np.sin(x2 - 25)


def dynamic_coefficient_pickup_a3(t):
    """K_din^(1)(t) for the drive law a_3 of (30), lifting with pick-up (tau_0 from pickup_contact_time); Omega from natural_frequency. Specialized to scene 'hoist_drive_laws'. Eq (26), (28), (30).

    Parameters
    ----------
    t : array_like
        time from the start of the drive [s], >= 0

    Returns
    -------
    ndarray
        [1], broadcast over the arguments.
    """
    t = _checked('t', t, 'nonnegative', 'time from the start of the drive, s')
    q0 = (12.5, 0.0)
    q1 = (25.0, 0.0)
    x0 = (np.select([np.less_equal(t, 706884997512073/2251799813685248),True], [0,1], default=np.nan))
    x1 = 25*t
    x2 = _cos_remainder(x1, 2)
    x3 = _sin_remainder(x1, 1)
    x4 = _sin_remainder(x1, 2)
    x5 = (np.select([np.less_equal(t, 1),True], [0,1], default=np.nan))
    x6 = x1 - 25
    return (562949953421312/17672124937801825)*x0*x3 + 0.04491518825424113*x0*np.cos(x1 - 17672124937801825/4503599627370496) + (1/4)*x0 + (1688849860263936/690317380382883875)*x2*x5 - 1688849860263936/690317380382883875*x2 + (422212465065984/27612695215315355)*x3*x5 - 4601191383648404306125559693312/97594999942899123751105573904575*x3 - 2533274790395904/17257934509572096875*x4*x5 + (2533274790395904/17257934509572096875)*x4 - 2533274790395904/17257934509572096875*x5*np.sin(x6) - 844424930131968/690317380382883875*x5*np.cos(x6) - 1688849860263936/690317380382883875*x5*_cos_phase(t, q1) - 261349515875844096/17257934509572096875*x5*_sin_phase(t, q1) + 2*_sin_phase(t, q0)**2


def dynamic_coefficient_pickup_a4(t):
    """K_din^(1)(t) for the drive law a_4 of (30), lifting with pick-up (tau_0 from pickup_contact_time); Omega from natural_frequency. Specialized to scene 'hoist_drive_laws'. Eq (26), (28), (30).

    Parameters
    ----------
    t : array_like
        time from the start of the drive [s], >= 0

    Returns
    -------
    ndarray
        [1], broadcast over the arguments.
    """
    t = _checked('t', t, 'nonnegative', 'time from the start of the drive, s')
    q0 = (12.5, 0.0)
    q1 = (25.0, 0.0)
    x0 = (np.select([np.less_equal(t, 706884997512073/2251799813685248),True], [0,1], default=np.nan))
    x1 = 25*t
    x2 = (844424930131968/138063476076576775)*_cos_remainder(x1, 2)
    x3 = (30399297484750848/86289672547860484375)*_cos_remainder(x1, 3)
    x4 = (562949953421312/17672124937801825)*_sin_remainder(x1, 1)
    x5 = (7599824371187712/3451586901914419375)*_sin_remainder(x1, 2)
    x6 = (10133099161583616/431448362739302421875)*_sin_remainder(x1, 3)
    x7 = (np.select([np.less_equal(t, 1),True], [0,1], default=np.nan))
    x8 = x1 - 25
    return x0*x4 + 0.04491518825424113*x0*np.cos(x1 - 17672124937801825/4503599627370496) + (1/4)*x0 - x2*x7 + x2 + x3*x7 - x3 - x4 + x5*x7 - x5 - x6*x7 + x6 + (306526249637904384/431448362739302421875)*x7*np.sin(x8) - 20266198323167232/86289672547860484375*x7*np.cos(x8) + (497366283847729152/86289672547860484375)*x7*_cos_phase(t, q1) - 939844947236880384/431448362739302421875*x7*_sin_phase(t, q1) + 2*_sin_phase(t, q0)**2


def dynamic_coefficient_from_weight_a1(t):
    """K_din^(2)(t) for the drive law a_1 of (30), lifting from weight; Omega from natural_frequency. Specialized to scene 'hoist_drive_laws'. Eq (27), (28), (30).

    Parameters
    ----------
    t : array_like
        time from the start of the drive [s], >= 0

    Returns
    -------
    ndarray
        [1], broadcast over the arguments.
    """
    t = _checked('t', t, 'nonnegative', 'time from the start of the drive, s')
    q0 = (12.5, 0.0)
    x0 = (np.select([np.less_equal(t, 1),True], [0,1], default=np.nan))
    return -0.0032963169657654417*x0*np.sin(25*t - 25/2) + (281474976710656/5663276531418399)*(1 - x0)*_sin_phase(t, q0)**2 + 5522539043063071/5663276531418399


def dynamic_coefficient_from_weight_a2(t):
    """K_din^(2)(t) for the drive law a_2 of (30), lifting from weight; Omega from natural_frequency. Specialized to scene 'hoist_drive_laws'. Eq (27), (28), (30).

    Parameters
    ----------
    t : array_like
        time from the start of the drive [s], >= 0

    Returns
    -------
    ndarray
        [1], broadcast over the arguments.
    """
    t = _checked('t', t, 'nonnegative', 'time from the start of the drive, s')
    q0 = (12.5, 0.0)
    x0 = (np.select([np.less_equal(t, 1),True], [0,1], default=np.nan))
    x1 = 25*t
    x2 = x1 - 25/2
    x3 = 1 - x0
    return -140737488355328/141581913285459975*x0*(0.13264379470240137*np.cos(x2) + 25*np.cos(x1 - 25)) - 0.0032963169657654417*x0*np.sin(x2) + (281474976710656/5663276531418399)*x3*_sin_phase(t, q0)**2 + (140737488355328/141581913285459975)*x3*_sin_remainder(x1, 1) + 5522539043063071/5663276531418399


def dynamic_coefficient_from_weight_a3(t):
    """K_din^(2)(t) for the drive law a_3 of (30), lifting from weight; Omega from natural_frequency. Specialized to scene 'hoist_drive_laws'. Eq (27), (28), (30).

    Parameters
    ----------
    t : array_like
        time from the start of the drive [s], >= 0

    Returns
    -------
    ndarray
        [1], broadcast over the arguments.
    """
    t = _checked('t', t, 'nonnegative', 'time from the start of the drive, s')
    q0 = (25.0, 0.0)
    x0 = 25*t
    x1 = (np.select([np.less_equal(t, 1),True], [0,1], default=np.nan))
    x2 = 1 - x1
    x3 = x0 - 25
    x4 = np.cos(x3)
    x5 = np.sin(x3)
    return (1688849860263936/138063476076576775)*x1*(25*x4 + 0.13264379470240137*np.cos(x0 - 25/2)) - 3377699720527872/3451586901914419375*x1*(623*x4 + 50*x5 + 2*_cos_phase(t, q0)) + (1688849860263936/86289672547860484375)*x1*(15475*x4 + 1869*x5 + 6*_sin_phase(t, q0)) - 6755399441055744/3451586901914419375*x2*_cos_remainder(x0, 2) - 1688849860263936/138063476076576775*x2*_sin_remainder(x0, 1) + (10133099161583616/86289672547860484375)*x2*_sin_remainder(x0, 2) + 1


def dynamic_coefficient_from_weight_a4(t):
    """K_din^(2)(t) for the drive law a_4 of (30), lifting from weight; Omega from natural_frequency. Specialized to scene 'hoist_drive_laws'. Eq (27), (28), (30).

    Parameters
    ----------
    t : array_like
        time from the start of the drive [s], >= 0

    Returns
    -------
    ndarray
        [1], broadcast over the arguments.
    """
    t = _checked('t', t, 'nonnegative', 'time from the start of the drive, s')
    q0 = (25.0, 0.0)
    x0 = 25*t
    x1 = (np.select([np.less_equal(t, 1),True], [0,1], default=np.nan))
    x2 = 1 - x1
    x3 = _sin_phase(t, q0)
    x4 = x0 - 25
    x5 = np.sin(x4)
    x6 = np.cos(x4)
    x7 = _cos_phase(t, q0)
    return -5066549580791808/17257934509572096875*x1*(6*x3 + 1869*x5 + 15475*x6) + (1688849860263936/2157241813696512109375)*x1*(24*x3 - 383149*x5 - 1891225*x6) - 5066549580791808/431448362739302421875*x1*(-61900*x5 - 383149*x6 + 24*x7) + (1688849860263936/690317380382883875)*x1*(50*x5 + 623*x6 + 2*x7) + (3377699720527872/690317380382883875)*x2*_cos_remainder(x0, 2) - 121597189939003392/431448362739302421875*x2*_cos_remainder(x0, 3) - 30399297484750848/17257934509572096875*x2*_sin_remainder(x0, 2) + (40532396646334464/2157241813696512109375)*x2*_sin_remainder(x0, 3) + 1


def optimal_coefficient_from_weight_a1(t):
    """k~_din1^(opt)(t) from weight, 0 <= t <= t_n. Specialized to scene 'hoist_drive_laws'. Eq (63), (65).

    Parameters
    ----------
    t : array_like
        time from the start of the drive [s], >= 0

    Returns
    -------
    ndarray
        [1], broadcast over the arguments.
    """
    t = _checked('t', t, 'nonnegative', 'time from the start of the drive, s')
    return 1


def optimal_coefficient_from_weight_a2(t):
    """k~_din2^(opt)(t) from weight, 0 <= t <= t_n. Specialized to scene 'hoist_drive_laws'. Eq (63), (65).

    Parameters
    ----------
    t : array_like
        time from the start of the drive [s], >= 0

    Returns
    -------
    ndarray
        [1], broadcast over the arguments.
    """
    t = _checked('t', t, 'nonnegative', 'time from the start of the drive, s')
    return 1 - t


def optimal_coefficient_from_weight_a3(t):
    """k~_din3^(opt)(t) from weight, 0 <= t <= t_n. Specialized to scene 'hoist_drive_laws'. Eq (63), (65).

    Parameters
    ----------
    t : array_like
        time from the start of the drive [s], >= 0

    Returns
    -------
    ndarray
        [1], broadcast over the arguments.
    """
    t = _checked('t', t, 'nonnegative', 'time from the start of the drive, s')
    return 12*t*(t - 1)**2


def optimal_coefficient_from_weight_a4(t):
    """k~_din4^(opt)(t) from weight, 0 <= t <= t_n. Specialized to scene 'hoist_drive_laws'. Eq (63), (65).

    Parameters
    ----------
    t : array_like
        time from the start of the drive [s], >= 0

    Returns
    -------
    ndarray
        [1], broadcast over the arguments.
    """
    t = _checked('t', t, 'nonnegative', 'time from the start of the drive, s')
    return -60*t**2*(t - 1)**3
