"""Scene-specialized code: model only what a scene needs (stages 2 and 3 of
the scene pipeline).

A scene names the outputs it wants and gives every parameter a value. The
specialized module keeps only those outputs, folds the values in as exact
numbers (so SymPy removes every term that vanishes for the scene before
printing) and leaves time, the scene's inputs and state as the only
arguments. A scene that gives a load as data (``Scene.load``) is specialized
by that load's ``SceneLoad.specialize``, the same stage for another input.
"""
from __future__ import annotations

import re
from dataclasses import replace
from pathlib import Path

import sympy as sp

from crane_sym import progress, registry
from crane_sym.codegen.module import render_module
from crane_sym.derivation import Derivation, Output, SpecializedLoad, TabulatedOutput
from crane_sym.mechanics.exact_phases import exact_table
from crane_sym.mechanics.phase_table import HybridRun, PhaseTable
from crane_sym.scenes.reading import Scene, SceneError, list_scenes, load_scene, scene_path
from crane_sym.symbols import STATE, TIME, SymbolTable

__all__ = ["module_name", "operation_count", "regenerate_command", "render_scene_module",
           "scene_files", "scene_values", "shipped_scene_modules", "specialize",
           "specialize_load", "switched_off", "tabulated_names", "tabulated_outputs",
           "tabulated_runs"]


def scene_values(d: Derivation | SymbolTable, scene: Scene) -> dict[sp.Symbol, sp.Rational]:
    """The scene's parameter values as exact SymPy numbers (SI), by symbol."""
    table = d.symbols if isinstance(d, Derivation) else d
    return {table[name].expr: sp.Rational(value) for name, value in scene.parameters.items()}


def switched_off(d: Derivation, scene: Scene) -> dict[sp.Symbol, sp.Expr]:
    """The parameters the scene's switched-off switches fix, with their values.

    Parameters
    ----------
    d : Derivation
        The scene's built derivation.
    scene : Scene
        The validated scene.
    """
    return {s: v for name in scene.switched_off for s, v in d.switches[name].off}


def specialize_load(scene: Scene) -> SpecializedLoad:
    """The functions of a scene that gives a load as data (``scene.load``), only
    those the scene asks for."""
    load = registry.scene_loads(scene.derivation)[scene.load_table]
    made = load.specialize(scene)
    wanted = [o for o in made.outputs if o.name in scene.outputs]
    return replace(made, outputs=wanted)


def specialize(d: Derivation, scene: Scene) -> list[Output]:
    """The scene's outputs with its values, switches and load folded in; time,
    the scene's inputs and state stay arguments.

    Parameters
    ----------
    d : Derivation
        The scene's built derivation.
    scene : Scene
        The validated scene.
    """
    if scene.load_table:
        return specialize_load(scene).outputs
    values = {**scene_values(d, scene), **switched_off(d, scene)}
    keep = {e.expr for e in d.symbols.with_role(TIME, STATE)} | {
        d.symbols[name].expr for name in scene.inputs}
    outputs = []
    for name in scene.outputs:
        if name in tabulated_names(d):
            continue                     # tabulated_outputs() makes those
        out = d.output(name)
        fold = {s: v for s, v in values.items() if s in out.args}
        expr = out.expr.xreplace(fold)
        args = tuple(a for a in out.args if a in keep or a not in values)
        requires = []
        for condition, what in out.requires:      # folded in: checked now, not left in
            folded = condition.xreplace(fold)
            if folded.free_symbols & set(args):
                requires.append((folded, what))
            elif not folded > 0:
                raise SceneError(f"scene {scene.name!r}: its values break {what} "
                                 f"(needed by {out.name})")
        outputs.append(Output(out.name, expr, args, out.labels,
                              f"{out.summary} Specialized to scene {scene.name!r}.", out.unit,
                              tuple(requires)))
    return outputs


def tabulated_names(d: Derivation) -> set[str]:
    """Names of the derivation's tabulated responses."""
    return {o.name for o in d.tabulated}


