"""What a design sweep prints and draws: the summary and the PNG.

The summary (``crane-sym sweep --format json``) gives the points, the blocks,
the seconds, per output the worst case with its design in the user's units,
and the fraction of designs within the limit. The PNG reads the written Zarr
dataset back lazily: a heat map for two axes (more axes: the worst over the
others), lines for one, the contour of the limit, the worst case marked. A
grid larger than :data:`MAX_PLOT` per axis is drawn from an evenly strided
subset (the worst case is marked from the full grid).
"""
from __future__ import annotations

from pathlib import Path
from typing import Any

import numpy as np

from .sweep import SweepResult

__all__ = ["MAX_PLOT", "plot", "summary", "text_lines"]

#: The most values per axis a heat map or line draws.
MAX_PLOT = 1000


def summary(result: SweepResult) -> dict[str, Any]:
    """The sweep's summary as JSON-ready data (values in the user's units)."""
    plan = result.plan
    axes = {a.name: a.values() for a in plan.axes}
    outputs = {}
    for o in plan.outputs:
        value, index = result.worst[o.name]
        unit, factor = plan.unit_of(o.name)
        kind = "min" if plan.limit and plan.limit.output == o.name and plan.limit.op == ">=" \
            else "max"
        outputs[o.name] = {
            "worst": {"value": value / factor, "unit": unit, "kind": kind,
                      "design": {a.name: {"value": float(axes[a.name][i]), "unit": a.unit}
                                 for a, i in zip(plan.axes, index)}}}
    data: dict[str, Any] = {
        "scene": plan.scene, "derivation": plan.derivation, "points": plan.points,
        "axes": {a.name: {"start": a.start, "stop": a.stop, "n": a.n, "unit": a.unit,
                          "spacing": "log" if a.log else "linear"} for a in plan.axes},
        "chunks": result.blocks * len(plan.outputs),
        "chunk_shape": [max(c) for c in result.chunks], "seconds": round(result.seconds, 4),
        "scheduler": result.scheduler, "outputs": outputs,
        "worst_case": {"output": (plan.limit.output if plan.limit else plan.outputs[0].name),
                       **outputs[plan.limit.output if plan.limit else plan.outputs[0].name]
                       ["worst"]}}
    if plan.window is not None:
        name, samples = plan.window
        data["window"] = {"name": name, "start_SI": samples[0], "stop_SI": samples[-1],
                          "samples": len(samples), "reduction": "max"}
    if plan.limit is not None:
        data["limit"] = {"text": plan.limit.text(), "within": result.within,
                         "fraction_within": result.within / plan.points}
    if result.dataset is not None:
        data["dataset"] = str(result.dataset)
    if result.plot is not None:
        data["plot"] = str(result.plot)
    data.update(result.extra)
    return data


def text_lines(data: dict[str, Any]) -> list[str]:
    """The summary as a few lines of text."""
    lines = [f"sweep of scene {data['scene']}: {data['points']} designs in {data['chunks']} "
             f"blocks, {data['seconds']:.3g} s ({data['scheduler']})"]
    for name, entry in data["outputs"].items():
        w = entry["worst"]
        design = ", ".join(f"{k} = {v['value']:.6g} {v['unit']}".rstrip()
                           for k, v in w["design"].items())
        lines.append(f"  {name}: {w['kind']} {w['value']:.6g} {w['unit']} at {design}")
    if "limit" in data:
        lim = data["limit"]
        lines.append(f"  within {lim['text']}: {lim['within']} of {data['points']} "
                     f"({100 * lim['fraction_within']:.4g} %)")
    if "certified" in data:
        c = data["certified"]
        lines.append(f"  certified {c['output']} over the box: [{c['lower']:.10g}, "
                     f"{c['upper']:.10g}] {c['unit']} (width <= {c['tolerance']:.3g} "
                     f"{c['unit']}, {c['boxes']} boxes)")
    for key in ("dataset", "plot"):
        if key in data:
            lines.append(f"  wrote {data[key]}")
    return lines


def _strided(n: int) -> slice:
    return slice(None, None, max(1, -(-n // MAX_PLOT)))


def plot(result: SweepResult, path: Path) -> Path:
    """The PNG of the first output (the limited one if there is a limit),
    written under a temporary name and renamed."""
    import matplotlib
    matplotlib.use("Agg")
    import xarray as xr
    from matplotlib.figure import Figure

    plan = result.plan
    name = plan.limit.output if plan.limit else plan.outputs[0].name
    unit, factor = plan.unit_of(name)
    field = xr.open_zarr(result.dataset)[name]
    axes = plan.axes
    worst_max = not (plan.limit and plan.limit.op == ">=")
    if len(axes) > 2:
        others = [a.name for a in axes[2:]]
        field = field.max(others) if worst_max else field.min(others)
    field = field.isel({a.name: _strided(a.n) for a in axes[:2]})
    values = np.asarray(field.values) / factor
    value, index = result.worst[name]
    best = [a.values()[i] for a, i in zip(axes, index)]
    fig = Figure(figsize=(7.5, 5.2), layout="constrained")
    ax = fig.add_subplot()
    label = f"{name} [{unit}]"
    marker = dict(marker="*", color="red", markersize=14, markeredgecolor="black",
                  linestyle="none", label=f"worst: {value / factor:.5g} {unit}", clip_on=False,
                  zorder=5)
    if len(axes) == 1:
        x = field[axes[0].name].values
        ax.plot(x, values, color="C0", label=name)
        ax.plot(best[0], value / factor, **marker)
        if plan.limit:
            ax.axhline(plan.limit.value, color="C3", linestyle="--", label=plan.limit.text())
        ax.set_xlabel(f"{axes[0].name} [{axes[0].unit}]")
        ax.set_ylabel(label)
        if axes[0].log:
            ax.set_xscale("log")
    else:
        x, y = field[axes[0].name].values, field[axes[1].name].values
        mesh = ax.pcolormesh(x, y, values.T, shading="nearest", cmap="viridis")
        fig.colorbar(mesh, ax=ax, label=label + (" (worst over " + ", ".join(
            a.name for a in axes[2:]) + ")" if len(axes) > 2 else ""))
        if plan.limit and values.min() < plan.limit.value < values.max():
            ax.contour(x, y, values.T, levels=[plan.limit.value], colors="white",
                       linewidths=2)
            ax.plot([], [], color="white", linewidth=2, label=f"limit: {plan.limit.text()}")
        ax.plot(best[0], best[1], **marker)
        ax.set_xlabel(f"{axes[0].name} [{axes[0].unit}]")
        ax.set_ylabel(f"{axes[1].name} [{axes[1].unit}]")
        ax.set_xscale("log" if axes[0].log else "linear")
        ax.set_yscale("log" if axes[1].log else "linear")
    fig.suptitle(f"{plan.scene}: {name} over {plan.points} designs")
    fig.legend(loc="outside lower center", ncols=3, fontsize="small", facecolor="0.85")
    tmp = path.with_name(f".{path.name}.partial.png")
    fig.savefig(tmp, dpi=110)
    tmp.replace(path)
    result.plot = path
    return path
