"""Kernels of exact phases and the waves on them, that generated modules carry.

A phase ``k·(t − c)`` is formed as a pair (hi, lo) with hi + lo correct to
~2**-104 (``_exact_phase``); the sines and cosines of a pair are corrected by
its low part, and a ``_Phase`` keeps those it has taken, so every kernel one
formula calls on the same phase (waves, sin²(x/2), entire-function helpers)
shares one ``np.sin`` and one ``np.cos``. Ordinary functions, tested in
``tests/test_kernels.py`` and ``tests/test_wave_sums.py``; the code generator
copies the ones a module calls (``DEPENDS``), so generated modules need NumPy
alone.
"""
from __future__ import annotations

import numpy as np

from crane_sym.kernels.arithmetic import _quick_two_sum, _two_product, _two_sum


class _Phase(tuple):
    """A phase pair (hi, lo) that keeps the sines and cosines taken of it, so
    the kernels one formula calls on the same phase share one np.sin and one
    np.cos of each multiple (``_sincos_pair``)."""

    def __new__(cls, hi, lo):
        phase = tuple.__new__(cls, (hi, lo))
        phase.taken = {}
        return phase


def _exact_phase(k, t, c=0.0):
    """k*(t - c) as a pair (hi, lo) with hi + lo correct to ~2**-104
    relative: t - c by TwoSum, the product by TwoProduct. A phase at long
    times or just after a switch, where one rounding is a large error of a
    sine near its zeros."""
    if np.ndim(c) == 0 and c == 0:   # t - 0 is exact: the product alone
        return _Phase(*_two_product(k, t))
    s, e = _two_sum(t, -c)
    p, pe = _two_product(k, s)
    return _Phase(*_quick_two_sum(p, pe + k * e))


def _pair(z):
    """A phase as (hi, lo): a pair from _exact_phase, or a double (lo = 0)."""
    return z if isinstance(z, tuple) else (z, 0.0)


def _sin_pair(z, q):
    """sin(q*z) for a phase pair z (q a power of two: q*hi is exact)."""
    return _sincos_pair(z, q)[0]


def _cos_pair(z, q):
    """cos(q*z) for a phase pair z (q a power of two)."""
    return _sincos_pair(z, q)[1]


def _sincos_pair(z, q):
    """(sin(q*z), cos(q*z)) for a phase pair z (q a power of two), each once;
    kept on a _Phase for the next kernel that asks."""
    taken = getattr(z, "taken", None)
    if taken is not None and q in taken:
        return taken[q]
    hi, lo = _pair(z)
    a = q * hi
    s, c = np.sin(a), np.cos(a)
    if not (np.ndim(lo) == 0 and lo == 0):
        d = q * lo
        s, c = s + c * d, c - s * d
    if taken is not None:
        taken[q] = (s, c)
    return s, c


def _sin_half_squared(z):
    """sin(z/2)**2 for a phase pair z, from its shared sine and cosine:
    (1 - cos z)/2 where cos z < 0, else sin(z)**2/(2 + 2 cos z); neither
    cancels (|cos z| in the unused branch: no division by zero)."""
    s, c = _sincos_pair(z, 1.0)
    return np.where(c < 0, 0.5 - 0.5 * c, s * s / (2.0 + 2.0 * np.abs(c)))


def _cos_half_squared(z):
    """cos(z/2)**2 for a phase pair z, from its shared sine and cosine:
    (1 + cos z)/2 where cos z > 0, else sin(z)**2/(2 - 2 cos z)."""
    s, c = _sincos_pair(z, 1.0)
    return np.where(c > 0, 0.5 + 0.5 * c, s * s / (2.0 + 2.0 * np.abs(c)))


def _wave(b, c, x):
    """b*cos(x) + c*sin(x) for a phase pair x, the two products summed with
    one rounding (TwoProduct): the wave is accurate near its zeros."""
    s, co = _sincos_pair(x, 1.0)
    p, p_err = _two_product(b, co)
    q, q_err = _two_product(c, s)
    return (p + q) + (p_err + q_err)


def _offset_wave(level, gap, b, c, x):
    """level + b*cos(x) + c*sin(x) for a phase pair x, as written where the
    level and the wave do not cancel (the sines shared with other kernels on
    x), and by _offset_back where they do (|sum| < |level|/2). The caller
    supplies gap = level**2 - b**2 - c**2 accurately."""
    s, co = _sincos_pair(x, 1.0)
    direct = level + (b * co + c * s)
    near = np.abs(direct) < 0.5 * np.abs(level)
    if not np.any(near):
        return direct
    direct = np.array(direct, dtype=float)
    pick = lambda v: np.broadcast_to(v, direct.shape)[near]   # noqa: E731
    direct[near] = _offset_back(*map(pick, (level, gap, b, c)), tuple(map(pick, _pair(x))))
    return direct


def _offset_back(level, gap, b, c, x):
    """level + b*cos(x) + c*sin(x) without cancellation where the wave swings
    back towards zero; x is a phase pair. Written level + a*cos(x - d)
    (|d| <= pi/2, a = ±hypot(b, c)); where level and a*cos(x - d) have
    opposite signs it is s*gap/(|level| + |a|) + s*|a|*(1 + q*cos(x - d)),
    s = sign(level), q = s*sign(a), the last factor as 2*cos(...)**2 or
    2*sin(...)**2."""
    hi, lo = _pair(x)
    sb = np.where(b < 0, -1.0, 1.0)
    r = np.hypot(b, c)
    theta, err = _two_sum(hi, -np.arctan2(c * sb, np.abs(b)))
    lo = err + lo
    s2, c2 = np.sin(0.5 * theta), np.cos(0.5 * theta)  # cos, sin of theta from these
    cos_theta = (c2 - s2) * (c2 + s2) - 2.0 * s2 * c2 * lo
    s = np.where(level < 0, -1.0, 1.0)
    q = s * sb
    if np.ndim(q) == 0:                                 # one side for every point
        half = c2 - s2 * (0.5 * lo) if q > 0 else s2 + c2 * (0.5 * lo)
    else:
        half = np.where(q > 0, c2 - s2 * (0.5 * lo), s2 + c2 * (0.5 * lo))
    back = s * (gap / (np.abs(level) + r) + 2.0 * r * half * half)
    return np.where(q * cos_theta >= 0, level + sb * r * cos_theta, back)


#: kernel -> kernels it calls (here or in ``kernels``), so a module carries only what it uses.
DEPENDS = {
    "_Phase": (),
    "_exact_phase": ("_Phase", "_two_sum", "_two_product", "_quick_two_sum"),
    "_pair": (), "_sincos_pair": ("_pair",),
    "_sin_pair": ("_sincos_pair",), "_cos_pair": ("_sincos_pair",),
    "_sin_half_squared": ("_sincos_pair",), "_cos_half_squared": ("_sincos_pair",),
    "_wave": ("_sincos_pair", "_two_product"),
    "_offset_back": ("_pair", "_two_sum"),
    "_offset_wave": ("_sincos_pair", "_offset_back"),
}
