"""Numeric functions for derivation 'hoist_brakes'. Generated; do not edit.

Source: crane_sym.derivations.hoist_brakes (paper 001_544065b666a6bc39.txt:
Hoists with safety brakes: gearbox torque in an emergency stop).
Specialized to scene 'hoist_table1' (Table 1 hoist: emergency stop with safety brakes): outputs rigid_hook_speed_hoisting, rigid_hook_speed_lowering, elastic_natural_frequency, backlash_at_motor_shaft, elastic_gearbox_torque; folded in: omega1 = 157.07963267948966 rad/s, J1 = 20.0 kg*m^2, J2 = 500.0 kg*m^2, m_h = 10000.0 kg, m_p = 52000.0 kg, m_r = 52000.0 kg, r = 0.5 m, i_g = 26.2 1, i_t = 4.0 1, g = 9.81 m/s^2, M_SB = 130000.0 N*m, M_BB = 5800.0 N*m, c = 40000.0 N*m/rad, d_t = 1.0 s, t_SB = 0.1 s, t_BB = 0.4 s, delta = 0.05235987755982989 rad.
Equations: (1), Fig. 9.
Printed by SymPy 1.14.0 with crane_sym 0.1.0; regenerate with `crane-sym generate --scene hoist_table1 --out <folder>`.

Functions and argument order:
    rigid_hook_speed_hoisting(t) -> [m/s]    eq (1)
    rigid_hook_speed_lowering(t) -> [m/s]    eq (1)
    elastic_natural_frequency() -> [rad/s]    eq Fig. 9
    backlash_at_motor_shaft() -> [rad]    eq Fig. 9
    elastic_gearbox_torque(t) -> [1]    eq Fig. 9
"""

import numpy as np

__all__ = ['rigid_hook_speed_hoisting', 'rigid_hook_speed_lowering', 'elastic_natural_frequency', 'backlash_at_motor_shaft', 'elastic_gearbox_torque']

SCENE_NAME = 'hoist_table1'
SCENE_TITLE = 'Table 1 hoist: emergency stop with safety brakes'


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


def rigid_hook_speed_hoisting(t, *, out=None):
    """Hook speed of the rigid drive, hoisting, after an emergency stop at t = 0: motor torque lost, brakes after their delays (Fig. 5). Specialized to scene 'hoist_table1'. Eq (1).

    Parameters
    ----------
    t : array_like
        time since the emergency stop [s], >= 0; served from 0.0 to 1e7
    out : ndarray, optional
        float64 array of the broadcast shape; the result is written into it and returned.

    Returns
    -------
    ndarray
        [m/s], broadcast over the arguments.
    """
    if (out is None
            and (type(t) in (float, int) or type(t) is np.float64)):
        if (0.0 <= t <= 1e7):
            try:    # a failed check or a math error: the array path decides
                x0 = (t <= 3602879701896397/36028797018963968)
                x1 = (t <= 3602879701896397/9007199254740992)
                return np.float64((((35184372088832/7374644389819187)*((5526748243772219/35184372088832 - 31563240217898936038604453381039675/240814792243731584959521748775076*t) if x0 else (380203393868225896107927431037056805011223607411/2118229313699556594490145576529263574864887808 - 4073022120124561968745557783548175/11467371059225313569501035655956*t) if x1 else (25692637231461402886596363568314821471849130703031/90377784051181081364912877931915245860901879808 - 148620505179114067723167995330035715/240814792243731584959521748775076*t))) if (((t < 332730682526853830747576052992198902627202103411/277633197038935744755715933699117118675904102400)) if x0 else ((((t < 380203393868225896107927431037056805011223607411/752360310452656372006581127860164255283570278400)) if x1 else ((t < 77077911694384208659789090704944464415547392109093/167331812936068246568838292165462359392118804316160))))) else (0)))
            except (ArithmeticError, ValueError):
                pass
    t = _checked('t', t, 'nonnegative', 'time since the emergency stop, s', (0.0, 1e7))
    shape = _broadcast(t=t)
    _one = out is None and not shape
    out = _out(out, shape)
    for _o, (t,) in _spans(out, shape, t):
        x0 = np.less_equal(t, 3602879701896397/36028797018963968)
        x1 = np.less_equal(t, 3602879701896397/9007199254740992)
        _o[...] = np.select([np.logical_or.reduce((np.logical_and.reduce((x0,np.less(t, 332730682526853830747576052992198902627202103411/277633197038935744755715933699117118675904102400))),np.logical_and.reduce((x1,np.logical_not(x0),np.less(t, 380203393868225896107927431037056805011223607411/752360310452656372006581127860164255283570278400))),np.logical_and.reduce((np.logical_not(x0),np.logical_not(x1),np.less(t, 77077911694384208659789090704944464415547392109093/167331812936068246568838292165462359392118804316160))))),True], [(35184372088832/7374644389819187)*np.select([x0,x1,True], [5526748243772219/35184372088832 - 31563240217898936038604453381039675/240814792243731584959521748775076*t,380203393868225896107927431037056805011223607411/2118229313699556594490145576529263574864887808 - 4073022120124561968745557783548175/11467371059225313569501035655956*t,25692637231461402886596363568314821471849130703031/90377784051181081364912877931915245860901879808 - 148620505179114067723167995330035715/240814792243731584959521748775076*t], default=np.nan),0], default=np.nan)
    return out[()] if _one else out


