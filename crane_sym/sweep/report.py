"""What a design sweep prints and draws: the summary and the PNG.

The summary (``crane-sym sweep --format json``) gives the points, the blocks,
the seconds, per output the worst case with its design in the user's units,
and the fraction of designs within the limit. The PNG is drawn from the data
the sweep computed with its blocks (:attr:`SweepResult.view`), never read back
from a file: a heat map for two axes (more axes: the worst over the others),
lines for one, the contour of the limit, the worst case marked. A grid larger
than :data:`MAX_PLOT` per axis is drawn from an evenly strided subset (the
worst case is marked from the full grid). The PNG carries the sweep's
``sweep_id`` in its metadata, as the dataset's attributes and the summary do.

Each quantity is shown in one unit, the plan's (:meth:`SweepPlan.unit_of` for
an output, the axis's own unit), in the text, the JSON and the PNG; a
dimensionless one in none. The PNG's labels are Matplotlib mathtext of the
paper's LaTeX names (:func:`labels`); an output maximised over an ``--at``
window says so (``max over t in [0, 1.5] s``) wherever its value is printed.
"""
from __future__ import annotations

import re
from pathlib import Path
from typing import Any

import sympy as sp

from crane_sym import registry
from crane_sym.latex import latex
from crane_sym.output_files import Stage
from crane_sym.scenes.plots import fitted
from crane_sym.sweep.dataset import capped_name, output_cap
from crane_sym.sweep.grid import MAX_PLOT, SweepResult, plotted, strided
from crane_sym.sweep.plan import SweepPlan

__all__ = ["MAX_PLOT", "figure", "labels", "names", "plot", "summary", "text_lines"]


def _quantity(value: float | str, unit: str, digits: int = 6) -> str:
    """``98.9009 kN``; a dimensionless value bare; text as it is."""
    number = value if isinstance(value, str) else f"{value:.{digits}g}"
    return f"{number} {unit}".rstrip()


def summary(result: SweepResult) -> dict[str, Any]:
    """The sweep's summary as JSON-ready data (values in the user's units).

    Parameters
    ----------
    result : SweepResult
        The sweep.
    """
    plan = result.plan
    axes = {a.name: a.values() for a in plan.axes}
    outputs = {}
    for o in plan.outputs:
        value, index = result.worst[o.name]
        unit, factor = plan.unit_of(o.name)
        kind = "min" if plan.limit and plan.limit.output == o.name and plan.limit.op == ">=" \
            else "max"
        outputs[o.name] = {
            "unit": unit,
            "worst": {"value": value / factor, "unit": unit, "kind": kind,
                      "design": {a.name: {"value": float(axes[a.name][i]), "unit": a.unit}
                                 for a, i in zip(plan.axes, index)}}}
        cap = output_cap(plan, o.name)
        if cap is not None:
            outputs[o.name]["capped"] = {"designs": result.capped.get(o.name, 0),
                                         "cap_phases": cap, "flag": capped_name(o.name)}
        if plan.windowed(o.name):
            outputs[o.name]["over"] = plan.window.text()
        if plan.independent_of(o.name):
            outputs[o.name]["independent_of"] = list(plan.independent_of(o.name))
    first = plan.limit.output if plan.limit else plan.outputs[0].name
    data: dict[str, Any] = {
        "scene": plan.scene, "derivation": plan.derivation, "points": plan.points,
        "axes": {a.name: {"start": a.start, "stop": a.stop, "n": a.n, "unit": a.unit,
                          "spacing": "log" if a.log else "linear"} for a in plan.axes},
        "chunks": result.blocks * len(plan.outputs),
        "chunk_shape": [max(c) for c in result.chunks], "seconds": round(result.seconds, 4),
        "scheduler": result.scheduler, "sweep_id": result.sweep_id, "outputs": outputs,
        "worst_case": {"output": first, **outputs[first]["worst"]}}
    if plan.window is not None:
        w = plan.window
        data["window"] = {"name": w.name, "start": w.start, "stop": w.stop, "points": w.n,
                          "unit": w.unit, "to_SI": w.to_si, "reduction": "max",
                          "text": w.text()}
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
    """The summary as a few lines of text.

    Parameters
    ----------
    data : dict
        From :func:`summary`.
    """
    what = "drive train" if str(data.get("derivation", "")).endswith(".toml") else "scene"
    blocks = "1 block" if data["chunks"] == 1 else f"{data['chunks']} blocks"
    lines = [f"sweep of {what} {data['scene']}: {data['points']} designs in {blocks}, "
             f"{data['seconds']:.3g} s ({data['scheduler']})"]
    for name, entry in data["outputs"].items():
        w = entry["worst"]
        design = ", ".join(f"{k} = {_quantity(v['value'], v['unit'])}"
                           for k, v in w["design"].items())
        over = f", {entry['over']}" if "over" in entry else ""
        lines.append(f"  {name}{over}: {w['kind']} {_quantity(w['value'], w['unit'])} "
                     f"at {design}")
        if "capped" in entry:
            c = entry["capped"]
            lines.append(f"    {c['designs']} of {data['points']} designs stopped at the cap of "
                         f"{c['cap_phases']} phases (NaN, flagged in {c['flag']}; left out of "
                         f"the worst case)")
        if "independent_of" in entry:
            lines.append(f"    ({name} does not depend on {', '.join(entry['independent_of'])}:"
                         " constant along that axis)")
    if "limit" in data:
        lim = data["limit"]
        lines.append(f"  within {lim['text']}: {lim['within']} of {data['points']} "
                     f"({100 * lim['fraction_within']:.4g} %)")
    if "certified" in data:
        c = data["certified"]
        w = data.get("window", {})
        over = (f" and {w['name']} in [{w['start']:g}, {w['stop']:g}] {w['unit']}".rstrip()
                if w.get("name") in c.get("over", ()) else "")
        lines.append(f"  certified {c['kind']} of {c['output']} over the box{over}: "
                     + _quantity(f"[{c['lower']:.10g}, {c['upper']:.10g}]", c["unit"])
                     + f" (width <= {_quantity(c['tolerance'], c['unit'], 3)}, "
                     f"{c['boxes']} boxes)")
    for key in ("dataset", "plot"):
        if key in data:
            lines.append(f"  wrote {data[key]}")
    return lines


