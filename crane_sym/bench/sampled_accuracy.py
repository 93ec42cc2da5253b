"""How accurate the sampled-load routes are: each against the exact response
of a closed-form load, sampled finer and finer (the error falls as the step
squared, and rounding grows only as the square root of the number of samples).
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Sequence

import mpmath
import numpy as np

from crane_sym.bench.sampled import mp_exact, reference, samples
from crane_sym.markdown import markdown_table
from crane_sym.mechanics.sampled_load import sampled_response, sampled_response_uniform

__all__ = ["AccuracyRow", "accuracy_markdown", "sampled_accuracy"]


@dataclass(frozen=True)
class AccuracyRow:
    """Worst errors of one sampled route on one closed-form load."""

    family: str
    theta: float
    route: str
    points: int
    x_over_peak: float
    v_over_peak: float
    x_pointwise: float
    v_pointwise: float


def _errors(got: np.ndarray, exact: np.ndarray) -> tuple[float, float]:
    """(worst error over the peak, worst pointwise relative error where
    |exact| >= 0.1 peak)."""
    peak = np.max(np.abs(exact))
    away = np.abs(exact) >= 0.1 * peak
    err = np.abs(got - exact)
    return float(np.max(err) / peak), float(np.max(err[away] / np.abs(exact[away])))


def sampled_accuracy(points: int = 100_001, thetas: Sequence[float] = (1e-6, 1e-3, 0.05, 1.0),
                     families: Sequence[str] = ("step", "ramp", "ramp_hold", "trapezoid"),
                     reference_points: int = 500, Omega: float = 7.3,
                     S0: float = 2.5) -> list[AccuracyRow]:
    """Errors of both sampled routes against the mpmath reference on each
    family, with t1 = 1024 steps and exact samples (S at k/1024 of t1); the
    times route gets 0.375 + k q, q the power of 2 nearest theta/Omega.

    Parameters
    ----------
    points : int, optional
        Number of samples of each load.
    thetas : sequence of float, optional
        The values of Omega h (step times frequency) to test.
    families : sequence of str, optional
        Load families (:func:`family_load`).
    reference_points : int, optional
        Samples checked against mpmath.
    Omega : float, optional
        Natural circular frequency [rad/s].
    S0 : float, optional
        Load amplitude [m/s^2].
    """
    m = 1024
    check = np.unique(np.append(np.linspace(0, points - 1, reference_points).astype(int),
                                [1, 2, m]))
    rows = []
    for family in families:
        S = samples(family, np.arange(points) / m, S0, 1.0)
        for theta in thetas:
            dt = theta / Omega
            with mpmath.workdps(50):
                since = [int(k) * mp_exact(dt) for k in check]
                t1 = m * mp_exact(dt)
            q = 2.0 ** round(math.log2(dt))
            t = 0.375 + np.arange(points) * q
            for route, got, (x, v) in (
                    ("sampled_response_uniform", sampled_response_uniform(dt, S, Omega),
                     reference(family, since, Omega, S0, t1)),
                    ("sampled_response (times)", sampled_response(t, S, Omega),
                     reference(family, t[check] - 0.375, Omega, S0, m * q))):
                ex, px = _errors(got.x[check], x)
                ev, pv = _errors(got.v[check], v)
                rows.append(AccuracyRow(family, theta, route, points, ex, ev, px, pv))
    return rows


def accuracy_markdown(rows: Sequence[AccuracyRow]) -> str:
    """The accuracy rows as one Markdown table.

    Parameters
    ----------
    rows : sequence of AccuracyRow
        Rows from :func:`sampled_accuracy`.
    """
    return markdown_table(
        ["load", "Omega h", "route", "points", "x: error / peak", "x': error / peak",
         "x: pointwise", "x': pointwise"],
        [[r.family, f"{r.theta:g}", r.route, r.points, f"{r.x_over_peak:.1e}",
          f"{r.v_over_peak:.1e}", f"{r.x_pointwise:.1e}", f"{r.v_pointwise:.1e}"]
         for r in rows], align="lrlrrrrr")
