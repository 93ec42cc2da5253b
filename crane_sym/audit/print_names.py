"""The derivation's names as a paper prints them, for reading prints by machine.

SymPy's LaTeX parser reads a Latin letter with a plain subscript (``m_1``,
``M_{SB}``) and little else. The vocabulary gives every way a symbol of the
derivation may be printed (its LaTeX as the derivation prints it, its paper
name from ``LATEX_NAMES``, ẋ to x⁗ of a coordinate as dots and as
``x^{(IV)}``, in a Mathcad form the typewriter names with their subscripts
flattened as the OCR flattens them); the names pass replaces each name the
parser cannot read by a token it can (``V_{pqa}``), the calls pass each call
``F(arg)`` of a function the derivation defines by a token for that call, and
:func:`map_symbols` turns the parsed expression back into the derivation's
symbols, refusing a name the derivation does not have.
"""
from __future__ import annotations

import re

import sympy as sp
from sympy.core.function import AppliedUndef

from crane_sym.derivation import Derivation
from crane_sym.latex import latex
from crane_sym.audit.latex_parse import BOUND, Unreadable, layout, parse_side, placeholder
from crane_sym.symbols import COORDINATE

__all__ = ["BOUND_SYMBOL", "calls_pass", "cached_vocabulary", "map_symbols", "names_pass",
           "vocabulary"]

#: What the parser reads natively: a Latin letter with a plain subscript.
_NATIVE = re.compile(r"^[A-Za-z](_\{?[A-Za-z0-9]+\}?)?$")
_ROMAN = {1: "I", 2: "II", 3: "III", 4: "IV"}
_WRAPPERS = re.compile(r"\\(?:text|mathrm|mathit|mathtt|operatorname)\s*")
#: The one symbol every bound variable of an integral becomes.
BOUND_SYMBOL = sp.Dummy("bound")


def _skeleton(tex: str) -> list[str]:
    """A name as atoms (commands and characters), without braces, spaces and
    ``\\text``-like wrappers, so ``\\dot{x}_{1}`` and ``\\dot x_1`` are one name."""
    tex = _WRAPPERS.sub("", tex)
    return [a for a in re.findall(r"\\[A-Za-z]+|\S", tex) if a not in "{}"]


def _compiled(key: str, _seen: dict = {}) -> re.Pattern:  # noqa: B006 (a cache)
    if key not in _seen:
        _seen[key] = _pattern(key.split())
    return _seen[key]


def _pattern(atoms: list[str]) -> re.Pattern:
    gap = r"(?:[\s{}]|\\(?:text|mathrm|mathit|mathtt)\b)*"
    body = gap.join(re.escape(a) for a in atoms)
    tail = r"(?![A-Za-z0-9])" if re.match(r"[\\A-Za-z0-9]", atoms[-1][-1]) else ""
    head = r"(?<![A-Za-z\\])" if atoms[0][0].isalpha() else ""
    return re.compile(head + body + tail)


_CACHE: dict[tuple, tuple] = {}


def cached_vocabulary(d: Derivation, typewriter: bool) -> tuple[dict, frozenset]:
    """The vocabulary and its function names, built once per derivation."""
    key = (id(d), typewriter, len(d.symbols))
    if key not in _CACHE:
        vocab = vocabulary(d, typewriter)
        functions = frozenset(k.replace(" ", "") for k, v in vocab.items()
                              if isinstance(v, AppliedUndef))
        _CACHE[key] = (vocab, functions)
    return _CACHE[key]


def vocabulary(d: Derivation, typewriter: bool = False) -> dict[str, sp.Basic]:
    """Every way the derivation's symbols may be printed -> the symbol: the LaTeX
    the derivation prints and ``latex_names``, ẋ and ẍ of each coordinate, the
    symbol's own name, π; with ``typewriter`` (a Mathcad form) the ``\\mathtt``
    names bare, ahead of the others.

    Parameters
    ----------
    d : Derivation
        The derivation whose symbols (and ``latex_names``) are the names.
    typewriter : bool, optional
        Whether the print is a Mathcad form.
    """
    names: dict[str, sp.Basic] = {}

    def add(tex: str, expr: sp.Basic, first: bool = False) -> None:
        key = " ".join(_skeleton(tex))
        if key and (first or key not in names):
            names[key] = expr
    if typewriter:             # a Mathcad form, its subscripts flattened by the OCR too
        for expr, tex in d.latex_names.items():
            if "\\mathtt" in tex:
                add(tex, expr, first=True)
                add(" ".join(a for a in _skeleton(tex) if a != "_"), expr, first=True)
    for entry in d.symbols:
        expr = entry.expr
        add(d.latex_names.get(expr, ""), expr)
        add(latex(expr, symbol_names=d.latex_names), expr)
        add(entry.name, expr)
        if entry.role == COORDINATE and isinstance(expr, AppliedUndef):
            t, name = expr.args[0], latex(expr, symbol_names=d.latex_names)
            for n in (1, 2, 3, 4):
                add(latex(expr.diff(t, n), symbol_names=d.latex_names), expr.diff(t, n))
                for mark in (str(n), _ROMAN[n]):            # x_2^{(IV)}
                    add(f"{name}^{{({mark})}}", expr.diff(t, n))
    add(r"\pi", sp.pi)
    return names


