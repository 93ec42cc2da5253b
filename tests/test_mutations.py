"""Every check can fail: each transcription of paper 000 mutated in turn (sign,
factor 2, two parameters of one dimension swapped, a decimal point), and every
mutant is caught (its readings are made from the transcription, so none survives
under a reading typed beside it).

The table for all five papers is in the README ("Every check can fail"); it is
made by ``crane_sym.audit.mutations.kills`` on each paper (minutes: not a test).
"""
from __future__ import annotations

import pytest
import sympy as sp

pytest.importorskip("lark")

from crane_sym import registry  # noqa: E402
from crane_sym.audit.mutations import MUTATIONS, kills, mutants  # noqa: E402


def test_each_mutant_of_000_is_caught():
    table = kills(registry.get("000"))
    assert sum(table.tried.values()) >= 30
    assert table.survivors == (), table.survivors
    assert table.row().startswith("| travel_braking | ")


def test_the_mutants_change_the_relation():
    m1, m2, u = sp.symbols("m1 m2 u", positive=True)     # 000's masses
    d = registry.get("000")
    found = mutants(sp.Eq(u, sp.Float(0.25)), d.symbols)
    assert set(found) == {"sign", "factor 2", "decimal point"}
    assert found["decimal point"].rhs == sp.Float(2.5)
    swapped = mutants(sp.Eq(u, m1 / m2), d.symbols)["swapped symbols"]
    assert swapped.rhs == m2 / m1 and set(MUTATIONS) >= set(found)
    assert mutants(sp.Eq(u, sp.Integer(0), evaluate=False), d.symbols) == {}


def test_a_symbol_for_another_reading_takes_the_transcribed_number():
    # 002's max k̃4 is printed as k̃_дин3 = 2.0736 and read as k̃_дин4: the reading's
    # number is the transcription's, so a sign, a factor 2 or a decimal point is caught
    table = kills(registry.get("002"), labels=("max k̃4 (after (66))",))
    assert sum(table.tried.values()) == 3 and table.survivors == ()
