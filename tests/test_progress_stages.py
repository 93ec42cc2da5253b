"""Long commands say what they are doing within seconds: the papers audited or
printed in worker processes relay their stages and steps to the parent, which
says them while it waits; a sweep says each stage (computing, drawing,
certifying). Progress goes to stderr only, stdout stays the result."""
from __future__ import annotations

import io
import re
import sys
import time
from pathlib import Path

from crane_sym import progress
from crane_sym.audit.papers import in_processes
from crane_sym.cli.main import main

FIG9 = Path(__file__).resolve().parents[1] / "examples" / "drive_trains" / "hoist_fig9.toml"


def _slow_paper(paper: str) -> str:
    """A worker's work: two stages, the second a step, a pause between them
    (what a long paper does), said through ``progress.current()``."""
    say = progress.current()
    with say.task(f"building {paper}"):
        say.step(f"{paper}: step (1) done")
        time.sleep(0.3)
    return paper.upper()


def test_the_workers_stages_reach_the_parent():
    stream = io.StringIO()
    with progress.reporting(progress.Progress(True, stream)):
        out = in_processes(_slow_paper, ["a", "b"], 2, "working",
                           lambda r: f"done {r}").results
    assert out == ["A", "B"]                                   # in the papers' order
    said = stream.getvalue()
    for paper in "ab":
        assert f"  building {paper} ..." in said and f"  {paper}: step (1) done" in said
        assert said.index(f"  building {paper} ...") < said.index(f"done {paper.upper()}")
        assert re.search(rf"  building {paper}: \d+\.\d s", said)


def test_silent_workers_say_nothing():
    stream = io.StringIO()
    with progress.reporting(progress.Progress(False, stream)):
        assert in_processes(_slow_paper, ["a", "b"], 2, "working", str).results == ["A", "B"]
    assert stream.getvalue() == ""


def test_a_sweep_says_its_stages(tmp_path, capsys, monkeypatch):
    monkeypatch.setattr(sys.stderr, "isatty", lambda: True)
    assert main(["sweep", str(FIG9), "--vary", "gearbox_mesh.stiffness=2e4:8e4:3",
                 "--output", "gearbox_mesh.peak", "--out", str(tmp_path / "out"),
                 "--format", "json"]) == 0
    captured = capsys.readouterr()
    for stage in ("computing 3 designs ...", "drawing the PNG ..."):
        assert stage in captured.err
    assert captured.out.lstrip().startswith("{")               # stdout: the JSON only



def test_a_batched_bench_case_says_each_stage():
    """`bench --sweep`'s batched rows: the first call, each run of the block, the
    per-design sample and the breakdown each say a line before they start, so a
    case of 25 s on a loaded machine is no silence (a small grid of the first
    declared case here)."""
    from dataclasses import replace

    from crane_sym.bench.batched import REPEATS, bench_batched
    from crane_sym.bench.cases import batched_cases
    paper, case = batched_cases()[0]
    case = replace(case, n=2, sample=2)
    stream = io.StringIO()
    with progress.reporting(progress.Progress(True, stream)):
        row = bench_batched(paper, case)
    said = stream.getvalue()
    stages = ["the first call (imports, the derivation) ...",
              *[f"{row['designs']} designs as one block, run {k} of {REPEATS} ..."
                for k in range(1, REPEATS + 1)],
              "the per-design loop on a sample of 2 ..."]
    if case.breakdown is not None:
        stages.append("where the batched time went (a second run) ...")
    places = [said.find(f"  {case.output}: {stage}") for stage in stages]
    assert -1 not in places and places == sorted(places), (stages, said)
