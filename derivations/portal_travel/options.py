"""What a scene of paper 003 takes in ``[options]``, and what is checked on load.

The paper's scenes are of four kinds, told apart by the outputs they name
(``report.scene_report``); each takes its own options: Fig. 10 the range of
tooth numbers, a gear pair how x_Σ is shared and whether undercut is
refused, the support loads the crane's largest reach, the start-up the
backlash values, the hold times, the end of the plot and its points (the
paper has no time symbol, so ``points`` is its own here). The conditions the
reports need (z_min < z_max, a centre distance the mesh can have, no undercut
when forbidden, a synchronous speed above the rated one, a plot that outlasts
the start) are checked by ``crane_sym.scenes.reading.load_scene`` before any file is
written; the gear pair through the paper's generated functions, which name
the value they refuse.
"""
from __future__ import annotations

import importlib

from sympy import S
from sympy.physics.units import time

from crane_sym.scenes.options import SceneCheck, SceneOption

from .model import SYMBOLS

#: The outputs that mark each kind of scene (its options here, its report in
#: ``report.REPORTS``).
FIG10_SCENES, PAIR_SCENES = ("pointed_tip_shift",), ("contact_ratio",)
SUPPORT_SCENES, STARTUP_SCENES = ("max_support_load",), ("startup_motor_mass",)
#: The tabulated curves a start-up scene's report plots (``outputs.tabulated``).
STARTUP_CURVES = ("startup_load", "startup_link_load", "startup_motor_speed",
                  "startup_crane_speed")
#: The report draws R_max for reaches from this share of the largest one.
REACH_FROM = 0.3
_Z, _REACH, _GAP = (SYMBOLS[n].serves for n in ("z", "L_max", "phi_b"))
GENERATED = "crane_sym.generated.portal_travel"

SCENE_OPTIONS = (
    SceneOption("z_min", "int", "smallest tooth number of Fig. 10", 8, low=3, high=10_000,
                outputs=FIG10_SCENES),
    SceneOption("z_max", "int", "largest tooth number of Fig. 10", 100, low=4,
                high=100_000, outputs=FIG10_SCENES),
    SceneOption("pinion_share", "number", "share x1/x_Σ of the sum of shifts put on the "
                "pinion", 1.0, low=0.0, high=1.0, outputs=PAIR_SCENES),
    SceneOption("forbid_undercut", "bool", "refuse a pair whose teeth are undercut", False,
                outputs=PAIR_SCENES),
    SceneOption("largest_reach_m", "number", "largest reach of the crane", 30.0, unit="m",
                low=_REACH[0] / REACH_FROM, high=_REACH[1], outputs=SUPPORT_SCENES),
    SceneOption("backlash", "quantities", "backlash of one drive on its fast shaft, one "
                "run each", ["0 rad", "0.5 rev", "1 rev"], unit="rad", dimension=S.One,
                low=_GAP[0], high=_GAP[1], length=(1, 6), outputs=STARTUP_SCENES),
    SceneOption("holds", "quantities", "hold time of each start step",
                ["0.4 s", "0.8 s", "0.8 s"], unit="s", dimension=time, low=0.0, above=True,
                high=60.0, length=(1, 6), outputs=STARTUP_SCENES),
    SceneOption("end", "quantities", "end of the plotted start-up", ["4 s"], unit="s",
                dimension=time, low=0.0, above=True, high=600.0, length=(1, 1),
                outputs=STARTUP_SCENES),
    SceneOption("points", "int", "time samples on [0, end]", 2001, low=2, high=100_000,
                outputs=STARTUP_SCENES),
)


def _missing(scene, names: tuple[str, ...], what: str) -> str | None:
    """The parameters of ``names`` the scene does not give, as a message."""
    missing = [n for n in names if n not in scene.parameters]
    return (f"{what} reads the parameters {missing}, which the scene does not give "
            "(keep them out of [scene] inputs)") if missing else None


def _one_kind(scene) -> str | None:
    kinds = (*STARTUP_SCENES, *FIG10_SCENES, *PAIR_SCENES, *SUPPORT_SCENES)
    if not any(o in scene.outputs for o in kinds):
        return f"a run needs one of the outputs {', '.join(kinds)} (the report's kinds)"
    return None


def _tooth_range(scene) -> str | None:
    z_min, z_max = scene.settings["z_min"], scene.settings["z_max"]
    if z_min >= z_max:
        return f"[options] z_min = {z_min} must be below z_max = {z_max}"
    return None


def _gear_pair(scene) -> str | None:
    """What the gear-pair report computes, through the paper's generated
    functions: a centre distance they refuse (``a_w``), tips inside the base
    circle (``x1``, ``x2``) for the scene's share or any other it plots, and
    undercut when the scene forbids it."""
    import numpy as np

    names = ("m", "z1", "z2", "a_w", "alpha", "h_a", "dy1", "dy2")
    if _missing(scene, names, "the gear pair"):
        return _missing(scene, names, "the gear pair")
    gen, q, o = importlib.import_module(GENERATED), scene.parameters, scene.settings
    m, z1, z2, a_w, alpha, h_a = (q[n] for n in ("m", "z1", "z2", "a_w", "alpha", "h_a"))
    x_sum = float(gen.shift_sum(m, z1, z2, a_w, alpha))
    shares = np.append(np.linspace(0.0, 1.0, 101), o["pinion_share"])
    for z, x, dy in ((z1, shares * x_sum, q["dy1"]), (z2, (1 - shares) * x_sum, q["dy2"])):
        gen.tip_diameter(m, z, x, h_a, dy)
        gen.tip_thickness(m, z, x, alpha, h_a, dy)
    gen.contact_ratio(m, z1, z2, shares * x_sum, (1 - shares) * x_sum, a_w, alpha, h_a,
                      q["dy1"], q["dy2"])
    if o["forbid_undercut"]:
        x1 = o["pinion_share"] * x_sum
        for zn, xi in (("z1", x1), ("z2", x_sum - x1)):
            least = float(gen.undercut_limit(q[zn], alpha, h_a))
            if xi < least:
                return (f"{zn} = {q[zn]:g} teeth are undercut with shift {xi:.4g}: the shift "
                        f"must be at least {least:.4g} (forbid_undercut = true)")
    return None


def _startup(scene) -> str | None:
    q, o = scene.parameters, scene.settings
    if _missing(scene, ("omega_0", "omega_n"), "the start-up"):
        return _missing(scene, ("omega_0", "omega_n"), "the start-up")
    if not q["omega_0"] > q["omega_n"]:
        return (f"parameter 'omega_0' (no-load speed) = {q['omega_0']:g} rad/s must exceed "
                f"omega_n = {q['omega_n']:g} rad/s")
    if not o["end"][0] > sum(o["holds"]):
        return (f"[options] end = {o['end'][0]:g} s must exceed the sum of the holds, "
                f"{sum(o['holds']):g} s")
    curves = [n for n in STARTUP_CURVES if n not in scene.outputs]
    if curves:
        return (f"the start-up's curves come from the scene's module: add {curves} to "
                "[scene] outputs")
    return None


SCENE_CHECKS = (
    SceneCheck("the scene is of one of the report's kinds", _one_kind),
    SceneCheck("z_min < z_max", _tooth_range, outputs=FIG10_SCENES),
    SceneCheck("a centre distance the mesh can have, tips outside the base circle, no "
               "undercut when forbidden", _gear_pair, outputs=PAIR_SCENES),
    SceneCheck("omega_0 > omega_n; end > the sum of the holds; the curves tabulated",
               _startup, outputs=STARTUP_SCENES),
)
