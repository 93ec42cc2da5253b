"""Long relations and wide matrices in rows a printed page holds.

A component model's energies, forces and equations of motion are sums of one
term per part; a model of seven bodies gives sums that run far past the right
edge of a page. A handout breaks them as a textbook does: the sum in aligned
rows, each continued with its sign (``T = a + b`` / ``+ c + d``). A matrix of
the state equations (x' = A x + b, one row and column per state) is shown
whole while it fits, else in blocks of whole columns, each labelled with the
columns it holds.

Widths are estimated from the LaTeX as it will be typeset (``typeset_width``,
in characters of the body text), not from the length of its source: a
subscript is smaller, a fraction as wide as its wider part, a command such as
``\\mathrm`` takes no room of its own.
"""
from __future__ import annotations

import re
from typing import Callable, Sequence

import sympy as sp

__all__ = ["WIDTH", "aligned_rows", "column_blocks", "sum_terms", "typeset_width"]

#: The widest row a handout writes, in characters of body text (A4 with the
#: page's margins holds about 80; math is set a little larger and spaced wider).
WIDTH = 60
#: Commands that draw nothing of their own (their argument is counted).
_SILENT = {"mathrm", "mathit", "mathbf", "operatorname", "left", "right", "dot", "ddot",
           "bar", "hat", "tilde", "vec", "begin", "end", "displaystyle", "text"}
#: Commands that draw a little space.
_SPACES = {",": 0.2, ";": 0.3, "quad": 1.0, "qquad": 2.0, " ": 0.3}
_TOKEN = re.compile(r"\\([A-Za-z]+|.)|([{}])|([_^])|(\s)|(.)", re.S)


def _group(tex: str, start: int) -> tuple[str, int]:
    """The braced group (or single token) at ``start``: its text and the index after it."""
    while start < len(tex) and tex[start].isspace():
        start += 1
    if start >= len(tex):
        return "", start
    if tex[start] != "{":
        m = _TOKEN.match(tex, start)
        return m.group(0), m.end()
    depth = 0
    for k in range(start, len(tex)):
        depth += {"{": 1, "}": -1}.get(tex[k], 0) if tex[k - 1:k] != "\\" else 0
        if depth == 0:
            return tex[start + 1:k], k + 1
    return tex[start + 1:], len(tex)


def typeset_width(tex: str) -> float:
    """The width of ``tex`` as typeset, in characters of body text: a
    sub- or superscript counts 0.7, a fraction its wider part, a command
    that only styles its argument nothing, an environment (``aligned``,
    ``pmatrix``) its widest cells column by column.

    Parameters
    ----------
    tex : str
        LaTeX math.

    Examples
    --------
    >>> typeset_width(r"\\frac{m_{\\mathrm{hook}}}{2}") < typeset_width("m_hook/2")
    True
    """
    width, k = 0.0, 0
    while k < len(tex):
        m = _TOKEN.match(tex, k)
        command, brace, script, space, char = m.groups()
        k = m.end()
        if command in ("frac", "dfrac", "tfrac"):
            num, k = _group(tex, k)
            den, k = _group(tex, k)
            width += max(typeset_width(num), typeset_width(den)) + 0.4
        elif command == "begin":
            env, k = _group(tex, k)
            end = tex.find(f"\\end{{{env}}}", k)
            end = len(tex) if end < 0 else end
            width += _table_width(tex[k:end]) + (2.0 if env.endswith("matrix") else 0.0)
            k = end + len(f"\\end{{{env}}}")
        elif script:
            arg, k = _group(tex, k)
            width += 0.7 * typeset_width(arg)
        elif command is not None:
            width += _SPACES.get(command, 0.0 if command in _SILENT else 1.0)
        elif char is not None:
            width += 1.6 if char in "=+-<>" else 1.0     # spaced relations and operators
    return width


def _table_width(body: str) -> float:
    """The width of an environment's rows ``a & b \\\\ c & d``: its columns side by side."""
    rows = [row.split("&") for row in re.split(r"\\\\", body)]
    columns = max(len(r) for r in rows)
    return sum(max(typeset_width(r[j]) if j < len(r) else 0.0 for r in rows) + 1.0
               for j in range(columns))


