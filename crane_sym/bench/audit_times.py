"""The main job's time: ``crane-sym audit`` of every paper and
``crane-sym generate --check``, each in a fresh process, against their targets,
and where an audit's time goes, paper by paper and stage by stage.

Targets: the audit of the five papers at most 20 s from a cold process, and
``generate --check`` at most 20 s. The stages of one paper's audit are its
build (``registry.get``), the checks of its printed formulas
(``audit_formula``: symbolic, numeric, dimensions), and the machine reading of
its prints (``machine_read``), the last with how many look-ups of the prints'
sides the committed table of parses answered (an unreadable side is looked up
each time it is met) and how many sides the Earley parser read afresh
(``crane_sym.audit.parse_table``). The audit's schedule (which paper ran on
which worker, from when to when, and the makespan) is the one its own
``--profile`` printed in that run. The machine is shared, so each
measurement is quoted with the load average before and after it. Where
``generate --check``'s time goes is each paper's share of it
(``scenes.generate.paper_files``: its build, its module, each scene's module,
the machine reading of its prints) timed in one fresh process.
"""
from __future__ import annotations

import multiprocessing
import os
import subprocess
import sys
import time
from concurrent.futures import ProcessPoolExecutor
from dataclasses import dataclass
from typing import Sequence

from crane_sym import registry
from crane_sym.audit.latex_parse import parse_side, parse_table
from crane_sym.audit.machine_read import machine_read
from crane_sym.audit.verdicts import audit_formula
from crane_sym.markdown import markdown_table

__all__ = ["AUDIT_TARGET", "CHECK_TARGET", "CommandTime", "PaperTimes", "ShareTimes",
           "as_markdown", "command_time", "paper_times", "share_times"]

#: Seconds: the audit of every paper from a cold process, and ``generate --check``.
AUDIT_TARGET = 20.0
CHECK_TARGET = 20.0


@dataclass(frozen=True)
class PaperTimes:
    """One paper's audit, stage by stage, in seconds (wall)."""

    paper: str
    formulas: int
    build: float
    checks: float
    reading: float
    from_table: int            # look-ups of its prints' sides the table answered
    parsed_fresh: int          # sides the Earley parser read afresh

    @property
    def total(self) -> float:
        """Build, checks and machine reading together."""
        return self.build + self.checks + self.reading


@dataclass(frozen=True)
class ShareTimes:
    """One paper's share of ``generate --check``, stage by stage, in seconds
    (wall): ``build``, ``module``, ``scene <name>`` a scene, ``machine reading``."""

    paper: str
    stages: tuple[tuple[str, float], ...]

    def seconds(self, stage: str) -> float:
        """The seconds of the stages named ``stage`` or ``stage <name>``."""
        return sum(t for name, t in self.stages
                   if name == stage or name.startswith(stage + " "))

    @property
    def total(self) -> float:
        """Every stage together."""
        return sum(t for _, t in self.stages)


@dataclass(frozen=True)
class CommandTime:
    """One command run in a fresh process: its wall time, its target, and the
    one-minute load average before and after it."""

    command: str
    seconds: float
    target: float
    load_before: float
    load_after: float
    schedule: tuple[str, ...] = ()   # its `schedule:` lines on stderr (audit --profile)

    @property
    def met(self) -> bool:
        """True when the command took at most its target."""
        return self.seconds <= self.target


def paper_times(ids: Sequence[str]) -> list[PaperTimes]:
    """Each paper built, its formulas checked and its prints read by machine,
    timed stage by stage in this process (the first build of each paper here).

    Parameters
    ----------
    ids : sequence of str
        The papers, by id.
    """
    table = parse_table()
    out = []
    for i in ids:
        parse_side.cache_clear()            # each paper's sides counted, as in a cold run
        found, fresh = table.found, table.fresh
        start = time.perf_counter()
        d = registry.get(i, code=False)      # as the audit builds it
        built = time.perf_counter()
        for f in d.published:
            audit_formula(d, f)
        checked = time.perf_counter()
        for f in d.published:
            machine_read(d, f)
        read = time.perf_counter()
        out.append(PaperTimes(i, len(d.published), built - start, checked - built,
                              read - checked, table.found - found, table.fresh - fresh))
    return out


def _shares(ids: list[str]) -> list[ShareTimes]:
    # imported on use: the bench's other sections need no scene machinery
    from crane_sym.scenes.generate import paper_files
    out = []
    for i in ids:
        stages: dict[str, float] = {}
        paper_files(i, stages)
        out.append(ShareTimes(i, tuple(stages.items())))
    return out


