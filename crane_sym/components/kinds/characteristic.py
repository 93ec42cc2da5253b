"""``[[characteristic]]``: a motor's β (v0 − v), its slope stepped at the hold times."""
from crane_sym.components.kinds.base import Key, Kind
from crane_sym.components.loads import Characteristic

KIND = Kind("characteristic", (Key("name", "word"), Key("body", "word"),
                               Key("speed", value="speed"), Key("slopes", "list"),
                               Key("holds", "list", required=False, default=[])),
            lambda g, entry, where: Characteristic(g["name"], g["body"], g["speed"], g["slopes"],
                                                   g["holds"]),
            "a motor's speed characteristic on a body")
