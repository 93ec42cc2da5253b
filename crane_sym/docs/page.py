"""A walkthrough as one printable, self-contained HTML page.

The page is the walkthrough's Markdown set as HTML (``markdown-it-py``), with a
table of contents, the figures of the paper's first shipped scene inline (PNG
as data URIs) and every formula as MathML (``latex2mathml``), which browsers
typeset natively (MathML Core: Chromium 109+, Firefox, Safari): no script, no
font and no address outside the file, so it prints, mails and posts as it is
on a machine with no network. ``docs.numbers.math_errors`` checks the same
conversion, so a formula that would not typeset fails the tests.
"""
from __future__ import annotations

import base64
import html
import re
import tempfile
from pathlib import Path

from markdown_it import MarkdownIt
from mdit_py_plugins.dollarmath import dollarmath_plugin

from crane_sym import registry
from crane_sym.docs.numbers import mathml
from crane_sym.docs.walkthrough import walkthrough
from crane_sym.escapes import terminal_text
from crane_sym.scenes.reading import load_scene, scenes_directory
from crane_sym.scenes.run import run_scene

__all__ = ["handout_page", "markdown_parser", "math_pieces", "render_page"]

_CSS = """
@page { size: A4; margin: 16mm 14mm; }
body { font-family: "DejaVu Serif", Georgia, serif; font-size: 11pt; line-height: 1.45;
       max-width: 46em; margin: 2em auto; padding: 0 1em; color: #111; }
h1 { font-size: 1.6em; margin-bottom: 0.2em; }
h2 { font-size: 1.3em; border-bottom: 1px solid #999; margin-top: 1.6em; }
h3 { font-size: 1.08em; margin-top: 1.4em; break-after: avoid; }
p { margin: 0.45em 0; }
nav.toc { font-size: 0.92em; columns: 2; column-gap: 2em; break-after: page; }
nav.toc ol { margin: 0.2em 0; padding-left: 1.4em; }
nav.toc ol ol { list-style: none; padding-left: 0.8em; }
nav.toc li.step { font-size: 0.92em; }
table { border-collapse: collapse; font-size: 0.86em; margin: 0.6em 0; }
th, td { border: 1px solid #bbb; padding: 0.15em 0.45em; vertical-align: top; }
pre { background: #f4f4f4; padding: 0.5em; font-size: 0.82em; white-space: pre-wrap;
      break-inside: avoid; }
.display { margin: 0.5em 0 0.5em 1.5em; overflow-x: auto; break-inside: avoid; }
math { font-size: 1.05em; }
mtd[columnalign="left"] { text-align: left; }
mtd[columnalign="right"] { text-align: right; }
figure { margin: 1em 0; break-inside: avoid; text-align: center; }
figure img { max-width: 100%; }
figcaption { font-size: 0.9em; color: #333; }
ul { margin: 0.3em 0; }
@media print { body { margin: 0; max-width: none; } a { color: inherit; } }
"""


def _math(content: str, options: dict) -> str:
    display = bool(options.get("display_mode"))
    try:
        out = mathml(content.strip(), display=display)
    except Exception:        # the converter's parse errors (``\frac{`` alone): as text
        code = f"<code>{html.escape(content.strip())}</code>"
        return f'<div class="display">{code}</div>\n' if display else code
    out = out.replace(' xmlns="http://www.w3.org/1998/Math/MathML"', "")
    return f'<div class="display">{out}</div>\n' if display else out


def markdown_parser() -> MarkdownIt:
    """CommonMark with tables and ``$…$``/``$$…$$`` math set as MathML; raw
    HTML off (a ``<script>`` in a file's title is shown as text)."""
    return (MarkdownIt("commonmark", {"html": False}).enable("table")
            .use(dollarmath_plugin, allow_space=True, allow_digits=True,
                 double_inline=True, renderer=_math))


def math_pieces(markdown: str) -> list[tuple[str, bool]]:
    """Every formula of ``markdown`` as (LaTeX, display), as the page sets them."""
    pieces = []
    for token in markdown_parser().parse(markdown):
        if token.type == "math_block":
            pieces.append((token.content.strip(), True))
        for child in token.children or []:
            if child.type in ("math_inline", "math_inline_double"):
                pieces.append((child.content.strip(), child.type != "math_inline"))
    return pieces


