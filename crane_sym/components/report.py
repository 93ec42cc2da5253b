"""What ``crane-sym run FILE`` does with a component file: the run from its
steady start, phase by phase in closed form, the peak load and dynamic factor
of every elastic link, the event times; a JSON of those numbers, the
generated module of the links' loads and a plot of them, written only into the
folder the user names.
"""
from __future__ import annotations

import io
import json
import math
from dataclasses import dataclass
from pathlib import Path
from typing import Sequence

import numpy as np

from crane_sym import output_files
from crane_sym.components.generate import module_name, render_component_module
from crane_sym.components.model import ComponentRun
from crane_sym.components.component_file import ComponentFile, read_component_file
from crane_sym.mechanics.phase_table import values
from crane_sym.components.parts import SENSES, UNITS
from crane_sym.mechanics.phase_table import largest
from crane_sym.scenes.panels import Panel, engineering, format_quantity
from crane_sym.scenes.results import number

__all__ = ["ComponentReport", "PartPeak", "load_figures", "part_peaks", "report_lines", "results",
           "run_component_file"]

#: Points of the plotted curves.
POINTS = 2001


@dataclass(frozen=True)
class PartPeak:
    """The largest value (signed, by magnitude) of what a part reports over a
    run (a DC motor's current, torque, speed) and when it occurs."""

    part: str
    what: str
    unit: str
    time: float
    value: float


@dataclass(frozen=True)
class ComponentReport:
    """The run, the peaks of what its parts report (computed once for the
    lines and the JSON), the lines printed, the files written."""

    run: ComponentRun
    parts: list[PartPeak]
    lines: list[str]
    files: list[Path]


def _reported(run: ComponentRun) -> list[tuple[str, str, str, np.ndarray]]:
    """(part, what, SI unit, weights w: the value is w·x) of every value the
    run's parts report (``Acting.outputs``, a span's force), in the order the
    parts were given."""
    a, out = run.system.assembly, []
    bodies = {l.part.name: a.bodies[l.part.body] for l in a.loads}
    for part, what, unit, value in run.model.equations.outputs:
        si = UNITS[unit][bodies[part].motion] if unit in UNITS else unit
        out.append((part, what, si, run.system.first_order.weights(value)))
    return out


def part_peaks(run: ComponentRun) -> list[PartPeak]:
    """The peak of every value the run's parts report (``Acting.outputs``), in
    the order the parts were given.

    Parameters
    ----------
    run : ComponentRun
        The run.
    """
    out = []
    for part, what, si, w in _reported(run):
        when, peak = largest(run.result, run.system, lambda mode, w=w: (w, 0.0), magnitude=True)
        out.append(PartPeak(part, what, si, when, peak))
    return out


#: How the sign of a link's load reads, said once above the loads.
SIGNS = ("signs: a link's load is c·u + d·u' with u = its second body's coordinate minus "
         "its first's (the order of `between`), so it is positive when the second body is "
         "ahead of the first; `positive = \"tension\"` (or \"compression\") on a "
         "translating link states its load in words")


def load_text(value: float, unit: str, positive: str | None, factor: float,
              scaled: str) -> str:
    """A link's load as an engineer reads it: in ``scaled`` units (``value`` /
    ``factor``), as tension or compression when the link declares what its
    positive load is, else signed.

    Parameters
    ----------
    value : float
        The load, SI.
    unit : str
        Its SI unit (for a value not scaled).
    positive : str or None
        What a positive load of the link is (``ElasticLink.positive``).
    factor, scaled : float, str
        From :func:`crane_sym.scenes.panels.engineering`.
    """
    if positive is None:
        return format_quantity(value / factor, scaled)
    word = positive if value >= 0 else SENSES[positive]
    return f"{format_quantity(abs(value) / factor, scaled)} {word}" if value else \
        format_quantity(0.0, scaled)


