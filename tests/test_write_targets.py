"""Writes replace only regular files the user named (crane_sym.output_files):
a target that is, or links to, a device, a FIFO or a socket, or that is one
of the command's own inputs, is refused in one line (exit 2) and left as it
was; ``-o -`` and ``-o /dev/stdout`` print."""
from __future__ import annotations

import os
import re
import shutil
import socket
import stat
from pathlib import Path

import pytest

from crane_sym.cli.main import main
from crane_sym.output_files import OutputError, check_target, inputs, staged

#: The harm these cases guard against (tests/fault_counts.py counts them).
pytestmark = pytest.mark.harm("writes")

FILE = Path(__file__).parents[1] / "examples" / "drive_trains" / "travel_braking_000.toml"


def _device(path: Path) -> None:
    if os.geteuid() != 0:
        pytest.skip("mknod of a character device needs root")
    os.mknod(path, 0o666 | stat.S_IFCHR, os.makedev(1, 3))    # what /dev/null is


def _socket(path: Path) -> None:
    server = socket.socket(socket.AF_UNIX)
    server.bind(str(path))
    server.close()                                 # the socket file stays


def _linked_device(path: Path) -> None:
    _device(path.with_name("dev"))
    path.symlink_to(path.with_name("dev"))


#: What is at the target, how to make it, the kind the error names.
TARGETS = {"character device": (_device, "character device"),
           "FIFO": (os.mkfifo, "FIFO"),
           "socket": (_socket, "socket"),
           "link to a device": (_linked_device, "character device")}


def _state(path: Path) -> tuple:
    info = os.lstat(path)
    return info.st_mode, info.st_ino, info.st_rdev


@pytest.mark.parametrize("case", list(TARGETS))
def test_walkthrough_refuses_a_special_file(case, tmp_path, capsys):
    make, kind = TARGETS[case]
    target = tmp_path / "page.md"
    make(target)
    before = _state(target)
    assert main(["walkthrough", str(FILE), "-o", str(target), "-q"]) == 2
    err = capsys.readouterr().err
    assert re.fullmatch(rf"crane-sym: error: -o '{re.escape(str(target))}' is a {kind}, "
                        r"not a regular file; not replaced \([^\n]*\)\n", err), err
    assert _state(target) == before                # still what it was
    assert not [p for p in tmp_path.iterdir() if p.name.startswith(".")]


@pytest.mark.parametrize("spelling", ["same", "relative", "link", "hard link"])
def test_walkthrough_refuses_its_own_input(spelling, tmp_path, monkeypatch, capsys):
    source = tmp_path / "x.toml"
    shutil.copy(FILE, source)
    monkeypatch.chdir(tmp_path)
    target = {"same": source, "relative": Path("./sub/../x.toml"),
              "link": tmp_path / "link.toml", "hard link": tmp_path / "hard.toml"}[spelling]
    (tmp_path / "sub").mkdir()
    if spelling == "link":
        target.symlink_to(source)
    if spelling == "hard link":
        os.link(source, target)
    assert main(["walkthrough", str(source), "-o", str(target), "-q"]) == 2
    err = capsys.readouterr().err
    assert re.fullmatch(r"crane-sym: error: -o '[^']+' is one of this command's inputs; "
                        r"not replaced \(name another file\)\n", err), err
    assert source.read_bytes() == FILE.read_bytes()


def test_a_stage_refuses_an_input_before_any_rename(tmp_path):
    source = tmp_path / "model.json"
    source.write_text("input")
    with inputs([source, "not a file", tmp_path]):
        with pytest.raises(OutputError, match=r"^--out '.*model\.json' is one of this "
                                              "command's inputs"):
            with staged(tmp_path) as stage:
                stage.text("a.txt", "new")         # renamed first if it were not checked
                stage.text("model.json", "new")
    assert source.read_text() == "input"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["model.json"]
    check_target(source)                           # outside the block: no longer an input


def test_a_stage_refuses_a_fifo_in_the_folder(tmp_path):
    os.mkfifo(tmp_path / "out.png")
    with pytest.raises(OutputError, match=r"^--out '.*out\.png' is a FIFO, not a regular"):
        with staged(tmp_path) as stage:
            stage.bytes("out.png", b"png")
    assert stat.S_ISFIFO(os.lstat(tmp_path / "out.png").st_mode)
    assert [p.name for p in tmp_path.iterdir()] == ["out.png"]


@pytest.mark.parametrize("target", ["-", "/dev/stdout"])
def test_dash_and_dev_stdout_print(target, tmp_path, monkeypatch, capfd):
    monkeypatch.chdir(tmp_path)
    assert main(["walkthrough", str(FILE), "-o", target, "-q"]) == 0
    out = capfd.readouterr().out
    assert out.startswith("# ") and "wrote" not in out
    assert list(tmp_path.iterdir()) == []          # no file named '-'
