"""Response of the undamped oscillator to a sampled load.

Users have measured drive-force records, not formulas. For the relative
coordinate of Semenyuk and Vudvud's travel brake and Chovnyuk et al.'s
hoist start-up,

.. math::

    \\ddot x + \\Omega^2 x = S(t), \\qquad x(t_0) = x_0, \\quad \\dot x(t_0) = v_0,

with :math:`S` known at samples :math:`t_0 \\le t_1 \\le \\dots \\le t_N` and
linear between them, Duhamel's integral (Chovnyuk et al., eqs (15)–(18), (33)) is
evaluated exactly, up to rounding, at every sample. The complex state
:math:`w = \\dot x + i\\Omega x` obeys :math:`\\dot w = i\\Omega w + S`, so

.. math::

    w_k = e^{i\\varphi_k}\\Big(w_0 + \\sum_{j<k} e^{-i\\varphi_j} I_j\\Big), \\qquad
    I_j = \\int_0^{h_j} e^{-i\\Omega s}\\, S(t_j + s)\\, ds
        = h_j\\,(S_j A_j + S_{j+1} B_j),

with :math:`\\varphi_k = \\Omega (t_k - t_0)`, :math:`h_j = t_{j+1} - t_j` and
the weights :math:`A_j, B_j` of ``segment_weights`` at
:math:`\\theta_j = \\Omega h_j`. The state :math:`u = w - iS/\\Omega
= \\dot x - i\\ddot x/\\Omega` obeys :math:`\\dot u = i\\Omega u - (i/\\Omega) S'`
and is summed the same way from the slopes, :math:`-i (S_{j+1} - S_j) E_j /
\\Omega`. Each sum is exact for a load linear between samples; each carries
rounding errors of the order of the sum of the magnitudes of its terms.
That bound is small for :math:`w` just after a sudden load (:math:`x`,
:math:`\\dot x` start from 0 while :math:`u` starts from :math:`S/\\Omega`),
and small for :math:`u` under a slow ramp (:math:`\\dot x`, :math:`\\ddot x`
stay small while :math:`w` grows with :math:`S`): x, x' and x'' are read, at
each sample, off the state with the smaller bound.

The work is O(N) in NumPy, without a Python loop over samples: segment
terms, two prefix sums, rotations. Accuracy holds over long records because

* the phases :math:`\\varphi_k` are exact in double-double (one ulp of
  :math:`\\Omega t` costs :math:`10^{-16}\\,\\Omega t` relative), and for a
  uniform record come from :math:`2\\sqrt N` sines and cosines;
* the prefix sums are blocked and compensated (``sampled_states.prefix_sums``,
  carried from chunk to chunk in double-double): a plain ``np.cumsum`` loses
  ~:math:`\\sqrt N` roundings of the sum;
* the weights have no cancellation at small :math:`\\Omega h`
  (:math:`1 - \\cos\\theta = 2\\sin^2(\\theta/2)`, ``kernels.arithmetic._sin_remainder``);
* :math:`|w_0 + \\sum| = |w_k|`: the final rotation cannot amplify errors.

Units (SI, as in Chovnyuk et al., eq (2)): times in s, :math:`S` in m/s^2 (the
reduced load :math:`S = P/m_1 + Q/m_2`), :math:`\\Omega` in rad/s, :math:`x`
in m, :math:`\\dot x` in m/s, :math:`\\ddot x` in m/s^2. Any consistent set of
units works the same way.
"""
from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np
from numpy.typing import ArrayLike

from crane_sym.kernels.arithmetic import _checked, _phase, _sin_remainder, _two_product, _two_sum
from crane_sym.mechanics.sampled_states import Rotations, Weights, respond


class SampledResponse(NamedTuple):
    """The state at the sample times.

    Attributes
    ----------
    x : ndarray
        Displacement :math:`x(t_k)` [m].
    v : ndarray
        Velocity :math:`\\dot x(t_k)` [m/s].
    a : ndarray or None
        Acceleration :math:`\\ddot x(t_k) = S_k - \\Omega^2 x_k` [m/s^2], when
        asked for; at a jump of :math:`S` (a repeated time) the two samples
        hold the values just before and just after it.
    """

    x: np.ndarray
    v: np.ndarray
    a: np.ndarray | None


