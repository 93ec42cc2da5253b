"""A scene that gives its own drive law: the ``[drive_law]`` table of paper 002.

The scene load ``DRIVE_LAW`` (a ``crane_sym.derivation.SceneLoad``) is how
the one scene pipeline meets a user's law: stage 1 reads the table
(:func:`read`), stage 2 convolves the law once, symbolically, with the
scene's exact numbers folded in (:func:`specialize`), stage 4 evaluates the
generated module and certifies the largest dynamic coefficient
(:func:`drive_law_report`). Example: ``scenes/hoist_user_drive_law.toml``::

    [parameters]
    m1 = "2 t"                       # m1, m2, C, g with units
    [drive_law]
    lifting = "from_weight"          # or "pickup"
    breakpoints = [0.0, 0.25, 1.0, 1.25]
    coefficients = [[0.0, 2.0], [0.5], [0.5, -2.0]]
    time_unit = "s"                  # optional; c_kj in acceleration_unit
    acceleration_unit = "m/s^2"      # per time_unit^j (optional)
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from types import ModuleType
from typing import Any, Mapping

import numpy as np
import sympy as sp
from sympy.physics.units import acceleration, force, length, mass
from sympy.physics.units import time as _TIME

from crane_sym.derivation import SceneLoad, SpecializedLoad
from crane_sym.mechanics.extrema import maximum_on_interval
from crane_sym.scenes.law_tables import LawLimits, check_keys, piecewise_law, read_law_table
from crane_sym.mechanics.loads import DEFAULT_TIME, PiecewiseLoad, exact_number
from crane_sym.scenes.panels import valid_mask
from crane_sym.scenes.reading import Panel, SceneError, SceneReport
from crane_sym.scenes.reading import format_quantity as fq
from crane_sym.symbols import TIME, PhysicalSymbol, SymbolTable

from .drive_law import (FROM_WEIGHT, PICKUP, DriveLawResponse, drive_law_outputs,
                        pickup_speed, respond)
from .validity import model_span

__all__ = ["DRIVE_LAW", "DriveLaw", "drive_law_report", "read", "response", "specialize"]

_KEYS = ("lifting", "breakpoints", "coefficients", "time_unit", "acceleration_unit")
_MAX_DEPTH = 16        # bisection depth of the interval search
_SAMPLE_SLACK = 1e-12  # relative: a sampled K may exceed the bound by rounding only
#: What a [drive_law] may hold. The symbolic work (the Duhamel response, its
#: printed module, the certified maximum) grows with the pieces (about as
#: their square) and their degree: the largest law allowed, 5 pieces of
#: degree 5 lifting with pick-up, takes about 30 s of CPU to generate and 40 s
#: to run (README, "Scenes"); 8 pieces took 44 s to generate, 30 pieces 170 s.
#: The other bounds keep the printed double-precision code accurate.
LIMITS = LawLimits(pieces=5, degree=5, end=1000.0, shortest=0.01, value=1000.0,
                   unit="m/s^2")
#: What the law's model needs from [parameters].
PARAMETERS = (
    PhysicalSymbol(sp.Symbol("m1", positive=True), mass, "kg", "reduced mass of the drive"),
    PhysicalSymbol(sp.Symbol("m2", positive=True), mass, "kg", "mass of the load"),
    PhysicalSymbol(sp.Symbol("C", positive=True), force / length, "N/m",
                   "stiffness of the rope"),
    PhysicalSymbol(sp.Symbol("g", positive=True), acceleration, "m/s^2",
                   "acceleration of gravity"),
)
#: The only argument of the generated functions.
TIME_SYMBOLS = SymbolTable([PhysicalSymbol(DEFAULT_TIME, _TIME, "s",
                                           "time from the start of the drive", TIME,
                                           "nonnegative", (1e-2, 2.0))])


@dataclass(frozen=True)
class DriveLaw:
    """A validated ``[drive_law]`` table, exact and in SI: breakpoints [s],
    ``coefficients[k][j]`` [m/s^(2+j)], and the lifting case."""

    lifting: str
    breakpoints: tuple[sp.Rational, ...]
    coefficients: tuple[tuple[sp.Rational, ...], ...]

    def law(self) -> PiecewiseLoad:
        """:math:`a(t)` (``law_tables.piecewise_law``)."""
        return piecewise_law(self.breakpoints, self.coefficients)


def read(table: Mapping[str, Any], where: str = "") -> DriveLaw:
    """Stage 1: the ``[drive_law]`` table checked by key, type and unit."""
    check_keys(table, _KEYS, _KEYS[:3])
    if table["lifting"] not in (FROM_WEIGHT, PICKUP):
        raise ValueError(f"lifting must be {FROM_WEIGHT!r} or {PICKUP!r}, "
                         f"got {table['lifting']!r}")
    breakpoints, rows = read_law_table(table, "acceleration_unit", acceleration, "m/s^2",
                                       LIMITS)
    law = DriveLaw(table["lifting"], breakpoints, rows)
    if law.lifting == PICKUP:
        pickup_speed(law.law())          # (29) needs v0 > 0: refused here, before any file
    return law


def _system(scene) -> dict[str, sp.Rational]:
    """m1, m2, C, g of the scene as exact numbers (a float read as it prints)."""
    return {p.name: exact_number(scene.parameters[p.name], p.name) for p in PARAMETERS}


def response(scene) -> DriveLawResponse:
    """The symbolic response of the hoist to the scene's law (``respond``)."""
    s = _system(scene)
    return respond(scene.load.law(), s["m1"], s["m2"], s["C"], s["g"], scene.load.lifting)


