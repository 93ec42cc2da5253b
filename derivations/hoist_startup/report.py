"""Scenes of paper 002: Figs 3 and 5, the drive laws a_i of (30), guaranteed maxima.

``scene_report(scene)`` answers a scene by its kind (``REPORTS``): one with
its own ``[drive_law]`` through its own module (``drive_law_scene``), else a
figure of the paper. ``figure_report`` evaluates the generated module
``crane_sym.generated.hoist_startup`` (by function name, never SymPy) for the
curves, and the symbolic Duhamel response of ``drive_law`` for the
maxima, which ``extrema.maximum_on_interval`` finds with a guarantee
(symbolic critical points or interval arithmetic), never by sampling alone.
The scene option ``figure`` selects what a scene reproduces:

``"fig3"``
    Fig. 3: :math:`x(t)/x_{ст}` under a suddenly applied load, (35)-(38).
``"fig5"``
    Fig. 5: :math:`x(t)/x_{ст}` under the linearly growing load
    :math:`\\bar P = k t`, (40)-(42), beside the static line :math:`k t/C`.
``"drive_laws"``
    :math:`K_{дин}(t)` for each law a_i of (30), lifting with pick-up (26)
    and from weight (27), beside the rope force of the rigid load (62); the
    maximum of each over the part of [0, duration] where the model holds
    (``validity``: with pick-up only once the load is lifted, greyed
    before); the load's acceleration in the
    normalisation of Table 1 against (65), Table 1 and the two maxima printed
    after it.

Nothing runs on import; the model and the published records
(``published_optimum``, ``tables``) are imported inside the functions that
read them.
"""
from __future__ import annotations

import importlib
import math
from types import ModuleType
from typing import Any, Callable

import numpy as np
import sympy as sp

from . import drive_law
from .drive_law_scene import DRIVE_LAW, drive_law_report
from .validity import model_span
from crane_sym.mechanics.extrema import maximum_on_interval
from crane_sym.mechanics.loads import DEFAULT_TIME, exact_number
from crane_sym.scenes.kinds import SceneKind, report_for
from crane_sym.scenes.panels import WARNING
from crane_sym.scenes.reading import Panel, Scene, SceneError, SceneReport
from crane_sym.scenes.reading import format_quantity as fq

GENERATED = "crane_sym.generated.hoist_startup"
CASES = (drive_law.PICKUP, drive_law.FROM_WEIGHT)
_CASE_TEXT = {drive_law.PICKUP: "with pick-up", drive_law.FROM_WEIGHT: "from weight"}
_MAX_DEPTH = 16          # bisection depth of the interval search (see ``maxima``)

#: The unit of each number of the reports (SI; ``"1"`` for a ratio: K = x/x_st,
#: the lag in x_st, the load's acceleration in v0/t_n, the time of (65)'s maximum
#: in t_n; ``certified`` is 1 or 0), for ``crane-sym run --format json``
#: (``fnmatch`` patterns, the first that matches).
VALUE_UNITS = {"t_ktilde_opt_max_*": "1", "t_*": "s", "valid_*": "s", "T": "s",
               "Omega": "rad/s", "v0": "m/s", "K_*": "1", "load_max_*": "1",
               "ktilde_opt_max_*": "1", "paper_ktilde_max_*": "1", "lag_*": "1",
               "certified": "1"}


def _generated() -> ModuleType:
    return importlib.import_module(GENERATED)


