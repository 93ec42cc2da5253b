"""How far a number of a reconstructed model moves with the parameters it had to choose.

A model the paper does not fully state needs values the paper never gives
(a stiffness, a damping ratio, a crane mass). A printed number the model
reproduces with those values is reproduced *through* them: it neither confirms
nor refutes the paper until one knows how far the number moves when the
chosen values go over their plausible ranges together. The band is the
number's range over the whole box of those ranges: every corner of the box
evaluated, then, from the best corner toward each end, a bounded optimiser
(L-BFGS-B inside the box), the lowest and highest values met being the band.
Moving one parameter at a time and stacking the swings is no range: effects
that do not add (a stiff link with little damping) reach past it, and a
print outside such a stack may still lie inside the box's range.

The box is studied lazily, once per evaluator and process, when a band is
first asked for (``Sensitivity.band``): building a derivation costs one run,
its audit the 2**n corners and the optimiser's runs. A paper whose runs are
slow keeps the extremes found as a committed table (:func:`extremes_table`)
and hands them back (``sweep(..., known=...)``); a test studies the box
again and compares. A :class:`Sensitivity`
carries the result into the step that derives the number, where the audit
reads it (``crane_sym.audit.verdicts``): the band is the tolerance that
decides the record.
"""
from __future__ import annotations

import itertools
from dataclasses import dataclass
from typing import Callable, Mapping

import numpy as np

__all__ = ["BoxStudy", "Chosen", "Extreme", "Sensitivity", "extremes_table", "sweep"]

#: Most runs of the optimiser per number and direction (past the corners).
OPTIMISER_RUNS = 40
#: Finite-difference step of the optimiser, as a share of each range.
STEP = 1e-3


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

    def at(self, share: float) -> float:
        """The value (in ``unit``) a share 0 … 1 of the way from ``low`` to ``high``."""
        return self.low + float(share) * (self.high - self.low)


@dataclass(frozen=True)
class Extreme:
    """The lowest or highest value of a number met in the box, and where."""

    value: float
    at: tuple[float, ...]        # each parameter's value there, in its unit
    by: str                      # "a corner" or "the optimiser"

    def text(self, parameters: tuple[Chosen, ...], digits: int = 3) -> str:
        """``"231 (a corner: link stiffness C 2 MN/m, ...)"``."""
        where = ", ".join(f"{p.name} {v:.3g}{' ' + p.unit if p.unit else ''}"
                          for p, v in zip(parameters, self.at))
        return f"{self.value:.{digits}g} ({self.by}: {where})"


class BoxStudy:
    """The numbers an evaluator returns, over the box of its chosen parameters.

    Every run is kept by its point, so the corners are run once for all the
    numbers and the optimiser of one number never repeats a corner."""

    def __init__(self, evaluate: Callable[[Mapping[str, float]], Mapping[str, float]],
                 parameters: tuple[Chosen, ...], fixed: Mapping[str, float] | None = None,
                 known: Mapping[str, tuple[Extreme, Extreme]] | None = None) -> None:
        self.evaluate, self.parameters = evaluate, tuple(parameters)
        self.fixed = dict(fixed or {})
        self._runs: dict[tuple[float, ...], dict[str, float]] = {}
        self._extremes: dict[str, tuple[Extreme, Extreme]] = dict(known or {})

    def run(self, shares: tuple[float, ...]) -> dict[str, float]:
        """The evaluator's numbers at ``shares`` (0 … 1 along each range)."""
        key = tuple(float(s) for s in shares)
        if key not in self._runs:
            values = self.fixed | {p.key: p.at(s) * p.scale
                                   for p, s in zip(self.parameters, key)}
            self._runs[key] = dict(self.evaluate(values))
        return self._runs[key]

    def _point(self, shares) -> tuple[float, ...]:
        return tuple(p.at(s) for p, s in zip(self.parameters, shares))

    def extremes(self, name: str) -> tuple[Extreme, Extreme]:
        """The lowest and highest ``name`` over the box: the corners, then the
        optimiser from the lowest and from the highest corner."""
        if name not in self._extremes:
            from scipy.optimize import minimize   # on use: SciPy's import costs ~0.5 s
            corners = list(itertools.product((0.0, 1.0), repeat=len(self.parameters)))
            values = [self.run(c)[name] for c in corners]
            found = []
            for sign, pick in ((1.0, int(np.argmin(values))), (-1.0, int(np.argmax(values)))):
                best = (values[pick], corners[pick], "a corner")
                result = minimize(lambda x, s=sign: s * self.run(tuple(x))[name],
                                  np.array(corners[pick]), method="L-BFGS-B",
                                  bounds=[(0.0, 1.0)] * len(corners[pick]),
                                  options={"maxfun": OPTIMISER_RUNS, "eps": STEP})
                if result.fun < sign * best[0]:          # result.fun is sign × value
                    best = (sign * float(result.fun), tuple(result.x), "the optimiser")
                found.append(Extreme(best[0], self._point(best[1]), best[2]))
            self._extremes[name] = (found[0], found[1])
        return self._extremes[name]