def _mathtext(tex: str) -> str | None:
    """``$tex$`` if Matplotlib's mathtext can set it, else None."""
    from matplotlib.mathtext import MathTextParser
    text = "$" + re.sub(r"\\text\{", r"\\mathrm{", tex) + "$"
    try:
        MathTextParser("path").parse(text, 72)
    except ValueError:
        return None
    return text


def names(plan: SweepPlan) -> dict[str, str]:
    """Name -> how the PNG writes it, for every axis, output and window
    variable: the paper's LaTeX name in mathtext (``LATEX_NAMES``, else
    SymPy's name of the symbol; an output by the symbol a step of the
    derivation defines as its expression, else in words; a component file's
    fields and outputs in words: ``stiffness of gearbox_mesh``)."""
    if any(o.kind == "component" for o in plan.outputs):
        def words(name: str) -> str:            # COMPONENT.FIELD, LINK.peak
            part, _, field = name.rpartition(".")
            return f"{field.replace('_', ' ')} of {part}" if part else name
        return {**{a.name: words(a.name) for a in plan.axes},
                **{o.name: words(o.name) for o in plan.outputs}}
    d = registry.get(plan.derivation)

    def tex(symbol, fallback: str) -> str:
        return _mathtext(latex(symbol, symbol_names=d.latex_names)) or fallback

    closed = {o.name: o.expr for o in d.outputs}
    defined = {}
    for step in d.steps:
        st = step.statement
        if isinstance(st, sp.Eq) and isinstance(st.lhs, sp.Symbol):
            defined.setdefault(st.rhs, st.lhs)
    found = {a.name: tex(d.symbols[a.name].expr, a.name) for a in plan.axes}
    for o in plan.outputs:
        words = o.name.replace("_", " ")
        symbol = defined.get(closed[o.name]) if o.name in closed else None
        found[o.name] = words if symbol is None else tex(symbol, words)
    if plan.window is not None:
        found[plan.window.name] = tex(d.symbols[plan.window.name].expr, plan.window.name)
    return found


