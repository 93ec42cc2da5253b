"""Figures of a scene's panels, laid out so that nothing hides the data.

At most four panels to a figure; one title per figure (the scene's, with the
group of its panels); legends to the right of the axes, outside the data
area; labels in Matplotlib mathtext where the panels give it. Where a
panel's model does not hold (``Panel.invalid``) the axis is greyed, the
curves are drawn faint, the y axis is scaled to the valid part and the legend
says why (:func:`grey_invalid`). Figures are built without pyplot's global
state and written by :func:`save`.
"""
from __future__ import annotations

import re
from pathlib import Path
from typing import Sequence

import numpy as np

from crane_sym.escapes import mathtext_text
from crane_sym.scenes.panels import Panel, valid_mask

__all__ = ["MAX_PANELS", "chunks", "figures", "fitted", "grey_invalid", "layout", "legend_outside",
           "numbered", "save"]

#: The most panels one figure holds.
MAX_PANELS = 4
#: Fill of a span where the model does not hold, and the curves' opacity there.
INVALID_FILL = {"facecolor": "0.85", "alpha": 0.6, "hatch": "//", "edgecolor": "0.6",
                "linewidth": 0.0}
INVALID_ALPHA = 0.3


def layout(panels: Sequence[Panel]) -> list[tuple[str, list[Panel]]]:
    """Runs of consecutive panels of one ``group``, each split into figures of
    at most :data:`MAX_PANELS` panels of nearly equal size: (group, panels)."""
    runs: list[tuple[str, list[Panel]]] = []
    for panel in panels:
        if runs and runs[-1][0] == panel.group:
            runs[-1][1].append(panel)
        else:
            runs.append((panel.group, [panel]))
    return [(group, part) for group, members in runs for part in chunks(members)]


