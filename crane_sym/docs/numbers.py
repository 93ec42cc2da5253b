"""Math a handout can show: numbers to the print's digits, long closed forms
with named intermediate quantities, TeX that renders, and a checker of it.

A walkthrough puts a derived value beside a printed one; a teacher compares
them only if both are decimals to the same digits (``printed_digits``,
``decimal``). A derived relation whose LaTeX would run past ``LIMIT``
characters is written as a textbook does, "…, with κ₁ = …": the largest
repeated pieces are named until every line fits (``named_lines``). The paper's
own LaTeX is never rewritten, only broken into lines at its row breaks and
operators (``broken_lines``, whitespace only). ``math_errors`` reads a piece of
math as TeX does (``%`` starts a comment, braces and ``\\left``/``\\right`` and
environments must pair) and converts it to MathML, the form the HTML handout
shows, failing on a command the converter does not know.
"""
from __future__ import annotations

import math
import re

import sympy as sp

from crane_sym.latex import cyrillic_as_text, latex

__all__ = ["LIMIT", "broken_lines", "decimal", "escape_specials", "is_number", "is_value",
           "math_errors", "mathml", "named_lines", "printed_digits"]

#: The longest line of LaTeX a handout writes.
LIMIT = 300
#: Letters for named intermediate quantities, the first the paper does not use.
_LETTERS = (r"\kappa", r"\chi", r"\eta", r"\zeta")


# --- numbers ---------------------------------------------------------------------------
def printed_digits(value: sp.Expr, tolerance: float = 0.0) -> int:
    """Decimal places of a printed number: from the half unit of its last digit
    (``tolerance``, relative, as a ``PublishedFormula`` keeps it), else the
    fewest places that write ``value`` exactly (at most 6)."""
    v = abs(float(value))
    if tolerance > 0 and v > 0:
        unit = 2 * tolerance * v
        return max(0, round(-math.log10(unit)))
    for places in range(7):
        if (sp.nsimplify(value) * 10 ** places).is_integer:
            return places
    return 6


def decimal(value: sp.Expr | float, places: int | None = None,
            percent: bool = False) -> str:
    """``value`` as a decimal with ``places`` decimals (default: 4 significant
    digits), in percent (``places`` then counts the percent's decimals)."""
    v = float(value) * (100 if percent else 1)
    if places is None:
        places = max(0, 3 - math.floor(math.log10(abs(v)))) if v else 0
    text = f"{v:.{max(places, 0)}f}"
    if text.startswith("-") and float(text) == 0:
        text = text[1:]
    return text + (r"\,\%" if percent else "")


def is_number(expr: sp.Basic) -> bool:
    """True for an expression without free symbols that evaluates to a real."""
    return isinstance(expr, sp.Expr) and expr.is_number and expr.is_real is not False


def is_value(relation: sp.Basic) -> bool:
    """True for a relation that gives one quantity a number (``N = 0.903``), not
    an equation that equals zero."""
    return (isinstance(relation, sp.Equality) and relation.lhs.is_Symbol
            and is_number(relation.rhs))


# --- TeX specials and line breaks ----------------------------------------------------
_SPECIAL = re.compile(r"(?<!\\)([%#])")


def escape_specials(tex: str) -> str:
    """``tex`` with TeX's comment and parameter characters (``%``, ``#``) escaped,
    so that a printed ``5%`` renders as 5 % and not as 5, and a decimal comma
    braced (``0{,}90``), so that it is not set as a punctuation comma."""
    return re.sub(r"(?<=\d),(?=\d)", "{,}", _SPECIAL.sub(r"\\\1", tex))


def broken_lines(tex: str, limit: int = LIMIT, width: int = 160) -> list[str]:
    """The paper's LaTeX in lines of at most ``limit`` characters where it can be
    broken: after a row break ``\\\\``, then after a space that follows an
    operator once a line passes ``width``. Only whitespace changes, so the
    print stays as printed; no line starts with an operator (Markdown would
    read ``- …`` or ``+ …`` as a list)."""
    lines = []
    for row in re.split(r"(?<=\\\\)\s+", tex.strip()):
        current = ""
        for piece in re.split(r"(?<=[=+\-,;]) ", row):
            if current and len(current) + len(piece) + 1 > width:
                lines.append(current)
                current = piece
            else:
                current = f"{current} {piece}" if current else piece
        lines.append(current)
    return [line for line in lines if line.strip()]


# --- named intermediate quantities ---------------------------------------------------
def _tex(expr: sp.Basic, names: dict) -> str:
    if isinstance(expr, sp.Equality):
        return _tex(expr.lhs, names) + " = " + _tex(expr.rhs, names)
    return cyrillic_as_text(latex(expr, symbol_names=names))


def _letter(names: dict, used: str) -> str:
    taken = " ".join(names.values()) + " " + used
    return next((x for x in _LETTERS if x not in taken), _LETTERS[0])


