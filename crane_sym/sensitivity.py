"""How far a number of a reconstructed model moves with the parameters it had to choose.

A model the paper does not fully state needs values the paper never gives
(a stiffness, a damping ratio, a crane mass). A printed number the model
reproduces with those values is reproduced *through* them: it neither confirms
nor refutes the paper until one knows how far the number moves when the
chosen values go over their plausible ranges. :func:`sweep` measures that:
each parameter alone to both ends of its range, the others at their chosen
values (the swing shown per parameter). The band is the swings stacked: the
chosen value plus every parameter's largest rise, minus every parameter's
largest fall, as a worst-case tolerance stack-up adds them. Running the
corners of the ranges instead costs 2**n runs and reaches combinations no
one would choose (a stiff, undamped, weakly started crane at once); the
stack-up needs 2n runs and is exact for effects that add. A
:class:`Sensitivity` carries the result into the step that derives the
number, where the audit reads it (``crane_sym.audit.verdicts``): the band is the
tolerance that decides the record.
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Callable, Mapping

__all__ = ["Chosen", "Sensitivity", "Swing", "sweep"]


@dataclass(frozen=True)
class Chosen:
    """A parameter the paper does not state, the value chosen and its plausible range.

    Parameters
    ----------
    key : str
        The name the model's evaluator knows it by (e.g. ``"c_l"``).
    name : str
        What it is, in words (e.g. ``"link stiffness c"``).
    unit : str
        Unit of ``chosen``, ``low`` and ``high`` as written in the report.
    chosen, low, high : float
        The value used and the ends of the plausible range, in ``unit``.
    why : str
        Where the range comes from (a catalogue, a standard, the text).
    scale : float
        Factor from ``unit`` to the evaluator's unit (SI), default 1.
    """

    key: str
    name: str
    unit: str
    chosen: float
    low: float
    high: float
    why: str
    scale: float = 1.0

    def __post_init__(self) -> None:
        if not self.low <= self.chosen <= self.high:
            raise ValueError(f"{self.key}: the chosen value {self.chosen} is outside its "
                             f"plausible range [{self.low}, {self.high}]")


@dataclass(frozen=True)
class Swing:
    """The number at both ends of one parameter's plausible range."""

    parameter: Chosen
    at_low: float
    at_high: float

    def text(self, digits: int = 3) -> str:
        """``"link stiffness c 2–10 MN/m (chosen 5): 231–251"``."""
        p = self.parameter
        unit = f" {p.unit}" if p.unit else ""
        return (f"{p.name} {p.low:g}–{p.high:g}{unit} (chosen {p.chosen:g}): "
                f"{self.at_low:.{digits}g}–{self.at_high:.{digits}g}")


@dataclass(frozen=True)
class Sensitivity:
    """A derived number at the chosen parameters and its swing with each of them.

    Parameters
    ----------
    value : float
        The number with every parameter at its chosen value.
    swings : tuple of Swing
        One per chosen parameter, each moved alone over its plausible range.
    """

    value: float
    swings: tuple[Swing, ...]
    how: str = ("each chosen parameter alone to both ends of its plausible range, "
                "the rises and the falls stacked")

    @property
    def band(self) -> tuple[float, float]:
        """The chosen value minus every parameter's largest fall, plus every
        parameter's largest rise (a worst-case stack-up of the swings)."""
        v = self.value
        fall = sum(max(0.0, v - min(s.at_low, s.at_high)) for s in self.swings)
        rise = sum(max(0.0, max(s.at_low, s.at_high) - v) for s in self.swings)
        return v - fall, v + rise

    @property
    def spread(self) -> float:
        """Half the band's width relative to the chosen value: the tolerance the
        chosen parameters leave on the number."""
        low, high = self.band
        return (high - low) / (2 * abs(self.value)) if self.value else float("inf")

    def text(self, digits: int = 3) -> str:
        """One paragraph: the band, then each parameter's swing, largest first."""
        low, high = self.band
        swings = sorted(self.swings, key=lambda s: -abs(s.at_high - s.at_low))
        return (f"{self.value:.{digits}g} at the chosen parameters, {low:.{digits}g}–"
                f"{high:.{digits}g} over their plausible ranges ({self.how}): "
                + "; ".join(s.text(digits) for s in swings))


def sweep(evaluate: Callable[[Mapping[str, float]], Mapping[str, float]],
          parameters: tuple[Chosen, ...],
          fixed: Mapping[str, float] | None = None) -> dict[str, Sensitivity]:
    """The sensitivity of every number ``evaluate`` returns to the chosen parameters.

    Parameters
    ----------
    evaluate : callable
        ``evaluate(values) -> {number name: value}``; ``values`` maps every
        ``Chosen.key`` (in the evaluator's unit) and every key of ``fixed``.
    parameters : tuple of Chosen
        The chosen parameters, each moved alone to ``low`` and ``high``.
    fixed : mapping, optional
        Further inputs of ``evaluate`` that stay as they are.

    Returns
    -------
    dict of str to Sensitivity
        One per number ``evaluate`` returns, in its order (1 + 2n runs).
    """
    base = dict(fixed or {}) | {p.key: p.chosen * p.scale for p in parameters}
    at_chosen = dict(evaluate(base))
    ends = {p.key: (evaluate(base | {p.key: p.low * p.scale}),
                    evaluate(base | {p.key: p.high * p.scale})) for p in parameters}
    return {name: Sensitivity(value, tuple(Swing(p, ends[p.key][0][name], ends[p.key][1][name])
                                           for p in parameters))
            for name, value in at_chosen.items()}
