"""LaTeX as a mechanics text writes it: x for x(t), ẋ and ẍ for its time
derivatives, a sum that starts with a positive term.

SymPy prints a coordinate as ``x{\\left(t \\right)}``, its derivative as
``\\frac{d}{d t} x{\\left(t \\right)}``, ``x2 − x1`` as ``- x_{1} + x_{2}``
and ``c·(x2 − x1)`` as ``- c (x_1 - x_2)``; a reader of a paper expects ``x``,
``\\dot{x}``, ``x_2 - x_1`` and ``c (x_2 - x_1)``. This printer changes only that.
"""
from __future__ import annotations

import re

import sympy as sp
from sympy.printing.latex import LatexPrinter

__all__ = ["cyrillic_as_text", "latex"]

_CYRILLIC = re.compile(r"[А-Яа-яЁёІіЇїЄєҐґ]+")
_TEXT = re.compile(r"\\(?:text|mathrm)\{[^{}]*\}")


def cyrillic_as_text(tex: str) -> str:
    """``tex`` with each Cyrillic run outside ``\\text{}``/``\\mathrm{}`` wrapped
    in ``\\text{}``, so that math renderers set it upright as a word.

    Parameters
    ----------
    tex : str
        LaTeX text.
    """
    out, last = [], 0
    for m in _TEXT.finditer(tex):
        out.append(_CYRILLIC.sub(lambda c: rf"\text{{{c.group(0)}}}", tex[last:m.start()]))
        out.append(m.group(0))
        last = m.end()
    out.append(_CYRILLIC.sub(lambda c: rf"\text{{{c.group(0)}}}", tex[last:]))
    return "".join(out)


_DOTS = {1: r"\dot", 2: r"\ddot", 3: r"\dddot", 4: r"\ddddot"}


def _of_time_only(f: sp.Basic) -> bool:
    return (isinstance(f, sp.core.function.AppliedUndef) and len(f.args) == 1
            and isinstance(f.args[0], sp.Symbol) and f.args[0].name == "t")


class _MechanicsPrinter(LatexPrinter):
    def _print_Function(self, expr, exp=None):  # noqa: N802 (SymPy's naming)
        if _of_time_only(expr):
            name = self._settings["symbol_names"].get(expr) or self._print(
                sp.Symbol(expr.func.__name__))
            return f"{name}^{{{exp}}}" if exp else name
        return super()._print_Function(expr, exp)

    def _print_Add(self, expr, order=None):  # noqa: N802
        terms = list(self._as_ordered_terms(expr, order=order))
        first = next((i for i, t in enumerate(terms) if not t.could_extract_minus_sign()), 0)
        terms.insert(0, terms.pop(first))         # lead with a positive term
        tex = ""
        for i, term in enumerate(terms):
            if i and term.could_extract_minus_sign():
                tex, term = tex + " - ", -term
            elif i:
                tex += " + "
            term_tex = self._print(term)
            tex += rf"\left({term_tex}\right)" if self._needs_add_brackets(term) else term_tex
        return tex

    def _print_Mul(self, expr):  # noqa: N802
        # −c·(x1 − x2) reads better as c·(x2 − x1): move the sign into a sum.
        sums = [f for f in expr.args if isinstance(f, sp.Add)]
        coeff = expr.as_coeff_Mul()[0]
        if coeff.is_negative and len(sums) == 1 and any(
                a.could_extract_minus_sign() for a in sums[0].args):
            flipped = sp.Add(*[-a for a in sums[0].args], evaluate=False)
            rest = [-f if f.is_Number else f for f in expr.args if f is not sums[0]]
            rest = [f for f in rest if f != 1]
            return super()._print_Mul(sp.Mul(*rest, flipped, evaluate=False))
        return super()._print_Mul(expr)

    def _print_Derivative(self, expr):  # noqa: N802
        f = expr.expr
        if _of_time_only(f) and all(v == f.args[0] for v, _ in expr.variable_count):
            n = sum(c for _, c in expr.variable_count)
            name = self._settings["symbol_names"].get(f) or self._print(
                sp.Symbol(f.func.__name__))
            if n in _DOTS:
                base, _, sub = name.partition("_")
                return f"{_DOTS[n]}{{{base}}}" + (f"_{sub}" if sub else "")
            return f"{name}^{{({n})}}"
        return super()._print_Derivative(expr)


def latex(expr: sp.Basic, **settings) -> str:
    """LaTeX of ``expr`` with x(t) printed x, its time derivatives dotted, and
    Cyrillic (the papers' subscripts) set as text.

    Parameters
    ----------
    expr : sympy.Basic
        The expression.
    **settings
        Passed to SymPy's ``LatexPrinter`` (e.g. ``symbol_names``).
    """
    return cyrillic_as_text(_MechanicsPrinter(settings).doprint(expr))