def figure_report(scene: Scene, module: ModuleType | None = None) -> SceneReport:
    """Numbers and curves of a figure scene of paper 002 (see ``crane_sym.scenes.reading``):
    the figure of its setting ``figure``, from the general module
    ``crane_sym.generated.hoist_startup``.

    Parameters
    ----------
    scene : crane_sym.scenes.reading.Scene
        SI parameters of its outputs (``Omega``, ``t_n``, ...); settings
        ``figure`` (one of ``"fig3"``, ``"fig5"``, ``"drive_laws"``),
        ``duration``, ``points``. What ``options.SCENE_CHECKS`` checked on
        load holds: the figure's parameters are given, Omega and tau_0 agree
        with (2) and (29).
    module : module, optional
        The scene's generated module (not read: the figures need the general one).

    Returns
    -------
    crane_sym.scenes.reading.SceneReport
        Always the values ``Omega`` [rad/s] and ``T`` [s]; the others are
        listed by :func:`fig3`, :func:`fig5`, :func:`drive_laws`.
    """
    # the figure, its parameters, Omega and tau_0 were checked on load (options.py)
    report = FIGURES[scene.settings["figure"]](scene, _generated())
    omega = scene.parameters["Omega"]
    report.values.update(Omega=omega, T=2 * math.pi / omega)
    return report


def fig3(scene: Scene, gen: ModuleType) -> SceneReport:
    """Fig. 3: :math:`K_{дин} = x/x_{ст} = 1 - \\cos\\Omega t` (35)-(38).

    Values: ``K_max_sampled`` and ``t_K_max_sampled`` on the grid,
    ``K_at_half_period`` (the paper: the largest displacement is twice the
    static one) and ``K_at_period``.
    """
    omega = scene.parameters["Omega"]
    period, times = 2 * math.pi / omega, scene.times()
    k = gen.dynamic_coefficient_instant(times, omega)
    top = int(np.argmax(k))
    half, full = (float(gen.dynamic_coefficient_instant(x, omega)) for x in (period / 2, period))
    values = {"K_max_sampled": float(k[top]), "t_K_max_sampled": float(times[top]),
              "K_at_half_period": half, "K_at_period": full}
    lines = [
        f"natural frequency Omega = {fq(omega, 'rad/s')}, period T = {fq(period, 's')}",
        f"K = x/x_st at T/2: {fq(half)} (paper, after (35): the largest displacement "
        f"is twice the static one, 2 x_st)",
        f"K = x/x_st at T: {full:.3f} (the load returns to x = 0 each period)",
        f"largest K on the grid: {fq(values['K_max_sampled'])} at "
        f"t = {fq(values['t_K_max_sampled'] / period)} T",
    ]
    panel = Panel(r"Suddenly applied load: $x(t)/x_\mathrm{ст} = 2\sin^2(\Omega t/2)$, "
                  "(35)-(38)", r"$x/x_\mathrm{ст}$",
                  [(r"$x(t)/x_\mathrm{ст}$ (38)", times / period, k),
                   (r"$x_\mathrm{ст}$ (static)", times / period, np.ones_like(times)),
                   (r"$2\,x_\mathrm{ст}$", times / period, np.full_like(times, 2.0))],
                  xlabel="$t/T$")
    return SceneReport(lines, values, [panel])


def fig5(scene: Scene, gen: ModuleType) -> SceneReport:
    """Fig. 5: :math:`x/x_{ст} = (t/t_п)(1 - \\sin\\Omega t/(\\Omega t))` (40)-(42).

    Values: ``K_at_t_n``, ``lag_max_sampled`` (largest amount by which x
    trails the static line k t/C, in x_ст) and ``lag_amplitude`` =
    :math:`1/(\\Omega t_п)`, the amplitude (40) gives it.
    """
    omega, t_n = scene.parameters["Omega"], scene.parameters["t_n"]
    period, times = 2 * math.pi / omega, scene.times()
    k = gen.dynamic_coefficient_ramp(times, omega, t_n)
    static = times / t_n
    values = {"K_at_t_n": float(gen.dynamic_coefficient_ramp(t_n, omega, t_n)),
              "lag_max_sampled": float((static - k).max()),
              "lag_amplitude": 1 / (omega * t_n)}
    lines = [
        f"natural frequency Omega = {fq(omega, 'rad/s')}, period T = {fq(period, 's')}, "
        f"t_n = {fq(t_n, 's')} = {fq(t_n / period)} T",
        f"x/x_st at t_n: {fq(values['K_at_t_n'])} (x_st = k t_n/C, (41))",
        f"x trails the static line k t/C by at most {fq(values['lag_max_sampled'])} x_st "
        f"(grid); (40): the lag sin(Ωt)/(Ω t_n) has amplitude 1/(Ω t_n) = "
        f"{fq(values['lag_amplitude'])}; x meets the line at t = T/2, T, 3T/2, ...",
    ]
    panel = Panel(r"Linearly growing load $\bar P = k\,t$: $x(t)/x_\mathrm{ст}$, "
                  "(40)-(42)", r"$x/x_\mathrm{ст}$",
                  [(r"$x(t)/x_\mathrm{ст}$ (42)", times / period, k),
                   (r"$k\,t/C$ over $x_\mathrm{ст}$ (static)", times / period, static)],
                  xlabel="$t/T$")
    return SceneReport(lines, values, [panel])


