"""Files only where asked: without ``--out`` (or ``-o``) a command prints its
results, writes nothing into the folder it runs in, and says in one line how
to get the files (README, "Files a command writes")."""
from __future__ import annotations

import json
from pathlib import Path

import pytest

from crane_sym.cli.main import main

EXAMPLES = Path(__file__).resolve().parents[1] / "examples" / "drive_trains"


def test_run_json_of_a_component_file_leaves_an_empty_folder_empty(tmp_path, monkeypatch,
                                                                   capsys):
    monkeypatch.chdir(tmp_path)
    assert main(["run", str(EXAMPLES / "hoist_fig9.toml"), "--format", "json", "-q"]) == 0
    captured = capsys.readouterr()
    assert list(tmp_path.iterdir()) == []
    data = json.loads(captured.out)                 # stdout stays pure JSON
    assert data["files"] == [] and data["results"]
    assert captured.err.strip().splitlines()[-1] == (
        "no files written: add --out DIR to write the JSON, the module of its loads "
        "and the plot")


def test_run_of_a_scene_prints_and_writes_nothing(tmp_path, monkeypatch, capsys):
    monkeypatch.chdir(tmp_path)
    assert main(["run", "overhead_crane_50t", "-q"]) == 0
    out = capsys.readouterr().out
    assert list(tmp_path.iterdir()) == []
    assert "scene overhead_crane_50t" in out and "module written" not in out
    assert out.strip().splitlines()[-1] == (
        "no files written: add --out DIR to write the scene's module and its plots")


def test_generate_scene_prints_the_module_and_writes_nothing(tmp_path, monkeypatch, capsys):
    monkeypatch.chdir(tmp_path)
    assert main(["generate", "--scene", "overhead_crane_50t", "-q"]) == 0
    captured = capsys.readouterr()
    assert list(tmp_path.iterdir()) == []
    assert captured.out.startswith('"""') and "def " in captured.out
    assert "add --out DIR" in captured.err


def test_bench_without_out_prints_and_writes_nothing(tmp_path, monkeypatch, capsys):
    monkeypatch.chdir(tmp_path)
    assert main(["bench", "--components", str(EXAMPLES / "hoist_fig9.toml"), "-q"]) == 0
    out = capsys.readouterr().out
    assert list(tmp_path.iterdir()) == []
    assert "| hoist_fig9 |" in out and "wrote" not in out
    assert out.strip().splitlines()[-1].startswith("no files written: add --out DIR")


@pytest.mark.harm("one-line")      # it ended in nothing at all, not in its result
def test_bench_components_json_prints_the_rows_and_writes_nothing(tmp_path, monkeypatch,
                                                                   capsys):
    """`bench --components FILE --format json`: stdout is the JSON of the model's
    stages and targets (it was empty), the hint on stderr, no file."""
    monkeypatch.chdir(tmp_path)
    assert main(["bench", "--components", str(EXAMPLES / "hoist_fig9.toml"), "--format",
                 "json", "-q"]) == 0
    captured = capsys.readouterr()
    (row,) = json.loads(captured.out)
    assert row["model"] == "hoist_fig9" and row["phases"] >= 30
    assert row["stages_seconds"] and all(s >= 0 for s in row["stages_seconds"].values())
    assert [t["target"] for t in row["targets"]] == ["derive and solve (s)",
                                                      "run of >= 30 phases (s)"]
    assert list(tmp_path.iterdir()) == []
    assert captured.err.strip() == ("no files written: add --out DIR to write the Markdown "
                                    "and PNG files")


def test_walkthrough_without_o_prints_and_writes_nothing(tmp_path, monkeypatch, capsys):
    monkeypatch.chdir(tmp_path)
    assert main(["walkthrough", str(EXAMPLES / "hoist_fig9.toml"), "-q"]) == 0
    captured = capsys.readouterr()
    assert list(tmp_path.iterdir()) == []
    assert captured.out.startswith("#")
    assert captured.err.strip() == "no files written: add -o FILE to write it to a file"