def rigid_hook_speed_lowering(t, *, out=None):
    """Hook speed of the rigid drive, lowering, after an emergency stop at t = 0: motor torque lost, brakes after their delays (Fig. 5). Specialized to scene 'hoist_table1'. Eq (1).

    Parameters
    ----------
    t : array_like
        time since the emergency stop [s], >= 0; served from 0.0 to 1e7
    out : ndarray, optional
        float64 array of the broadcast shape; the result is written into it and returned.

    Returns
    -------
    ndarray
        [m/s], broadcast over the arguments.
    """
    if (out is None
            and (type(t) in (float, int) or type(t) is np.float64)):
        if (0.0 <= t <= 1e7):
            try:    # a failed check or a math error: the array path decides
                x0 = (t <= 3602879701896397/36028797018963968)
                x1 = (t <= 3602879701896397/9007199254740992)
                return np.float64((((35184372088832/7374644389819187)*(((31563240217898936038604453381039675/240814792243731584959521748775076)*t + 5526748243772219/35184372088832) if x0 else (380203393868225896107927431037056805011223607411/2118229313699556594490145576529263574864887808 - 22406984086817929266447806692432325/240814792243731584959521748775076*t) if x1 else (25692637231461402886596363568314821471849130703031/90377784051181081364912877931915245860901879808 - 85494024743316195645959088567956365/240814792243731584959521748775076*t))) if ((True) if x0 else ((((t < 380203393868225896107927431037056805011223607411/197093916374784882495149260461930017931762073600)) if x1 else ((t < 77077911694384208659789090704944464415547392109093/96257714494100695911375013138488377011087354101760))))) else (0)))
            except (ArithmeticError, ValueError):
                pass
    t = _checked('t', t, 'nonnegative', 'time since the emergency stop, s', (0.0, 1e7))
    shape = _broadcast(t=t)
    _one = out is None and not shape
    out = _out(out, shape)
    for _o, (t,) in _spans(out, shape, t):
        x0 = np.less_equal(t, 3602879701896397/36028797018963968)
        x1 = np.less_equal(t, 3602879701896397/9007199254740992)
        _o[...] = np.select([np.logical_and.reduce((np.logical_or.reduce((x0,x1,np.less(t, 77077911694384208659789090704944464415547392109093/96257714494100695911375013138488377011087354101760))),np.logical_or.reduce((x0,np.logical_not(x1),np.less(t, 380203393868225896107927431037056805011223607411/197093916374784882495149260461930017931762073600))))),True], [(35184372088832/7374644389819187)*np.select([x0,x1,True], [(31563240217898936038604453381039675/240814792243731584959521748775076)*t + 5526748243772219/35184372088832,380203393868225896107927431037056805011223607411/2118229313699556594490145576529263574864887808 - 22406984086817929266447806692432325/240814792243731584959521748775076*t,25692637231461402886596363568314821471849130703031/90377784051181081364912877931915245860901879808 - 85494024743316195645959088567956365/240814792243731584959521748775076*t], default=np.nan),0], default=np.nan)
    return out[()] if _one else out


def elastic_natural_frequency(*, out=None):
    """Natural frequency of the two-mass drive in contact (motor shafts J1 against everything beyond the gearbox input, stiffness c). Specialized to scene 'hoist_table1'. Eq Fig. 9.

    Parameters
    ----------

    out : ndarray, optional
        float64 array of the broadcast shape; the result is written into it and returned.

    Returns
    -------
    ndarray
        [rad/s], broadcast over the arguments.
    """
    shape = _broadcast()
    return _into(out, shape, 143.8559563251128)


def backlash_at_motor_shaft(*, out=None):
    """The drum-coupling backlash seen at the motor shaft. Specialized to scene 'hoist_table1'. Eq Fig. 9.

    Parameters
    ----------

    out : ndarray, optional
        float64 array of the broadcast shape; the result is written into it and returned.

    Returns
    -------
    ndarray
        [rad], broadcast over the arguments.
    """
    shape = _broadcast()
    return _into(out, shape, 27823993466796606199971640168145/20282409603651670423947251286016)


