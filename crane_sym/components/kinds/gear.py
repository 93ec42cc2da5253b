"""``[[gear]]``: an ideal gear; ``input`` turns ``ratio`` times as far as ``output``."""
from sympy.physics.units import Dimension

from crane_sym.components.kinds.base import Key, Kind, Symbolic
from crane_sym.components.parts import Gear

KIND = Kind("gear", (Key("name", "word"), Key("input", "body"), Key("output", "body"),
                     Key("ratio", "number", Dimension(1), "positive")),
            lambda g, entry, where: Gear(g["name"], g["input"], g["output"], g["ratio"]),
            "an ideal gear between two rotating bodies",
            symbols=(Symbolic("ratio", "i", "positive", lambda gear: gear.ratio,
                              "ratio of the gear {name}"),))
