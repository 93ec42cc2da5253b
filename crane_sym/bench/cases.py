"""What a paper offers the benches: cases it declares, the benches discover.

The machinery names no paper, scene or value. A paper that wants a closed form
of its swept against per-design integration declares :class:`SweepBenchCase`
values in ``SWEEP_BENCH_CASES``; one with a response a sampled load can
reproduce declares :class:`SampledBenchCase` values in ``SAMPLED_BENCH_CASES``
(both in the paper's ``bench_cases.py``, re-exported by its package, as
``hard_cases``). A paper with a hybrid sweep output solved a block at a time
declares :class:`BatchedBenchCase` values in ``BATCHED_BENCH_CASES``. A
paper may give a generated time function a hand-written NumPy version in
``HAND_WRITTEN`` (function name -> callable with the same arguments): the
floor a careful hand would reach, which the targets against ``np.cos`` time
in the same run. :func:`sweep_cases`, :func:`sampled_cases`,
:func:`batched_cases` and :func:`hand_written` collect them through the
registry.
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Callable, Mapping, Sequence

from crane_sym import registry

__all__ = ["BatchedBenchCase", "SampledBenchCase", "SweepBenchCase", "batched_cases",
           "hand_written", "sampled_cases", "sweep_cases"]


@dataclass(frozen=True)
class SweepBenchCase:
    """A closed-form peak swept over two axes against integrating each design.

    Attributes
    ----------
    output : str
        The generated function the sweep maps (time-free, a peak).
    axes : tuple of str
        Two ``--vary`` texts with ``{n}`` for the number of values an axis
        takes (``"m1=1:100:{n}:log"``).
    scene : str or None
        A shipped scene that gives every other value; None builds the plan
        from ``fixed`` and the axes' ``units`` alone.
    system : str
        The paper's ODE system a user would integrate instead
        (``ODESystem.name``), and ``quantity``, the one of its quantities that
        is the output's time response.
    design : callable
        ``design(values)`` for one design's SI values by name: (the system's
        parameters by name, the ends of the pieces to integrate over, the
        closed-form peak).
    response : (str, str) or None
        A time response of the scene and the ``--at`` that fixes its time, for
        the parallel-efficiency and cluster measurements (the main case only).
    fixed, units :
        With no scene: the values (SI) of the parameters no axis sets, and the
        unit of each axis.
    """

    output: str
    axes: tuple[str, str]
    scene: str | None
    system: str
    quantity: str
    design: Callable[[Mapping[str, float]], tuple[Mapping[str, float], list[float], float]]
    response: tuple[str, str] | None = None
    fixed: Mapping[str, float] = None
    units: Mapping[str, str] = None


@dataclass(frozen=True)
class SampledBenchCase:
    """A generated response the sampled-load route reproduces: the response of
    x'' + Ω²x = S(t) to a load family of ``bench.sampled`` (``family``, with
    amplitude ``S0`` and time ``t1``), ``closed_form(t)`` the generated
    function, ``scale`` what turns x into it; ``step`` a power of 2 [s].
    ``exact()``, where the closed form's inputs are not Ω and S0 themselves,
    gives the Ω and S0 (mpmath, at the working precision) that its double
    inputs imply exactly."""

    name: str
    family: str
    Omega: float
    S0: float
    t1: float
    step: float
    closed_form: Callable
    scale: float
    exact: Callable[[], tuple] | None = None


@dataclass(frozen=True)
class BatchedBenchCase:
    """A simulated sweep output solved a block at a time (``SweepOutput.batched``)
    against the per-design loop it replaces.

    Attributes
    ----------
    output, scene : str
        The sweep output and the shipped scene that gives every other value.
    axes : tuple of str
        ``--vary`` texts with ``{n}`` for the values an axis takes.
    per_design : callable
        ``per_design(values, options) -> ndarray``: the output one design at a
        time (``values`` as a sweep output's ``evaluate`` takes them).
    n : int
        Values per axis (N = n ** len(axes) designs).
    sample : int
        Designs the per-design loop runs (seeded picks from the grid).
    breakdown : callable, optional
        ``breakdown(plan, axes) -> {part: seconds}``: where the batched time
        goes, from a second run.
    at : tuple of str
        ``--at`` texts for arguments the scene does not give.
    run : callable, optional
        ``run(values, options, i) -> HybridRun``: design ``i`` of the grid's
        flat ``values`` as the per-design run (for the rows against
        ``solve_ivp``, :mod:`crane_sym.bench.batched_targets`); None: no such rows.
    targets : bool
        The case the batched solver's targets are measured on.
    block_target : float, optional
        Seconds for a grid of ``block_n`` values per axis as one block
        (:mod:`crane_sym.bench.design_targets`); None: no such row.
    block_n : int
        Values per axis of that grid.
    """

    output: str
    scene: str
    axes: tuple[str, ...]
    per_design: Callable
    n: int = 100
    sample: int = 24
    breakdown: Callable | None = None
    at: tuple[str, ...] = ()
    run: Callable | None = None
    targets: bool = False
    block_target: float | None = None
    block_n: int = 100


def batched_cases() -> list[tuple[str, BatchedBenchCase]]:
    """(paper id, case) of every paper that declares ``BATCHED_BENCH_CASES``."""
    return [(i, c) for i in registry.ids()
            for c in getattr(registry.module(i), "BATCHED_BENCH_CASES", ())]


def sweep_cases() -> list[tuple[str, SweepBenchCase]]:
    """(paper id, case) of every paper that declares ``SWEEP_BENCH_CASES``."""
    return [(i, c) for i in registry.ids()
            for c in getattr(registry.module(i), "SWEEP_BENCH_CASES", ())]


def sampled_cases() -> list[tuple[str, SampledBenchCase]]:
    """(paper id, case) of every paper that declares ``SAMPLED_BENCH_CASES``."""
    return [(i, c) for i in registry.ids()
            for c in _call(getattr(registry.module(i), "SAMPLED_BENCH_CASES", ()))]


def hand_written(paper: str) -> Mapping[str, Callable]:
    """The hand-written NumPy versions paper ``paper`` declares
    (``HAND_WRITTEN``), by generated function name.

    Parameters
    ----------
    paper : str
        The derivation id.
    """
    return dict(getattr(registry.module(paper), "HAND_WRITTEN", {}))


def _call(cases) -> Sequence:
    return cases() if callable(cases) else cases