def share_times(ids: Sequence[str]) -> list[ShareTimes]:
    """Each paper's share of ``generate --check``, stage by stage, the papers
    one after another in one fresh process (spawned, so nothing is built or
    cached before it).

    Parameters
    ----------
    ids : sequence of str
        The papers, by id.
    """
    with ProcessPoolExecutor(1, mp_context=multiprocessing.get_context("spawn")) as pool:
        return pool.submit(_shares, list(ids)).result()


def command_time(args: Sequence[str], target: float) -> CommandTime:
    """``python -m crane_sym ARGS`` run in a fresh process (its output discarded),
    timed; RuntimeError naming the command if it fails.

    Parameters
    ----------
    args : sequence of str
        The command line after ``crane-sym``.
    target : float
        The command's target [s].
    """
    before = os.getloadavg()[0]
    start = time.perf_counter()
    done = subprocess.run([sys.executable, "-m", "crane_sym", *args], stdout=subprocess.DEVNULL,
                          stderr=subprocess.PIPE, text=True)
    seconds = time.perf_counter() - start
    if done.returncode != 0:
        last = (done.stderr.strip().splitlines() or ["no message"])[-1]
        raise RuntimeError(f"bench --audit: `crane-sym {' '.join(args)}` exited "
                           f"{done.returncode}: {last}")
    schedule = tuple(line[len("schedule: "):] for line in done.stderr.splitlines()
                     if line.startswith("schedule: "))
    return CommandTime("crane-sym " + " ".join(args), seconds, target, before,
                       os.getloadavg()[0], schedule)


def as_markdown(commands: Sequence[CommandTime], papers: Sequence[PaperTimes],
                shares: Sequence[ShareTimes] = ()) -> str:
    """The targets table (met / not met) and the stages tables.

    Parameters
    ----------
    commands : sequence of CommandTime
        The commands timed in fresh processes.
    papers : sequence of PaperTimes
        The stages of each paper's audit.
    shares : sequence of ShareTimes, optional
        The stages of each paper's share of ``generate --check``.
    """
    targets = markdown_table(
        ["command (fresh process)", "seconds", "target", "met", "load before / after"],
        [[f"`{c.command}`", f"{c.seconds:.1f}", f"≤ {c.target:g} s",
          "met" if c.met else "not met", f"{c.load_before:.2f} / {c.load_after:.2f}"]
         for c in commands])
    rows = [[p.paper, str(p.formulas), f"{p.build:.2f}", f"{p.checks:.2f}",
             f"{p.reading:.2f}", f"{p.from_table} / {p.parsed_fresh}", f"{p.total:.2f}"]
            for p in papers]
    rows.append(["all", str(sum(p.formulas for p in papers)),
                 *(f"{sum(getattr(p, s) for p in papers):.2f}"
                   for s in ("build", "checks", "reading")),
                 f"{sum(p.from_table for p in papers)} / "
                 f"{sum(p.parsed_fresh for p in papers)}",
                 f"{sum(p.total for p in papers):.2f}"])
    schedules = [line for c in commands if c.schedule
                 for line in ["", f"Schedule of `{c.command}` (its own --profile):", "",
                              *(f"- {s}" for s in c.schedule)]]
    stages = markdown_table(
        ["paper", "formulas", "build s", "checks s", "machine reading s",
         "table look-ups / sides parsed afresh", "total s"], rows)
    parts = ["## Targets", "", targets, *schedules, "", "## Where an audit's time goes "
             "(one process, paper by paper)", "", stages]
    if shares:
        def slowest(share: ShareTimes) -> str:
            scenes = [(t, name[len("scene "):]) for name, t in share.stages
                      if name.startswith("scene ")]
            return f"{max(scenes)[1]} {max(scenes)[0]:.2f}" if scenes else "—"
        kinds = ("build", "module", "scene", "machine reading")
        rows = [[s.paper, *(f"{s.seconds(k):.2f}" for k in kinds), slowest(s), f"{s.total:.2f}"]
                for s in shares]
        rows.append(["all", *(f"{sum(s.seconds(k) for s in shares):.2f}" for k in kinds), "",
                     f"{sum(s.total for s in shares):.2f}"])
        parts += ["", "## Where generate --check's time goes (one fresh process, paper by "
                  "paper)", "", markdown_table(["paper", "build s", "module s", "scenes s",
                                                "machine reading s", "slowest scene s",
                                                "total s"], rows)]
    return "\n".join(parts)
