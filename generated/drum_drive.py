"""Numeric functions for derivation 'drum_drive'. Generated; do not edit.

Source: crane_sym.derivations.drum_drive (paper 004_f118c513e0426caf.txt:
Dynamic model of a drive with a driving drum).
Equations: (7), (10), (12), (13), (18), (19), (21).
Printed by SymPy 1.14.0 with crane_sym 0.1.0; regenerate with `crane-sym generate`.

Functions and argument order:
    branch_effective_mass(q, L) -> [kg]    eq (7)
    drive_chain_frequency_1(I1, I2, I3, C1, C2) -> [rad/s]    eq (13)
    drive_chain_frequency_2(I1, I2, I3, C1, C2) -> [rad/s]    eq (13)
    running_tight_force(M0, D, F0, C_t, C_z, C_y) -> [N]    eq (12)
    running_slack_force(M0, D, F0, C_t, C_z, C_y) -> [N]    eq (12)
    running_drum_shaft_deflection(M0, D, F0, C_t, C_z, C_y) -> [m]    eq (12)
    drum_torque(F1, F2, D) -> [N*m]    eq (18)
    traction_margin(F1, F2, mu, alpha) -> [1]    eq (19)
    least_mu_alpha(F1, F2) -> [1]    eq (19)
    pulsating_force(t, F1_t, F2_t, F3_t, F4_t, K1, K2, K3, K4, t_3) -> [N]    eq (21)
    state_derivative(I1, I2, I3, C1, C2, nu1, nu2, m3, m_L, C_y, nu_y, C_t, C_z, nu_z, nu_t, q, L, r, M0, F0, W, s1, s2, s3, s4, s5, s6, s7, s8, s9, s10) -> [SI]    eq (12)
    state_jacobian(I1, I2, I3, C1, C2, nu1, nu2, m3, m_L, C_y, nu_y, C_t, C_z, nu_z, nu_t, q, L, r) -> [SI]    eq (12)
    mass_matrix(I1, I2, I3, m3, m_L, q, L, r) -> [SI]    eq (12)
    damping_matrix(nu1, nu2, nu_y, nu_z, nu_t, r) -> [SI]    eq (12)
    stiffness_matrix(C1, C2, C_y, C_t, C_z, r) -> [SI]    eq (12)
    generalized_forces(M0, F0, W) -> [SI]    eq (10), (12)
"""

import math

import numpy as np

__all__ = ['branch_effective_mass', 'drive_chain_frequency_1', 'drive_chain_frequency_2', 'running_tight_force', 'running_slack_force', 'running_drum_shaft_deflection', 'drum_torque', 'traction_margin', 'least_mu_alpha', 'pulsating_force', 'state_derivative', 'state_jacobian', 'mass_matrix', 'damping_matrix', 'stiffness_matrix', 'generalized_forces']


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


def _matrix(shape, elements):
    """Row-major ``elements`` as an array of ``shape`` followed by the
    broadcast shape of the elements (a matrix per input point)."""
    flat = np.broadcast_arrays(*[np.asarray(e, dtype=float) for e in elements])
    return np.stack(flat).reshape(tuple(shape) + flat[0].shape)


def _cube(x):
    """x**3 as two products: NumPy's ``x**3`` calls ``pow`` per point."""
    return x * (x * x)


def _spans(out, shape, *values, size=16384):
    """(a piece of ``out``, ``values`` on it) for each block of at most
    ``size`` points of the flat ``out``, when ``out`` and every array among
    ``values`` are C-contiguous of the full ``shape``: an expression's
    temporaries then stay block-sized and in the cache, so a call needs no
    full-size work array. Else one piece, the whole (broadcasting as is)."""
    full = tuple(shape)
    flat = out.flags.c_contiguous and all(
        np.ndim(v) == 0 or (v.shape == full and v.flags.c_contiguous) for v in values)
    if not flat or out.size <= size:
        return [(out, values)]
    o = out.reshape(-1)
    arrays = [v if np.ndim(v) == 0 else v.reshape(-1) for v in values]
    return [(o[i:i + size], tuple(v if np.ndim(v) == 0 else v[i:i + size] for v in arrays))
            for i in range(0, o.size, size)]


def branch_effective_mass(q, L, *, out=None):
    """Effective mass q*L/3 of a span moved at one point (linear speed (6)). Eq (7).

    Parameters
    ----------
    q : array_like
        mass of one metre of the traction element [kg/m], > 0; served from 5e-7 to 2e7
    L : array_like
        length of a branch (of the span in (7)) [m], > 0; served from 1e-5 to 3e9
    out : ndarray, optional
        float64 array of the broadcast shape; the result is written into it and returned.

    Returns
    -------
    ndarray
        [kg], broadcast over the arguments.
    """
    if (out is None
            and (type(q) in (float, int) or type(q) is np.float64)
            and (type(L) in (float, int) or type(L) is np.float64)):
        if (5e-7 <= q <= 2e7 and 1e-5 <= L <= 3e9):
            try:    # a failed check or a math error: the array path decides
                return np.float64((1/3)*L*q)
            except (ArithmeticError, ValueError):
                pass
    q = _checked('q', q, 'positive', 'mass of one metre of the traction element, kg/m', (5e-7, 2e7))
    L = _checked('L', L, 'positive', 'length of a branch (of the span in (7)), m', (1e-5, 3e9))
    shape = _broadcast(q=q, L=L)
    return _into(out, shape, (1/3)*L*q)


def drive_chain_frequency_1(I1, I2, I3, C1, C2, *, out=None):
    """Lower elastic natural frequency of the free-free chain I1-C1-I2-C2-I3. Eq (13).

    Parameters
    ----------
    I1 : array_like
        moment of inertia of the motor rotor (reduced to the drum shaft) [kg*m^2], > 0; served from 1e-8 to 1e8
    I2 : array_like
        moment of inertia of the intermediate mass (gearbox, couplings; reduced) [kg*m^2], > 0; served from 1e-8 to 1e12
    I3 : array_like
        moment of inertia of the driving drum [kg*m^2], > 0; served from 1e-8 to 5e8
    C1 : array_like
        torsional stiffness, motor to intermediate mass [N*m/rad], > 0; served from 1e-8 to 1e12
    C2 : array_like
        torsional stiffness, intermediate mass to drum [N*m/rad], > 0; served from 1e-19 to 1e19
    out : ndarray, optional
        float64 array of the broadcast shape; the result is written into it and returned.

    Returns
    -------
    ndarray
        [rad/s], broadcast over the arguments.
    """
    if (out is None
            and (type(I1) in (float, int) or type(I1) is np.float64)
            and (type(I2) in (float, int) or type(I2) is np.float64)
            and (type(I3) in (float, int) or type(I3) is np.float64)
            and (type(C1) in (float, int) or type(C1) is np.float64)
            and (type(C2) in (float, int) or type(C2) is np.float64)):
        if (1e-8 <= I1 <= 1e8 and 1e-8 <= I2 <= 1e12 and 1e-8 <= I3 <= 5e8 and 1e-8 <= C1 <= 1e12
                and 1e-19 <= C2 <= 1e19):
            try:    # a failed check or a math error: the array path decides
                x0 = I1 + I2
                x1 = C1*x0/I1
                x2 = C2*(I2 + I3)/I3
                return np.float64(1.4142135623730951*math.sqrt(C1)*math.sqrt(C2)*math.sqrt(I3 + x0)/(math.sqrt(I1)*math.sqrt(I3)*math.sqrt(x1 + x2 + math.sqrt(4*C1*C2 + (x1 - x2)**2))))
            except (ArithmeticError, ValueError):
                pass
    I1 = _checked('I1', I1, 'positive', 'moment of inertia of the motor rotor (reduced to the drum shaft), kg*m^2', (1e-8, 1e8))
    I2 = _checked('I2', I2, 'positive', 'moment of inertia of the intermediate mass (gearbox, couplings; reduced), kg*m^2', (1e-8, 1e12))
    I3 = _checked('I3', I3, 'positive', 'moment of inertia of the driving drum, kg*m^2', (1e-8, 5e8))
    C1 = _checked('C1', C1, 'positive', 'torsional stiffness, motor to intermediate mass, N*m/rad', (1e-8, 1e12))
    C2 = _checked('C2', C2, 'positive', 'torsional stiffness, intermediate mass to drum, N*m/rad', (1e-19, 1e19))
    shape = _broadcast(I1=I1, I2=I2, I3=I3, C1=C1, C2=C2)
    x0 = I1 + I2
    x1 = C1*x0/I1
    x2 = C2*(I2 + I3)/I3
    return _into(out, shape, 1.4142135623730951*np.sqrt(C1)*np.sqrt(C2)*np.sqrt(I3 + x0)/(np.sqrt(I1)*np.sqrt(I3)*np.sqrt(x1 + x2 + np.sqrt(4*C1*C2 + (x1 - x2)**2))))


