"""The fault tables counted by the harm each case guards against: one
rerunnable command prints, per class, the cases tried and passed.

    python tests/fault_counts.py [pytest options]

A case is a test (a row of a table) marked ``@pytest.mark.harm(kind)``, by
its module's ``pytestmark`` or by its own mark:

- ``pages``: a page, a plot or a terminal runs or shows what a file's text
  smuggles in (script, MathML attributes, fences, escape codes, mathtext);
- ``writes``: a write replaces a device, a FIFO, a socket, a link's target or
  the command's own input;
- ``bounds``: a formula or a model takes more than a stated bound of time and
  memory (formula bombs, model sizes, a sweep's estimate);
- ``one-line``: a failure that is not one line naming the part, the value and
  the bound, with exit 2 and nothing written (tracebacks, warnings before the
  line, anonymous messages, signals).

The tables run in this process, one at a time (``-n 0``); a skipped case (a
device node needs root, Chromium may be missing) is counted as tried and
named, never as passed.
"""
from __future__ import annotations

import sys
from collections import Counter
from pathlib import Path

import pytest

HERE = Path(__file__).resolve().parent
#: The tables: every test module that marks its cases with a harm.
TABLES = sorted(p.name for p in HERE.glob("test_*.py")
                if "pytest.mark.harm(" in p.read_text(encoding="utf-8"))
#: The classes, in the order printed.
KINDS = ("pages", "writes", "bounds", "one-line")


class Tally:
    """A pytest plugin: each marked case's outcome, by its class."""

    def __init__(self) -> None:
        self.kind: dict[str, str] = {}
        self.outcome: dict[str, str] = {}

    def pytest_collection_modifyitems(self, items) -> None:
        for item in items:
            mark = item.get_closest_marker("harm")
            if mark is not None:
                if mark.args[0] not in KINDS:
                    raise ValueError(f"{item.nodeid}: harm {mark.args[0]!r} is not one of "
                                     f"{KINDS}")
                self.kind[item.nodeid] = mark.args[0]

    def pytest_runtest_logreport(self, report) -> None:
        if report.nodeid not in self.kind:
            return
        before = self.outcome.get(report.nodeid, "passed")
        if report.failed:
            self.outcome[report.nodeid] = "failed"
        elif report.skipped and before != "failed":
            self.outcome[report.nodeid] = "skipped"
        elif report.when == "call" and before == "passed":
            self.outcome[report.nodeid] = "passed"

    def lines(self) -> list[str]:
        """One line a class: tried, passed, and the cases that did not pass."""
        out = []
        for kind in KINDS:
            cases = [n for n, k in self.kind.items() if k == kind and n in self.outcome]
            counts = Counter(self.outcome[n] for n in cases)
            line = f"{kind}: tried {len(cases)}, passed {counts['passed']}"
            for what in ("failed", "skipped"):
                if counts[what]:
                    line += f", {what} {counts[what]}"
            out.append(line)
            out += [f"  {self.outcome[n]}: {n}" for n in cases if self.outcome[n] != "passed"]
        return out


def main(argv: list[str]) -> int:
    """Run the tables with ``argv`` as extra pytest options; print the counts."""
    tally = Tally()
    code = pytest.main(["-n", "0", "-q", "-p", "no:cacheprovider", "-m", "harm",
                        *[str(HERE / t) for t in TABLES], *argv], plugins=[tally])
    print("\n".join(["", f"fault tables ({', '.join(TABLES)}):", *tally.lines()]))
    return int(code)


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
