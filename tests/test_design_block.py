"""A block of designs that differ only in their links' stiffness and damping
(``crane_sym.components.design_block``, issue 39 item 3): one model, the
values as arrays, and the same numbers, bit for bit, as a model a design
(``Designs.runs``, ``sweep_outputs._designs``), on every example file that
starts at rest, on designs the batched closed forms refuse, and on 003's
start-up; what a block does not take goes the per-design way."""
from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from crane_sym.components.design_block import plain_block
from crane_sym.components.designs import designs
from crane_sym.components.parts import ComponentError
from crane_sym.mechanics.batched_runs import largest_of_runs

ROOT = Path(__file__).resolve().parents[1]
#: The example files that start at rest and whose links a block may vary.
AT_REST = ("drive_trains/bridge_travel", "drive_trains/drum_drive",
           "drive_trains/drum_drive_004", "drive_trains/hoist_drive_law_pickup",
           "drive_trains/portal_startup", "drive_trains/slack_rope",
           "drive_trains/travel_braking_000", "hard_cases/chain_8",
           "hard_cases/critical_free", "hard_cases/critical_ramp")


def _link_keys(found) -> list[str]:
    return [n for n, f in found.fields.items()
            if f.table == "elastic" and f.key in ("stiffness", "damping")]


def _both(found, output: str, values: dict):
    """(the block's result, the result of a model a design) of one block."""
    shape, block = found._block(output, values)
    assert block is not None
    _, runs, _ = found.runs(output, values)
    return block, largest_of_runs(runs, magnitude=True)


def _same(a, b) -> None:
    np.testing.assert_array_equal(a.value, b.value)
    np.testing.assert_array_equal(a.time, b.time)
    np.testing.assert_array_equal(a.phases, b.phases)
    np.testing.assert_array_equal(a.fallback, b.fallback)
    np.testing.assert_array_equal(a.capped, b.capped)


@pytest.mark.parametrize("name", AT_REST)
def test_a_block_is_bit_for_bit_a_model_a_design_on_every_example_at_rest(name):
    """Each link's stiffness and damping scaled by 0.7, 1 and 1.3 together
    (a damping of 0 stays 0): three designs, their first link's peak."""
    found = designs(ROOT / "examples" / f"{name}.toml")
    links = {l.part.name: l for l in found.design({}).assembly.links}
    values = {n: getattr(links[found.fields[n].component], found.fields[n].key) *
              np.array([0.7, 1.0, 1.3]) for n in _link_keys(found)}
    output = f"{found.links[0]}.peak"
    block, each = _both(found, output, values)
    _same(block, each)


def test_designs_the_closed_forms_refuse_are_built_alone_and_agree():
    """The 5-body file with its trolley drive damped just below, at and above
    critical (2√(k m_t)) and undamped: the designs the batched route refuses
    take their own run, built then and only then, and every number is the
    per-design-model block's."""
    found = designs(ROOT / "examples/drive_trains/bridge_travel.toml")
    critical = 2 * np.sqrt(2e6 * 40e3)
    values = {"trolley_drive.damping": np.array([critical * (1 - 1e-8), critical,
                                                 critical * (1 + 1e-6), 0.0, 1.4e3]),
              "drive_line.stiffness": np.array([150.0, 200.0, 250.0, 300.0, 350.0])}
    built = []
    design = type(found).design

    def counting(self, one):
        built.append(dict(one))
        return design(self, one)
    with pytest.MonkeyPatch.context() as mp:
        mp.setattr(type(found), "design", counting)
        shape, block = found._block("drive_line.peak", values)
    assert built and len(built) == 1 + int(block.fallback.sum())        # the first, then those alone
    _, runs, _ = found.runs("drive_line.peak", values)
    _same(block, largest_of_runs(runs, magnitude=True))
    assert block.fallback.any(), "the hard designs should reach the per-design route"


def test_what_a_block_does_not_take_goes_the_per_design_way():
    found = designs(ROOT / "examples/drive_trains/bridge_travel.toml")
    model = found.design({})
    assert plain_block(model, {("drive_line", "backlash"): np.array([0.01, 0.02])}) is None
    assert plain_block(model, {("motors", "inertia"): np.array([0.5, 0.6])}) is None
    assert plain_block(model, {}) is None
    assert plain_block(model, {("drive_line", "stiffness"): np.array([150.0, 250.0])})
    lift = designs(ROOT / "examples/drive_trains/lift_off.toml")       # a ground contact
    keys = _link_keys(lift)
    f = lift.fields[keys[0]]
    assert plain_block(lift.design({}), {(f.component, f.key): np.array([1e6, 2e6])}) is None
    steady = designs(ROOT / "examples/drive_trains/hoist_fig9.toml")  # a steady motor
    keys = _link_keys(steady)
    f = steady.fields[keys[0]]
    assert plain_block(steady.design({}), {(f.component, f.key): np.array([1e6, 2e6])}) is None


def test_a_value_that_breaks_its_sign_is_refused_by_the_designs_built_one_by_one():
    """A negative stiffness: no block is made, and the error is the one the
    designs built one by one raise, naming the field."""
    found = designs(ROOT / "examples/drive_trains/bridge_travel.toml")
    values = {"drive_line.stiffness": np.array([150.0, -5.0])}
    assert found._block("drive_line.peak", values)[1] is None
    with pytest.raises(ComponentError, match="stiffness"):
        found.largest("drive_line.peak", values)


def test_a_design_past_the_bound_on_periods_is_named_as_before():
    """Both links stiff (the bound counts periods of the slowest mode): the
    block refuses the first design past it with the message the designs
    built one by one give."""
    found = designs(ROOT / "examples/drive_trains/bridge_travel.toml")
    values = {"drive_line.stiffness": np.array([250.0, 1e12, 1e14]),
              "trolley_drive.stiffness": np.array([2e6, 1e14, 1e16])}
    messages = []
    for route in ("block", "each"):
        with pytest.MonkeyPatch.context() as mp:
            if route == "each":
                mp.setattr(type(found), "_block", lambda self, o, v: ((3,), None))
            with pytest.raises(ComponentError) as caught:
                found.largest("drive_line.peak", values)
            messages.append(str(caught.value))
    assert messages[0] == messages[1] and "drive_line.stiffness = 1e+12" in messages[0]
    assert "periods of the slowest mode" in messages[0]


def test_003s_start_up_as_a_block_is_bit_for_bit_its_designs_models():
    """C_пр and ζ swept (twin eigenvalues among them): one block, the same
    peaks as a model a design; a swept crane mass is no block."""
    from crane_sym.bench.batched import _grid
    from crane_sym.bench.cases import batched_cases
    from crane_sym.derivations.portal_travel import sweep_outputs as so
    (_, case), = [(p, c) for p, c in batched_cases() if c.block_target is not None]
    chosen, _, names, axes = _grid(case, 8)
    grids = np.meshgrid(*axes, indexing="ij")
    values = {**{k: v for k, v in chosen.fixed.items() if k in so._PARAMETERS},
              **dict(zip(names, grids))}
    assert so._block(values) is not None
    shape, runs = so._designs(values)
    each = largest_of_runs(runs, magnitude=False, max_events=so.MAX_PHASES)
    np.testing.assert_array_equal(so._peak_startup_link_force(values, {}),
                                  each.value.reshape(shape))
    heavier = dict(values, m_k=np.linspace(2e5, 3e5, grids[0].size).reshape(grids[0].shape))
    assert so._block(heavier) is None
