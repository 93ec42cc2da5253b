"""`crane-sym walkthrough FILE`: the derivation of a component model as a
handout. Its equations are the model's (the LaTeX of every Lagrange equation,
T, Π, Φ, each generalised force), its phase table is the run's (event times
to 9 digits), its peaks the run's; every formula typesets; -o in a missing
folder and a bad file are one line, exit 2, nothing written."""
from __future__ import annotations

import re
from pathlib import Path

import pytest

from crane_sym.cli.main import main
from crane_sym.components.file_audit import audit_file
from crane_sym.components.component_file import read_component_file
from crane_sym.docs.drive_train import drive_train_walkthrough
from crane_sym.docs.numbers import math_errors
from crane_sym.docs.page import math_pieces
from crane_sym.latex import latex

EXAMPLES = Path(__file__).resolve().parents[1] / "examples" / "drive_trains"
FILES = [EXAMPLES / "hoist_fig9.toml", EXAMPLES / "hoist_rope_stretch.toml",
         EXAMPLES / "bridge_travel.toml"]


@pytest.fixture(scope="module", params=FILES, ids=lambda p: p.stem)
def handout(request):
    path = request.param
    read = read_component_file(path)
    run = read.model.run(read.duration, read.body, read.speed, rest=read.rest)
    return read, run, drive_train_walkthrough(path)


def _one_line(text: str) -> str:
    """The displays of ``text`` with their aligned rows joined again: what
    they say, without the breaks that fit them to a page."""
    text = re.sub(r"\\begin\{aligned\}\s*&?|\\end\{aligned\}|\{\}\s*&|\\\\\s*&(\s*\\quad)?", " ",
                  text)
    return re.sub(r"\s+", "", text)


def test_the_equations_are_the_models(handout):
    read, _, text = handout
    eq = read.model.equations
    said = _one_line(text)
    for line in eq.latex():
        assert _one_line(line) in said
    names = eq.latex_names
    assert _one_line(f"T = {latex(eq.T, symbol_names=names)}") in said
    assert _one_line(f"\\Pi = {latex(eq.V, symbol_names=names)}") in said
    assert _one_line(f"\\Phi = {latex(eq.dissipation, symbol_names=names)}") in said
    for q in eq.coordinates:
        assert _one_line(f"Q_{{{latex(q, symbol_names=names)}}} = "
                         f"{latex(eq.forces[q], symbol_names=names)}") in said
    link = read.model.assembly.links[0].part.name.replace("_", "\\_")
    assert f"c_{{\\mathrm{{{link}}}}}" in text          # a stiffness, named after its link


def test_the_phases_are_the_runs(handout):
    _, run, text = handout
    table = text.split("## The run")[1].split("## Results")[0]
    rows = re.findall(r"^\| (\d+) \| ([\d.e+-]+) s \| ([\d.e+-]+) s \| (\d+) \| (.+?) \|$",
                      table, flags=re.M)
    assert len(rows) == len(run.result.segments)
    for (k, t0, t1, _, event), seg in zip(rows, run.result.segments):
        assert float(t0) == pytest.approx(seg.t0, rel=1e-8, abs=1e-12)
        assert float(t1) == pytest.approx(seg.t1, rel=1e-8, abs=1e-12)
        assert event == (seg.event if seg.event != "end" else "end of the run")
    modes = {seg.mode for seg in run.result.segments}
    assert len(re.findall(r"^\*\*Mode \d+:\*\*", text, flags=re.M)) == len(modes)


def test_the_peaks_are_the_runs(handout):
    _, run, text = handout
    results = text.split("## Results")[1]
    for p in run.peaks:
        row = next(line for line in results.splitlines() if line.startswith(f"| {p.link} |"))
        peak, at = re.findall(r"([-\d.e+]+) (?:N\*m|N|s)", row)[:2]
        assert float(peak) == pytest.approx(p.value, rel=1e-5)
        assert float(at) == pytest.approx(p.time, rel=1e-5)
        assert f"{p.factor:.4g}"[:4] in row


def test_every_formula_typesets(handout):
    _, _, text = handout
    pieces = math_pieces(text)
    assert len(pieces) > 40
    assert [(tex[:60], errs) for tex, _ in pieces if (errs := math_errors(tex))] == []


def test_the_files_formulas_with_their_verdicts(handout):
    read, _, text = handout
    if not read.formulas:
        assert "## The file's formulas" not in text
        return
    part = text.split("## The file's formulas")[1]
    said = {"confirmed": "Verdict: **confirmed** (decided by symbolic)",
            "discrepancy": "Verdict: **discrepancy** (decided by numeric)",
            "not_checkable": "Verdict: **not_checkable** (no check could decide)"}
    verdicts = [r.verdict for r in audit_file(read)]
    assert sorted(set(verdicts)) == sorted(v for v in said if said[v] in part)
    assert part.count("Verdict: **") == len(verdicts) == len(read.formulas)


