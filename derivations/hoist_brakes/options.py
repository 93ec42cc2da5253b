"""What a scene of paper 001 takes in ``[options]``, and what is checked on load.

Beside ``duration`` and ``points``, a scene says whether its payload may
exceed the rated one (``payload_limit``); ``crane_sym.scenes.reading.load_scene``
refuses a payload above the rated one, before any file is written, unless
the scene allows it.
"""
from __future__ import annotations

from crane_sym.scenes.options import SceneCheck, SceneOption

SCENE_OPTIONS = (
    SceneOption("payload_limit", "choice", "the largest payload m_p the scene admits: "
                "\"rated\" refuses one above the rated m_r, \"any\" admits it", "rated",
                choices=("rated", "any")),
)


def _payload_within_rated(scene) -> str | None:
    q = scene.parameters
    if scene.settings["payload_limit"] == "rated" and "m_p" in q and "m_r" in q \
            and q["m_p"] > q["m_r"]:
        return (f"parameter 'm_p' (payload) = {q['m_p']:g} kg is above the rated payload "
                f"m_r = {q['m_r']:g} kg (options: payload_limit = \"rated\")")
    return None


SCENE_CHECKS = (
    SceneCheck("payload m_p <= rated m_r unless payload_limit = \"any\"",
               _payload_within_rated),
)
