"""Scenes: a derivation's numeric results for one concrete machine.

A scene is a TOML file naming a derivation, the outputs of interest, the
parameter values with units, and options such as the simulated duration::

    [scene]
    name = "overhead_crane_50t"
    derivation = "travel_braking"
    title = "50 t overhead crane: braking the bridge travel"
    outputs = ["elastic_force", "velocity_m1"]
    [parameters]
    m1 = "4.4 t"
    [options]
    duration = "1.5 s"
    points = 1501

Optional: ``[scene] inputs`` lists parameters left as arguments of the
scene's functions, and ``[options] <switch> = false`` turns off a part of the
model the derivation declares in ``Derivation.switches`` (e.g. ``damping``).
Values are converted to SI by :func:`crane_sym.units.convert`; they are parsed,
never evaluated. Scenes shipped with the package live in
``crane_sym/derivations/scenes/`` (``derivations/scenes/`` in a clone).
"""
from __future__ import annotations

import difflib
import re
import tomllib
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np
from sympy.physics.units import time as _TIME

from . import registry, units
from .symbols import STATE, TIME

__all__ = ["Panel", "Scene", "SceneError", "SceneReport", "format_quantity",
           "list_scenes", "load_scene", "run_scene", "scenes_directory"]

_SAFE_NAME = re.compile(r"[A-Za-z0-9_][A-Za-z0-9_.-]{0,99}")
_SCENE_KEYS = ("name", "derivation", "title", "outputs")
_OPTIONAL_SCENE_KEYS = ("inputs",)
_TABLES = ("scene", "parameters", "options")
_MAX_POINTS = 1_000_000


class SceneError(ValueError):
    """A scene file that cannot be read or does not fit its derivation."""


@dataclass(frozen=True)
class Scene:
    """A validated scene.

    Attributes
    ----------
    name, title : str
        Identifier (also the stem of the plot file) and a one-line title.
    derivation : str
        Registry id of the derivation.
    outputs : tuple of str
        Output functions of the derivation the scene is about.
    parameters : dict of str to float
        SI values, in the order of the derivation's symbol table.
    options : dict
        ``duration`` (float, s), ``points`` (int) and any other raw values.
    path : Path
        The TOML file the scene was read from.
    inputs : tuple of str
        Parameters the scene leaves as arguments of its functions
        (``[scene] inputs``, e.g. a load that varies in time).
    switched_off : tuple of str
        Switches of the derivation turned off (``[options] <switch> = false``).
    """

    name: str
    derivation: str
    title: str
    outputs: tuple[str, ...]
    parameters: dict[str, float]
    options: dict[str, Any]
    path: Path
    inputs: tuple[str, ...] = ()
    switched_off: tuple[str, ...] = ()


@dataclass
class Panel:
    """One subplot: curves ``(label, x, y)`` sharing a y axis."""

    title: str
    ylabel: str
    curves: list[tuple[str, np.ndarray, np.ndarray]] = field(default_factory=list)
    xlabel: str = "t [s]"


@dataclass
class SceneReport:
    """What a derivation's ``scene_report(scene)`` returns.

    Attributes
    ----------
    lines : list of str
        Text to print, numbers already formatted with units.
    values : dict of str to float
        The same key results as numbers (SI), for tests and further use.
    panels : list of Panel
        Curves to plot, one subplot per panel.
    """

    lines: list[str] = field(default_factory=list)
    values: dict[str, float] = field(default_factory=dict)
    panels: list[Panel] = field(default_factory=list)


def format_quantity(value: float, unit: str = "", digits: int = 4) -> str:
    """``value`` with ``digits`` significant digits and its unit, e.g. ``"45.31 kN"``."""
    text = f"{value:#.{digits}g}"
    if "e" not in text:
        text = text.rstrip(".")
    return f"{text} {unit}".rstrip()


def scenes_directory() -> Path:
    """The folder of the scenes shipped with the package."""
    import crane_sym.derivations as package
    return Path(package.__file__).parent / "scenes"


def list_scenes() -> list[str]:
    """Names of the shipped scenes, sorted."""
    return sorted(p.stem for p in scenes_directory().glob("*.toml"))