def segment_weights(theta: ArrayLike) -> Weights:
    """The weights of a linear segment, for :math:`\\theta = \\Omega h \\ge 0`,

    .. math::

        A = \\int_0^1 e^{-i\\theta\\sigma}(1 - \\sigma)\\,d\\sigma, \\qquad
        B = \\int_0^1 e^{-i\\theta\\sigma}\\,\\sigma\\,d\\sigma, \\qquad
        E = A + B = \\int_0^1 e^{-i\\theta\\sigma}\\,d\\sigma,

    so that :math:`\\int_0^h e^{-i\\Omega s} S(s)\\,ds = h\\,(S(0) A + S(h) B)`
    for a linear :math:`S`. Written without cancellation at small
    :math:`\\theta`, with :math:`q = 2\\sin^2(\\theta/2) = 1 - \\cos\\theta`
    and :math:`r = \\sin\\theta - \\theta` (``kernels.arithmetic._sin_remainder``):

    .. math::

        \\Re A = q/\\theta^2, \\quad \\Im A = r/\\theta^2, \\quad
        \\Re B = \\sin\\theta/\\theta - q/\\theta^2, \\quad
        \\Im B = -(r + \\theta q)/\\theta^2, \\quad
        \\Re E = \\sin\\theta/\\theta, \\quad \\Im E = -q/\\theta

    (:math:`\\sin\\theta - \\theta\\cos\\theta = r + \\theta q`, terms of the
    order :math:`\\theta^3/6` and :math:`\\theta^3/2`). Each part is accurate
    to a few ulp of its own size (of :math:`1/\\theta` where it crosses zero);
    below :math:`\\theta = 10^{-20}` the first terms of the series are exact.

    Returns
    -------
    Weights of 1-D ndarrays (a scalar ``theta`` gives length 1)
    """
    theta = np.atleast_1d(np.asarray(theta, dtype=float))
    tiny = theta < 1e-20                        # theta^2 below an ulp: the series' first terms
    th = np.where(tiny, 1.0, theta) if tiny.any() else theta
    r = _sin_remainder(th, 1)                   # sin(th) - th
    inv2 = th * th
    np.divide(1.0, inv2, out=inv2)
    q = np.sin(0.5 * th)
    q *= q
    q *= 2.0                                    # 1 - cos(th)
    im_b = th * q
    im_b += r
    im_b *= -inv2                               # -(r + th q)/th^2
    re_a = q * inv2                             # q/th^2
    re_e = np.sin(th)
    re_e /= th                                  # sin(th)/th
    re_b = re_e - re_a                          # sin(th)/th - q/th^2
    im_a = r * inv2                             # r/th^2
    im_e = q
    im_e /= -th                                 # -q/th
    weights = Weights(re_a, im_a, re_b, im_b, re_e, im_e)
    if tiny.any():
        small = theta[tiny]
        for part, first in zip(weights, (0.5, small / -6, 0.5, small / -3, 1.0, small / -2)):
            part[tiny] = first
    return weights


def _rotation(hi: np.ndarray, lo: np.ndarray) -> np.ndarray:
    """:math:`e^{i(hi + lo)}` for a double-double phase, |lo| <= ulp(hi)."""
    c, s = np.cos(hi), np.sin(hi)
    out = np.empty(np.shape(hi), dtype=complex)
    re, im = out.real, out.imag
    np.multiply(s, lo, out=re)
    np.subtract(c, re, out=re)          # cos(hi) - sin(hi) lo
    np.multiply(c, lo, out=im)
    np.add(s, im, out=im)               # sin(hi) + cos(hi) lo
    return out


def _uniform_rotations(theta: tuple[float, float], n: int) -> Rotations:
    """:math:`e^{ij\\theta}` for the samples j in [first, end), j < n, for a
    double-double :math:`\\theta`.

    With :math:`j = qB + r` and :math:`B \\approx \\sqrt n`, each value is the
    product of two of :math:`2\\sqrt n` rotations computed from exact
    double-double phases: about 2 sqrt(n) sines and cosines instead of 2n,
    and a few ulp of error at any :math:`j\\theta`.
    """
    block = max(1, math.isqrt(n - 1) + 1)
    inner = _rotation(*_phase(np.arange(block, dtype=float), theta))

    def rotations(first: int, end: int) -> np.ndarray:
        q0, q1 = first // block, (end - 1) // block + 1
        outer = _rotation(*_phase(np.arange(q0, q1, dtype=float) * block, theta))
        q, r = np.divmod(np.arange(first, end), block)
        return outer[q - q0] * inner[r]
    return rotations