def test_cli_writes_markdown_and_html(tmp_path, capsys):
    md, page = tmp_path / "fig9.md", tmp_path / "fig9.html"
    assert main(["walkthrough", str(FILES[0]), "-o", str(md), "--quiet"]) == 0
    assert md.read_text(encoding="utf-8").startswith("# Table 1 hoist")
    assert main(["walkthrough", str(FILES[0]), "--format", "html", "-o", str(page),
                 "--quiet"]) == 0
    html = page.read_text(encoding="utf-8")
    assert html.count("<math") > 40 and 'src="data:image/png;base64,' in html
    assert "$$" not in html
    assert sorted(p.name for p in tmp_path.iterdir()) == ["fig9.html", "fig9.md"]


@pytest.mark.parametrize("args, message", [
    (["-o", "{tmp}/missing/x.md"], "the folder"),
    (["--format", "ipynb", "-o", "{tmp}/x.ipynb"], "Markdown or html"),
])
def test_cli_errors_are_one_line_and_write_nothing(args, message, tmp_path, capsys):
    args = [a.replace("{tmp}", str(tmp_path)) for a in args]
    assert main(["walkthrough", str(FILES[0]), *args, "--quiet"]) == 2
    out = capsys.readouterr()
    assert out.out == "" and len(out.err.strip().splitlines()) == 1 and message in out.err
    assert list(tmp_path.rglob("*")) == []


def test_a_bad_file_is_one_line_and_writes_nothing(tmp_path, capsys):
    bad = tmp_path / "bad.toml"
    bad.write_text(FILES[0].read_text(encoding="utf-8").replace('name = "gearbox_mesh"\n',
                                                                 'name = "gearbox_mesh"\nstiff = 1\n'),
                   encoding="utf-8")
    out = tmp_path / "out.md"
    assert main(["walkthrough", str(bad), "-o", str(out), "--quiet"]) == 2
    err = capsys.readouterr().err
    assert len(err.strip().splitlines()) == 1 and "unknown key 'stiff'" in err
    assert main(["walkthrough", str(tmp_path / "none.toml"), "-o", str(out), "--quiet"]) == 2
    assert "no component file" in capsys.readouterr().err
    assert sorted(p.name for p in tmp_path.iterdir()) == ["bad.toml"]


@pytest.mark.parametrize("form", ["markdown", "html"])
def test_an_audit_that_fails_ends_the_walkthrough_as_it_ends_audit(form, tmp_path, capsys,
                                                                   monkeypatch):
    """A page is not written with its formulas "not audited": when the file's audit
    fails (the file's fault, not a formula's), the walkthrough ends as `audit FILE`
    does, on the same one line, exit 2, nothing written."""
    import crane_sym.components.file_audit as file_audit

    def failing(read):
        raise file_audit.ComponentError(f"{read.path.name}: the audit failed here")
    monkeypatch.setattr(file_audit, "audit_file", failing)
    out = tmp_path / "page.out"
    assert main(["audit", str(FILES[1]), "--quiet"]) == 2
    said = capsys.readouterr().err
    assert main(["walkthrough", str(FILES[1]), "--format", form, "-o", str(out),
                 "--quiet"]) == 2
    err = capsys.readouterr().err
    assert err == said == "crane-sym: error: hoist_rope_stretch.toml: the audit failed here\n"
    assert list(tmp_path.iterdir()) == []


def test_a_law_in_time_is_named_and_its_clock_is_in_the_state():
    """002's acceleration law (degree 1): its symbol is in the table of symbols
    with its unit, its one clock state w_1 = τ closes the state vector, and
    every symbol of the equations is one the table names."""
    text = drive_train_walkthrough(EXAMPLES / "hoist_drive_law.toml")
    symbols = text.split("## Symbols")[1].split("## Rigid groups")[0]
    assert r"| $a_{\mathrm{hoist}}$ |" in symbols and "| m/s^2 |" in symbols
    state = re.findall(r"\$x_\{(\d+)\} = (.*?)\$", text.split("The state is $x$: ")[1]
                       .split(" (each group's")[0])
    assert [int(k) for k, _ in state] == list(range(1, len(state) + 1))
    assert [s for _, s in state[-2:]] == [r"\dot{x}_{\mathrm{load}}", r"w_{\mathrm{hoist},1}"]
    equations = text.split("## Lagrange's equations")[1].split("## Modes")[0]
    assert "a_{hoist}" not in text and r"a_{\mathrm{hoist}}" in equations
