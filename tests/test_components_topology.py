"""Topology errors of component models: one line, naming the component."""
from __future__ import annotations

import pytest

from crane_sym.components import (Brake, ComponentError, Drum, ElasticLink, Gear, Gravity,
                                  Inertia, Mass, Model, Motor)


def base():
    return [Inertia("motor", "20 kg*m^2"), Inertia("drum", "500 kg*m^2"), Mass("hook", "10 t"),
            ElasticLink("shaft", "motor", "drum", "4e4 N*m/rad"),
            Drum("rope", "drum", "hook", "0.5 m", 4)]


CASES = {
    "a body connected to nothing": (
        base() + [Inertia("spare", "1 kg*m^2")],
        ["inertia 'spare'", "connected to nothing"]),
    "a link to an unknown body": (
        base() + [Inertia("pinion", 1.0), ElasticLink("coupling", "motr", "pinion", 1e4)],
        ["elastic link 'coupling'", "unknown body 'motr'", "did you mean 'motor'"]),
    "a brake on an unknown body": (
        base() + [Brake("safety", "drun", "1 kN*m")],
        ["brake 'safety'", "unknown body 'drun'"]),
    "a loop of gears with inconsistent ratios": (
        base() + [Inertia("a", 1.0), Inertia("b", 1.0), Inertia("c", 1.0),
                  Gear("g1", "a", "b", 2), Gear("g2", "b", "c", 3), Gear("g3", "a", "c", 5),
                  ElasticLink("e", "motor", "a", 1e4)],
        ["closes a loop of rigid links (g1, g2, g3)", "disagree"]),
    "a body without inertia between two rigid links": (
        base() + [Inertia("a", 0.0), Inertia("b", 0.0), Inertia("c", 0.0),
                  Gear("g1", "a", "b", 2), Gear("g2", "b", "c", 3),
                  ElasticLink("e1", "motor", "a", 1e4), ElasticLink("e2", "c", "drum", 1e4)],
        ["inertia 'b'", "no inertia between the rigid links gear 'g1' and gear 'g2'"]),
    "a body without inertia between two elastic links": (
        base() + [Inertia("a", 0.0), ElasticLink("e1", "motor", "a", 1e4),
                  ElasticLink("e2", "a", "drum", 1e4)],
        ["inertia 'a'", "no inertia between elastic links"]),
    "an elastic link inside a rigid group": (
        base() + [Inertia("pinion", 1.0), Gear("g", "motor", "pinion", 3),
                  ElasticLink("twin", "pinion", "motor", 1e4)],
        ["elastic link 'twin'", "never twist"]),
    "two components of one name": (
        base() + [Brake("rope", "drum", "1 kN*m")],
        ["brake 'rope'", "taken by drum 'rope'"]),
    "a stiffness of the wrong dimension": (
        [Inertia("a", 1.0), Inertia("b", 1.0), ElasticLink("e", "a", "b", "4e4 N/m")],
        ["elastic link 'e'", "stiffness '4e4 N/m'", "force*length"]),
    "gravity on a rotating body": (
        base() + [Gravity("weight", "drum")],
        ["gravity 'weight'", "rotates"]),
    "a gear to a translating body": (
        base() + [Gear("g", "drum", "hook", 2)],
        ["gear 'g'", "two rotating bodies"]),
    "parts not connected to each other": (
        base() + [Inertia("x", 1.0), Inertia("y", 1.0), Gear("g", "x", "y", 2)],
        ["inertia 'x'", "not connected"]),
    "two steady motors": (
        base() + [Motor("m1", "motor", "steady"), Motor("m2", "drum", "steady")],
        ["motor 'm2'", "only one motor"]),
}


@pytest.mark.parametrize("case", sorted(CASES))
def test_topology_error_is_one_line_naming_the_component(case):
    parts, phrases = CASES[case]
    with pytest.raises(ComponentError) as info:
        Model(parts)
    message = str(info.value)
    assert "\n" not in message
    for phrase in phrases:
        assert phrase in message, (case, message)


@pytest.mark.parametrize("make, phrase", [
    (lambda: Inertia("motor", "20 kg"), "inertia 'motor': inertia '20 kg'"),
    (lambda: Inertia("motor", "-1 kg*m^2"), "must be >= 0"),
    (lambda: Gear("g", "a", "b", 0), "gear 'g': ratio must not be 0"),
    (lambda: Drum("d", "a", "b", "0.5 m/s"), "drum 'd': radius"),
    (lambda: ElasticLink("e", "a", "b", 0), "elastic link 'e': stiffness must be > 0"),
    (lambda: ElasticLink("e", "a", "b", 1, contact="middle"), "contact must be"),
    (lambda: Brake("b", "a", "1 kN*m", build_up="linear"), "brake 'b': build_up"),
    (lambda: Brake("b", "a", "1 kN*m", build_up="ramp"), "time of its ramp must be > 0"),
    (lambda: Inertia("2x", 1.0), "inertia name"),
    (lambda: Motor("m", "a", "__import__('os')"), "motor 'm': torque"),
])
def test_component_values_are_checked_on_construction(make, phrase):
    with pytest.raises(ComponentError) as info:
        make()
    assert phrase in str(info.value) and "\n" not in str(info.value)


def test_a_consistent_gear_loop_is_accepted():
    parts = base() + [Inertia("a", 1.0), Inertia("b", 1.0), Inertia("c", 1.0),
                      Gear("g1", "a", "b", 2), Gear("g2", "b", "c", 3), Gear("g3", "a", "c", 6),
                      ElasticLink("e", "motor", "a", 1e4)]
    model = Model(parts)
    assert [g.name for g in model.assembly.groups] == ["motor", "drum", "a"]
    assert dict((b.name, k) for b, k in model.assembly.groups[2].members)["c"] == \
        pytest.approx(1 / 6)
