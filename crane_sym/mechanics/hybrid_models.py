"""A paper's piecewise-linear model behind one small interface: what scenes,
sweeps and the bench reach, whichever paper wrote it.

A paper declares its models in ``derivations/<id>/hybrid.py`` as
``HYBRID_MODELS`` (name -> :class:`HybridModel`). A model takes SI values by
name (``parameters``) and the settings it reads (a scene's, or a sweep's
options: ``settings``), and its ``start`` builds the
:class:`~crane_sym.mechanics.phase_table.HybridRun`: the
:class:`~crane_sym.mechanics.piecewise_linear.HybridSystem`, its initial mode
and state, the end of the run and the instants scheduled in advance. Its
``outputs`` are affine maps of the state, per mode (:class:`HybridOutput`).

Every consumer takes the same path:

- a scene's module tabulates an output (``derivation.TabulatedOutput`` with
  ``run=model.runner(output)``; the printer solves it in mpmath);
- a report solves the run in double (:meth:`HybridModel.solve`) and reads
  curves, peaks and events off the :class:`HybridSolution`;
- a design sweep evaluates a peak per design (:meth:`HybridModel.peak_sweep`,
  the numeric eigenvector route);
- the bench takes the ``HybridRun`` of a tabulated output and integrates the
  same system with SciPy.
"""
from __future__ import annotations

from dataclasses import dataclass, replace
from functools import partial
from typing import Any, Callable, Hashable, Mapping

import numpy as np

from crane_sym.mechanics.phase_table import Affine, HybridRun, largest, values
from crane_sym.mechanics.piecewise_linear import HybridSystem, PiecewiseResult

__all__ = ["HybridModel", "HybridOutput", "HybridSolution"]


@dataclass(frozen=True)
class HybridOutput:
    """One output of a hybrid model: g = w·x + k in each mode.

    Attributes
    ----------
    unit : str
        Unit of g (SI, or ``"1"``).
    description : str
        What g is, one line.
    affine : callable
        ``affine(system)`` gives the map mode -> (w, k) of the built system.
    magnitude : bool
        Its peak is the largest |g| (the value keeping its sign), not the
        largest g.
    """

    unit: str
    description: str
    affine: Callable[[HybridSystem], Affine]
    magnitude: bool = False


@dataclass(frozen=True)
class HybridModel:
    """A piecewise-linear model of a paper, built from values by name.

    Attributes
    ----------
    name : str
        Key in the paper's ``HYBRID_MODELS``.
    summary : str
        What the run is, one sentence.
    parameters : tuple of str
        The SI values ``start`` reads, by name.
    settings : tuple of str
        The settings (scene or sweep options) ``start`` reads.
    start : callable
        ``start(values, settings)`` -> :class:`~crane_sym.mechanics.phase_table.HybridRun`:
        the system, its initial mode and state, the end, the schedule (its
        output is the first of ``outputs``).
    outputs : mapping of str to HybridOutput
        The outputs, by name.
    """

    name: str
    summary: str
    parameters: tuple[str, ...]
    settings: tuple[str, ...]
    start: Callable[[Mapping[str, float], Mapping[str, Any]], HybridRun]
    outputs: Mapping[str, HybridOutput]

    def run(self, values: Mapping[str, float], settings: Mapping[str, Any],
            output: str | None = None, *, exact: bool | None = None) -> HybridRun:
        """The run with ``output`` (default: the first) as its output.

        Parameters
        ----------
        values : mapping of str to float
            SI values by the names of ``parameters``.
        settings : mapping of str to object
            The settings of ``settings``.
        output : str, optional
            Name of one of ``outputs``.
        exact : bool, optional
            The closed forms' route (``piecewise_linear.simulate``).

        Returns
        -------
        HybridRun
        """
        run = self.start(values, settings)
        chosen = self.outputs[output or next(iter(self.outputs))]
        return replace(run, output=chosen.affine(run.system), exact=exact)

    def runner(self, output: str) -> Callable[[Mapping[str, float], Mapping[str, Any]],
                                              HybridRun]:
        """``run(values, settings)`` of one output: what a
        ``derivation.TabulatedOutput`` takes as its ``run``."""
        return partial(self.run, output=output)

    def solve(self, values: Mapping[str, float], settings: Mapping[str, Any], *,
              exact: bool | None = None) -> HybridSolution:
        """The phases of the run, each in closed form, in double.

        Parameters
        ----------
        values, settings : mapping
            As :meth:`run` takes them.
        exact : bool, optional
            The closed forms' route; False (numeric eigenvectors) for many designs.

        Returns
        -------
        HybridSolution
        """
        run = self.run(values, settings, exact=exact)
        return HybridSolution(self, run, run.solve())

    def peak_sweep(self, output: str) -> Callable[[Mapping[str, Any], Mapping[str, Any]],
                                                  np.ndarray]:
        """``evaluate(values, options)`` of a ``derivation.SweepOutput``: the peak
        of ``output`` (|g| where the output says so) per design, one run each,
        the numeric eigenvector route (each design has new matrices)."""
        return partial(_peaks, self, output)


@dataclass(frozen=True)
class HybridSolution:
    """A solved run of a :class:`HybridModel`: its outputs at any times, their
    peaks (per phase at the ends and the stationary points), its events."""

    model: HybridModel
    run: HybridRun
    result: PiecewiseResult

    @property
    def system(self) -> HybridSystem:
        """The built system."""
        return self.run.system

    @property
    def events(self) -> list[tuple[float, str, Hashable]]:
        """(time, event that ended the phase, mode of the phase), in order."""
        return self.result.events

    def state(self, times: np.ndarray) -> np.ndarray:
        """x at ``times``, shape ``times.shape + (n,)``."""
        return self.result.state(times)

    def values(self, output: str, times: np.ndarray) -> np.ndarray:
        """The output ``output`` at ``times`` (inside the run)."""
        return values(self.result, times, self.model.outputs[output].affine(self.system))

    def peak(self, output: str) -> tuple[float, float]:
        """(time, value) of the output's largest value (of |value| if the
        output says so; the value keeps its sign)."""
        chosen = self.model.outputs[output]
        return largest(self.result, self.system, chosen.affine(self.system),
                       magnitude=chosen.magnitude)


def _peaks(model: HybridModel, output: str, values: Mapping[str, Any],
           options: Mapping[str, Any]) -> np.ndarray:
    """The peak of ``output`` for every design of the broadcast ``values``."""
    names = list(values)
    arrays = np.broadcast_arrays(*[np.asarray(values[n], dtype=float) for n in names])
    out = np.empty(arrays[0].shape)
    magnitude = model.outputs[output].magnitude
    for index in np.ndindex(out.shape):
        design = {n: float(a[index]) for n, a in zip(names, arrays)}
        peak = model.solve(design, options, exact=False).peak(output)[1]
        out[index] = abs(peak) if magnitude else peak
    return out