def _signed(terms: Sequence[str]) -> list[str]:
    """The terms of a sum as they are joined: the first as it is, each other
    with its sign in front (``+ a``, ``- b``)."""
    out = []
    for k, t in enumerate(terms):
        t = t.strip()
        if k and not t.startswith("-"):
            t = "+ " + t
        elif k:
            t = "- " + t[1:].lstrip()
        out.append(t)
    return out


def aligned_rows(lhs: str, terms: Sequence[str], tail: str = "", width: float = WIDTH) -> str:
    """``lhs = t1 + t2 + … [tail]`` as LaTeX, in aligned rows of at most
    ``width`` (``typeset_width``) when it does not fit on one line: the
    relation sign in the first row, each further row continued with the sign
    of its first term.

    Parameters
    ----------
    lhs : str
        The left side, LaTeX (``T``, ``Q_{q}``), or empty for an equation read
        as ``terms = rhs``.
    terms : sequence of str
        The terms of the sum, each LaTeX with its own sign.
    tail : str
        What follows the sum, LaTeX with its relation (``= Q``, ``\\approx 3.2``),
        or empty.
    width : float
        The widest row.
    """
    joined = _signed(terms) or ["0"]
    head = f"{lhs} = " if lhs else ""
    tail = f" {tail}" if tail else ""
    one = head + " ".join(joined) + tail
    if typeset_width(one) <= width:
        return one
    rows, current = [], ""
    for t in joined:
        if current and typeset_width(head + current + " " + t) > width:
            rows.append(current)
            current = t
        else:
            current = f"{current} {t}" if current else t
    if tail and typeset_width(head + current + tail) > width:
        rows.append(current)
        current = ""
    rows.append(current + tail)
    if lhs:
        body = [f"{lhs} ={{}} & {rows[0]}"] + [f"& {r}" for r in rows[1:]]
    else:
        body = [f"& {rows[0]}"] + [f"& \\quad {r}" for r in rows[1:]]
    return r"\begin{aligned}" + r" \\ ".join(body) + r"\end{aligned}"


def sum_terms(expr: sp.Expr, tex: Callable[[sp.Expr], str]) -> list[str]:
    """The terms of ``expr`` as LaTeX (``tex`` of each), in SymPy's printed order."""
    from sympy.printing.latex import LatexPrinter
    return [tex(t) for t in LatexPrinter()._as_ordered_terms(sp.sympify(expr))]


def column_blocks(name: str, entries: Sequence[Sequence[str]],
                  width: float = WIDTH) -> list[tuple[range, str]]:
    """A matrix as LaTeX displays: ``name = (…)`` when it fits in ``width``, else
    blocks of as many whole columns as fit, each ``name_{[:, k…l]}``.

    Parameters
    ----------
    name : str
        The matrix's name, LaTeX (``A``).
    entries : sequence of sequence of str
        The entries, LaTeX, row by row.
    width : float
        The widest display.

    Returns
    -------
    list of (range, str)
        The columns of each block (0-based) and its display.
    """
    n = len(entries[0]) if entries else 0
    widths = [max(typeset_width(row[j]) for row in entries) + 2.0 for j in range(n)]
    if sum(widths) + typeset_width(name) + 4 <= width:
        return [(range(n), _pmatrix(name, entries, range(n)))]
    blocks, start = [], 0
    while start < n:
        stop, used = start, 10.0                # the label, the sign, the brackets
        while stop < n and (stop == start or used + widths[stop] <= width):
            used += widths[stop]
            stop += 1
        label = (f"{name}_{{[:,\\,{start + 1}]}}" if stop == start + 1 else
                 f"{name}_{{[:,\\,{start + 1}\\ldots {stop}]}}")
        blocks.append((range(start, stop), _pmatrix(label, entries, range(start, stop))))
        start = stop
    return blocks


def _pmatrix(label: str, entries: Sequence[Sequence[str]], cols: range) -> str:
    body = r" \\ ".join(" & ".join(row[j] for j in cols) for row in entries)
    return f"{label} = \\begin{{pmatrix}} {body} \\end{{pmatrix}}"
