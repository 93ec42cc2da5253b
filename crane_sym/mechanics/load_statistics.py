"""Load statistics: exceedance probabilities of a normally distributed load.

For a load R ~ N(m_R, σ_R²) the probability that R exceeds a level r is
Q(u) = P(R > r) = erfc(u/√2)/2 with u = (r − m_R)/σ_R. Computed as
``1 − Φ(u)`` it cancels to 0 beyond u ≈ 8.3 and loses digits long before;
here it is formed from ``erfc`` (exact tail, no subtraction), and its
logarithm, which stays finite where Q underflows (u > 37.5), from the scaled
complementary error function erfcx(t) = exp(t²)·erfc(t):
log Q(u) = log(erfcx(u/√2)/2) − u²/2.
"""
from __future__ import annotations

import math

import numpy as np
from scipy import special


def _standardized(level, mean, std) -> np.ndarray:
    std = np.asarray(std, dtype=float)
    if np.any(~np.isfinite(std)) or np.any(std <= 0):
        raise ValueError("std: the standard deviation must be finite and > 0")
    level, mean = np.asarray(level, dtype=float), np.asarray(mean, dtype=float)
    if np.any(~np.isfinite(level)) or np.any(~np.isfinite(mean)):
        raise ValueError("level and mean must be finite")
    return (level - mean) / std


def exceedance_probability(level, mean, std) -> np.ndarray:
    """P(R > level) for R normal with ``mean`` and ``std``: erfc(u/√2)/2,
    accurate to a few ulp in the far tail (no 1 − Φ)."""
    u = _standardized(level, mean, std)
    return 0.5 * special.erfc(u / math.sqrt(2.0))


def log_exceedance_probability(level, mean, std) -> np.ndarray:
    """log P(R > level): finite far beyond the underflow of P itself.

    For u > 0 from erfcx (no overflow, no cancellation); for u <= 0 as
    log1p(−Q(−u)), with Q(−u) = P(R < level) at most 1/2.

    Parameters
    ----------
    level : float or ndarray
        The level R must exceed.
    mean, std : float or ndarray
        Mean and standard deviation of the normal R (std > 0).
    """
    u = _standardized(level, mean, std)
    t = u / math.sqrt(2.0)
    with np.errstate(divide="ignore"):
        upper = np.log(0.5 * special.erfcx(np.maximum(t, 0.0))) - t * t
        lower = np.log1p(-0.5 * special.erfc(-np.minimum(t, 0.0)))
    return np.where(u > 0, upper, lower)


def level_for_exceedance(probability, mean, std) -> np.ndarray:
    """The level exceeded with ``probability`` (0 < p < 1): m_R + σ_R·u with
    u = √2·erfcinv(2p), exact for tiny p where Φ⁻¹(1 − p) is not."""
    p = np.asarray(probability, dtype=float)
    if np.any(~(p > 0)) or np.any(~(p < 1)):
        raise ValueError("probability must lie in (0, 1)")
    _standardized(0.0, mean, std)
    return np.asarray(mean, dtype=float) + np.asarray(std, dtype=float) * (
        math.sqrt(2.0) * special.erfcinv(2.0 * p))


__all__ = ["exceedance_probability", "level_for_exceedance",
           "log_exceedance_probability"]
