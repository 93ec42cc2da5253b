"""SymPy's random draws fixed while a derivation is built.

SymPy's multivariate factorization (Wang's algorithm, ``sp.factor``) draws
its evaluation points from SymPy's own generator, which the OS seeds anew in
each process. The result never depends on the draw, but the time does: paper
004's Jacobian factors in 2 s under most draws and ran past 17 min under one
(about one process in 20). A build under :func:`fixed_sympy_draws` takes the
same path, and the same time, in every process.
"""
from __future__ import annotations

from collections.abc import Iterator
from contextlib import contextmanager

from sympy.core.random import rng

#: The seed every build starts from (any fixed value; paper 004 built under it
#: in 2-12 s with each of 24 hash seeds, one of them the seed that hung).
SEED = 20261128


@contextmanager
def fixed_sympy_draws(seed: int = SEED) -> Iterator[None]:
    """SymPy's generator seeded with ``seed`` inside the block, and given back
    its state after it (a caller's own draws are not disturbed). Also a
    decorator: ``@fixed_sympy_draws()``.

    Parameters
    ----------
    seed : int
        The seed of SymPy's generator inside the block.
    """
    state = rng.getstate()
    rng.seed(seed)
    try:
        yield
    finally:
        rng.setstate(state)
