"""Speed against error of piecewise-linear runs: the phases in closed form
(``crane_sym.mechanics.piecewise_linear``, tabulated by ``crane_sym.mechanics.phase_table``)
against SciPy's ``solve_ivp`` with events, the alternative a user would run.

The integrator gets what a careful user gives it: the same modes, guards and
switching rule, a terminal event per guard, a restart at every event and
scheduled instant, dense output, rtol every half decade from 1e-6 to 1e-12
and atol scaled to the state's size. Both are measured against a reference
that shares neither's arithmetic: each phase's exp(Mt) by ``mpmath.expm`` at
30 digits, carried from phase to phase at the closed form's event times.
"""
from __future__ import annotations

import tempfile
import time
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Hashable, Sequence

import mpmath
import numpy as np
from scipy.integrate import solve_ivp

from crane_sym import registry
from crane_sym.markdown import markdown_table
from crane_sym.mechanics.closed_forms import clear_cache
from crane_sym.mechanics.phase_table import HybridRun, PhaseTable
from crane_sym.mechanics.piecewise_linear import PiecewiseResult, by_phase
from crane_sym.scenes.reading import list_scenes, load_scene
from crane_sym.scenes.run import import_module_file
from crane_sym.scenes.specialize import module_name, render_scene_module, tabulated_runs

__all__ = ["IntegratedRun", "PiecewiseRow", "as_markdown", "bench_run", "integrate_hybrid",
           "mp_reference", "RTOLS", "scene_sections", "summary"]

#: rtol of the integrators: every half decade from 1e-6 to 1e-12.
RTOLS = tuple(float(f"{10 ** (-k / 2):.3g}") for k in range(12, 25))


@dataclass
class IntegratedRun:
    """A run integrated phase by phase: (t0, t1, mode, dense solution) each."""

    phases: list[tuple[float, float, Hashable, Any]] = field(default_factory=list)

    def _each(self, times: np.ndarray):
        for i, mask in by_phase([p[0] for p in self.phases], times):
            _, _, mode, sol = self.phases[i]
            yield mask, mode, sol(times[mask])

    def state(self, times: np.ndarray) -> np.ndarray:
        """x at ``times``, shape ``times.shape + (n,)``."""
        t0, _, _, sol = self.phases[0]
        out = np.empty(np.shape(times) + sol(t0).shape)
        for mask, _, x in self._each(times):
            out[mask] = x.T
        return out

    def output(self, run: HybridRun, times: np.ndarray) -> np.ndarray:
        """The run's output (w·x + k)/scale at ``times``."""
        out = np.empty(np.shape(times))
        for mask, mode, x in self._each(times):
            w, k = run.output(mode)
            out[mask] = (np.asarray(w) @ x + k) / run.scale
        return out


def integrate_hybrid(run: HybridRun, rtol: float, atol: float, method: str = "DOP853",
                     max_step: float = np.inf, max_phases: int = 10_000) -> IntegratedRun:
    """``run`` by ``solve_ivp``: each mode until its first terminal event (a guard
    changing sign) or the next scheduled instant, then ``run.system.switch``."""
    system, mode = run.system, run.mode
    t, x = 0.0, np.asarray(run.x0, float)
    pending = sorted((float(s), name) for s, name in run.schedule if 0 <= s < run.t_end)
    result = IntegratedRun()
    for _ in range(max_phases):
        A, b = system.matrices(mode)
        stop = pending[0][0] if pending else run.t_end
        guards = system.guards(mode)
        events = []
        for guard in guards:
            def event(_, y, w=np.array(guard.weights), k=guard.constant):
                return w @ y + k
            event.terminal, event.direction = True, guard.direction
            events.append(event)
        if stop > t:
            sol = solve_ivp(lambda _, y: A @ y + b, (t, stop), x, method=method, rtol=rtol,
                            atol=atol, dense_output=True, max_step=max_step, events=events,
                            **({"jac": lambda *_: A} if method in ("Radau", "BDF", "LSODA") else {}))
            hits = [(te[0], g.name) for te, g in zip(sol.t_events or [], guards)
                    if len(te) and te[0] > t]
            end, name = min(hits) if hits else (stop, None)
            result.phases.append((t, end, mode, sol.sol))
            x = sol.sol(end)
        else:
            end, name = t, None
        t = end
        if name is None:
            if not pending:
                return result
            name = pending.pop(0)[1]
        mode, x = system.switch(mode, name, t, x)
    raise RuntimeError(f"more than {max_phases} phases")


