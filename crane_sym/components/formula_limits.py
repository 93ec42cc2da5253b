"""Bounds on the work one formula of a component file may cost.

A ``[[formula]]`` is the user's text, and one line of LaTeX can ask for
unbounded work: ``9^{9^{9^{9}}}`` (a number of 10^8 digits when parsed),
``(m_1+m_2+c)^{100000}`` (expanded by the symbolic check: 17 GB),
``c!!!!!!!!!!``, ``\\sum_{k=1}^{10^{12}}``, 33,000 terms (the Earley parser
takes ~10 ms a term). The audit of a component file bounds it in three
places, and a formula over a bound gets the verdict not_checkable, "too large
to check", with the bound it broke, while the audit goes on (a formula
refused for another reason, "cannot be checked", with the reason):

1. the text, before it is parsed (:func:`check_print`): its length, the
   depth of its groups and of its superscripts, a number raised to a raised
   power, the size of a number in an exponent or before a factorial, the
   factorials;
2. the parsed expression (:func:`bounded`): powers, factorials and
   iterated sums and products that would be too large to evaluate, a limit
   (not checked), a value imaginary for the file's positive values, or
   infinite or undefined (a division by zero);
3. time (:func:`budget`): reading a formula and checking it each have a
   budget of seconds, enforced by ``SIGALRM`` in the main thread (elsewhere,
   on a thread that cannot take a signal, only 1 and 2 hold).
"""
from __future__ import annotations

import re
import signal
import threading
from contextlib import contextmanager
from typing import Iterator

import sympy as sp

__all__ = ["CHECK_SECONDS", "MAX_CHARACTERS", "MAX_DEPTH", "MAX_EXPONENT", "MAX_FACTORIAL",
           "MAX_FACTORIALS", "MAX_SUPERSCRIPTS", "MAX_TERMS", "PARSE_SECONDS", "Refused",
           "TooLarge", "bounded", "budget", "check_print"]

#: Characters of a formula's LaTeX.
MAX_CHARACTERS = 1000
#: Nesting of groups: ``{}``, ``()``, ``[]``, ``\left``/``\right`` pairs alike.
MAX_DEPTH = 12
#: Superscripts inside superscripts (``e^{-x^{2}}`` is 2).
MAX_SUPERSCRIPTS = 2
#: The largest number allowed as an exponent ((a + b + c)^100 expands to
#: 5151 terms).
MAX_EXPONENT = 100
#: The largest number a factorial may be taken of.
MAX_FACTORIAL = 100
#: Factorials in one formula.
MAX_FACTORIALS = 4
#: Terms a ``\sum`` or ``\prod`` with numbers for bounds may have.
MAX_TERMS = 1000
#: Seconds to read (parse) one formula.
PARSE_SECONDS = 10.0
#: Seconds to check one formula (symbolic, numeric and dimensional checks).
CHECK_SECONDS = 30.0

_OPEN = {"{": "}", "(": ")", "[": "]"}
_NUMBER = re.compile(r"\d+(?:\.\d*)?")


class Refused(Exception):
    """A formula this module does not let the audit check; the message says
    why, :attr:`prefix` what that means."""

    prefix = "cannot be checked"


class TooLarge(Refused):
    """A formula over a bound of this module; the message names the bound."""

    prefix = "too large to check"


def _depth(tex: str) -> tuple[int, int]:
    """(deepest group, deepest superscript) of ``tex``; a superscript's group
    is the braces after ``^`` or its one character."""
    groups: list[bool] = []                  # per open group: is it a superscript's
    deepest = high = 0
    k = 0
    while k < len(tex):
        c = tex[k]
        if c == "\\" and tex.startswith(("\\left", "\\right"), k):
            k += 5 if tex.startswith("\\left", k) else 6
            continue                         # the delimiter after it counts below
        if c == "\\":
            k += 2                           # an escaped character is no group
            continue
        if c == "^":
            after = tex[k + 1:k + 2]
            if after == "{":
                groups.append(True)
                k += 2
            else:                            # one character (or one command) raised
                k += 1
                high = max(high, sum(groups) + 1)
            deepest = max(deepest, len(groups))
            high = max(high, sum(groups))
            continue
        if c in _OPEN:
            groups.append(False)
            deepest = max(deepest, len(groups))
        elif c in _OPEN.values() and groups:
            groups.pop()
        k += 1
    return deepest, high


