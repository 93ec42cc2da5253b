"""Stage 4 of the scene pipeline: run a scene and plot it.

Every scene takes the same path (``crane-sym run``): read and validate the
TOML (``scenes.reading.load_scene``) → specialize (``specialize``) → generate its
module, written beside the plot as ``scene_<name>.py``, the file
``crane-sym generate --scene`` writes → import that file and hand it to the
derivation's ``scene_report(scene, module)`` → plot the report's panels.
The scene's module is rendered before the output folder is made, so a scene
refused there leaves no folder behind; a report that greys a panel where its
model does not hold must say so in a ``warning:`` line.
"""
from __future__ import annotations

import importlib
import importlib.util
import inspect
import tempfile
from pathlib import Path
from types import ModuleType
from typing import Callable

from crane_sym import progress, registry
from crane_sym.output_files import Stage, check_folder, staged
from crane_sym.scenes import plots
from crane_sym.scenes.panels import WARNING
from crane_sym.scenes.reading import Scene, SceneError, SceneReport, load_scene
from crane_sym.scenes.specialize import module_name, render_scene_module

__all__ = ["import_module_file", "plot_report", "run_scene", "time_function"]


def import_module_file(path: Path) -> ModuleType:
    """Import the module the printer wrote at ``path`` (our own output, never
    user text).

    Parameters
    ----------
    path : Path
        The module's file.
    """
    spec = importlib.util.spec_from_file_location(f"_crane_sym_scene_{path.stem}", path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def time_function(scene: Scene, module: ModuleType, name: str) -> Callable:
    """``name`` as a function of time alone: from the scene's own module when
    the scene names it among its outputs, else from the paper's general
    module ``crane_sym.generated.<id>`` with the scene's parameters filled in.

    Parameters
    ----------
    scene : Scene
        The scene.
    module : module
        Its specialized module.
    name : str
        An output of the paper.
    """
    if name in scene.outputs:
        return getattr(module, name)
    general = getattr(importlib.import_module(f"crane_sym.generated.{scene.derivation}"),
                      name)
    names = [p.name for p in inspect.signature(general).parameters.values()
             if p.name != "t" and p.kind is p.POSITIONAL_OR_KEYWORD]
    missing = [p for p in names if p not in scene.parameters]
    if missing:
        raise SceneError(f"scene {scene.name!r}: {name} needs {missing}, which the scene "
                         "does not give")
    given = {p: scene.parameters[p] for p in names}
    return lambda t: general(t, **given)


def run_scene(scene: Scene | str | Path,
              outdir: Path | None) -> tuple[SceneReport, list[Path]]:
    """Evaluate a scene through its own generated module and plot it.

    Parameters
    ----------
    scene : Scene, or a scene name or TOML path
        From :func:`crane_sym.scenes.reading.load_scene`, or what it reads.
    outdir : Path or None
        Folder for the module and the plots; created if needed. None: the
        report only, nothing written where anyone looks (the module is imported
        from a temporary folder, removed at once; no plots).

    Returns
    -------
    (SceneReport, list of Path)
        The derivation's report (its last line names the module written) and
        the PNGs written (:func:`plot_report`): ``<outdir>/<scene.name>.png``,
        or ``<scene.name>_1.png``, ``_2`` ... when the panels need several
        figures; none without ``outdir``.
    """
    if not isinstance(scene, Scene):
        scene = load_scene(scene)
    make = getattr(registry.module(scene.derivation), "scene_report", None)
    if make is None:
        raise SceneError(f"derivation {scene.derivation!r} has no scene_report()")
    say = progress.current()
    if outdir is not None:
        check_folder(outdir)
    with say.task(f"specializing and printing {module_name(scene)}"):
        text = render_scene_module(scene)    # stage 2 refuses bad data: nothing written
    if outdir is None:
        with tempfile.TemporaryDirectory(prefix="crane_sym_scene_") as scratch:
            written = Path(scratch) / module_name(scene)
            written.write_text(text, encoding="utf-8")
            with say.task(f"running scene {scene.name}"):
                return _checked(make(scene, import_module_file(written)), scene), []
    # The module and the plots go to temporaries in the folder and are renamed
    # into place together at the end: a failure or a signal leaves nothing.
    with staged(outdir) as stage:
        source = Path(outdir) / module_name(scene)
        written = stage.write(source.name, text.encode("utf-8"), ".py")
        with say.task(f"running scene {scene.name}"):
            report = _checked(make(scene, import_module_file(written)), scene)
        report.lines.append(f"module written to {source}")
        with say.task(f"plotting {len(report.panels)} panels"):
            paths = plot_report(report, scene.title, stage, f"{scene.name}.png")
    return report, paths


def _checked(report: SceneReport, scene: Scene) -> SceneReport:
    """The report, refused when it has no panels or greys a panel unsaid."""
    if not isinstance(report, SceneReport) or not report.panels:
        raise SceneError(f"{scene.derivation}.scene_report() returned no panels")
    greyed = [p.title for p in report.panels if p.invalid]
    if greyed and not report.warnings:
        raise SceneError(f"{scene.derivation}.scene_report() greys where the model does "
                         f"not hold in {greyed} but states it in no line starting with "
                         f"{WARNING!r}")
    return report


def plot_report(report: SceneReport, title: str, stage: Stage, name: str) -> list[Path]:
    """Write the report's panels as PNGs into ``stage``: ``name`` when one
    figure holds them all, else ``<stem>_1.png``, ``<stem>_2.png`` ... (see
    :func:`crane_sym.scenes.plots.figures`); return the final paths. ``title`` is
    text, never mathtext (``figures`` escapes it: a ``$`` in it is printed as a ``$``)."""
    made = plots.figures(report.panels, title)
    paths = plots.numbered(stage.folder / name, len(made))
    for fig, path in zip(made, paths):
        plots.save(fig, stage.path(path.name, ".png"))
    return paths
