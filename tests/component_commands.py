"""A component file through the command line, as the tests of a new kind use
it: its sweep, the stored grid read back, and its walkthrough's text."""
from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest

from crane_sym.cli.main import main


def swept(path: Path, axis: str, output: str, out: Path, capsys) -> tuple[dict, np.ndarray,
                                                                          np.ndarray]:
    """``crane-sym sweep path --vary axis --output output --format json``: its
    JSON, the axis's values and the output's (SI) from the stored dataset."""
    xr = pytest.importorskip("xarray")
    code = main(["sweep", str(path), "--vary", axis, "--output", output, "--out", str(out),
                 "--format", "json", "-q"])
    text = capsys.readouterr().out
    assert code == 0, text
    data = json.loads(text)
    stored = xr.open_zarr(data["dataset"]).load()
    return data, stored[axis.split("=")[0]].values, stored[output].values


def walkthrough(path: Path, out: Path) -> str:
    """``crane-sym walkthrough path -o out/page.md``: the page's text."""
    page = out / "page.md"
    assert main(["walkthrough", str(path), "-o", str(page), "-q"]) == 0
    return page.read_text(encoding="utf-8")
