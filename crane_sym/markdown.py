"""Markdown: one writer for every table the toolkit prints (the audit, the
walkthrough, the benches), and text from a file set as text.

The table writer only lays cells out; each caller formats its numbers and
escapes its text (a ``|`` inside a cell written ``\\|``) the way its readers
need. Text a user wrote (a component file's title, a formula's name, a message
quoting a formula) goes through :func:`markdown_text` (one line, every
character Markdown or HTML reads as markup escaped) or :func:`fenced` (a code
fence longer than any run of backticks inside it).
"""
from __future__ import annotations

import re
from typing import Iterable, Sequence

from crane_sym.escapes import terminal_text

__all__ = ["fenced", "markdown_table", "markdown_text"]

#: What Markdown (CommonMark, GFM tables and strikethrough, dollar math) or HTML
#: reads as markup inside a line: brackets escaped, ``(`` ``!`` cannot make a
#: link or an image; ``#`` matters only at a line's start, which a caller writes.
_MARKUP = re.compile(r"([\\`*\[\]<>&$|~]|(?<![A-Za-z0-9])_|_(?![A-Za-z0-9]))")


def markdown_text(text: object) -> str:
    """``text`` as one line of literal Markdown text: whitespace runs (line
    breaks too) as one space, control characters as their escapes
    (:func:`crane_sym.escapes.terminal_text`: the Markdown is printed too), and
    every markup character backslash-escaped, which CommonMark allows for any
    ASCII punctuation (an ``_`` inside a word, which cannot start emphasis,
    as it is: ``safety_brakes``).

    Parameters
    ----------
    text : object
        Text from a file, or anything ``str`` writes as such.

    Examples
    --------
    >>> print(markdown_text("<b>x</b> *a* | $b$"))
    \\<b\\>x\\</b\\> \\*a\\* \\| \\$b\\$
    """
    return _MARKUP.sub(r"\\\1", terminal_text(" ".join(str(text).split())))


def fenced(text: str, info: str = "text") -> str:
    """``text`` verbatim in a code fence longer than any backtick run in it,
    so nothing inside can close the fence.

    Parameters
    ----------
    text : str
        The verbatim text.
    info : str, optional
        The fence's info string (the language).
    """
    longest = max((len(run) for run in re.findall(r"`+", text)), default=0)
    fence = "`" * max(3, longest + 1)
    return f"{fence}{info}\n{text}\n{fence}"

_RULES = {"l": "---", "r": "---:", "c": ":---:"}


def markdown_table(header: Sequence[object], rows: Iterable[Sequence[object]],
                   align: str | None = None) -> str:
    """A Markdown (GFM) table: the header, the rule, one line per row.

    Parameters
    ----------
    header : sequence of str
        The column titles, in order.
    rows : iterable of sequences
        One sequence of cells per row, as many as ``header``; each cell is
        written with ``str`` and must already be safe inside a table cell.
    align : str, optional
        One letter per column: ``l`` (the rule ``---``), ``r`` (``---:``) or
        ``c`` (``:---:``). Default: ``---`` for every column.

    Returns
    -------
    str
        The table, lines joined by ``\\n``, without a final newline:
        ``| a | b |``, ``| --- | ---: |``, then ``| 1 | 2 |`` per row.

    Raises
    ------
    ValueError
        If ``align`` or a row does not have one entry per column.

    Examples
    --------
    >>> print(markdown_table(["x", "y"], [[1, 2.5]], align="lr"))
    | x | y |
    | --- | ---: |
    | 1 | 2.5 |
    """
    width = len(header)
    align = "l" * width if align is None else align
    if len(align) != width or set(align) - set(_RULES):
        raise ValueError(f"align {align!r}: needs one of l, r, c for each of the "
                         f"{width} columns")
    lines = [_line(header), _line(_RULES[a] for a in align)]
    for k, row in enumerate(rows):
        row = list(row)
        if len(row) != width:
            raise ValueError(f"row {k} has {len(row)} cells, the header {width}: {row!r}")
        lines.append(_line(row))
    return "\n".join(lines)


def _line(cells: Iterable[object]) -> str:
    return "| " + " | ".join(str(c) for c in cells) + " |"
