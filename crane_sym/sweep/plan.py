"""What a design sweep is: the checked plan and its parts.

A :class:`SweepPlan` holds the axes (:class:`Axis`), the outputs
(:class:`OutputSpec`), the fixed SI values, an optional :class:`Limit` and
``--at`` :class:`Window`, and the unit each output is shown in;
:func:`crane_sym.sweep.spec.plan` builds one from the command line, checked.
One unit per quantity: the summary, the dataset's ``display_units`` and the
PNG show an output in :meth:`SweepPlan.unit_of`, an axis in its own unit, a
window in its own unit; a dimensionless quantity in none (:func:`shown_unit`).
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field, replace
from typing import Any

import numpy as np

__all__ = ["Axis", "Limit", "OutputSpec", "SweepError", "SweepPlan", "Window", "shown_unit"]


class SweepError(ValueError):
    """A sweep argument that cannot be honoured; the message names it."""


def shown_unit(unit: str) -> str:
    """``unit`` as a summary prints it: nothing for a dimensionless ``"1"``."""
    return "" if unit.strip() in ("", "1") else unit


@dataclass(frozen=True)
class Axis:
    """One swept parameter: ``n`` values from ``start`` to ``stop`` (both
    included) in ``unit``, evenly or (``log``) geometrically spaced; ``to_si``
    is the factor from ``unit`` to SI, applied once to the whole axis."""

    name: str
    start: float
    stop: float
    n: int
    log: bool
    unit: str
    to_si: float

    def values(self) -> np.ndarray:
        """The axis in the user's unit, endpoints exact."""
        make = np.geomspace if self.log else np.linspace
        out = make(self.start, self.stop, self.n)
        out[0], out[-1] = self.start, self.stop
        return out

    def si(self) -> np.ndarray:
        """The axis in SI."""
        return self.values() * self.to_si


@dataclass(frozen=True)
class Limit:
    """``output <= value`` (or ``>=``), ``value`` in ``unit``; ``si`` is the
    bound in SI as the user gave it (kept when it is shown in another unit)."""

    output: str
    op: str
    value: float
    unit: str
    to_si: float
    si: float

    def text(self) -> str:
        """Normalised, in its unit: ``peak_elastic_force <= 40 kN``."""
        return f"{self.output} {self.op} {self.value:g} {self.unit}".rstrip()

    def shown_in(self, unit: str, to_si: float) -> Limit:
        """The same bound, its value in ``unit``."""
        return replace(self, value=self.si / to_si, unit=unit, to_si=to_si)


@dataclass(frozen=True)
class Window:
    """``--at NAME=START:STOP:N [UNIT]``: ``n`` samples of ``name`` from
    ``start`` to ``stop`` (in ``unit``) over which each output taking ``name``
    is maximised; ``n == 1`` is a plain value (``--at t=120 ms``)."""

    name: str
    start: float
    stop: float
    n: int
    unit: str
    to_si: float

    def si(self) -> np.ndarray:
        """The samples in SI."""
        return np.linspace(self.start, self.stop, self.n) * self.to_si

    def text(self) -> str:
        """``max over t in [0, 1.5] s``."""
        return f"max over {self.name} in [{self.start:g}, {self.stop:g}] {self.unit}".rstrip()


@dataclass(frozen=True)
class OutputSpec:
    """An output to sweep: its generated function (``closed``) or the paper's
    simulated response (``simulated``), arguments in order, SI unit.
    ``uses``: the arguments its value depends on (None: all of ``args``)."""

    name: str
    kind: str
    args: tuple[str, ...]
    unit: str
    summary: str = ""
    uses: tuple[str, ...] | None = None

    @property
    def depends(self) -> tuple[str, ...]:
        """The arguments the output's value depends on, in argument order."""
        return self.args if self.uses is None else self.uses


@dataclass(frozen=True)
class SweepPlan:
    """Everything a sweep needs, checked: the fixed SI values of every other
    argument (``fixed``), the axes in grid order, the outputs, the limit."""

    scene: str
    derivation: str
    axes: tuple[Axis, ...]
    outputs: tuple[OutputSpec, ...]
    fixed: dict[str, float]
    limit: Limit | None = None
    display: dict[str, tuple[str, float]] = field(default_factory=dict)
    options: dict[str, Any] = field(default_factory=dict)
    window: Window | None = None

    @property
    def shape(self) -> tuple[int, ...]:
        """Points per axis."""
        return tuple(a.n for a in self.axes)

    @property
    def points(self) -> int:
        """Designs in the grid."""
        return math.prod(self.shape)

    def unit_of(self, output: str) -> tuple[str, float]:
        """The unit an output is reported in and its factor to SI (``""`` for
        a dimensionless one); ``display``, else the output's SI unit."""
        return self.display.get(output, (shown_unit(self.output(output).unit), 1.0))

    def independent_of(self, output: str) -> tuple[str, ...]:
        """The axes ``output`` does not depend on (constant along them)."""
        uses = self.output(output).depends
        return tuple(a.name for a in self.axes if a.name not in uses)

    def windowed(self, output: str) -> bool:
        """Whether ``output`` is maximised over the ``--at`` window."""
        return self.window is not None and self.window.name in self.output(output).depends

    def output(self, name: str) -> OutputSpec:
        """The output spec called ``name``."""
        return next(o for o in self.outputs if o.name == name)