# --- the drive laws a_i -------------------------------------------------------------------
def _exact(scene: Scene) -> dict[str, sp.Rational]:
    """The scene's parameters as exact numbers (each float read as the decimal it prints)."""
    return {k: exact_number(v, k) for k, v in scene.parameters.items()}


def law_polynomial(i: int, v0: sp.Rational, t_n: sp.Rational) -> sp.Expr:
    """a_i(t) of (30) with numbers, on :math:`0 \\le t < t_п` (0 after)."""
    from . import model as hs
    return sp.expand(hs.PRINTED_LAWS[i].subs({hs.v0: v0, hs.t_n: t_n}))


def law_response(i: int, case: str, exact: dict[str, sp.Rational]) -> drive_law.DriveLawResponse:
    """The symbolic response of the hoist to a_i, by ``drive_law``; the
    contact time is (29) with the scene's v0, as in the generated functions."""
    poly = sp.Poly(law_polynomial(i, exact["v0"], exact["t_n"]), DEFAULT_TIME)
    law = drive_law.drive_law([0, exact["t_n"]], [poly.all_coeffs()[::-1]])
    tau0 = exact["m2"] * exact["g"] / (exact["C"] * exact["v0"])
    return drive_law.respond(law, exact["m1"], exact["m2"], exact["C"], exact["g"], case,
                             contact_time=tau0 if case == drive_law.PICKUP else None)


def _k(gen: ModuleType, case: str, i: int, times: np.ndarray, q: dict) -> np.ndarray:
    f = getattr(gen, f"dynamic_coefficient_{case}_a{i}")
    head = (times, q["Omega"]) + ((q["tau_0"],) if case == drive_law.PICKUP else ())
    return f(*head, q["m1"], q["m2"], q["g"], q["v0"], q["t_n"])


def _law(gen: ModuleType, i: int, times: np.ndarray, q: dict) -> np.ndarray:
    """a_i(t) [m/s²], from ``optimal_coefficient_from_weight_a{i}`` = a_i t_п/v0 (65),
    and 0 from t_п on, as in the drive-law functions."""
    law = getattr(gen, f"optimal_coefficient_from_weight_a{i}")
    inside = law(np.minimum(times, q["t_n"]), q["t_n"]) * q["v0"] / q["t_n"]
    return np.where(times < q["t_n"], inside, 0.0)


def _reference(case: str, a0: float, q: dict) -> float:
    """The force of (25), :math:`(m_2 P(0) + m_1 Q(0))/(m_1 + m_2)`."""
    weight = q["m2"] * q["g"]
    q0 = 0.0 if case == drive_law.PICKUP else weight
    return (q["m2"] * ((q["m1"] + q["m2"]) * a0 + weight) + q["m1"] * q0) / (q["m1"] + q["m2"])


