"""Markdown tables: one writer for every table the toolkit prints (the audit,
the walkthrough, the benches).

The writer only lays cells out; each caller formats its numbers and escapes
its text (a ``|`` inside a cell written ``\\|``) the way its readers need.
"""
from __future__ import annotations

from typing import Iterable, Sequence

__all__ = ["markdown_table"]

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
