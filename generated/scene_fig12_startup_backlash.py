"""Numeric functions for derivation 'portal_travel'. Generated; do not edit.

Source: crane_sym.derivations.portal_travel (paper 003_5e8a923a75d2f7ba.txt:
Travel mechanisms of rail-mounted portal cranes: gear geometry, start-up with backlash and support loads).
Specialized to scene 'fig12_startup_backlash' (Paper 003, Fig. 12 / Table 1: start-up of the travel drive with backlash): outputs startup_motor_mass, startup_rated_force, startup_no_load_speed, startup_backlash_at_rim, startup_first_slope, startup_slope_ratio, startup_link_damping, startup_rigid_breakaway; folded in: J_r = 0.225 kg*m^2, n_m = 2.0 1, omega_n = 97.91297103688188 rad/s, omega_0 = 104.71975511965977 rad/s, v_n = 0.5333333333333333 m/s, P_m = 13000.0 W, lambda_p = 2.0 1, c_l = 5000000.0 N/m, zeta = 0.05 1, m_k = 250000.0 kg, W_f = 30000.0 N, W_w = 30000.0 N.
Inputs left as arguments: phi_b.
Equations: start-up, rated force, start-up, slope ratio, start-up, link damping, start-up, no-load speed, start-up, rigid break-away, start-up, backlash at the rim, start-up, first characteristic, start-up, motor mass at the rim.
Printed by SymPy 1.14.0 with crane_sym 0.1.0; regenerate with `crane-sym generate --scene fig12_startup_backlash --out <folder>`.

Functions and argument order:
    startup_motor_mass() -> [kg]    eq start-up, motor mass at the rim
    startup_rated_force() -> [N]    eq start-up, rated force
    startup_no_load_speed() -> [m/s]    eq start-up, no-load speed
    startup_backlash_at_rim(phi_b) -> [m]    eq start-up, backlash at the rim
    startup_first_slope() -> [N*s/m]    eq start-up, first characteristic
    startup_slope_ratio() -> [1]    eq start-up, slope ratio
    startup_link_damping() -> [N*s/m]    eq start-up, link damping
    startup_rigid_breakaway() -> [m/s^2]    eq start-up, rigid break-away
"""

import numpy as np

__all__ = ['startup_motor_mass', 'startup_rated_force', 'startup_no_load_speed', 'startup_backlash_at_rim', 'startup_first_slope', 'startup_slope_ratio', 'startup_link_damping', 'startup_rigid_breakaway']

SCENE_NAME = 'fig12_startup_backlash'
SCENE_TITLE = 'Paper 003, Fig. 12 / Table 1: start-up of the travel drive with backlash'


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


def startup_motor_mass(*, out=None):
    """Motor rotors of one side reduced to the wheel rim. Specialized to scene 'fig12_startup_backlash'. Eq start-up, motor mass at the rim.

    Parameters
    ----------

    out : ndarray, optional
        float64 array of the broadcast shape; the result is written into it and returned.

    Returns
    -------
    ndarray
        [kg], broadcast over the arguments.
    """
    shape = _broadcast()
    return _into(out, shape, 96208257100536606546645018867057122430119640677/6343323078693154850863132054743673842171904)


def startup_rated_force(*, out=None):
    """Rated force of one side at the rim. Specialized to scene 'fig12_startup_backlash'. Eq start-up, rated force.

    Parameters
    ----------

    out : ndarray, optional
        float64 array of the broadcast shape; the result is written into it and returned.

    Returns
    -------
    ndarray
        [N], broadcast over the arguments.
    """
    shape = _broadcast()
    return _into(out, shape, 234187180623265792000/4803839602528529)


def startup_no_load_speed(*, out=None):
    """No-load speed at the rim. Specialized to scene 'fig12_startup_backlash'. Eq start-up, no-load speed.

    Parameters
    ----------

    out : ndarray, optional
        float64 array of the broadcast shape; the result is written into it and returned.

    Returns
    -------
    ndarray
        [m/s], broadcast over the arguments.
    """
    shape = _broadcast()
    return _into(out, shape, 17699741391091986546819815914391/31029859126258140561491189825536)


def startup_backlash_at_rim(phi_b, *, out=None):
    """Backlash phi_b of the fast shaft as a gap at the rim. Specialized to scene 'fig12_startup_backlash'. Eq start-up, backlash at the rim.

    Parameters
    ----------
    phi_b : array_like
        backlash of one drive, on its fast shaft [rad], >= 0; served from 0.0 to 6.3e6
    out : ndarray, optional
        float64 array of the broadcast shape; the result is written into it and returned.

    Returns
    -------
    ndarray
        [m], broadcast over the arguments.
    """
    if (out is None
            and (type(phi_b) in (float, int) or type(phi_b) is np.float64)):
        if (0.0 <= phi_b <= 6.3e6):
            try:    # a failed check or a math error: the array path decides
                return np.float64((4803839602528529/881921639752878848)*phi_b)
            except (ArithmeticError, ValueError):
                pass
    phi_b = _checked('phi_b', phi_b, 'nonnegative', 'backlash of one drive, on its fast shaft, rad', (0.0, 6.3e6))
    shape = _broadcast(phi_b=phi_b)
    return _into(out, shape, (4803839602528529/881921639752878848)*phi_b)


def startup_first_slope(*, out=None):
    """Slope beta_1 of the first start characteristic of one side. Specialized to scene 'fig12_startup_backlash'. Eq start-up, first characteristic.

    Parameters
    ----------

    out : ndarray, optional
        float64 array of the broadcast shape; the result is written into it and returned.

    Returns
    -------
    ndarray
        [N*s/m], broadcast over the arguments.
    """
    shape = _broadcast()
    return _into(out, shape, 14533590447831015228229892627184197912230073729024000/85026718649041081616156715405505457997799160839)


def startup_slope_ratio(*, out=None):
    """Ratio q of the slopes of consecutive characteristics (three steps to the natural one). Specialized to scene 'fig12_startup_backlash'. Eq start-up, slope ratio.

    Parameters
    ----------

    out : ndarray, optional
        float64 array of the broadcast shape; the result is written into it and returned.

    Returns
    -------
    ndarray
        [1], broadcast over the arguments.
    """
    shape = _broadcast()
    return _into(out, shape, 1.9740230337485716)


def startup_link_damping(*, out=None):
    """Damping coefficient b of a link. Specialized to scene 'fig12_startup_backlash'. Eq start-up, link damping.

    Parameters
    ----------

    out : ndarray, optional
        float64 array of the broadcast shape; the result is written into it and returned.

    Returns
    -------
    ndarray
        [N*s/m], broadcast over the arguments.
    """
    shape = _broadcast()
    return _into(out, shape, 27538.023104123033)


def startup_rigid_breakaway(*, out=None):
    """Acceleration of the rigid drive at break-away on the first characteristic. Specialized to scene 'fig12_startup_backlash'. Eq start-up, rigid break-away.

    Parameters
    ----------

    out : ndarray, optional
        float64 array of the broadcast shape; the result is written into it and returned.

    Returns
    -------
    ndarray
        [m/s^2], broadcast over the arguments.
    """
    shape = _broadcast()
    return _into(out, shape, 428174307811787961016312352740501104533438464000/889123641937180962904536525710016352701607640677)
