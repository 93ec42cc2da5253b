"""Numeric functions for derivation 'portal_travel'. Generated; do not edit.

Source: crane_sym.derivations.portal_travel (paper 003_5e8a923a75d2f7ba.txt:
Travel mechanisms of rail-mounted portal cranes: gear geometry, start-up with backlash and support loads).
Specialized to scene 'fig12_startup_backlash' (Paper 003, Fig. 12 / Table 1: start-up of the travel drive with backlash): outputs startup_motor_mass, startup_rated_force, startup_no_load_speed, startup_backlash_at_rim, startup_first_slope, startup_slope_ratio, startup_link_damping, startup_rigid_breakaway, startup_load, startup_link_load, startup_motor_speed, startup_crane_speed; folded in: J_r = 0.225 kg*m^2, n_m = 2.0 1, omega_n = 97.91297103688188 rad/s, omega_0 = 104.71975511965977 rad/s, v_n = 0.5333333333333333 m/s, P_m = 13000.0 W, lambda_p = 2.0 1, c_l = 5000000.0 N/m, zeta = 0.05 1, m_k = 250000.0 kg, W_f = 30000.0 N, W_w = 30000.0 N.
Inputs left as arguments: phi_b.
Equations: Fig. 12, start-up, rated force, start-up, slope ratio, start-up, link damping, start-up, no-load speed, start-up, rigid break-away, start-up, backlash at the rim, start-up, first characteristic, start-up, motor mass at the rim.
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
    startup_load_0(t) -> [N]    eq Fig. 12
    startup_load_1(t) -> [N]    eq Fig. 12
    startup_load_2(t) -> [N]    eq Fig. 12
    startup_link_load_0(t) -> [N]    eq Fig. 12
    startup_link_load_1(t) -> [N]    eq Fig. 12
    startup_link_load_2(t) -> [N]    eq Fig. 12
    startup_motor_speed_0(t) -> [m/s]    eq Fig. 12
    startup_motor_speed_1(t) -> [m/s]    eq Fig. 12
    startup_motor_speed_2(t) -> [m/s]    eq Fig. 12
    startup_crane_speed_0(t) -> [m/s]    eq Fig. 12
    startup_crane_speed_1(t) -> [m/s]    eq Fig. 12
    startup_crane_speed_2(t) -> [m/s]    eq Fig. 12
"""

import numpy as np

__all__ = ['startup_motor_mass', 'startup_rated_force', 'startup_no_load_speed', 'startup_backlash_at_rim', 'startup_first_slope', 'startup_slope_ratio', 'startup_link_damping', 'startup_rigid_breakaway', 'startup_load_0', 'startup_load_1', 'startup_load_2', 'startup_link_load_0', 'startup_link_load_1', 'startup_link_load_2', 'startup_motor_speed_0', 'startup_motor_speed_1', 'startup_motor_speed_2', 'startup_crane_speed_0', 'startup_crane_speed_1', 'startup_crane_speed_2']

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


def _phase_sum(t, edges, first, powers, sigmas, omegas, cos_amps, sin_amps, consts):
    """A piecewise closed form tabulated per phase, at times ``t``.

    Phase i holds on [edges[i], edges[i + 1]) with τ = t − edges[i] and its
    terms j = first[i] … first[i + 1] − 1:
    consts[i] + Σ_j τ^k_j e^{σ_j τ} (a_j cos ω_j τ + b_j sin ω_j τ).
    Each phase is evaluated on its own points only (one partition of t).
    """
    flat = t.ravel()
    which = np.searchsorted(edges, flat, side="right") - 1
    np.clip(which, 0, consts.size - 1, out=which)
    order = np.argsort(which, kind="stable")
    cuts = np.searchsorted(which[order], np.arange(consts.size + 1))
    result = np.empty(flat.shape)
    for i in range(consts.size):
        points = order[cuts[i]:cuts[i + 1]]
        if not points.size:
            continue
        tau = flat[points] - edges[i]
        acc = np.full(tau.shape, consts[i])
        for j in range(first[i], first[i + 1]):
            if omegas[j]:
                angle = omegas[j] * tau
                term = cos_amps[j] * np.cos(angle) + sin_amps[j] * np.sin(angle)
            else:
                term = np.full(tau.shape, cos_amps[j])
            if sigmas[j]:
                term *= np.exp(sigmas[j] * tau)
            if powers[j]:
                term *= tau ** powers[j]
            acc += term
        result[points] = acc
    return result.reshape(t.shape)


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


