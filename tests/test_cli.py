"""The command line as a user meets it: regeneration from nothing, --check by
name, --version, --help, progress on stderr only, the accuracy verdict, list."""
from __future__ import annotations

import contextlib
import fcntl
import importlib.util
import io
import json
import os
import re
import shlex
import sys
from importlib import metadata
from pathlib import Path

import pytest

from crane_sym import progress, registry
from crane_sym.scenes import generate
from crane_sym.codegen import files as module_files
from crane_sym.bench import accuracy as reference
from crane_sym.cli.main import main, parser
from crane_sym.registry import EXAMPLES

ROOT = Path(__file__).resolve().parents[1]


class _Terminal(io.StringIO):
    """A captured stderr that says it is a terminal (progress is shown there)."""

    def isatty(self) -> bool:
        return True


@pytest.fixture(scope="module")
def written(tmp_path_factory) -> tuple[Path, str, str]:
    """`crane-sym generate --out DIR` into a folder that does not exist yet, run
    once for the whole test run (a full regeneration is the slowest command
    there is): the folder, stdout and stderr (a terminal's). pytest-xdist's
    workers share it: the first to take the lock regenerates, the others wait
    and read what it left."""
    run = tmp_path_factory.getbasetemp()         # a worker's: popen-gwN in the run's
    shared = (run.parent if os.environ.get("PYTEST_XDIST_WORKER") else run) / "cli_generate"
    shared.mkdir(exist_ok=True)
    out, streams = shared / "generated", shared / "streams.json"
    with open(shared / "lock", "w") as lock:
        fcntl.flock(lock, fcntl.LOCK_EX)
        if not streams.exists():
            stdout, stderr = io.StringIO(), _Terminal()
            with contextlib.redirect_stdout(stdout), contextlib.redirect_stderr(stderr):
                code = main(["generate", "--out", str(out)])
            assert code == 0, stderr.getvalue()
            streams.write_text(json.dumps([stdout.getvalue(), stderr.getvalue()]),
                               encoding="utf-8")
    stdout, stderr = json.loads(streams.read_text(encoding="utf-8"))
    return out, stdout, stderr


@pytest.fixture(scope="module")
def files(written) -> dict[str, str]:
    """Everything `crane-sym generate` wrote, by file name."""
    return {p.name: p.read_text(encoding="utf-8") for p in sorted(written[0].iterdir())}


def _terminal(monkeypatch) -> None:
    """stderr (pytest's capture, active only inside the test body) pretends to
    be a terminal."""
    monkeypatch.setattr(sys.stderr, "isatty", lambda: True)


# --- 3. Regeneration -----------------------------------------------------------

def test_generate_writes_an_empty_folder_in_full(written, files, monkeypatch, capsys):
    """Every file the committed generated/ holds, nothing else, the same bytes;
    progress on stderr only; and --check of that folder says it is fresh."""
    out, stdout, stderr = written
    committed = module_files.default_directory()
    assert sorted(files) == sorted(p.name for p in committed.iterdir() if p.is_file())
    assert all((committed / n).read_text(encoding="utf-8") == t for n, t in files.items())
    assert f"wrote {out / '__init__.py'}" in stdout
    # progress went to stderr, per derivation and per scene (in one process or in
    # several, as each paper comes back)
    assert "printing travel_braking.py" in stderr or "printed travel_braking.py" in stderr
    assert "specializing scene overhead_crane_50t" in stderr \
        or "specialized scenes overhead_crane_50t" in stderr
    assert "wrote" not in stderr and "printing" not in stdout
    # --check against this folder (what the derivations produce is `files`: the
    # regeneration itself is the fixture's, and CI's `generate --check`)
    monkeypatch.setattr(generate, "all_files", lambda: files)
    assert main(["generate", "--check", "--out", str(out)]) == 0
    assert capsys.readouterr().out.strip() == f"{out} is up to date ({len(files)} files)"


