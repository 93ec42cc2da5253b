"""``[[gear]]``: an ideal gear; ``input`` turns ``ratio`` times as far as ``output``."""
from sympy.physics.units import Dimension

from crane_sym.components.kinds.base import Key, Kind, Symbolic, ends_moving
from crane_sym.components.parts import ROTATING, Gear

RATIO = Symbolic("ratio", "i", "positive", lambda gear: gear.ratio, "ratio of the gear {name}")

KIND = Kind("gear", (Key("name", "word"), Key("input", "body"), Key("output", "body"),
                     Key("ratio", "number", Dimension(1), "positive")),
            lambda g, entry, where: Gear(g["name"], g["input"], g["output"], g["ratio"]),
            "an ideal gear between two rotating bodies",
            symbols=(RATIO,),
            check=lambda part, bodies, components: ends_moving(
                part, bodies, (ROTATING, ROTATING), "joins two rotating bodies"),
            rigid=lambda part: 1 / RATIO.symbol(part.name))