_TABLE_STARTUP_LOAD_0 = (
    # edges: phase starts and the end of the run [s]
    np.array([0.0, 0.04406711170105, 0.4, 1.2, 2.0, 4.0]),
    # first: first term of each phase
    np.array([0, 1, 3, 5, 7, 13], dtype=np.intp),
    # powers: power k of tau
    np.array([0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 2, 3, 4], dtype=np.intp),
    # sigmas: decay sigma [1/s]
    np.array([-6.542810601667, -6.021485671952, -1.262954044262, -10.72334838299, -2.836419353872,
              -36.97859625199, -4.486873609035, -84.61459455363, -2.055030044295, -84.61459455363,
              -84.61459455363, -84.61459455363, -84.61459455363]),
    # omegas: angular frequency omega [rad/s]
    np.array([16.93687928793, 17.90756986958, 0.0, 14.09770770106, 0.0, 0.0, 5.23188304444, 0.0,
              6.062779843024, 0.0, 0.0, 0.0, 0.0]),
    # cos_amps: cosine amplitudes
    np.array([-195000.0, -122063.2145903, 122063.2145903, -201059.0619353, 265546.4364422,
              22226.64420559, 5233.263103537, 1391.38752209, -5700.964300792, -4.511908908612,
              0.00731547526351, -7.907396391045e-06, 6.410408972026e-09]),
    # sin_amps: sine amplitudes
    np.array([-54425.14736461, 82420.28184104, 0.0, -69444.97704176, 0.0, 0.0, 177519.1524603,
              0.0, 34882.44205153, 0.0, 0.0, 0.0, 0.0]),
    # consts: constant of each phase
    np.array([195000.0, 60000.0, 60000.0, 60000.0, 60000.0]),
)


def startup_load_0(t, *, out=None):
    """Force F1 + F2 of both links on the crane during the start-up from rest on the stepped rheostat start (start steps held for the setting holds), backlash in both drives. Case 0 (from 0) of those the scene's settings list. Eq Fig. 12.

    Solved for this scene phase by phase in mpmath
    (crane_sym.mechanics.exact_phases).
    The run has 5 phases, each in closed form; they end at
    0.0440671 s crane slips +, 0.4 s motors_left next step, 1.2 s
    motors_left next step, 2 s motors_left next step, 4 s end.

    Parameters
    ----------
    t : array_like
        time [s], 0 <= t <= 4.0
    out : ndarray, optional
        float64 array of t's shape; the result is written into it and returned.

    Returns
    -------
    ndarray
        [N], t's shape.
    """
    t = _checked('t', t, 'nonnegative', 'time, s')
    if t.size and t.max() > 4.0:
        raise ValueError(f"t must be <= 4.0 s (the end of the run this scene tabulates), got {t.max()!r}")
    return _into(out, t.shape, _phase_sum(t, *_TABLE_STARTUP_LOAD_0))


_TABLE_STARTUP_LOAD_1 = (
    # edges: phase starts and the end of the run [s]
    np.array([0.0, 0.0844912363767, 0.0844912364767, 0.09568110932053, 0.4, 1.2, 2.0, 4.0]),
    # first: first term of each phase
    np.array([0, 0, 1, 2, 4, 6, 8, 14], dtype=np.intp),
    # powers: power k of tau
    np.array([0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 2, 3, 4], dtype=np.intp),
    # sigmas: decay sigma [1/s]
    np.array([-6.542810601667, -6.542810601667, -6.021485671952, -1.262954044262, -10.72334838299,
              -2.836419353872, -36.97859625199, -4.486873609035, -84.61459455363, -2.055030044295,
              -84.61459455363, -84.61459455363, -84.61459455363, -84.61459455363]),
    # omegas: angular frequency omega [rad/s]
    np.array([16.93687928793, 16.93687928793, 17.90756986958, 0.0, 14.09770770106, 0.0, 0.0,
              5.23188304444, 0.0, 6.062779843024, 0.0, 0.0, 0.0, 0.0]),
    # cos_amps: cosine amplitudes
    np.array([-87853.52769035, -175707.0550185, -116220.4202539, 116220.4202539, -224780.8878054,
              270957.3675154, 22392.53688292, 5628.563583048, 1390.328263955, -5739.040162767,
              -4.508474009174, 0.007309906019453, -7.90137651964e-06, 6.405528751564e-09]),
    # sin_amps: sine amplitudes
    np.array([72473.28252715, 144946.5652752, 172668.3390622, 0.0, -85715.28498071, 0.0, 0.0,
              178928.8828795, 0.0, 34862.90021577, 0.0, 0.0, 0.0, 0.0]),
    # consts: constant of each phase
    np.array([0.0, 97500.0, 195000.0, 60000.0, 60000.0, 60000.0, 60000.0]),
)


def startup_load_1(t, *, out=None):
    """Force F1 + F2 of both links on the crane during the start-up from rest on the stepped rheostat start (start steps held for the setting holds), backlash in both drives. Case 1 (from 0) of those the scene's settings list. Eq Fig. 12.

    Solved for this scene phase by phase in mpmath
    (crane_sym.mechanics.exact_phases).
    The run has 7 phases, each in closed form; they end at
    0.0844912 s link_left closes +, 0.0844912 s link_right closes +,
    0.0956811 s crane slips +, 0.4 s motors_left next step, 1.2 s
    motors_left next step, 2 s motors_left next step, 4 s end.

    Parameters
    ----------
    t : array_like
        time [s], 0 <= t <= 4.0
    out : ndarray, optional
        float64 array of t's shape; the result is written into it and returned.

    Returns
    -------
    ndarray
        [N], t's shape.
    """
    t = _checked('t', t, 'nonnegative', 'time, s')
    if t.size and t.max() > 4.0:
        raise ValueError(f"t must be <= 4.0 s (the end of the run this scene tabulates), got {t.max()!r}")
    return _into(out, t.shape, _phase_sum(t, *_TABLE_STARTUP_LOAD_1))


