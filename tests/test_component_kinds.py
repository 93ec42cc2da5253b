"""Component kinds declared once (``crane_sym.components.kinds``): the reader,
a sweep's fields and the walkthrough loop over ``KINDS``; a kind added from one
module (here a toy flywheel, and a toy damper to the ground with physics of its
own, each registered for the test only) is read, checked, swept and run; a
link's load is the one its energies give."""
from __future__ import annotations

import math
from dataclasses import dataclass
from pathlib import Path

import pytest
import sympy as sp
from sympy.physics.units import length, mass

from crane_sym.components import ComponentError, Inertia, kinds
from crane_sym.components.acting import Load, body_of
from crane_sym.components.designs import Designs
from crane_sym.components.kinds import Key, Kind
from crane_sym.components.kinds.base import Acting, Symbolic
from crane_sym.components.parts import (DIMENSIONS, ROTATING, TRANSLATING, UNITS, VALUE_KINDS,
                                        Component, Value, value)
from crane_sym.components.component_file import read_component_file

EXAMPLES = sorted((Path(__file__).resolve().parents[1] / "examples" / "drive_trains")
                  .glob("*.toml"))


# --- the toy kind: one module's worth, as ARCHITECTURE.md "How to add a kind" shows ---
def _flywheel(g: dict, entry: dict, where: str):
    """A solid disc: J = m r² / 2 about its axis."""
    owner = f"flywheel {g['name']!r}"
    m = value(owner, "mass", g["mass"], mass).si
    r = value(owner, "radius", g["radius"], length).si
    if m < 0 or r <= 0:
        raise ComponentError(f"{owner}: mass must be >= 0 and radius > 0, "
                             f"got {g['mass']!r}, {g['radius']!r}")
    return Inertia(g["name"], m * r**2 / 2)


FLYWHEEL = Kind("flywheel", (Key("name", "word"), Key("mass", value=mass, sign="nonnegative"),
                             Key("radius", value=length, sign="positive")),
                _flywheel, "a solid disc, a rotating body of inertia m r²/2")
# -------------------------------------------------------------------------------------



# --- a toy kind with new physics, one module's worth: a viscous damper from a body to
# the ground, F = −d v along the body's coordinate (v = κ q̇ its speed) ---------------
@dataclass(frozen=True)
class Dashpot(Component):
    """A linear viscous damper between ``body`` and the ground."""

    name: str
    body: str
    damping: Value
    kind = "dashpot"


def _dashpot_check(part: Dashpot, bodies: dict, components) -> Load:
    """d in SI, a damping of its body's motion (N·s/m on a mass, N·m·s/rad on a shaft)."""
    body, where = body_of(part, bodies)
    return Load(part, None, (part.damping.check(where, "damping",
                                                DIMENSIONS["damping"][body.motion]),))


DAMPING = Symbolic("damping", "d", "nonnegative", lambda load: load.values[0],
                   "damping of the dashpot {name} to the ground")
DASHPOT = Kind("dashpot", (Key("name", "word"), Key("body", "body"),
                           Key("damping", value="damping", sign="nonnegative")),
               lambda g, entry, where: Dashpot(g["name"], g["body"],
                                               value(where, "damping", g["damping"])),
               "a viscous damper from a body to the ground", symbols=(DAMPING,),
               acts=lambda part, kappa, q: Acting(
                   -DAMPING.symbol(part.name) * kappa * q.diff(q.args[0])),
               check=_dashpot_check)
# -------------------------------------------------------------------------------------

DRIVE = """
[model]
name = "toy"

{wheel}

[[inertia]]
name = "drum"
inertia = "30 kg*m^2"

[[elastic]]
name = "shaft"
between = ["wheel", "drum"]
stiffness = "2e5 N*m/rad"
damping = "40 N*m*s/rad"

[[motor]]
name = "drive"
body = "wheel"
torque = "1.5 kN*m"

[[resistance]]
name = "load"
body = "drum"
torque = "-1 kN*m"

[run]
duration = "0.5 s"
start = "rest"
"""
AS_FLYWHEEL = '[[flywheel]]\nname = "wheel"\nmass = "100 kg"\nradius = "0.5 m"'
AS_INERTIA = '[[inertia]]\nname = "wheel"\ninertia = "12.5 kg*m^2"'


@pytest.fixture()
def with_flywheel(monkeypatch):
    """The flywheel registered for this test only: KINDS is the one list."""
    monkeypatch.setattr(kinds, "KINDS", [*kinds.KINDS, FLYWHEEL])


