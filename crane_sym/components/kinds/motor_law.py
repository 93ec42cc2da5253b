"""``[[motor_law]]``: a torque, acceleration or speed law in time, piecewise polynomial
(paper 002's drive laws)."""
from crane_sym.components.kinds.base import Key, Kind
from crane_sym.components.laws import MotorLaw

KIND = Kind("motor_law", (Key("name", "word"), Key("body", "word"), Key("law", "word"),
                          Key("unit", "word"), Key("breakpoints", "law"),
                          Key("coefficients", "law"),
                          Key("time_unit", "word", required=False, default="s")),
            lambda g, entry, where: MotorLaw(g["name"], g["body"], g["breakpoints"],
                                             g["coefficients"], g["unit"], g["law"],
                                             g["time_unit"]),
            "a law in time on a body")
