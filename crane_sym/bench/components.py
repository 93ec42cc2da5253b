"""Where the time of a component model goes: from its TOML file to its run.

Each stage is timed on its own, SymPy's cache cleared before it (a model
derived once in a session is what a user meets): reading the file and its
units into parts, the topology (rigid groups), Lagrange's equations of T, Π,
Φ and Q, the mode matrices (M, D, K, f in the symbols, then as a NumPy
function), and the first run (the steady start, each mode's closed form, the
certified event search). A repeated run of the derived model is the "run"
row: its least time over three (the closed forms of its modes and the NumPy
functions of its three systems are kept from the first run). The first run's
split comes from a profile of the first run of the same model derived anew
(cProfile's cumulative times as fractions of its whole, applied to the
unprofiled time).

Targets (issue 27, item 7): deriving and solving a model of up to 5 bodies
is at most 2 s; a run of the derived model with at least 30 phases at most
0.2 s. Issue 34: a model of up to 8 bodies at most 5 s, of up to 20 bodies
at most 10 s, near-critical damping or not (``examples/hard_cases``).
"""
from __future__ import annotations

import cProfile
import pstats
import time
from dataclasses import dataclass
from pathlib import Path
from typing import Sequence

from sympy.core.cache import clear_cache

from crane_sym.bench.rows import least_time
from crane_sym.bench.targets import Goal
from crane_sym.components.hybrid import ComponentSystem
from crane_sym.components.model import Model
from crane_sym.components.reading import read_parts
from crane_sym.components.topology import assemble
from crane_sym.mechanics.closed_forms import clear_cache as clear_forms
from crane_sym.markdown import markdown_table

__all__ = ["BY_SIZE", "ComponentTiming", "DERIVE_AND_SOLVE", "RUN", "as_dicts", "as_markdown",
           "goals", "time_model"]

#: Limits of item 7, in seconds.
DERIVE_AND_SOLVE, RUN = 2.0, 0.2
#: Limits of deriving and solving by the number of bodies (issue 34), in seconds.
BY_SIZE = ((5, DERIVE_AND_SOLVE), (8, 5.0), (20, 10.0))
#: The least number of phases for which a run's time is held to :data:`RUN`.
PHASES = 30
#: What the first run's profile is split into: (label, function name, file ending);
#: the rest of the run (the steady start's least squares, the switches) is the
#: remainder.
SPLIT = (("lambdify, once per system (3 a run: 2 probes of the steady start)", "numeric",
          "components/equations.py"),
         ("closed forms of the modes (exact Jordan form where cheap, spectral clusters "
          "elsewhere)", "closed_form", "mechanics/closed_forms.py"),
         ("certified event search", "first_crossing", "mechanics/piecewise_linear.py"))


@dataclass(frozen=True)
class ComponentTiming:
    """Seconds of each stage of one model, its size and its first run's split."""

    name: str
    bodies: int
    groups: int
    backlash: int
    brakes: int
    phases: int
    stages: tuple[tuple[str, float], ...]
    run: float
    split: tuple[tuple[str, float], ...]           # fractions of the first run

    @property
    def derive_and_solve(self) -> float:
        """From the file to the first run's end."""
        return sum(s for _, s in self.stages)


def _timed(call):
    _cold()
    t0 = time.perf_counter()
    out = call()
    return time.perf_counter() - t0, out


def _split(read) -> tuple[tuple[str, float], ...]:
    """The shares of a first run by :data:`SPLIT`, from a profile of the run of
    a model derived anew (its mode matrices in the symbols made before, as the
    unprofiled first run has them; its lambdify not yet), each share its
    fraction of the profiled whole (the profiler's overhead scaled out)."""
    model = Model(read.parts, read.name, read.title)
    model.equations.linear
    profile = cProfile.Profile()
    _cold()
    profile.enable()
    model.run(read.duration, read.body, read.speed, rest=read.rest)
    profile.disable()
    stats = pstats.Stats(profile)
    whole = stats.total_tt
    out = []
    for label, name, where in SPLIT:
        total = sum(v[3] for (path, _, fn), v in stats.stats.items()
                    if fn == name and path.replace("\\", "/").endswith(where))
        out.append((label, total / whole))
    out.append(("the rest: steady start's least squares, switches", 1 - sum(f for _, f in out)))
    return tuple(out)


def _cold() -> None:
    clear_cache()
    clear_forms()