def report_lines(run: ComponentRun, parts: Sequence[PartPeak]) -> list[str]:
    """The components dropped as not needed, a brake that engages the instant
    a steady start begins (its friction is not in that steady motion), how
    the loads' signs read, peak
    loads (in kN or kN·m where they are that large, in words where a link
    declares its ``positive``; with time and dynamic factor), the peaks of
    what its parts report (``parts``, :func:`part_peaks` of the run) and
    events, one per line."""
    lines = [d.line() for d in run.model.dropped]
    for t, event in run.schedule:          # a steady start: the brake comes after it
        if t == 0 and event.endswith(" engages"):
            brake = event.removesuffix(" engages")
            lines.append(f"note: brake {brake!r} engages at t = 0, the instant the run "
                         "starts from its steady motion, which is computed without it (a "
                         "friction that acts throughout: start = \"rest\", or give the "
                         "motion's resistance as a [[resistance]])")
    if any(p.positive is None for p in run.peaks):
        lines.append(SIGNS)
    for p in run.peaks:
        factor = "" if p.factor is None or p.angle else \
            f", dynamic factor {format_quantity(p.factor)}"   # a pendulum's is its angle, below
        scale = engineering(max(abs(p.value), abs(p.static)), p.unit)
        lines.append(f"peak load of {p.link}: {load_text(p.value, p.unit, p.positive, *scale)}"
                     f" at t = {format_quantity(p.time, 's')} (at the start "
                     f"{load_text(p.static, p.unit, p.positive, *scale)}{factor})")
        if p.angle:
            lines.append(f"peak sway angle of {p.link}: {format_quantity(p.factor)} rad "
                         f"({format_quantity(math.degrees(p.factor))} deg) at t = "
                         f"{format_quantity(p.time, 's')} (its pull over the load's weight)")
    for r in run.reactions:
        scale = engineering(max(abs(r.value), abs(r.start)), r.unit)
        lines.append(f"peak reaction of {r.contact}: {load_text(r.value, r.unit, None, *scale)}"
                     f" at t = {format_quantity(r.time, 's')} (at the start "
                     f"{load_text(r.start, r.unit, None, *scale)})")
    for p in parts:
        lines.append(f"peak {p.what} of {p.part}: {format_quantity(p.value, p.unit)} at "
                     f"t = {format_quantity(p.time, 's')}")
    for t, event in run.events:
        lines.append(f"event at t = {format_quantity(t, 's', 6)}: {event}")
    return lines


def results(report: ComponentReport) -> dict:
    """What ``crane-sym run FILE --format json`` prints: per elastic link
    ``<link>.peak`` (signed, as printed), ``<link>.peak_time``,
    ``<link>.start_load`` and ``<link>.factor`` (None without a reference),
    each as ``{"value": number, "unit": text}`` (SI, signed as
    ``sign_convention`` says); ``positive``, what a positive load is for each
    link that declares it (``"tension"``, ``"compression"``); the events with
    their times; no warnings (a component run holds throughout); the files
    written.

    Parameters
    ----------
    report : ComponentReport
        From :func:`run_component_file`.
    """
    model = report.run.model
    found = {}
    for p in report.run.peaks:
        found.update({f"{p.link}.peak": {"value": number(p.value), "unit": p.unit},
                      f"{p.link}.peak_time": {"value": number(p.time), "unit": "s"},
                      f"{p.link}.start_load": {"value": number(p.static), "unit": p.unit},
                      f"{p.link}.factor": {"value": None if p.factor is None
                                           else number(p.factor), "unit": "1"}})
        if p.angle:
            found[f"{p.link}.angle"] = {"value": number(p.factor), "unit": "rad"}
    for r in report.run.reactions:
        found.update({f"{r.contact}.reaction_peak": {"value": number(r.value), "unit": r.unit},
                      f"{r.contact}.reaction_peak_time": {"value": number(r.time), "unit": "s"},
                      f"{r.contact}.reaction_start": {"value": number(r.start),
                                                      "unit": r.unit}})
    for p in report.parts:
        found.update({f"{p.part}.{p.what}.peak": {"value": number(p.value), "unit": p.unit},
                      f"{p.part}.{p.what}.peak_time": {"value": number(p.time), "unit": "s"}})
    return {"scene": model.name, "title": model.title, "model": model.name,
            "results": found,
            "sign_convention": SIGNS.removeprefix("signs: "),
            "positive": {p.link: p.positive for p in report.run.peaks if p.positive},
            "events": [{"time": {"value": number(t), "unit": "s"}, "event": e}
                       for t, e in report.run.events],
            "warnings": [], "lines": list(report.lines),
            "files": [str(f) for f in report.files]}