def _rigid(gen: ModuleType, case: str, i: int, times: np.ndarray, q: dict) -> np.ndarray:
    """K of the rigid load, ẍ2 = a_i (61)-(62): rope force m2 a_i + Q over (25)."""
    weight = q["m2"] * q["g"]
    resistance = (weight * np.minimum(times / q["tau_0"], 1.0) if case == drive_law.PICKUP
                  else np.full_like(times, weight))
    a0 = float(_law(gen, i, np.zeros(1), q)[0])
    return (q["m2"] * _law(gen, i, times, q) + resistance) / _reference(case, a0, q)


def _printed_maxima() -> dict[int, tuple[float, str]]:
    """The largest k̃_i^(opt) the paper states, per law: (value, where and how)."""
    from .published_optimum import PUBLISHED
    from .tables import TABLE1
    printed = {p.label: p.printed.rhs for p in PUBLISHED if p.printed is not None}
    cell = {i: max((float(c.replace(",", ".")), n / 4) for n, c in enumerate(row))
            for i, row in TABLE1.items()}
    table = {i: f"Table 1's largest cell {cell[i][0]:.4f} at t/t_n = {cell[i][1]}"
             for i in cell}
    return {2: (cell[2][0], table[2]),
            3: (float(printed["max k̃3 (after (66))"]),
                f"1,7778 at t_3* = t_n/3 (text after (66)); {table[3]}"),
            4: (float(printed["max k̃4 (after (66))"]),
                f"2,0736 at t_4* = 0,4 t_n (text after (66), printed as k̃_дин3); "
                f"{table[4]}")}


def maxima(scene: Scene) -> dict[tuple[str, int], dict[str, Any]]:
    """Guaranteed maxima per (case, i), each over the part of [0, duration]
    where the model holds.

    ``"span"``: that part (``validity.model_span``: with pick-up from
    lift-off, :math:`t \\ge \\tau_0`, on; until the rope goes slack);
    ``"K"``: K of (26)/(27) over it; ``"load"``: the load's acceleration
    over :math:`v_0/t_п`, the elastic counterpart of k̃ of (63)-(65), over
    Table 1's span ([0, t_п] from weight, [τ_0, t_п] with pick-up) within
    it; ``"rigid"``: k̃_i^(opt) of (65) over [0, t_п] (symbolic).

    The elastic responses go straight to the interval search (``solveset``
    can stall factoring their derivatives, sums of sinusoids with long
    rational phases). Where a response starts flat (a_4 from weight: K − 1 =
    O(t⁵)) the enclosures of K' cannot exclude 0 on ever smaller boxes; the
    depth limit ``_MAX_DEPTH`` leaves those boxes to be bounded by an
    enclosure of K itself, and ``certified`` says that no bound exceeds the
    maximum found.
    """
    exact, t = _exact(scene), DEFAULT_TIME
    unit = exact["v0"] / exact["t_n"]
    out = {}
    for i in range(1, 5):
        rigid = maximum_on_interval(law_polynomial(i, exact["v0"], exact["t_n"]) / unit,
                                    t, 0, exact["t_n"])
        for case in CASES:
            response = law_response(i, case, exact)
            span = model_span(response, scene.settings["duration"])
            if span.empty:
                raise SceneError(f"scene {scene.name!r}: a{i} {_CASE_TEXT[case]}: the load "
                                 "never lifts within the duration; lengthen it")
            start, stop = (exact_number(x, "t") for x in (span.start, span.end))
            search = {"symbolic": False, "max_depth": _MAX_DEPTH}
            out[(case, i)] = {
                "span": span,
                "K": maximum_on_interval(response.dynamic_coefficient(), t, start, stop,
                                         **search),
                "load": maximum_on_interval(response.load_acceleration() / unit, t, start,
                                            min(exact["t_n"], stop), **search),
                "rigid": rigid}
    return out


