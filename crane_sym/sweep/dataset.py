"""A design sweep's labelled dataset: one variable per output (SI), one
coordinate per axis in the user's units, units and provenance as attributes,
and the sweep's id that ties the dataset to its PNG and summary.
"""
from __future__ import annotations

import hashlib
from typing import Any

import numpy as np

from crane_sym import __version__, registry
from crane_sym.sweep.plan import SweepPlan, shown_unit

__all__ = ["capped_name", "dataset", "output_cap", "sweep_id"]


def dataset(plan: SweepPlan, arrays: dict[str, Any]):
    """The labelled dataset: one variable per output (SI), one coordinate per
    axis in the user's units, units and provenance as attributes: per output
    the unit the summary and the PNG show it in (``display_units``), the axes
    it does not depend on, the window it is maximised over; the window's
    start, stop, points and unit; the fixed values, the window's variable
    not among them."""
    import xarray as xr

    dims = tuple(a.name for a in plan.axes)
    coords = {a.name: (a.name, a.values(), {"units": a.unit, "to_SI": a.to_si,
                                            "spacing": "log" if a.log else "linear"})
              for a in plan.axes}
    variables = {}
    for o in plan.outputs:
        unit, factor = plan.unit_of(o.name)
        attrs = {"units": shown_unit(o.unit), "long_name": o.summary, "kind": o.kind,
                 "display_units": unit, "display_to_SI": factor}
        if plan.independent_of(o.name):
            attrs["independent_of"] = ", ".join(plan.independent_of(o.name))
        if plan.windowed(o.name):
            attrs["cell_methods"] = f"{plan.window.name}: maximum"
            attrs["window"] = plan.window.text()
        cap = output_cap(plan, o.name)
        if cap is not None:
            attrs["cap_phases"] = cap
            attrs["capped"] = (f"NaN where a design's run passed {cap} phases (a contact "
                               f"that chatters): flagged in {capped_name(o.name)}")
            variables[capped_name(o.name)] = (
                dims, _isnan(arrays[o.name]),
                {"long_name": f"{o.name}: run stopped at the cap of {cap} phases, no value",
                 "cap_phases": cap})
        variables[o.name] = (dims, arrays[o.name], attrs)
    window = plan.window
    attrs = {"scene": plan.scene, "derivation": plan.derivation,
             "fixed_SI": ", ".join(f"{k}={v!r}" for k, v in sorted(plan.fixed.items())
                                   if k not in dims and (window is None or k != window.name)),
             "generated_by": f"crane_sym {__version__} (crane-sym sweep)",
             "sweep_id": sweep_id(plan)}
    if plan.limit is not None:
        attrs["limit"] = plan.limit.text()
    if window is not None:
        attrs.update({"window": f"{window.text()}, {window.n} samples: each output that "
                                f"depends on {window.name} is its maximum over them",
                      "window_variable": window.name, "window_start": window.start,
                      "window_stop": window.stop, "window_points": window.n,
                      "window_units": window.unit, "window_to_SI": window.to_si})
    return xr.Dataset(variables, coords=coords, attrs=attrs)


def output_cap(plan: SweepPlan, name: str) -> int | None:
    """The most phases a design's run of output ``name`` may take
    (``SweepOutput.cap``), None for an output without a cap."""
    if next(o for o in plan.outputs if o.name == name).kind != "simulated":
        return None
    return getattr(registry.sweep_outputs(plan.derivation).get(name), "cap", None)


def capped_name(name: str) -> str:
    """The dataset's flag of the designs of ``name`` stopped at the cap."""
    return f"{name}_capped"


def _isnan(array):
    import dask.array as da
    return da.isnan(array) if isinstance(array, da.Array) else np.isnan(array)


def sweep_id(plan: SweepPlan) -> str:
    """A name for the sweep that ``plan`` describes (a hash of it): the same in
    the dataset's attributes, the PNG's metadata and the summary, so a
    dataset and a PNG can be checked to belong together."""
    return hashlib.sha256(repr(plan).encode("utf-8")).hexdigest()[:16]