_TABLE_ELASTIC_GEARBOX_TORQUE = (
    # edges: phase starts and the end of the run [s]
    np.array([0.0, 0.1, 0.1074719531602, 0.1479346131459, 0.1715070637225, 0.2119697237082,
              0.2277688696214, 0.2682315296071, 0.2918039801837, 0.3322666401694, 0.3480657860826,
              0.3885284460683, 0.4, 0.4118056961865, 0.4419769195551, 0.4619850901963,
              0.4921563135649, 0.5151610863832, 0.5453323097518, 0.565340480393, 0.5955117037616,
              0.6185164765799, 0.6486876999485, 0.6686958705897, 0.6842494680993, 0.7013648239873,
              0.7026328769089, 0.7248067653936, 0.7922500296236, 0.8100663517856, 1.0]),
    # first: first term of each phase
    np.array([0, 1, 2, 2, 3, 3, 4, 4, 5, 5, 6, 6, 7, 8, 8, 9, 9, 10, 10, 11, 11, 12, 12, 13, 13,
              13, 14, 15, 15, 15, 15], dtype=np.intp),
    # powers: power k of tau
    np.array([0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0], dtype=np.intp),
    # sigmas: decay sigma [1/s]
    np.array([0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0]),
    # omegas: angular frequency omega [rad/s]
    np.array([143.8559563251, 143.8559563251, 143.8559563251, 143.8559563251, 143.8559563251,
              143.8559563251, 143.8559563251, 143.8559563251, 143.8559563251, 143.8559563251,
              143.8559563251, 143.8559563251, 143.8559563251, 44.72135955, 143.8559563251]),
    # cos_amps: cosine amplitudes
    np.array([0.09664386693908, 1.520892607331, 0.6412993836655, 0.6412993836655, 0.6412993836655,
              0.6412993836655, 0.6412993836655, -5.343055714335, 0.4481324109246, 0.4481324109246,
              0.4481324109246, 0.4481324109246, 0.4481324109246, -1.998750452139, -0.2617751882994]),
    # sin_amps: sine amplitudes
    np.array([0.0, -0.09367689765358, -5.115125536812, 1.382253516797, -5.115125536812,
              1.382253516797, -5.115125536812, -0.2332811737762, 3.384304170047, -5.329337840183,
              3.384304170047, -5.329337840183, 3.384304170047, -12.58181901073, -3.869879445083]),
    # consts: constant of each phase
    np.array([0.9033561330609, -0.6412993836655, 0.0, -0.6412993836655, 0.0, -0.6412993836655,
              0.0, -0.6412993836655, 0.0, -0.6412993836655, 0.0, -0.6412993836655,
              -0.4481324109246, 0.0, -0.4481324109246, 0.0, -0.4481324109246, 0.0,
              -0.4481324109246, 0.0, -0.4481324109246, 0.0, -0.4481324109246, 0.0, 0.0,
              1.998750452139, -0.4481324109246, 0.0, 0.0, 0.0]),
)


def elastic_gearbox_torque(t, *, out=None):
    """Relative gearbox torque M_G/M_st of the elastic drive with the coupling backlash, emergency stop while lowering the payload m_p: motor torque lost at t = 0, safety brakes after t_SB, service brakes after t_BB, brakes that stick at zero speed. Eq Fig. 9.

    Solved for this scene phase by phase in mpmath
    (crane_sym.mechanics.exact_phases).
    The run has 30 phases, each in closed form; they end at
    0.1 s safety engages, 0.107472 s coupling opens, 0.147935 s coupling
    closes -, 0.171507 s coupling opens, 0.21197 s coupling closes +,
    0.227769 s coupling opens, 0.268232 s coupling closes -, 0.291804 s
    coupling opens, 0.332267 s coupling closes +, 0.348066 s coupling opens,
    0.388528 s coupling closes -, 0.4 s service engages, 0.411806 s coupling
    opens, 0.441977 s coupling closes +, 0.461985 s coupling opens, 0.492156
    s coupling closes -, 0.515161 s coupling opens, 0.545332 s coupling
    closes +, 0.56534 s coupling opens, 0.595512 s coupling closes -,
    0.618516 s coupling opens, 0.648688 s coupling closes +, 0.668696 s
    coupling opens, 0.684249 s shaft rests, 0.701365 s coupling closes -,
    0.702633 s shaft slips +, 0.724807 s coupling opens, 0.79225 s shaft
    rests, 0.810066 s motor rests, 1 s end.

    Parameters
    ----------
    t : array_like
        time [s], 0 <= t <= 1.0
    out : ndarray, optional
        float64 array of t's shape; the result is written into it and returned.

    Returns
    -------
    ndarray
        [1], t's shape.
    """
    t = _checked('t', t, 'nonnegative', 'time, s')
    if t.size and t.max() > 1.0:
        raise ValueError(f"t must be <= 1.0 s (the end of the run this scene tabulates), got {t.max()!r}")
    return _into(out, t.shape, _phase_sum(t, *_TABLE_ELASTIC_GEARBOX_TORQUE))
