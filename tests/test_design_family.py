"""Designs of one component template solved as one family
(:mod:`crane_sym.components.design_family`: a mode's matrices, guards and
generic switches for all its designs at once) against the same designs asked
one by one (each design's own ``ComponentSystem``, the route before the
family), on a drive train with backlash, a brake that slips and sticks, a
law with pieces and a DC motor whose controller hits its torque limit; the
designs' runs take different sequences of modes."""
from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from crane_sym.components import design_family
from crane_sym.components.designs import designs
from crane_sym.components.hybrid import ComponentSystem
from crane_sym.mechanics.phase_table import HybridRun

EXAMPLE = Path(__file__).resolve().parents[1] / "examples" / "drive_trains" / "dc_hoist_pi.toml"

#: dc_hoist_pi with a coupling with backlash before its gearbox, a holding
#: brake engaged at 1.5 s on the drum, and a speed reference that ramps up,
#: holds and ramps down (three pieces): the controller hits its limit, the
#: brake stops the drum, the drum slips again and the backlash opens.
CHANGES = (
    ('name = "dc_hoist_pi"', 'name = "family_check"'),
    ('[[gear]]\nname = "gearbox"\ninput = "motor"',
     '[[inertia]]\nname = "shaft"\ninertia = "0 kg*m^2"\n\n'
     '[[elastic]]\nname = "coupling"\nbetween = ["motor", "shaft"]\n'
     'stiffness = "2e4 N*m/rad"\ndamping = "20 N*m*s/rad"\nbacklash = "2 deg"\n\n'
     '[[brake]]\nname = "holding"\nbody = "drum"\ntorque = "25 kN*m"\ndelay = "1.5 s"\n\n'
     '[[gear]]\nname = "gearbox"\ninput = "shaft"'),
    ('breakpoints = [0.0, 1.0, 100.0]\ncoefficients = [[0.0, 100.0], [100.0]]',
     'breakpoints = [0.0, 1.0, 1.3, 100.0]\n'
     'coefficients = [[0.0, 100.0], [100.0], [100.0, -200.0]]'),
)
#: Brake torques [N m] either side of what holds the drum, controller limits
#: [N m] either side of what the start-up asks.
GRID = {"holding.torque": np.array([8e3, 18e3, 25e3, 40e3])[:, None],
        "speed_loop.limit": np.array([700.0, 1000.0, 3000.0])[None, :]}


@pytest.fixture(scope="module")
def found(tmp_path_factory):
    text = EXAMPLE.read_text()
    for old, new in CHANGES:
        assert old in text
        text = text.replace(old, new)
    path = tmp_path_factory.mktemp("family") / "family_check.toml"
    path.write_text(text)
    return designs(str(path))


def _sequences(found) -> set[tuple[str, ...]]:
    """The events of each design's run, solved alone."""
    grid = dict(zip(GRID, np.broadcast_arrays(*GRID.values())))
    out = set()
    for at in np.ndindex(4, 3):
        model = found.design({name: float(v[at]) for name, v in grid.items()})
        mode, x0, system = found.start(model)
        run = HybridRun(system, mode, x0, found.duration, model.schedule(),
                        system.link_load(0))
        out.add(tuple(event for _, event, _ in run.solve().events))
    return out


@pytest.mark.parametrize("output", ["coupling.peak", "rope.peak", "armature.current.peak"])
def test_the_family_equals_the_designs_asked_one_by_one(found, monkeypatch, output):
    asked = []
    matrices = design_family.DesignFamily.matrices

    def counted(self, mode, index):
        asked.append(len(index))
        return matrices(self, mode, index)
    monkeypatch.setattr(design_family.DesignFamily, "matrices", counted)
    together = found.largest(output, GRID)
    assert asked and max(asked) > 1             # the family answered for several at once
    monkeypatch.setattr(ComponentSystem, "family", staticmethod(lambda systems: None))
    one_by_one = found.largest(output, GRID)
    assert together.shape == (4, 3) and np.all(np.isfinite(together))
    np.testing.assert_allclose(together, one_by_one, rtol=1e-12, atol=0.0)


def test_the_designs_take_different_sequences_of_modes(found):
    events = _sequences(found)
    assert len(events) >= 3
    every = {e for run in events for e in run}
    for needed in ("coupling opens", "drum rests", "drum slips -", "speed_loop limited +",
                   "speed_loop next piece"):
        assert needed in every, needed


def test_the_kinds_hooks_answer_for_every_design_as_each_alone(found):
    """The kinds' guards, the brake's capacity and rates, the slopes and the
    links' loads of every mode the designs pass through, asked of the array
    of designs, against each design asked alone (its own numbers, not the
    template's lambdified form): the same events, and numbers to 1e-12."""
    from crane_sym.components.design_arrays import (DesignArray, free_limits, mode_guards,
                                                    mode_matrices)
    from crane_sym.components.design_outputs import link_loads
    grid = dict(zip(GRID, np.broadcast_arrays(*GRID.values())))
    systems, modes = [], set()
    for at in np.ndindex(4, 3):
        model = found.design({name: float(v[at]) for name, v in grid.items()})
        mode, x0, system = found.start(model)
        run = HybridRun(system, mode, x0, found.duration, model.schedule(),
                        system.link_load(0))
        systems.append(system)
        modes |= {segment.mode for segment in run.solve().segments}
    array = DesignArray.of(systems)
    assert len(modes) >= 5
    for mode in modes:
        together = mode_guards(array, mode, lambda: mode_matrices(array, free_limits(mode)))
        A, b = design_family.DesignFamily(array).matrices(mode, np.arange(array.k))
        w, k = link_loads(array, (0,), mode)
        for d, system in enumerate(systems):
            alone = system.guards(mode)
            assert [g.name for g in alone] == [g[0] for g in together]
            for guard, (_, weights, constant, direction) in zip(alone, together):
                assert guard.direction == direction
                np.testing.assert_allclose(weights[d], guard.weights, rtol=1e-12, atol=1e-9)
                np.testing.assert_allclose(constant[d], guard.constant, rtol=1e-12, atol=1e-9)
            A1, b1 = system.matrices(mode)
            np.testing.assert_allclose(A[d], A1, rtol=1e-12, atol=1e-12 * np.abs(A1).max())
            np.testing.assert_allclose(b[d], b1, rtol=1e-12, atol=1e-12 * max(np.abs(b1).max(), 1))
            w1, k1 = system.link_load(0)(mode)
            np.testing.assert_array_equal(w[d], w1)
            assert k[d] == k1