def drive_chain_frequency_2(I1, I2, I3, C1, C2, *, out=None):
    """Higher elastic natural frequency of the free-free chain I1-C1-I2-C2-I3. Eq (13).

    Parameters
    ----------
    I1 : array_like
        moment of inertia of the motor rotor (reduced to the drum shaft) [kg*m^2], > 0; served from 1e-8 to 1e8
    I2 : array_like
        moment of inertia of the intermediate mass (gearbox, couplings; reduced) [kg*m^2], > 0; served from 1e-8 to 1e12
    I3 : array_like
        moment of inertia of the driving drum [kg*m^2], > 0; served from 1e-8 to 5e8
    C1 : array_like
        torsional stiffness, motor to intermediate mass [N*m/rad], > 0; served from 1e-8 to 1e12
    C2 : array_like
        torsional stiffness, intermediate mass to drum [N*m/rad], > 0; served from 1e-19 to 1e19
    out : ndarray, optional
        float64 array of the broadcast shape; the result is written into it and returned.

    Returns
    -------
    ndarray
        [rad/s], broadcast over the arguments.
    """
    if (out is None
            and (type(I1) in (float, int) or type(I1) is np.float64)
            and (type(I2) in (float, int) or type(I2) is np.float64)
            and (type(I3) in (float, int) or type(I3) is np.float64)
            and (type(C1) in (float, int) or type(C1) is np.float64)
            and (type(C2) in (float, int) or type(C2) is np.float64)):
        if (1e-8 <= I1 <= 1e8 and 1e-8 <= I2 <= 1e12 and 1e-8 <= I3 <= 5e8 and 1e-8 <= C1 <= 1e12
                and 1e-19 <= C2 <= 1e19):
            try:    # a failed check or a math error: the array path decides
                x0 = C1*(I1 + I2)/I1
                x1 = C2*(I2 + I3)/I3
                return np.float64(0.7071067811865476*math.sqrt(x0 + x1 + math.sqrt(4*C1*C2 + (x0 - x1)**2))/math.sqrt(I2))
            except (ArithmeticError, ValueError):
                pass
    I1 = _checked('I1', I1, 'positive', 'moment of inertia of the motor rotor (reduced to the drum shaft), kg*m^2', (1e-8, 1e8))
    I2 = _checked('I2', I2, 'positive', 'moment of inertia of the intermediate mass (gearbox, couplings; reduced), kg*m^2', (1e-8, 1e12))
    I3 = _checked('I3', I3, 'positive', 'moment of inertia of the driving drum, kg*m^2', (1e-8, 5e8))
    C1 = _checked('C1', C1, 'positive', 'torsional stiffness, motor to intermediate mass, N*m/rad', (1e-8, 1e12))
    C2 = _checked('C2', C2, 'positive', 'torsional stiffness, intermediate mass to drum, N*m/rad', (1e-19, 1e19))
    shape = _broadcast(I1=I1, I2=I2, I3=I3, C1=C1, C2=C2)
    x0 = C1*(I1 + I2)/I1
    x1 = C2*(I2 + I3)/I3
    return _into(out, shape, 0.7071067811865476*np.sqrt(x0 + x1 + np.sqrt(4*C1*C2 + (x0 - x1)**2))/np.sqrt(I2))


def running_tight_force(M0, D, F0, C_t, C_z, C_y, *, out=None):
    """Tight-branch force F1 in steady running. Eq (12).

    Parameters
    ----------
    M0 : array_like
        driving torque of the motor, reduced to the drum shaft [N*m], > 0; served from 1e-5 to 1e11
    D : array_like
        diameter of the driving drum, D = 2r [m], > 0; served from 2e-7 to 4e6
    F0 : array_like
        pretension of both branches at rest [N], > 0; served from 0.001 to 1e12
    C_t : array_like
        longitudinal stiffness of the tight (incoming) branch [N/m], > 0; served from 0.001 to 1e13
    C_z : array_like
        longitudinal stiffness of the slack (outgoing) branch [N/m], > 0; served from 0.001 to 1e13
    C_y : array_like
        bending stiffness of the drum shaft at the drum [N/m], > 0; served from 0.001 to 1e14
    out : ndarray, optional
        float64 array of the broadcast shape; the result is written into it and returned.

    Returns
    -------
    ndarray
        [N], broadcast over the arguments.
    """
    if (out is None
            and (type(M0) in (float, int) or type(M0) is np.float64)
            and (type(D) in (float, int) or type(D) is np.float64)
            and (type(F0) in (float, int) or type(F0) is np.float64)
            and (type(C_t) in (float, int) or type(C_t) is np.float64)
            and (type(C_z) in (float, int) or type(C_z) is np.float64)
            and (type(C_y) in (float, int) or type(C_y) is np.float64)):
        if (1e-5 <= M0 <= 1e11 and 2e-7 <= D <= 4e6 and 0.001 <= F0 <= 1e12
                and 0.001 <= C_t <= 1e13 and 0.001 <= C_z <= 1e13 and 0.001 <= C_y <= 1e14):
            try:    # a failed check or a math error: the array path decides
                x0 = C_t*C_y
                x1 = C_y*C_z
                x2 = 4*C_t*C_z
                x3 = D*F0
                return np.float64((2*M0*x0 + M0*x2 + x0*x3 + x1*x3)/(D*(x0 + x1 + x2)))
            except (ArithmeticError, ValueError):
                pass
    M0  = _checked('M0', M0, 'positive', 'driving torque of the motor, reduced to the drum shaft, N*m', (1e-5, 1e11))
    D   = _checked('D', D, 'positive', 'diameter of the driving drum, D = 2r, m', (2e-7, 4e6))
    F0  = _checked('F0', F0, 'positive', 'pretension of both branches at rest, N', (0.001, 1e12))
    C_t = _checked('C_t', C_t, 'positive', 'longitudinal stiffness of the tight (incoming) branch, N/m', (0.001, 1e13))
    C_z = _checked('C_z', C_z, 'positive', 'longitudinal stiffness of the slack (outgoing) branch, N/m', (0.001, 1e13))
    C_y = _checked('C_y', C_y, 'positive', 'bending stiffness of the drum shaft at the drum, N/m', (0.001, 1e14))
    shape = _broadcast(M0=M0, D=D, F0=F0, C_t=C_t, C_z=C_z, C_y=C_y)
    x0 = C_t*C_y
    x1 = C_y*C_z
    x2 = 4*C_t*C_z
    x3 = D*F0
    return _into(out, shape, (2*M0*x0 + M0*x2 + x0*x3 + x1*x3)/(D*(x0 + x1 + x2)))