def test_default_directory_is_found_without_the_package(monkeypatch):
    """No generated/__init__.py (or no generated/ at all): the clone's folder."""
    assert module_files.default_directory() == ROOT / "generated"
    monkeypatch.setattr(importlib.util, "find_spec", lambda name: None)
    assert module_files.default_directory() == ROOT / "generated"


def _spoil(folder: Path, how: str) -> str:
    """Make ``folder`` (a fresh copy of generated/) wrong in one way; return the
    file name that --check must name."""
    if how == "missing":
        (folder / "__init__.py").unlink()
        return "__init__.py"
    if how == "stale":
        with open(folder / "hoist_startup.py", "a", encoding="utf-8") as f:
            f.write("# edited by hand\n")
        return "hoist_startup.py"
    (folder / "old_paper.py").write_text("x = 1\n", encoding="utf-8")
    return "old_paper.py"


@pytest.mark.parametrize("how", ["missing", "stale", "stray"])
def test_check_names_missing_stale_and_stray_files(how, tmp_path, files, monkeypatch, capsys):
    folder = tmp_path / "generated"
    module_files.write(files, folder)
    (folder / "__pycache__").mkdir()             # not a stray: not a .py file
    name = _spoil(folder, how)
    monkeypatch.setattr(generate, "all_files", lambda: files)
    assert main(["generate", "--check", "--out", str(folder)]) == 1
    captured = capsys.readouterr()
    assert captured.out.splitlines() == [f"{how}: {folder / name} " + {
        "missing": "is not there",
        "stale": "differs from what the derivations produce",
        "stray": "is not produced by any derivation or scene"}[how]]
    counts = {k: int(n) for n, k in re.findall(r"(\d+) (missing|stale|stray)", captured.err)}
    assert counts == {k: int(k == how) for k in ("missing", "stale", "stray")}
    found = module_files.compare(files, folder)
    assert not found.ok and module_files.stale(files, folder) == ([] if how == "stray" else [name])


def test_shipped_generated_folder_is_fresh_and_has_no_stray_file(files):
    assert module_files.compare(files, module_files.default_directory()).ok


# --- 7. The command line ---------------------------------------------------------

def test_version_comes_from_the_package_metadata(capsys):
    with pytest.raises(SystemExit) as done:
        main(["--version"])
    assert done.value.code == 0
    assert capsys.readouterr().out.strip() == f"crane-sym {metadata.version('crane_sym')}"


def _help(argv: list[str], capsys) -> str:
    with pytest.raises(SystemExit):
        main(argv + ["--help"])
    return capsys.readouterr().out


def test_help_is_plain_text_with_an_example_per_command(capsys):
    top = _help([], capsys)
    assert "``" not in top and "crane_sym:" not in top
    commands = parser()._subparsers._group_actions[0].choices
    assert set(commands) == set(EXAMPLES)
    for name in commands:
        text = _help([name], capsys)
        assert "``" not in text, name
        example = text.split("example", 1)[1]
        assert f"crane-sym {name}" in example, name


def test_list_shows_authors_and_title_not_the_file(capsys):
    assert main(["list"]) == 0
    out = capsys.readouterr().out
    assert "Yuriy Chovnyuk, Mykhaylo Dykteruk, Svetlana Komotskaya" in out
    assert "M.P. Martyntsiv, O.M. Udovytskyi, B.V. Sologub" in out
    assert ".txt" not in out
    for i in registry.ids():
        assert registry.module(i).TITLE in out
    assert main(["list", "--format", "json"]) == 0
    rows = json.loads(capsys.readouterr().out)
    assert [r["authors"] for r in rows] == [list(registry.module(i).AUTHORS)
                                            for i in registry.ids()]
    # in Latin letters (transliterated from Cyrillic; a German ö stays an ö)
    assert all(r["authors"] and not any(re.search("[А-Яа-яЁёІіЇїЄєҐґ]", a)
                                        for a in r["authors"]) for r in rows)


