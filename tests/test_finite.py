"""Finite in, finite out: every generated function returns a finite value for
every argument its checks accept (the range each argument serves,
``PhysicalSymbol.serves``), or refuses a condition between arguments by name;
the scalar and array paths agree; a sample agrees with mpmath."""
import importlib
import math

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings, strategies as st

from crane_sym import registry
from crane_sym.bench.accuracy import accuracy

PAPERS = registry.ids()


def _functions(paper: str):
    d = registry.get(paper)
    module = importlib.import_module(f"crane_sym.generated.{paper}")
    return d, [(out, getattr(module, out.name)) for out in d.outputs]


def _value(entry, draw) -> float:
    """A value anywhere in the range ``entry`` serves: log-uniform in
    magnitude, its ends and 0 (where allowed) included."""
    low, high = entry.serves
    top = math.log10(high)
    bottom = math.log10(low) if low > 0 else top - 30
    kind = draw(st.sampled_from(["inside", "inside", "inside", "low", "high"]))
    if kind == "high":
        magnitude = high
    elif kind == "low":
        magnitude = low if low > 0 else 0.0
    else:
        magnitude = min(high, max(low, 10 ** draw(st.floats(bottom, top))))
    sign = -1.0 if low < 0 and draw(st.booleans()) else 1.0
    return sign * magnitude


def _refusal_is_stated(err: ValueError, out) -> bool:
    """A refusal of values inside every argument's range is a condition
    between arguments, named in the message (a ``requires`` of the output, a
    gear geometry that cannot exist): never an argument's own range check,
    which these values pass."""
    text = str(err)
    return bool(text) and "the range this function serves" not in text \
        and "must be finite" not in text


@pytest.mark.parametrize("paper", PAPERS)
@settings(max_examples=300, deadline=None, derandomize=True,
          suppress_health_check=[HealthCheck.too_slow])
@given(data=st.data())
def test_every_accepted_argument_gives_a_finite_value(paper, data):
    d, functions = _functions(paper)
    out, fn = data.draw(st.sampled_from(functions))
    args = {str(a): _value(d.symbols[a], data.draw) for a in out.args}
    try:
        value = np.asarray(fn(**args), dtype=float)
    except ValueError as err:
        assert _refusal_is_stated(err, out), f"{out.name}{args}: {err}"
        return
    assert np.all(np.isfinite(value)), f"{out.name}{args} = {value}"
    arrays = {k: np.array([v, v]) for k, v in args.items()}       # the array path
    both = np.asarray(fn(**arrays), dtype=float)                  # accepts them too
    assert np.all(np.isfinite(both)), f"{out.name}{args} (arrays) = {both}"


@pytest.mark.parametrize("paper", PAPERS)
def test_outside_the_range_served_is_refused_with_the_bound(paper):
    """One step past either end of an argument's range is refused, on the
    scalar and the array path alike, and the message gives the bound."""
    d, functions = _functions(paper)
    for out, fn in functions:
        inside = {str(a): d.symbols[a].serves[1] for a in out.args}
        for a in out.args:
            low, high = d.symbols[a].serves
            for bad in (high * 2, -high * 2 if low < 0 else (low / 2 if low > 0 else None)):
                if bad is None:
                    continue
                for wrap in (float, lambda v: np.array([v])):
                    args = {k: wrap(v) for k, v in inside.items()} | {str(a): wrap(bad)}
                    with pytest.raises(ValueError, match=rf"^{a} must be"):
                        fn(**args)


@pytest.mark.parametrize("paper", PAPERS)
def test_a_sample_of_the_served_range_agrees_with_mpmath(paper):
    """Five seeded points per function, anywhere in the box it serves, within
    max(1e-12, 2·cond·2⁻⁵³) of the derived expression in mpmath: correct to
    twelve digits a million times beyond the physical ranges (the hard cases
    of ``crane-sym accuracy`` hold the physical ranges to 1e-15)."""
    d, functions = _functions(paper)
    rng = np.random.default_rng(3)
    for out, fn in functions:
        if getattr(out.expr, "is_Matrix", False):
            continue
        columns = {}
        for a in out.args:
            low, high = d.symbols[a].serves
            bottom = math.log10(low) if low > 0 else math.log10(high) - 30
            columns[str(a)] = np.clip(10 ** rng.uniform(bottom, math.log10(high), 5), low, high)
        try:
            row = accuracy(out, fn, "served", columns, tolerance=1e-12)
        except ValueError as err:                  # a stated condition between arguments
            assert _refusal_is_stated(err, out), f"{out.name}: {err}"
            continue
        assert row.excess <= 1, f"{out.name} at {row.where}: {row.max_rel_error:.2e}"


@pytest.mark.parametrize("paper", PAPERS)
def test_every_hard_case_lies_in_the_range_served(paper):
    """The hard cases of ``crane-sym accuracy`` (limits, extreme ratios) are
    values the functions serve: the range checks refuse none of them."""
    cases = getattr(registry.module(paper), "hard_cases", None)
    if cases is None:
        pytest.skip(f"{paper} declares no hard cases")
    d = registry.get(paper)
    for case, columns in cases().items():
        for name, values in columns.items():
            if name in d.symbols:
                low, high = d.symbols[name].serves
                values = np.asarray(values, dtype=float)
                assert np.all((low <= values) & (values <= high)), (case, name)