def tabulated_runs(d: Derivation, scene: Scene) -> list[tuple[TabulatedOutput, HybridRun]]:
    """The scene's tabulated responses with their runs on the scene's data:
    one each, or one per case of a response whose run gives several (named
    ``<name>_<k>`` for case k).

    Parameters
    ----------
    d : Derivation
        The scene's derivation (its ``tabulated`` responses).
    scene : Scene
        The scene: which outputs it names, its parameters and settings.
    """
    found = []
    for out in d.tabulated:
        if out.name in scene.outputs:
            runs = out.run(scene.parameters, scene.settings)
            if isinstance(runs, HybridRun):
                found.append((out, runs))
            else:
                found += [(replace(out, name=f"{out.name}_{k}",
                                   summary=f"{out.summary} Case {k} (from 0) of those "
                                           "the scene's settings list."), run)
                          for k, run in enumerate(runs)]
    return found


def tabulated_outputs(d: Derivation, scene: Scene) -> list[tuple[TabulatedOutput, PhaseTable]]:
    """The scene's tabulated responses, each solved with the scene's data
    (:func:`tabulated_runs`) in mpmath, each said as it starts (a run of many
    phases takes seconds)."""
    say, tables = progress.current(), []
    for out, run in tabulated_runs(d, scene):
        say.say(f"{scene.name}: solving {out.name} phase by phase in mpmath")
        tables.append((out, exact_table(run)))
    return tables


def module_name(scene: Scene) -> str:
    """File name of the specialized module.

    Parameters
    ----------
    scene : Scene
        The scene.
    """
    return f"scene_{scene.name}.py"


def regenerate_command(scene: Scene) -> str:
    """The command that writes the scene's module again, for its header: the
    scene by name when it is a shipped one, else by its file's name (never an
    absolute path, so a module reads the same on every machine)."""
    shipped = scene.name in list_scenes() and scene_path(scene.name).resolve() == \
        Path(scene.path).resolve()
    name = Path(scene.path).name
    plain = re.fullmatch(r"[A-Za-z0-9][A-Za-z0-9_.-]*", name) is not None
    return (f"crane-sym generate --scene {scene.name if shipped else name if plain else 'FILE'}"
            " --out <folder>")


def render_scene_module(scene: Scene) -> str:
    """Source of the module specialized to ``scene`` (pure; deterministic).

    Parameters
    ----------
    scene : Scene
        The validated scene.
    """
    command = regenerate_command(scene)
    constants = {"SCENE_NAME": scene.name, "SCENE_TITLE": scene.title}
    if scene.load_table:
        made = specialize_load(scene)
        package = registry.module(scene.derivation)
        d = Derivation(id=scene.derivation, paper=package.PAPER, title=package.TITLE,
                       citation="", model="", symbols=made.symbols)
        return render_module(d, made.outputs, scene_note=made.note, regenerate=command,
                             constants=constants)
    d = registry.get(scene.derivation)
    given = ", ".join(f"{k} = {v!r} {d.symbols[k].unit}" for k, v in scene.parameters.items())
    note = (f"Specialized to scene {scene.name!r} ({scene.title}): outputs "
            f"{', '.join(scene.outputs)}; folded in: {given}.")
    for name in scene.switched_off:
        fixed = ", ".join(f"{s} = {v}" for s, v in d.switches[name].off)
        note += f"\nSwitched off: {name} ({d.switches[name].description}: {fixed})."
    if scene.inputs:
        note += f"\nInputs left as arguments: {', '.join(scene.inputs)}."
    return render_module(d, specialize(d, scene), scene_note=note,
                         tables=tabulated_outputs(d, scene), regenerate=command,
                         constants=constants)


def operation_count(outputs: list[Output]) -> int:
    """SymPy operation count of the outputs' expressions (a size measure).

    Parameters
    ----------
    outputs : list of Output
        The outputs.
    """
    return sum(sp.count_ops(o.expr) for o in outputs)


def scene_files(path_or_name: str | Path) -> dict[str, str]:
    """File name -> source of the module of one scene (``generate --scene``).

    Parameters
    ----------
    path_or_name : str or Path
        A shipped scene's name or a TOML file.
    """
    scene = load_scene(path_or_name)
    return {module_name(scene): render_scene_module(scene)}


def shipped_scene_modules() -> dict[str, str]:
    """File name -> source of the specialized module of every shipped scene."""
    files = {}
    for name in list_scenes():
        files.update(scene_files(name))
    return files
