"""Papers audited in worker processes give the records one process gives, in
the papers' order; the bench of the main job says met or not met."""
from __future__ import annotations

import pytest

pytest.importorskip("lark")

from crane_sym.audit.papers import audit_papers, workers  # noqa: E402
from crane_sym.bench.audit_times import (CommandTime, PaperTimes, as_markdown,  # noqa: E402
                                         paper_times)

PAPERS = ["hoist_brakes", "travel_braking"]


def test_two_processes_give_the_records_of_one_in_the_papers_order():
    serial = audit_papers(PAPERS, 1)
    parallel = audit_papers(PAPERS, 2)
    assert [a.paper for a in parallel] == PAPERS
    assert [[r.as_dict() for r in a.records] for a in parallel] == \
        [[r.as_dict() for r in a.records] for a in serial]
    assert all(a.records and a.build > 0 and a.slowest for a in parallel)


def test_workers_are_at_most_one_a_paper():
    assert workers(1) == 1 and 1 <= workers(5) <= 5


def test_the_targets_table_says_met_and_not_met():
    fast = CommandTime("crane-sym audit", 12.0, 20.0, 1.0, 1.5)
    slow = CommandTime("crane-sym generate --check", 31.0, 20.0, 2.0, 2.5)
    papers = [PaperTimes("a", 3, 1.0, 2.0, 0.5, 10, 0), PaperTimes("b", 2, 2.0, 1.0, 0.5, 4, 1)]
    text = as_markdown([fast, slow], papers)
    assert "| `crane-sym audit` | 12.0 | ≤ 20 s | met | 1.00 / 1.50 |" in text
    assert "| `crane-sym generate --check` | 31.0 | ≤ 20 s | not met |" in text
    assert "| all | 5 | 3.00 | 3.00 | 1.00 | 14 / 1 | 7.00 |" in text


def test_a_papers_stages_are_timed():
    (times,) = paper_times(["travel_braking"])
    assert times.formulas > 0 and min(times.build, times.checks, times.reading) > 0
    assert times.from_table + times.parsed_fresh > 0