def running_slack_force(M0, D, F0, C_t, C_z, C_y, *, out=None):
    """Slack-branch force F2 in steady running. Eq (12).

    Parameters
    ----------
    M0 : array_like
        driving torque of the motor, reduced to the drum shaft [N*m], > 0; served from 1e-5 to 1e11
    D : array_like
        diameter of the driving drum, D = 2r [m], > 0; served from 2e-7 to 4e6
    F0 : array_like
        pretension of both branches at rest [N], > 0; served from 0.001 to 1e12
    C_t : array_like
        longitudinal stiffness of the tight (incoming) branch [N/m], > 0; served from 0.001 to 1e13
    C_z : array_like
        longitudinal stiffness of the slack (outgoing) branch [N/m], > 0; served from 0.001 to 1e13
    C_y : array_like
        bending stiffness of the drum shaft at the drum [N/m], > 0; served from 0.001 to 1e14
    out : ndarray, optional
        float64 array of the broadcast shape; the result is written into it and returned.

    Returns
    -------
    ndarray
        [N], broadcast over the arguments.
    """
    if (out is None
            and (type(M0) in (float, int) or type(M0) is np.float64)
            and (type(D) in (float, int) or type(D) is np.float64)
            and (type(F0) in (float, int) or type(F0) is np.float64)
            and (type(C_t) in (float, int) or type(C_t) is np.float64)
            and (type(C_z) in (float, int) or type(C_z) is np.float64)
            and (type(C_y) in (float, int) or type(C_y) is np.float64)):
        if (1e-5 <= M0 <= 1e11 and 2e-7 <= D <= 4e6 and 0.001 <= F0 <= 1e12
                and 0.001 <= C_t <= 1e13 and 0.001 <= C_z <= 1e13 and 0.001 <= C_y <= 1e14):
            try:    # a failed check or a math error: the array path decides
                x0 = C_t*C_y
                x1 = C_y*C_z
                x2 = 4*C_t*C_z
                x3 = D*F0
                return np.float64((-2*M0*x1 - M0*x2 + x0*x3 + x1*x3)/(D*(x0 + x1 + x2)))
            except (ArithmeticError, ValueError):
                pass
    M0  = _checked('M0', M0, 'positive', 'driving torque of the motor, reduced to the drum shaft, N*m', (1e-5, 1e11))
    D   = _checked('D', D, 'positive', 'diameter of the driving drum, D = 2r, m', (2e-7, 4e6))
    F0  = _checked('F0', F0, 'positive', 'pretension of both branches at rest, N', (0.001, 1e12))
    C_t = _checked('C_t', C_t, 'positive', 'longitudinal stiffness of the tight (incoming) branch, N/m', (0.001, 1e13))
    C_z = _checked('C_z', C_z, 'positive', 'longitudinal stiffness of the slack (outgoing) branch, N/m', (0.001, 1e13))
    C_y = _checked('C_y', C_y, 'positive', 'bending stiffness of the drum shaft at the drum, N/m', (0.001, 1e14))
    shape = _broadcast(M0=M0, D=D, F0=F0, C_t=C_t, C_z=C_z, C_y=C_y)
    x0 = C_t*C_y
    x1 = C_y*C_z
    x2 = 4*C_t*C_z
    x3 = D*F0
    return _into(out, shape, (-2*M0*x1 - M0*x2 + x0*x3 + x1*x3)/(D*(x0 + x1 + x2)))


def running_drum_shaft_deflection(M0, D, F0, C_t, C_z, C_y, *, out=None):
    """Drum-shaft deflection y in steady running. Eq (12).

    Parameters
    ----------
    M0 : array_like
        driving torque of the motor, reduced to the drum shaft [N*m], > 0; served from 1e-5 to 1e11
    D : array_like
        diameter of the driving drum, D = 2r [m], > 0; served from 2e-7 to 4e6
    F0 : array_like
        pretension of both branches at rest [N], > 0; served from 0.001 to 1e12
    C_t : array_like
        longitudinal stiffness of the tight (incoming) branch [N/m], > 0; served from 0.001 to 1e13
    C_z : array_like
        longitudinal stiffness of the slack (outgoing) branch [N/m], > 0; served from 0.001 to 1e13
    C_y : array_like
        bending stiffness of the drum shaft at the drum [N/m], > 0; served from 0.001 to 1e14
    out : ndarray, optional
        float64 array of the broadcast shape; the result is written into it and returned.

    Returns
    -------
    ndarray
        [m], broadcast over the arguments.
    """
    if (out is None
            and (type(M0) in (float, int) or type(M0) is np.float64)
            and (type(D) in (float, int) or type(D) is np.float64)
            and (type(F0) in (float, int) or type(F0) is np.float64)
            and (type(C_t) in (float, int) or type(C_t) is np.float64)
            and (type(C_z) in (float, int) or type(C_z) is np.float64)
            and (type(C_y) in (float, int) or type(C_y) is np.float64)):
        if (1e-5 <= M0 <= 1e11 and 2e-7 <= D <= 4e6 and 0.001 <= F0 <= 1e12
                and 0.001 <= C_t <= 1e13 and 0.001 <= C_z <= 1e13 and 0.001 <= C_y <= 1e14):
            try:    # a failed check or a math error: the array path decides
                x0 = D*F0
                return np.float64(2*(C_t*M0 + C_t*x0 - C_z*M0 + C_z*x0)/(D*(C_t*C_y + 4*C_t*C_z + C_y*C_z)))
            except (ArithmeticError, ValueError):
                pass
    M0  = _checked('M0', M0, 'positive', 'driving torque of the motor, reduced to the drum shaft, N*m', (1e-5, 1e11))
    D   = _checked('D', D, 'positive', 'diameter of the driving drum, D = 2r, m', (2e-7, 4e6))
    F0  = _checked('F0', F0, 'positive', 'pretension of both branches at rest, N', (0.001, 1e12))
    C_t = _checked('C_t', C_t, 'positive', 'longitudinal stiffness of the tight (incoming) branch, N/m', (0.001, 1e13))
    C_z = _checked('C_z', C_z, 'positive', 'longitudinal stiffness of the slack (outgoing) branch, N/m', (0.001, 1e13))
    C_y = _checked('C_y', C_y, 'positive', 'bending stiffness of the drum shaft at the drum, N/m', (0.001, 1e14))
    shape = _broadcast(M0=M0, D=D, F0=F0, C_t=C_t, C_z=C_z, C_y=C_y)
    x0 = D*F0
    return _into(out, shape, 2*(C_t*M0 + C_t*x0 - C_z*M0 + C_z*x0)/(D*(C_t*C_y + 4*C_t*C_z + C_y*C_z)))


