"""The fault table: every command that writes, given what a user gets wrong or
what goes wrong around it, fails with one line naming the cause, the exit
code the command line documents, and nothing left behind in --out.

One row a case: the command line (built in a scratch folder), the line that
must appear on stderr (a regular expression over the whole of it: one line,
no traceback), the exit code, and the folder that must end up empty or
absent. Adding a command means adding its rows here. The sweep's own faults
under real signals and clusters are in ``test_sweep_faults.py``.
"""
from __future__ import annotations

import os
import re
from dataclasses import dataclass
from pathlib import Path
from typing import Callable

import pytest

from crane_sym import output_files
from crane_sym.cli.main import Terminated, main
from crane_sym.scenes.reading import scene_path

#: The harm these cases guard against (tests/fault_counts.py counts them).
pytestmark = pytest.mark.harm("one-line")


@dataclass(frozen=True)
class Fault:
    """One row: ``argv(tmp)`` is the command; ``line`` must match stderr
    whole (one line); ``code`` the exit code; ``clean(tmp)`` the paths that
    must hold nothing afterwards; ``arrange(tmp, monkeypatch)`` sets the scene."""

    argv: Callable[[Path], list[str]]
    line: str
    code: int = 2
    clean: Callable[[Path], list[Path]] = lambda tmp: [tmp / "out"]
    arrange: Callable[[Path, pytest.MonkeyPatch], None] = lambda tmp, mp: None


def _scene(tmp: Path, shipped: str, **replace: str) -> Path:
    """A copy of a shipped scene in ``tmp`` with lines starting ``key =`` replaced."""
    lines = scene_path(shipped).read_text(encoding="utf-8").splitlines()
    for key, value in replace.items():
        lines = [f"{key} = {value}" if line.split("=")[0].strip() == key else line
                 for line in lines]
    path = tmp / f"{shipped}.toml"
    path.write_text("\n".join(lines) + "\n", encoding="utf-8")
    return path


def _coefficient(tmp: Path, value: str) -> Path:
    """The shipped user drive law with its second piece's constant set to ``value``."""
    text = scene_path("hoist_user_drive_law").read_text(encoding="utf-8")
    assert "    [0.5],          # a = 0.5\n" in text
    path = tmp / "hoist_user_drive_law.toml"
    path.write_text(text.replace("    [0.5],          # a = 0.5\n", f"    [{value}],\n"),
                    encoding="utf-8")
    return path


def _file(tmp: Path, name: str = "out") -> Path:
    (tmp / name).write_text("a file, not a folder")
    return tmp / name


def _not_writable(tmp: Path, mp: pytest.MonkeyPatch) -> None:
    """A read-only folder (the tests run as root, who may write anywhere)."""
    real = os.access
    mp.setattr(os, "access", lambda p, mode, **k: False if Path(p) == tmp / "ro"
               else real(p, mode, **k))
    (tmp / "ro").mkdir()


def _interrupt_after_first_write(kind: type[BaseException]):
    """Arrange a KeyboardInterrupt (SIGINT) or Terminated (SIGTERM) raised
    right after a command's first temporary file is written."""
    def arrange(tmp: Path, mp: pytest.MonkeyPatch) -> None:
        real = output_files.Stage.write

        def write(self, name, data, suffix=""):
            real(self, name, data, suffix)
            raise kind()
        mp.setattr(output_files.Stage, "write", write)
    return arrange


def _symlinked_target(name: str):
    """A file outside --out, and a symlink to it at ``out/name``."""
    def arrange(tmp: Path, mp: pytest.MonkeyPatch) -> None:
        (tmp / "outside.txt").write_text("keep me")
        (tmp / "out").mkdir()
        (tmp / "out" / name).symlink_to(tmp / "outside.txt")
    return arrange


RUN = "overhead_crane_50t"
ONE = r"^crane-sym: error: [^\n]+\n$"

