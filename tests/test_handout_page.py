"""The printable page (``crane-sym walkthrough ID --format html``): one file that
needs nothing outside itself, with contents, the first scene's figures and
every formula as MathML; and a real browser (Debian's Chromium, headless)
typesets it: every formula has a size, fractions stand taller than a line,
every figure loads, and the screenshot is not blank.

The browser tests skip, saying why, where no Chromium is installed; ``.ci/run``
installs it, so in CI they run.
"""
from __future__ import annotations

import json
import re
import shutil
import subprocess
from pathlib import Path

import pytest

from crane_sym.cli.main import main
from crane_sym.docs.page import handout_page, math_pieces
from crane_sym.docs.walkthrough import walkthrough

PAPER = "001"
#: The flags Chromium needs on a machine with no network and no screen.
FLAGS = ("--headless", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
         "--disable-background-networking", "--disable-component-update", "--disable-sync",
         "--hide-scrollbars", "--window-size=1000,1400")
#: Measures the typeset page once it has loaded and writes the result into it.
MEASURE = """<script>
window.addEventListener('load', () => {
  const maths = [...document.querySelectorAll('math')];
  const box = e => e.getBoundingClientRect();
  const em = parseFloat(getComputedStyle(document.body).fontSize);
  const fracs = maths.filter(m => m.querySelector('mfrac') && !m.closest('td'));
  const out = {
    math: maths.length,
    empty: maths.filter(m => box(m).width <= 0 || box(m).height <= 0).length,
    fractions: fracs.length,
    tall_fractions: fracs.filter(m => box(m).height > 1.6 * em).length,
    images: document.images.length,
    broken: [...document.images].filter(i => !i.complete || i.naturalWidth === 0).length,
    toc_links: document.querySelectorAll('nav.toc a').length,
    targets: [...document.querySelectorAll('nav.toc a')].filter(
      a => document.getElementById(a.getAttribute('href').slice(1))).length,
  };
  const pre = document.createElement('pre');
  pre.id = 'measure';
  pre.textContent = JSON.stringify(out);
  document.body.appendChild(pre);
});
</script>"""


@pytest.fixture(scope="module")
def page() -> str:
    return handout_page(PAPER)


def _chromium() -> str:
    found = shutil.which("chromium") or shutil.which("chromium-browser")
    if found is None:
        pytest.skip("no Chromium on this machine (Debian: apt-get install chromium; "
                    ".ci/run installs it)")
    return found


def _run(browser: str, profile: Path, *args: str) -> subprocess.CompletedProcess:
    return subprocess.run([browser, *FLAGS, f"--user-data-dir={profile}", *args],
                          capture_output=True, text=True, timeout=180, check=True)


def test_page_is_one_file_with_contents_figures_and_mathml(page):
    assert page.startswith("<!DOCTYPE html>") and "</html>" in page
    # nothing is fetched: no script, no stylesheet or image from an address
    assert "<script" not in page and not re.search(r"""(src|href)=["'](?!#|data:)""", page)
    assert "http://" not in page and "https://" not in page
    # the contents link every step heading
    steps = re.findall(r'<h3 id="([^"]+)">Step \d+', page)
    assert steps and all(f'href="#{s}"' in page for s in steps)
    # the first scene's figures, inline
    assert len(re.findall(r'<img alt="Figure \d+: [^"]+" src="data:image/png;base64,', page)) \
        >= 1
    # every formula of the walkthrough is MathML, and no TeX is left over
    assert page.count("<math") == len(math_pieces(walkthrough(PAPER)))
    assert "$$" not in page and not re.search(r"<mi>\\\w+", page)


def test_the_command_writes_the_page(tmp_path):
    target = tmp_path / "hoist.html"
    assert main(["walkthrough", PAPER, "--format", "html", "-o", str(target)]) == 0
    assert target.read_text(encoding="utf-8").startswith("<!DOCTYPE html>")


def test_chromium_typesets_every_formula_and_figure(page, tmp_path):
    browser = _chromium()
    measured = tmp_path / "measured.html"
    measured.write_text(page.replace("</body>", MEASURE + "</body>"), encoding="utf-8")
    dom = _run(browser, tmp_path / "profile", "--dump-dom", measured.as_uri()).stdout
    m = json.loads(re.search(r'<pre id="measure">(.*?)</pre>', dom, re.S).group(1))
    assert m["math"] == page.count("<math") and m["empty"] == 0, m
    assert m["fractions"] and m["tall_fractions"] == m["fractions"], m   # MathML laid out
    assert m["images"] >= 1 and m["broken"] == 0, m
    assert m["toc_links"] and m["targets"] == m["toc_links"], m


def screenshot(page: str, folder: Path, *flags: str):
    """The pixels of ``page`` as headless Chromium shows it (with ``flags``),
    and the PNG's path."""
    mpimg = pytest.importorskip("matplotlib.image")
    browser = _chromium()
    source = folder / "page.html"
    source.write_text(page, encoding="utf-8")
    shot = folder / "page.png"
    _run(browser, folder / "profile", *flags, f"--screenshot={shot}", source.as_uri())
    return mpimg.imread(shot), shot


def test_chromium_screenshot_is_a_page(page, tmp_path):
    pixels, _ = screenshot(page, tmp_path)
    assert pixels.shape[0] >= 1000 and pixels.shape[1] >= 900
    ink = (pixels[..., :3].mean(axis=2) < 0.5).mean()        # dark pixels: text, math
    assert 0.005 < ink < 0.5, ink
