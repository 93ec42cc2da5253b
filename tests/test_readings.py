"""Readings made from the transcription (``crane_sym.readings``): each operation
does what it names, the readings of the five papers that restate a transcription
under a named meaning, operator scope, line-break sign or lost mark are made
from it (none typed beside it), and a mutation of such a transcription reaches
its reading's verdict."""
from __future__ import annotations

from dataclasses import replace

import pytest
import sympy as sp

from crane_sym import registry
from crane_sym.audit.mutations import kills
from crane_sym.readings import Meaning, Reinterpretation, Scaled, SignOnce

t = sp.Symbol("t")
a, b, c, k, dy = sp.symbols("a b c k Delta_y", positive=True)


def test_each_operation_does_what_it_names():
    assert Meaning(((k, -dy),)).applied(sp.Eq(a, b * (1 + k))) == sp.Eq(a, b * (1 - dy))
    assert SignOnce(b).applied(sp.Eq(a, c + b)).rhs == c - b
    assert Scaled(c ** -2).applied(sp.Eq(a, b / 2 * c)).rhs == b / (2 * c)
    assert Scaled(sp.Rational(1, 100)).applied(sp.Eq(a, 154)).rhs == sp.Rational(77, 50)


def test_a_meaning_of_a_function_of_time_takes_its_derivative_again():
    y1, y2, y = (sp.Function(n)(t) for n in ("y1", "y2", "y"))
    read = Meaning(((y1, y + y2),)).applied(sp.Eq(a, (y1.diff(t) - y2.diff(t)) ** 2))
    assert sp.expand(read.rhs - y.diff(t) ** 2) == 0


#: paper -> the records whose reading restates the transcription another way
MADE_FROM_THE_TRANSCRIPTION = {
    "000": ("(6)", "(7)"),
    "002": ("(9)", "(10)", "(11)", "(13)", "(34), via Y", "(39)", "(43), via Y_1",
            "(44), via Y_1", "(48), via Y_2", "(49), via Y_2"),
    "003": ("Form 1, d_a1", "Form 1, d_a2", "Form 1 appendix, Fo",
            "Form 1 appendix, equation", "Form 1, epsilon_alpha = 1.54"),
    "004": ("(11)", "(20)"),
}


@pytest.mark.parametrize("paper", sorted(MADE_FROM_THE_TRANSCRIPTION))
def test_the_listed_readings_are_made_from_their_transcription(paper):
    formulas = {f.label: f for f in registry.get(paper).published}
    for label in MADE_FROM_THE_TRANSCRIPTION[paper]:
        f = formulas[label]
        assert f.conventions and all(isinstance(conv.reading, Reinterpretation)
                                     for conv in f.conventions), label
        lhs, rhs = f.printed.lhs, f.printed.rhs
        doubled = sp.Eq(lhs, 2 * rhs, evaluate=False) if rhs != 0 else sp.Eq(2 * lhs, rhs)
        assert all(replace(f, printed=doubled).reading(conv) != f.reading(conv)
                   for conv in f.conventions), label


@pytest.mark.parametrize("paper, labels", [
    ("000", ("(6)", "(7)")), ("002", ("(11)", "(13)", "(43), via Y_1"))])
def test_a_mutated_transcription_reaches_its_reading(paper, labels):
    table = kills(registry.get(paper), labels=labels)
    assert sum(table.tried.values()) >= 2 * len(labels)
    assert table.survivors == (), table.survivors
