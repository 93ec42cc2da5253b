"""``[[mass]]``: a translating body, its mass in kg."""
from crane_sym.components.kinds.base import Key, Kind, Symbolic
from crane_sym.components.parts import Mass

KIND = Kind("mass", (Key("name", "word"), Key("mass", value="mass", sign="nonnegative")),
            lambda g, entry, where: Mass(g["name"], g["mass"]),
            "a translating body",
            symbols=(Symbolic("mass", "m", "positive", lambda body: body.inertia,
                              "mass of {name}"),),
            counted="bodies")