def _candidates(expr: sp.Basic, names: dict, budget: int) -> list[tuple[int, sp.Basic]]:
    """Subexpressions worth a name, best first: a repeated piece by the LaTeX it
    saves (as a textbook names the frequency that occurs three times), then a
    single piece by its length; at most ``budget`` characters, no atoms."""
    counts: dict[sp.Basic, int] = {}
    for sub in sp.preorder_traversal(expr):
        if sub is expr or sub.is_Atom or isinstance(sub, (sp.Equality, sp.Tuple)):
            continue
        if isinstance(sub, sp.Expr) and not isinstance(sub, sp.Piecewise):
            counts[sub] = counts.get(sub, 0) + 1
    scored = []
    for sub, n in counts.items():
        length = len(_tex(sub, names))
        if 24 <= length <= budget:
            scored.append(((n - 1) * length, length, sub))
    scored.sort(key=lambda s: (-s[0], -s[1], sp.default_sort_key(s[2])))
    return [(saved, sub) for saved, _, sub in scored]


def named_lines(statement: sp.Basic, names: dict | None = None,
                limit: int = LIMIT) -> tuple[str, list[str]]:
    """A relation in lines of at most ``limit`` characters of LaTeX.

    Parameters
    ----------
    statement : sympy.Basic
        A relation or an expression.
    names : dict, optional
        The paper's LaTeX names of symbols.
    limit : int
        The longest line allowed.

    Returns
    -------
    (str, list of str)
        The relation, with the largest repeated pieces replaced by named
        quantities κ₁, κ₂, … until each line fits, and the definitions
        ``κ_{i} = …`` in the order they were named (empty when it fits as is).
    """
    names = dict(names or {})
    main = statement
    if len(_tex(main, names)) <= limit:
        return _tex(main, names), []
    letter = _letter(names, _tex(main, names))
    defs: list[tuple[sp.Symbol, sp.Basic]] = []
    for k in range(1, 60):
        lines = [(None, main)] + defs
        long = [(s, e) for s, e in lines
                if len(_tex(e if s is None else sp.Eq(s, e, evaluate=False), names)) > limit]
        if not long:
            break
        _, expr = max(long, key=lambda se: len(_tex(se[1], names)))
        found = _candidates(expr, names, limit - 20)
        if not found:
            break
        piece = found[0][1]
        kappa = sp.Symbol(f"kappa_{k}")
        names[kappa] = rf"{letter}_{{{k}}}"
        main = main.xreplace({piece: kappa})
        defs = [(s, e.xreplace({piece: kappa})) for s, e in defs] + [(kappa, piece)]
    return (_tex(main, names),
            [_tex(s, names) + " = " + _tex(e, names) for s, e in defs])


# --- the checker ---------------------------------------------------------------------
_COMMAND = re.compile(r"\\([A-Za-z]+)")
_ENV = re.compile(r"\\(begin|end)\{(\w+\*?)\}")


def _braces_balance(tex: str) -> bool:
    depth = 0
    for m in re.finditer(r"(?<!\\)[{}]", tex):
        depth += 1 if m.group(0) == "{" else -1
        if depth < 0:
            return False
    return depth == 0


def mathml(tex: str, display: bool = False) -> str:
    """MathML of ``tex`` (``latex2mathml``), ``aligned`` set as an array (the
    converter has no ``aligned``), display or inline; allow-listed and escaped
    (:func:`crane_sym.docs.safe_mathml.safe_mathml`)."""
    from latex2mathml.converter import convert_to_element

    from crane_sym.docs.safe_mathml import safe_mathml

    def aligned(m: re.Match) -> str:
        body = m.group(1)
        cols = 1 + max(row.count("&") for row in body.split(r"\\"))
        return (r"\begin{array}{" + ("rl" * cols)[:cols] + "}" + body + r"\end{array}")

    tex = re.sub(r"\\begin\{aligned\}(.*?)\\end\{aligned\}", aligned, tex, flags=re.S)
    return safe_mathml(convert_to_element(tex, display="block" if display else "inline"))


def math_errors(tex: str) -> list[str]:
    """What stops ``tex`` from rendering as written: a TeX comment (``%``) or
    parameter (``#``) character, unbalanced braces, ``\\left`` without
    ``\\right``, an environment not closed, a command the MathML converter does
    not know, or a conversion error. Empty when it renders."""
    errors = []
    if _SPECIAL.search(tex):
        errors.append("an unescaped % or # (TeX reads the rest of the line as a "
                      "comment, or a macro parameter)")
    if not _braces_balance(tex):
        errors.append("unbalanced braces")
    if len(re.findall(r"\\left\b", tex)) != len(re.findall(r"\\right\b", tex)):
        errors.append(r"\left and \right do not pair")
    stack = []
    for kind, name in _ENV.findall(tex):
        if kind == "begin":
            stack.append(name)
        elif not stack or stack.pop() != name:
            errors.append(rf"\end{{{name}}} closes no \begin{{{name}}}")
    if stack:
        errors.append(rf"\begin{{{stack[-1]}}} not closed")
    if errors:
        return errors
    try:
        out = mathml(tex)
    except Exception as exc:   # the converter's own parse errors
        return [f"the MathML converter fails: {type(exc).__name__}: {exc}"]
    unknown = sorted(set(re.findall(r">\s*\\([A-Za-z]+)", out)))
    return [rf"unknown command \{u}" for u in unknown]


def short_exact(value: sp.Expr, limit: int = 40) -> bool:
    """True when the exact form of a number is short enough to show beside its
    decimal (a fraction, π over a fraction), never a Float."""
    return not value.has(sp.Float) and len(latex(value)) <= limit and not value.is_Integer
