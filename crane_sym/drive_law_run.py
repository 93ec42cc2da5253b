"""``crane-sym run`` for a drive-law scene: the generated code, plotted and checked.

The scene's module is rendered (``drive_law.render_drive_law_module``: the
symbolic convolution, once) and written beside the plot as
``scene_<name>.py``, the same file ``crane-sym generate --scene`` writes; the
curves are evaluated from that file. The largest dynamic coefficient comes
from the symbolic response by ``extrema.maximum_on_interval`` (interval
arithmetic: guaranteed, not sampled), and the sampled curve must stay below it.
"""
from __future__ import annotations

import importlib.util
import math
from pathlib import Path
from types import ModuleType

import numpy as np

from .drive_law import (FROM_WEIGHT, DriveLawScene, load_drive_law_scene, module_name,
                        render_drive_law_module)
from .extrema import maximum_on_interval
from .loads import DEFAULT_TIME, exact_number
from .scenes import Panel, SceneError, SceneReport, plot_report
from .scenes import format_quantity as fq

_MAX_DEPTH = 16        # bisection depth of the interval search
_SAMPLE_SLACK = 1e-12  # relative: a sampled K may exceed the bound by rounding only

__all__ = ["run_drive_law_scene"]


def _load(path: Path) -> ModuleType:
    """Import the module the printer wrote at ``path`` (our own output, not user text)."""
    spec = importlib.util.spec_from_file_location(f"_crane_sym_scene_{path.stem}", path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def drive_law_report(scene: DriveLawScene, gen: ModuleType) -> SceneReport:
    """Curves of ``gen`` over the scene's span and the guaranteed maximum of K."""
    response = scene.response()
    t = np.linspace(0.0, scene.duration, scene.points)
    k = gen.dynamic_coefficient(t)
    found = maximum_on_interval(response.dynamic_coefficient(), DEFAULT_TIME, 0,
                                exact_number(scene.duration, "duration"),
                                symbolic=False, max_depth=_MAX_DEPTH)
    k_max, t_max = float(found.value), float(found.location)
    if np.max(k) > k_max * (1 + _SAMPLE_SLACK):
        raise SceneError(f"scene {scene.name!r}: the generated K reaches {np.max(k)!r}, "
                         f"above the guaranteed maximum {k_max!r}")
    omega = math.sqrt(float(scene.C * (scene.m1 + scene.m2) / (scene.m1 * scene.m2)))
    case = "from weight (27)" if scene.lifting == FROM_WEIGHT else "with pick-up (26)"
    v0 = float(response.final_speed)
    lines = [f"lifting {case}; natural frequency Omega = {omega:.4g} rad/s (2), "
             f"period T = {fq(2 * math.pi / omega, 's')}",
             f"final drive speed v0 = {fq(v0, 'm/s')}"
             + (f", rope picks up the load at tau_0 = {fq(float(response.contact_time), 's')}"
                if response.contact_time is not None else ""),
             f"K_max = {k_max:.6f} at t = {fq(t_max, 's')} over [0, {fq(scene.duration, 's')}] "
             f"(interval arithmetic, certified: {found.certified}); sampled max "
             f"{np.max(k):.6f}"]
    panels = [Panel("drive law a(t) and speed v(t)", "a [m/s²], v [m/s]",
                    [("a(t)", t, gen.drive_acceleration(t)), ("v(t)", t, gen.drive_speed(t))]),
              Panel("dynamic coefficient K(t) (25)", "K", [("K(t)", t, k)]),
              Panel("rope force (24)", "F [kN]", [("C x(t)", t, gen.rope_force(t) / 1e3)]),
              Panel("load acceleration (1)", "a₂ [m/s²]",
                    [("ẍ₂(t)", t, gen.load_acceleration(t))])]
    return SceneReport(lines=lines, values={"Omega": omega, "K_max": k_max, "t_max": t_max,
                                            "v0": v0, "certified": float(found.certified)},
                       panels=panels)


def run_drive_law_scene(path_or_name: str | Path, outdir: Path
                        ) -> tuple[DriveLawScene, SceneReport, Path]:
    """Render the scene's module into ``outdir``, evaluate it, plot it.

    Returns the scene, its report and the PNG ``<outdir>/<name>.png``.
    """
    scene = load_drive_law_scene(path_or_name)
    outdir = Path(outdir)
    outdir.mkdir(parents=True, exist_ok=True)
    source = outdir / module_name(scene)
    source.write_text(render_drive_law_module(scene), encoding="utf-8")
    report = drive_law_report(scene, _load(source))
    report.lines.append(f"module written to {source}")
    return scene, report, plot_report(report, scene.title, outdir / f"{scene.name}.png")
