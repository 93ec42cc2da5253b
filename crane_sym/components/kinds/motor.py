"""``[[motor]]``: a constant (or ``steady``) torque on a body, optionally switched off."""
from sympy.physics.units import time

from crane_sym.components.kinds.base import Key, Kind, load_key
from crane_sym.components.loads import Motor

KIND = Kind("motor", (Key("name", "word"), Key("body", "word"),
                      Key("torque", value="load", sign="positive", required=False),
                      Key("force", value="load", sign="positive", required=False),
                      Key("off_at", value=time, sign="nonnegative", required=False)),
            lambda g, entry, where: Motor(g["name"], g["body"], g[load_key(entry, where)],
                                          g["off_at"]),
            "a motor's constant or steady torque on a body")