def _locate(path_or_name: str | Path) -> Path:
    text = str(path_or_name)
    if isinstance(path_or_name, Path) or text.endswith(".toml") or "/" in text \
            or "\\" in text:
        path = Path(path_or_name)
        if not path.is_file():
            raise SceneError(f"no scene file {str(path)!r}")
        return path
    if not _SAFE_NAME.fullmatch(text) or text not in list_scenes():
        raise SceneError(f"unknown scene {text!r}; known: {', '.join(list_scenes())}")
    return scenes_directory() / f"{text}.toml"


def read_toml(path: Path) -> dict[str, Any]:
    """The scene file's tables; SceneError if it is not valid UTF-8 TOML."""
    try:
        return tomllib.loads(path.read_text(encoding="utf-8"))
    except (tomllib.TOMLDecodeError, UnicodeDecodeError) as exc:
        raise SceneError(f"{path}: not valid TOML: {exc}") from None


def load_scene(path_or_name: str | Path) -> Scene:
    """Read and validate a scene.

    Parameters
    ----------
    path_or_name : str or Path
        A TOML file, or the name of a scene shipped with the package
        (see :func:`list_scenes`).

    Returns
    -------
    Scene
        With every parameter in SI units.

    Raises
    ------
    SceneError
        For unreadable TOML, missing or unknown keys, an unknown derivation or
        output, and a missing, unknown or badly dimensioned parameter (the
        message names the parameter).
    """
    path = _locate(path_or_name)
    data = read_toml(path)
    where = f"scene file {path.name!r}"
    extra = sorted(set(data) - set(_TABLES))
    if extra:
        raise SceneError(f"{where}: unknown tables {extra}; expected {list(_TABLES)}")
    head = _table(data, "scene", where)
    missing = [k for k in _SCENE_KEYS if k not in head]
    if missing:
        raise SceneError(f"{where}: [scene] lacks {missing}")
    unknown = sorted(set(head) - set(_SCENE_KEYS) - set(_OPTIONAL_SCENE_KEYS))
    if unknown:
        raise SceneError(f"{where}: unknown [scene] keys {unknown}")
    name = head["name"]
    if not isinstance(name, str) or not _SAFE_NAME.fullmatch(name):
        raise SceneError(f"{where}: name must be letters, digits, '_', '-' or '.', "
                         f"got {name!r}")
    where = f"scene {name!r}"
    if not isinstance(head["title"], str):
        raise SceneError(f"{where}: title must be text")
    try:
        derivation_id = registry.resolve(str(head["derivation"]))
    except KeyError as exc:
        raise SceneError(f"{where}: {exc.args[0]}") from None
    derivation = registry.get(derivation_id)
    known_outputs = [o.name for o in derivation.outputs]
    outputs = head["outputs"]
    if not isinstance(outputs, list) or not outputs \
            or not all(isinstance(o, str) for o in outputs):
        raise SceneError(f"{where}: outputs must be a non-empty list of names")
    for out in outputs:
        if out not in known_outputs:
            raise SceneError(f"{where}: unknown output {out!r} of derivation "
                             f"{derivation_id!r}; known: {', '.join(known_outputs)}")
    if len(set(outputs)) != len(outputs):
        raise SceneError(f"{where}: an output is listed twice in {outputs}")

    # Required: what the scene's outputs take, less what a switch fixes or the
    # scene keeps as an input; allowed: what any output takes.
    required = {a for o in derivation.outputs if o.name in outputs for a in o.args}
    allowed = {a for o in derivation.outputs for a in o.args}
    entries = [e for e in derivation.symbols
               if e.expr in allowed and e.role not in (TIME, STATE)]
    raw = _table(data, "parameters", where)
    names = [e.name for e in entries]
    options = _options(_table(data, "options", where), where)
    switched_off = _switched_off(derivation, options, where)
    fixed = {str(s) for name in switched_off for s, _ in derivation.switches[name].off}
    inputs = _inputs(head.get("inputs", []), {str(a) for a in required}, where)
    for key in sorted((fixed | set(inputs)) & set(raw)):
        why = "is an input of the scene" if key in inputs else "is fixed by a switch"
        raise SceneError(f"{where}: parameter {key!r} {why}; remove it from [parameters]")
    for key in raw:
        if key not in names:
            close = difflib.get_close_matches(key, names, n=3)
            hint = f"did you mean {', '.join(map(repr, close))}? " if close else ""
            raise SceneError(f"{where}: unknown parameter {key!r}; {hint}"
                             f"{derivation_id!r} takes {', '.join(names)}")
    parameters: dict[str, float] = {}
    for entry in entries:
        if entry.name not in raw and (entry.expr not in required
                                      or entry.name in fixed or entry.name in inputs):
            continue
        if entry.name not in raw:
            raise SceneError(f"{where}: parameter {entry.name!r} ({entry.description}, "
                             f"{entry.unit}) is missing")
        try:
            parameters[entry.name] = units.convert(entry.name, raw[entry.name],
                                                   entry.dimension)
        except units.UnitError as exc:
            raise SceneError(f"{where}: {exc}") from None
    return Scene(name, derivation_id, head["title"], tuple(outputs), parameters,
                 options, path, inputs, switched_off)


