"""Printed LaTeX read by machine: a small pre-pass, then SymPy's LaTeX parser.

SymPy's parser with the ``lark`` backend builds expressions from a grammar,
without ``eval``. It reads little of what a dynamics paper prints, so a
pre-pass rewrites the print first, each rule a small function tested on its
own (``tests/test_machine_read.py``):

- ``names``: every name the parser cannot read (ẋ as ``\\dot{x}``, Greek
  capitals, ``P_{\\text{дин}}``, ``(x_2 - x_1)^*``) is replaced by a token it
  can (``V_{pqa}``), mapped back to the derivation's symbol after parsing;
  without this ``\\dot{x}`` would not parse, or would parse as ``dot·x``;
- ``layout``: equation numbers, ``\\quad``, ``\\left``/``\\right``, braces and
  square brackets used as parentheses, ``\\cdot`` at a line break, decimal
  commas, ``%``, Mathcad's ``:=``;
- ``split``: one print holding several relations (``\\quad``, ``;``, rows of
  ``cases`` and ``aligned``, ``\\Leftrightarrow``, a chain ``a = b = c``) gives
  one candidate per relation.

A print the parser still cannot read is ``unreadable`` with its reason.

The Earley parser is slow, so each side's parse is kept in a committed table
(``crane_sym.audit.parse_table``, ``generated/machine_reading.json``), read
before the parser is asked; :func:`parser` is the fingerprint the table is
valid for.
"""
from __future__ import annotations

import hashlib
import inspect
import re
import warnings
from dataclasses import dataclass
from functools import lru_cache
from pathlib import Path

import sympy as sp
from sympy.utilities.exceptions import SymPyDeprecationWarning

from crane_sym.audit.parse_hints import parse_hint
from crane_sym.audit.parse_table import ParseTable, entry_for, expression, form, rebuilt

__all__ = ["Unreadable", "candidates", "layout", "parse", "placeholder", "split",
           "wrap_calls", "bound_variables", "BOUND", "parse_side", "parse_table",
           "parser"]


class Unreadable(ValueError):
    """The parser cannot read a print; the message says why."""


def placeholder(k: int) -> str:
    """The ``k``-th token the parser reads as one symbol: ``V_{pqa}``, ``V_{pqb}``, ...
    (letters only: the grammar takes no digits in a multi-letter subscript)."""
    letters = ""
    k += 1
    while k:
        k, r = divmod(k - 1, 26)
        letters = chr(ord("a") + r) + letters
    return f"V_{{pq{letters}}}"


_EQ_NUMBER = re.compile(r"(\\quad|\\qquad|,|;|\.)?\s*\(\d+\)\s*[.,;]?\s*$")
_TEXT = re.compile(r"\\(?:text|mathrm)\{([^{}]*)\}")
_ENV = re.compile(r"\\(?:begin|end)\{(?:cases|aligned|array|matrix)\}(?:\{[^{}]*\})?")
_DECIMAL = re.compile(r"(?<=\d),(?=\d)")


def layout(tex: str) -> str:
    """The print with its typesetting reduced to what the parser reads: no
    equation number, ``\\text``, ``\\left``/``\\right``, spacing commands or
    environments; ``{``/``}`` after ``\\left``/``\\right`` and ``[``/``]`` as
    parentheses; decimal commas as points; ``%`` as a factor 10⁻²; ``:=`` as ``=``."""
    tex = _EQ_NUMBER.sub("", tex.strip())
    tex = _TEXT.sub(" ", tex)          # prose ("где", "или"): names are replaced before
    tex = _ENV.sub(" ", tex)
    tex = tex.replace(":=", "=")
    tex = re.sub(r"\\(?:left|right)\s*\.", " ", tex)
    tex = re.sub(r"\\left\s*\\\{|\\left\s*\[|\\left\s*\(", "(", tex)
    tex = re.sub(r"\\right\s*\\\}|\\right\s*\]|\\right\s*\)", ")", tex)
    tex = re.sub(r"\\left\s*\||\\right\s*\|", "|", tex)
    tex = tex.replace("\\{", "(").replace("\\}", ")").replace("[", "(").replace("]", ")")
    tex = re.sub(r"\\[,;!:]|\\ |~", " ", tex)
    tex = _DECIMAL.sub(".", tex)
    tex = re.sub(r"\}\s*\(", r"} \\cdot (", tex)    # \frac{a}{b}(x): a product
    tex = re.sub(r"\s*\\?%", r" \\cdot 10^{-2}", tex)
    return " ".join(tex.split()).strip(" .,;")