def drive_laws(scene: Scene, gen: ModuleType) -> SceneReport:
    """K(t) for each a_i of (30), both lifting cases, and the maxima against the paper.

    Values, per ``case`` in ``pickup``, ``from_weight`` and law ``i``:
    ``valid_from_{case}_a{i}``, ``valid_to_{case}_a{i}`` (where the model
    holds, ``validity.model_span``); ``K_max_{case}_a{i}``,
    ``t_K_max_{case}_a{i}`` (guaranteed, over that part);
    ``K_max_sampled_{case}_a{i}`` (the generated function on the whole
    grid); ``load_max_{case}_a{i}``, ``t_load_max_{case}_a{i}`` (guaranteed,
    Table 1's span); per law ``ktilde_opt_max_a{i}``, ``t_ktilde_opt_max_a{i}``
    (guaranteed max of (65), t in units of t_п) and, where the paper states
    one, ``paper_ktilde_max_a{i}``; ``certified`` (1.0 when every maximum is).
    """
    q, times = scene.parameters, scene.times()
    found, printed = maxima(scene), _printed_maxima()
    values: dict[str, float] = {}
    by_case: dict[str, list[Panel]] = {case: [] for case in CASES}
    rows = []
    for (case, i), ext in found.items():
        curve, key = _k(gen, case, i, times, q), f"{case}_a{i}"
        values.update({f"K_max_{key}": float(ext["K"].value),
                       f"t_K_max_{key}": float(ext["K"].location),
                       f"K_max_sampled_{key}": float(curve.max()),
                       f"load_max_{key}": float(ext["load"].value),
                       f"t_load_max_{key}": float(ext["load"].location),
                       f"ktilde_opt_max_a{i}": float(ext["rigid"].value),
                       f"t_ktilde_opt_max_a{i}": float(ext["rigid"].location / q["t_n"])})
        if i in printed:
            values[f"paper_ktilde_max_a{i}"] = printed[i][0]
        span = ext["span"]
        values.update({f"valid_from_{key}": span.start, f"valid_to_{key}": span.end})
        rows.append(f"a{i} {_CASE_TEXT[case]:<12} K_max = {fq(values[f'K_max_{key}'], digits=7)}"
                    f" at t = {fq(values[f't_K_max_{key}'], 's')}; load acceleration max "
                    f"{fq(values[f'load_max_{key}'], digits=5)} v0/t_n at t = "
                    f"{fq(values[f't_load_max_{key}'], 's')}"
                    + ("" if span.whole else f"; valid {span.interval()}"))
        group = (rf"lifting {_CASE_TEXT[case]}, $K_\mathrm{{дин}}(t)$ "
                 f"{'(26)' if case == drive_law.PICKUP else '(27)'}")
        by_case[case].append(Panel(
            f"drive law $a_{i}$ of (30)", r"$K_\mathrm{дин}$",
            [("elastic rope, Duhamel (generated)", times, curve),
             (rf"rigid load, $\ddot x_2 = a_{i}$ (61)-(62)", times,
              _rigid(gen, case, i, times, q))], group=group, invalid=span.spans()))
    values["certified"] = float(all(e.certified for d in found.values() for e in d.values()))
    span, period = scene.settings["duration"], 2 * math.pi / q["Omega"]
    lines = [f"maxima over [0, {fq(span, 's')}], where the model holds, by interval "
             f"arithmetic (elastic) and solveset (rigid), all certified: "
             f"{bool(values['certified'])}; T = {fq(period, 's')}, "
             f"tau_0 = {fq(q['tau_0'], 's')}"]
    if span >= q["t_n"] + period:
        lines.append("after t_n the motion is a free undamped oscillation, so these are "
                     "the maxima for all t >= 0")
    lines += _validity_warnings(found) + rows
    lines.append("k~_i^(opt) of (65) (rigid load, in v0/t_n) against the paper and the "
                 "elastic load's acceleration over Table 1's span:")
    for i in range(1, 5):
        ours = (f"max (65) = {fq(values[f'ktilde_opt_max_a{i}'], digits=6)} at t = "
                f"{fq(values[f't_ktilde_opt_max_a{i}'], digits=4)} t_n")
        paper = (f"paper: {printed[i][1]}" if i in printed else
                 "paper: (65) gives k~_1 = 1, no Table 1 row")
        elastic = ", ".join(f"{_CASE_TEXT[c]} {fq(values[f'load_max_{c}_a{i}'], digits=5)}"
                            for c in CASES)
        lines.append(f"a{i}: {ours}; {paper}; elastic: {elastic}")
    panels = [p for case in CASES for p in by_case[case]] + [_table1_panel(gen, times, q)]
    return SceneReport(lines, values, panels)


