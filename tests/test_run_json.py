"""``crane-sym run --format json``: every shipped scene and every example
component file prints JSON that loads, each result a number (or null) with its
unit, the warnings as a list; the text format stays the default."""
from __future__ import annotations

import json
import math
from pathlib import Path

import pytest

from crane_sym.cli.main import main
from crane_sym.scenes.reading import list_scenes

EXAMPLES = sorted((Path(__file__).resolve().parents[1] / "examples" / "drive_trains")
                  .glob("*.toml"))


def _checked(data: dict, name: str) -> None:
    assert data["scene"] == name
    assert isinstance(data["warnings"], list)
    assert all(isinstance(w, str) and w.startswith("warning:") for w in data["warnings"])
    assert data["results"], "no results"
    for key, result in data["results"].items():
        assert set(result) == {"value", "unit"}, key
        assert isinstance(result["unit"], str) and result["unit"], f"{key} has no unit"
        value = result["value"]
        assert value is None or (isinstance(value, (int, float)) and math.isfinite(value)), key


@pytest.mark.parametrize("name", list_scenes())
def test_every_shipped_scene_prints_its_results_with_units(name, tmp_path, capsys):
    assert main(["run", name, "--out", str(tmp_path), "--format", "json", "--quiet"]) == 0
    data = json.loads(capsys.readouterr().out)
    _checked(data, name)
    assert all(Path(f).is_file() for f in data["files"])


@pytest.mark.parametrize("path", EXAMPLES, ids=[p.stem for p in EXAMPLES])
def test_every_example_component_file_prints_its_results_with_units(path, tmp_path, capsys):
    assert main(["run", str(path), "--out", str(tmp_path), "--format", "json", "--quiet"]) == 0
    data = json.loads(capsys.readouterr().out)
    _checked(data, data["model"])
    timed = {k.removesuffix(".peak_time") for k in data["results"] if k.endswith(".peak_time")}
    assert timed, "no peak with its time"
    for name in timed:
        assert data["results"][f"{name}.peak_time"]["unit"] == "s"
        if "." not in name:            # a link's load; a part's value (<part>.<what>) has its own
            assert data["results"][f"{name}.peak"]["unit"] in ("N", "N*m")
        else:
            assert data["results"][f"{name}.peak"]["unit"] in ("A", "N", "N*m", "rad/s", "m/s")
    for name in {k.removesuffix(".reaction_peak") for k in data["results"]
                 if k.endswith(".reaction_peak")}:
        assert data["results"][f"{name}.reaction_peak"]["unit"] in ("N", "N*m")
        assert data["results"][f"{name}.reaction_peak_time"]["unit"] == "s"
    assert all(e["time"]["unit"] == "s" for e in data["events"])


def test_text_stays_the_default(tmp_path, capsys):
    assert main(["run", "overhead_crane_50t", "--out", str(tmp_path), "--quiet"]) == 0
    out = capsys.readouterr().out
    assert out.startswith("scene overhead_crane_50t:") and "F_max = 45.31 kN" in out
    with pytest.raises(json.JSONDecodeError):
        json.loads(out)
