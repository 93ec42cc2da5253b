"""The designs of a template share what rests on its structure alone
(``crane_sym.components.layout``), and a block's runs are built apart from
their solve (``Designs.runs``): the same runs, tables and numbers as a
design built on its own."""
from __future__ import annotations

from dataclasses import replace
from pathlib import Path

import numpy as np

from crane_sym.bench import design_targets
from crane_sym.components.designs import designs
from crane_sym.components.hybrid import ComponentSystem
from crane_sym.components.layout import layout

ROOT = Path(__file__).resolve().parents[1]
FILE = ROOT / "examples" / "drive_trains" / "bridge_travel.toml"


def test_designs_of_one_template_share_one_layout_and_build_the_same_tables():
    """Two designs of the 5-body file: one Layout object between them and
    the file's model; each design's tables equal those a system built
    without the shared layout has (its kinds' parts, columns, events and
    rules), and its parts are its own."""
    found = designs(FILE)
    one = found.design({"drive_line.stiffness": 200.0})
    two = found.design({"drive_line.stiffness": 300.0, "trolley_drive.stiffness": 2e6})
    assert layout(one.equations) is layout(two.equations) is layout(found.model.equations)
    first, second = ComponentSystem(one.equations), ComponentSystem(two.equations)
    assert first.rules is second.rules and first.columns == second.columns
    assert first.events == second.events and first.events is not second.events
    drive = [l.part for l in first.of_kind["elastic"]]
    assert [p.name for p in drive] == ["drive_line", "trolley_drive"]
    assert drive[0].stiffness != second.of_kind["elastic"][0].part.stiffness
    for events, table, parts in first.switching:
        for i, load in enumerate(parts):
            for name, key in events.names(load.part):
                assert first.rules[name] == (events.rules[key], i)


def test_a_design_starts_with_its_runs_system_and_the_same_state():
    """``Model.started`` (the start's system kept for the run) gives the mode,
    state and numbers of ``Model.start`` with a system built afresh."""
    model = designs(FILE).design({"drive_line.stiffness": 220.0})
    f = designs(FILE).file
    mode, x0, system = model.started(f.body, f.speed, f.rest)
    mode2, x2, extra = model.start(f.body, f.speed, f.rest)
    fresh = ComponentSystem(model.equations, extra)
    assert mode == mode2 and np.array_equal(x0, x2) and extra == {}
    for a, b in zip(system.matrices(mode), fresh.matrices(mode)):
        assert np.array_equal(a, b)
    assert model.schedule(f.rest) == tuple(sorted(model.schedule(f.rest)))


def test_a_blocks_runs_are_what_it_solves_and_the_row_times_them(monkeypatch):
    """``Designs.runs`` of a 2 × 2 block: four runs, one shape, a reference
    per design for a factor (the link's given 300 N·m); the bench row times
    their building apart and says so in its Markdown."""
    found = designs(FILE)
    values = {"drive_line.stiffness": np.array([150.0, 350.0])[:, None],
              "trolley_drive.stiffness": np.array([1e6, 3e6])[None, :]}
    shape, runs, reference = found.runs("drive_line.factor", values)
    assert shape == (2, 2) and len(runs) == 4 and reference.shape == (4,)
    assert np.array_equal(reference, np.full(4, 300.0))
    assert len({id(r.system) for r in runs}) == 4
    monkeypatch.setattr(design_targets, "PROFILE_DESIGNS", 4)
    row = design_targets.file_row(replace(design_targets.FILE_CASES[0], n=2), ROOT)
    assert row["construction"]["designs"] == 4 and row["construction"]["seconds"] > 0
    assert "designs built, not solved" in "\n".join(design_targets.markdown_rows([row]))
