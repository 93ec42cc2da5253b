"""``[[elastic]]``: a spring and a viscous damper between two bodies of one kind,
with an optional backlash gap: F = c (u − flank) + d u̇, u = x(second) − x(first);
or, with ``slack`` h instead, a rope that only pulls: F = c (u − h) + d u̇ while
u ≥ h, 0 below (a key of this kind, not a kind of its own: a slack rope is an
elastic link whose gap runs from −∞ to h, so its load, peak, dynamic factor,
sweep and walkthrough are the elastic link's)."""
from sympy.physics.units import time

from crane_sym.components.kinds.base import Key, Kind, Symbolic, failure
from crane_sym.components.parts import DIMENSIONS, UNITS, ComponentError, ElasticLink


def _build(g: dict, entry: dict, where: str) -> ElasticLink:
    first, second = g["between"]
    if "slack" in entry and ("backlash" in entry or "contact" in entry):
        given = "backlash" if "backlash" in entry else "contact"
        raise ComponentError(f"{where}: slack {entry['slack']!r} makes a rope that only pulls; "
                             f"it takes no {given} (got {given} = {entry[given]!r})")
    return ElasticLink(g["name"], first, second, g["stiffness"], g["damping"], g["backlash"],
                       g["contact"], g["reference"], g["positive"], g["slack"], g["fails_at"])


def _switching(part: ElasticLink, motion: str) -> tuple:
    gap = (("slack", part.slack.si, "slack") if part.slack is not None else
           ("backlash", part.backlash.si, "backlash (gap)"))
    return ((gap[0], gap[1], DIMENSIONS["backlash"][motion], UNITS["backlash"][motion],
             f"{gap[2]} of the elastic link {part.name}"),
            *failure(part, f"the elastic link {part.name}"))


KIND = Kind("elastic", (Key("name", "word"), Key("between", "ends"),
                        Key("stiffness", value="stiffness", sign="positive"),
                        Key("damping", value="damping", sign="nonnegative", required=False,
                            default=0.0),
                        Key("backlash", value="backlash", sign="nonnegative", required=False,
                            default=0.0),
                        Key("contact", "word", required=False, default="positive"),
                        Key("reference", value="load", sign="nonzero", required=False),
                        Key("positive", "word", required=False),
                        Key("slack", value="backlash", sign="nonnegative", required=False),
                        Key("fails_at", value=time, sign="positive", required=False)),
            _build, "a spring and damper between two bodies, with an optional backlash, "
            "or a rope that only pulls (slack)",
            "elastic link",
            symbols=(Symbolic("stiffness", "c", "positive", lambda link: link.stiffness,
                              "stiffness of the elastic link {name}"),
                     Symbolic("damping", "d", "nonnegative", lambda link: link.damping,
                              "damping of the elastic link {name}")),
            shape=lambda link: link.gapped, switching=_switching, counted="links")