def drum_torque(F1, F2, D, *, out=None):
    """Torque (F1 - F2)*D/2 of the branch forces on the drum. Eq (18).

    Parameters
    ----------
    F1 : array_like
        force in the tight branch (F0 + C_t*e1 in the model) [N], > 0; served from 0.001 to 1e12
    F2 : array_like
        force in the slack branch (F0 + C_z*e2 in the model) [N], > 0; served from 1e-8 to 1e13
    D : array_like
        diameter of the driving drum, D = 2r [m], > 0; served from 2e-7 to 4e6
    out : ndarray, optional
        float64 array of the broadcast shape; the result is written into it and returned.

    Returns
    -------
    ndarray
        [N*m], broadcast over the arguments.
    """
    if (out is None
            and (type(F1) in (float, int) or type(F1) is np.float64)
            and (type(F2) in (float, int) or type(F2) is np.float64)
            and (type(D) in (float, int) or type(D) is np.float64)):
        if (0.001 <= F1 <= 1e12 and 1e-8 <= F2 <= 1e13 and 2e-7 <= D <= 4e6):
            try:    # a failed check or a math error: the array path decides
                return np.float64((1/2)*D*(F1 - F2))
            except (ArithmeticError, ValueError):
                pass
    F1 = _checked('F1', F1, 'positive', 'force in the tight branch (F0 + C_t*e1 in the model), N', (0.001, 1e12))
    F2 = _checked('F2', F2, 'positive', 'force in the slack branch (F0 + C_z*e2 in the model), N', (1e-8, 1e13))
    D  = _checked('D', D, 'positive', 'diameter of the driving drum, D = 2r, m', (2e-7, 4e6))
    shape = _broadcast(F1=F1, F2=F2, D=D)
    return _into(out, shape, (1/2)*D*(F1 - F2))


def traction_margin(F1, F2, mu, alpha, *, out=None):
    """Margin exp(mu*alpha) - 1.25*F1/F2 of the traction condition; > 0 holds. Eq (19).

    Parameters
    ----------
    F1 : array_like
        force in the tight branch (F0 + C_t*e1 in the model) [N], > 0; served from 0.001 to 1e12
    F2 : array_like
        force in the slack branch (F0 + C_z*e2 in the model) [N], > 0; served from 1e-8 to 1e13
    mu : array_like
        friction coefficient between element and drum [1], > 0; served from 5e-8 to 2.0
    alpha : array_like
        wrap angle of the element on the drum [rad], > 0; served from 5e-7 to 300.0
    out : ndarray, optional
        float64 array of the broadcast shape; the result is written into it and returned.

    Returns
    -------
    ndarray
        [1], broadcast over the arguments.
    """
    if (out is None
            and (type(F1) in (float, int) or type(F1) is np.float64)
            and (type(F2) in (float, int) or type(F2) is np.float64)
            and (type(mu) in (float, int) or type(mu) is np.float64)
            and (type(alpha) in (float, int) or type(alpha) is np.float64)):
        if (0.001 <= F1 <= 1e12 and 1e-8 <= F2 <= 1e13 and 5e-8 <= mu <= 2.0
                and 5e-7 <= alpha <= 300.0):
            try:    # a failed check or a math error: the array path decides
                return np.float64(-5/4*F1/F2 + math.exp(alpha*mu))
            except (ArithmeticError, ValueError):
                pass
    F1    = _checked('F1', F1, 'positive', 'force in the tight branch (F0 + C_t*e1 in the model), N', (0.001, 1e12))
    F2    = _checked('F2', F2, 'positive', 'force in the slack branch (F0 + C_z*e2 in the model), N', (1e-8, 1e13))
    mu    = _checked('mu', mu, 'positive', 'friction coefficient between element and drum, 1', (5e-8, 2.0))
    alpha = _checked('alpha', alpha, 'positive', 'wrap angle of the element on the drum, rad', (5e-7, 300.0))
    shape = _broadcast(F1=F1, F2=F2, mu=mu, alpha=alpha)
    return _into(out, shape, -5/4*F1/F2 + np.exp(alpha*mu))


def least_mu_alpha(F1, F2, *, out=None):
    """Least mu*alpha that satisfies the traction condition (19). Eq (19).

    Parameters
    ----------
    F1 : array_like
        force in the tight branch (F0 + C_t*e1 in the model) [N], > 0; served from 0.001 to 1e12
    F2 : array_like
        force in the slack branch (F0 + C_z*e2 in the model) [N], > 0; served from 1e-8 to 1e13
    out : ndarray, optional
        float64 array of the broadcast shape; the result is written into it and returned.

    Returns
    -------
    ndarray
        [1], broadcast over the arguments.
    """
    if (out is None
            and (type(F1) in (float, int) or type(F1) is np.float64)
            and (type(F2) in (float, int) or type(F2) is np.float64)):
        if (0.001 <= F1 <= 1e12 and 1e-8 <= F2 <= 1e13):
            try:    # a failed check or a math error: the array path decides
                return np.float64(math.log((5/4)*F1/F2))
            except (ArithmeticError, ValueError):
                pass
    F1 = _checked('F1', F1, 'positive', 'force in the tight branch (F0 + C_t*e1 in the model), N', (0.001, 1e12))
    F2 = _checked('F2', F2, 'positive', 'force in the slack branch (F0 + C_z*e2 in the model), N', (1e-8, 1e13))
    shape = _broadcast(F1=F1, F2=F2)
    return _into(out, shape, np.log((5/4)*F1/F2))