def time_model(path: str | Path) -> ComponentTiming:
    """Time every stage of the component file ``path`` (see the module docstring).

    Parameters
    ----------
    path : str or Path
        A component model TOML file.
    """
    t_read, read = _timed(lambda: read_parts(path))
    t_model, model = _timed(lambda: Model(read.parts, read.name, read.title))
    t_topology, _ = _timed(lambda: assemble(read.parts))      # again, alone
    equations = model.equations
    t_linear, _ = _timed(lambda: equations.linear)
    t_numeric, _ = _timed(lambda: ComponentSystem(equations, {equations.motor_loads[0]: 0.0}
                                                  if equations.motor_loads else {}))
    assembly = model.assembly

    def solve():
        return model.run(read.duration, read.body, read.speed, rest=read.rest)
    t_first, first = _timed(solve)
    t_run, _ = least_time(solve, budget=1.0, repeats=3)
    t_peaks, _ = _timed(lambda: first.peaks)
    split = _split(read)
    system = first.system
    stages = (("read the file, units, parts", t_read), ("topology: rigid groups", t_topology),
              ("Lagrange: T, Π, Φ, Q and the equations", max(t_model - t_topology, 0.0)),
              ("mode matrices M, D, K, f (symbolic)", t_linear),
              ("mode matrices as NumPy (lambdify)", t_numeric),
              ("first run: steady start, closed forms, events", t_first),
              ("peaks of every link (certified bounds)", t_peaks))
    return ComponentTiming(read.name, len(assembly.bodies), len(assembly.groups),
                           len(system.backlash), len(system.of_kind["brake"]),
                           len(first.result.segments),
                           stages, t_run, split)


def goals(timings: Sequence[ComponentTiming]) -> list[Goal]:
    """Item 7's targets for every model (the run's only where it has
    :data:`PHASES` phases or more)."""
    out = []
    for t in timings:
        what = (f"{t.bodies} bodies, {t.backlash} backlash, {t.brakes} brakes, "
                f"{t.phases} phases")
        limit = next((s for n, s in BY_SIZE if t.bodies <= n), BY_SIZE[-1][1])
        out.append(Goal(t.name, "derive and solve (s)", t.derive_and_solve, limit, what))
        if t.phases >= PHASES:
            out.append(Goal(t.name, f"run of >= {PHASES} phases (s)", t.run, RUN, what))
    return out


def as_dicts(timings: Sequence[ComponentTiming]) -> list[dict]:
    """JSON-ready rows, one a model: its size, each stage in seconds, the run,
    the first run's split, and its targets met or not (``bench --components
    FILE --format json``).

    Parameters
    ----------
    timings : sequence of ComponentTiming
        Rows of :func:`time_model`.
    """
    out = []
    for t in timings:
        out.append({"model": t.name, "bodies": t.bodies, "groups": t.groups,
                    "backlash": t.backlash, "brakes": t.brakes, "phases": t.phases,
                    "stages_seconds": dict(t.stages), "run_seconds": t.run,
                    "first_run_split": dict(t.split),
                    "derive_and_solve_seconds": t.derive_and_solve,
                    "targets": [{"target": g.target, "measured": g.measured,
                                 "limit": g.limit, "met": g.met} for g in goals([t])]})
    return out


def as_markdown(timings: Sequence[ComponentTiming]) -> str:
    """One table of the stages per model, the first run's split, then the targets.

    Parameters
    ----------
    timings : sequence of ComponentTiming
        Rows of :func:`time_model`.
    """
    from crane_sym.bench.targets import goals_table
    parts = []
    for t in timings:
        rows = [[label, f"{s * 1e3:.1f}"] for label, s in t.stages]
        first = dict(t.stages)["first run: steady start, closed forms, events"]
        rows += [[f"  of which {label}", f"{f * first * 1e3:.1f}"] for label, f in t.split]
        rows += [["derive and solve (sum)", f"{t.derive_and_solve * 1e3:.1f}"],
                 ["run of the derived model (least of 3)", f"{t.run * 1e3:.1f}"]]
        parts += [f"### {t.name}: {t.bodies} bodies in {t.groups} rigid groups, "
                  f"{t.backlash} backlash, {t.brakes} brakes, {t.phases} phases", "",
                  markdown_table(["stage", "ms"], rows, align="lr"), ""]
    parts += ["### Targets", "", goals_table(goals(timings)), ""]
    return "\n".join(parts)