def _replace(tex: str, pattern: re.Pattern, token: str) -> str:
    """``tex`` with each match of ``pattern`` replaced by `` token ``, taking the
    closing braces of the braces the match opened (``\\dot{x`` takes its ``}``)."""
    out, last = [], 0
    for m in pattern.finditer(tex):
        end, depth = m.end(), m.group(0).count("{") - m.group(0).count("}")
        while depth > 0:
            rest = tex[end:]
            stripped = rest.lstrip()
            if not stripped.startswith("}"):
                break
            end += len(rest) - len(stripped) + 1
            depth -= 1
        out += [tex[last:m.start()], f" {token} "]
        last = end
    return "".join(out + [tex[last:]])


def names_pass(tex: str, vocab: dict[str, sp.Basic],
               tokens: dict[str, sp.Basic]) -> str:
    """The print with every name the parser cannot read replaced by a token (added
    to ``tokens``); names the parser reads (``m_1``) are left for the mapping.

    Parameters
    ----------
    tex : str
        The print's LaTeX.
    vocab : dict of str to Basic
        The names (:func:`vocabulary`).
    tokens : dict of str to Basic
        The tokens given so far, added to.
    """
    complex_names = [k for k in vocab if not _NATIVE.match(k.replace(" ", ""))]
    for key in sorted(complex_names, key=lambda k: -len(k.split())):
        if not all(atom in tex for atom in key.split()):
            continue                # a match holds each atom as printed
        pattern = _compiled(key)
        if pattern.search(tex):
            token = placeholder(len(tokens))
            tokens[_plain(token)] = vocab[key]
            tex = _replace(tex, pattern, token)
    return tex


def calls_pass(tex: str, vocab: dict[str, sp.Basic], tokens: dict[str, sp.Basic]) -> str:
    """Each call ``F(arg)`` of a function of the derivation (by its name, or by the
    token the names pass gave it) replaced by a token for ``F(arg)``, ``arg`` read
    on its own: the parser takes ``S(θ)`` inside an integral for ``S·θ``.

    Parameters
    ----------
    tex : str
        The print's LaTeX after :func:`names_pass`.
    vocab : dict of str to Basic
        The names (:func:`vocabulary`).
    tokens : dict of str to Basic
        The tokens given so far, added to.
    """
    functions = {k.replace(" ", ""): v for k, v in vocab.items() if isinstance(v, AppliedUndef)
                 and _NATIVE.match(k.replace(" ", ""))}
    functions |= {k: v for k, v in tokens.items() if isinstance(v, (AppliedUndef,
                                                                   sp.Derivative))}
    for name in sorted(functions, key=len, reverse=True):
        atoms = _skeleton(name.replace("_", "_{", 1) + "}" if "_" in name else name)
        head = re.compile(_pattern(atoms).pattern + r"[\s}]*\(")
        start = 0
        while (m := head.search(tex, start)) is not None:
            depth, j = 1, m.end()
            while j < len(tex) and depth:
                depth += {"(": 1, ")": -1}.get(tex[j], 0)
                j += 1
            try:
                arg = read_expression(tex[m.end():j - 1], vocab, tokens)
            except Unreadable:
                start = m.end()
                continue
            f = functions[name]
            if isinstance(f, sp.Derivative):      # \ddot{Q}(t): the derivative, at t only
                if arg != f.variables[0]:
                    start = m.end()
                    continue
                call = f
            else:
                call = f.func(arg)
            token = placeholder(len(tokens))
            tokens[_plain(token)] = call
            tex = tex[:m.start()] + f" {token} " + tex[j:]
            start = m.start()
    return tex


def read_expression(tex: str, vocab: dict[str, sp.Basic],
                    tokens: dict[str, sp.Basic]) -> sp.Basic:
    """One expression of a print (a call's argument) read on its own."""
    tex = calls_pass(names_pass(tex, vocab, tokens), vocab, tokens)
    return map_symbols(parse_side(layout(tex), frozenset()), vocab, tokens)


def _plain(name) -> str:
    return str(name).replace("{", "").replace("}", "")


def map_symbols(expr: sp.Basic, vocab: dict[str, sp.Basic],
                tokens: dict[str, sp.Basic]) -> sp.Basic:
    """The parsed expression in the derivation's symbols; raises Unreadable on a
    name the derivation does not have.

    Parameters
    ----------
    expr : Basic
        What the parser returned.
    vocab : dict of str to Basic
        The names (:func:`vocabulary`).
    tokens : dict of str to Basic
        The tokens of the names and calls passes.
    """
    native = {k.replace(" ", ""): v for k, v in vocab.items()}

    def symbol_for(name: str) -> sp.Basic:
        key = str(name).replace("{", "").replace("}", "")
        if key in tokens:
            return tokens[key]
        if key == BOUND:
            return BOUND_SYMBOL
        if key in native:
            return native[key]
        if key == "e":
            return sp.E
        raise Unreadable(f"no symbol of the derivation is printed {name!r}")
    calls = {}
    for call in sorted(expr.atoms(AppliedUndef), key=sp.default_sort_key):   # one message a run
        target = symbol_for(type(call).__name__)
        args = tuple(map_symbols(a, vocab, tokens) for a in call.args)
        if isinstance(target, AppliedUndef) and len(target.args) == len(args):
            calls[call] = target.func(*args)       # S(θ) of the function S(t)
        else:
            raise Unreadable(f"{call} is not a function the derivation defines")
    expr = expr.xreplace(calls)
    subs = {s: symbol_for(s.name) for s in sorted(expr.free_symbols, key=sp.default_sort_key)}
    mapped = expr.xreplace(subs)
    floats = {f: sp.Rational(str(f)) for f in mapped.atoms(sp.Float)}
    return mapped.xreplace(floats)