def test_designs_are_one_family_only_where_they_share_one_template(found):
    """Designs of the file's template make one family; a model derived on its
    own (the same parts, its own equations) beside them does not, and the
    starts from rest of such a mix are refused rather than stacked."""
    from crane_sym.components.template_forms import one_template, template
    from crane_sym.components.model import Model
    from crane_sym.components.start import rest_starts
    models = [found.design({"holding.torque": v}) for v in (8e3, 25e3)]
    systems = [ComponentSystem(m.equations) for m in models]
    assert one_template(systems) and template(systems[0]) is not None
    assert isinstance(ComponentSystem.family(systems), design_family.DesignFamily)
    own = Model(models[0].components, "own")
    alone = ComponentSystem(own.equations)
    assert template(alone) is None
    assert not one_template([*systems, alone]) and not one_template([alone])
    assert ComponentSystem.family([*systems, alone]) is None
    with pytest.raises(ValueError, match="not of one template"):
        rest_starts([*models, own], [*systems, alone])


def _switched_together_and_alone(found, field, values, event, brake):
    """``event`` switched for designs of ``found`` (``field`` at ``values``,
    each twice) at once and one by one, brake ``brake``'s group moving
    forwards, backwards and at rest (some at a twist): (modes together,
    modes alone), the states checked equal."""
    from crane_sym.components.design_arrays import DesignArray
    from crane_sym.components.design_switches import switched
    models = [found.design({field: v}) for v in values] * 2
    systems = [found.start(m)[2] for m in models]
    mode, x0, _ = found.start(models[0])
    assert event in systems[0].together
    k = len(models)
    x = np.tile(x0, (k, 1))
    g = systems[0].place(systems[0].of_kind["brake"][brake])[0]
    x[:, systems[0].v(g)] = ([2.0, -2.0] + [0.0] * k)[:k]
    x[:, systems[0].q(g)] += ([0.0] * 3 + [0.3, -0.3] + [0.0] * k)[:k]
    modes, after = switched(DesignArray.of(systems), mode, event, x.copy())
    alone = []
    for d, system in enumerate(systems):
        new, state = system.switch(mode, event, 0.0, x[d].copy())
        alone.append(new)
        np.testing.assert_array_equal(after[d], state)
    return modes, alone


@pytest.mark.parametrize("event", ["motor_brakes engages", "motor_brakes ramp done",
                                   "rolling engages"])
def test_a_brakes_rule_for_the_designs_at_once_is_each_designs_own(event):
    """A brake's engaging and its ramp's end (``Events.together``) switched for
    the designs of one template at once: each design's mode and state as its
    own rule (``ComponentSystem.switch``) gives them. A ramp brake holds
    nothing as it engages, so its group slides the way it moves or is pushed."""
    bridge = designs(EXAMPLE.parent / "bridge_travel.toml")
    modes, alone = _switched_together_and_alone(bridge, "motor_brakes.torque",
                                                (1.0, 300.0, 3e4), event, 1)
    assert modes == alone
    assert len(set(modes)) >= (2 if event == "motor_brakes engages" else 1)


def test_a_step_brake_engaging_holds_the_designs_within_it_as_each_alone(found):
    """The holding brake (a step) engaging on the drum, for designs whose
    torque holds the drum's load and designs whose torque does not: the
    designs at rest held or sliding, each as its own rule says."""
    from crane_sym.components.modes import BACKWARD, FORWARD, HELD
    modes, alone = _switched_together_and_alone(found, "holding.torque",
                                                (8e3, 18e3, 25e3, 40e3), "holding engages", 0)
    assert modes == alone
    g = found.design({"holding.torque": 8e3}).assembly.place["drum"][0]
    assert {m.motion[g] for m in modes} >= {FORWARD, BACKWARD, HELD}


def test_a_blocks_systems_are_freed_by_their_reference_counts():
    """A block's designs solved together leave no reference cycle: once the
    runs are dropped, every design's system is gone without the cycle
    collector (which would otherwise walk a block's 10⁶ objects after it)."""
    import gc
    import weakref

    from crane_sym.mechanics.batched_runs import largest_of_runs
    bridge = designs(EXAMPLE.parent / "bridge_travel.toml")
    gc.collect()
    gc.disable()
    try:
        _, runs, _ = bridge.runs("drive_line.peak",
                                 {"motor_brakes.torque": np.array([150.0, 300.0, 600.0])})
        largest_of_runs(runs, magnitude=True)
        systems = [weakref.ref(r.system) for r in runs]
        models = [weakref.ref(r.output.system.equations) for r in runs]
        del runs
        assert all(s() is None for s in systems) and all(m() is None for m in models)
    finally:
        gc.enable()