_TABLE_STARTUP_LOAD_2 = (
    # edges: phase starts and the end of the run [s]
    np.array([0.0, 0.1276884291522, 0.1276884291522, 0.135931398866, 0.4, 1.2, 2.0, 4.0]),
    # first: first term of each phase
    np.array([0, 0, 1, 2, 4, 6, 8, 14], dtype=np.intp),
    # powers: power k of tau
    np.array([0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 2, 3, 4], dtype=np.intp),
    # sigmas: decay sigma [1/s]
    np.array([-6.542810601667, -6.542810601667, -6.021485671952, -1.262954044262, -10.72334838299,
              -2.836419353872, -36.97859625199, -4.486873609035, -84.61459455363, -2.055030044295,
              -84.61459455363, -84.61459455363, -84.61459455363, -84.61459455363]),
    # omegas: angular frequency omega [rad/s]
    np.array([16.93687928793, 16.93687928793, 17.90756986958, 0.0, 14.09770770106, 0.0, 0.0,
              5.23188304444, 0.0, 6.062779843024, 0.0, 0.0, 0.0, 0.0]),
    # cos_amps: cosine amplitudes
    np.array([-85517.25560077, -171034.5112015, -113679.0086063, 113679.0086063, -240320.0165765,
              278172.4426549, 22613.29953101, 6160.006581183, 1388.914462582, -5789.832698915,
              -4.50388941796, 0.007302472699256, -7.893341743062e-06, 6.399015077364e-09]),
    # sin_amps: sine amplitudes
    np.array([96616.12730111, 193232.2546022, 211923.0946792, 0.0, -124310.0352424, 0.0, 0.0,
              180807.0747215, 0.0, 34836.92893803, 0.0, 0.0, 0.0, 0.0]),
    # consts: constant of each phase
    np.array([0.0, 97500.0, 195000.0, 60000.0, 60000.0, 60000.0, 60000.0]),
)


def startup_load_2(t, *, out=None):
    """Force F1 + F2 of both links on the crane during the start-up from rest on the stepped rheostat start (start steps held for the setting holds), backlash in both drives. Case 2 (from 0) of those the scene's settings list. Eq Fig. 12.

    Solved for this scene phase by phase in mpmath
    (crane_sym.mechanics.exact_phases).
    The run has 7 phases, each in closed form; they end at
    0.127688 s link_left closes +, 0.127688 s link_right closes +, 0.135931
    s crane slips +, 0.4 s motors_left next step, 1.2 s motors_left next
    step, 2 s motors_left next step, 4 s end.

    Parameters
    ----------
    t : array_like
        time [s], 0 <= t <= 4.0
    out : ndarray, optional
        float64 array of t's shape; the result is written into it and returned.

    Returns
    -------
    ndarray
        [N], t's shape.
    """
    t = _checked('t', t, 'nonnegative', 'time, s')
    if t.size and t.max() > 4.0:
        raise ValueError(f"t must be <= 4.0 s (the end of the run this scene tabulates), got {t.max()!r}")
    return _into(out, t.shape, _phase_sum(t, *_TABLE_STARTUP_LOAD_2))


_TABLE_STARTUP_LINK_LOAD_0 = (
    # edges: phase starts and the end of the run [s]
    np.array([0.0, 0.04406711170105, 0.4, 1.2, 2.0, 4.0]),
    # first: first term of each phase
    np.array([0, 1, 3, 5, 7, 13], dtype=np.intp),
    # powers: power k of tau
    np.array([0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 2, 3, 4], dtype=np.intp),
    # sigmas: decay sigma [1/s]
    np.array([-6.542810601667, -6.021485671952, -1.262954044262, -10.72334838299, -2.836419353872,
              -36.97859625199, -4.486873609035, -84.61459455363, -2.055030044295, -84.61459455363,
              -84.61459455363, -84.61459455363, -84.61459455363]),
    # omegas: angular frequency omega [rad/s]
    np.array([16.93687928793, 17.90756986958, 0.0, 14.09770770106, 0.0, 0.0, 5.23188304444, 0.0,
              6.062779843024, 0.0, 0.0, 0.0, 0.0]),
    # cos_amps: cosine amplitudes
    np.array([-97500.0, -61031.60729515, 61031.60729515, -100529.5309677, 132773.2182211,
              11113.3221028, 2616.631551769, 695.693761045, -2850.482150396, -2.255954454306,
              0.003657737631755, -3.953698195523e-06, 3.205204486013e-09]),
    # sin_amps: sine amplitudes
    np.array([-27212.5736823, 41210.14092052, 0.0, -34722.48852088, 0.0, 0.0, 88759.57623017, 0.0,
              17441.22102577, 0.0, 0.0, 0.0, 0.0]),
    # consts: constant of each phase
    np.array([97500.0, 30000.0, 30000.0, 30000.0, 30000.0]),
)