def mp_reference(run: HybridRun, result: PiecewiseResult, times: np.ndarray,
                 dps: int = 30) -> np.ndarray:
    """The output at ``times`` from exp(Mt) by mpmath at ``dps`` digits, phase by
    phase, the state carried in mpmath across the closed form's event times
    (each switch applied to the state in double, as the model defines it)."""
    out = np.empty(np.shape(times))
    with mpmath.workdps(dps):
        z = mpmath.matrix(list(map(mpmath.mpf, run.x0)) + [1])
        for number, seg in enumerate(result.segments):
            A, b = run.system.matrices(seg.mode)
            n = len(b)
            M = mpmath.zeros(n + 1, n + 1)
            for i in range(n):
                for j in range(n):
                    M[i, j] = mpmath.mpf(float(A[i, j]))
                M[i, n] = mpmath.mpf(float(b[i]))
            w, k = run.output(seg.mode)
            inside = np.flatnonzero((times >= seg.t0) & (times <= seg.t1))
            for i in inside:
                zt = mpmath.expm(M * (mpmath.mpf(float(times[i])) - mpmath.mpf(seg.t0))) * z
                value = sum(mpmath.mpf(float(w[j])) * zt[j] for j in range(n)) + k
                out[i] = float(value / run.scale)
            z = mpmath.expm(M * (mpmath.mpf(seg.t1) - mpmath.mpf(seg.t0))) * z
            if number + 1 < len(result.segments):
                nxt = result.segments[number + 1]
                for j in range(n):        # what the switch rule set (a stuck speed)
                    if abs(nxt.x0[j] - float(z[j])) > 1e-9 * (1 + abs(float(z[j]))):
                        z[j] = mpmath.mpf(float(nxt.x0[j]))
    return out


@dataclass(frozen=True)
class PiecewiseRow:
    """One way to compute the run: seconds (best of ``repeats``), worst error
    over the sample relative to the peak, phases found."""

    method: str
    rtol: float
    seconds: float
    error: float
    phases: int


def _best(fn, repeats: int) -> tuple[float, Any]:
    best, value = np.inf, None
    for _ in range(repeats):
        start = time.perf_counter()
        value = fn()
        best = min(best, time.perf_counter() - start)
    return best, value


def bench_run(run: HybridRun, points: int = 2000, reference_points: int = 400,
              methods: Sequence[str] = ("DOP853", "LSODA", "Radau"),
              rtols: Sequence[float] = RTOLS, repeats: int = 3,
              module_function: Any = None) -> tuple[list[PiecewiseRow], PhaseTable]:
    """Rows for the closed form (event search and table; evaluation of ``points``
    times; the scene module's function if given) and every integrator."""
    clear_cache()
    cold_s, _ = _best(run.solve, 1)                   # SymPy's Jordan forms included
    solve_s, result = _best(run.solve, repeats)
    table_s, table = _best(lambda: run.table(result), repeats)
    times = np.linspace(0.0, run.t_end, points)
    check = np.linspace(0.0, run.t_end, reference_points)
    ref = mp_reference(run, result, check)
    peak = np.max(np.abs(ref))
    error = lambda values: float(np.max(np.abs(values - ref)) / peak)  # noqa: E731
    eval_s, _ = _best(lambda: table(times), repeats * 3)
    phases = len(table.events)
    rows = [PiecewiseRow("closed form: event search, cold", np.nan, cold_s, np.nan, phases),
            PiecewiseRow("closed form: event search", np.nan, solve_s, np.nan, phases),
            PiecewiseRow("closed form: table", np.nan, table_s, np.nan, phases),
            PiecewiseRow(f"closed form: evaluate {points} times", np.nan, eval_s,
                         error(table(check)), phases)]
    if module_function is not None:
        gen_s, _ = _best(lambda: module_function(times), repeats * 3)
        rows.append(PiecewiseRow(f"scene module: evaluate {points} times", np.nan, gen_s,
                                 error(module_function(check)), phases))
    size = np.max(np.abs([seg.x0 for seg in result.segments]), axis=0) + 1.0
    # A user who knows the contact frequency caps the step at a tenth of its period.
    period = 2 * np.pi / max(max(seg.form.omegas.max(initial=0.0) for seg in result.segments),
                             1.0 / run.t_end)
    for method in methods:
        for cap, name in ((np.inf, method), (period / 10, f"{method}, max_step T/10")):
            for rtol in rtols:
                seconds, sol = _best(lambda: integrate_hybrid(run, rtol, rtol * size, method,
                                                              cap), 1)
                sol_eval_s, _ = _best(lambda: sol.output(run, times), 1)
                rows.append(PiecewiseRow(name, rtol, seconds + sol_eval_s,
                                         error(sol.output(run, check)), len(sol.phases)))
    return rows, table


