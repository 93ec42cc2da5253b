"""A band over unstated parameters is their number's range over the whole box:
the corners, and a bounded optimiser for an extreme inside it."""
from __future__ import annotations

import math

import pytest

from crane_sym.sensitivity import Chosen, sweep

_AB = (Chosen("a", "a", "", 1.0, 0.0, 2.0, "test"), Chosen("b", "b", "", 1.0, 0.0, 2.0, "test"))


def test_the_band_is_the_box_not_a_stack_of_one_at_a_time_swings():
    """a·b at a = b = 1 over [0, 2]²: the corners give 0 … 4; moving each alone and
    stacking the swings would give −1 … 3, missing the corner (2, 2)."""
    s = sweep(lambda v: {"ab": v["a"] * v["b"]}, _AB)["ab"]
    assert s.value == 1.0 and s.band == (0.0, 4.0)
    lowest, highest = s.extremes
    assert highest.at == (2.0, 2.0) and highest.by == "a corner"
    assert "0–4 over their plausible ranges" in s.text()


def test_an_extreme_inside_the_box_is_found_by_the_optimiser():
    """sin(3a) + b/10 on [0, 1] × [0, 1]: its top, 1.1 at a = π/6, is no corner."""
    box = (Chosen("a", "a", "", 0.5, 0.0, 1.0, "test"), Chosen("b", "b", "", 0.5, 0.0, 1.0, "t"))
    s = sweep(lambda v: {"f": math.sin(3 * v["a"]) + v["b"] / 10}, box)["f"]
    low, high = s.band
    assert high == pytest.approx(1.1, abs=1e-5) and low == pytest.approx(0.0, abs=1e-12)
    assert s.extremes[1].by == "the optimiser"
    assert s.extremes[1].at[0] == pytest.approx(math.pi / 6, abs=1e-3)


def test_the_box_is_run_once_for_all_numbers_and_only_when_asked():
    runs = []

    def evaluate(v):
        runs.append(dict(v))
        return {"sum": v["a"] + v["b"], "diff": v["a"] - v["b"]}
    found = sweep(evaluate, _AB)
    assert len(runs) == 1                        # the chosen values only
    assert found["sum"].band == (0.0, 4.0) and found["diff"].band == (-2.0, 2.0)
    corners = {(r["a"], r["b"]) for r in runs}
    assert {(0.0, 0.0), (0.0, 2.0), (2.0, 0.0), (2.0, 2.0)} <= corners