def startup_link_load_0(t, *, out=None):
    """Force F1 of one link (one side) during the start-up from rest on the stepped rheostat start (start steps held for the setting holds), backlash in both drives. Case 0 (from 0) of those the scene's settings list. Eq Fig. 12.

    Solved for this scene phase by phase in mpmath
    (crane_sym.mechanics.exact_phases).
    The run has 5 phases, each in closed form; they end at
    0.0440671 s crane slips +, 0.4 s motors_left next step, 1.2 s
    motors_left next step, 2 s motors_left next step, 4 s end.

    Parameters
    ----------
    t : array_like
        time [s], 0 <= t <= 4.0
    out : ndarray, optional
        float64 array of t's shape; the result is written into it and returned.

    Returns
    -------
    ndarray
        [N], t's shape.
    """
    t = _checked('t', t, 'nonnegative', 'time, s')
    if t.size and t.max() > 4.0:
        raise ValueError(f"t must be <= 4.0 s (the end of the run this scene tabulates), got {t.max()!r}")
    return _into(out, t.shape, _phase_sum(t, *_TABLE_STARTUP_LINK_LOAD_0))


_TABLE_STARTUP_LINK_LOAD_1 = (
    # edges: phase starts and the end of the run [s]
    np.array([0.0, 0.0844912363767, 0.0844912364767, 0.09568110932053, 0.4, 1.2, 2.0, 4.0]),
    # first: first term of each phase
    np.array([0, 0, 1, 2, 5, 8, 10, 16], dtype=np.intp),
    # powers: power k of tau
    np.array([0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 2, 3, 4], dtype=np.intp),
    # sigmas: decay sigma [1/s]
    np.array([-6.542810601667, -6.542810601667, -6.542810601667, -6.021485671952, -1.262954044262,
              -12.03140596751, -10.72334838299, -2.836419353872, -36.97859625199, -4.486873609035,
              -84.61459455363, -2.055030044295, -84.61459455363, -84.61459455363, -84.61459455363,
              -84.61459455363]),
    # omegas: angular frequency omega [rad/s]
    np.array([16.93687928793, 16.93687928793, 16.93687928793, 17.90756986958, 0.0, 13.59821756805,
              14.09770770106, 0.0, 0.0, 5.23188304444, 0.0, 6.062779843024, 0.0, 0.0, 0.0, 0.0]),
    # cos_amps: cosine amplitudes
    np.array([-87853.52769035, -87853.52751012, -2.383871847109e-06, -58110.21012697,
              58110.21012697, 8.614905125117e-07, -112390.4439027, 135478.6837577, 11196.26844146,
              2814.281791524, 695.1641319773, -2869.520081384, -2.254237004587, 0.003654953009727,
              -3.95068825982e-06, 3.202764375782e-09]),
    # sin_amps: sine amplitudes
    np.array([72473.28252715, 72473.28262853, -8.107008064316e-06, 86334.1695311, 0.0,
              -5.273847294668e-07, -42857.64249035, 0.0, 0.0, 89464.44143975, 0.0, 17431.45010788,
              0.0, 0.0, 0.0, 0.0]),
    # consts: constant of each phase
    np.array([0.0, 97500.0, 97500.0, 30000.0, 30000.0, 30000.0, 30000.0]),
)


def startup_link_load_1(t, *, out=None):
    """Force F1 of one link (one side) during the start-up from rest on the stepped rheostat start (start steps held for the setting holds), backlash in both drives. Case 1 (from 0) of those the scene's settings list. Eq Fig. 12.

    Solved for this scene phase by phase in mpmath
    (crane_sym.mechanics.exact_phases).
    The run has 7 phases, each in closed form; they end at
    0.0844912 s link_left closes +, 0.0844912 s link_right closes +,
    0.0956811 s crane slips +, 0.4 s motors_left next step, 1.2 s
    motors_left next step, 2 s motors_left next step, 4 s end.

    Parameters
    ----------
    t : array_like
        time [s], 0 <= t <= 4.0
    out : ndarray, optional
        float64 array of t's shape; the result is written into it and returned.

    Returns
    -------
    ndarray
        [N], t's shape.
    """
    t = _checked('t', t, 'nonnegative', 'time, s')
    if t.size and t.max() > 4.0:
        raise ValueError(f"t must be <= 4.0 s (the end of the run this scene tabulates), got {t.max()!r}")
    return _into(out, t.shape, _phase_sum(t, *_TABLE_STARTUP_LINK_LOAD_1))


_TABLE_STARTUP_LINK_LOAD_2 = (
    # edges: phase starts and the end of the run [s]
    np.array([0.0, 0.1276884291522, 0.1276884291522, 0.135931398866, 0.4, 1.2, 2.0, 4.0]),
    # first: first term of each phase
    np.array([0, 0, 1, 2, 4, 6, 8, 14], dtype=np.intp),
    # powers: power k of tau
    np.array([0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 2, 3, 4], dtype=np.intp),
    # sigmas: decay sigma [1/s]
    np.array([-6.542810601667, -6.542810601667, -6.021485671952, -1.262954044262, -10.72334838299,
              -2.836419353872, -36.97859625199, -4.486873609035, -84.61459455363, -2.055030044295,
              -84.61459455363, -84.61459455363, -84.61459455363, -84.61459455363]),
    # omegas: angular frequency omega [rad/s]
    np.array([16.93687928793, 16.93687928793, 17.90756986958, 0.0, 14.09770770106, 0.0, 0.0,
              5.23188304444, 0.0, 6.062779843024, 0.0, 0.0, 0.0, 0.0]),
    # cos_amps: cosine amplitudes
    np.array([-85517.25560077, -85517.25560077, -56839.50430317, 56839.50430317, -120160.0082882,
              139086.2213274, 11306.64976551, 3080.003290591, 694.4572312909, -2894.916349457,
              -2.25194470898, 0.003651236349628, -3.946670871531e-06, 3.199507538682e-09]),
    # sin_amps: sine amplitudes
    np.array([96616.12730111, 96616.12730111, 105961.5473396, 0.0, -62155.01762121, 0.0, 0.0,
              90403.53736076, 0.0, 17418.46446902, 0.0, 0.0, 0.0, 0.0]),
    # consts: constant of each phase
    np.array([0.0, 97500.0, 97500.0, 30000.0, 30000.0, 30000.0, 30000.0]),
)


