"""``[[gravity]]``: the weight of a translating body along its coordinate."""
from sympy.physics.units import length, time

from crane_sym.components.kinds.base import Key, Kind
from crane_sym.components.loads import Gravity

KIND = Kind("gravity", (Key("name", "word"), Key("body", "word"),
                        Key("g", value=length / time**2, sign="nonnegative", required=False,
                            default="9.81 m/s^2"),
                        Key("direction", "word", required=False, default="+")),
            lambda g, entry, where: Gravity(g["name"], g["body"], g["g"], g["direction"]),
            "the weight of a translating body")
