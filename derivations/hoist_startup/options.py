"""What a scene of paper 002 takes in ``[options]``, and what is checked on load.

A scene without a drive law of its own names the figure it reproduces
(``figure``, one of ``report.FIGURES``); ``crane_sym.scenes.reading.load_scene``
checks, before any file is written, that the scene gives the parameters the
figure reads and that Omega and tau_0, where the scene gives them with the
data of (2) or (29), agree with those equations. A scene with a
``[drive_law]`` takes ``duration`` and ``points`` only. Where the report
certifies maxima by interval arithmetic (a drive law, ``figure =
"drive_laws"``), its work grows with the periods of the free oscillation in
the span, so the span holds at most ``MAX_PERIODS`` of them.
"""
from __future__ import annotations

import importlib
import math

from crane_sym.scenes.options import SceneCheck, SceneOption

from .drive_law_scene import DRIVE_LAW
from .report import FIGURES, GENERATED

#: The parameters each figure reads, beside the time grid.
FIGURE_PARAMETERS = {"fig3": ("Omega",), "fig5": ("Omega", "t_n"),
                     "drive_laws": ("m1", "m2", "C", "g", "v0", "t_n", "Omega", "tau_0")}
_CONSISTENCY = 1e-9      # relative agreement of Omega, tau_0 with (2), (29)
#: Most periods 2 pi/Omega in the span of a scene whose maxima are certified:
#: the certified maximum of the shipped law takes about 20 s over 10 periods,
#: 29 s over 20 and 63 s over 40 (README, "Scenes"); after the law the motion
#: is a free undamped oscillation, so a longer span shows nothing new.
MAX_PERIODS = 20

SCENE_OPTIONS = (
    SceneOption("figure", "choice", "what the scene reproduces", choices=tuple(FIGURES)),
)


def _figure_has_its_parameters(scene) -> str | None:
    figure = scene.settings["figure"]
    missing = [p for p in FIGURE_PARAMETERS[figure] if p not in scene.parameters]
    if missing:
        return (f"figure {figure!r} reads the parameters {missing}, which the scene does "
                "not give; give them in [parameters] (and an output that takes them)")
    return None


def _defined_agree(scene) -> str | None:
    """Omega and tau_0, where the scene gives them with the data of (2) or (29),
    must equal what those equations give (the generated functions take them as
    arguments, so nothing else would notice a mismatch)."""
    gen, q = importlib.import_module(GENERATED), scene.parameters
    for name, func, args, eq in (
            ("Omega", gen.natural_frequency, ("m1", "m2", "C"), "(2)"),
            ("tau_0", gen.pickup_contact_time, ("m2", "g", "C", "v0"), "(29)")):
        if name in q and all(a in q for a in args):
            derived = float(func(*(q[a] for a in args)))
            if not math.isclose(q[name], derived, rel_tol=_CONSISTENCY):
                return (f"parameter {name!r} = {q[name]!r} does not follow from "
                        f"{', '.join(args)}: {eq}, {func.__name__}, gives {derived!r}")
    return None


def _span_in_periods(scene) -> str | None:
    """At most ``MAX_PERIODS`` periods in the span, where maxima are certified."""
    if scene.settings.get("figure", "drive_laws") != "drive_laws":
        return None
    q = scene.parameters
    omega = (math.sqrt((q["m1"] + q["m2"]) * q["C"] / (q["m1"] * q["m2"]))
             if all(n in q for n in ("m1", "m2", "C")) else q.get("Omega"))
    if omega is None:
        return None
    periods = scene.settings["duration"] * omega / (2 * math.pi)
    if periods > MAX_PERIODS:
        return (f"[options] duration = {scene.settings['duration']:g} s holds {periods:.4g} "
                f"periods 2 pi/Omega = {2 * math.pi / omega:.4g} s; at most {MAX_PERIODS} "
                f"are allowed where the maximum is certified (duration <= "
                f"{MAX_PERIODS * 2 * math.pi / omega:.4g} s)")
    return None


SCENE_CHECKS = (
    SceneCheck("the figure's parameters are given", _figure_has_its_parameters),
    SceneCheck("Omega and tau_0 agree with (2) and (29)", _defined_agree),
    SceneCheck(f"at most {MAX_PERIODS} periods in the span of a figure whose maxima are "
               "certified", _span_in_periods),
    SceneCheck(f"at most {MAX_PERIODS} periods in the span of a drive law",
               _span_in_periods, outputs=DRIVE_LAW.outputs),
)
