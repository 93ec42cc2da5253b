"""What a scene's run returns: lines, values, panels, and where its model holds.

A derivation's ``scene_report(scene, module)`` returns a :class:`SceneReport`:
lines to print, key values and :class:`Panel` s to plot. A model that does
not hold on part of a panel's x axis (a brake that stops slipping, a load
still resting on the ground) marks that part as :class:`Span` s in
``Panel.invalid`` (:func:`outside` makes them from the valid interval);
``crane_sym.scenes.plots`` greys them, draws the curves there faint, scales the y
axis to the valid part and names the reason in the legend. The report says
so in a line that starts with ``warning:`` (``scenes.run`` refuses a report
that greys a panel without one), and takes its maxima over the valid part
(:func:`valid_mask`).
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Sequence

import numpy as np

__all__ = ["WARNING", "Panel", "SceneReport", "Span", "engineering", "format_quantity",
           "outside", "valid_mask"]

#: How a report line that states a crossed validity begins.
WARNING = "warning:"


@dataclass(frozen=True)
class Span:
    """The open part ``start < x < end`` of a panel's x axis where its model
    does not hold (``-inf``/``inf`` for "from the start"/"to the end"), and
    ``reason``: why, one short legend entry (mathtext allowed)."""

    start: float
    end: float
    reason: str

    def __post_init__(self) -> None:
        if not self.start < self.end:
            raise ValueError(f"span ({self.start}, {self.end}) is empty")
        if not self.reason:
            raise ValueError("a span where the model does not hold needs a reason")


@dataclass
class Panel:
    """One subplot: curves ``(label, x, y)`` sharing a y axis. Text may use
    Matplotlib mathtext (``$K_\\mathrm{дин}$``). Consecutive panels of one
    ``group`` are plotted together, at most four to a figure, titled with it;
    ``styles`` gives Matplotlib line options by curve label; ``invalid`` the
    parts of the x axis where the model does not hold (greyed); ``ylim`` the y
    range when the data's own would hide what matters (cases compared on one
    scale, a curve that runs far off the paper's axes: say so in its label)."""

    title: str
    ylabel: str
    curves: list[tuple[str, np.ndarray, np.ndarray]] = field(default_factory=list)
    xlabel: str = "$t$ [s]"
    group: str = ""
    styles: dict[str, dict] = field(default_factory=dict)
    invalid: list[Span] = field(default_factory=list)
    ylim: tuple[float, float] | None = None


@dataclass
class SceneReport:
    """What a derivation's ``scene_report(scene)`` returns.

    Attributes
    ----------
    lines : list of str
        Text to print, numbers already formatted with units; a line that
        states where the model stops holding starts with :data:`WARNING`.
    values : dict of str to float
        The same key results as numbers (SI), for tests and further use.
    panels : list of Panel
        Curves to plot, one subplot per panel.
    """

    lines: list[str] = field(default_factory=list)
    values: dict[str, float] = field(default_factory=dict)
    panels: list[Panel] = field(default_factory=list)

    @property
    def warnings(self) -> list[str]:
        """The lines that start with :data:`WARNING`."""
        return [line for line in self.lines if line.startswith(WARNING)]


def format_quantity(value: float, unit: str = "", digits: int = 4) -> str:
    """``value`` with ``digits`` significant digits and its unit, e.g. ``"45.31 kN"``.

    Parameters
    ----------
    value : float
        The value.
    unit : str, optional
        Its unit.
    digits : int, optional
        Significant digits.
    """
    text = f"{value:#.{digits}g}"
    if "e" not in text:
        text = text.rstrip(".")
    return f"{text} {unit}".rstrip()


#: The loads an engineer reads in kN or MN, with the unit they are given in (SI).
_SCALED = {"N": "N", "N*m": "N·m"}


def engineering(magnitude: float, unit: str) -> tuple[float, str]:
    """(factor, unit) for a load of about ``magnitude`` in the SI ``unit``: a
    force or torque of a thousand newtons or more in kN or kN·m (a million:
    MN, MN·m), divided by the factor; another unit as it is (factor 1).

    Parameters
    ----------
    magnitude : float
        The size of the values to show (the largest |value|).
    unit : str
        Their SI unit as the toolkit writes it (``N``, ``N*m``).

    >>> engineering(-152100.0, "N")
    (1000.0, 'kN')
    """
    if unit not in _SCALED:
        return 1.0, unit
    size = abs(magnitude)
    if size >= 1e6:
        return 1e6, "M" + _SCALED[unit]
    if size >= 1e3:
        return 1e3, "k" + _SCALED[unit]
    return 1.0, _SCALED[unit]


def outside(start: float, end: float, before: str = "", after: str = "") -> list[Span]:
    """The spans outside the valid interval ``[start, end]``: ``x < start``
    (why: ``before``) unless ``start`` is ``-inf`` or ``before`` empty, and
    ``x > end`` (``after``) unless ``end`` is ``inf`` or ``after`` empty.

    >>> [s.end for s in outside(-math.inf, 2.5, after="crane stopped")]
    [inf]

    Parameters
    ----------
    start, end : float
        The valid interval.
    before, after : str, optional
        Why the model does not hold below ``start`` and above ``end``.
    """
    spans = []
    if before and start > -math.inf:
        spans.append(Span(-math.inf, start, before))
    if after and end < math.inf:
        spans.append(Span(end, math.inf, after))
    return spans


def valid_mask(x: np.ndarray | Sequence[float], spans: Sequence[Span]) -> np.ndarray:
    """True where ``x`` lies in none of ``spans``.

    Parameters
    ----------
    x : array_like
        The x values.
    spans : sequence of Span
        The invalid spans.
    """
    x = np.asarray(x, dtype=float)
    ok = np.ones(x.shape, dtype=bool)
    for span in spans:
        ok &= ~((x > span.start) & (x < span.end))
    return ok
