"""``[[initial]]``: a body's state at t = 0 beside the run's start, displaced
from where the start puts it and/or moving at a given velocity
(:mod:`crane_sym.components.initial` applies it)."""
from crane_sym.components.kinds.base import Key, Kind
from crane_sym.components.loads import Initial
from crane_sym.components.parts import ComponentError


def _build(g: dict, entry: dict, where: str) -> Initial:
    if g["displacement"] is None and g["velocity"] is None:
        raise ComponentError(f"{where}: give a displacement, a velocity or both")
    return Initial(g["name"], g["body"], g["displacement"], g["velocity"])


KIND = Kind("initial", (Key("name", "word"), Key("body", "body"),
                        Key("displacement", value="displacement", required=False),
                        Key("velocity", value="speed", required=False)),
            _build, "a body's displacement and velocity at t = 0", "initial state")