def chunks(items: Sequence, size: int = MAX_PANELS) -> list[list]:
    """``items`` in the fewest runs of at most ``size``, of nearly equal length
    (nine in fours: 3, 3, 3).

    Parameters
    ----------
    items : sequence
        The items.
    size : int, optional
        Most items a run.
    """
    parts = max(1, -(-len(items) // size))
    length, extra = divmod(len(items), parts)
    out, start = [], 0
    for k in range(parts):
        stop = start + length + (k < extra)
        out.append(list(items[start:stop]))
        start = stop
    return out


def numbered(path: Path, count: int) -> list[Path]:
    """``[path]`` for one figure, else ``<stem>_1<suffix>`` ... ``_<count>``.

    Parameters
    ----------
    path : Path
        The file named for one figure.
    count : int
        Number of figures.
    """
    path = Path(path)
    if count == 1:
        return [path]
    return [path.with_name(f"{path.stem}_{k}{path.suffix}") for k in range(1, count + 1)]


def legend_outside(ax, **options):
    """A legend to the right of ``ax``, outside its data area."""
    return ax.legend(loc="upper left", bbox_to_anchor=(1.02, 1.0), borderaxespad=0.0,
                     **options)


def figures(panels: Sequence[Panel], title: str) -> list:
    """One Matplotlib figure per entry of :func:`layout`, each with one title:
    ``title``, the panels' group if they have one, and the panel's own title
    when the figure holds a single panel (several panels keep theirs as
    captions); the group is said once, not again when that title starts with
    it ("Fig. 5: …" under "Fig. 5").

    Parameters
    ----------
    panels : sequence of Panel
        The report's panels.
    title : str
        The figure title (text, not mathtext).
    """
    from matplotlib.figure import Figure

    pages = layout(panels)
    out = []
    for group, members in pages:
        legends = any(len(p.curves) > 1 or p.invalid for p in members)
        fig = Figure(figsize=(10.5 if legends else 8.0, 2.9 * len(members) + 0.9),
                     layout="constrained")
        axes = fig.subplots(len(members), 1, squeeze=False)[:, 0]
        for ax, panel in zip(axes, members):
            if panel.invalid:
                grey_invalid(ax, panel)
            else:
                for label, x, y in panel.curves:
                    ax.plot(x, y, label=label, **panel.styles.get(label, {}))
            ax.set(xlabel=panel.xlabel, ylabel=panel.ylabel)
            if panel.ylim is not None:
                ax.set_ylim(*panel.ylim)
            if len(members) > 1:
                ax.set_title(panel.title, fontsize=10)
            ax.grid(True, alpha=0.4)
            if len(panel.curves) > 1 or panel.invalid:
                legend_outside(ax, fontsize=9)
        single = members[0].title if len(members) == 1 else ""
        # a figure's name once: not again when the panel's own title starts with it
        text = mathtext_text(title)                 # the user's text, never mathtext
        heading = f"{text}: {group}" if group and not single.startswith(group) else text
        named = re.match(r"(Fig\. \d+[a-z]?): ", single)
        if named and named.group(1) in heading:
            single = single[named.end():]
        if single and single.lower() not in heading.lower():  # said once
            heading += "\n" + single
        fig.suptitle(fitted(heading, fig.get_figwidth()))
        out.append(fig)
    return out


def fitted(title: str, inches: float, points: float = 12.0) -> str:
    """``title`` broken at spaces into lines that fit a figure ``inches`` wide
    at ``points`` (a suptitle's size): a long title wraps instead of running
    past both edges, where the PNG clips it. Mathtext (``$…$``) is not broken.

    Parameters
    ----------
    title : str
        The title; its own line breaks are kept.
    inches : float
        The figure's width.
    points : float
        The title's font size.
    """
    import textwrap
    chars = max(20, int(0.92 * inches * 72 / (0.6 * points)))   # a sans glyph is ~0.6 em
    keep = "\u00a0"                      # a space inside $…$, not a place to break
    title = re.sub(r"\$[^$]*\$", lambda m: m.group(0).replace(" ", keep), title)
    return "\n".join(textwrap.fill(line, chars, break_long_words=False,
                                   break_on_hyphens=False).replace(keep, " ")
                     for line in title.split("\n"))


def grey_invalid(ax, panel: Panel) -> None:
    """Plot ``panel``'s curves on ``ax`` with its ``invalid`` spans greyed:
    the curves full where the model holds and faint (no legend entry) where
    it does not, each span filled and named in the legend (its ``reason``),
    the y axis scaled to the valid part."""
    shown = []
    for label, x, y in panel.curves:
        x, y = np.asarray(x, dtype=float), np.asarray(y, dtype=float)
        ok = valid_mask(x, panel.invalid)
        faint = ~ok
        faint[1:] |= ~ok[:-1]                    # joined to the valid part
        faint[:-1] |= ~ok[1:]
        style = panel.styles.get(label, {})
        (line,) = ax.plot(x, np.where(ok, y, np.nan), label=label, **style)
        ax.plot(x, np.where(faint, y, np.nan), label="_faint", alpha=INVALID_ALPHA,
                **{**style, "color": line.get_color()})
        shown.append(y[ok & np.isfinite(y)])
    lo, hi = ax.get_xlim()                       # the data's range with its margins
    named = set()
    for span in panel.invalid:
        left, right = max(span.start, lo), min(span.end, hi)
        if left < right:
            label = "_" if span.reason in named else span.reason
            ax.axvspan(left, right, zorder=0, label=label, **INVALID_FILL)
            named.add(span.reason)
    ax.set_xlim(lo, hi)
    values = np.concatenate(shown) if shown else np.empty(0)
    if values.size:
        bottom, top = float(values.min()), float(values.max())
        pad = 0.05 * (top - bottom) or 0.05 * max(abs(top), 1.0)
        ax.set_ylim(bottom - pad, top + pad)


def save(fig, path: Path, dpi: int = 120) -> Path:
    """Write ``fig`` to the PNG ``path`` (deterministic bytes); return ``path``.

    Parameters
    ----------
    fig : matplotlib.figure.Figure
        The figure.
    path : Path
        The PNG to write.
    dpi : int, optional
        Resolution.
    """
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    fig.savefig(path, dpi=dpi, metadata={"Software": None})
    return path
