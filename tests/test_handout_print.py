"""The page of a drive train of the user's own prints: nothing runs past the
right edge of the page. A headless Chromium (skipped where missing, as in
tests/test_handout_page.py) lays out the walkthrough page of a seven-coordinate
gantry hoist (examples/drive_trains/gantry_hoist.toml: its energies, Lagrange's
equations and 14-column mode matrices are far wider than a page on one line)
at the width of an A4 page and reports every element that reaches past the
body's right edge or scrolls; its screenshot is kept for a reader to look at
(``CRANE_SYM_SHOTS=folder``)."""
from __future__ import annotations

import json
import os
import re
import shutil
from pathlib import Path

import pytest

from crane_sym.docs.drive_train import drive_train_page, drive_train_walkthrough
from crane_sym.docs.rows import WIDTH, aligned_rows, column_blocks, typeset_width

from test_handout_page import _chromium, _run, screenshot

GANTRY = Path(__file__).resolve().parents[1] / "examples" / "drive_trains" / "gantry_hoist.toml"
#: Lists the outermost elements that reach past the body's right edge, or that
#: scroll sideways (a display cut off in print), once the page has loaded.
OVERFLOW = """<script>
window.addEventListener('load', () => {
  const edge = document.body.getBoundingClientRect().right + 0.5;
  const wide = [];
  for (const e of document.body.querySelectorAll('*')) {
    if (wide.some(w => w.contains(e))) continue;
    const r = e.getBoundingClientRect();
    const scrolls = e.scrollWidth > e.clientWidth + 1 && getComputedStyle(e).overflowX !== 'visible';
    if (r.right > edge || scrolls) wide.push(e);
  }
  const pre = document.createElement('pre');
  pre.id = 'overflow';
  pre.textContent = JSON.stringify({
    edge, displays: document.querySelectorAll('.display').length,
    wide: wide.map(e => e.tagName + ' ' + Math.round(e.getBoundingClientRect().width)
                        + ' px: ' + (e.textContent || '').slice(0, 80)),
  });
  document.body.appendChild(pre);
});
</script>"""


@pytest.fixture(scope="module")
def page() -> str:
    return drive_train_page(GANTRY)


def test_long_sums_are_aligned_rows_and_say_the_same():
    terms = [r"\frac{J_{\mathrm{drum}} \dot{\theta}_{\mathrm{drum}}^{2}}{2}"] * 6
    tex = aligned_rows("T", terms)
    rows = tex.removeprefix(r"\begin{aligned}").removesuffix(r"\end{aligned}").split(r" \\ ")
    assert len(rows) > 1 and rows[0].startswith("T ={} & ")
    assert all(r.startswith("& + ") for r in rows[1:])
    assert all(typeset_width(r) <= WIDTH for r in rows)
    joined = " ".join(r.removeprefix("T ={} & ").removeprefix("& ") for r in rows)
    assert joined == " + ".join(terms)                  # only the breaks are new
    assert aligned_rows("T", terms[:1]) == f"T = {terms[0]}"       # short: one line


def test_a_wide_matrix_comes_in_blocks_of_whole_columns():
    entries = [[f"{i}{j} \\cdot 10^{{4}}" for j in range(14)] for i in range(14)]
    blocks = column_blocks("A", entries)
    assert len(blocks) > 1
    assert [j for cols, _ in blocks for j in cols] == list(range(14))
    assert all(typeset_width(tex) <= WIDTH for _, tex in blocks)
    assert column_blocks("b", [[e[0]] for e in entries])[0][1].startswith("b = ")


def test_the_gantry_handout_is_wider_than_a_line(page):
    """The model is one the test means: seven coordinates, 14 states."""
    text = drive_train_walkthrough(GANTRY)
    assert "$x_{14} = " in text and r"A_{[:,\,1\ldots" in text
    assert text.count(r"\begin{aligned}") >= 7 + 3         # Lagrange's seven, T, Π, Φ


def test_nothing_runs_past_the_page_edge(page, tmp_path):
    browser = _chromium()
    measured = tmp_path / "measured.html"
    measured.write_text(page.replace("</body>", OVERFLOW + "</body>"), encoding="utf-8")
    # 794 px: an A4 page at 96 dpi, the width the page prints at
    dom = _run(browser, tmp_path / "profile", "--window-size=794,1123", "--dump-dom",
               measured.as_uri()).stdout
    found = json.loads(re.search(r'<pre id="overflow">(.*?)</pre>', dom, re.S).group(1)
                       .replace("&amp;", "&").replace("&lt;", "<").replace("&gt;", ">"))
    assert found["displays"] > 20 and found["wide"] == [], found


def test_the_screenshot_shows_the_page(page, tmp_path):
    # the page at A4 width, long enough to hold the energies and the modes
    pixels, shot = screenshot(page, tmp_path, "--window-size=794,6000")
    ink = (pixels[..., :3].mean(axis=2) < 0.5)
    assert 0.005 < ink.mean() < 0.5, ink.mean()
    if os.environ.get("CRANE_SYM_SHOTS"):
        shutil.copy(shot, Path(os.environ["CRANE_SYM_SHOTS"]) / "gantry.png")


def test_a_long_figure_title_is_fitted_not_clipped():
    pytest.importorskip("matplotlib")
    import numpy as np

    from crane_sym.scenes.panels import Panel
    from crane_sym.scenes.plots import figures
    title = ("Gantry crane hoist of the north yard, bay 3: motor, coupling with backlash, "
             "gear, two drums, two ropes, one hook and a service brake")
    t = np.linspace(0.0, 1.0, 5)
    (fig,) = figures([Panel("load of the elastic link rope_a", "[N]", [("a", t, t)])], title)
    fig.canvas.draw()
    box = fig._suptitle.get_window_extent()
    assert "\n" in fig._suptitle.get_text()
    assert 0 <= box.x0 and box.x1 <= fig.bbox.width            # inside the PNG
