"""The papers audited, each built and judged in a process of its own when
more than one core is free.

A paper's build and audit share nothing with another paper's, and SymPy holds
the GIL, so two papers in two processes take about the time of the longer one
where one process takes their sum. The records come back in the papers'
order, the same records a single process gives (``tests/test_audit_papers.py``).
The papers are handed to the pool longest first (LPT: a paper's last measured
seconds, ``registry.AUDIT_SECONDS``), so the longest never starts last and
leaves one core idle at the end; each paper's slot (its worker, its start and
end) is kept, the schedule ``audit --profile`` prints. While they work, each worker's progress (the stage it is in, the step it
finished) is relayed to the parent through a queue and said there, so a
long paper is never a silence.
"""
from __future__ import annotations

import math
import os
import queue
import time
from concurrent.futures import FIRST_COMPLETED, ProcessPoolExecutor, wait
from dataclasses import dataclass, replace
from typing import Callable, Generic, Mapping, TypeVar

from crane_sym import progress, registry
from crane_sym.audit.latex_parse import parse_table
from crane_sym.audit.recall import Recall, recall
from crane_sym.audit.verdicts import AuditRecord, audit

__all__ = ["PaperAudit", "Pooled", "Slot", "audit_paper", "audit_papers", "in_processes",
           "longest_first", "schedule_text", "workers"]

T = TypeVar("T")


@dataclass(frozen=True)
class Slot:
    """Where and when one paper's work ran: its worker (1, 2, ... in the order
    the workers first reported; 0 for this process) and its start and end [s]
    after the work began."""

    paper: str
    worker: int
    start: float
    end: float


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
    slot: Slot | None = None


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
        d = registry.get(paper, code=False)      # no outputs: the audit reads none
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


def longest_first(papers: list[str], seconds: Mapping[str, float]) -> list[str]:
    """``papers`` in the order a pool should take them: the longest by
    ``seconds`` first (one without an estimate before all, as it may be the
    longest), ties in the papers' order.

    Parameters
    ----------
    papers : list of str
        The papers' ids.
    seconds : mapping of str to float
        Each paper's estimated seconds.

    >>> longest_first(["a", "b", "c"], {"a": 1.0, "b": 5.0, "c": 1.0})
    ['b', 'a', 'c']
    """
    return sorted(papers, key=lambda p: -seconds.get(p, math.inf))


@dataclass(frozen=True)
class Pooled(Generic[T]):
    """What a pool gave: the results in the papers' order, and each paper's slot."""

    results: list[T]
    slots: list[Slot]


def _timed(work: Callable[[str], T], paper: str, outbox) -> tuple[T, int, float, float]:
    """``work(paper)`` relayed (:func:`_relayed`), with this worker's process id
    and its start and end on the system's monotonic clock."""
    start = time.monotonic()
    result = _relayed(work, paper, outbox)
    return result, os.getpid(), start, time.monotonic()


def in_processes(work: Callable[[str], T], papers: list[str], processes: int,
                 what: str, done: Callable[[T], str],
                 seconds: Mapping[str, float] | None = None) -> Pooled[T]:
    """``work(paper)`` for each paper in ``processes`` worker processes,
    submitted longest first (:func:`longest_first`; in the papers' order
    without ``seconds``), the results in the order of ``papers`` with each
    paper's slot; ``done(result)`` said as each comes back.

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
    seconds : mapping of str to float, optional
        Each paper's estimated seconds: the longest are submitted first.
    """
    import multiprocessing

    say = progress.current()
    with say.task(f"{what}: {len(papers)} papers in {processes} processes"), \
            multiprocessing.Manager() as manager, \
            ProcessPoolExecutor(max_workers=processes) as pool:
        inbox = manager.Queue() if say.enabled else None
        began = time.monotonic()
        order = longest_first(papers, seconds) if seconds is not None else papers
        futures = {pool.submit(_timed, work, paper, inbox): paper for paper in order}
        results, pending, ran = {}, set(futures), {}
        while pending:
            finished, pending = wait(pending, timeout=0.5, return_when=FIRST_COMPLETED)
            if inbox is not None:
                _drain(inbox, say)
            for future in finished:
                paper = futures[future]
                results[paper], *ran[paper] = future.result()
                say.say(f"  {done(results[paper])} ({len(results)} of {len(papers)})")
    pids = list(dict.fromkeys(ran[p][0] for p in sorted(ran, key=lambda p: ran[p][1])))
    slots = [Slot(p, pids.index(ran[p][0]) + 1, ran[p][1] - began, ran[p][2] - began)
             for p in papers]
    return Pooled([results[paper] for paper in papers], slots)


def schedule_text(slots: list[Slot]) -> str:
    """The schedule in lines: each worker's papers with their start and end
    [s], and the makespan (the last end).

    Parameters
    ----------
    slots : list of Slot
        Each paper's slot.

    >>> print(schedule_text([Slot("a", 1, 0.1, 2.0), Slot("b", 2, 0.1, 1.0)]))
    worker 1: a 0.1–2.0 s
    worker 2: b 0.1–1.0 s
    makespan 2.0 s
    """
    lines = []
    for worker in sorted({s.worker for s in slots}):
        mine = sorted((s for s in slots if s.worker == worker), key=lambda s: s.start)
        name = "this process" if worker == 0 else f"worker {worker}"
        lines.append(f"{name}: " + ", ".join(f"{s.paper} {s.start:.1f}–{s.end:.1f} s"
                                             for s in mine))
    lines.append(f"makespan {max((s.end for s in slots), default=0.0):.1f} s")
    return "\n".join(lines)


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
        began, out = time.monotonic(), []
        for paper in papers:
            start = time.monotonic() - began
            a = audit_paper(paper)
            out.append(replace(a, slot=Slot(paper, 0, start, time.monotonic() - began)))
        return out
    pool = in_processes(audit_paper, papers, processes, "building and auditing",
                        lambda a: f"audited {a.paper}: {len(a.records)} printed formulas, "
                                  f"build {a.build:.1f} s, audit {a.audit:.1f} s",
                        registry.AUDIT_SECONDS)
    return [replace(a, slot=slot) for a, slot in zip(pool.results, pool.slots)]
