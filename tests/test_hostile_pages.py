"""A shared component file cannot make its page run anything: the text of the
file (title, formula names, the formulas, messages quoting them) is escaped
where it lands, the HTML page renders Markdown with raw HTML off, and its
MathML passes an allow-list (crane_sym.docs.safe_mathml). A headless Chromium
(Debian's, skipped where missing as in tests/test_handout_page.py) opens the
hostile page and a canary shows whether any script ran."""
from __future__ import annotations

import json
import re
from pathlib import Path

import pytest

from crane_sym.cli.main import main
from crane_sym.docs.numbers import mathml
from crane_sym.docs.safe_mathml import ATTRIBUTES, ELEMENTS

from test_handout_page import _chromium, _run

#: The harm these cases guard against (tests/fault_counts.py counts them).
pytestmark = pytest.mark.harm("pages")

EXAMPLE = Path(__file__).parents[1] / "examples" / "drive_trains" / "travel_braking_000.toml"
#: What a script that runs does: it marks the page, which the dumped DOM shows.
CANARY = "document.documentElement.setAttribute('data-canary','ran')"
#: The mark in the dumped DOM (the page's text may quote the canary, escaped).
RAN = re.compile(r'<html[^>]*\sdata-canary="ran"')
#: Text from a file that would run script if it landed raw.
PAYLOADS = {
    "script": f"<script>{CANARY}</script>",
    "img onerror": f"<img src=x onerror=\"{CANARY}\">",
    "svg onload": f"<svg onload=\"{CANARY}\"></svg>",
    "fence escape": f"```\n<img src=x onerror=\"{CANARY}\">\n```",
}
#: Formulas whose MathML would carry script without the allow-list.
FORMULAS = {
    "text": rf"p = \text{{<script>{CANARY}</script>}} c",
    "href": rf"p = \href{{javascript:{CANARY}}}{{\sqrt{{c}}}}",
    "style": r"p = \style{background:url(javascript:alert(1))}{\sqrt{c}}",
    "fence in an unreadable formula": f"p = \\frac{{``` <img src=x onerror=\"{CANARY}\">",
    "dollar break-out": f"p = c $$ <script>{CANARY}</script> $$",
}
#: What no tag of a page built from the file may hold (text may quote it, escaped).
LIVE = re.compile(r"^<\s*/?\s*script|javascript:|\son[a-z]+\s*=", re.I)


def live_tags(page: str) -> list[str]:
    """The tags of ``page`` that could run script: a ``<script>``, a handler
    attribute, a ``javascript:`` address. A ``<`` of the file's text is
    ``&lt;``, so every ``<`` left starts a real tag."""
    return [tag for tag in re.findall(r"<[^>]*>?", page) if LIVE.search(tag)]


def _toml(text: str) -> str:
    """A TOML basic string (JSON's escapes are TOML's)."""
    return json.dumps(text)


def hostile_file(folder: Path) -> Path:
    """The 000 example with every payload in its title and formula names, and
    the hostile formulas added."""
    text = EXAMPLE.read_text(encoding="utf-8")
    title = " ".join(PAYLOADS.values()) + " \x1b[31m red $\\input{x}$"
    text = re.sub(r'(?m)^title = .*$', lambda m: f"title = {_toml(title)}", text, count=1)
    names = iter(PAYLOADS.values())
    text = re.sub(r'(?m)^name = "\((14|6)\)"$', lambda m: f"name = {_toml(next(names))}", text)
    for k, latex in enumerate(FORMULAS.values()):
        text += (f"\n[[formula]]\nname = {_toml(list(PAYLOADS.values())[k % len(PAYLOADS)] + f' {k}')}"
                 f"\nlatex = {_toml(latex)}\nsymbols = {{ c = \"transmission.stiffness\" }}"
                 "\nquantity = \"transmission.frequency\"\n")
    path = folder / "hostile.toml"
    path.write_text(text, encoding="utf-8")
    return path


@pytest.fixture(scope="module")
def pages(tmp_path_factory) -> dict[str, str]:
    folder = tmp_path_factory.mktemp("hostile")
    source = hostile_file(folder)
    out = {}
    for form, name in (("html", "page.html"), ("markdown", "page.md")):
        assert main(["walkthrough", str(source), "--format", form, "-o",
                     str(folder / name), "-q"]) == 0
        out[form] = (folder / name).read_text(encoding="utf-8")
    return out