def _json(run: ComponentRun, name: str) -> str:
    return json.dumps({
        "model": name,
        "dropped": [{"component": d.part.label, "reason": d.reason} for d in run.model.dropped],
        "peaks": [{"link": p.link, "time_s": p.time, "value": p.value, "unit": p.unit,
                   "static": p.static, "reference": p.reference, "dynamic_factor": p.factor,
                   "positive": p.positive}
                  for p in run.peaks],
        "reactions": [{"contact": r.contact, "time_s": r.time, "value": r.value,
                       "unit": r.unit, "start": r.start} for r in run.reactions],
        "events": [{"time_s": float(t), "event": e} for t, e in run.events],
    }, indent=2)


def load_figures(run: ComponentRun, title: str) -> list:
    """The figures (Matplotlib) of the loads of the run's elastic links, its
    spans' forces (or torques) and its ground contacts' reactions, at most
    four panels each; each axis says what it shows in words and units (a
    link's tension where it declares its ``positive``, kN or kN·m where the
    load is that large).

    Parameters
    ----------
    run : ComponentRun
        The run.
    title : str
        The figures' title.
    """
    from crane_sym.scenes.plots import figures
    times = np.linspace(0.0, run.t_end, POINTS)
    panels = []
    for i, p in enumerate(run.peaks):
        factor, unit = engineering(max(abs(p.value), abs(p.static)), p.unit)
        what = (p.positive if p.positive is not None else
                "torque" if p.unit == "N*m" else "force")
        panels.append(Panel(f"load of the elastic link {p.link}", f"{what} [{unit}]",
                            [(p.link, times, values(run.result, times,
                                                    run.system.link_load(i)) / factor)],
                            group="elastic links", xlabel="time [s]"))
    spans = {part.name for part in run.system.assembly.couplings}
    for part, what, si, w in (r for r in _reported(run) if r[0] in spans):
        load = values(run.result, times, lambda mode, w=w: (w, 0.0))
        factor, unit = engineering(float(np.abs(load).max()), si)
        panels.append(Panel(f"{what} of the span {part}", f"{what} [{unit}]",
                            [(part, times, load / factor)], group="spans",
                            xlabel="time [s]"))
    for j, r in enumerate(run.reactions):
        factor, unit = engineering(max(abs(r.value), abs(r.start)), r.unit)
        panels.append(Panel(f"reaction of the ground contact {r.contact}",
                            f"reaction [{unit}]",
                            [(r.contact, times, values(run.result, times,
                                                       run.system.contact_load(j)) / factor)],
                            group="ground contacts", xlabel="time [s]"))
    return figures(panels, title) if panels else []


def run_component_file(path: str | Path, out: str | Path | None) -> ComponentReport:
    """Read ``path``, run it, write ``<name>.json``, the module
    ``model_<name>.py`` (the links' loads as tables of closed forms) and
    ``<name>_loads*.png`` (:func:`load_figures`) into ``out`` (nothing else, nowhere else).

    Parameters
    ----------
    path : str or Path
        The component TOML file.
    out : str or Path or None
        The output folder (made if missing; nothing is written elsewhere);
        None: the report only, no file written anywhere.
    """
    if out is not None:
        output_files.check_folder(out)
    read: ComponentFile = read_component_file(path)
    model = read.model
    run = model.run(read.duration, read.body, read.speed, rest=read.rest)
    parts = part_peaks(run)
    lines = report_lines(run, parts)
    if out is None:
        return ComponentReport(run, parts, lines, [])
    figs = load_figures(run, model.title or model.name)
    source = render_component_module(run)
    with output_files.staged(out) as stage:
        files = [stage.text(f"{model.name}.json", _json(run, model.name)),
                 stage.text(module_name(run), source)]
        names = ([f"{model.name}_loads.png"] if len(figs) == 1 else
                 [f"{model.name}_loads_{k}.png" for k in range(1, len(figs) + 1)])
        for fig, name in zip(figs, names):
            buffer = io.BytesIO()
            fig.savefig(buffer, format="png", dpi=120, metadata={"Software": None})
            files.append(stage.bytes(name, buffer.getvalue()))
    return ComponentReport(run, parts, lines, files)
