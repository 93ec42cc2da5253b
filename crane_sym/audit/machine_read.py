"""The printed LaTeX read by machine and compared with the hand transcription.

The hand transcription of a print (``PublishedFormula.printed``) is what the
audit checks; nothing else guarantees that it is the LaTeX printed beside it.
Here the print is parsed (``crane_sym.audit.latex_parse``), the paper's names are
mapped to the derivation's symbols (every symbol's LaTeX as the derivation
prints it and as ``LATEX_NAMES`` gives it, ẋ and ẍ of each coordinate, and,
in a Mathcad form, its typewriter names), and each relation of the print is
compared with the hand transcription symbolically. The record gets one of:

- ``agrees``: a relation of the print is the hand transcription;
- ``differs``: the print parses, but no relation of it is the transcription;
  the difference is given, and it must be explained: by a reconstruction the
  record labels (the OCR was damaged) or by a reading the record names (the
  parse is that reading); an unexplained difference is a defect of the
  transcription (``tests/test_machine_read.py`` forbids it);
- ``unreadable``: the parser cannot read the print; the reason is given.
"""
from __future__ import annotations

import re
from dataclasses import dataclass, replace
from functools import lru_cache

import sympy as sp
from sympy.core.function import AppliedUndef

from crane_sym.audit.checks import (numeric_equivalence, numerically_nonzero,
                                   symbolic_equivalence)
from crane_sym.derivation import Derivation
from crane_sym.latex import latex
from crane_sym.outcomes import FAIL
from crane_sym.audit.latex_parse import (Parsed, Unreadable, bound_variables, candidates, parse,
                                         parse_side, parse_table, parser)
from crane_sym.audit.parse_table import render
from crane_sym.audit.print_names import (BOUND_SYMBOL, cached_vocabulary, calls_pass, map_symbols,
                                         names_pass)
from crane_sym.published import FITTED_VALUE, PublishedFormula

__all__ = ["AGREES", "DIFFERS", "FORMULA", "NOTHING", "NUMBER", "UNREADABLE", "MachineRead",
           "machine_read", "parse_table_text", "subject", "table_entries"]

AGREES, DIFFERS, UNREADABLE = "agrees", "differs", "unreadable"
#: What a transcription is, for the coverage: a number (a bare number, or a name
#: equal to one) or a formula; none when nothing was transcribed.
NUMBER, FORMULA, NOTHING = "number", "formula", "nothing transcribed"
_WRAPPERS = re.compile(r"\\(?:text|mathrm|mathit|mathtt|operatorname)\s*")


@dataclass(frozen=True)
class MachineRead:
    """How the print reads by machine against the hand transcription."""

    status: str
    detail: str
    parsed: str = ""           # LaTeX of the relation compared
    explained_by: str = ""     # of a difference: the reconstruction or the reading
    subject: str = FORMULA     # what was transcribed: NUMBER, FORMULA or NOTHING

    def text(self) -> str:
        """One line for the reports."""
        extra = f" ({self.explained_by})" if self.explained_by else ""
        return f"{self.status}{extra}: {self.detail}"

    def as_dict(self) -> dict:
        """JSON-ready form."""
        return {"status": self.status, "detail": self.detail, "parsed": self.parsed,
                "explained_by": self.explained_by or None, "subject": self.subject}


def _relation(p: Parsed, vocab, tokens) -> sp.Eq | sp.Basic:
    if isinstance(p.rhs, sp.core.relational.Relational):
        raise Unreadable("an inequality: the parse is a condition, the transcription an "
                         "equation")
    rhs = map_symbols(p.rhs, vocab, tokens)
    if p.lhs is None:
        return rhs
    return sp.Eq(map_symbols(p.lhs, vocab, tokens), rhs, evaluate=False)


def _canonical(expr: sp.Basic) -> sp.Basic:
    """Bound variables renamed alike (∫ f(θ) dθ is ∫ f(ϑ) dϑ), |x| as its cases."""
    def rename(integral: sp.Integral) -> sp.Integral:
        (var, *limits), = integral.limits
        return sp.Integral(integral.function.xreplace({var: BOUND_SYMBOL}),
                           (BOUND_SYMBOL, *limits))
    expr = expr.replace(lambda e: isinstance(e, sp.Integral) and len(e.limits) == 1, rename)
    return expr.replace(lambda e: isinstance(e, sp.Abs), lambda e: e.rewrite(sp.Piecewise))


@lru_cache(maxsize=4096)
def _zero(expr: sp.Basic) -> bool:
    """``expr`` is 0: expanded first; simplified only if needed (integrals kept
    unevaluated: the print and the transcription write the same integrals)
    and not where numbers show it is not 0 (``numerically_nonzero``), so a 0
    rests on the symbolic proof alone. Asked once per run of each expression."""
    if sp.expand(expr) == 0:
        return True
    return not numerically_nonzero(expr) and sp.simplify(expr, doit=False) == 0


