"""The machine reading's parses, kept as a committed table.

Lark's Earley parser takes most of an audit's time (a print's side in 0.02 to
0.2 s, some 1 400 sides), and the prints never change between runs. The table
``generated/machine_reading.json`` holds each side's parse, keyed by a SHA-256
of the side's text and the names read as functions, under a fingerprint of the
parser (SymPy's and lark's versions, the grammar files, the source of the live
parse): a side not in it, or a table of another parser, is parsed afresh, and
the audit says how many were. ``crane-sym generate`` writes the table with the
modules, ``crane-sym generate --check`` fails on it when a side is missing or
stray, or the fingerprint changed.

A parse is stored as a structural form, nested lists of a class name and its
arguments (``["Mul", ["Integer", "-1"], ["Symbol", "x"]]``), rebuilt by
:func:`expression` from an allow-list of SymPy classes, never by ``eval`` or
``sympify``; an entry is kept only when its form rebuilds the parse exactly
(equal, and giving the same form again).
"""
from __future__ import annotations

import hashlib
import importlib.util
import json
import warnings
from dataclasses import dataclass, field
from pathlib import Path

import sympy as sp
from sympy.core.function import AppliedUndef
from sympy.utilities.exceptions import SymPyDeprecationWarning

__all__ = ["FILE", "ParseTable", "entry_for", "expression", "form", "key", "rebuilt", "render"]

#: The table's file name in ``generated/``.
FILE = "machine_reading.json"
_SINGLETONS = ("Pi", "Exp1", "ImaginaryUnit", "Infinity", "NegativeInfinity",
               "ComplexInfinity", "NaN", "EulerGamma")
#: Classes a form may name, rebuilt as ``cls(*args, evaluate=False)`` (relations and
#: functions) or ``cls(*args)`` (containers).
_EVALUATED = {c.__name__: c for c in (
    sp.Add, sp.Mul, sp.Pow, sp.sin, sp.cos, sp.tan, sp.cot, sp.sec, sp.csc, sp.asin,
    sp.acos, sp.atan, sp.acot, sp.sinh, sp.cosh, sp.tanh, sp.coth, sp.asinh, sp.acosh,
    sp.atanh, sp.exp, sp.log, sp.Abs, sp.sign, sp.floor, sp.ceiling, sp.factorial,
    sp.Min, sp.Max, sp.Derivative, sp.Equality, sp.Unequality, sp.StrictLessThan,
    sp.LessThan, sp.StrictGreaterThan, sp.GreaterThan)}
_CONTAINERS = {c.__name__: c for c in (sp.Tuple, sp.Integral, sp.Sum, sp.Product, sp.Limit)}


def key(side: str, functions: frozenset) -> str:
    """The SHA-256 of a side's text and the names read as functions."""
    text = side + "\x1f" + ",".join(sorted(functions))
    return hashlib.sha256(text.encode("utf-8")).hexdigest()


def form(expr: sp.Basic) -> list:
    """The structural form of ``expr``; ValueError on a class outside the allow-list.

    Parameters
    ----------
    expr : sympy.Basic
        A parse of SymPy's LaTeX parser.
    """
    if isinstance(expr, sp.Integer):
        return ["Integer", str(int(expr))]
    if isinstance(expr, sp.Rational):
        return ["Rational", str(expr.p), str(expr.q)]
    if isinstance(expr, sp.Float):
        sign, man, exp, bc = expr._mpf_
        return ["Float", sign, format(int(man), "x"), exp, bc, expr._prec]
    if isinstance(expr, sp.Symbol) and type(expr) is sp.Symbol:
        return ["Symbol", expr.name, dict(sorted(expr._assumptions_orig.items()))]
    name = type(expr).__name__
    if name in _SINGLETONS and expr is getattr(sp.S, name):
        return ["S", name]
    if isinstance(expr, AppliedUndef):
        return ["Undef", name, dict(sorted(type(expr)._kwargs.items())), *map(form, expr.args)]
    if name in _EVALUATED and _EVALUATED[name] is type(expr) \
            or name in _CONTAINERS and _CONTAINERS[name] is type(expr):
        return [name, *map(form, expr.args)]
    raise ValueError(f"parse table: no structural form for {name} ({sp.srepr(expr)[:60]})")


