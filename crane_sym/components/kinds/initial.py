"""``[[initial]]``: a body's state at t = 0 beside the run's start, displaced
from where the start puts it and/or moving at a given velocity."""
from crane_sym.components.kinds.base import Key, Kind
from crane_sym.components.loads import Initial

KIND = Kind("initial", (Key("name", "word"), Key("body", "body"),
                        Key("displacement", value="displacement", required=False),
                        Key("velocity", value="speed", required=False)),
            lambda g, entry, where: Initial(g["name"], g["body"], g["displacement"],
                                            g["velocity"]),
            "a body's displacement and velocity at t = 0", "initial state")