def _validity_warnings(found: dict[tuple[str, int], dict[str, Any]]) -> list[str]:
    """The ``warning:`` lines of the laws whose model does not hold throughout:
    the first law's text, the others' instants."""
    partial = [(i, d["span"]) for (_, i), d in found.items() if not d["span"].whole]
    if not partial:
        return []
    first = partial[0][1].warnings(f"a{partial[0][0]}:")
    others = ", ".join(f"a{i}: {s.interval()}" for i, s in partial[1:])
    return first + (
        [f"{WARNING} valid parts of the others: {others}"] if others else [])


def _table1_panel(gen: ModuleType, times: np.ndarray, q: dict) -> Panel:
    """k̃_i^(opt) of (65) (Table 1) and the elastic load's ẍ2/(v0/t_п), from weight:
    :math:`m_2 \\ddot x_2 = K F_{ref} - m_2 g` by (1) and (25)."""
    mask, unit = times <= q["t_n"], q["v0"] / q["t_n"]
    panel = Panel(r"Table 1, (65): $\tilde k_i^\mathrm{(opt)}$ of the rigid load (dashed) and "
                  r"the elastic load's $\ddot x_2/(v_0/t_\mathrm{п})$, from weight",
                  r"$\tilde k$", [], xlabel=r"$t/t_\mathrm{п}$")
    for i in range(2, 5):
        a0 = float(_law(gen, i, np.zeros(1), q)[0])
        force = _k(gen, drive_law.FROM_WEIGHT, i, times, q) * _reference(
            drive_law.FROM_WEIGHT, a0, q)
        load = (force - q["m2"] * q["g"]) / (q["m2"] * unit)
        x = times[mask] / q["t_n"]
        rigid, elastic = rf"$\tilde k_{i}^\mathrm{{(opt)}}$ (65)", f"elastic, $a_{i}$"
        panel.curves += [(rigid, x, _law(gen, i, times, q)[mask] / unit),
                         (elastic, x, load[mask])]
        panel.styles.update({rigid: {"color": f"C{i}", "linestyle": "--"},
                             elastic: {"color": f"C{i}"}})
    return panel


FIGURES: dict[str, Callable[[Scene, ModuleType], SceneReport]] = {
    "fig3": fig3, "fig5": fig5, "drive_laws": drive_laws}

#: The kinds of scene of paper 002: a drive law given as data (its own module,
#: ``drive_law_scene.drive_law_report``), else a figure of the paper.
REPORTS = (SceneKind("a drive law of one's own ([drive_law])", drive_law_report,
                     load=DRIVE_LAW.table),
           SceneKind("a figure of the paper (setting figure)", figure_report))


def scene_report(scene: Scene, module: ModuleType | None = None) -> SceneReport:
    """Numbers and curves of a paper-002 scene: the report of its kind (``REPORTS``).

    Parameters
    ----------
    scene : crane_sym.scenes.reading.Scene
        The loaded scene.
    module : module, optional
        The scene's generated module (a drive-law scene's report reads it).

    Returns
    -------
    crane_sym.scenes.reading.SceneReport
    """
    return report_for(REPORTS, scene, module)
