"""The kinds of scene a paper answers, and which report answers a scene.

Every paper's ``report.py`` declares ``REPORTS``, a tuple of
:class:`SceneKind`: one report function each, and what marks a scene of that
kind — the outputs it names, or the scene load it gives — by the rule that
picks the options a scene takes (``SceneOption.outputs``). Its
``scene_report(scene, module)`` is :func:`report_for` on that tuple, so a
paper never dispatches on anything else (an option picks what a report
draws, never which report runs). A paper with one kind of scene declares one
kind without marks.
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Any, Callable, Sequence

from crane_sym.scenes.panels import SceneReport

__all__ = ["SceneKind", "kind_of", "report_for"]


@dataclass(frozen=True)
class SceneKind:
    """One kind of scene of a paper and the report that answers it.

    Attributes
    ----------
    name : str
        What the scenes of this kind are about, a few words.
    report : callable
        ``report(scene, module) -> SceneReport``; ``module`` is the scene's
        generated module.
    outputs : tuple of str
        A scene naming any of these is of this kind.
    load : str
        A scene giving this scene load table (``SceneLoad.table``) is of this
        kind.

    A kind with neither takes every scene without a load that no kind before
    it took.
    """

    name: str
    report: Callable[[Any, Any], SceneReport]
    outputs: tuple[str, ...] = ()
    load: str = ""

    def takes(self, outputs: Sequence[str], load: str) -> bool:
        """Whether a scene with these ``outputs`` and load table ``load``
        (``""`` for none) is of this kind."""
        if self.load:
            return load == self.load
        if self.outputs:
            return any(o in outputs for o in self.outputs)
        return not load


def kind_of(kinds: Sequence[SceneKind], scene: Any) -> SceneKind:
    """The first of ``kinds`` that takes ``scene`` (a
    ``crane_sym.scenes.reading.Scene``); ``ValueError`` naming the kinds if none does."""
    for kind in kinds:
        if kind.takes(scene.outputs, scene.load_table):
            return kind
    raise ValueError(f"scene {scene.name!r} is of none of the kinds "
                     f"{[k.name for k in kinds]} (outputs {list(scene.outputs)}, load "
                     f"{scene.load_table!r})")


def report_for(kinds: Sequence[SceneKind], scene: Any, module: Any) -> SceneReport:
    """The report of ``scene`` by the first of ``kinds`` that takes it.

    Parameters
    ----------
    kinds : sequence of SceneKind
        A paper's ``REPORTS``.
    scene : crane_sym.scenes.reading.Scene
        The loaded scene.
    module : module or None
        The scene's generated module.

    Returns
    -------
    SceneReport
    """
    return kind_of(kinds, scene).report(scene, module)
