"""Numeric functions for derivation 'drum_drive'. Generated; do not edit.

Source: crane_sym.derivations.drum_drive (paper 004_f118c513e0426caf.txt:
Dynamic model of a drive with a driving drum).
Specialized to scene 'drum_drive_undamped' (Driving drum, worked example without dissipation: the state derivative of (12)): outputs state_derivative, state_jacobian; folded in: I1 = 13.0 kg*m^2, I2 = 3.0 kg*m^2, I3 = 50.0 kg*m^2, C1 = 20000.0 N*m/rad, C2 = 50000.0 N*m/rad, m3 = 800.0 kg, m_L = 2500.0 kg, C_y = 20000000.0 N/m, C_t = 50000.0 N/m, C_z = 50000.0 N/m, q = 2.4 kg/m, L = 600.0 m, r = 0.25 m, M0 = 440.0 N*m, F0 = 20000.0 N.
Switched off: damping (the Rayleigh dissipation Φ of (11): nu1 = 0, nu2 = 0, nu_y = 0, nu_z = 0, nu_t = 0).
Inputs left as arguments: W.
Equations: (12).
Printed by SymPy 1.14.0 with crane_sym 0.1.0; regenerate with `crane-sym generate --scene drum_drive_undamped --out <folder>`.

Functions and argument order:
    state_derivative(W, s1, s2, s3, s4, s5, s6, s7, s8, s9, s10) -> [SI]    eq (12)
    state_jacobian() -> [SI]    eq (12)
"""

import numpy as np

__all__ = ['state_derivative', 'state_jacobian']

SCENE_NAME = 'drum_drive_undamped'
SCENE_TITLE = 'Driving drum, worked example without dissipation: the state derivative of (12)'


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


def _matrix(shape, elements):
    """Row-major ``elements`` as an array of ``shape`` followed by the
    broadcast shape of the elements (a matrix per input point)."""
    flat = np.broadcast_arrays(*[np.asarray(e, dtype=float) for e in elements])
    return np.stack(flat).reshape(tuple(shape) + flat[0].shape)


def state_derivative(W, s1, s2, s3, s4, s5, s6, s7, s8, s9, s10):
    """Right-hand side d(state)/dt of (12) for scipy.integrate.solve_ivp; state (phi1, phi2, phi3, y, z, and their rates) = (s1, ..., s10). Specialized to scene 'drum_drive_undamped'. Eq (12).

    Parameters
    ----------
    W : array_like
        resistance of the loads to the motion of the run [N]; served from -1e11 to 1e11
    s1 : array_like
        state 1: φ1 [rad]; served from -2e6 to 2e6
    s2 : array_like
        state 2: φ2 [rad]; served from -2e6 to 2e6
    s3 : array_like
        state 3: φ3 [rad]; served from -2e6 to 2e6
    s4 : array_like
        state 4: y [m]; served from -2e6 to 2e6
    s5 : array_like
        state 5: z [m]; served from -2e6 to 2e6
    s6 : array_like
        state 6: dφ1/dt [rad/s]; served from -2e6 to 2e6
    s7 : array_like
        state 7: dφ2/dt [rad/s]; served from -2e6 to 2e6
    s8 : array_like
        state 8: dφ3/dt [rad/s]; served from -2e6 to 2e6
    s9 : array_like
        state 9: dy/dt [m/s]; served from -2e6 to 2e6
    s10 : array_like
        state 10: dz/dt [m/s]; served from -2e6 to 2e6

    Returns
    -------
    ndarray
        [SI], shape (10, 1) followed by the broadcast shape of the arguments.
    """
    W   = _checked('W', W, 'real', 'resistance of the loads to the motion of the run, N', (-1e11, 1e11))
    s1  = _checked('s1', s1, 'real', 'state 1: φ1, rad', (-2e6, 2e6))
    s2  = _checked('s2', s2, 'real', 'state 2: φ2, rad', (-2e6, 2e6))
    s3  = _checked('s3', s3, 'real', 'state 3: φ3, rad', (-2e6, 2e6))
    s4  = _checked('s4', s4, 'real', 'state 4: y, m', (-2e6, 2e6))
    s5  = _checked('s5', s5, 'real', 'state 5: z, m', (-2e6, 2e6))
    s6  = _checked('s6', s6, 'real', 'state 6: dφ1/dt, rad/s', (-2e6, 2e6))
    s7  = _checked('s7', s7, 'real', 'state 7: dφ2/dt, rad/s', (-2e6, 2e6))
    s8  = _checked('s8', s8, 'real', 'state 8: dφ3/dt, rad/s', (-2e6, 2e6))
    s9  = _checked('s9', s9, 'real', 'state 9: dy/dt, m/s', (-2e6, 2e6))
    s10 = _checked('s10', s10, 'real', 'state 10: dz/dt, m/s', (-2e6, 2e6))
    shape = _broadcast(W=W, s1=s1, s2=s2, s3=s3, s4=s4, s5=s5, s6=s6, s7=s7, s8=s8, s9=s9, s10=s10)
    return _matrix((10, 1), [s6, s7, s8, s9, s10, -20000/13*s1 + (20000/13)*s2 + 440/13, (20000/3)*s1 - 70000/3*s2 + (50000/3)*s3, (1216944576219100180400838803456/3713709198428620747889430541788775)*W + (70177137228634778946281549070336000/148548367937144829915577221671551)*s2 - 80166223958433226494967581507584000/148548367937144829915577221671551*s3 + (39956346919193790194744129748992000/148548367937144829915577221671551)*s5, 225179981368524800/9907919180215091 - 113152940637683712000/9907919180215091*s4, -5577662641004209253995503419392/18568545992143103739447152708943875*W - 2433889152438200360801677606912000/148548367937144829915577221671551*s2 + (3853657824693817256700987991654400/148548367937144829915577221671551)*s3 - 5679074689022467583597241538969600/148548367937144829915577221671551*s5])


def state_jacobian():
    """Jacobian of state_derivative (constant: the model is linear). Specialized to scene 'drum_drive_undamped'. Eq (12).

    Parameters
    ----------


    Returns
    -------
    ndarray
        [SI], shape (10, 10) followed by the broadcast shape of the arguments.
    """
    shape = _broadcast()
    return _matrix((10, 10), [0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, -20000/13, 20000/13, 0, 0, 0, 0, 0, 0, 0, 0, 20000/3, -70000/3, 50000/3, 0, 0, 0, 0, 0, 0, 0, 0, 70177137228634778946281549070336000/148548367937144829915577221671551, -80166223958433226494967581507584000/148548367937144829915577221671551, 0, 39956346919193790194744129748992000/148548367937144829915577221671551, 0, 0, 0, 0, 0, 0, 0, 0, -113152940637683712000/9907919180215091, 0, 0, 0, 0, 0, 0, 0, -2433889152438200360801677606912000/148548367937144829915577221671551, 3853657824693817256700987991654400/148548367937144829915577221671551, 0, -5679074689022467583597241538969600/148548367937144829915577221671551, 0, 0, 0, 0, 0])