def summary(rows: Sequence[PiecewiseRow], points: int) -> list[str]:
    """The lines a reader wants first: the closed form's cost and error, the
    fastest integrator reaching 1e-6 and 1e-9 of the peak, how often the
    integrators lost a contact, and where the closed form loses."""
    by = {r.method: r for r in rows}
    warm = sum(by[m].seconds for m in ("closed form: event search", "closed form: table",
                                       f"closed form: evaluate {points} times"))
    closed_error = by[f"closed form: evaluate {points} times"].error
    phases = by["closed form: table"].phases
    lines = [f"closed form: {warm * 1e3:.1f} ms warm (event search, table, {points} times), "
             f"error {closed_error:.1e} of the peak, {phases} phases; cold (SymPy's Jordan "
             f"forms, once per new set of modes) {by['closed form: event search, cold'].seconds:.2f} s"]
    module = by.get(f"scene module: evaluate {points} times")
    if module:
        lines.append(f"scene module alone (the run tabulated when it was generated): "
                     f"{module.seconds * 1e3:.2f} ms for {points} times, error {module.error:.1e}")
    integrators = [r for r in rows if not np.isnan(r.rtol)]
    for goal in (1e-6, 1e-9):
        good = [r for r in integrators if r.error <= goal]
        if good:
            best = min(good, key=lambda r: r.seconds)
            lines.append(f"fastest integrator within {goal:g} of the peak: {best.method} at rtol "
                         f"{best.rtol:.3g}, {best.seconds * 1e3:.1f} ms = "
                         f"{best.seconds / warm:.2g}x the warm closed form"
                         + (f", {best.seconds / module.seconds:.0f}x the scene module"
                            if module else ""))
        else:
            lines.append(f"no integrator setting came within {goal:g} of the peak")
    lost = [r for r in integrators if r.phases != phases]
    lines.append(f"integrator runs that skipped or added a contact: {len(lost)} of "
                 f"{len(integrators)}")
    faster = [r for r in integrators if r.seconds < warm]
    if faster:
        lines.append(f"integrator runs faster than the warm closed form: {len(faster)} "
                     f"(best error among them {min(r.error for r in faster):.1e})")
    cold = by["closed form: event search, cold"].seconds
    lines.append(f"integrator runs faster than the cold closed form: "
                 f"{sum(r.seconds < cold for r in integrators)} of {len(integrators)}")
    return lines


def as_markdown(rows: Sequence[PiecewiseRow], points: int) -> str:
    """The rows as a Markdown table, each time also as a ratio to the closed form
    (event search, table and evaluation of ``points`` times)."""
    closed = sum(r.seconds for r in rows if r.method.startswith("closed form")
                 and not r.method.endswith("cold"))
    lines = []
    for r in rows:
        rtol = "" if np.isnan(r.rtol) else f"{r.rtol:.3g}"
        err = "" if np.isnan(r.error) else f"{r.error:.1e}"
        ratio = "" if r.method.startswith(("closed", "scene")) else f"{r.seconds / closed:.2g}"
        lines.append([r.method, rtol, f"{r.seconds:.2e}", ratio, err, r.phases])
    return markdown_table(["method", "rtol", "seconds", "× closed form", "error / peak",
                           "phases"], lines)


def scene_sections(derivation_id: str, points: int = 2000,
                   methods: Sequence[str] = ("DOP853", "LSODA", "Radau"),
                   rtols: Sequence[float] = RTOLS) -> list[str]:
    """One Markdown section per tabulated run of every shipped scene of the
    derivation (the first output of each: the others are the same run, read
    through other weights): the closed form (the library's and the scene
    module's) against the integrators, in one run.

    Parameters
    ----------
    derivation_id : str
        A registered derivation id.
    points : int, optional
        Number of output times.
    methods : sequence of str, optional
        ``solve_ivp`` methods compared with the closed form.
    rtols : sequence of float, optional
        Integrator tolerances.
    """
    d = registry.get(derivation_id)
    sections = []
    for scene in map(load_scene, list_scenes()):
        wanted, systems = [], []
        for out, run in tabulated_runs(d, scene) if scene.derivation == d.id else []:
            if run.system not in systems:
                wanted.append((out, run))
                systems.append(run.system)
        if not wanted:
            continue
        with tempfile.TemporaryDirectory() as folder:
            path = Path(folder) / module_name(scene)
            path.write_text(render_scene_module(scene), encoding="utf-8")
            module = import_module_file(path)
        for out, run in wanted:
            rows, table = bench_run(run, points, methods=methods, rtols=rtols,
                                    module_function=getattr(module, out.name))
            sections += [f"## {out.name}, scene {scene.name}", "",
                         f"{out.summary} {len(table.events)} phases on [0, {run.t_end:g}] s; "
                         f"{points} evaluation times; errors on 400 times against exp(Mt) by "
                         "mpmath at 30 digits; integrators restarted at every event, atol = "
                         "rtol × the state's size.", "",
                         *[f"- {line}" for line in summary(rows, points)], "",
                         as_markdown(rows, points), ""]
    return sections