def test_list_scenes_names_every_shipped_scene_and_its_paper(capsys):
    from crane_sym.scenes.reading import list_scenes
    assert main(["list", "--scenes", "--format", "json"]) == 0
    rows = json.loads(capsys.readouterr().out)
    assert [r["name"] for r in rows] == list_scenes()
    assert {r["derivation"] for r in rows} <= set(registry.ids())
    assert main(["list", "--scenes"]) == 0
    lines = capsys.readouterr().out.splitlines()
    assert [line.split()[:2] for line in lines] == [[r["name"], r["derivation"]] for r in rows]


def test_every_name_in_an_example_can_be_listed(capsys):
    """The papers and scenes an example names are ones `crane-sym list` shows,
    and its help says so."""
    from crane_sym.scenes.reading import list_scenes
    papers, scenes = set(registry.ids()) | set(registry.ALIASES), set(list_scenes())
    for name, example in EXAMPLES.items():
        named = []
        for command in example.replace("\\\n", " ").split("\n"):
            args = vars(parser().parse_args(shlex.split(command.split(">")[0])[1:]))
            named += [(w, papers) for w in args.get("ids", []) if not w.endswith(".toml")]
            named += [(args[k], papers) for k in ("id",) if k in args
                      and not args[k].endswith(".toml")]
            named += [(args[k], scenes) for k in ("scene",) if args.get(k)
                      and not args[k].endswith(".toml")]
            files = [args[k] for k in ("scene", "file", "id")
                     if str(args.get(k, "")).endswith(".toml")]
            files += [w for w in args.get("ids", []) if w.endswith(".toml")]
            assert all((Path(__file__).parents[1] / f).is_file() for f in files), files
        assert [w for w, known in named if w not in known] == [], name
        if named:
            assert "crane-sym list" in _help([name], capsys).split("example", 1)[1], name


@pytest.mark.parametrize("terminal, argv", [
    (False, ["audit", "000", "--format", "json"]),
    (True, ["audit", "000", "--format", "json", "--quiet"]),
    (True, ["-q", "audit", "000", "--format", "json"])])
def test_progress_is_silent_off_a_terminal_and_with_quiet(terminal, argv, capsys,
                                                          monkeypatch):
    if terminal:                                # --quiet wins over a terminal
        _terminal(monkeypatch)
    assert sys.stderr.isatty() == terminal
    assert main(argv) == 0
    captured = capsys.readouterr()
    assert captured.err == ""
    assert len(json.loads(captured.out)) == len(registry.get("travel_braking").published)


def test_progress_goes_to_stderr_on_a_terminal(capsys, monkeypatch):
    _terminal(monkeypatch)
    assert main(["audit", "000", "--format", "json"]) == 0
    captured = capsys.readouterr()
    assert "building travel_braking" in captured.err
    assert "auditing travel_braking (16 printed formulas)" in captured.err
    assert "checking printed formula (14)" in captured.err
    json.loads(captured.out)                     # stdout is still clean JSON


@pytest.mark.parametrize("quiet", [False, True])
def test_run_shows_its_stages_on_a_terminal(quiet, tmp_path, capsys, monkeypatch):
    """`run` says each stage of the scene pipeline on stderr, nothing with -q."""
    _terminal(monkeypatch)
    argv = ["run", "overhead_crane_50t", "--out", str(tmp_path)] + (["-q"] if quiet else [])
    assert main(argv) == 0
    captured = capsys.readouterr()
    stages = ("reading scene overhead_crane_50t", "specializing and printing "
              "scene_overhead_crane_50t.py", "running scene overhead_crane_50t", "plotting")
    if quiet:
        assert captured.err == ""
    else:
        assert all(f"{stage}" in captured.err for stage in stages)
    assert captured.out.startswith("scene overhead_crane_50t:")


def test_progress_reports_each_step_of_a_build(capsys):
    """A derivation under construction reports each step it adds."""
    from crane_sym.derivations import travel_braking
    with progress.reporting(progress.Progress(True)):
        travel_braking.build()
    err = capsys.readouterr().err
    assert "travel_braking: step (14) done" in err and "step (1) done" in err
    travel_braking.build()                       # no reporter installed: silent
    assert capsys.readouterr().err == ""


