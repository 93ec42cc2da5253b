"""Text is data: whatever a scene's title or file name holds, the module
printed for it parses, runs nothing of it, and keeps the title whole as a
literal (SCENE_TITLE); run and generate --scene exit 0 and write only into
--out."""
import json
import os
from pathlib import Path

import pytest

from crane_sym.cli.main import main
from crane_sym.scenes.run import import_module_file
from crane_sym.scenes.reading import scene_path

TITLES = [
    'x"""; __import__("os").system("touch PWNED"); """',
    'a"""b',
    "ends with a quote\"",
    "ends with a backslash \\",
    "\\N{BULLET} escapes \\x41 \\u0041 \\n \\\\",
    "line one\nline two\r\n\ttabbed",
    "$\\frac{1}{0$ mathtext and {braces} and 'single' and ''' triple",
    "Кран 50 т — ünïcödé ✓",
]


def _scene_file(folder: Path, shipped: str, title: str, file_name: str) -> Path:
    lines = scene_path(shipped).read_text(encoding="utf-8").splitlines()
    lines = [f"title = {json.dumps(title)}" if line.startswith("title =") else line
             for line in lines]
    path = folder / file_name
    path.write_text("\n".join(lines) + "\n", encoding="utf-8")
    return path


@pytest.mark.parametrize("title", TITLES)
@pytest.mark.parametrize("shipped", ["overhead_crane_50t", "hoist_user_drive_law"])
def test_generate_scene_keeps_the_title_as_data(tmp_path, monkeypatch, shipped, title):
    monkeypatch.chdir(tmp_path)                 # where a payload would touch its file
    toml = _scene_file(tmp_path, shipped, title, 'odd "name" \\ .toml')
    out = tmp_path / "out"
    assert main(["generate", "--scene", str(toml), "--out", str(out)]) == 0
    (module_path,) = out.iterdir()
    module = import_module_file(module_path)
    assert module.SCENE_TITLE == title
    assert not (tmp_path / "PWNED").exists()
    assert "PWNED" not in os.listdir(tmp_path)
    source = module_path.read_text(encoding="utf-8")
    assert 'generate --scene FILE' in source     # an odd file name is not pasted


@pytest.mark.parametrize("title", TITLES[:3])
def test_run_keeps_the_title_as_data(tmp_path, monkeypatch, title, capsys):
    monkeypatch.chdir(tmp_path)
    toml = _scene_file(tmp_path, "overhead_crane_50t", title, "scene.toml")
    out = tmp_path / "out"
    assert main(["run", str(toml), "--out", str(out), "-q"]) == 0
    assert not (tmp_path / "PWNED").exists()
    assert sorted(p.name for p in out.iterdir()) == ["overhead_crane_50t.png",
                                                     "scene_overhead_crane_50t.py"]
    assert import_module_file(out / "scene_overhead_crane_50t.py").SCENE_TITLE == title
