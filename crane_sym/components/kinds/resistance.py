"""``[[resistance]]``: a constant torque (a force on a translating body), either sign."""
from crane_sym.components.acting import force_load
from crane_sym.components.kinds.base import Acting, Key, Kind, Symbolic, load_key
from crane_sym.components.loads import Resistance

LOAD = Symbolic("torque", "R", "real", lambda load: load.load,
                "{key} of the resistance {name} on {body}")

KIND = Kind("resistance", (Key("name", "word"), Key("body", "body"),
                           Key("torque", value="load", required=False),
                           Key("force", value="load", required=False)),
            lambda g, entry, where: Resistance(g["name"], g["body"], g[load_key(entry, where)]),
            "a constant resistance on a body",
            idle=lambda part, duration, rest: "its load is 0" if part.load.si == 0 else None,
            symbols=(LOAD,),
            acts=lambda part, kappa, q: Acting(LOAD.symbol(part.name), constant=True),
            check=lambda part, bodies, components: force_load(part, bodies))