def startup_link_load_2(t, *, out=None):
    """Force F1 of one link (one side) during the start-up from rest on the stepped rheostat start (start steps held for the setting holds), backlash in both drives. Case 2 (from 0) of those the scene's settings list. Eq Fig. 12.

    Solved for this scene phase by phase in mpmath
    (crane_sym.mechanics.exact_phases).
    The run has 7 phases, each in closed form; they end at
    0.127688 s link_left closes +, 0.127688 s link_right closes +, 0.135931
    s crane slips +, 0.4 s motors_left next step, 1.2 s motors_left next
    step, 2 s motors_left next step, 4 s end.

    Parameters
    ----------
    t : array_like
        time [s], 0 <= t <= 4.0
    out : ndarray, optional
        float64 array of t's shape; the result is written into it and returned.

    Returns
    -------
    ndarray
        [N], t's shape.
    """
    t = _checked('t', t, 'nonnegative', 'time, s')
    if t.size and t.max() > 4.0:
        raise ValueError(f"t must be <= 4.0 s (the end of the run this scene tabulates), got {t.max()!r}")
    return _into(out, t.shape, _phase_sum(t, *_TABLE_STARTUP_LINK_LOAD_2))


_TABLE_STARTUP_MOTOR_SPEED_0 = (
    # edges: phase starts and the end of the run [s]
    np.array([0.0, 0.04406711170105, 0.4, 1.2, 2.0, 4.0]),
    # first: first term of each phase
    np.array([0, 1, 3, 5, 7, 13], dtype=np.intp),
    # powers: power k of tau
    np.array([0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 2, 3, 4], dtype=np.intp),
    # sigmas: decay sigma [1/s]
    np.array([-6.542810601667, -6.021485671952, -1.262954044262, -10.72334838299, -2.836419353872,
              -36.97859625199, -4.486873609035, -84.61459455363, -2.055030044295, -84.61459455363,
              -84.61459455363, -84.61459455363, -84.61459455363]),
    # omegas: angular frequency omega [rad/s]
    np.array([16.93687928793, 17.90756986958, 0.0, 14.09770770106, 0.0, 0.0, 5.23188304444, 0.0,
              6.062779843024, 0.0, 0.0, 0.0, 0.0]),
    # cos_amps: cosine amplitudes
    np.array([1.226122095321e-82, 0.2003773020809, -0.4021199080758, 0.1330373605647,
              -0.4509966274976, -0.1056156761672, 0.01505354071083, -0.02211546824409,
              0.003177529231606, 7.17147283589e-05, -1.16276133221e-07, 1.256844487989e-10,
              -1.018905184945e-13]),
    # sin_amps: sine amplitudes
    np.array([0.3795558660533, 0.1659822723428, 0.0, 0.3614164743081, 0.0, 0.0, -0.146424626445,
              0.0, -0.01335932480694, 0.0, 0.0, 0.0, 0.0]),
    # consts: constant of each phase
    np.array([-1.366297818447e-82, 0.3948992184286, 0.4814997917942, 0.525369884435,
              0.5475935828877]),
)


def startup_motor_speed_0(t, *, out=None):
    """Speed v1 of one side's motors at the wheel rim during the start-up from rest on the stepped rheostat start (start steps held for the setting holds), backlash in both drives. Case 0 (from 0) of those the scene's settings list. Eq Fig. 12.

    Solved for this scene phase by phase in mpmath
    (crane_sym.mechanics.exact_phases).
    The run has 5 phases, each in closed form; they end at
    0.0440671 s crane slips +, 0.4 s motors_left next step, 1.2 s
    motors_left next step, 2 s motors_left next step, 4 s end.

    Parameters
    ----------
    t : array_like
        time [s], 0 <= t <= 4.0
    out : ndarray, optional
        float64 array of t's shape; the result is written into it and returned.

    Returns
    -------
    ndarray
        [m/s], t's shape.
    """
    t = _checked('t', t, 'nonnegative', 'time, s')
    if t.size and t.max() > 4.0:
        raise ValueError(f"t must be <= 4.0 s (the end of the run this scene tabulates), got {t.max()!r}")
    return _into(out, t.shape, _phase_sum(t, *_TABLE_STARTUP_MOTOR_SPEED_0))


