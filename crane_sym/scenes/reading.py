"""Scenes: a derivation's numeric results for one concrete machine.

A scene is a TOML file naming a derivation, the outputs of interest, the
parameter values with units, and options such as the simulated duration::

    [scene]
    name = "my_crane"                # the scene's name (files are named after it)
    derivation = "..."               # an id that `crane-sym list` shows
    title = "My crane: braking the bridge travel"
    outputs = ["...", "..."]         # outputs of that derivation
    [parameters]
    m1 = "4.4 t"                     # every parameter the outputs take, with units
    [options]
    duration = "1.5 s"
    points = 1501

(`crane-sym list --scenes` names the scenes shipped with the papers; each is
a complete example.)

Optional: ``[scene] inputs`` lists parameters left as arguments of the
scene's functions, ``[options] <switch> = false`` turns off a part of the
model the derivation declares in ``Derivation.switches`` (e.g. ``damping``),
and a table named after one of the derivation's scene loads
(``SCENE_LOADS`` of its package, e.g. ``[drive_law]`` of Chovnyuk et al.) gives a
load as data, which the specializer turns into the scene's functions.
``[options]`` takes what ``crane_sym.scenes.options.options_for`` declares for
the scene (``duration``, ``points``, the switches, the paper's
``SCENE_OPTIONS``), read into ``Scene.settings``; the paper's ``SCENE_CHECKS``
run last. An unknown key in any table is an error naming the closest known one.
Values are converted to SI by :func:`crane_sym.units.convert`; they are parsed,
never evaluated, and checked against the sign the symbol table admits. This is
stage 1 of the one scene pipeline (read and validate → ``specialize`` →
generate → ``scenes.run``). Scenes shipped with the package live in
``derivations/<id>/scenes/`` of each paper.
"""
from __future__ import annotations

import re
import tomllib
from dataclasses import dataclass, field, replace
from pathlib import Path
from typing import Any

import numpy as np

from crane_sym import registry
from crane_sym.derivation import SceneLoad
from crane_sym.scenes.fields import (SceneError, known_keys, read_inputs, read_outputs,
                                     read_parameters, required_table, switches_off,
                                     toml_reason)
from crane_sym.scenes.panels import Panel, SceneReport, Span, format_quantity
from crane_sym.scenes.options import OptionError, failed_check, options_for, read_options
from crane_sym.symbols import STATE, TIME

# Panel, SceneReport, Span and format_quantity live in ``panels``; they are
# named here too, where every report has always imported them from.
__all__ = ["Panel", "Scene", "SceneError", "SceneReport", "Span", "format_quantity",
           "list_scenes", "load_scene", "read_toml", "scene_path", "scenes_directory"]

_SAFE_NAME = re.compile(r"[A-Za-z0-9_][A-Za-z0-9_.-]{0,99}")
_SCENE_KEYS = ("name", "derivation", "title", "outputs")
_OPTIONAL_SCENE_KEYS = ("inputs",)
_TABLES = ("scene", "parameters", "options")


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
        The ``[options]`` table as written, but ``duration`` (float, s) and
        ``points`` (int); reports read :attr:`settings`.
    path : Path
        The TOML file the scene was read from.
    inputs : tuple of str
        Parameters the scene leaves as arguments of its functions
        (``[scene] inputs``, e.g. a load that varies in time).
    switched_off : tuple of str
        Switches of the derivation turned off (``[options] <switch> = false``).
    load_table : str
        The table of a scene load (``"drive_law"``), or ``""``.
    load : object
        The load as its ``SceneLoad.read`` validated it, or None.
    settings : dict
        Every option the scene takes (``scenes.options``), read by its
        declaration: given or default, bounds checked, quantities in SI.
        What a report reads.
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
    load_table: str = ""
    load: Any = None
    settings: dict[str, Any] = field(default_factory=dict)

    def times(self, end: float | None = None) -> np.ndarray:
        """The scene's time grid: ``settings["points"]`` samples on [0, end],
        ``end`` the setting ``duration`` unless given (a paper whose scenes
        name their span otherwise, e.g. a start-up's ``end``); the last sample is
        ``end`` exactly.

        Parameters
        ----------
        end : float, optional
            End of the span [s]; default ``settings["duration"]``.

        Returns
        -------
        ndarray
            float64, shape ``(points,)``.
        """
        span = self.settings["duration"] if end is None else end
        return np.linspace(0.0, span, self.settings["points"])


