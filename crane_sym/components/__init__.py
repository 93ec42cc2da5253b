"""Component models: a drive train of the user's own, from parts.

Rotating inertias and translating masses; ideal gears and rope drums that
refer bodies to one another (merged into rigid groups, one coordinate each);
elastic links with stiffness, viscous damping and an optional backlash gap;
brakes (delay, step, ramp or exponential build-up, holding at rest within
their capacity); motors (a constant or steady torque, switched off at an
instant; or a characteristic β (v0 − v) stepped at hold times; or a
piecewise polynomial law in time, paper 002's drive laws); gravity on masses;
constant resistances. From them: topology checks
with one-line errors naming the component, T, Π, Φ and Q, Lagrange's
equations in the components' symbols, the piecewise-linear system of its
modes, a run solved phase by phase in closed form, and the component TOML
(``reading`` reads its parts, ``component_file`` derives its run's model);
quantities a reviewer checks (reduced inertia, static load, frequency, closed
form, peak) and verdicts on the formulas a file lists (``file_audit``).
Each kind of component is declared once, in its module of ``kinds``: its
table and keys, how its part is built, when a run may drop it, the symbols
its values take, its share of the generalized forces.

May import: the top-level vocabulary (``units``, ``symbols``, ...),
``audit`` (the papers' checks, for a file's formulas), ``mechanics``,
``kernels``, ``codegen`` and ``scenes`` (its helpers for reading tables);
papers never.
"""
from crane_sym.components.loads import (STEADY, Brake, Characteristic, Gravity, Motor,
                                        Resistance)
from crane_sym.components.laws import MotorLaw
from crane_sym.components.parts import ComponentError, Drum, ElasticLink, Gear, Inertia, Mass
from crane_sym.components.model import ComponentRun, LinkPeak, Model
from crane_sym.components.component_file import ComponentFile, read_component_file

__all__ = ["Brake", "Characteristic", "ComponentError", "ComponentFile", "ComponentRun", "Drum",
           "ElasticLink", "Gear", "Gravity", "Inertia", "LinkPeak", "Mass", "Model", "Motor",
           "MotorLaw", "Resistance", "STEADY", "read_component_file"]
