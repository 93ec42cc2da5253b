"""A value a part reports (``Equations.outputs``: a DC motor's current, a
span's force derived from its energies) at its largest over a run, for a
[[formula]] that names it (``<span>.force_peak``)."""
from __future__ import annotations

from dataclasses import dataclass

from sympy.physics.units import Dimension

from crane_sym.components.model import ComponentRun, Model
from crane_sym.components.parts import DIMENSIONS, ROTATING, TRANSLATING, ComponentError
from crane_sym.mechanics.phase_table import largest

__all__ = ["ReportedPeak", "reported_peak"]

#: The dimension of a reported load by its SI unit.
LOADS = {"N": DIMENSIONS["load"][TRANSLATING], "N*m": DIMENSIONS["load"][ROTATING]}


@dataclass(frozen=True)
class ReportedPeak:
    """The largest |value| (signed) of what a part reports, its unit and
    dimension, and how it was found."""

    value: float
    time: float
    unit: str
    dimension: Dimension
    how: str


def reported_peak(model: Model, path: str, run: ComponentRun | None,
                  what: str) -> ReportedPeak:
    """The peak over ``run`` of the ``what`` that part ``<name>`` of
    ``path`` (``<name>.<...>``) reports; ComponentError, one line, where
    no part of that name reports it or no run is given.

    Parameters
    ----------
    model : Model
        The file's model.
    path : str
        The quantity's name, its part's name first.
    run : ComponentRun or None
        The file's run.
    what : str
        What the part reports (``force``).
    """
    name = path.partition(".")[0]
    found = [out for out in model.equations.outputs if out[:2] == (name, what)]
    if not found or found[0][2] not in LOADS:
        raise ComponentError(f"quantity {path!r}: no part {name!r} reports a {what}")
    if run is None:
        raise ComponentError(f"quantity {path!r} needs the file's run")
    _, _, unit, expr = found[0]
    w = run.system.first_order.weights(expr)
    when, peak = largest(run.result, run.system, lambda mode: (w, 0.0), magnitude=True)
    return ReportedPeak(peak, when, unit, LOADS[unit],
                        f"the largest {what} of {name} over the run, at t = {when:.6g} s")
