"""The bench command on a small grid: rows for every function and method,
errors that mean what they say."""
import json

import pytest

pytest.importorskip("scipy")

from crane_sym import bench, registry, scenes  # noqa: E402
from crane_sym.cli import main  # noqa: E402


@pytest.fixture(scope="module")
def rows():
    scene = scenes.load_scene("overhead_crane_50t")
    return bench.bench(registry.get("travel_braking"), scene.parameters, 0.5, points=60,
                       reference_points=20, methods=("DOP853", "Radau"), rtols=(1e-3, 1e-10))


def test_every_generated_function_has_a_row_with_its_error(rows):
    d = registry.get("travel_braking")
    generated = {r.function: r for r in rows if r.method == "generated"}
    assert set(generated) == {o.name for o in d.outputs}
    assert all(r.max_rel_error <= 2e-15 for r in generated.values())


def test_integrators_on_both_coordinate_systems_and_tolerances(rows):
    force = [r.method for r in rows if r.function == "elastic_force"]
    for system in ("absolute coordinates", "relative coordinate"):
        for method in ("DOP853 rtol=0.001", "Radau rtol=1e-10", "odeint rtol=1e-10"):
            assert any(m.startswith(method) and system in m for m in force), (method, system)
    loose = [r for r in rows if r.function == "elastic_force" and "rtol=0.001" in r.method]
    tight = [r for r in rows if r.function == "elastic_force" and "DOP853 rtol=1e-10" in r.method]
    assert min(r.max_error_over_peak for r in loose) > max(r.max_error_over_peak for r in tight)


def test_bench_command_json(tmp_path, capsys):
    assert main(["bench", "000", "--format", "json", "--out", str(tmp_path), "--points", "40",
                 "--throughput-points", "1000"]) == 0
    data = json.loads(capsys.readouterr().out)
    assert {"function", "method", "seconds", "points", "max_rel_error"} <= set(data[0])
    assert (tmp_path / "bench_travel_braking.md").read_text().startswith("# Bench")
    assert (tmp_path / "bench_travel_braking.png").read_bytes()[:4] == b"\x89PNG"