def check_print(tex: str) -> None:
    """Nothing if ``tex`` may be parsed; :class:`TooLarge` naming the bound
    otherwise (see the module docstring, item 1).

    Parameters
    ----------
    tex : str
        A formula's LaTeX as the file gives it.

    Examples
    --------
    >>> check_print(r"F = c (1 - \\cos p t)")
    >>> check_print(r"p = 9^{9^{9^{9}}}")
    Traceback (most recent call last):
    ...
    crane_sym.components.formula_limits.TooLarge: superscripts nested 3 deep (at most 2)
    """
    if len(tex) > MAX_CHARACTERS:
        raise TooLarge(f"{len(tex)} characters (at most {MAX_CHARACTERS})")
    deepest, high = _depth(tex)
    if deepest > MAX_DEPTH:
        raise TooLarge(f"groups nested {deepest} deep (at most {MAX_DEPTH})")
    if high > MAX_SUPERSCRIPTS:
        raise TooLarge(f"superscripts nested {high} deep (at most {MAX_SUPERSCRIPTS})")
    tower = re.search(r"(?:(?<![\w{.])\d+|(?<!\w)\{\s*\d+\s*\})\s*\^\s*\{[^{}]*\^", tex)
    if tower:                                # parsed, 9^{9^{9}} is a number of 10^8 digits
        raise TooLarge(f"a number raised to a raised power ({tower.group().strip()}...)")
    for m in re.finditer(r"\^\s*(\{\s*[-+]?\s*)?(\d+(?:\.\d*)?)", tex):
        if float(m.group(2)) > MAX_EXPONENT:
            raise TooLarge(f"the exponent {m.group(2)} (at most {MAX_EXPONENT})")
    bangs = re.findall(r"!+", tex.replace("\\!", ""))   # \! is a negative space
    if any(len(run) > 1 for run in bangs):
        raise TooLarge(f"a factorial of a factorial ({max(bangs, key=len)}; one ! at a time)")
    if len(bangs) > MAX_FACTORIALS:
        raise TooLarge(f"{len(bangs)} factorials (at most {MAX_FACTORIALS})")
    for m in re.finditer(r"(\d+(?:\.\d*)?)\s*\}?\s*!", tex.replace("\\!", "")):
        if float(m.group(1)) > MAX_FACTORIAL:
            raise TooLarge(f"the factorial {m.group(1)}! (at most {MAX_FACTORIAL}!)")


def _number(e: sp.Basic) -> float | None:
    """``e`` as a float if it is a number, else None (a huge one as inf)."""
    if not e.is_number:
        return None
    try:
        return float(sp.Abs(e).evalf(15))
    except (TypeError, ValueError, OverflowError):
        return float("inf")


def bounded(expr: sp.Basic) -> sp.Basic:
    """The parsed right side ``expr`` with every ``\\sum`` and ``\\prod`` written
    out (the checks cannot take them whole), if it may be checked;
    :class:`TooLarge` naming the bound otherwise (see the module docstring,
    item 2); :class:`Refused` for a limit, an iterated operator with a bound
    that is no number, an imaginary value, or one infinite or undefined.

    Parameters
    ----------
    expr : sympy.Basic
        The formula's right side, parsed (its symbols positive).

    Examples
    --------
    >>> import sympy as sp
    >>> k, c = sp.symbols("k c", positive=True)
    >>> bounded(sp.Sum(c * k, (k, 1, 3)))
    6*c
    """
    for e in sp.preorder_traversal(expr):
        if isinstance(e, sp.Limit):
            raise Refused("a limit (\\lim) is not checked; write the value it has")
        if isinstance(e, sp.Pow):
            n = _number(e.exp)
            if n is not None and n > MAX_EXPONENT:
                raise TooLarge(f"the exponent {sp.sstr(e.exp)[:40]} (at most {MAX_EXPONENT})")
        if isinstance(e, sp.factorial):
            n = _number(e.args[0])
            if n is not None and n > MAX_FACTORIAL:
                raise TooLarge(f"the factorial of {sp.sstr(e.args[0])[:40]} (at most "
                               f"{MAX_FACTORIAL}!)")
        if isinstance(e, (sp.Sum, sp.Product)):
            name = "\\sum" if isinstance(e, sp.Sum) else "\\prod"
            for _, low, high in e.limits:
                span = _number(high - low)
                if span is None:
                    raise Refused(f"a {name} whose bounds are not numbers")
                if span + 1 > MAX_TERMS:
                    raise TooLarge(f"a {name} of {sp.sstr(high - low + 1)[:40]} terms (at "
                                   f"most {MAX_TERMS})")
    if expr.has(sp.I):
        raise Refused("it is imaginary for the file's positive values")
    expr = expr.replace(lambda e: isinstance(e, (sp.Sum, sp.Product)), lambda e: e.doit())
    if expr.has(sp.zoo, sp.oo, -sp.oo, sp.nan):
        raise Refused("it is infinite or undefined (a division by zero, a logarithm of 0)")
    return expr


class _Overrun(BaseException):
    """The alarm of :func:`budget` (a BaseException: no ``except Exception``
    of a parser or of SymPy may swallow it)."""


@contextmanager
def budget(seconds: float, what: str) -> Iterator[None]:
    """The block may take ``seconds``; past them it is stopped and
    :class:`TooLarge` raised ("``what`` took over ... s"). In the main thread
    only (``SIGALRM``; an alarm already set outside is left alone).

    Parameters
    ----------
    seconds : float
        The budget.
    what : str
        What the block does, for the message ("reading it", "checking it").
    """
    if (threading.current_thread() is not threading.main_thread()
            or not hasattr(signal, "setitimer") or signal.getitimer(signal.ITIMER_REAL)[0]):
        yield
        return

    def stop(signum, frame) -> None:
        raise _Overrun()

    previous = signal.signal(signal.SIGALRM, stop)
    signal.setitimer(signal.ITIMER_REAL, seconds)
    try:
        try:
            yield
        finally:
            signal.setitimer(signal.ITIMER_REAL, 0)
    except _Overrun:                # in the block, or before the timer was stopped
        raise TooLarge(f"{what} took over {seconds:g} s") from None
    finally:
        signal.signal(signal.SIGALRM, previous)