def _write(tmp_path: Path, wheel: str, name: str = "toy.toml") -> Path:
    path = tmp_path / name
    path.write_text(DRIVE.format(wheel=wheel), encoding="utf-8")
    return path


def test_an_unregistered_kind_is_an_unknown_table(tmp_path):
    with pytest.raises(ComponentError, match="unknown table 'flywheel'"):
        read_component_file(_write(tmp_path, AS_FLYWHEEL))


def test_a_kind_added_from_one_declaration_runs_as_its_parts_would(tmp_path, with_flywheel):
    toy = read_component_file(_write(tmp_path, AS_FLYWHEEL))
    plain = read_component_file(_write(tmp_path, AS_INERTIA, "plain.toml"))
    assert toy.model.assembly.bodies["wheel"].inertia == 12.5
    runs = [f.model.run(f.duration, f.body, f.speed, rest=f.rest) for f in (toy, plain)]
    assert runs[0].peaks[0].value == runs[1].peaks[0].value != 0.0
    assert runs[0].peaks[0].time == runs[1].peaks[0].time
    # its keys are checked as declared, in one line naming the key and the table
    bad = DRIVE.format(wheel=AS_FLYWHEEL.replace('"0.5 m"', '"0.5 s"'))
    (tmp_path / "bad.toml").write_text(bad, encoding="utf-8")
    with pytest.raises(ComponentError, match=r"flywheel 'wheel': radius '0.5 s' is time") as err:
        read_component_file(tmp_path / "bad.toml")
    assert "\n" not in str(err.value)
    with pytest.raises(ComponentError, match=r"\[\[flywheel\]\] 'wheel': unknown key 'radus'"):
        (tmp_path / "typo.toml").write_text(DRIVE.format(wheel=AS_FLYWHEEL.replace(
            "radius", "radus")), encoding="utf-8")
        read_component_file(tmp_path / "typo.toml")


def test_a_sweep_varies_a_new_kinds_values_by_its_declaration(tmp_path, with_flywheel):
    designs = Designs(_write(tmp_path, AS_FLYWHEEL))
    field = designs.fields["wheel.radius"]
    assert (field.table, field.dimension, field.sign) == ("flywheel", length, "positive")
    doubled = designs.design({"wheel.radius": 1.0})
    assert doubled.assembly.bodies["wheel"].inertia == 50.0


def test_the_key_tables_come_from_the_declarations():
    """DIMENSIONS and UNITS are two columns of VALUE_KINDS; every key a kind says
    holds a kind of value names one of them."""
    assert set(DIMENSIONS) == set(UNITS) == set(VALUE_KINDS)
    assert UNITS["backlash"][ROTATING] == "rad" and DIMENSIONS["inertia"][ROTATING] == mass * length**2
    tables = [k.table for k in kinds.KINDS]
    assert len(tables) == len(set(tables)) == 17
    for kind in kinds.KINDS:
        names = [k.name for k in kind.keys]
        assert len(names) == len(set(names)) and names[0] == "name", kind.table
        assert list(kind.required + kind.optional) == names, kind.table   # required first
    with pytest.raises(ValueError, match="value must be one of"):
        Key("x", value="stifness")


@pytest.mark.parametrize("path", EXAMPLES, ids=lambda p: p.stem)
def test_a_links_load_is_the_one_its_energies_give(path):
    """F_k = ∂Π/∂u_k + ∂Φ/∂u̇_k equals the spring-and-damper law χ (c (u − δ) + d u̇),
    symbolically, and a run's output takes exactly c, d and −c from it."""
    model = read_component_file(path).model
    eq = model.equations
    for k, link in enumerate(model.assembly.links):
        name = link.part.name
        c, d = sp.Symbol(f"c_{name}", positive=True), sp.Symbol(f"d_{name}", nonnegative=True)
        spring = kinds.of(link.part).stiffness          # a pendulum's m g/L
        c = c if spring is None else spring(link.part)
        chi, delta = ((sp.Symbol(f"chi_{name}", real=True), sp.Symbol(f"delta_{name}", real=True))
                      if link.gapped else (1, 0))
        u = eq.twists[k]
        assert sp.expand(eq.link_loads[k] - chi * (c * (u - delta) + d * u.diff(eq.t))) == 0
        assert eq.link_coefficients(k) == (link.stiffness, link.damping,
                                           -link.stiffness if link.gapped else 0.0)


