"""Scene-specialized code: model only what a scene needs.

A scene names the outputs it wants and gives every parameter a value. The
specialized module keeps only those outputs, folds the values in as exact
numbers (so SymPy removes every term that vanishes for the scene before
printing) and leaves time as the only argument.
"""
from __future__ import annotations

from typing import Callable

import sympy as sp

from .codegen import render_module
from .derivation import Derivation, Output
from .scenes import Scene, list_scenes, load_scene
from .symbols import STATE, TIME


def scene_values(d: Derivation, scene: Scene) -> dict[sp.Symbol, sp.Rational]:
    """The scene's parameter values as exact SymPy numbers (SI)."""
    return {d.symbols[name].expr: sp.Rational(value) for name, value in scene.parameters.items()}


def switched_off(d: Derivation, scene: Scene) -> dict[sp.Symbol, sp.Expr]:
    """The parameters the scene's switched-off switches fix, with their values."""
    return {s: v for name in scene.switched_off for s, v in d.switches[name].off}


def specialize(d: Derivation, scene: Scene) -> list[Output]:
    """The scene's outputs with its values and switches folded in; time and the
    scene's inputs stay arguments."""
    values = {**scene_values(d, scene), **switched_off(d, scene)}
    keep = {e.expr for e in d.symbols.with_role(TIME, STATE)} | {
        d.symbols[name].expr for name in scene.inputs}
    outputs = []
    for name in scene.outputs:
        out = d.output(name)
        expr = out.expr.xreplace({s: v for s, v in values.items() if s in out.args})
        args = tuple(a for a in out.args if a in keep or a not in values)
        outputs.append(Output(out.name, expr, args, out.labels,
                              f"{out.summary} Specialized to scene {scene.name!r}.", out.unit))
    return outputs


def module_name(scene: Scene) -> str:
    """File name of the specialized module."""
    return f"scene_{scene.name}.py"


def render_scene_module(d: Derivation, scene: Scene) -> str:
    """Source of the module specialized to ``scene``."""
    given = ", ".join(f"{k} = {v!r} {d.symbols[k].unit}" for k, v in scene.parameters.items())
    note = (f"Specialized to scene {scene.name!r} ({scene.title}): outputs "
            f"{', '.join(scene.outputs)}; folded in: {given}.")
    for name in scene.switched_off:
        fixed = ", ".join(f"{s} = {v}" for s, v in d.switches[name].off)
        note += f"\nSwitched off: {name} ({d.switches[name].description}: {fixed})."
    if scene.inputs:
        note += f"\nInputs left as arguments: {', '.join(scene.inputs)}."
    return render_module(d, specialize(d, scene), scene_note=note)


def operation_count(outputs: list[Output]) -> int:
    """SymPy operation count of the outputs' expressions (a size measure)."""
    return sum(sp.count_ops(o.expr) for o in outputs)


def scene_files(path_or_name, get: Callable[[str], Derivation]) -> dict[str, str]:
    """File name -> source of the module of one scene: a drive-law scene
    (``crane_sym.drive_law``) or a scene of a derivation's outputs."""
    from .drive_law import drive_law_files, is_drive_law_scene
    if is_drive_law_scene(path_or_name):
        return drive_law_files(path_or_name)
    scene = load_scene(path_or_name)
    d = get(scene.derivation)
    return {module_name(scene): render_scene_module(d, scene)} if d.outputs else {}


def shipped_scene_modules(get: Callable[[str], Derivation]) -> dict[str, str]:
    """File name -> source of the specialized module of every shipped scene."""
    files = {}
    for name in list_scenes():
        files.update(scene_files(name, get))
    return files
