"""``bench --fast-paths`` on small arrays: every timed paper's functions
against np.cos with the hand-written floor beside ramp_hold, the memory rows,
targets met or not, and the section alone from the command line. No timing
is asserted."""
import pytest

pytest.importorskip("scipy")

from crane_sym.bench import fast_paths as fp  # noqa: E402
from crane_sym.bench.targets import HAND  # noqa: E402
from crane_sym.cli import bench as cli_bench  # noqa: E402


@pytest.fixture(scope="module")
def result():
    # the piecewise targets are read at 1e5 points, so the run uses them
    return fp.fast_paths(["hoist_startup", "drum_drive"], points=10**5, memory_points=4000)


def test_inputs_of_a_paper_without_timed_scenes_are_none():
    found = fp.bench_inputs("hoist_startup")
    assert found is not None
    d, chosen, values, duration = found
    assert chosen and duration > 0 and d.id == "hoist_startup"


def test_ramp_hold_timed_beside_its_hand_written_floor(result):
    rows = result["arrays"]["hoist_startup"]
    kinds = {k for f, k, n, w, c in rows if f == "dynamic_coefficient_ramp_hold"}
    assert kinds == {"piecewise", HAND}
    assert all(n == 10**5 and w > 0 and c > 0 for f, k, n, w, c in rows)


def test_targets_name_the_floor_and_the_memory(result):
    targets = {(g.paper, g.target) for g in result["goals"]}
    assert ("hoist_startup", "piecewise at 1e5, warm, against by hand (time ratio)") in targets
    assert any(p == "drum_drive" and "peak memory" in t for p, t in targets)
    chains = {r.function for rows in result["memory"].values() for r in rows}
    assert {"dynamic_coefficient_ramp", "optimal_coefficient_from_weight_a4",
            "pulsating_force"} <= chains


def test_markdown_says_met_or_not_and_the_load(result):
    text = fp.markdown(result)
    assert "load average" in text and "## Targets" in text
    assert ("| met |" in text or "NOT MET" in text)
    assert "hand-written NumPy" in text and "drum_drive: peak memory" in text


def test_the_section_alone_from_the_command_line(monkeypatch, capsys):
    called = []
    monkeypatch.setattr(fp, "fast_paths", lambda ids: called.append(ids) or {
        "arrays": {}, "memory": {}, "goals": [], "points": 1, "memory_points": 1,
        "load_before": 0.0, "load_after": 0.0})
    from crane_sym.cli.main import main
    assert main(["bench", "--fast-paths", "--quiet"]) == 0
    assert len(called) == 1 and "# Bench: fast paths" in capsys.readouterr().out
    assert cli_bench is not None