_TABLE_STARTUP_MOTOR_SPEED_1 = (
    # edges: phase starts and the end of the run [s]
    np.array([0.0, 0.0844912363767, 0.0844912364767, 0.09568110932053, 0.4, 1.2, 2.0, 4.0]),
    # first: first term of each phase
    np.array([0, 1, 2, 3, 6, 9, 11, 17], dtype=np.intp),
    # powers: power k of tau
    np.array([0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 2, 3, 4], dtype=np.intp),
    # sigmas: decay sigma [1/s]
    np.array([-11.26994983829, -6.542810601667, -6.542810601667, -6.542810601667, -6.021485671952,
              -1.262954044262, -12.03140596751, -10.72334838299, -2.836419353872, -36.97859625199,
              -4.486873609035, -84.61459455363, -2.055030044295, -84.61459455363, -84.61459455363,
              -84.61459455363, -84.61459455363]),
    # omegas: angular frequency omega [rad/s]
    np.array([0.0, 16.93687928793, 16.93687928793, 16.93687928793, 17.90756986958, 0.0,
              13.59821756805, 14.09770770106, 0.0, 0.0, 5.23188304444, 0.0, 6.062779843024, 0.0,
              0.0, 0.0, 0.0]),
    # cos_amps: cosine amplitudes
    np.array([-0.5704099821747, 0.3502964709259, 0.3502964711103, -2.687590338647e-11,
              0.3504722805798, -0.3828716527408, -3.640517076191e-12, 0.1374115912425,
              -0.4601864012272, -0.1064039583354, 0.01488244237908, -0.02209863182053,
              0.003191741855466, 7.166013220345e-05, -1.161876126341e-07, 1.255887656964e-10,
              -1.018129496224e-13]),
    # sin_amps: sine amplitudes
    np.array([0.0, 0.2442343924372, 0.2442343916842, 1.678128250946e-11, 0.1112352947507, 0.0,
              -1.44212379823e-12, 0.4133129123221, 0.0, 0.0, -0.147625991602, 0.0,
              -0.01335069504317, 0.0, 0.0, 0.0, 0.0]),
    # consts: constant of each phase
    np.array([0.5704099821747, -4.709919151398e-42, -5.961764988108e-82, 0.3948992184286,
              0.4814997917942, 0.525369884435, 0.5475935828877]),
)


def startup_motor_speed_1(t, *, out=None):
    """Speed v1 of one side's motors at the wheel rim during the start-up from rest on the stepped rheostat start (start steps held for the setting holds), backlash in both drives. Case 1 (from 0) of those the scene's settings list. Eq Fig. 12.

    Solved for this scene phase by phase in mpmath
    (crane_sym.mechanics.exact_phases).
    The run has 7 phases, each in closed form; they end at
    0.0844912 s link_left closes +, 0.0844912 s link_right closes +,
    0.0956811 s crane slips +, 0.4 s motors_left next step, 1.2 s
    motors_left next step, 2 s motors_left next step, 4 s end.

    Parameters
    ----------
    t : array_like
        time [s], 0 <= t <= 4.0
    out : ndarray, optional
        float64 array of t's shape; the result is written into it and returned.

    Returns
    -------
    ndarray
        [m/s], t's shape.
    """
    t = _checked('t', t, 'nonnegative', 'time, s')
    if t.size and t.max() > 4.0:
        raise ValueError(f"t must be <= 4.0 s (the end of the run this scene tabulates), got {t.max()!r}")
    return _into(out, t.shape, _phase_sum(t, *_TABLE_STARTUP_MOTOR_SPEED_1))


_TABLE_STARTUP_MOTOR_SPEED_2 = (
    # edges: phase starts and the end of the run [s]
    np.array([0.0, 0.1276884291522, 0.1276884291522, 0.135931398866, 0.4, 1.2, 2.0, 4.0]),
    # first: first term of each phase
    np.array([0, 1, 2, 3, 5, 7, 9, 15], dtype=np.intp),
    # powers: power k of tau
    np.array([0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 2, 3, 4], dtype=np.intp),
    # sigmas: decay sigma [1/s]
    np.array([-11.26994983829, -6.542810601667, -6.542810601667, -6.021485671952, -1.262954044262,
              -10.72334838299, -2.836419353872, -36.97859625199, -4.486873609035, -84.61459455363,
              -2.055030044295, -84.61459455363, -84.61459455363, -84.61459455363, -84.61459455363]),
    # omegas: angular frequency omega [rad/s]
    np.array([0.0, 16.93687928793, 16.93687928793, 17.90756986958, 0.0, 14.09770770106, 0.0, 0.0,
              5.23188304444, 0.0, 6.062779843024, 0.0, 0.0, 0.0, 0.0]),
    # cos_amps: cosine amplitudes
    np.array([-0.5704099821747, 0.4351345176058, 0.4351345176058, 0.4157583585491,
              -0.3744993333524, 0.101115455336, -0.4724402826901, -0.1074529694293,
              0.0146505581535, -0.02207616009438, 0.003210703945859, 7.158726222309e-05,
              -1.160694634096e-07, 1.254610565978e-10, -1.017094177504e-13]),
    # sin_amps: sine amplitudes
    np.array([0.0, 0.2114609834871, 0.2114609834871, 0.08742226993527, 0.0, 0.4793195127594, 0.0,
              0.0, -0.1492270985523, 0.0, -0.01333922075183, 0.0, 0.0, 0.0, 0.0]),
    # consts: constant of each phase
    np.array([0.5704099821747, -3.694750246668e-42, -3.898317716275e-83, 0.3948992184286,
              0.4814997917942, 0.525369884435, 0.5475935828877]),
)