def _slug(text: str, taken: set[str]) -> str:
    base = re.sub(r"[^\w]+", "-", re.sub(r"<[^>]+>", "", text).lower()).strip("-")[:60]
    slug, k = base or "section", 1
    while slug in taken:
        k += 1
        slug = f"{base}-{k}"
    taken.add(slug)
    return slug


def _with_contents(body: str) -> str:
    """``body`` with an id on every h2/h3 and a table of contents before the
    first h2 (after the title and the citation)."""
    taken: set[str] = set()
    entries: list[tuple[int, str, str]] = []

    def anchor(m: re.Match) -> str:
        level, inner = int(m.group(1)), m.group(2)
        slug = _slug(inner, taken)
        entries.append((level, slug, inner))
        return f'<h{level} id="{slug}">{inner}</h{level}>'

    body = re.sub(r"<h([23])>(.*?)</h\1>", anchor, body)
    items, open_sub = [], False
    for level, slug, inner in entries:
        if level == 2:
            items.append(("</ol>" if open_sub else "") + f'<li><a href="#{slug}">{inner}</a>')
            open_sub = False
        else:
            items.append(("" if open_sub else "<ol>")
                         + f'<li class="step"><a href="#{slug}">{inner}</a></li>')
            open_sub = True
    toc = ('<nav class="toc"><h2>Contents</h2><ol>' + "".join(items)
           + ("</ol>" if open_sub else "") + "</ol></nav>")
    at = body.find("<h2")
    return body[:at] + toc + body[at:] if at >= 0 else body + toc


def render_page(markdown: str, title: str, figures: list[tuple[str, bytes]] = (),
                figures_note: str = "") -> str:
    """The page: ``markdown`` as HTML with math as MathML, a table of contents,
    and ``figures`` (caption, PNG bytes) inline after the model.

    Parameters
    ----------
    markdown : str
        A walkthrough (:func:`crane_sym.docs.walkthrough.render`).
    title : str
        The page title.
    figures : list of (str, bytes)
        Caption and PNG of each figure.
    figures_note : str
        A sentence above the figures: where they come from.

    Returns
    -------
    str
        One HTML document that needs nothing outside itself.
    """
    body = markdown_parser().render(markdown)
    if figures:
        shown = "\n".join(
            f'<figure><img alt="{html.escape(cap)}" src="data:image/png;base64,'
            f'{base64.b64encode(png).decode()}"><figcaption>{html.escape(cap)}'
            "</figcaption></figure>" for cap, png in figures)
        note = f"<p>{html.escape(figures_note)}</p>\n" if figures_note else ""
        block = f"<h2>Figures</h2>\n{note}{shown}\n<h2>Symbols</h2>"
        body = body.replace("<h2>Symbols</h2>", block, 1)
    body = _with_contents(body)
    return ("<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
            f"<title>{html.escape(terminal_text(title))}</title>\n"
            "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n"
            f"<style>{_CSS}</style>\n</head>\n<body>\n{body}</body>\n</html>\n")


def scene_figures(derivation: str) -> tuple[str, list[tuple[str, bytes]]]:
    """The figures of the first scene shipped with ``derivation`` (by file name),
    run now: (a sentence on where they come from, [(caption, PNG)])."""
    files = sorted(scenes_directory(registry.resolve(derivation)).glob("*.toml"))
    if not files:
        return "", []
    scene = load_scene(files[0])
    with tempfile.TemporaryDirectory() as tmp:
        _, pngs = run_scene(scene, Path(tmp) / "run")
        figures = [(f"Figure {k}: {scene.title}" + (f", part {k}" if len(pngs) > 1 else ""),
                    p.read_bytes()) for k, p in enumerate(pngs, start=1)]
    note = (f"Computed from the data of the scene '{scene.title}' shipped with the "
            "paper, with the generated functions of the derivation below.")
    return note, figures


def handout_page(name: str) -> str:
    """The printable page of a registered derivation: its audited walkthrough,
    with the figures of its first shipped scene.

    Parameters
    ----------
    name : str
        A derivation id or paper number.
    """
    key = registry.resolve(name)
    note, figures = scene_figures(key)
    return render_page(walkthrough(key), registry.get(key).title, figures, note)