def pulsating_force(t, F1_t, F2_t, F3_t, F4_t, K1, K2, K3, K4, t_3, *, out=None):
    """Pulsating load F'(t) of (21), as printed. Eq (21).

    Parameters
    ----------
    t : array_like
        time from the start of the drive [s], >= 0; served from 0.0 to 2e7
    F1_t : array_like
        amplitude F_1(t) of the pulsating load (21) [N], > 0; served from 0.0001 to 1e11
    F2_t : array_like
        amplitude F_2(t) of the pulsating load (21) [N], > 0; served from 0.0001 to 1e11
    F3_t : array_like
        amplitude F_3(t) of the pulsating load (21) [N], > 0; served from 0.0001 to 1e11
    F4_t : array_like
        amplitude F_4(t) of the pulsating load (21) [N], > 0; served from 0.0001 to 1e11
    K1 : array_like
        constant K_1 of (21) (pretension at the load) [N], > 0; served from 0.0001 to 1e11
    K2 : array_like
        constant K_2 of (21) (pretension at the load) [N], > 0; served from 0.0001 to 1e11
    K3 : array_like
        constant K_3 of (21) (pretension at the load) [N], > 0; served from 0.0001 to 1e11
    K4 : array_like
        constant K_4 of (21) (pretension at the load) [N], > 0; served from 0.0001 to 1e11
    t_3 : array_like
        stop time t_3 of the transporter in (21) [s], > 0; served from 5e-7 to 3e7
    out : ndarray, optional
        float64 array of the broadcast shape; the result is written into it and returned.

    Returns
    -------
    ndarray
        [N], broadcast over the arguments.
    """
    if (out is None
            and (type(t) in (float, int) or type(t) is np.float64)
            and (type(F1_t) in (float, int) or type(F1_t) is np.float64)
            and (type(F2_t) in (float, int) or type(F2_t) is np.float64)
            and (type(F3_t) in (float, int) or type(F3_t) is np.float64)
            and (type(F4_t) in (float, int) or type(F4_t) is np.float64)
            and (type(K1) in (float, int) or type(K1) is np.float64)
            and (type(K2) in (float, int) or type(K2) is np.float64)
            and (type(K3) in (float, int) or type(K3) is np.float64)
            and (type(K4) in (float, int) or type(K4) is np.float64)
            and (type(t_3) in (float, int) or type(t_3) is np.float64)):
        if (0.0 <= t <= 2e7 and 0.0001 <= F1_t <= 1e11 and 0.0001 <= F2_t <= 1e11
                and 0.0001 <= F3_t <= 1e11 and 0.0001 <= F4_t <= 1e11 and 0.0001 <= K1 <= 1e11
                and 0.0001 <= K2 <= 1e11 and 0.0001 <= K3 <= 1e11 and 0.0001 <= K4 <= 1e11
                and 5e-7 <= t_3 <= 3e7):
            try:    # a failed check or a math error: the array path decides
                k0 = 3.141592653589793/t_3
                x0 = math.sin(k0*t)
                k1 = -K2
                k2 = -K4
                k3 = (1/4)*F1_t
                k4 = (1/4)*F3_t
                k5 = (1/4)*K1 + (1/4)*K3
                return np.float64(k3*x0 + k4*x0 + k5 - 1/4*abs(F2_t*x0 + k1) - 1/4*abs(F4_t*x0 + k2))
            except (ArithmeticError, ValueError):
                pass
    t    = _checked('t', t, 'nonnegative', 'time from the start of the drive, s', (0.0, 2e7))
    F1_t = _checked('F1_t', F1_t, 'positive', 'amplitude F_1(t) of the pulsating load (21), N', (0.0001, 1e11))
    F2_t = _checked('F2_t', F2_t, 'positive', 'amplitude F_2(t) of the pulsating load (21), N', (0.0001, 1e11))
    F3_t = _checked('F3_t', F3_t, 'positive', 'amplitude F_3(t) of the pulsating load (21), N', (0.0001, 1e11))
    F4_t = _checked('F4_t', F4_t, 'positive', 'amplitude F_4(t) of the pulsating load (21), N', (0.0001, 1e11))
    K1   = _checked('K1', K1, 'positive', 'constant K_1 of (21) (pretension at the load), N', (0.0001, 1e11))
    K2   = _checked('K2', K2, 'positive', 'constant K_2 of (21) (pretension at the load), N', (0.0001, 1e11))
    K3   = _checked('K3', K3, 'positive', 'constant K_3 of (21) (pretension at the load), N', (0.0001, 1e11))
    K4   = _checked('K4', K4, 'positive', 'constant K_4 of (21) (pretension at the load), N', (0.0001, 1e11))
    t_3  = _checked('t_3', t_3, 'positive', 'stop time t_3 of the transporter in (21), s', (5e-7, 3e7))
    shape = _broadcast(t=t, F1_t=F1_t, F2_t=F2_t, F3_t=F3_t, F4_t=F4_t, K1=K1, K2=K2, K3=K3, K4=K4,
                       t_3=t_3)
    k0 = 3.141592653589793/t_3
    k1 = -K2
    k2 = -K4
    k3 = (1/4)*F1_t
    k4 = (1/4)*F3_t
    k5 = (1/4)*K1 + (1/4)*K3
    if out is None and not shape:
        x0 = np.sin(k0*t)
        return k3*x0 + k4*x0 + k5 - 1/4*abs(F2_t*x0 + k1) - 1/4*abs(F4_t*x0 + k2)
    out = _out(out, shape)
    for _o, (t, F2_t, F4_t, k0, k1, k2, k3, k4, k5) in _spans(
            out, shape, t, F2_t, F4_t, k0, k1, k2, k3, k4, k5):
        x0 = np.sin(k0*t)
        np.multiply(x0, F2_t, out=_o)
        np.add(_o, k1, out=_o)
        np.abs(_o, out=_o)
        np.divide(_o, -4, out=_o)
        _w0 = np.empty_like(_o)
        np.multiply(x0, F4_t, out=_w0)
        np.add(_w0, k2, out=_w0)
        np.abs(_w0, out=_w0)
        np.divide(_w0, -4, out=_w0)
        np.add(_o, _w0, out=_o)
        np.multiply(x0, k3, out=_w0)
        np.add(_o, _w0, out=_o)
        np.multiply(x0, k4, out=_w0)
        np.add(_o, _w0, out=_o)
        np.add(_o, k5, out=_o)
    return out


