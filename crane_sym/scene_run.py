"""Stage 4 of the scene pipeline: run a scene and plot it.

Every scene takes the same path (``crane-sym run``): read and validate the
TOML (``scenes.load_scene``) → specialize (``specialize``) → generate its
module, written beside the plot as ``scene_<name>.py``, the file
``crane-sym generate --scene`` writes → import that file and hand it to the
derivation's ``scene_report(scene, module)`` → plot the report's panels.
"""
from __future__ import annotations

import importlib
import importlib.util
import inspect
from pathlib import Path
from types import ModuleType
from typing import Callable

from . import registry
from .scenes import Scene, SceneError, SceneReport, load_scene
from .specialize import module_name, render_scene_module

__all__ = ["import_module_file", "plot_figures", "plot_report", "run_scene", "time_function"]


def import_module_file(path: Path) -> ModuleType:
    """Import the module the printer wrote at ``path`` (our own output, never
    user text)."""
    spec = importlib.util.spec_from_file_location(f"_crane_sym_scene_{path.stem}", path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def time_function(scene: Scene, module: ModuleType, name: str) -> Callable:
    """``name`` as a function of time alone: from the scene's own module when
    the scene names it among its outputs, else from the paper's general
    module ``crane_sym.generated.<id>`` with the scene's parameters filled in."""
    if name in scene.outputs:
        return getattr(module, name)
    general = getattr(importlib.import_module(f"crane_sym.generated.{scene.derivation}"),
                      name)
    names = [p for p in inspect.signature(general).parameters if p != "t"]
    missing = [p for p in names if p not in scene.parameters]
    if missing:
        raise SceneError(f"scene {scene.name!r}: {name} needs {missing}, which the scene "
                         "does not give")
    given = {p: scene.parameters[p] for p in names}
    return lambda t: general(t, **given)


def run_scene(scene: Scene | str | Path, outdir: Path) -> tuple[SceneReport, Path]:
    """Evaluate a scene through its own generated module and plot it.

    Parameters
    ----------
    scene : Scene, or a scene name or TOML path
        From :func:`crane_sym.scenes.load_scene`, or what it reads.
    outdir : Path
        Folder for the module and the plot; created if needed.

    Returns
    -------
    (SceneReport, Path)
        The derivation's report (its last line names the module written) and
        the PNG ``<outdir>/<scene.name>.png``.
    """
    if not isinstance(scene, Scene):
        scene = load_scene(scene)
    make = getattr(registry.module(scene.derivation), "scene_report", None)
    if make is None:
        raise SceneError(f"derivation {scene.derivation!r} has no scene_report()")
    outdir = Path(outdir)
    outdir.mkdir(parents=True, exist_ok=True)
    source = outdir / module_name(scene)
    source.write_text(render_scene_module(scene), encoding="utf-8")
    report = make(scene, import_module_file(source))
    if not isinstance(report, SceneReport) or not report.panels:
        raise SceneError(f"{scene.derivation}.scene_report() returned no panels")
    report.lines.append(f"module written to {source}")
    path, *extras = plot_figures(report, scene.title, outdir / f"{scene.name}.png")
    report.lines.extend(f"figure written to {extra}" for extra in extras)
    return report, path


def plot_report(report: SceneReport, title: str, path: Path) -> Path:
    """Write the report's panels to PNGs (see :func:`plot_figures`); returns ``path``."""
    return plot_figures(report, title, path)[0]


def plot_figures(report: SceneReport, title: str, path: Path) -> list[Path]:
    """Write the report's panels, one subplot each: the panels of the first figure
    named (``Panel.figure``, ``""`` for a scene with one figure) to ``path``,
    those of each further figure ``name`` to ``<stem>_<name>.png`` beside it.
    Returns the paths written, ``path`` first."""
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    groups: dict[str, list] = {}
    for panel in report.panels:
        groups.setdefault(panel.figure, []).append(panel)
    written = []
    for i, (name, panels) in enumerate(groups.items()):
        target = path if i == 0 else path.with_name(f"{path.stem}_{name}.png")
        _plot_panels(panels, title, target)
        written.append(target)
    return written


def _plot_panels(panels: list, title: str, path: Path) -> None:
    """One PNG: the panels stacked, legends placed where they cover the least data."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    n = len(panels)
    fig, axes = plt.subplots(n, 1, figsize=(8, 3.4 * n), squeeze=False,
                             layout="constrained")
    try:
        for ax, panel in zip(axes[:, 0], panels):
            for label, x, y in panel.curves:
                ax.plot(x, y, label=label)
            ax.set(title=panel.title, xlabel=panel.xlabel, ylabel=panel.ylabel)
            ax.grid(True, alpha=0.4)
            if len(panel.curves) > 1:
                ax.legend(loc="best", framealpha=0.9, fontsize="small")
        fig.suptitle(title)
        fig.savefig(path, dpi=120, metadata={"Software": None})
    finally:
        plt.close(fig)
