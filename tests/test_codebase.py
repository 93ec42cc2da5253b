"""Tests on the code base itself (STYLE.md item 10): what every paper gets for
free once it is registered.

- every step of every registered derivation is labelled and says how;
- every published formula has exactly one verdict, decided by a named check;
- every generated function (paper modules and shipped scene modules) has a
  docstring and validates each argument: NaN and a non-positive value where the
  sign forbids it raise ValueError naming the parameter, text raises TypeError;
- every scene in ``derivations/*/scenes/`` loads, generates and runs.
"""
from __future__ import annotations

import importlib
import inspect
import re

import numpy as np
import pytest

from crane_sym import registry
from crane_sym.audit.verdicts import VERDICTS, audit
from crane_sym.cli.main import main
from crane_sym.scenes.run import run_scene
from crane_sym.scenes.reading import list_scenes, load_scene, scenes_directory
from crane_sym.scenes.specialize import module_name

IDS = registry.ids()
#: An equation number "(12)" (maybe with a qualifier), or a name that starts with a letter.
LABEL = re.compile(r"\(\d+[a-z]?\).*|[^\W\d_].*")
CHECKS = {"symbolic", "numeric", "dimension", "none"}


@pytest.mark.parametrize("name", IDS)
def test_every_step_is_labelled_and_says_how(name):
    d = registry.get(name)
    assert d.steps, name
    for step in d.steps:
        assert LABEL.fullmatch(step.label), (name, step.label)
        assert step.how.strip(), (name, step.label)


@pytest.mark.parametrize("name", IDS)
def test_every_published_formula_has_one_verdict_from_a_named_check(name):
    d = registry.get(name)
    records = audit(d)
    assert [r.label for r in records] == [f.label for f in d.published]
    for record in records:
        assert record.verdict in VERDICTS, record
        assert record.method in CHECKS, record
        assert record.detail.strip(), record


def _generated_modules() -> list[str]:
    modules = [f"crane_sym.generated.{i}" for i in IDS if registry.get(i).outputs]
    return modules + [f"crane_sym.generated.{module_name(load_scene(s))[:-3]}"
                      for s in list_scenes()]


def _checked_arguments(fn) -> dict[str, str]:
    """Argument -> sign, from the ``_checked`` calls of a generated function."""
    source = inspect.getsource(fn)
    return dict(re.findall(r"_checked\('(\w+)', \w+, '(\w+)'", source))


@pytest.mark.parametrize("module_name_", _generated_modules())
def test_every_generated_function_is_documented_and_validates(module_name_):
    module = importlib.import_module(module_name_)
    assert module.__doc__ and "Generated; do not edit." in module.__doc__
    assert module.__all__
    for name in module.__all__:
        fn = getattr(module, name)
        params = [p.name for p in inspect.signature(fn).parameters.values()
                  if p.kind is p.POSITIONAL_OR_KEYWORD]
        assert fn.__doc__ and "Parameters" in fn.__doc__ and "Returns" in fn.__doc__, name
        signs = _checked_arguments(fn)
        assert list(signs) == params, (name, "every argument is checked, in order")
        for i, param in enumerate(params):
            good = [1.0] * len(params)
            for bad, error in ((float("nan"), ValueError), ("1.0", TypeError)):
                args = good.copy()
                args[i] = bad
                with pytest.raises(error, match=rf"\b{re.escape(param)}\b"):
                    fn(*args)
            if signs[param] in ("positive", "nonnegative"):
                args = good.copy()
                args[i] = -1.0
                with pytest.raises(ValueError, match=rf"\b{re.escape(param)}\b"):
                    fn(*args)


def test_every_shipped_scene_lives_in_its_papers_package():
    for name in list_scenes():
        scene = load_scene(name)
        assert scene.path.parent == scenes_directory(scene.derivation), name


@pytest.mark.parametrize("name", list_scenes())
def test_every_shipped_scene_generates_and_runs(name, tmp_path):
    """generate --scene writes the shipped module; run goes through the same
    module and returns finite numbers and a PNG."""
    assert main(["generate", "--scene", name, "--out", str(tmp_path / "gen")]) == 0
    written = (tmp_path / "gen" / f"scene_{name}.py").read_text(encoding="utf-8")
    shipped = importlib.import_module(f"crane_sym.generated.scene_{name}")
    assert written == inspect.getsource(shipped)     # bytes, as `generate --check`
    report, pngs = run_scene(name, tmp_path / "run")
    assert pngs and all(p.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n" for p in pngs)
    assert (tmp_path / "run" / f"scene_{name}.py").read_text(encoding="utf-8") == written
    # numbers; NaN only where a report documents it (an event not reached)
    assert report.values and all(isinstance(v, float) for v in report.values.values())
    assert sum(np.isfinite(v) for v in report.values.values()) >= len(report.values) / 2
    # and the command a user types: exit 0, the same module, every plot named
    assert main(["run", name, "--out", str(tmp_path / "cli")]) == 0
    assert (tmp_path / "cli" / f"scene_{name}.py").read_text(encoding="utf-8") == written
    assert sorted(p.name for p in (tmp_path / "cli").glob("*.png")) == \
        sorted(p.name for p in pngs)


def test_run_command_prints_the_report(tmp_path, capsys):
    assert main(["run", "overhead_crane_50t", "--out", str(tmp_path)]) == 0
    out = capsys.readouterr().out
    assert "scene overhead_crane_50t:" in out and "module written to" in out
    png = tmp_path / "overhead_crane_50t.png"
    assert f"1 plot written: {png}" in out and png.is_file()


@pytest.mark.parametrize("name", registry.ids())
def test_every_paper_names_its_authors_and_title(name):
    """`crane-sym list` shows them: a paper package exports AUTHORS, PAPER, TITLE."""
    module = registry.module(name)
    assert module.AUTHORS and all(a.strip() for a in module.AUTHORS), name
    assert module.PAPER.endswith(".txt") and module.TITLE, name