def expression(f: list) -> sp.Basic:
    """The expression a structural form stands for, built from the allow-list
    (never by ``eval``); ValueError on a form it does not know.

    Parameters
    ----------
    f : list
        A form of :func:`form`, as read from the table.
    """
    tag, *rest = f
    if tag == "Integer":
        return sp.Integer(int(rest[0]))
    if tag == "Rational":
        return sp.Rational(int(rest[0]), int(rest[1]))
    if tag == "Float":
        sign, man, exp, bc, prec = rest
        return sp.Float((sign, man, exp, bc), precision=prec)
    if tag == "Symbol":
        return sp.Symbol(rest[0], **rest[1])
    if tag == "S" and rest[0] in _SINGLETONS:
        return getattr(sp.S, rest[0])
    if tag == "Undef":
        name, kwargs, *args = rest
        return sp.Function(name, **kwargs)(*map(expression, args))
    args = [expression(a) for a in rest]
    if tag in _EVALUATED:
        return _EVALUATED[tag](*args, evaluate=False)
    if tag in _CONTAINERS:
        return _CONTAINERS[tag](*args)
    raise ValueError(f"parse table: unknown form {tag!r}")


def rebuilt(f: list) -> sp.Basic:
    """:func:`expression`, quiet about the deprecated Mul of a Tuple that SymPy's
    lark transformer builds (``F i n d(x)``: what the live parse warns about too).

    Parameters
    ----------
    f : list
        A form of :func:`form`, as read from the table.
    """
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", SymPyDeprecationWarning)
        return expression(f)


def entry_for(side: str, functions: frozenset, parsed: sp.Basic | None,
              unreadable: str = "") -> dict:
    """The table's entry for one side: its parse's form, or the parser's reason
    it cannot read it; ``{"live": why}`` when the form would not rebuild the
    parse exactly (such a side is parsed afresh on every run).

    Parameters
    ----------
    side, functions : str, frozenset
        The side and the names read as functions.
    parsed : sympy.Basic or None
        The live parse (None when the parser could not read the side).
    unreadable : str, optional
        The reason, when ``parsed`` is None.
    """
    entry: dict = {"side": side, "functions": sorted(functions)}
    if parsed is None:
        return {**entry, "unreadable": unreadable}
    try:
        shape = json.loads(json.dumps(form(parsed)))
        again = rebuilt(shape)
        same = again == parsed and form(again) == shape
    except ValueError as why:
        return {**entry, "live": str(why)}
    return {**entry, "form": shape} if same else {**entry, "live": "the form does not "
                                                  "rebuild the parse exactly"}


@dataclass
class ParseTable:
    """The table as read, and what this process asked of it (``requested``:
    key -> entry, found or parsed afresh)."""

    fingerprint: str
    entries: dict[str, dict]
    path: Path | None
    requested: dict[str, dict] = field(default_factory=dict)
    fresh: int = 0                   # sides parsed afresh (not in the table)
    found: int = 0                   # look-ups the table answered

    @classmethod
    def read(cls, fingerprint: str) -> "ParseTable":
        """The table of ``generated/`` (found by name, not imported) when its
        fingerprint is ``fingerprint``; an empty one otherwise.

        Parameters
        ----------
        fingerprint : str
            The fingerprint of the parser in this process.
        """
        spec = importlib.util.find_spec("crane_sym.generated")
        locations = list(spec.submodule_search_locations or []) if spec else []
        path = Path(locations[0]) / FILE if locations else None
        if path is None or not path.is_file():
            return cls(fingerprint, {}, path)
        data = json.loads(path.read_text(encoding="utf-8"))
        same = data.get("parser", {}).get("fingerprint") == fingerprint
        return cls(fingerprint, data.get("parses", {}) if same else {}, path)

    def lookup(self, side: str, functions: frozenset) -> dict | None:
        """The stored entry of a side (None if the table lacks it, or stores
        it as ``live``)."""
        entry = self.entries.get(key(side, functions))
        if entry is None or "live" in entry or entry["side"] != side:
            return None
        self.requested[key(side, functions)] = entry
        self.found += 1
        return entry

    def keep(self, entry: dict) -> None:
        """Note an entry parsed afresh in this process, and hold it for the next
        look-up (an unreadable side raises, so ``parse_side``'s cache misses it)."""
        k = key(entry["side"], frozenset(entry["functions"]))
        self.requested[k] = self.entries[k] = entry
        self.fresh += 1


def render(entries: dict[str, dict], parser: dict[str, str]) -> str:
    """The table's file text: a header, then one entry a line in key order.

    Parameters
    ----------
    entries : dict of str to dict
        Key -> entry: what the machine reading of every paper asked.
    parser : dict of str to str
        The parser's versions and fingerprint, written in the header.
    """
    head = {"about": "The machine reading's parse of each printed side (crane_sym.audit."
                     "parse_table): written by `crane-sym generate`, checked by `crane-sym "
                     "generate --check`; keys are SHA-256 of the side and its function names.",
            "parser": parser}
    lines = [json.dumps(k) + ": " + json.dumps(e, ensure_ascii=False)
             for k, e in sorted(entries.items())]
    body = ",\n".join(lines)
    return (json.dumps(head, ensure_ascii=False, indent=1)[:-2]
            + ',\n "parses": {\n' + body + "\n }\n}\n")
