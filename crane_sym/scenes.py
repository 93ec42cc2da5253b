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
scene's functions, ``[options] <switch> = false`` turns off a part of the
model the derivation declares in ``Derivation.switches`` (e.g. ``damping``),
and a table named after one of the derivation's scene loads
(``SCENE_LOADS`` of its package, e.g. ``[drive_law]`` of paper 002) gives a
load as data, which the specializer turns into the scene's functions.
Values are converted to SI by :func:`crane_sym.units.convert`; they are parsed,
never evaluated, and checked against the sign the symbol table admits. This is
stage 1 of the one scene pipeline (read and validate → ``specialize`` →
generate → ``scene_run``). Scenes shipped with the package live in
``derivations/<id>/scenes/`` of each paper.
"""
from __future__ import annotations

import difflib
import re
import tomllib
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from sympy.physics.units import time as _TIME

from . import registry, units
from .derivation import SceneLoad
from .panels import Panel, SceneReport, Span, format_quantity
from .symbols import STATE, TIME, PhysicalSymbol

# Panel, SceneReport, Span and format_quantity live in ``panels``; they are
# named here too, where every report has always imported them from.
__all__ = ["Panel", "Scene", "SceneError", "SceneReport", "Span", "format_quantity",
           "list_scenes", "load_scene", "read_toml", "scene_path", "scenes_directory"]

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
    load_table : str
        The table of a scene load (``"drive_law"``), or ``""``.
    load : object
        The load as its ``SceneLoad.read`` validated it, or None.
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


def scenes_directory(derivation: str) -> Path:
    """The folder of the scenes shipped with a derivation's package."""
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
    """The file of the shipped scene ``name``."""
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
        output, a missing, unknown, badly dimensioned or out-of-sign parameter
        (the message names the parameter), and a scene load that its
        ``SceneLoad.read`` refuses (the message names the table).
    """
    path = _locate(path_or_name)
    data = read_toml(path)
    where = f"scene file {path.name!r}"
    head = _table(data, "scene", where)
    missing = [k for k in ("name", "derivation", "title") if k not in head]
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
    loads = registry.scene_loads(derivation_id)
    extra = sorted(set(data) - set(_TABLES) - set(loads))
    if extra:
        raise SceneError(f"{where}: unknown tables {extra}; expected "
                         f"{list(_TABLES) + sorted(loads)}")
    given = [key for key in loads if key in data]
    if len(given) > 1:
        raise SceneError(f"{where}: give one scene load, not {given}")
    # A derivation without time (gear geometry, statics) has no duration to give.
    timed = bool(given) or bool(registry.get(derivation_id).symbols.with_role(TIME))
    options = _options(_table(data, "options", where), where, timed)
    raw = _table(data, "parameters", where)
    if given:
        return _load_scene_with_load(path, head, derivation_id, loads[given[0]], data,
                                     raw, options, where)

    if "outputs" not in head:
        raise SceneError(f"{where}: [scene] lacks ['outputs']")
    derivation = registry.get(derivation_id)
    known = [*derivation.outputs, *derivation.tabulated]
    outputs = _outputs(head["outputs"], [o.name for o in known], derivation_id, where)
    # Required: what the scene's outputs take, less what a switch fixes or the
    # scene keeps as an input; allowed: what any output takes.
    required = {a for o in known if o.name in outputs for a in o.args}
    allowed = {a for o in known for a in o.args}
    entries = [e for e in derivation.symbols
               if e.expr in allowed and e.role not in (TIME, STATE)]
    switched_off = _switched_off(derivation, options, where)
    fixed = {str(s) for name in switched_off for s, _ in derivation.switches[name].off}
    inputs = _inputs(head.get("inputs", []), {str(a) for a in required}, where)
    for key in sorted((fixed | set(inputs)) & set(raw)):
        why = "is an input of the scene" if key in inputs else "is fixed by a switch"
        raise SceneError(f"{where}: parameter {key!r} {why}; remove it from [parameters]")
    needed = [e for e in entries if e.expr in required and e.name not in fixed | set(inputs)]
    parameters = _parameters(raw, entries, needed, derivation_id, where)
    return Scene(name, derivation_id, head["title"], tuple(outputs), parameters,
                 options, path, inputs, switched_off)


def _load_scene_with_load(path: Path, head: dict[str, Any], derivation_id: str,
                          load: SceneLoad, data: dict[str, Any], raw: dict[str, Any],
                          options: dict[str, Any], where: str) -> Scene:
    """The rest of :func:`load_scene` for a scene that gives a load as data: the
    load's own parameters, its outputs, its table read by ``load.read``."""
    if "inputs" in head:
        raise SceneError(f"{where}: a scene with [{load.table}] keeps no inputs")
    outputs = _outputs(head.get("outputs", list(load.outputs)), list(load.outputs),
                       f"{derivation_id}, [{load.table}]", where)
    entries = list(load.parameters)
    parameters = _parameters(raw, entries, entries, derivation_id, where)
    table = data[load.table]
    if not isinstance(table, dict):
        raise SceneError(f"{where}: [{load.table}] must be a table")
    try:
        value = load.read(table, where)
    except (TypeError, ValueError) as exc:
        raise SceneError(f"{where}: [{load.table}] {exc}") from None
    return Scene(head["name"], derivation_id, head["title"], tuple(outputs), parameters,
                 options, path, load_table=load.table, load=value)


