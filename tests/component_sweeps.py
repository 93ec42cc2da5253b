"""A component file's sweep through the command line, its stored grid read
back: what the tests of a new kind compare with a closed form."""
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
