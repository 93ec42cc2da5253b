"""The fixed ground as a link's end (``between = ["ground", body]``): a mass
on a spring to the ground against its closed form, the ground's term dropped
from the twist in every place that reads a link's ends, and a file that
misuses the reserved name refused in one line, exit 2."""
from __future__ import annotations

import math
import re
from pathlib import Path

import numpy as np
import pytest
import sympy as sp

from crane_sym.cli.main import main
from crane_sym.components.component_file import read_component_file

M, C, G, LIFT = 2500.0, 4.0e6, 9.81, 0.02        # kg, N/m, m/s^2, m
OMEGA = math.sqrt(C / M)
HUNG = """
[model]
name = "hung"

[[mass]]
name = "load"
mass = "{m} kg"

[[elastic]]
name = "spring"
between = {between}
stiffness = "{c} N/m"

[[gravity]]
name = "weight"
body = "load"
g = "{g} m/s^2"

[[initial]]
name = "lifted"
body = "load"
displacement = "-{lift} m"

[run]
duration = "{duration} s"
"""


def _file(tmp_path: Path, between: str = '["ground", "load"]', **change: str) -> Path:
    path = tmp_path / "hung.toml"
    text = HUNG.format(m=M, c=C, g=G, lift=LIFT, between=between,
                       duration=1.5 * 2 * math.pi / OMEGA)
    for old, new in change.items():
        text = text.replace(old, new)
    path.write_text(text)
    return path


def test_a_mass_on_a_spring_to_the_ground_swings_about_its_weight(tmp_path):
    """x points down; lifted by a from its rest m g / c and let go, the spring
    carries m g − c a cos ωt, ω² = c/m: its peak m g + c a at π/ω."""
    read = read_component_file(_file(tmp_path))
    run = read.model.run(read.duration, read.body, read.speed, rest=read.rest)
    (peak,) = run.peaks
    assert peak.value == pytest.approx(M * G + C * LIFT, rel=1e-12)
    assert peak.time == pytest.approx(math.pi / OMEGA, rel=1e-9)
    assert peak.static == pytest.approx(M * G - C * LIFT, rel=1e-12)
    w, k = run.system.link_load(0)(run.result.segments[0].mode)
    for t in np.linspace(0.0, 3 * math.pi / OMEGA, 7):
        got = float(np.asarray(w) @ run.result.state(np.array(t)) + k)
        assert got == pytest.approx(M * G - C * LIFT * math.cos(OMEGA * t), abs=1e-9 * M * G)


def test_the_ground_is_no_coordinate_in_the_equations(tmp_path):
    """Π = c x²/2: the twist of a link to the ground is its body's coordinate
    alone (or minus it, the ground named second)."""
    for between, sign in (('["ground", "load"]', 1), ('["load", "ground"]', -1)):
        eq = read_component_file(_file(tmp_path, between)).model.equations
        (x,) = eq.coordinates
        assert eq.coordinates == (x,) and len(eq.twists) == 1
        assert sp.simplify(eq.twists[0] - sign * x) == 0
        c = sp.Symbol("c_spring", positive=True)
        assert sp.simplify(eq.V - c * x**2 / 2) == 0


@pytest.mark.parametrize("between,change,line", [
    ('["ground", "ground"]', {}, r"elastic link 'spring' joins the ground to itself"),
    ('["ground", "load"]', {'name = "load"': 'name = "ground"', 'body = "load"': 'body = "ground"'},
     r"mass name 'ground' is reserved for the fixed end a link may name in 'between'; call "
     r"the body something else"),
    ('["ground", "load"]', {'body = "load"\ng': 'body = "ground"\ng'},
     r"gravity 'weight' names unknown body 'ground'.*"),
])
def test_the_reserved_name_is_refused_in_one_line(tmp_path, capsys, between, change, line):
    code = main(["run", str(_file(tmp_path, between, **change)), "-q"])
    err = capsys.readouterr().err
    assert code == 2, err
    assert re.fullmatch(rf"crane-sym: error: (component model 'hung': )?{line}\n", err), err


def test_a_grounded_body_cannot_start_at_a_steady_speed(tmp_path, capsys):
    path = _file(tmp_path)
    path.write_text(path.read_text().replace("[run]\n", '[run]\nspeed = "1 m/s"\n'))
    code = main(["run", str(path), "-q"])
    err = capsys.readouterr().err
    assert code == 2, err
    assert re.fullmatch(r"crane-sym: error: (component model 'hung': )?start: elastic link "
                        r"'spring' holds a body to the ground, which cannot move at the "
                        r"steady speed 1 of mass 'load'; start at speed 0\n", err), err