def startup_motor_speed_2(t, *, out=None):
    """Speed v1 of one side's motors at the wheel rim during the start-up from rest on the stepped rheostat start (start steps held for the setting holds), backlash in both drives. Case 2 (from 0) of those the scene's settings list. Eq Fig. 12.

    Solved for this scene phase by phase in mpmath
    (crane_sym.mechanics.exact_phases).
    The run has 7 phases, each in closed form; they end at
    0.127688 s link_left closes +, 0.127688 s link_right closes +, 0.135931
    s crane slips +, 0.4 s motors_left next step, 1.2 s motors_left next
    step, 2 s motors_left next step, 4 s end.

    Parameters
    ----------
    t : array_like
        time [s], 0 <= t <= 4.0
    out : ndarray, optional
        float64 array of t's shape; the result is written into it and returned.

    Returns
    -------
    ndarray
        [m/s], t's shape.
    """
    t = _checked('t', t, 'nonnegative', 'time, s')
    if t.size and t.max() > 4.0:
        raise ValueError(f"t must be <= 4.0 s (the end of the run this scene tabulates), got {t.max()!r}")
    return _into(out, t.shape, _phase_sum(t, *_TABLE_STARTUP_MOTOR_SPEED_2))


_TABLE_STARTUP_CRANE_SPEED_0 = (
    # edges: phase starts and the end of the run [s]
    np.array([0.0, 0.04406711170105, 0.4, 1.2, 2.0, 4.0]),
    # first: first term of each phase
    np.array([0, 0, 2, 4, 6, 11], dtype=np.intp),
    # powers: power k of tau
    np.array([0, 0, 0, 0, 0, 0, 0, 0, 1, 2, 3], dtype=np.intp),
    # sigmas: decay sigma [1/s]
    np.array([-6.021485671952, -1.262954044262, -10.72334838299, -2.836419353872, -36.97859625199,
              -4.486873609035, -84.61459455363, -2.055030044295, -84.61459455363, -84.61459455363,
              -84.61459455363]),
    # omegas: angular frequency omega [rad/s]
    np.array([17.90756986958, 0.0, 14.09770770106, 0.0, 0.0, 5.23188304444, 0.0, 6.062779843024,
              0.0, 0.0, 0.0]),
    # cos_amps: cosine amplitudes
    np.array([-0.008303316084088, -0.3865959023445, 0.03997049393671, -0.374481207907,
              -0.002404271276728, -0.08018084420159, -6.577277635924e-05, -0.01949894877428,
              2.132840570207e-07, -3.458124432118e-10, 3.737933581802e-13]),
    # sin_amps: sine amplitudes
    np.array([-0.03005718593372, 0.0, -0.02664395688878, 0.0, 0.0, -0.06476220100986, 0.0,
              -0.01037061948387, 0.0, 0.0, 0.0]),
    # consts: constant of each phase
    np.array([0.0, 0.3948992184286, 0.4814997917942, 0.525369884435, 0.5475935828877]),
)


def startup_crane_speed_0(t, *, out=None):
    """Speed v_k of the crane during the start-up from rest on the stepped rheostat start (start steps held for the setting holds), backlash in both drives. Case 0 (from 0) of those the scene's settings list. Eq Fig. 12.

    Solved for this scene phase by phase in mpmath
    (crane_sym.mechanics.exact_phases).
    The run has 5 phases, each in closed form; they end at
    0.0440671 s crane slips +, 0.4 s motors_left next step, 1.2 s
    motors_left next step, 2 s motors_left next step, 4 s end.

    Parameters
    ----------
    t : array_like
        time [s], 0 <= t <= 4.0
    out : ndarray, optional
        float64 array of t's shape; the result is written into it and returned.

    Returns
    -------
    ndarray
        [m/s], t's shape.
    """
    t = _checked('t', t, 'nonnegative', 'time, s')
    if t.size and t.max() > 4.0:
        raise ValueError(f"t must be <= 4.0 s (the end of the run this scene tabulates), got {t.max()!r}")
    return _into(out, t.shape, _phase_sum(t, *_TABLE_STARTUP_CRANE_SPEED_0))


