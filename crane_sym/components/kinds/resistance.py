"""``[[resistance]]``: a constant torque (a force on a translating body), either sign."""
from crane_sym.components.kinds.base import Key, Kind, load_key
from crane_sym.components.loads import Resistance

KIND = Kind("resistance", (Key("name", "word"), Key("body", "word"),
                           Key("torque", value="load", required=False),
                           Key("force", value="load", required=False)),
            lambda g, entry, where: Resistance(g["name"], g["body"], g[load_key(entry, where)]),
            "a constant resistance on a body")