def scenes_directory(derivation: str) -> Path:
    """The folder of the scenes shipped with a derivation's package.

    Parameters
    ----------
    derivation : str
        A derivation id.
    """
    return Path(registry.module_path(derivation)).parent / "scenes"


def _shipped() -> dict[str, Path]:
    """Name -> file of every shipped scene, over the registered derivations."""
    found: dict[str, Path] = {}
    for derivation in registry.ids():
        for path in sorted(scenes_directory(derivation).glob("*.toml")):
            if path.stem in found:
                raise SceneError(f"scene name {path.stem!r} is shipped twice: "
                                 f"{found[path.stem]} and {path}")
            found[path.stem] = path
    return found


def list_scenes() -> list[str]:
    """Names of the shipped scenes, sorted."""
    return sorted(_shipped())


def scene_path(name: str) -> Path:
    """The file of the shipped scene ``name``.

    Parameters
    ----------
    name : str
        A shipped scene's name.
    """
    shipped = _shipped()
    if not _SAFE_NAME.fullmatch(name) or name not in shipped:
        raise SceneError(f"unknown scene {name!r}; known: {', '.join(sorted(shipped))}")
    return shipped[name]


def _locate(path_or_name: str | Path) -> Path:
    text = str(path_or_name)
    if isinstance(path_or_name, Path) or text.endswith(".toml") or "/" in text \
            or "\\" in text:
        path = Path(path_or_name)
        if not path.is_file():
            raise SceneError(f"no scene file {str(path)!r}")
        return path
    return scene_path(text)