@pytest.mark.parametrize("case", list(FORMULAS))
def test_mathml_of_a_hostile_formula_is_inert(case):
    out = mathml(FORMULAS[case].split("$$")[0].replace("```", ""), display=True)
    assert live_tags(out) == [], out
    assert "href" not in out and "style" not in out
    assert set(re.findall(r"</?([a-z]+)", out)) <= ELEMENTS, out
    assert set(re.findall(r"\s([a-z]+)=", out)) <= ATTRIBUTES | {"xmlns"}, out


def test_mtext_keeps_the_text_as_text():
    assert "<mtext>&lt;b&gt;a&amp;b</mtext>" in mathml(r"\text{<b>a&b}")


def test_the_html_page_carries_no_live_markup(pages):
    page = pages["html"]
    assert "<script" not in page.lower() and live_tags(page) == []
    assert "&lt;script&gt;" in page                       # the title shown as text
    assert page.count("<pre") >= 1                        # the unreadable formula, fenced
    for block in re.findall(r"<pre>(.*?)</pre>", page, re.S):
        assert "<" not in block.replace("<code", "").replace("</code", "")


def test_the_markdown_escapes_the_file_text(pages):
    md = pages["markdown"]
    title = md.splitlines()[0]
    assert title.startswith("# \\<script\\>") and "\x1b" not in md.replace("\\x1b", "")
    # no raw tag outside a fence: every < of the file's text is escaped or fenced
    outside = re.sub(r"(?ms)^(`{3,})text\n.*?\n\1$", "", md)
    assert not re.search(r"(?<!\\)<(script|img|svg)", outside), outside


def test_chromium_runs_no_script_of_the_hostile_page(pages, tmp_path):
    browser = _chromium()
    control = tmp_path / "control.html"          # the canary works: a live script marks
    control.write_text(f"<!DOCTYPE html><html><body>{PAYLOADS['script']}</body></html>")
    assert RAN.search(_run(browser, tmp_path / "p1", "--dump-dom", control.as_uri()).stdout)
    page = tmp_path / "page.html"
    page.write_text(pages["html"], encoding="utf-8")
    dom = _run(browser, tmp_path / "p2", "--dump-dom", page.as_uri()).stdout
    assert "<math" in dom and "&lt;script&gt;" in dom and not RAN.search(dom)


def test_run_prints_and_plots_the_title_as_text(tmp_path, capsys):
    pytest.importorskip("matplotlib")
    source = hostile_file(tmp_path)
    assert main(["run", str(source), "--out", str(tmp_path / "out"), "-q"]) == 0
    out = capsys.readouterr().out
    assert "\x1b" not in out and "\\x1b[31m red $\\input{x}$" in out   # escaped, one line
    assert list((tmp_path / "out").glob("*.png"))                      # mathtext took it


def test_math_the_converter_cannot_read_is_shown_as_text():
    from crane_sym.docs.page import render_page
    page = render_page("# t\n\nbad $\\frac{$ and\n\n$$\n\\frac{\n$$\n", "t")
    assert "<code>\\frac{</code></span> and" in page and live_tags(page) == []
    assert '<div class="display"><code>\\frac{</code></div>' in page


@pytest.mark.parametrize("form", ["table", "markdown", "json"])
def test_audit_of_the_file_prints_no_escape_code(form, tmp_path, capsys):
    source = hostile_file(tmp_path)
    text = source.read_text(encoding="utf-8")
    text = text.replace('name = "<script>', 'name = "\\u001b[2J<script>', 1)
    source.write_text(text, encoding="utf-8")
    assert main(["audit", str(source), "--format", form, "-q"]) == 0
    out = capsys.readouterr().out
    assert "\x1b" not in out and ("\\x1b[2J" in out or "\\u001b[2J" in out)


@pytest.mark.parametrize("title", ["$\\input{x}$ cost $5", "bad $\\frac{$", "\x1b[31m red"])
def test_a_plot_title_is_text_never_mathtext(title, tmp_path):
    pytest.importorskip("matplotlib")
    import numpy as np

    from crane_sym.scenes.panels import Panel
    from crane_sym.scenes.plots import figures
    t = np.linspace(0.0, 1.0, 5)
    (fig,) = figures([Panel("$F$", "$F$ [N]", [("$F_1$", t, t)])], title)
    fig.savefig(tmp_path / "x.png")                 # mathtext would fail on the title
    shown = fig._suptitle.get_text().splitlines()[0]   # then the panel's own title
    assert "\x1b" not in shown and shown.count("$") == shown.count("\\$")
