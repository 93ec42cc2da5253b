"""What a scene of paper 004 takes in ``[options]``, and what is checked on load.

A scene that asks for ``pulsating_force`` is simulated as the example of the
paper (``report.example_report``): it gives the simulation-only values of
the model (masses and resistances that no generated function takes), the
mass of the run without loads and, optionally, the integrator. A scene that
asks for the state derivative (``report_state``) gives the constant load on
the run. ``crane_sym.scenes.reading.load_scene`` reads them all before any file is
written.
"""
from __future__ import annotations

from crane_sym.scenes.options import SceneCheck, SceneOption, from_symbol

from .model import MODEL_SYMBOLS

_SYMBOLS = {s.name: s for s in MODEL_SYMBOLS}
_EXAMPLE = ("pulsating_force",)
#: Simulation-only values of the example (symbols of the model, given with units).
SIM_OPTIONS = ("m3", "m_L", "nu1", "nu2", "nu_y", "nu_z", "nu_t")
#: The integrators of ``scipy.integrate.solve_ivp``.
METHODS = ("RK23", "RK45", "DOP853", "Radau", "BDF", "LSODA")

SCENE_OPTIONS = (
    *(from_symbol(_SYMBOLS[name], outputs=_EXAMPLE) for name in SIM_OPTIONS),
    SceneOption("m_L_empty", "quantity", "mass of the run without loads", unit="kg",
                dimension=_SYMBOLS["m_L"].dimension, low=_SYMBOLS["m_L"].serves[0],
                high=_SYMBOLS["m_L"].serves[1], outputs=_EXAMPLE),
    SceneOption("method", "choice", "integrator of scipy.integrate.solve_ivp", "LSODA",
                choices=METHODS, outputs=_EXAMPLE),
    from_symbol(_SYMBOLS["W"], default="1 kN", outputs=("state_derivative",)),
)


def _runnable(scene) -> str | None:
    """A run simulates the example (``pulsating_force``) or the scene's own
    state derivative, which needs its Jacobian."""
    if "pulsating_force" in scene.outputs or {"state_derivative", "state_jacobian"} <= set(
            scene.outputs):
        return None
    return "a run needs pulsating_force, or state_derivative with state_jacobian"


SCENE_CHECKS = (
    SceneCheck("the scene can be run: pulsating_force, or state_derivative with "
               "state_jacobian", _runnable),
)
