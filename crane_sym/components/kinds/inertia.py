"""``[[inertia]]``: a rotating body, its moment of inertia in kg·m²."""
from crane_sym.components.kinds.base import Key, Kind, Symbolic
from crane_sym.components.parts import Inertia

KIND = Kind("inertia", (Key("name", "word"), Key("inertia", value="inertia", sign="nonnegative")),
            lambda g, entry, where: Inertia(g["name"], g["inertia"]),
            "a rotating body",
            symbols=(Symbolic("inertia", "J", "positive", lambda body: body.inertia,
                              "moment of inertia of {name}"),),
            counted="bodies")
