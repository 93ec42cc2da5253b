"""Files a command writes (crane_sym.output_files): inside the folder named,
whole or not at all, a symlink at a target replaced and never followed."""
import os

import pytest

from crane_sym.output_files import (OutputError, check_folder, out_file, out_folder, staged,
                                    write_text)


def test_a_symlink_at_the_target_is_replaced_not_followed(tmp_path):
    outside = tmp_path / "outside.txt"
    outside.write_text("keep me")
    out = tmp_path / "out"
    out.mkdir()
    (out / "result.py").symlink_to(outside)
    write_text(out, "result.py", "new")
    assert outside.read_text() == "keep me"
    assert not (out / "result.py").is_symlink()
    assert (out / "result.py").read_text() == "new"


def test_a_failure_inside_the_stage_leaves_nothing(tmp_path):
    (tmp_path / "a.txt").write_text("old")
    with pytest.raises(RuntimeError):
        with staged(tmp_path) as stage:
            stage.text("a.txt", "new")
            stage.text("b.txt", "new")
            raise RuntimeError("boom")
    assert sorted(p.name for p in tmp_path.iterdir()) == ["a.txt"]
    assert (tmp_path / "a.txt").read_text() == "old"


def test_keyboard_interrupt_inside_the_stage_leaves_nothing(tmp_path):
    with pytest.raises(KeyboardInterrupt):
        with staged(tmp_path) as stage:
            stage.text("a.txt", "new")
            raise KeyboardInterrupt
    assert list(tmp_path.iterdir()) == []


def test_files_of_one_stage_land_together(tmp_path):
    with staged(tmp_path) as stage:
        stage.text("a.txt", "1")
        folder = stage.path("data.zarr")
        folder.mkdir()
        (folder / "x").write_text("2")
        assert not (tmp_path / "a.txt").exists()          # nothing before the end
    assert (tmp_path / "a.txt").read_text() == "1"
    assert (tmp_path / "data.zarr" / "x").read_text() == "2"
    with staged(tmp_path) as stage:                       # a folder replaced whole
        folder = stage.path("data.zarr")
        folder.mkdir()
        (folder / "y").write_text("3")
    assert sorted(p.name for p in (tmp_path / "data.zarr").iterdir()) == ["y"]
    assert sorted(p.name for p in tmp_path.iterdir()) == ["a.txt", "data.zarr"]


def test_temporary_names_are_unique(tmp_path):
    with staged(tmp_path) as one, staged(tmp_path) as two:
        assert one.path("a.png", ".png") != two.path("a.png", ".png")


@pytest.mark.parametrize("name", ["../x", "a/b", "", ".."])
def test_only_plain_names(tmp_path, name):
    with pytest.raises(ValueError, match="plain file name"):
        with staged(tmp_path) as stage:
            stage.text(name, "x")


def test_folder_errors_name_the_option(tmp_path, monkeypatch):
    afile = tmp_path / "f"
    afile.write_text("")
    with pytest.raises(OutputError, match=r"^--out '.*f' is a file, not a folder$"):
        check_folder(afile)
    with pytest.raises(OutputError, match="is a file"):
        out_folder(afile / "sub")
    with pytest.raises(OutputError, match=r"^-o '.*' is a folder; give a file name$"):
        out_file(tmp_path)
    with pytest.raises(OutputError, match="does not exist"):
        out_file(tmp_path / "no" / "such.md")
    assert check_folder(tmp_path / "new" / "deeper") == tmp_path / "new" / "deeper"
    assert not (tmp_path / "new").exists()                # checked, not made
    monkeypatch.setattr(os, "access", lambda *a, **k: False)
    with pytest.raises(OutputError, match="not writable"):
        check_folder(tmp_path / "x")


def test_an_os_error_while_writing_becomes_one_line(tmp_path, monkeypatch):
    def full(*args, **kwargs):
        raise OSError(28, "No space left on device")
    monkeypatch.setattr(os, "replace", full)
    with pytest.raises(OutputError, match=r"^--out '.*': cannot write \(no space left on the "
                                          r"device\)$"):
        write_text(tmp_path, "a.txt", "x")
    assert list(tmp_path.iterdir()) == []