def _switched_off(derivation, options: dict[str, Any], where: str) -> tuple[str, ...]:
    """Names of the derivation's switches the options turn off (true/false only)."""
    off = []
    for name in derivation.switches:
        if name in options:
            if not isinstance(options[name], bool):
                raise SceneError(f"{where}: option {name!r} must be true or false, "
                                 f"got {options[name]!r}")
            if not options[name]:
                off.append(name)
    return tuple(off)


def _inputs(raw: Any, takes: set[str], where: str) -> tuple[str, ...]:
    """``[scene] inputs``: parameters of the outputs left as arguments."""
    if not isinstance(raw, list) or not all(isinstance(x, str) for x in raw):
        raise SceneError(f"{where}: inputs must be a list of parameter names")
    for name in raw:
        if name not in takes:
            raise SceneError(f"{where}: input {name!r} is not a parameter of the scene's "
                             f"outputs ({', '.join(sorted(takes))})")
    return tuple(raw)


def _table(data: dict[str, Any], key: str, where: str) -> dict[str, Any]:
    value = data.get(key)
    if not isinstance(value, dict):
        raise SceneError(f"{where}: missing table [{key}]")
    return value


def _options(raw: dict[str, Any], where: str) -> dict[str, Any]:
    options = dict(raw)
    if "duration" not in raw:
        raise SceneError(f"{where}: [options] lacks 'duration', e.g. duration = \"2 s\"")
    try:
        duration = units.convert("duration", raw["duration"], _TIME)
    except units.UnitError as exc:
        raise SceneError(f"{where}: {exc}") from None
    if not duration > 0:
        raise SceneError(f"{where}: duration must be > 0, got {raw['duration']!r}")
    points = raw.get("points", 1001)
    if isinstance(points, bool) or not isinstance(points, int) \
            or not 2 <= points <= _MAX_POINTS:
        raise SceneError(f"{where}: points must be an integer in 2..{_MAX_POINTS}, "
                         f"got {points!r}")
    options.update(duration=duration, points=points)
    return options


def run_scene(scene: Scene, outdir: Path) -> tuple[SceneReport, Path]:
    """Evaluate a scene and plot it.

    Parameters
    ----------
    scene : Scene
        From :func:`load_scene`.
    outdir : Path
        Folder for the plot; created if needed.

    Returns
    -------
    (SceneReport, Path)
        The derivation's report and the PNG ``<outdir>/<scene.name>.png``.
    """
    module = registry.module(scene.derivation)
    make = getattr(module, "scene_report", None)
    if make is None:
        raise SceneError(f"derivation {scene.derivation!r} has no scene_report()")
    report = make(scene)
    if not isinstance(report, SceneReport) or not report.panels:
        raise SceneError(f"{scene.derivation}.scene_report() returned no panels")

    path = plot_report(report, scene.title, Path(outdir) / f"{scene.name}.png")
    return report, path


def plot_report(report: SceneReport, title: str, path: Path) -> Path:
    """Write the report's panels, one subplot each, to the PNG ``path``."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    n = len(report.panels)
    fig, axes = plt.subplots(n, 1, figsize=(8, 3.2 * n), squeeze=False,
                             layout="constrained")
    try:
        for ax, panel in zip(axes[:, 0], report.panels):
            for label, x, y in panel.curves:
                ax.plot(x, y, label=label)
            ax.set(title=panel.title, xlabel=panel.xlabel, ylabel=panel.ylabel)
            ax.grid(True, alpha=0.4)
            if len(panel.curves) > 1:
                ax.legend(loc="lower right", framealpha=0.9)
        fig.suptitle(title)
        fig.savefig(path, dpi=120, metadata={"Software": None})
    finally:
        plt.close(fig)
    return path