@dataclass(frozen=True)
class Sensitivity:
    """A derived number at the chosen parameters and its range over their box.

    Parameters
    ----------
    value : float
        The number with every parameter at its chosen value.
    study : BoxStudy
        The box of the chosen parameters, studied when the band is first asked for.
    name : str
        The number's name among the study's.
    """

    value: float
    study: BoxStudy
    name: str
    how: str = ("the range over the whole box of the plausible ranges: all corners, then "
                "a bounded optimiser (L-BFGS-B) from the lowest and the highest corner")

    @property
    def parameters(self) -> tuple[Chosen, ...]:
        """The chosen parameters whose box the band spans."""
        return self.study.parameters

    @property
    def extremes(self) -> tuple[Extreme, Extreme]:
        """The lowest and the highest value over the box, with where."""
        return self.study.extremes(self.name)

    @property
    def band(self) -> tuple[float, float]:
        """The number's lowest and highest value over the box (the chosen
        value included)."""
        low, high = self.extremes
        return min(low.value, self.value), max(high.value, self.value)

    @property
    def spread(self) -> float:
        """Half the band's width relative to the chosen value: the tolerance the
        chosen parameters leave on the number."""
        low, high = self.band
        return (high - low) / (2 * abs(self.value)) if self.value else float("inf")

    def text(self, digits: int = 3) -> str:
        """One paragraph: the band, where its ends are reached, the ranges."""
        low, high = self.band
        lowest, highest = self.extremes
        ranges = "; ".join(f"{p.name} {p.low:g}–{p.high:g}{' ' + p.unit if p.unit else ''}"
                           f" (chosen {p.chosen:g})" for p in self.parameters)
        return (f"{self.value:.{digits}g} at the chosen parameters, {low:.{digits}g}–"
                f"{high:.{digits}g} over their plausible ranges ({self.how}); lowest "
                f"{lowest.text(self.parameters, digits)}, highest "
                f"{highest.text(self.parameters, digits)}; ranges: {ranges}")


def sweep(evaluate: Callable[[Mapping[str, float]], Mapping[str, float]],
          parameters: tuple[Chosen, ...],
          fixed: Mapping[str, float] | None = None,
          known: Mapping[str, tuple[Extreme, Extreme]] | None = None
          ) -> dict[str, Sensitivity]:
    """The sensitivity of every number ``evaluate`` returns to the chosen parameters.

    Parameters
    ----------
    evaluate : callable
        ``evaluate(values) -> {number name: value}``; ``values`` maps every
        ``Chosen.key`` (in the evaluator's unit) and every key of ``fixed``.
    parameters : tuple of Chosen
        The chosen parameters, whose box of plausible ranges the bands span.
    fixed : mapping, optional
        Further inputs of ``evaluate`` that stay as they are.
    known : mapping, optional
        Extremes already found by name (a committed table); the box is studied
        only for the numbers not in it.

    Returns
    -------
    dict of str to Sensitivity
        One per number ``evaluate`` returns, in its order: one run now (the
        chosen values), the box's when a band is first asked for.

    Examples
    --------
    >>> p = (Chosen("a", "a", "", 1.0, 0.0, 2.0, ""), Chosen("b", "b", "", 1.0, 0.0, 2.0, ""))
    >>> s = sweep(lambda v: {"ab": v["a"] * v["b"]}, p)["ab"]
    >>> s.value, s.band
    (1.0, (0.0, 4.0))
    """
    base = dict(fixed or {}) | {p.key: p.chosen * p.scale for p in parameters}
    study = BoxStudy(evaluate, parameters, fixed, known)
    return {name: Sensitivity(float(value), study, name)
            for name, value in evaluate(base).items()}


def extremes_table(sensitivities: Mapping[str, Sensitivity]) -> dict[str, tuple]:
    """The extremes of every number as plain tuples, ``name -> ((value, at, by),
    (value, at, by))``: what a committed table holds (``repr`` of it is a
    Python literal), each box studied now where it was not.

    Parameters
    ----------
    sensitivities : mapping of str to Sensitivity
        The numbers by name, as :func:`sweep` gives them.
    """
    return {name: tuple((float(e.value), tuple(map(float, e.at)), e.by)
                        for e in s.extremes)
            for name, s in sensitivities.items()}