def test_every_declared_symbol_names_a_key_and_every_part_finds_its_kind():
    """A kind's symbols come from its own keys (their dimensions and units are
    the keys'), and ``kinds.of`` gives each part the kind whose table built it."""
    for kind in kinds.KINDS:
        for declared in kind.symbols:
            assert kind.key(declared.key).value is not None, (kind.table, declared.key)
    seen = set()
    for path in EXAMPLES:
        read = read_component_file(path)
        for table, entries in read.tables.items():
            for entry in entries:
                part = next(p for p in read.parts if p.name == entry["name"])
                assert kinds.of(part).table == table
                seen.add(table)
    assert seen == {k.table for k in kinds.KINDS}      # the examples hold every kind


SPRING_MASS = """
[model]
name = "damped"

[[mass]]
name = "cart"
mass = "{m} kg"

[[elastic]]
name = "spring"
between = ["ground", "cart"]
stiffness = "{c} N/m"

[[resistance]]
name = "push"
body = "cart"
force = "{F} N"

[[dashpot]]
name = "dash"
body = "cart"
damping = "{d}"

[run]
duration = "{T} s"
start = "rest"
"""


def test_a_kind_with_new_physics_from_one_module_runs_against_its_closed_form(
        tmp_path, monkeypatch):
    """m ẍ + d ẋ + c x = F from rest (the damper the toy kind's only physics):
    the spring's load c x peaks first at t = π/ω_d with F (1 + e^(−ζπ/√(1−ζ²)))."""
    monkeypatch.setattr(kinds, "KINDS", [*kinds.KINDS, DASHPOT])
    m, c, F, d = 500.0, 2.0e5, 1.0e3, 1.2e3
    omega, zeta = math.sqrt(c / m), d / (2 * math.sqrt(c * m))
    damped = omega * math.sqrt(1 - zeta**2)
    path = tmp_path / "damped.toml"
    path.write_text(SPRING_MASS.format(m=m, c=c, F=F, d=f"{d} N*s/m", T=1.2 * math.pi / damped),
                    encoding="utf-8")
    read = read_component_file(path)
    assert read.model.equations.values[sp.Symbol("d_dash", nonnegative=True)] == d
    peak = read.model.run(read.duration, read.body, read.speed, rest=read.rest).peaks[0]
    want = F * (1 + math.exp(-zeta * math.pi / math.sqrt(1 - zeta**2)))
    assert abs(peak.value - want) <= 1e-9 * want
    assert abs(peak.time - math.pi / damped) <= 1e-9 * (math.pi / damped)
    # a sweep varies its damping as declared: a damping of the mass it acts on
    field = Designs(path).fields["dash.damping"]
    assert (field.table, field.dimension, field.sign) == (
        "dashpot", DIMENSIONS["damping"][TRANSLATING], "nonnegative")
    # its own check: d against the body's motion, in one line naming the part and the bound
    path.write_text(SPRING_MASS.format(m=m, c=c, F=F, d=f"{d} N*m*s/rad", T=1.0),
                    encoding="utf-8")
    with pytest.raises(ComponentError) as err:
        read_component_file(path)
    assert str(err.value) == ("component model 'damped': dashpot 'dash' on mass 'cart': damping "
                              "'1200.0 N*m*s/rad' is mass*length**2/time, expected "
                              "force*time/length (e.g. N*s/m)")


def test_a_sweep_field_takes_its_dimension_from_the_body_a_link_to_the_ground_holds(tmp_path):
    """A shaft held by a torsion spring to the ground: the spring's stiffness
    is a torsional one (N·m/rad), from the shaft's motion, never the ground's."""
    path = tmp_path / "grounded.toml"
    path.write_text('[model]\nname = "grounded"\n\n[[inertia]]\nname = "shaft"\n'
                    'inertia = "10 kg*m^2"\n\n[[elastic]]\nname = "spring"\n'
                    'between = ["ground", "shaft"]\nstiffness = "1e4 N*m/rad"\n\n'
                    '[[motor]]\nname = "drive"\nbody = "shaft"\ntorque = "100 N*m"\n\n'
                    '[run]\nduration = "0.1 s"\nstart = "rest"\n', encoding="utf-8")
    field = Designs(path).fields["spring.stiffness"]
    assert field.dimension == DIMENSIONS["stiffness"][ROTATING]
