"""Numeric functions for derivation 'portal_travel'. Generated; do not edit.

Source: crane_sym.derivations.portal_travel (paper 003_5e8a923a75d2f7ba.txt:
Travel mechanisms of rail-mounted portal cranes: gear geometry, start-up with backlash and support loads).
Specialized to scene 'portal_support_loads' (Paper 003, (3)-(4): largest portal leg load; Table 3's normal law): outputs max_support_load; folded in: psi = 1.3 1, G_g = 98100.0 N, G_pch = 1275000.0 N, G_vs = 392000.0 N, x_o = 2.5 m, c = 6.0 m.
Inputs left as arguments: L_max.
Equations: (3), (4).
Printed by SymPy 1.14.0 with crane_sym 0.1.0; regenerate with `crane-sym generate --scene portal_support_loads --out <folder>`.

Functions and argument order:
    max_support_load(L_max) -> [N]    eq (3), (4)
"""

import numpy as np

__all__ = ['max_support_load']

SCENE_NAME = 'portal_support_loads'
SCENE_TITLE = "Paper 003, (3)-(4): largest portal leg load; Table 3's normal law"


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


def max_support_load(L_max, *, out=None):
    """Largest vertical load on one portal leg, load case 2v (reconstructed portal: see the derivation). Specialized to scene 'portal_support_loads'. Eq (3), (4).

    Parameters
    ----------
    L_max : array_like
        maximum reach [m], > 0; served from 1.5e-5 to 4e7
    out : ndarray, optional
        float64 array of the broadcast shape; the result is written into it and returned.

    Returns
    -------
    ndarray
        [N], broadcast over the arguments.
    """
    if (out is None
            and (type(L_max) in (float, int) or type(L_max) is np.float64)):
        if (1.5e-5 <= L_max <= 4e7):
            try:    # a failed check or a math error: the array path decides
                return np.float64((47862005039879947875/4503599627370496)*L_max + 824192508806006051625/4503599627370496)
            except (ArithmeticError, ValueError):
                pass
    L_max = _checked('L_max', L_max, 'positive', 'maximum reach, m', (1.5e-5, 4e7))
    shape = _broadcast(L_max=L_max)
    return _into(out, shape, (47862005039879947875/4503599627370496)*L_max + 824192508806006051625/4503599627370496)
