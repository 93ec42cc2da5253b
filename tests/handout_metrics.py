"""How a walkthrough reads, in three numbers: its length in lines, its longest
line, and how many code names its prose carries.

A code name is what a teacher would have to explain away: a file or module
name, a dotted attribute, a function or variable name in snake case, a paper
symbol spelled in ASCII (``psi``, ``2pi``, ``sa1m``), a backtick code span, the
name of a tool, or an internal word of the checks ("the none check", the LaTeX
parser's messages). Prose is everything but math (``$…$``, ``$$…$$``), quotes
of the paper (``'…'``, ``«…»``) and fenced blocks (the paper's OCR and the
model's diagram, verbatim).

Run as a script to print the numbers of walkthrough files::

    python tests/handout_metrics.py walkthrough_001.md walkthrough_003.md

The tests import :func:`metrics` and :func:`code_names` from here.
"""
from __future__ import annotations

import re
import sys
from dataclasses import dataclass
from pathlib import Path

#: (kind, pattern) of a code name in prose.
CODE_PATTERNS: tuple[tuple[str, re.Pattern], ...] = (
    ("code span", re.compile(r"`[^`\n]+`")),
    ("file", re.compile(r"\b[\w.-]+\.(?:py|txt|toml|png|json|md|ipynb|csv)\b")),
    ("dotted name", re.compile(r"\b[a-z_]{2,}\.[A-Za-z_][A-Za-z0-9_]{2,}\b")),
    ("snake case", re.compile(r"\b[a-z]{3,}[a-z0-9]*(?:_[A-Za-z0-9]+)+\b")),
    ("constant", re.compile(r"\b[A-Z][A-Z0-9]{3,}_[A-Z0-9_]{3,}\b")),
    ("ASCII Greek", re.compile(
        r"(?<![\\\w])\d*(?:alpha|beta|gamma|epsilon|eps|zeta|theta|lambda|sigma|"
        r"omega|psi|phi|pi)(?:_[A-Za-z0-9]+|\d[a-z0-9]*)?\b")),
    ("Mathcad name", re.compile(r"\b(?:atw|xsum|xs|sa1m|sa1|da1|da2|xp|eps)\b")),
    ("tool", re.compile(r"\b(?:SymPy|sympy|mpmath|NumPy|numpy|SciPy|scipy|lark|"
                        r"nsimplify|lambdify)\b")),
    ("check internals", re.compile(
        r"\bnone check\b|\bparser context\b|No terminal matches|Token\(|\bcrane-sym\b")),
)
_FENCE = re.compile(r"^(`{3,})[^\n]*\n.*?^\1[ \t]*$", re.S | re.M)
_DISPLAY = re.compile(r"\$\$.*?\$\$", re.S)
_INLINE = re.compile(r"(?<!\\)\$[^$\n]+?(?<!\\)\$")
#: A quote of the paper ('ZJ7' read as LF): the paper's words, not code.
_QUOTE = re.compile(r"(?<![\w'])'[^'\n]*'(?![\w'])|«[^»\n]*»")


def prose(markdown: str) -> str:
    """``markdown`` without fenced blocks and math (each replaced by a space)."""
    text = _FENCE.sub(" ", markdown)
    text = _DISPLAY.sub(" ", text)
    return _QUOTE.sub(" ", _INLINE.sub(" ", text))


def code_names(markdown: str) -> list[tuple[str, str]]:
    """Every code name in the prose of ``markdown``: (kind, text), in order of kind."""
    text, found = prose(markdown), []
    for kind, pattern in CODE_PATTERNS:      # each span counted once, by its first kind
        found += [(kind, m.group(0)) for m in pattern.finditer(text)]
        text = pattern.sub(lambda m: " " * len(m.group(0)), text)
    return found


@dataclass(frozen=True)
class Metrics:
    """The three numbers of a walkthrough."""

    lines: int
    longest: int
    code_names: int

    def __str__(self) -> str:
        return (f"{self.lines} lines, longest {self.longest} characters, "
                f"{self.code_names} code names")


def metrics(markdown: str) -> Metrics:
    """Length in lines, longest line (characters) and number of code names."""
    lines = markdown.splitlines()
    return Metrics(len(lines), max((len(line) for line in lines), default=0),
                   len(code_names(markdown)))


def main(paths: list[str]) -> int:
    """Print the numbers of each file, and its code names by kind with ``-v``."""
    verbose = "-v" in paths
    for path in (p for p in paths if p != "-v"):
        text = Path(path).read_text(encoding="utf-8")
        print(f"{path}: {metrics(text)}")
        if verbose:
            kinds: dict[str, list[str]] = {}
            for kind, name in code_names(text):
                kinds.setdefault(kind, []).append(name)
            for kind, names in kinds.items():
                print(f"  {kind} ({len(names)}): {sorted(set(names))[:30]}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