#: Magnitudes the sampled-load functions serve: every product of three stays
#: far from overflow, and every sum over a record of 1e9 samples with it.
SERVES = 1e90


def _serves(sign: str) -> tuple[float, float]:
    return {"positive": (1.0 / SERVES, SERVES), "nonnegative": (0.0, SERVES)}.get(
        sign, (-SERVES, SERVES))


#: The largest phase Omega*(t_N - t_0) [rad] served: beyond it the low part of
#: a double-double phase is no longer below one radian.
PHASE_SPAN = 1e15


def _phase_span(Omega: float, span: float) -> None:
    if not Omega * span <= PHASE_SPAN:
        raise ValueError(f"Omega*(t[-1] - t[0]) must be <= {PHASE_SPAN:g} rad (the phase of "
                         f"the last sample; a double no longer resolves it beyond), got "
                         f"{Omega * span:.3g}")


def _scalar(value: object, name: str, sign: str, what: str) -> float:
    array = _checked(name, value, sign, what, _serves(sign))
    if array.ndim != 0:
        raise ValueError(f"{name} must be a scalar ({what}), got shape {array.shape}")
    return float(array)


def _load(S: ArrayLike, n: int | None) -> np.ndarray:
    S = _checked("S", S, "real", "load samples, m/s^2", _serves("real"))
    if S.ndim != 1:
        raise ValueError(f"S must be a 1-D array of load samples, got shape {S.shape}")
    if n is not None and S.size != n:
        raise ValueError(f"S must have one sample per time: t has {n}, S has {S.size}")
    if S.size < 2:
        raise ValueError(f"S needs at least 2 samples, got {S.size}")
    return S


def _times(t: ArrayLike) -> np.ndarray:
    t = _checked("t", t, "real", "sample times, s", _serves("real"))
    if t.ndim != 1:
        raise ValueError(f"t must be a 1-D array of sample times, got shape {t.shape}")
    if t.size < 2:
        raise ValueError(f"t needs at least 2 samples, got {t.size}")
    step = np.diff(t)
    if np.any(step < 0):
        k = int(np.argmax(step < 0))
        raise ValueError(f"t must be non-decreasing: t[{k + 1}] = {float(t[k + 1])!r} < "
                         f"t[{k}] = {float(t[k])!r}")
    same = step == 0
    if np.any(same[1:] & same[:-1]):
        k = int(np.argmax(same[1:] & same[:-1]))
        raise ValueError(f"t repeats t[{k}] = {float(t[k])!r} more than twice (one repeat marks "
                         f"a jump of S; t must otherwise increase)")
    return t