def _fake_accuracy(excess: float):
    def fake(out, function, case, columns, tolerance=1e-15):
        return reference.AccuracyRow(out.name, case, 3, excess * 1e-15, {}, 1e-16, excess)
    return fake


@pytest.mark.parametrize("excess, code", [(0.5, 0), (1.0, 0), (1.01, 1), (float("nan"), 1)])
def test_accuracy_ends_with_a_verdict_and_its_exit_code(excess, code, capsys, monkeypatch):
    monkeypatch.setattr(reference, "accuracy", _fake_accuracy(excess))
    assert main(["accuracy", "000"]) == code
    last = capsys.readouterr().out.splitlines()[-1]
    pairs = len(registry.get("travel_braking").outputs) * \
        len(registry.module("travel_braking").hard_cases())
    if code:
        assert last.startswith(f"FAIL: {pairs} of {pairs} function/case pairs over target: ")
        assert "elastic_force (" in last
    else:
        assert last == f"PASS: all {pairs} function/case pairs within target"


@pytest.mark.parametrize("argv", [["accuracy", "999"], ["accuracy", "000", "999"],
                                  ["audit", "999"], ["walkthrough", "999"]])
def test_an_unknown_id_prints_nothing_to_stdout_and_exits_2(argv, capsys):
    """No table header before the error: ids are resolved before any output."""
    assert main(argv) == 2
    out, err = capsys.readouterr()
    assert out == ""
    assert err.startswith("crane-sym: error: unknown derivation '999'")


def test_bench_with_an_unknown_id_makes_no_folder(tmp_path, capsys):
    assert main(["bench", "999", "--out", str(tmp_path / "bench")]) == 2
    assert not (tmp_path / "bench").exists()
    assert capsys.readouterr().out == ""


def test_bench_designs_prints_its_targets_met_or_not(monkeypatch, tmp_path, capsys):
    """``bench --designs`` (section (g) alone) on grids of 3 × 3 designs, the
    profile on 9: a row per target with its limit and met / not met, where
    the time goes beside a row not met (the file's, its limit set to 0 s), the
    file's designs built alone, and its
    Markdown written only into ``--out`` (no timing asserted: timings belong
    to the bench, not to a test)."""
    from dataclasses import replace

    from crane_sym.bench import design_targets
    cases = [(paper, replace(case, block_n=3)) for paper, case in design_targets.batched_cases()
             if case.block_target is not None]
    assert cases
    monkeypatch.setattr(design_targets, "batched_cases", lambda: cases)
    monkeypatch.setattr(design_targets, "FILE_CASES",
                        tuple(replace(c, n=3, target=0.0) for c in design_targets.FILE_CASES))
    monkeypatch.setattr(design_targets, "PROFILE_DESIGNS", 9)
    out = tmp_path / "bench"
    assert main(["bench", "--designs", "--quiet", "--out", str(out)]) == 0
    text = capsys.readouterr().out
    assert "## (g) 10⁴ designs of a model from components, as a sweep runs them (issue 39)" in text
    rows = [line for line in text.splitlines() if line.startswith("| 9 designs of ")]
    assert len(rows) == 2
    assert "portal_travel peak_startup_link_force" in rows[0] and "| ≤ 1 s |" in rows[0]
    assert "bridge_travel.toml drive_line.peak" in rows[1] and "| ≤ 0 s |" in rows[1]
    assert rows[1].endswith("| not met |")              # a limit of 0 s: its profile follows
    assert all(re.search(r"\| (met|not met) \|$", row) for row in rows)
    assert all("NaN 0" in row for row in rows)
    missed = sum(row.endswith("| not met |") for row in rows)
    assert text.count("where the time goes (9 designs, cProfile") == missed >= 1
    assert "bridge_travel.toml drive_line.peak: where the time goes" in text
    assert "its 9 designs built, not solved" in text
    assert sorted(p.name for p in out.iterdir()) == ["bench_designs.md"]