_TABLE_STARTUP_CRANE_SPEED_1 = (
    # edges: phase starts and the end of the run [s]
    np.array([0.0, 0.0844912363767, 0.0844912364767, 0.09568110932053, 0.4, 1.2, 2.0, 4.0]),
    # first: first term of each phase
    np.array([0, 0, 0, 0, 2, 4, 6, 11], dtype=np.intp),
    # powers: power k of tau
    np.array([0, 0, 0, 0, 0, 0, 0, 0, 1, 2, 3], dtype=np.intp),
    # sigmas: decay sigma [1/s]
    np.array([-6.021485671952, -1.262954044262, -10.72334838299, -2.836419353872, -36.97859625199,
              -4.486873609035, -84.61459455363, -2.055030044295, -84.61459455363, -84.61459455363,
              -84.61459455363]),
    # omegas: angular frequency omega [rad/s]
    np.array([17.90756986958, 0.0, 14.09770770106, 0.0, 0.0, 5.23188304444, 0.0, 6.062779843024,
              0.0, 0.0, 0.0]),
    # cos_amps: cosine amplitudes
    np.array([-0.02680848454345, -0.3680907338852, 0.04613812688262, -0.3821118582419,
              -0.002422216000881, -0.08095122864693, -6.57227037897e-05, -0.01947974694527,
              2.131216846629e-07, -3.455491774875e-10, 3.735087906896e-13]),
    # sin_amps: sine amplitudes
    np.array([-0.0349745158691, 0.0, -0.02868326904595, 0.0, 0.0, -0.06512066003936, 0.0,
              -0.01038923192162, 0.0, 0.0, 0.0]),
    # consts: constant of each phase
    np.array([0.0, 0.0, 0.0, 0.3948992184286, 0.4814997917942, 0.525369884435, 0.5475935828877]),
)


def startup_crane_speed_1(t, *, out=None):
    """Speed v_k of the crane during the start-up from rest on the stepped rheostat start (start steps held for the setting holds), backlash in both drives. Case 1 (from 0) of those the scene's settings list. Eq Fig. 12.

    Solved for this scene phase by phase in mpmath
    (crane_sym.mechanics.exact_phases).
    The run has 7 phases, each in closed form; they end at
    0.0844912 s link_left closes +, 0.0844912 s link_right closes +,
    0.0956811 s crane slips +, 0.4 s motors_left next step, 1.2 s
    motors_left next step, 2 s motors_left next step, 4 s end.

    Parameters
    ----------
    t : array_like
        time [s], 0 <= t <= 4.0
    out : ndarray, optional
        float64 array of t's shape; the result is written into it and returned.

    Returns
    -------
    ndarray
        [m/s], t's shape.
    """
    t = _checked('t', t, 'nonnegative', 'time, s')
    if t.size and t.max() > 4.0:
        raise ValueError(f"t must be <= 4.0 s (the end of the run this scene tabulates), got {t.max()!r}")
    return _into(out, t.shape, _phase_sum(t, *_TABLE_STARTUP_CRANE_SPEED_1))


_TABLE_STARTUP_CRANE_SPEED_2 = (
    # edges: phase starts and the end of the run [s]
    np.array([0.0, 0.1276884291522, 0.1276884291522, 0.135931398866, 0.4, 1.2, 2.0, 4.0]),
    # first: first term of each phase
    np.array([0, 0, 0, 0, 2, 4, 6, 11], dtype=np.intp),
    # powers: power k of tau
    np.array([0, 0, 0, 0, 0, 0, 0, 0, 1, 2, 3], dtype=np.intp),
    # sigmas: decay sigma [1/s]
    np.array([-6.021485671952, -1.262954044262, -10.72334838299, -2.836419353872, -36.97859625199,
              -4.486873609035, -84.61459455363, -2.055030044295, -84.61459455363, -84.61459455363,
              -84.61459455363]),
    # omegas: angular frequency omega [rad/s]
    np.array([17.90756986958, 0.0, 14.09770770106, 0.0, 0.0, 5.23188304444, 0.0, 6.062779843024,
              0.0, 0.0, 0.0]),
    # cos_amps: cosine amplitudes
    np.array([-0.03485758707144, -0.3600416313572, 0.05519963068719, -0.3922867643321,
              -0.002446096047229, -0.08197942285342, -6.56558714802e-05, -0.01945418955483,
              2.129049648147e-07, -3.451977943543e-10, 3.731289758971e-13]),
    # sin_amps: sine amplitudes
    np.array([-0.03711338279705, 0.0, -0.02619966335427, 0.0, 0.0, -0.06559613042667, 0.0,
              -0.01041408008422, 0.0, 0.0, 0.0]),
    # consts: constant of each phase
    np.array([0.0, 0.0, 0.0, 0.3948992184286, 0.4814997917942, 0.525369884435, 0.5475935828877]),
)


def startup_crane_speed_2(t, *, out=None):
    """Speed v_k of the crane during the start-up from rest on the stepped rheostat start (start steps held for the setting holds), backlash in both drives. Case 2 (from 0) of those the scene's settings list. Eq Fig. 12.

    Solved for this scene phase by phase in mpmath
    (crane_sym.mechanics.exact_phases).
    The run has 7 phases, each in closed form; they end at
    0.127688 s link_left closes +, 0.127688 s link_right closes +, 0.135931
    s crane slips +, 0.4 s motors_left next step, 1.2 s motors_left next
    step, 2 s motors_left next step, 4 s end.

    Parameters
    ----------
    t : array_like
        time [s], 0 <= t <= 4.0
    out : ndarray, optional
        float64 array of t's shape; the result is written into it and returned.

    Returns
    -------
    ndarray
        [m/s], t's shape.
    """
    t = _checked('t', t, 'nonnegative', 'time, s')
    if t.size and t.max() > 4.0:
        raise ValueError(f"t must be <= 4.0 s (the end of the run this scene tabulates), got {t.max()!r}")
    return _into(out, t.shape, _phase_sum(t, *_TABLE_STARTUP_CRANE_SPEED_2))