def _refuted(parsed, hand: sp.Eq, d: Derivation) -> bool:
    """True when mpmath at a few seeded points shows the parse is not the
    relation ``hand`` in any form ``_same`` accepts (``numeric_equivalence``
    fails by more than a relative 10⁻¹²: neither equal sides, nor equal
    residuals, nor a constant residual ratio), so no simplification need be
    tried; False when the numbers cannot tell (an integral, a name outside the
    symbol table, a point where the print is undefined) or the expanded
    difference is already 0."""
    if parsed.has(sp.Integral) or hand.has(sp.Integral):
        return False
    relation = parsed if isinstance(parsed, sp.Equality) \
        else sp.Eq(hand.lhs, parsed, evaluate=False)
    if relation.lhs == hand.lhs and sp.expand(relation.rhs - hand.rhs) == 0 \
            or sp.expand((relation.lhs - relation.rhs) - (hand.lhs - hand.rhs)) == 0:
        return False
    try:
        return numeric_equivalence(relation, hand, d.symbols, points=3,
                                   tol=1e-12).status == FAIL
    except (ValueError, TypeError, ArithmeticError, NameError, AttributeError):
        return False


def _same(parsed, hand: sp.Eq, d: Derivation) -> bool:
    parsed, hand = _canonical(parsed), _canonical(hand)
    if _refuted(parsed, hand, d):
        return False               # numbers refute it: no simplification can confirm it
    if not isinstance(parsed, sp.Equality):
        return _zero(parsed - hand.rhs)
    if parsed.lhs == hand.lhs:
        return _zero(parsed.rhs - hand.rhs)
    if _zero((parsed.lhs - parsed.rhs) - (hand.lhs - hand.rhs)) \
            or _zero((parsed.lhs - parsed.rhs) + (hand.lhs - hand.rhs)):
        return True
    if parsed.has(sp.Integral) or hand.has(sp.Integral):
        return False               # no rearrangement test that would integrate
    try:
        return symbolic_equivalence(parsed, hand, d.symbols).status == "pass"
    except (TypeError, ValueError, ZeroDivisionError):
        return False


def _difference(parsed, hand: sp.Eq, names: dict) -> str:
    parsed, hand = _canonical(parsed), _canonical(hand)
    if isinstance(parsed, sp.Equality) and parsed.lhs == hand.lhs:
        diff = sp.simplify(parsed.rhs - hand.rhs, doit=False)
    elif isinstance(parsed, sp.Equality):
        diff = sp.simplify((parsed.lhs - parsed.rhs) - (hand.lhs - hand.rhs), doit=False)
    else:
        diff = sp.simplify(parsed - hand.rhs, doit=False)
    return latex(diff, symbol_names=names) if sp.count_ops(diff) < 200 else "(long)"


def subject(f: PublishedFormula) -> str:
    """What ``f`` transcribes: ``number`` (a number, or a name equal to one),
    ``formula``, or ``nothing transcribed``.

    Parameters
    ----------
    f : PublishedFormula
        A published formula.
    """
    if f.printed is None:
        return NOTHING
    sides = (f.printed.lhs, f.printed.rhs)
    numeric = [s for s in sides if s.is_number]
    return NUMBER if numeric and all(s.is_number or s.is_Symbol for s in sides) else FORMULA


def machine_read(d: Derivation, f: PublishedFormula) -> MachineRead:
    """The print of ``f`` read by machine against its hand transcription, with
    what the transcription is (:func:`subject`).

    Parameters
    ----------
    d : Derivation
        The built paper, whose symbols and names the print is read in.
    f : PublishedFormula
        One of its published formulas.
    """
    return replace(_compared(d, f), subject=subject(f))


def _compared(d: Derivation, f: PublishedFormula) -> MachineRead:
    """The print of ``f`` parsed and compared with its transcription."""
    if f.printed is None:
        return MachineRead(UNREADABLE, "no transcription to compare: " + f.not_checkable)
    if "\\div" in f.latex:
        return MachineRead(UNREADABLE, "\\div: the print leaves the scope of ÷ open")
    read, reasons, tokens = _read(d, f)
    for _, rel in read:
        if _same(rel, f.printed, d):
            return MachineRead(AGREES, "the parse is the hand transcription",
                               _tex(rel, d.latex_names))
    relations = [r for _, r in read if isinstance(r, sp.Equality)
                 or (r.is_number and f.printed.rhs.is_number)]
    ours = [r for r in relations if isinstance(r, sp.Equality) and r.lhs == f.printed.lhs]
    if len(relations) == 1 and not reasons:
        ours = relations       # the print's one relation, rearranged or not
    if reasons and ours:       # a relation not read may be the one transcribed
        ours = _comparable(d, f, ours)
        if not ours:
            reasons = ["part of the print was not read, and what was read is not "
                       "the transcription: " + reasons[0]]
    if not ours:
        why = reasons[0] if reasons else (
            "the relation this record transcribes is not among those read: "
            + "; ".join(f"${_tex(r, d.latex_names)}$" for r in relations)
            if relations else "no relation in the print")
        if f.reconstructed or f.verbatim and _debris(f.latex):
            why = "OCR debris: " + why
        return MachineRead(UNREADABLE, _tokens_back(why, tokens, d.latex_names))
    rel = ours[0]
    unread = "; ".join(dict.fromkeys(reasons))
    unread = f"; the parts not read: {unread}" if unread else ""
    return MachineRead(DIFFERS, "printed − transcribed: $" +
                       _difference(rel, f.printed, d.latex_names) + "$"
                       + _tokens_back(unread, tokens, d.latex_names),
                       _tex(rel, d.latex_names), _explained(d, f, [r for _, r in read]))