def _outputs(raw: Any, known: list[str], owner: str, where: str) -> list[str]:
    """``[scene] outputs``: a non-empty list of known names, none twice."""
    if not isinstance(raw, list) or not raw or not all(isinstance(o, str) for o in raw):
        raise SceneError(f"{where}: outputs must be a non-empty list of names")
    for out in raw:
        if out not in known:
            raise SceneError(f"{where}: unknown output {out!r} of {owner!r}; "
                             f"known: {', '.join(known)}")
    if len(set(raw)) != len(raw):
        raise SceneError(f"{where}: an output is listed twice in {raw}")
    return list(raw)


def _parameters(raw: dict[str, Any], entries: list[PhysicalSymbol],
                needed: list[PhysicalSymbol], owner: str, where: str) -> dict[str, float]:
    """``[parameters]`` in SI: every name known, every needed one given, each of
    the right dimension, of the sign its symbol admits and within the range
    its generated functions serve (``PhysicalSymbol.serves``)."""
    names = [e.name for e in entries]
    for key in raw:
        if key not in names:
            close = difflib.get_close_matches(key, names, n=3)
            hint = f"did you mean {', '.join(map(repr, close))}? " if close else ""
            raise SceneError(f"{where}: unknown parameter {key!r}; {hint}"
                             f"{owner!r} takes {', '.join(names)}")
    parameters: dict[str, float] = {}
    for entry in entries:
        if entry.name not in raw:
            if entry in needed:
                raise SceneError(f"{where}: parameter {entry.name!r} ({entry.description}, "
                                 f"{entry.unit}) is missing")
            continue
        try:
            value = units.convert(entry.name, raw[entry.name], entry.dimension)
        except units.UnitError as exc:
            raise SceneError(f"{where}: {exc}") from None
        bound = {"positive": (value > 0, "> 0"), "nonnegative": (value >= 0, ">= 0")}
        ok, text = bound.get(entry.sign, (True, ""))
        if not ok:
            raise SceneError(f"{where}: parameter {entry.name!r} ({entry.description}) "
                             f"must be {text}, got {raw[entry.name]!r}")
        low, high = entry.serves
        if not low <= value <= high:
            raise SceneError(f"{where}: parameter {entry.name!r} ({entry.description}) must "
                             f"be within [{low:g}, {high:g}] {entry.unit} (the range its "
                             f"generated functions serve), got {raw[entry.name]!r}")
        parameters[entry.name] = value
    return parameters


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


def _options(raw: dict[str, Any], where: str, timed: bool = True) -> dict[str, Any]:
    options = dict(raw)
    if not timed:
        if "duration" in raw:
            raise SceneError(f"{where}: [options] duration: the derivation has no time")
        return options
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
