"""``[[elastic]]``: a spring and a viscous damper between two bodies of one kind,
with an optional backlash gap: F = c (u − flank) + d u̇, u = x(second) − x(first)."""
from crane_sym.components.kinds.base import Key, Kind, Symbolic
from crane_sym.components.parts import DIMENSIONS, UNITS, ElasticLink


def _build(g: dict, entry: dict, where: str) -> ElasticLink:
    first, second = g["between"]
    return ElasticLink(g["name"], first, second, g["stiffness"], g["damping"], g["backlash"],
                       g["contact"], g["reference"], g["positive"])


def _switching(part: ElasticLink, motion: str) -> tuple:
    return (("backlash", part.backlash.si, DIMENSIONS["backlash"][motion],
             UNITS["backlash"][motion], f"backlash (gap) of the elastic link {part.name}"),)


KIND = Kind("elastic", (Key("name", "word"), Key("between", "ends"),
                        Key("stiffness", value="stiffness", sign="positive"),
                        Key("damping", value="damping", sign="nonnegative", required=False,
                            default=0.0),
                        Key("backlash", value="backlash", sign="nonnegative", required=False,
                            default=0.0),
                        Key("contact", "word", required=False, default="positive"),
                        Key("reference", value="load", sign="nonzero", required=False),
                        Key("positive", "word", required=False)),
            _build, "a spring and damper between two bodies, with an optional backlash",
            "elastic link",
            symbols=(Symbolic("stiffness", "c", "positive", lambda link: link.stiffness,
                              "stiffness of the elastic link {name}"),
                     Symbolic("damping", "d", "nonnegative", lambda link: link.damping,
                              "damping of the elastic link {name}")),
            shape=lambda link: link.backlash.si > 0, switching=_switching)