def labels(plan: SweepPlan) -> dict[str, str]:
    """:func:`names` with the unit in brackets (none for a dimensionless
    quantity): ``$P_{t}$ [kN]``, ``$F_{\\max}$ [kN]``."""
    units = {a.name: a.unit for a in plan.axes}
    units.update({o.name: plan.unit_of(o.name)[0] for o in plan.outputs})
    if plan.window is not None:
        units[plan.window.name] = plan.window.unit
    return {k: f"{v} [{units[k]}]" if units[k] else v for k, v in names(plan).items()}


def figure(result: SweepResult):
    """The Matplotlib figure of the first output (the limited one if there is
    a limit), from the data the sweep computed (:attr:`SweepResult.view`)."""
    from matplotlib.figure import Figure

    plan = result.plan
    if result.view is None:
        raise ValueError("the sweep kept no data to draw: run it with a folder to write to")
    name = plotted(plan)
    unit, factor = plan.unit_of(name)
    tex, label = names(plan), labels(plan)
    axes = plan.axes
    coords = [a.values()[strided(a.n)] for a in axes[:2]]
    values = result.view / factor
    value, index = result.worst[name]
    best = [a.values()[i] for a, i in zip(axes, index)]
    over = ""
    if plan.windowed(name):
        w = plan.window
        over = f", max over {tex[w.name]} in [{w.start:g}, {w.stop:g}] {w.unit}".rstrip()
    limit = ""
    if plan.limit:
        limit = f"{tex[name]} {'≤' if plan.limit.op == '<=' else '≥'} " \
            f"{_quantity(plan.limit.value, plan.limit.unit)}"
    summary = next(o.summary for o in plan.outputs if o.name == name)
    shows = fitted(f"{label[name]}{over}: {summary}" if summary else label[name] + over, 5.2,
                   10.0)                          # what the values are, in words
    fig = Figure(figsize=(7.5, 5.2), layout="constrained")
    ax = fig.add_subplot()
    marker = dict(marker="*", color="red", markersize=14, markeredgecolor="black",
                  linestyle="none", label=f"worst: {_quantity(value / factor, unit, 5)}",
                  clip_on=False, zorder=5)
    if len(axes) == 1:
        x = coords[0]
        ax.plot(x, values, color="C0", label=tex[name])
        ax.plot(best[0], value / factor, **marker)
        if plan.limit:
            ax.axhline(plan.limit.value, color="C3", linestyle="--", label=f"limit: {limit}")
        ax.set_xlabel(label[axes[0].name])
        ax.set_ylabel(shows)
        if axes[0].log:
            ax.set_xscale("log")
    else:
        x, y = coords
        mesh = ax.pcolormesh(x, y, values.T, shading="nearest", cmap="viridis")
        fig.colorbar(mesh, ax=ax, label=fitted(shows.replace("\n", " ") + (
            " (worst over " + ", ".join(tex[a.name] for a in axes[2:]) + ")"
            if len(axes) > 2 else ""), 5.2, 10.0))
        if plan.limit and values.min() < plan.limit.value < values.max():
            ax.contour(x, y, values.T, levels=[plan.limit.value], colors="white",
                       linewidths=2)
            ax.plot([], [], color="white", linewidth=2, label=f"limit: {limit}")
        ax.plot(best[0], best[1], **marker)
        ax.set_xlabel(label[axes[0].name])
        ax.set_ylabel(label[axes[1].name])
        ax.set_xscale("log" if axes[0].log else "linear")
        ax.set_yscale("log" if axes[1].log else "linear")
    title = f"{plan.scene}: {name}" + (f", {plan.window.text()}" if over else "")
    fig.suptitle(f"{title}, {plan.points} designs")
    fig.legend(loc="outside lower center", ncols=3, fontsize="small", facecolor="0.85")
    return fig


def plot(result: SweepResult, stage: Stage) -> Path:
    """:func:`figure` as ``<scene>_sweep.png`` in ``stage``, its ``sweep_id``
    in the PNG's metadata; renamed into place with the dataset when the stage
    is committed. Returns the final path.

    Parameters
    ----------
    result : SweepResult
        The sweep.
    stage : Stage
        The stage of the sweep's files.
    """
    name = f"{result.plan.scene}_sweep.png"
    figure(result).savefig(stage.path(name, ".png"), dpi=110,
                           metadata={"sweep_id": result.sweep_id})
    result.plot = stage.folder / name
    return result.plot
