"""The papers audited, each built and judged in a process of its own when
more than one core is free.

A paper's build and audit share nothing with another paper's, and SymPy holds
the GIL, so two papers in two processes take about the time of the longer one
where one process takes their sum. The records come back in the papers'
order, the same records a single process gives (``tests/test_audit_papers.py``).
While they work, each worker's progress (the stage it is in, the step it
finished) is relayed to the parent through a queue and said there, so a
long paper is never a silence.
"""
from __future__ import annotations

import os
import queue
import time
from concurrent.futures import FIRST_COMPLETED, ProcessPoolExecutor, wait
from dataclasses import dataclass
from typing import Callable, TypeVar

from crane_sym import progress, registry
from crane_sym.audit.latex_parse import parse_table
from crane_sym.audit.recall import Recall, recall
from crane_sym.audit.verdicts import AuditRecord, audit

__all__ = ["PaperAudit", "audit_paper", "audit_papers", "in_processes", "workers"]

T = TypeVar("T")


@dataclass(frozen=True)
class PaperAudit:
    """One paper's records, with its build and audit times [s], its five
    slowest steps (seconds, label), how many sides of its prints the parser
    read afresh, not from the committed table, and the recall of its print
    (its printed items with a record)."""

    paper: str
    records: list[AuditRecord]
    build: float
    audit: float
    slowest: tuple[tuple[float, str], ...]
    parsed_fresh: int
    recall: Recall


def audit_paper(paper: str) -> PaperAudit:
    """Build one paper and judge its printed formulas, timed.

    Parameters
    ----------
    paper : str
        The paper's id.
    """
    say = progress.current()
    fresh = parse_table().fresh
    start = time.perf_counter()
    with say.task(f"building {paper}"):
        d = registry.get(paper)
    built = time.perf_counter()
    with say.task(f"auditing {paper} ({len(d.published)} printed formulas)"):
        records = audit(d)
    slowest = tuple((s.seconds, s.label) for s in sorted(d.steps, key=lambda s: -s.seconds)[:5])
    return PaperAudit(paper, records, built - start, time.perf_counter() - built, slowest,
                      parse_table().fresh - fresh, recall(d, records))


class _Relay(progress.Progress):
    """A worker's progress, sent to the parent's queue as ("say" | "step", text)."""

    def __init__(self, outbox) -> None:
        super().__init__(outbox is not None)
        self._outbox = outbox

    def say(self, message: str) -> None:
        if self.enabled:
            self._outbox.put(("say", message))

    def step(self, message: str) -> None:
        if self.enabled:
            self._outbox.put(("step", message))

    def done(self) -> None:
        """Nothing to clear: the parent owns the terminal."""


def _relayed(work: Callable[[str], T], paper: str, outbox) -> T:
    """``work(paper)`` in a worker process, its progress sent to ``outbox``
    (silent when None)."""
    with progress.reporting(_Relay(outbox)):
        return work(paper)


def _drain(inbox, say: progress.Progress) -> None:
    """Say what the workers have sent since the last call."""
    while True:
        try:
            kind, message = inbox.get_nowait()
        except (queue.Empty, OSError, EOFError):
            return
        (say.step if kind == "step" else say.say)(f"  {message}")


def in_processes(work: Callable[[str], T], papers: list[str], processes: int,
                 what: str, done: Callable[[T], str]) -> list[T]:
    """``work(paper)`` for each paper in ``processes`` worker processes, the
    results in the order of ``papers``; ``done(result)`` said as each comes back.

    Parameters
    ----------
    work : callable
        A module-level function of a paper's id (it is sent to the workers).
    papers : list of str
        The papers' ids.
    processes : int
        How many worker processes.
    what : str
        What is done, for the progress line of the whole.
    done : callable
        One progress line on a result.
    """
    import multiprocessing

    say = progress.current()
    with say.task(f"{what}: {len(papers)} papers in {processes} processes"), \
            multiprocessing.Manager() as manager, \
            ProcessPoolExecutor(max_workers=processes) as pool:
        inbox = manager.Queue() if say.enabled else None
        futures = {pool.submit(_relayed, work, paper, inbox): paper for paper in papers}
        results, pending = {}, set(futures)
        while pending:
            finished, pending = wait(pending, timeout=0.5, return_when=FIRST_COMPLETED)
            if inbox is not None:
                _drain(inbox, say)
            for future in finished:
                results[futures[future]] = future.result()
                say.say(f"  {done(results[futures[future]])} ({len(results)} of "
                        f"{len(papers)})")
    return [results[paper] for paper in papers]


def workers(papers: int) -> int:
    """Processes for ``papers`` papers: one a core this process may use, at most
    one a paper.

    Parameters
    ----------
    papers : int
        How many papers are to be audited.
    """
    cores = len(os.sched_getaffinity(0)) if hasattr(os, "sched_getaffinity") else os.cpu_count()
    return max(1, min(papers, cores or 1))


def audit_papers(papers: list[str], processes: int) -> list[PaperAudit]:
    """Each paper audited, in ``processes`` worker processes when more than one
    (in this one otherwise), the results in the order of ``papers``.

    Parameters
    ----------
    papers : list of str
        The papers' ids.
    processes : int
        How many processes to use (:func:`workers` gives one a core).
    """
    if processes <= 1 or len(papers) <= 1:
        return [audit_paper(paper) for paper in papers]
    return in_processes(audit_paper, papers, processes, "building and auditing",
                        lambda a: f"audited {a.paper}: {len(a.records)} printed formulas, "
                                  f"build {a.build:.1f} s, audit {a.audit:.1f} s")