def read_toml(path: Path) -> dict[str, Any]:
    """The scene file's tables; SceneError if it is not valid UTF-8 TOML.

    Parameters
    ----------
    path : Path
        The scene file.
    """
    try:
        return tomllib.loads(path.read_text(encoding="utf-8"))
    except (tomllib.TOMLDecodeError, UnicodeDecodeError, RecursionError) as exc:
        raise SceneError(f"{path}: not valid TOML: {toml_reason(exc)}") from None


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
        With every parameter in SI units and every option read by its
        declaration (``Scene.settings``).

    Raises
    ------
    SceneError
        For unreadable TOML, missing or unknown keys in any table (with the
        names close to an unknown one), an unknown derivation or output, a
        missing, unknown, badly dimensioned or out-of-range parameter or option
        (the message names it and its bound or choices), a scene load that its
        ``SceneLoad.read`` refuses (the message names the table), and a
        condition the paper declares between options and parameters
        (``SCENE_CHECKS``) that the scene breaks.
    """
    path = _locate(path_or_name)
    data = read_toml(path)
    where = f"scene file {path.name!r}"
    head = required_table(data, "scene", where)
    known_keys(head, [*_SCENE_KEYS, *_OPTIONAL_SCENE_KEYS], "[scene] key", where)
    missing = [k for k in ("name", "derivation", "title") if k not in head]
    if missing:
        raise SceneError(f"{where}: [scene] lacks {missing}")
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
    loads = registry.scene_loads(derivation_id)
    known_keys(data, [*_TABLES, *sorted(loads)], "table", where)
    given = [key for key in loads if key in data]
    if len(given) > 1:
        raise SceneError(f"{where}: give one scene load, not {given}")
    # A derivation without time (gear geometry, statics) has no duration to give.
    timed = bool(given) or bool(registry.get(derivation_id).symbols.with_role(TIME))
    raw_options = required_table(data, "options", where)
    raw = required_table(data, "parameters", where)
    if given:
        scene = _load_scene_with_load(path, head, derivation_id, loads[given[0]], data,
                                      raw, where)
    else:
        scene = _load_plain_scene(path, head, derivation_id, raw, raw_options, where)
    return _with_options(scene, raw_options, timed, where)


def _load_plain_scene(path: Path, head: dict[str, Any], derivation_id: str,
                      raw: dict[str, Any], raw_options: dict[str, Any], where: str) -> Scene:
    """The outputs, inputs, switches and parameters of a scene without a load."""
    if "outputs" not in head:
        raise SceneError(f"{where}: [scene] lacks ['outputs']")
    derivation = registry.get(derivation_id)
    known = [*derivation.outputs, *derivation.tabulated]
    outputs = read_outputs(head["outputs"], [o.name for o in known], derivation_id, where)
    # Required: what the scene's outputs take, less what a switch fixes or the
    # scene keeps as an input; allowed: what any output takes.
    required = {a for o in known if o.name in outputs for a in o.args}
    allowed = {a for o in known for a in o.args}
    entries = [e for e in derivation.symbols
               if e.expr in allowed and e.role not in (TIME, STATE)]
    switched_off = switches_off(derivation, raw_options, where)
    fixed = {str(s) for name in switched_off for s, _ in derivation.switches[name].off}
    inputs = read_inputs(head.get("inputs", []), {str(a) for a in required}, where)
    for key in sorted((fixed | set(inputs)) & set(raw)):
        why = "is an input of the scene" if key in inputs else "is fixed by a switch"
        raise SceneError(f"{where}: parameter {key!r} {why}; remove it from [parameters]")
    needed = [e for e in entries if e.expr in required and e.name not in fixed | set(inputs)]
    parameters = read_parameters(raw, entries, needed, derivation_id, where)
    return Scene(head["name"], derivation_id, head["title"], tuple(outputs), parameters,
                 {}, path, inputs, switched_off)


def _load_scene_with_load(path: Path, head: dict[str, Any], derivation_id: str,
                          load: SceneLoad, data: dict[str, Any], raw: dict[str, Any],
                          where: str) -> Scene:
    """The rest of :func:`load_scene` for a scene that gives a load as data: the
    load's own parameters, its outputs, its table read by ``load.read``."""
    if "inputs" in head:
        raise SceneError(f"{where}: a scene with [{load.table}] keeps no inputs")
    outputs = read_outputs(head.get("outputs", list(load.outputs)), list(load.outputs),
                       f"{derivation_id}, [{load.table}]", where)
    entries = list(load.parameters)
    parameters = read_parameters(raw, entries, entries, derivation_id, where)
    table = data[load.table]
    if not isinstance(table, dict):
        raise SceneError(f"{where}: [{load.table}] must be a table")
    try:
        value = load.read(table, where)
    except (TypeError, ValueError) as exc:
        raise SceneError(f"{where}: [{load.table}] {exc}") from None
    return Scene(head["name"], derivation_id, head["title"], tuple(outputs), parameters,
                 {}, path, load_table=load.table, load=value)


def _with_options(scene: Scene, raw: dict[str, Any], timed: bool, where: str) -> Scene:
    """``scene`` with its options read by their declarations (``options_for``)
    and the paper's conditions (``SCENE_CHECKS``) checked."""
    if not timed and "duration" in raw:
        raise SceneError(f"{where}: [options] duration: the derivation has no time")
    if timed and "duration" not in raw:
        raise SceneError(f"{where}: [options] lacks 'duration', e.g. duration = \"2 s\"")
    try:
        settings = read_options(raw, options_for(scene.derivation, scene.outputs,
                                                 scene.load_table, timed))
        options = {**raw, **{k: settings[k] for k in ("duration", "points") if k in settings}}
        scene = replace(scene, options=options, settings=settings)
        failure = failed_check(scene)
    except OptionError as exc:
        raise SceneError(f"{where}: {exc}") from None
    if failure:
        raise SceneError(f"{where}: {failure}")
    return scene