def specialize(scene) -> SpecializedLoad:
    """Stage 2: the law convolved once with the scene's numbers folded in;
    every function takes time ``t`` [s] only."""
    s, r = _system(scene), response(scene)
    law = "; ".join(f"[{sp.sstr(b)}, {sp.sstr(e)}): {sp.sstr(p)}" for b, e, p in
                    r.law.intervals if p != 0)
    note = (f"Drive law of scene {scene.name!r} ({scene.title}), {scene.load.lifting}:\n"
            f"a(t) [m/s^2] = {law}; 0 elsewhere.\n"
            f"Folded in (SI): m1 = {sp.sstr(s['m1'])} kg, m2 = {sp.sstr(s['m2'])} kg, "
            f"C = {sp.sstr(s['C'])} N/m, g = {sp.sstr(s['g'])} m/s^2"
            + (f", tau_0 = {sp.sstr(r.contact_time)} s" if r.contact_time is not None
               else "") + ".")
    return SpecializedLoad(drive_law_outputs(r), note, TIME_SYMBOLS)


DRIVE_LAW = SceneLoad(
    table="drive_law",
    description="drive acceleration a(t), piecewise polynomial, lifting from weight "
                "or with pick-up",
    parameters=PARAMETERS,
    outputs=("drive_acceleration", "drive_speed", "relative_forcing", "rope_stretch",
             "rope_stretch_rate", "rope_force", "dynamic_coefficient", "load_acceleration"),
    read=read,
    specialize=specialize,
)


def drive_law_report(scene, gen: ModuleType) -> SceneReport:
    """Stage 4: curves of the scene's module ``gen`` over the scene's span, the
    part of it where the model holds (``validity.model_span``: the load
    lifted, the rope taut), and the guaranteed maximum of K over that part
    only (interval arithmetic, not sampling)."""
    r = response(scene)
    duration, t = scene.settings["duration"], scene.times()
    k = gen.dynamic_coefficient(t)
    span = model_span(r, duration)
    omega = math.sqrt(float(r.C * (r.m1 + r.m2) / (r.m1 * r.m2)))
    pickup = r.lifting == PICKUP
    case = "with pick-up (26)" if pickup else "from weight (27)"
    v0 = float(r.final_speed)
    lines = [f"lifting {case}; natural frequency Omega = {omega:.4g} rad/s (2), "
             f"period T = {fq(2 * math.pi / omega, 's')}",
             f"final drive speed v0 = {fq(v0, 'm/s')}"
             + (f", rope picks up the load at tau_0 = {fq(float(r.contact_time), 's')}"
                if pickup else ""),
             *span.warnings()]
    values = {"Omega": omega, "v0": v0, "valid_from": math.nan if span.empty else span.start,
              "valid_to": span.end, "certified": float(span.certified)}
    if span.empty:
        lines.append("K_max: not given, the model is valid nowhere on "
                     f"[0, {fq(duration, 's')}]")
        values.update(K_max=math.nan, t_max=math.nan)
    else:
        found = maximum_on_interval(r.dynamic_coefficient(), DEFAULT_TIME,
                                    exact_number(span.start, "start"),
                                    exact_number(span.end, "end"),
                                    symbolic=False, max_depth=_MAX_DEPTH)
        k_max, t_max = float(found.value), float(found.location)
        sampled = float(np.max(k[valid_mask(t, span.spans())], initial=-math.inf))
        if sampled > k_max * (1 + _SAMPLE_SLACK):
            raise SceneError(f"scene {scene.name!r}: the generated K reaches {sampled!r}, "
                             f"above the guaranteed maximum {k_max!r}")
        part = (f"[0, {fq(duration, 's')}]" if span.whole
                else f"the valid part {span.interval()} only")
        lines.append(f"K_max = {k_max:.6f} at t = {fq(t_max, 's')} over {part} (interval "
                     f"arithmetic, certified: {found.certified and span.certified}); sampled "
                     f"max {sampled:.6f}")
        values.update(K_max=k_max, t_max=t_max,
                      certified=float(found.certified and span.certified))
    x_eq = "(22)" if pickup else "(24)"
    panels = [Panel("Drive law: acceleration $a(t)$", "$a$ [m/s²]",
                    [("$a(t)$", t, gen.drive_acceleration(t))]),
              Panel("Drive law: speed $v(t)$", "$v$ [m/s]",
                    [("$v(t)$", t, gen.drive_speed(t))]),
              Panel("Dynamic coefficient $K(t)$ (25)", "$K$", [("$K(t)$", t, k)]),
              Panel(f"Rope force {x_eq}", "$F$ [kN]",
                    [(r"$C\,x(t)$", t, gen.rope_force(t) / 1e3)]),
              Panel("Load acceleration (1)", r"$\ddot x_2$ [m/s²]",
                    [(r"$\ddot x_2(t)$", t, gen.load_acceleration(t))])]
    for panel in panels[2:]:              # the drive law is data: it holds throughout
        panel.invalid = span.spans()
    return SceneReport(lines=lines, values=values, panels=panels)