ROWS: dict[str, Fault] = {
    # --out that cannot be written
    "run --out a file": Fault(
        lambda t: ["run", RUN, "--out", str(_file(t))],
        r"^crane-sym: error: --out '.*out' is a file, not a folder\n$", clean=lambda t: []),
    "generate --scene --out a file": Fault(
        lambda t: ["generate", "--scene", RUN, "--out", str(_file(t))],
        r"^crane-sym: error: --out '.*out' is a file, not a folder\n$", clean=lambda t: []),
    "generate --out a file": Fault(
        lambda t: ["generate", "--out", str(_file(t))],
        r"^crane-sym: error: --out '.*out' is a file, not a folder\n$", clean=lambda t: []),
    "sweep --out a file": Fault(
        lambda t: ["sweep", RUN, "--vary", "m1=1:10:3", "--output", "peak_elastic_force",
                   "--out", str(_file(t))],
        r"^crane-sym: error: --out '.*out' is a file, not a folder\n$", clean=lambda t: []),
    "run --out not writable": Fault(
        lambda t: ["run", RUN, "--out", str(t / "ro" / "out")],
        r"^crane-sym: error: --out '.*ro/out': '.*ro' is not writable \(permission denied\)\n$",
        clean=lambda t: [t / "ro"], arrange=_not_writable),
    "generate --scene --out not writable": Fault(
        lambda t: ["generate", "--scene", RUN, "--out", str(t / "ro")],
        r"^crane-sym: error: --out '.*ro': '.*ro' is not writable \(permission denied\)\n$",
        clean=lambda t: [t / "ro"], arrange=_not_writable),
    "walkthrough -o a folder": Fault(
        lambda t: ["walkthrough", "000", "-o", str(t)],
        r"^crane-sym: error: -o '.*' is a folder; give a file name\n$", clean=lambda t: []),
    "walkthrough -o in a missing folder": Fault(
        lambda t: ["walkthrough", "000", "-o", str(t / "no" / "such" / "w.md")],
        r"^crane-sym: error: -o '.*w\.md': the folder '.*such' does not exist\n$",
        clean=lambda t: [t / "no"]),
    # a scene file that cannot be read
    "run a missing scene file": Fault(
        lambda t: ["run", str(t / "missing.toml"), "--out", str(t / "out")],
        r"^crane-sym: error: no scene file '.*missing\.toml'\n$"),
    "run a folder as the scene": Fault(
        lambda t: ["run", str(t / "dir.toml"), "--out", str(t / "out")],
        ONE, arrange=lambda t, mp: (t / "dir.toml").mkdir()),
    # values outside what the generated functions serve
    "run m1 = 1e-300 t": Fault(
        lambda t: ["run", str(_scene(t, RUN, m1='"1e-300 t"')), "--out", str(t / "out")],
        r"^crane-sym: error: scene 'overhead_crane_50t': parameter 'm1' \(.*\) must be "
        r"within \[0.0001, 1e\+12\] kg \(the range its generated functions serve\), "
        r"got '1e-300 t'\n$"),
    "generate --scene m1 = 1e-320 kg": Fault(
        lambda t: ["generate", "--scene", str(_scene(t, RUN, m1='"1e-320 kg"')),
                   "--out", str(t / "out")],
        r"^crane-sym: error: scene 'overhead_crane_50t': parameter 'm1' .* must be within "
        r".*, got '1e-320 kg'\n$"),
    "run a negative mass": Fault(
        lambda t: ["run", str(_scene(t, RUN, m2='"-800 kg"')), "--out", str(t / "out")],
        r"^crane-sym: error: scene 'overhead_crane_50t': parameter 'm2' .* must be > 0, "
        r"got '-800 kg'\n$"),
    # signals while writing: one line, 130 / 143, nothing half-written
    "run interrupted (SIGINT)": Fault(
        lambda t: ["run", RUN, "--out", str(t / "out")],
        r"^crane-sym: interrupted \(SIGINT\); nothing half-written is left\n$", code=130,
        arrange=_interrupt_after_first_write(KeyboardInterrupt)),
    "run terminated (SIGTERM)": Fault(
        lambda t: ["run", RUN, "--out", str(t / "out")],
        r"^crane-sym: terminated \(SIGTERM\); nothing half-written is left\n$", code=143,
        arrange=_interrupt_after_first_write(Terminated)),
    "generate --scene terminated (SIGTERM)": Fault(
        lambda t: ["generate", "--scene", RUN, "--out", str(t / "out")],
        r"^crane-sym: terminated \(SIGTERM\); nothing half-written is left\n$", code=143,
        arrange=_interrupt_after_first_write(Terminated)),
    "walkthrough -o interrupted (SIGINT)": Fault(
        lambda t: ["walkthrough", "000", "-o", str(t / "out" / "w.md")],
        r"^crane-sym: interrupted \(SIGINT\); nothing half-written is left\n$", code=130,
        arrange=lambda t, mp: ((t / "out").mkdir(),
                               _interrupt_after_first_write(KeyboardInterrupt)(t, mp))),
    # scene options and laws: checked on load, before anything is written
    "run an unknown [options] key": Fault(
        lambda t: ["run", str(_scene(t, RUN, duration='"1.5 s"\ndurration = "2 s"')),
                   "--out", str(t / "out")],
        r"^crane-sym: error: scene 'overhead_crane_50t': unknown \[options\] key 'durration'; "
        r"did you mean 'duration'\? .*\n$"),
    "run a negative simulation-only mass": Fault(
        lambda t: ["run", str(_scene(t, "drum_drive_example", m3='"-800 kg"')),
                   "--out", str(t / "out")],
        r"^crane-sym: error: scene 'drum_drive_example': \[options\] m3 \(.*\) must be a "
        r"quantity of mass .*, got '-800 kg'\n$"),
    "run z_min above z_max": Fault(
        lambda t: ["run", str(_scene(t, "fig10_shift_limits", z_min="120")),
                   "--out", str(t / "out")],
        r"^crane-sym: error: scene 'fig10_shift_limits': \[options\] z_min = 120 must be "
        r"below z_max = 100\n$"),
    "generate --scene a reach that is not a number": Fault(
        lambda t: ["generate", "--scene",
                   str(_scene(t, "portal_support_loads", largest_reach_m='"x"')),
                   "--out", str(t / "out")],
        r"^crane-sym: error: scene 'portal_support_loads': \[options\] largest_reach_m "
        r"\(.*\) must be a number in .*, got 'x'\n$"),
    "run a drive-law coefficient of 1e308": Fault(
        lambda t: ["run", str(_coefficient(t, "1e308")), "--out", str(t / "out")],
        r"^crane-sym: error: scene 'hoist_user_drive_law': \[drive_law\] "
        r"coefficients\[1\]\[0\] = 1e\+308 \(SI\) is too large: .*\n$"),
    # bench options
    "bench --points 0": Fault(
        lambda t: ["bench", "000", "--points", "0", "--out", str(t / "out")],
        r"^crane-sym: error: --points: must be an integer in 2\.\.1e7, got 0\n$"),
    "bench --rtols -1": Fault(
        lambda t: ["bench", "000", "--rtols", "-1", "--out", str(t / "out")],
        r"^crane-sym: error: --rtols: each tolerance must be in \[1e-13, 0\.1\], got -1\n$"),
    "bench --sizes 0": Fault(
        lambda t: ["bench", "000", "--sizes", "0", "--out", str(t / "out")],
        r"^crane-sym: error: --sizes: each must be an integer in 1\.\.1e8, got 0\n$"),
    # sweep options
    "sweep --limit infinite": Fault(
        lambda t: ["sweep", RUN, "--vary", "m1=1:10:3", "--output", "peak_elastic_force",
                   "--limit", "peak_elastic_force<=1e999 kN", "--out", str(t / "out")],
        r"^crane-sym: error: --limit 'peak_elastic_force<=1e999 kN': the bound must be a "
        r"finite number\n$"),
    "sweep --chunk-mib 1e-9": Fault(
        lambda t: ["sweep", RUN, "--vary", "m1=1:10:3", "--output", "peak_elastic_force",
                   "--chunk-mib", "1e-9", "--out", str(t / "out")],
        r"^crane-sym: error: --chunk-mib 1e-09: .*\n$"),
}


