"""Numeric functions for derivation 'travel_braking'. Generated; do not edit.

Source: crane_sym.derivations.travel_braking (paper 000_4ef6efc8a81a3b06.txt:
Dynamic loads when the travel mechanism of an overhead crane brakes).
Specialized to scene 'overhead_crane_50t' (50 t overhead crane: braking the bridge travel with full load): outputs elastic_force, velocity_m1, velocity_m2; folded in: m1 = 4400.0 kg, m2 = 110000.0 kg, c = 3000000.0 N/m, P_t = 24000.0 N, W = 11000.0 N, v0 = 1.3333333333333333 m/s.
Equations: (1), (2), (13), (14).
Printed by SymPy 1.14.0 with crane_sym 0.1.0; regenerate with `crane-sym generate`.

Functions and argument order:
    elastic_force(t) -> [N]    eq (14)
    velocity_m1(t) -> [m/s]    eq (1), (13)
    velocity_m2(t) -> [m/s]    eq (2), (13)
"""

import numpy as np

__all__ = ['elastic_force', 'velocity_m1', 'velocity_m2']


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


def elastic_force(t):
    """Force F(t) in the elastic link. Specialized to scene 'overhead_crane_50t'. Eq (14).

    Parameters
    ----------
    t : array_like
        time since the brake was applied [s], >= 0

    Returns
    -------
    ndarray
        [N], broadcast over the arguments.
    """
    t = _checked('t', t, 'nonnegative', 'time since the brake was applied, s')
    q0 = (13.314380468978918, 2.0725079895853809e-16)
    return (589000/13)*_sin_phase(t, q0)**2


def velocity_m1(t):
    """Velocity of the motor-side mass m1. Specialized to scene 'overhead_crane_50t'. Eq (1), (13).

    Parameters
    ----------
    t : array_like
        time since the brake was applied [s], >= 0

    Returns
    -------
    ndarray
        [m/s], broadcast over the arguments.
    """
    t = _checked('t', t, 'nonnegative', 'time since the brake was applied, s')
    q0 = (26.628760937957836, 4.1450159791707617e-16)
    return -175/572*t - 0.1933473889602708*_sin_phase(t, q0) + 6004799503160661/4503599627370496


def velocity_m2(t):
    """Velocity of the crane-side mass m2. Specialized to scene 'overhead_crane_50t'. Eq (2), (13).

    Parameters
    ----------
    t : array_like
        time since the brake was applied [s], >= 0

    Returns
    -------
    ndarray
        [m/s], broadcast over the arguments.
    """
    t = _checked('t', t, 'nonnegative', 'time since the brake was applied, s')
    q0 = (26.628760937957836, 4.1450159791707617e-16)
    return -175/572*t + 0.007733895558410831*_sin_phase(t, q0) + 6004799503160661/4503599627370496