def sampled_response(t: ArrayLike, S: ArrayLike, Omega: float, x0: float = 0.0,
                     v0: float = 0.0, *, acceleration: bool = False) -> SampledResponse:
    """Exact response of :math:`\\ddot x + \\Omega^2 x = S(t)` to a load linear
    between samples, at the sample times.

    Parameters
    ----------
    t : array_like, shape (N + 1,)
        Sample times [s], increasing, uniform or not. A time given twice
        marks a jump of the load: ``S`` holds the values before and after it.
    S : array_like, shape (N + 1,)
        The load at those times [m/s^2], the reduced load
        :math:`S = P/m_1 + Q/m_2` of Chovnyuk et al., eq (2) (a force over a mass).
    Omega : float
        Natural circular frequency :math:`\\Omega` [rad/s], > 0.
    x0, v0 : float
        :math:`x(t_0)` [m] and :math:`\\dot x(t_0)` [m/s].
    acceleration : bool
        Also return :math:`\\ddot x` [m/s^2] (equal to :math:`S - \\Omega^2 x`,
        but not computed as that difference, which would cancel under a slow
        load).

    Returns
    -------
    SampledResponse
        ``x`` [m], ``v`` [m/s] and ``a`` [m/s^2] (None unless asked for), one
        value per sample.

    Raises
    ------
    ValueError
        Naming the argument: times decreasing or repeated more than twice,
        shapes that do not match, NaN or inf anywhere, ``Omega <= 0``, a
        magnitude beyond ``SERVES`` = 1e90 (``Omega`` below 1e-90), a phase
        ``Omega*(t[-1] - t[0])`` beyond ``PHASE_SPAN`` = 1e15 rad: inside those
        bounds every result is finite.
    TypeError
        For strings or non-numeric arrays.

    Exact for a load linear between samples, up to rounding that grows like
    the square root of N: against mpmath (``bench.sampled_accuracy.sampled_accuracy``:
    step, ramp, ramp-hold, trapezoid, N = 1e5, :math:`\\Omega h` from 1e-6
    to 1) the errors of x and x' stay below 2e-14 of their peaks. A load
    curved between samples is replaced by its chords (an error
    :math:`O(h^2)`). The work is
    O(N): two sines and cosines per sample and per segment, two blocked,
    compensated prefix sums. For a uniform record,
    ``sampled_response_uniform`` needs none of the per-sample sines and
    cosines.
    """
    t = _times(t)
    S = _load(S, t.size)
    Omega = _scalar(Omega, "Omega", "positive", "natural circular frequency, rad/s")
    x0 = _scalar(x0, "x0", "real", "initial displacement, m")
    v0 = _scalar(v0, "v0", "real", "initial velocity, m/s")
    _phase_span(Omega, float(t[-1]) - float(t[0]))
    return _sampled(t, S, Omega, x0, v0, acceleration, compensated=True)


def _sampled(t: np.ndarray, S: np.ndarray, Omega: float, x0: float, v0: float,
             acceleration: bool, compensated: bool) -> SampledResponse:
    h = np.diff(t)
    uniform = bool(h[0] > 0 and np.all(h == h[0]))
    one = Weights(*(float(w[0]) for w in segment_weights(Omega * h[0]))) if uniform else None

    def rotations(first: int, end: int) -> np.ndarray:
        since = _two_sum(t[first:end], -t[0])    # t - t0, exactly
        return _rotation(*_phase(Omega, since))

    def segments(first: int, end: int) -> tuple:
        if uniform:                              # one step: one set of weights
            return float(h[0]), one
        return h[first:end], segment_weights(Omega * h[first:end])
    return SampledResponse(*respond(S, Omega, rotations, segments, x0, v0, acceleration,
                                    compensated))


def sampled_response_uniform(dt: float, S: ArrayLike, Omega: float, x0: float = 0.0,
                             v0: float = 0.0, *, acceleration: bool = False
                             ) -> SampledResponse:
    """``sampled_response`` for samples at :math:`t_0 + k\\,dt` exactly,
    k = 0 .. N (:math:`t_0` does not matter: the system is time-invariant).

    Parameters
    ----------
    dt : float
        Sampling step [s], > 0.
    S, Omega, x0, v0, acceleration
        As in ``sampled_response``.

    One set of segment weights serves every segment, and the phases
    :math:`k\\,\\Omega\\,dt` come from about :math:`2\\sqrt N` sines and cosines
    (``_uniform_rotations``): the cheapest route for a measured record.
    """
    dt = _scalar(dt, "dt", "positive", "sampling step, s")
    S = _load(S, None)
    Omega = _scalar(Omega, "Omega", "positive", "natural circular frequency, rad/s")
    x0 = _scalar(x0, "x0", "real", "initial displacement, m")
    v0 = _scalar(v0, "v0", "real", "initial velocity, m/s")
    _phase_span(Omega, dt * (S.size - 1))
    return _uniform(dt, S, Omega, x0, v0, acceleration, compensated=True)


def _uniform(dt: float, S: np.ndarray, Omega: float, x0: float, v0: float,
             acceleration: bool, compensated: bool) -> SampledResponse:
    theta = _two_product(Omega, dt)            # Omega*dt, exactly
    weights = Weights(*(float(w[0]) for w in segment_weights(theta[0])))
    return SampledResponse(*respond(S, Omega, _uniform_rotations(theta, S.size),
                                    lambda first, end: (dt, weights), x0, v0, acceleration,
                                    compensated))