_SEPARATORS = re.compile(r"\\quad|\\qquad|;|\\\\|\\Leftrightarrow|\\Rightarrow|&")


def split(tex: str) -> list[str]:
    """The relations of a print: its pieces between separators, each chain
    ``a = b = c`` as ``a = b``, ``b = c`` and ``a = c``; a piece without ``=`` is
    kept as an expression."""
    out: list[str] = []
    pieces = [p.strip(" ,.") for p in _SEPARATORS.split(tex)]
    merged: list[str] = []
    for piece in pieces:       # an aligned row "&= ..." continues the one before
        if merged and (piece.startswith("=") or merged[-1].endswith("=")):
            merged[-1] = merged[-1] + " " + piece
        elif piece:
            merged.append(piece)
    for piece in merged:
        members = [m.strip() for m in _top_level_split(piece, "=") if m.strip()]
        if len(members) <= 2:
            out.append(" = ".join(members))
            continue
        out += [f"{a} = {b}" for a, b in zip(members, members[1:])]
        out.append(f"{members[0]} = {members[-1]}")
    return [c for c in out if c]


def _top_level_split(text: str, sep: str) -> list[str]:
    parts, depth, last = [], 0, 0
    for i, ch in enumerate(text):
        depth += ch in "({" and 1 or ch in ")}" and -1 or 0
        if ch == sep and depth == 0 and text[i - 1:i] not in ("<", ">", "\\", ":"):
            parts.append(text[last:i])
            last = i + 1
    parts.append(text[last:])
    return parts


_CALL = re.compile(r"\\(?:sin|cos|tan|cot|sinh|cosh|tanh|exp|ln|log|arcsin|arccos|arctan)"
                   r"(?:\s*\^\s*\{?\d\}?)?\s*\(")


def wrap_calls(tex: str) -> str:
    """Each ``\\sin(...)`` (and its kin) in parentheses of its own, so that the
    parser cannot take what follows into the argument: ``\\sin(x)/(y)`` is
    ``sin(x)/y``, not ``sin(x/y)``."""
    out, i = [], 0
    for m in _CALL.finditer(tex):
        if m.start() < i:
            continue
        depth, j = 1, m.end()
        while j < len(tex) and depth:
            depth += {"(": 1, ")": -1}.get(tex[j], 0)
            j += 1
        if depth:
            break
        out += [tex[i:m.start()], "(", tex[m.start():j], ")"]
        i = j
    return "".join(out + [tex[i:]])


#: The letter a bound variable of an integral is printed as after ``bound_variables``.
BOUND = "w"
_INTEGRAL = re.compile(r"\\int(?P<body>.*?)\bd\s*(?P<var>\\[A-Za-z]+|[A-Za-z])(?![A-Za-z])")


def bound_variables(tex: str) -> str:
    """The variable of each ``\\int ... d\\theta`` renamed ``w`` inside that integral,
    before names are replaced (a bound variable is no symbol of the derivation,
    and the parser reads only a letter after the ``d``).

    Parameters
    ----------
    tex : str
        The print's LaTeX.
    """
    def rename(m: re.Match) -> str:
        var = re.escape(m.group("var"))
        body = re.sub(var + r"(?![A-Za-z])", BOUND, m.group("body"))
        return f"\\int{body} d{BOUND}"
    return _INTEGRAL.sub(rename, tex)


def _depth(e: sp.Basic) -> int:
    inner = max((_depth(a) for a in e.args), default=0)
    return inner + isinstance(e, sp.Function)


def _resolve(tree, functions: frozenset = frozenset()) -> sp.Basic:
    """An ambiguous parse (lark's ``_ambig``) resolved as a reader would: keep every
    printed symbol, call as a function only the names in ``functions``, nest
    functions as little as possible (``A \\cos(pt) + B \\sin(pt)`` is two terms,
    not ``A cos(B sin(pt) + pt)``)."""
    if isinstance(tree, sp.Basic):
        return tree
    options = [_resolve(c, functions) for c in getattr(tree, "children", [])]
    options = [o for o in options if isinstance(o, sp.Basic)]
    if not options:
        raise Unreadable("the parser returned no expression")

    def plain(name) -> str:
        return str(name).replace("{", "").replace("}", "")

    def cost(e: sp.Basic) -> tuple:
        calls = [plain(type(c).__name__) for c in e.atoms(sp.core.function.AppliedUndef)]
        bad = sum(c not in functions for c in calls)
        symbols = [s for s in e.free_symbols if plain(s.name) not in functions]
        inner = sum(sp.count_ops(a) for f in e.atoms(sp.Function) for a in f.args)
        return (bad, -len(symbols), bad - len(calls), _depth(e), inner, sp.count_ops(e))
    return min(options, key=cost)


