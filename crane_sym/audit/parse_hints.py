"""What to write instead when SymPy's lark LaTeX parser stops: the construct it
stopped at, named, and the spelling it reads.

The parser reads a product written by juxtaposition only between plain
factors: ``(a + b) n`` reads, ``(a + b) n^2`` and ``n^2 (a + b)`` do not (its
grammar has no rule for a bracket beside a power), though both read with the
product written out, ``(a + b) \\cdot n^2``. Its own message gives only the
character and the column ("No terminal matches '^' ... col 20").
"""
from __future__ import annotations

import re

__all__ = ["parse_hint"]

_STOP = re.compile(r"No terminal matches '(.)' .*?col (\d+)")
#: A bracket closed just before a factor (``(a + b) n``, ``\right) n``, ``} n``).
_BRACKET_THEN_FACTOR = re.compile(r"(\)|\\right\)|\})(\s*)(\\?[A-Za-z]+(?:_\{?\w+\}?)?)\s*$")
#: A power just before (``n^2``, ``n^{2}``).
_POWER = re.compile(r"\^\s*(\{[^{}]*\}|\w)\s*$")


def parse_hint(text: str, message: str) -> str:
    """One clause naming the construct the parser stopped at and the spelling
    that reads, or "" when the message is not one it knows.

    Parameters
    ----------
    text : str
        The LaTeX the parser was given.
    message : str
        The first line of the parser's error.

    >>> parse_hint(r"(a + b) n^2", "No terminal matches '^' in the current "
    ...            "parser context, at line 1 col 10")
    "a bracket times a power with no sign between them ('(a + b) n^2'): write the product out, '(a + b) \\\\cdot n^2'"
    """
    stop = _STOP.search(message)
    if not stop:
        return ""
    char, col = stop.group(1), int(stop.group(2)) - 1
    before, after = text[:col], text[col:]
    if char == "^":
        near = _BRACKET_THEN_FACTOR.search(before)
        if near:
            start = near.start(3)
            power = re.match(r"\^\s*(\{[^{}]*\}|\w)", after)
            end = col + (power.end() if power else 1)
            head = text.rfind("(", 0, near.start(1)) if near.group(1) == ")" else near.start(1)
            shown = text[max(head, 0):end]
            fixed = text[max(head, 0):start].rstrip() + " \\cdot " + text[start:end]
            return (f"a bracket times a power with no sign between them ('{shown}'): "
                    f"write the product out, '{fixed}'")
    if char in "(\\" and _POWER.search(before):
        start = before.rfind("^")
        base = re.search(r"(\\?[A-Za-z]+(?:_\{?\w+\}?)?)\s*$", before[:start])
        head = base.start() if base else start
        shown = text[head:col + 1]
        fixed = before[head:].rstrip() + " \\cdot " + text[col:col + 1]
        return (f"a power times a bracket with no sign between them ('{shown}...'): "
                f"write the product out, '{fixed}...'")
    return f"the parser stops at '{char}' after '{before[-20:]}'"