def state_derivative(I1, I2, I3, C1, C2, nu1, nu2, m3, m_L, C_y, nu_y, C_t, C_z, nu_z, nu_t, q, L, r, M0, F0, W, s1, s2, s3, s4, s5, s6, s7, s8, s9, s10):
    """Right-hand side d(state)/dt of (12) for scipy.integrate.solve_ivp; state (phi1, phi2, phi3, y, z, and their rates) = (s1, ..., s10). Eq (12).

    Parameters
    ----------
    I1 : array_like
        moment of inertia of the motor rotor (reduced to the drum shaft) [kg*m^2], > 0; served from 1e-8 to 1e8
    I2 : array_like
        moment of inertia of the intermediate mass (gearbox, couplings; reduced) [kg*m^2], > 0; served from 1e-8 to 1e12
    I3 : array_like
        moment of inertia of the driving drum [kg*m^2], > 0; served from 1e-8 to 5e8
    C1 : array_like
        torsional stiffness, motor to intermediate mass [N*m/rad], > 0; served from 1e-8 to 1e12
    C2 : array_like
        torsional stiffness, intermediate mass to drum [N*m/rad], > 0; served from 1e-19 to 1e19
    nu1 : array_like
        resistance coefficient of the C1 shaft [N*m*s/rad], >= 0; served from 0.0 to 1e9
    nu2 : array_like
        resistance coefficient of the C2 shaft [N*m*s/rad], >= 0; served from 0.0 to 1e9
    m3 : array_like
        mass of the drum with its shaft's share (moves with y) [kg], > 0; served from 5e-5 to 5e9
    m_L : array_like
        mass of the loaded run (loads, carriers, element), lumped at z [kg], > 0; served from 0.0001 to 1e11
    C_y : array_like
        bending stiffness of the drum shaft at the drum [N/m], > 0; served from 0.001 to 1e14
    nu_y : array_like
        resistance coefficient of the drum-shaft bending [N*s/m], >= 0; served from 0.0 to 1e11
    C_t : array_like
        longitudinal stiffness of the tight (incoming) branch [N/m], > 0; served from 0.001 to 1e13
    C_z : array_like
        longitudinal stiffness of the slack (outgoing) branch [N/m], > 0; served from 0.001 to 1e13
    nu_z : array_like
        resistance coefficient of the slack branch's stretching [N*s/m], >= 0; served from 0.0 to 1e10
    nu_t : array_like
        running resistance of the element per unit speed [N*s/m], >= 0; served from 0.0 to 1e10
    q : array_like
        mass of one metre of the traction element [kg/m], > 0; served from 5e-7 to 2e7
    L : array_like
        length of a branch (of the span in (7)) [m], > 0; served from 1e-5 to 3e9
    r : array_like
        radius of the driving drum [m], > 0; served from 1e-7 to 2e6
    M0 : array_like
        driving torque of the motor, reduced to the drum shaft [N*m], > 0; served from 1e-5 to 1e11
    F0 : array_like
        pretension of both branches at rest [N], > 0; served from 0.001 to 1e12
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
    I1   = _checked('I1', I1, 'positive', 'moment of inertia of the motor rotor (reduced to the drum shaft), kg*m^2', (1e-8, 1e8))
    I2   = _checked('I2', I2, 'positive', 'moment of inertia of the intermediate mass (gearbox, couplings; reduced), kg*m^2', (1e-8, 1e12))
    I3   = _checked('I3', I3, 'positive', 'moment of inertia of the driving drum, kg*m^2', (1e-8, 5e8))
    C1   = _checked('C1', C1, 'positive', 'torsional stiffness, motor to intermediate mass, N*m/rad', (1e-8, 1e12))
    C2   = _checked('C2', C2, 'positive', 'torsional stiffness, intermediate mass to drum, N*m/rad', (1e-19, 1e19))
    nu1  = _checked('nu1', nu1, 'nonnegative', 'resistance coefficient of the C1 shaft, N*m*s/rad', (0.0, 1e9))
    nu2  = _checked('nu2', nu2, 'nonnegative', 'resistance coefficient of the C2 shaft, N*m*s/rad', (0.0, 1e9))
    m3   = _checked('m3', m3, 'positive', "mass of the drum with its shaft's share (moves with y), kg", (5e-5, 5e9))
    m_L  = _checked('m_L', m_L, 'positive', 'mass of the loaded run (loads, carriers, element), lumped at z, kg', (0.0001, 1e11))
    C_y  = _checked('C_y', C_y, 'positive', 'bending stiffness of the drum shaft at the drum, N/m', (0.001, 1e14))
    nu_y = _checked('nu_y', nu_y, 'nonnegative', 'resistance coefficient of the drum-shaft bending, N*s/m', (0.0, 1e11))
    C_t  = _checked('C_t', C_t, 'positive', 'longitudinal stiffness of the tight (incoming) branch, N/m', (0.001, 1e13))
    C_z  = _checked('C_z', C_z, 'positive', 'longitudinal stiffness of the slack (outgoing) branch, N/m', (0.001, 1e13))
    nu_z = _checked('nu_z', nu_z, 'nonnegative', "resistance coefficient of the slack branch's stretching, N*s/m", (0.0, 1e10))
    nu_t = _checked('nu_t', nu_t, 'nonnegative', 'running resistance of the element per unit speed, N*s/m', (0.0, 1e10))
    q    = _checked('q', q, 'positive', 'mass of one metre of the traction element, kg/m', (5e-7, 2e7))
    L    = _checked('L', L, 'positive', 'length of a branch (of the span in (7)), m', (1e-5, 3e9))
    r    = _checked('r', r, 'positive', 'radius of the driving drum, m', (1e-7, 2e6))
    M0   = _checked('M0', M0, 'positive', 'driving torque of the motor, reduced to the drum shaft, N*m', (1e-5, 1e11))
    F0   = _checked('F0', F0, 'positive', 'pretension of both branches at rest, N', (0.001, 1e12))
    W    = _checked('W', W, 'real', 'resistance of the loads to the motion of the run, N', (-1e11, 1e11))
    s1   = _checked('s1', s1, 'real', 'state 1: φ1, rad', (-2e6, 2e6))
    s2   = _checked('s2', s2, 'real', 'state 2: φ2, rad', (-2e6, 2e6))
    s3   = _checked('s3', s3, 'real', 'state 3: φ3, rad', (-2e6, 2e6))
    s4   = _checked('s4', s4, 'real', 'state 4: y, m', (-2e6, 2e6))
    s5   = _checked('s5', s5, 'real', 'state 5: z, m', (-2e6, 2e6))
    s6   = _checked('s6', s6, 'real', 'state 6: dφ1/dt, rad/s', (-2e6, 2e6))
    s7   = _checked('s7', s7, 'real', 'state 7: dφ2/dt, rad/s', (-2e6, 2e6))
    s8   = _checked('s8', s8, 'real', 'state 8: dφ3/dt, rad/s', (-2e6, 2e6))
    s9   = _checked('s9', s9, 'real', 'state 9: dy/dt, m/s', (-2e6, 2e6))
    s10  = _checked('s10', s10, 'real', 'state 10: dz/dt, m/s', (-2e6, 2e6))
    shape = _broadcast(I1=I1, I2=I2, I3=I3, C1=C1, C2=C2, nu1=nu1, nu2=nu2, m3=m3, m_L=m_L, C_y=C_y,
                       nu_y=nu_y, C_t=C_t, C_z=C_z, nu_z=nu_z, nu_t=nu_t, q=q, L=L, r=r, M0=M0, F0=F0,
                       W=W, s1=s1, s2=s2, s3=s3, s4=s4, s5=s5, s6=s6, s7=s7, s8=s8, s9=s9, s10=s10)
    x0 = C1*s2
    x1 = nu1*s7
    x2 = C1*s1
    x3 = nu1*s6
    x4 = C2*s3
    x5 = nu2*s8
    x6 = C2*s2
    x7 = nu2*s7
    x8 = 3*I3
    x9 = L*q
    x10 = 2*x9
    x11 = r**2
    x12 = x10*x11
    x13 = 1/(I3*x10 + L**2*q**2*x11 + m_L*x12 + m_L*x8)
    x14 = 3*m_L
    x15 = r*x9
    x16 = C_t*s4
    x17 = r*x14
    x18 = C_t*s5
    x19 = C_z*s4
    x20 = C_z*s5
    x21 = nu_z*s10
    x22 = nu_z*s9
    x23 = nu_t*s10
    x24 = 3*x15
    x25 = x11*x14
    x26 = C_t*s3
    x27 = C_z*s3
    x28 = nu_z*s8
    x29 = 3*x11*x9
    x30 = _cube(r)
    return _matrix((10, 1), [s6, s7, s8, s9, s10, (M0 + x0 + x1 - x2 - x3)/I1, (-x0 - x1 + x2 + x3 + x4 + x5 - x6 - x7)/I2, x13*(W*x15 - x10*x4 - x10*x5 + x10*x6 + x10*x7 - x14*x4 - x14*x5 + x14*x6 + x14*x7 + x15*x23 + x16*x17 + x16*x24 + x17*x18 - x17*x19 + x17*x20 + x17*x21 - x17*x22 + x18*x24 - x19*x24 + x20*x24 + x21*x24 - x22*x24 - x25*x26 - x25*x27 - x25*x28 - x26*x29 - x27*x29 - x28*x29), 3*(C_t*r*s3 - C_y*s4 - C_z*r*s3 + C_z*s5 + 2*F0 - nu_y*s9 + nu_z*s10 - r*x28 - x16 - x18 - x19 - x22)/(3*m3 + x10), x13*(C2*L*q*r*s3 + 3*C_t*I3*r*s3 + 3*C_t*L*q*s3*x30 + 3*C_z*I3*r*s3 + 3*C_z*I3*s4 + 3*C_z*L*q*s3*x30 + 3*C_z*L*q*s4*x11 + 3*I3*nu_z*r*s8 + 3*I3*nu_z*s9 + L*nu2*q*r*s8 + 3*L*nu_z*q*s8*x30 + 3*L*nu_z*q*s9*x11 - W*x12 - W*x8 - x12*x23 - x15*x6 - x15*x7 - x16*x29 - x16*x8 - x18*x29 - x18*x8 - x20*x29 - x20*x8 - x21*x29 - x21*x8 - x23*x8)])


def state_jacobian(I1, I2, I3, C1, C2, nu1, nu2, m3, m_L, C_y, nu_y, C_t, C_z, nu_z, nu_t, q, L, r):
    """Jacobian of state_derivative (constant: the model is linear). Eq (12).

    Parameters
    ----------
    I1 : array_like
        moment of inertia of the motor rotor (reduced to the drum shaft) [kg*m^2], > 0; served from 1e-8 to 1e8
    I2 : array_like
        moment of inertia of the intermediate mass (gearbox, couplings; reduced) [kg*m^2], > 0; served from 1e-8 to 1e12
    I3 : array_like
        moment of inertia of the driving drum [kg*m^2], > 0; served from 1e-8 to 5e8
    C1 : array_like
        torsional stiffness, motor to intermediate mass [N*m/rad], > 0; served from 1e-8 to 1e12
    C2 : array_like
        torsional stiffness, intermediate mass to drum [N*m/rad], > 0; served from 1e-19 to 1e19
    nu1 : array_like
        resistance coefficient of the C1 shaft [N*m*s/rad], >= 0; served from 0.0 to 1e9
    nu2 : array_like
        resistance coefficient of the C2 shaft [N*m*s/rad], >= 0; served from 0.0 to 1e9
    m3 : array_like
        mass of the drum with its shaft's share (moves with y) [kg], > 0; served from 5e-5 to 5e9
    m_L : array_like
        mass of the loaded run (loads, carriers, element), lumped at z [kg], > 0; served from 0.0001 to 1e11
    C_y : array_like
        bending stiffness of the drum shaft at the drum [N/m], > 0; served from 0.001 to 1e14
    nu_y : array_like
        resistance coefficient of the drum-shaft bending [N*s/m], >= 0; served from 0.0 to 1e11
    C_t : array_like
        longitudinal stiffness of the tight (incoming) branch [N/m], > 0; served from 0.001 to 1e13
    C_z : array_like
        longitudinal stiffness of the slack (outgoing) branch [N/m], > 0; served from 0.001 to 1e13
    nu_z : array_like
        resistance coefficient of the slack branch's stretching [N*s/m], >= 0; served from 0.0 to 1e10
    nu_t : array_like
        running resistance of the element per unit speed [N*s/m], >= 0; served from 0.0 to 1e10
    q : array_like
        mass of one metre of the traction element [kg/m], > 0; served from 5e-7 to 2e7
    L : array_like
        length of a branch (of the span in (7)) [m], > 0; served from 1e-5 to 3e9
    r : array_like
        radius of the driving drum [m], > 0; served from 1e-7 to 2e6

    Returns
    -------
    ndarray
        [SI], shape (10, 10) followed by the broadcast shape of the arguments.
    """
    I1   = _checked('I1', I1, 'positive', 'moment of inertia of the motor rotor (reduced to the drum shaft), kg*m^2', (1e-8, 1e8))
    I2   = _checked('I2', I2, 'positive', 'moment of inertia of the intermediate mass (gearbox, couplings; reduced), kg*m^2', (1e-8, 1e12))
    I3   = _checked('I3', I3, 'positive', 'moment of inertia of the driving drum, kg*m^2', (1e-8, 5e8))
    C1   = _checked('C1', C1, 'positive', 'torsional stiffness, motor to intermediate mass, N*m/rad', (1e-8, 1e12))
    C2   = _checked('C2', C2, 'positive', 'torsional stiffness, intermediate mass to drum, N*m/rad', (1e-19, 1e19))
    nu1  = _checked('nu1', nu1, 'nonnegative', 'resistance coefficient of the C1 shaft, N*m*s/rad', (0.0, 1e9))
    nu2  = _checked('nu2', nu2, 'nonnegative', 'resistance coefficient of the C2 shaft, N*m*s/rad', (0.0, 1e9))
    m3   = _checked('m3', m3, 'positive', "mass of the drum with its shaft's share (moves with y), kg", (5e-5, 5e9))
    m_L  = _checked('m_L', m_L, 'positive', 'mass of the loaded run (loads, carriers, element), lumped at z, kg', (0.0001, 1e11))
    C_y  = _checked('C_y', C_y, 'positive', 'bending stiffness of the drum shaft at the drum, N/m', (0.001, 1e14))
    nu_y = _checked('nu_y', nu_y, 'nonnegative', 'resistance coefficient of the drum-shaft bending, N*s/m', (0.0, 1e11))
    C_t  = _checked('C_t', C_t, 'positive', 'longitudinal stiffness of the tight (incoming) branch, N/m', (0.001, 1e13))
    C_z  = _checked('C_z', C_z, 'positive', 'longitudinal stiffness of the slack (outgoing) branch, N/m', (0.001, 1e13))
    nu_z = _checked('nu_z', nu_z, 'nonnegative', "resistance coefficient of the slack branch's stretching, N*s/m", (0.0, 1e10))
    nu_t = _checked('nu_t', nu_t, 'nonnegative', 'running resistance of the element per unit speed, N*s/m', (0.0, 1e10))
    q    = _checked('q', q, 'positive', 'mass of one metre of the traction element, kg/m', (5e-7, 2e7))
    L    = _checked('L', L, 'positive', 'length of a branch (of the span in (7)), m', (1e-5, 3e9))
    r    = _checked('r', r, 'positive', 'radius of the driving drum, m', (1e-7, 2e6))
    shape = _broadcast(I1=I1, I2=I2, I3=I3, C1=C1, C2=C2, nu1=nu1, nu2=nu2, m3=m3, m_L=m_L, C_y=C_y,
                       nu_y=nu_y, C_t=C_t, C_z=C_z, nu_z=nu_z, nu_t=nu_t, q=q, L=L, r=r)
    x0 = 1/(I1)
    x1 = C1*x0
    x2 = nu1*x0
    x3 = 1/(I2)
    x4 = 3*m_L
    x5 = L*q
    x6 = 2*x5
    x7 = r**2
    x8 = x6*x7
    x9 = 1/(I3*x4 + I3*x6 + L**2*q**2*x7 + m_L*x8)
    x10 = x9*(x4 + x6)
    x11 = x4*x7
    x12 = x5*x7
    x13 = 3*x12
    x14 = C_t*x13 + C_z*x13
    x15 = C_t - C_z
    x16 = 3*x15
    x17 = r*x9
    x18 = x17*(m_L + x5)
    x19 = C_t + C_z
    x20 = 3*x19
    x21 = nu_z*x4
    x22 = 3*nu_z
    x23 = x12*x22
    x24 = 3/(3*m3 + x6)
    x25 = x15*x24
    x26 = nu_z*x24
    x27 = C2*x5
    x28 = 3*I3
    x29 = x9*(I3 + x12)
    x30 = nu2*x5
    x31 = nu_z*x28 + x23
    return _matrix((10, 10), [0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, -x1, x1, 0, 0, 0, -x2, x2, 0, 0, 0, C1*x3, -x3*(C1 + C2), C2*x3, 0, 0, nu1*x3, -x3*(nu1 + nu2), nu2*x3, 0, 0, 0, C2*x10, -x9*(C2*x4 + C2*x6 + C_t*x11 + C_z*x11 + x14), x16*x18, x18*x20, 0, nu2*x10, -x9*(nu2*x4 + nu2*x6 + x21*x7 + x23), -x18*x22, x17*(nu_t*x5 + x21 + x22*x5), 0, 0, r*x25, -x24*(C_y + x19), -x25, 0, 0, -r*x26, -x24*(nu_y + nu_z), x26, 0, -x17*x27, x17*(C_t*x28 + C_z*x28 + x14 + x27), -x16*x29, -x20*x29, 0, -x17*x30, x17*(x30 + x31), x22*x29, -x9*(nu_t*x28 + nu_t*x8 + x31)])


def mass_matrix(I1, I2, I3, m3, m_L, q, L, r):
    """Mass matrix M of (12). Eq (12).

    Parameters
    ----------
    I1 : array_like
        moment of inertia of the motor rotor (reduced to the drum shaft) [kg*m^2], > 0; served from 1e-8 to 1e8
    I2 : array_like
        moment of inertia of the intermediate mass (gearbox, couplings; reduced) [kg*m^2], > 0; served from 1e-8 to 1e12
    I3 : array_like
        moment of inertia of the driving drum [kg*m^2], > 0; served from 1e-8 to 5e8
    m3 : array_like
        mass of the drum with its shaft's share (moves with y) [kg], > 0; served from 5e-5 to 5e9
    m_L : array_like
        mass of the loaded run (loads, carriers, element), lumped at z [kg], > 0; served from 0.0001 to 1e11
    q : array_like
        mass of one metre of the traction element [kg/m], > 0; served from 5e-7 to 2e7
    L : array_like
        length of a branch (of the span in (7)) [m], > 0; served from 1e-5 to 3e9
    r : array_like
        radius of the driving drum [m], > 0; served from 1e-7 to 2e6

    Returns
    -------
    ndarray
        [SI], shape (5, 5) followed by the broadcast shape of the arguments.
    """
    I1  = _checked('I1', I1, 'positive', 'moment of inertia of the motor rotor (reduced to the drum shaft), kg*m^2', (1e-8, 1e8))
    I2  = _checked('I2', I2, 'positive', 'moment of inertia of the intermediate mass (gearbox, couplings; reduced), kg*m^2', (1e-8, 1e12))
    I3  = _checked('I3', I3, 'positive', 'moment of inertia of the driving drum, kg*m^2', (1e-8, 5e8))
    m3  = _checked('m3', m3, 'positive', "mass of the drum with its shaft's share (moves with y), kg", (5e-5, 5e9))
    m_L = _checked('m_L', m_L, 'positive', 'mass of the loaded run (loads, carriers, element), lumped at z, kg', (0.0001, 1e11))
    q   = _checked('q', q, 'positive', 'mass of one metre of the traction element, kg/m', (5e-7, 2e7))
    L   = _checked('L', L, 'positive', 'length of a branch (of the span in (7)), m', (1e-5, 3e9))
    r   = _checked('r', r, 'positive', 'radius of the driving drum, m', (1e-7, 2e6))
    shape = _broadcast(I1=I1, I2=I2, I3=I3, m3=m3, m_L=m_L, q=q, L=L, r=r)
    x0 = L*q
    x1 = (2/3)*x0
    x2 = (1/3)*r*x0
    return _matrix((5, 5), [I1, 0, 0, 0, 0, 0, I2, 0, 0, 0, 0, 0, I3 + r**2*x1, 0, x2, 0, 0, 0, m3 + x1, 0, 0, 0, x2, 0, m_L + x1])


def damping_matrix(nu1, nu2, nu_y, nu_z, nu_t, r):
    """Damping matrix C of (12). Eq (12).

    Parameters
    ----------
    nu1 : array_like
        resistance coefficient of the C1 shaft [N*m*s/rad], >= 0; served from 0.0 to 1e9
    nu2 : array_like
        resistance coefficient of the C2 shaft [N*m*s/rad], >= 0; served from 0.0 to 1e9
    nu_y : array_like
        resistance coefficient of the drum-shaft bending [N*s/m], >= 0; served from 0.0 to 1e11
    nu_z : array_like
        resistance coefficient of the slack branch's stretching [N*s/m], >= 0; served from 0.0 to 1e10
    nu_t : array_like
        running resistance of the element per unit speed [N*s/m], >= 0; served from 0.0 to 1e10
    r : array_like
        radius of the driving drum [m], > 0; served from 1e-7 to 2e6

    Returns
    -------
    ndarray
        [SI], shape (5, 5) followed by the broadcast shape of the arguments.
    """
    nu1  = _checked('nu1', nu1, 'nonnegative', 'resistance coefficient of the C1 shaft, N*m*s/rad', (0.0, 1e9))
    nu2  = _checked('nu2', nu2, 'nonnegative', 'resistance coefficient of the C2 shaft, N*m*s/rad', (0.0, 1e9))
    nu_y = _checked('nu_y', nu_y, 'nonnegative', 'resistance coefficient of the drum-shaft bending, N*s/m', (0.0, 1e11))
    nu_z = _checked('nu_z', nu_z, 'nonnegative', "resistance coefficient of the slack branch's stretching, N*s/m", (0.0, 1e10))
    nu_t = _checked('nu_t', nu_t, 'nonnegative', 'running resistance of the element per unit speed, N*s/m', (0.0, 1e10))
    r    = _checked('r', r, 'positive', 'radius of the driving drum, m', (1e-7, 2e6))
    shape = _broadcast(nu1=nu1, nu2=nu2, nu_y=nu_y, nu_z=nu_z, nu_t=nu_t, r=r)
    x0 = -nu1
    x1 = -nu2
    x2 = nu_z*r
    x3 = -x2
    x4 = -nu_z
    return _matrix((5, 5), [nu1, x0, 0, 0, 0, x0, nu1 + nu2, x1, 0, 0, 0, x1, nu2 + nu_z*r**2, x2, x3, 0, 0, x2, nu_y + nu_z, x4, 0, 0, x3, x4, nu_t + nu_z])


def stiffness_matrix(C1, C2, C_y, C_t, C_z, r):
    """Stiffness matrix K of (12). Eq (12).

    Parameters
    ----------
    C1 : array_like
        torsional stiffness, motor to intermediate mass [N*m/rad], > 0; served from 1e-8 to 1e12
    C2 : array_like
        torsional stiffness, intermediate mass to drum [N*m/rad], > 0; served from 1e-19 to 1e19
    C_y : array_like
        bending stiffness of the drum shaft at the drum [N/m], > 0; served from 0.001 to 1e14
    C_t : array_like
        longitudinal stiffness of the tight (incoming) branch [N/m], > 0; served from 0.001 to 1e13
    C_z : array_like
        longitudinal stiffness of the slack (outgoing) branch [N/m], > 0; served from 0.001 to 1e13
    r : array_like
        radius of the driving drum [m], > 0; served from 1e-7 to 2e6

    Returns
    -------
    ndarray
        [SI], shape (5, 5) followed by the broadcast shape of the arguments.
    """
    C1  = _checked('C1', C1, 'positive', 'torsional stiffness, motor to intermediate mass, N*m/rad', (1e-8, 1e12))
    C2  = _checked('C2', C2, 'positive', 'torsional stiffness, intermediate mass to drum, N*m/rad', (1e-19, 1e19))
    C_y = _checked('C_y', C_y, 'positive', 'bending stiffness of the drum shaft at the drum, N/m', (0.001, 1e14))
    C_t = _checked('C_t', C_t, 'positive', 'longitudinal stiffness of the tight (incoming) branch, N/m', (0.001, 1e13))
    C_z = _checked('C_z', C_z, 'positive', 'longitudinal stiffness of the slack (outgoing) branch, N/m', (0.001, 1e13))
    r   = _checked('r', r, 'positive', 'radius of the driving drum, m', (1e-7, 2e6))
    shape = _broadcast(C1=C1, C2=C2, C_y=C_y, C_t=C_t, C_z=C_z, r=r)
    x0 = -C1
    x1 = -C2
    x2 = r**2
    x3 = C_t - C_z
    x4 = -r*x3
    x5 = C_t + C_z
    x6 = -r*x5
    return _matrix((5, 5), [C1, x0, 0, 0, 0, x0, C1 + C2, x1, 0, 0, 0, x1, C2 + C_t*x2 + C_z*x2, x4, x6, 0, 0, x4, C_y + x5, x3, 0, 0, x6, x3, x5])


def generalized_forces(M0, F0, W):
    """Generalized forces F(W) of (12). Eq (10), (12).

    Parameters
    ----------
    M0 : array_like
        driving torque of the motor, reduced to the drum shaft [N*m], > 0; served from 1e-5 to 1e11
    F0 : array_like
        pretension of both branches at rest [N], > 0; served from 0.001 to 1e12
    W : array_like
        resistance of the loads to the motion of the run [N]; served from -1e11 to 1e11

    Returns
    -------
    ndarray
        [SI], shape (5, 1) followed by the broadcast shape of the arguments.
    """
    M0 = _checked('M0', M0, 'positive', 'driving torque of the motor, reduced to the drum shaft, N*m', (1e-5, 1e11))
    F0 = _checked('F0', F0, 'positive', 'pretension of both branches at rest, N', (0.001, 1e12))
    W  = _checked('W', W, 'real', 'resistance of the loads to the motion of the run, N', (-1e11, 1e11))
    shape = _broadcast(M0=M0, F0=F0, W=W)
    return _matrix((5, 1), [M0, 0, 0, 2*F0, -W])