@dataclass(frozen=True)
class Parsed:
    """One relation of a print, parsed (``rhs`` alone when it has no ``=``)."""

    source: str
    lhs: sp.Basic | None
    rhs: sp.Basic


def parse(candidate: str, functions: frozenset = frozenset()) -> Parsed:
    """One candidate relation parsed by SymPy's lark parser (no ``eval``), an
    ambiguity resolved with ``functions`` the names that are functions; raises
    :class:`Unreadable` with the parser's reason.

    Parameters
    ----------
    candidate : str
        One relation (or expression) of a print, after the layout pass.
    functions : frozenset of str, optional
        The names to read as functions.
    """
    sides = [s.strip() for s in _top_level_split(candidate, "=")]
    if len(sides) > 2 or not all(sides):
        raise Unreadable(f"not one relation: {candidate!r}")
    out = [parse_side(side, functions) for side in sides]
    return Parsed(candidate, out[0] if len(out) == 2 else None, out[-1])


@lru_cache(maxsize=4096)
def parse_side(side: str, functions: frozenset) -> sp.Basic:
    """One side parsed: from the committed table of parses when it holds the
    side (``crane_sym.audit.parse_table``), else by the Earley parser, which is
    slow (papers repeat their prints: each side is parsed once per process).
    A fresh parse is returned as the table would give it (its names plain
    strings, not lark's tokens), so a run reads the same with or without it.

    Parameters
    ----------
    side : str
        One side of a relation, after the layout pass.
    functions : frozenset of str
        The names to read as functions.
    """
    table = parse_table()
    entry = table.lookup(side, functions)
    if entry is None:
        try:
            parsed = _parse_live(side, functions)
        except Unreadable as why:
            table.keep(entry_for(side, functions, None, str(why)))
            raise
        entry = entry_for(side, functions, parsed)
        table.keep(entry)
        if "live" in entry:
            return parsed
    if "unreadable" in entry:
        raise Unreadable(entry["unreadable"])
    return rebuilt(entry["form"])


def _parse_live(side: str, functions: frozenset) -> sp.Basic:
    """One side parsed by SymPy's lark parser, an ambiguity resolved by ``_resolve``."""
    from sympy.parsing.latex import parse_latex
    try:
        with warnings.catch_warnings():    # the lark transformer's Mul of a Tuple
            warnings.simplefilter("ignore", SymPyDeprecationWarning)
            return _resolve(parse_latex(wrap_calls(side), backend="lark"), functions)
    except Unreadable:
        raise
    except Exception as err:       # lark's UnexpectedInput and its kin
        first = str(err).splitlines()[0] if str(err) else type(err).__name__
        hint = parse_hint(wrap_calls(side), first)
        raise Unreadable(f"the parser cannot read {side!r}: {first}"
                         + (f"; {hint}" if hint else "")) from None


def parser() -> dict[str, str]:
    """SymPy's and lark's versions and a fingerprint of what a parse depends on:
    both versions, the grammar files and the source of the live parse."""
    import lark
    grammar = Path(sp.__file__).parent / "parsing" / "latex" / "lark" / "grammar"
    digest = hashlib.sha256(f"{sp.__version__} {lark.__version__}".encode())
    for path in sorted(grammar.glob("*.lark")):
        digest.update(path.read_bytes())
    for part in (_parse_live, wrap_calls, _resolve, _depth, form, expression):
        try:
            digest.update(inspect.getsource(part).encode("utf-8"))
        except OSError:            # no source installed: a fingerprint no table has
            digest.update(part.__code__.co_code)
    return {"sympy": sp.__version__, "lark": lark.__version__,
            "fingerprint": digest.hexdigest()[:16]}


@lru_cache(maxsize=1)
def parse_table() -> ParseTable:
    """The committed table of parses, read once per process (empty when its
    fingerprint is not this parser's: then every side is parsed afresh)."""
    return ParseTable.read(parser()["fingerprint"])


def candidates(tex: str) -> list[str]:
    """The relations of a print after the layout pass (names already replaced).

    Parameters
    ----------
    tex : str
        The print's LaTeX, its names already replaced by tokens.
    """
    return split(layout(tex))