@pytest.mark.parametrize("case", list(ROWS))
def test_fault(case, tmp_path, monkeypatch, capsys):
    row = ROWS[case]
    monkeypatch.chdir(tmp_path)
    row.arrange(tmp_path, monkeypatch)
    code = main(row.argv(tmp_path) + ["-q"])
    err = capsys.readouterr().err
    assert code == row.code, err
    assert re.match(row.line, err), err
    for folder in row.clean(tmp_path):
        assert not folder.exists() or list(folder.iterdir()) == [], sorted(folder.iterdir())


@pytest.mark.harm("writes")
@pytest.mark.parametrize("name,argv", [
    ("scene_overhead_crane_50t.py", lambda t: ["generate", "--scene", RUN, "--out",
                                               str(t / "out")]),
    ("overhead_crane_50t.png", lambda t: ["run", RUN, "--out", str(t / "out")])])
def test_a_symlink_in_out_is_replaced_never_followed(name, argv, tmp_path, capsys):
    _symlinked_target(name)(tmp_path, None)
    assert main(argv(tmp_path) + ["-q"]) == 0
    assert (tmp_path / "outside.txt").read_text() == "keep me"
    assert not (tmp_path / "out" / name).is_symlink()
    assert not [p for p in (tmp_path / "out").iterdir() if p.name.startswith(".")]


def test_sigterm_while_the_command_line_is_imported_is_one_line(tmp_path):
    """SIGTERM during start-up (the second or two of importing SymPy and the
    command line) ends with the line and 143, as later (it ended silently, -15):
    a process delivers it to itself just as the entry point imports the
    command line."""
    import subprocess
    import sys
    child = (
        "import builtins, os, signal, sys\n"
        "from crane_sym.cli import start\n"
        "real = builtins.__import__\n"
        "def importing(name, *args, **kwargs):\n"
        "    if name == 'crane_sym.cli.main':\n"
        "        os.kill(os.getpid(), signal.SIGTERM)\n"
        "    return real(name, *args, **kwargs)\n"
        "builtins.__import__ = importing\n"
        "sys.exit(start.main(['audit', '000', '-q']))\n")
    done = subprocess.run([sys.executable, "-c", child], capture_output=True, text=True,
                          timeout=120, cwd=tmp_path,
                          env={**os.environ, "PYTHONPATH": str(Path(__file__).parents[1])})
    assert done.returncode == 143, done.stderr
    assert done.stderr == "crane-sym: terminated (SIGTERM); nothing half-written is left\n"
    assert done.stdout == "" and list(tmp_path.iterdir()) == []
