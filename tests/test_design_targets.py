"""Section (g) of ``bench --sweep`` (``crane_sym.bench.design_targets``) on
tiny grids: a row is timed, judged against its target, and a row not met says
where its time goes."""
from __future__ import annotations

from dataclasses import replace
from pathlib import Path

from crane_sym.bench import design_targets

ROOT = Path(__file__).resolve().parents[1]


def test_a_component_file_row_not_met_says_where_the_time_goes(monkeypatch):
    """A 2 × 2 grid of the 5-body file against a target of 0 s: not met,
    no NaN, its profile functions of the package with shares in (0, 1), the
    largest first, all in the Markdown."""
    monkeypatch.setattr(design_targets, "PROFILE_DESIGNS", 4)
    case = replace(design_targets.FILE_CASES[0], n=2, target=0.0)
    row = design_targets.file_row(case, ROOT)
    assert row["designs"] == 4 and row["nan"] == 0 and row["met"] is False
    assert row["seconds"] > 0 and row["load_before"] >= 0
    shares = [share for _, share in row["profile"]]
    assert row["profile"] and all(name.startswith("crane_sym.") for name, _ in row["profile"])
    assert all(0 < s < 1 for s in shares) and shares == sorted(shares, reverse=True)
    text = "\n".join(design_targets.markdown_rows([row]))
    assert "| ≤ 0 s | not met |" in text and "where the time goes" in text
    assert row["profile"][0][0] in text


def test_a_row_met_prints_no_profile_and_a_missing_file_is_skipped(tmp_path):
    row = {"name": "x", "designs": 4, "seconds": 0.1, "cpu_seconds": 0.1, "nan": 0,
           "load_before": 1.0, "load_after": 1.0, "target": 1.0, "met": True,
           "profile": [("crane_sym.a.b", 0.5)]}
    text = "\n".join(design_targets.markdown_rows([row]))
    assert "| ≤ 1 s | met |" in text and "where the time goes" not in text
    skipped = design_targets.file_row(design_targets.FILE_CASES[0], tmp_path)
    assert "not found" in skipped["skipped"]
    assert "skipped" in "\n".join(design_targets.markdown_rows([skipped]))
