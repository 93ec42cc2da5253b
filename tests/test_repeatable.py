"""SymPy's random draws are fixed while a derivation is built."""
from types import SimpleNamespace

from sympy.core.random import rng

from crane_sym import registry
from crane_sym.repeatable import SEED, fixed_sympy_draws


def test_the_same_draws_in_every_block_and_the_callers_state_given_back():
    rng.seed(7)
    expected_after = [rng.random() for _ in range(3)]
    rng.seed(7)
    with fixed_sympy_draws():
        first = [rng.random() for _ in range(5)]
    assert [rng.random() for _ in range(3)] == expected_after
    with fixed_sympy_draws():
        assert [rng.random() for _ in range(5)] == first
    with fixed_sympy_draws(SEED + 1):
        assert [rng.random() for _ in range(5)] != first


def test_a_derivation_is_built_under_the_fixed_draws(monkeypatch):
    with fixed_sympy_draws():
        expected = rng.random()
    drawn = []
    fake = SimpleNamespace(build=lambda code=True: drawn.append(rng.random()) or "built")
    monkeypatch.setattr(registry, "module", lambda name: fake)
    rng.seed(1)                           # whatever state the caller left
    assert registry.built.__wrapped__("travel_braking") == "built"   # past the cache
    assert drawn == [expected]
