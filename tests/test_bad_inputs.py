"""One validation on every path: a bad scene value gets the same error, naming
the parameter, from the library, from ``generate --scene`` and from ``run``; the
commands exit 2 and write nothing. A generated function names the arguments that
do not broadcast."""
from __future__ import annotations

import re
from pathlib import Path

import numpy as np
import pytest

from crane_sym.cli.main import main
from crane_sym.scenes.reading import load_scene, scene_path
from crane_sym.scenes.run import run_scene

BASE = scene_path("overhead_crane_50t").read_text(encoding="utf-8")

#: (case, parameter, its TOML value or None to leave it out, what the error says)
BAD = [
    ("negative mass", "m1", '"-4.4 t"', r"parameter 'm1' \(.*\) must be > 0, got '-4.4 t'"),
    ("zero mass (a division needs it)", "m1", '"0 kg"', r"'m1' \(.*\) must be > 0, got '0 kg'"),
    ("negative stiffness", "c", '"-3e6 N/m"', r"'c' \(.*\) must be > 0"),
    ("negative braking force", "P_t", '"-24 kN"', r"'P_t' \(braking force\) must be > 0"),
    ("negative speed", "v0", '"-80 m/min"', r"'v0' \(.*\) must be > 0"),
    ("wrong dimension", "c", '"3.0e6 kg"', r"'c' expects force/length .* which is mass"),
    ("unknown unit", "W", '"11 kilofoo"', r"'W': '11 kilofoo': unknown unit 'kilofoo'"),
    ("not a quantity", "P_t", '"lots"', r"'P_t': 'lots' must start with a number"),
    ("NaN", "W", '"nan N"', r"'W': 'nan N': value must be finite"),
    ("infinity", "W", '"inf N"', r"'W': 'inf N': value must be finite"),
    ("overflow", "m2", '"1e400 kg"', r"'m2': '1e400 kg': value must be finite"),
    ("a bare number has no unit", "m1", "4400", r"'m1' needs a unit of mass .* bare number"),
    ("missing", "v0", None, r"'v0' \(.*\) is missing"),
]


def _scene(tmp_path: Path, param: str, value: str | None) -> Path:
    pattern = re.compile(rf"^{re.escape(param)} = .*$", re.M)
    assert pattern.search(BASE), param
    text = pattern.sub("" if value is None else f"{param} = {value}", BASE)
    path = tmp_path / "bad.toml"
    path.write_text(text, encoding="utf-8")
    return path


@pytest.mark.parametrize("case, param, value, message", BAD, ids=[b[0] for b in BAD])
def test_every_path_rejects_a_bad_value_naming_it(case, param, value, message, tmp_path,
                                                  capsys):
    path = _scene(tmp_path, param, value)
    with pytest.raises((ValueError, KeyError, TypeError)) as library:
        load_scene(path)
    assert re.search(message, str(library.value)), str(library.value)
    with pytest.raises((ValueError, KeyError, TypeError)):
        run_scene(path, tmp_path / "lib")
    for command in (["generate", "--scene", str(path), "--out", str(tmp_path / "gen")],
                    ["run", str(path), "--out", str(tmp_path / "run")]):
        capsys.readouterr()
        assert main(command) == 2, command
        err = capsys.readouterr().err
        assert err.startswith("crane-sym: error:") and re.search(message, err), err
    for folder in ("lib", "gen", "run"):
        assert not (tmp_path / folder).exists() or not any((tmp_path / folder).iterdir())


def test_broadcast_errors_name_the_arguments():
    from crane_sym.generated.travel_braking import elastic_force
    with pytest.raises(ValueError, match=r"t \(3,\), m1 \(4,\)"):
        elastic_force(t=np.zeros(3), m1=np.full(4, 4.4e3), m2=110e3, c=3e6, P_t=24e3,
                      W=11e3)
    assert elastic_force(t=np.zeros((3, 1)), m1=np.full(4, 4.4e3), m2=110e3, c=3e6,
                         P_t=24e3, W=11e3).shape == (3, 4)
