"""Faults of a component file that were tracebacks: each is one line naming
the part, the value and the bound, exit 2, nothing written (a table, as
tests/test_fault_table.py is for scenes)."""
from __future__ import annotations

import re
from pathlib import Path
from typing import NamedTuple

import pytest

from crane_sym.cli.main import main

EXAMPLES = Path(__file__).parents[1] / "examples" / "drive_trains"
TRAVEL, HOIST = "travel_braking_000.toml", "hoist_rope_stretch.toml"
MAGNITUDE = r"must be 0 or of magnitude 1e-30 to 1e\+30 in SI units, got "


class Fault(NamedTuple):
    example: str
    old: str
    new: str
    line: str                      # what follows "crane-sym: error: ", a regex


#: The example, the text replaced, its replacement, the line expected.
ROWS = {
    "mass 1e308 kg": Fault(TRAVEL, 'mass = "4.4 t"', 'mass = "1e308 kg"',
                           rf"mass 'drive': mass {MAGNITUDE}'1e308 kg'"),
    "mass 1e-320 kg": Fault(TRAVEL, 'mass = "4.4 t"', 'mass = "1e-320 kg"',
                            rf"mass 'drive': mass {MAGNITUDE}'1e-320 kg'"),
    "stiffness 1e-300 N/m": Fault(TRAVEL, 'stiffness = "3.0e6 N/m"', 'stiffness = "1e-300 N/m"',
                                  rf"elastic link 'transmission': stiffness {MAGNITUDE}"
                                  r"'1e-300 N/m'"),
    "stiffness 1e40 N/m": Fault(TRAVEL, 'stiffness = "3.0e6 N/m"', 'stiffness = "1e40 N/m"',
                                rf"elastic link 'transmission': stiffness {MAGNITUDE}"
                                r"'1e40 N/m'"),
    "force 1e300 N": Fault(TRAVEL, 'force = "24 kN"', 'force = "1e300 N"',
                           rf"resistance 'brake': \w+ {MAGNITUDE}'1e300 N'"),
    "speed 1e308 rpm": Fault(HOIST, 'speed = "1500 rpm"', 'speed = "1e308 rpm"',
                             rf"run: speed {MAGNITUDE}'1e308 rpm'"),
    "reeving 1e300": Fault(HOIST, "reeving = 4", "reeving = 1e300",
                           rf"drum 'tackle': reeving {MAGNITUDE}'1e\+300'"),
    "ratio 1e-320": Fault(HOIST, "ratio = 26.2", "ratio = 1e-320",
                          rf"gear 'gearbox': ratio {MAGNITUDE}'1e-320'"),
    "TOML nested 5000 deep": Fault(TRAVEL, "[run]", "[deep]\nx = " + "[" * 5000 + "]" * 5000
                                   + "\n\n[run]",
                                   r"(\S+/)?x\.toml: not valid TOML: arrays or tables nested too "
                                   r"deep \(the reader's limit is below \d+\)"),
}
COMMANDS = {"run": ["run", "{file}", "--out", "{out}"],
            "walkthrough": ["walkthrough", "{file}", "-o", "{out}/page.md"],
            "model show": ["model", "show", "{file}"]}


#: `model show` reads no [run] table: the run's speed is not its input.
PAIRS = [(case, command) for case in ROWS for command in COMMANDS
         if (case, command) != ("speed 1e308 rpm", "model show")]


@pytest.mark.parametrize("case,command", PAIRS)
def test_one_line(case, command, tmp_path, capsys):
    row = ROWS[case]
    text = (EXAMPLES / row.example).read_text(encoding="utf-8")
    assert row.old in text
    source = tmp_path / "x.toml"
    source.write_text(text.replace(row.old, row.new, 1), encoding="utf-8")
    out = tmp_path / "out"
    argv = [a.format(file=source, out=out) for a in COMMANDS[command]]
    if command == "walkthrough":
        out.mkdir()
    code = main(argv + ([] if command == "model show" else ["-q"]))
    captured = capsys.readouterr()
    assert code == 2, captured.err
    assert re.fullmatch(rf"crane-sym: error: {row.line}\n", captured.err), captured.err
    assert captured.out == ""
    assert not out.exists() or list(out.iterdir()) == []
