"""``[[ground_contact]]``: a body resting on the ground, which pushes it but
never pulls: held at x = 0 by the reaction R ≥ 0, lifting off where R would
turn negative, set down where it comes back (:mod:`crane_sym.components.hybrid`
holds its two modes)."""
from crane_sym.components.kinds.base import Key, Kind
from crane_sym.components.loads import GroundContact

KIND = Kind("ground_contact", (Key("name", "word"), Key("body", "body"),
                               Key("direction", "word", required=False, default="+")),
            lambda g, entry, where: GroundContact(g["name"], g["body"], g["direction"]),
            "a body resting on the ground: it lifts off and is set down again",
            "ground contact", roles=lambda part: frozenset({"rests"}))