def _comparable(d: Derivation, f: PublishedFormula, ours: list) -> list:
    """The parts read of a print, part of which is not read, that can only be
    the part ``f`` transcribes: not another record's part of the same print
    (the outer members of (8) beside its middle member), and in no name the
    transcription does not hold (a middle member written with x_*(t) or Y_2(t),
    which the transcription writes out). Each of them that is not ``f``'s
    transcription is a difference from the print, read by machine."""
    others = [g.printed for g in d.published
              if g.latex == f.latex and g.label != f.label and g.printed is not None]
    own = _names(f.printed)
    return [r for r in ours if _names(r) <= own
            and not any(_same(r, other, d) for other in others)]


def _names(expr: sp.Basic) -> set:
    """The symbols and the undefined functions ``expr`` is written in."""
    return expr.free_symbols | {type(a) for a in expr.atoms(AppliedUndef)}


def _read(d: Derivation, f: PublishedFormula) -> tuple[list, list[str], dict]:
    """The relations of the print parsed and mapped to the derivation's symbols
    (candidate, relation), the parser's reasons for those it cannot read, and
    the tokens the names pass gave."""
    vocab, functions = cached_vocabulary(d, f.verbatim)
    tokens: dict[str, sp.Basic] = {}
    tex = names_pass(bound_variables(f.latex), vocab, tokens)
    tex = calls_pass(tex, vocab, tokens)
    read, reasons = [], []
    for cand in candidates(tex):
        try:
            read.append((cand, _relation(parse(cand, functions), vocab, tokens)))
        except Unreadable as why:
            reasons.append(str(why))
    return read, reasons, tokens


def table_entries(d: Derivation) -> dict[str, dict]:
    """The committed table's entries for every side the machine reading of ``d``
    parses (key -> entry), each from the table where it holds the side, else
    parsed afresh (``crane_sym.audit.parse_table``).

    Parameters
    ----------
    d : Derivation
        The built paper, each of whose published prints is read.
    """
    parse_side.cache_clear()           # every side asked again, so every one is noted
    table = parse_table()
    table.requested.clear()
    for f in d.published:
        if f.printed is not None and "\\div" not in f.latex:
            _read(d, f)
    return dict(table.requested)


def parse_table_text(entries: dict[str, dict]) -> str:
    """The text of ``generated/machine_reading.json`` holding ``entries``.

    Parameters
    ----------
    entries : dict of str to dict
        Key -> entry, of every paper (:func:`table_entries`).
    """
    return render(entries, parser())


def _explained(d: Derivation, f: PublishedFormula, parsed: list) -> str:
    """What explains a difference: the record's reconstruction, or a reading it names
    that one of the parsed relations is; "" when nothing does (a defect)."""
    for c in f.conventions:
        if c.kind == FITTED_VALUE:     # changes what is compared, not how the print reads
            continue
        if any(_same(rel, f.reading(c), d) for rel in parsed):
            return f"the parse is the record's {c.kind} reading: {c.note}"
    if f.reconstructed:
        return "a labelled reconstruction from OCR damage"
    if f.read_as:
        return f"the transcriber's named reading: {f.read_as}"
    return ""


def _debris(tex: str) -> bool:
    """OCR left characters no formula holds (Cyrillic outside text, stray quotes)."""
    return bool(re.search(r"[А-Яа-я„“”’'\"^]", _WRAPPERS.sub("", tex)))


def _tex(rel, names: dict) -> str:
    if isinstance(rel, sp.Equality):
        return latex(rel.lhs, symbol_names=names) + " = " + latex(rel.rhs, symbol_names=names)
    return latex(rel, symbol_names=names)


def _tokens_back(text: str, tokens: dict[str, sp.Basic], names: dict) -> str:
    """A parser message with each token shown as the name it stands for."""
    for token, expr in tokens.items():
        shown = latex(expr, symbol_names=names)
        text = text.replace(token.replace("pq", "{pq") + "}", shown).replace(token, shown)
    return text
