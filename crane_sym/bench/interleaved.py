"""Timings that can be trusted on a shared machine: every trial run once a
round, the rounds repeated, and each trial's minimum and median kept.

On a machine that other jobs share, a measurement taken minutes after another
compares two machines: the load moves between them. Interleaving puts the
1-worker and 2-worker runs of the code and of its controls (np.sin, a
memory-bound copy) in the same rounds, so a ratio of two trials compares
runs seconds apart; the order within a round is rotated round by round, so no
trial always follows the same one. A ratio is given from the minimum times
(what the machine gives when others leave it alone) and per round (its
spread over the rounds says how far the minimum can be trusted).
"""
from __future__ import annotations

import os
import resource
import time
from dataclasses import dataclass, field
from typing import Callable, Sequence

import numpy as np

from crane_sym import progress

__all__ = ["Rounds", "Trial", "efficiency", "run_rounds"]


@dataclass(frozen=True)
class Trial:
    """One thing timed once a round: ``run`` on ``workers`` cores."""

    name: str
    run: Callable[[], object]
    workers: int = 1


def _cpu() -> float:
    usage = resource.getrusage(resource.RUSAGE_SELF)
    return usage.ru_utime + usage.ru_stime


@dataclass
class Rounds:
    """Wall seconds of every trial in every round (``seconds[name][k]``),
    this process's CPU seconds per wall second in it (``cores``), and the
    one-minute load average at each round's start (``loads``)."""

    seconds: dict[str, list[float]] = field(default_factory=dict)
    cores: dict[str, list[float]] = field(default_factory=dict)
    loads: list[float] = field(default_factory=list)

    @property
    def count(self) -> int:
        """The rounds run (N)."""
        return len(self.loads)

    def least(self, name: str) -> float:
        """The least wall seconds of ``name`` over the rounds."""
        return min(self.seconds[name])

    def median(self, name: str) -> float:
        """The median wall seconds of ``name`` over the rounds."""
        return float(np.median(self.seconds[name]))

    def ratio(self, one: str, two: str, workers: int = 2) -> tuple[float, np.ndarray]:
        """Parallel efficiency T₁/(p·T_p) of trial ``two`` (on ``workers``)
        against ``one``: from the minimum times, and round by round."""
        a, b = np.array(self.seconds[one]), np.array(self.seconds[two])
        return self.least(one) / (workers * self.least(two)), a / (workers * b)


def efficiency(rounds: Rounds, one: str, two: str) -> dict[str, float | list[float]]:
    """T₁/(2·T₂) of ``two`` against ``one``: from the minima, the median and
    range over the rounds, each round's value.

    Parameters
    ----------
    rounds : Rounds
        The interleaved measurement.
    one, two : str
        The 1-worker and the 2-worker trial.
    """
    least, each = rounds.ratio(one, two)
    return {"least": least, "median": float(np.median(each)), "low": float(each.min()),
            "high": float(each.max()), "rounds": [float(e) for e in each]}


def run_rounds(trials: Sequence[Trial], count: int) -> Rounds:
    """Every trial once a round, ``count`` rounds, the order rotated by one
    each round; one untimed call of each first (imports, allocations).

    Parameters
    ----------
    trials : sequence of Trial
        What is timed, each once a round.
    count : int
        Rounds (N), at least 1.

    >>> r = run_rounds([Trial("a", lambda: None), Trial("b", lambda: None, 2)], 3)
    >>> r.count, len(r.seconds["b"])
    (3, 3)
    """
    if count < 1:
        raise ValueError(f"interleaved rounds: need at least 1, got {count}")
    say = progress.current()
    for t in trials:
        t.run()
    out = Rounds({t.name: [] for t in trials}, {t.name: [] for t in trials})
    for k in range(count):
        out.loads.append(os.getloadavg()[0])
        say.step(f"  round {k + 1} of {count} (load {out.loads[-1]:.1f}) ...")
        turn = k % len(trials)
        for t in [*trials[turn:], *trials[:turn]]:
            start, cpu = time.perf_counter(), _cpu()
            t.run()
            wall = time.perf_counter() - start
            out.seconds[t.name].append(wall)
            out.cores[t.name].append((_cpu() - cpu) / wall if wall > 0 else 0.0)
    return out
