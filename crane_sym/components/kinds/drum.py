"""``[[drum]]``: a rope drum; the ``load`` moves ``radius/reeving`` per radian of the ``drum``."""
from sympy.physics.units import Dimension, length

from crane_sym.components.kinds.base import Key, Kind, Symbolic, ends_moving
from crane_sym.components.parts import ROTATING, TRANSLATING, Drum

RADIUS = Symbolic("radius", "r", "positive", lambda drum: drum.radius, "radius of the drum {name}")
REEVING = Symbolic("reeving", "n", "positive", lambda drum: drum.reeving,
                   "reeving (rope falls) of the drum {name}")

KIND = Kind("drum", (Key("name", "word"), Key("drum", "body"), Key("load", "body"),
                     Key("radius", value=length, sign="positive"),
                     Key("reeving", "number", Dimension(1), "positive", False, 1)),
            lambda g, entry, where: Drum(g["name"], g["drum"], g["load"], g["radius"],
                                         g["reeving"]),
            "a rope drum between a rotating and a translating body",
            symbols=(RADIUS, REEVING),
            check=lambda part, bodies, components: ends_moving(
                part, bodies, (ROTATING, TRANSLATING),
                "turns with a rotating drum and moves a translating load"),
            rigid=lambda part: RADIUS.symbol(part.name) / REEVING.symbol(part.name))
