"""Papers audited in worker processes give the records one process gives, in
the papers' order; the bench of the main job says met or not met."""
from __future__ import annotations

import pytest

pytest.importorskip("lark")

from crane_sym import registry  # noqa: E402
from crane_sym.audit.papers import (Slot, audit_paper, audit_papers,  # noqa: E402
                                    longest_first, schedule_text, workers)
from crane_sym.audit.verdicts import audit  # noqa: E402
from crane_sym.codegen.module import render_module  # noqa: E402
from crane_sym.bench.audit_times import (CommandTime, PaperTimes, ShareTimes,  # noqa: E402
                                         as_markdown, paper_times, share_times)

PAPERS = ["hoist_brakes", "travel_braking"]


def test_two_processes_give_the_records_of_one_in_the_papers_order():
    serial = audit_papers(PAPERS, 1)
    parallel = audit_papers(PAPERS, 2)
    assert [a.paper for a in parallel] == PAPERS
    assert [[r.as_dict() for r in a.records] for a in parallel] == \
        [[r.as_dict() for r in a.records] for a in serial]
    assert all(a.records and a.build > 0 and a.slowest for a in parallel)
    slots = [a.slot for a in parallel]
    assert [s.paper for s in slots] == PAPERS and {s.worker for s in slots} <= {1, 2}
    assert all(0 <= s.start < s.end for s in slots)
    assert [a.slot.worker for a in serial] == [0, 0]        # this process, in order
    assert serial[0].slot.end <= serial[1].slot.start


def test_the_audit_builds_a_paper_without_its_code_and_judges_it_alike(monkeypatch):
    asked = []
    get = registry.get
    monkeypatch.setattr(registry, "get",
                        lambda name, code=True: asked.append(code) or get(name, code=code))
    audit_paper("travel_braking")
    assert asked == [False]
    light, full = registry.built("travel_braking", False), registry.get("travel_braking")
    assert not light.code and not (light.outputs or light.ode_systems)
    assert full.code and full.outputs and full.ode_systems
    assert [s.label for s in light.steps] == [s.label for s in full.steps]
    assert [r.as_dict() for r in audit(light)] == [r.as_dict() for r in audit(full)]
    assert registry.get("travel_braking", code=False) is full   # a full build serves
    with pytest.raises(ValueError, match="built without its outputs"):
        render_module(light)


def test_the_pool_takes_the_longest_paper_first():
    assert longest_first(["a", "b", "c", "d"], {"a": 1.0, "b": 9.0, "c": 3.0}) == \
        ["d", "b", "c", "a"]                                # unknown d may be longest
    ids = registry.ids()
    assert set(registry.AUDIT_SECONDS) == set(ids) == set(registry.GENERATE_SECONDS)
    order = longest_first(ids, registry.AUDIT_SECONDS)
    assert [registry.AUDIT_SECONDS[i] for i in order] == \
        sorted(registry.AUDIT_SECONDS.values(), reverse=True)


def test_the_schedule_names_each_workers_papers_and_the_makespan():
    text = schedule_text([Slot("a", 1, 0.2, 5.0), Slot("b", 2, 0.2, 3.0),
                          Slot("c", 2, 3.0, 6.5)])
    assert text.splitlines() == ["worker 1: a 0.2–5.0 s", "worker 2: b 0.2–3.0 s, c 3.0–6.5 s",
                                 "makespan 6.5 s"]


def test_workers_are_at_most_one_a_paper():
    assert workers(1) == 1 and 1 <= workers(5) <= 5


def test_the_targets_table_says_met_and_not_met():
    fast = CommandTime("crane-sym audit", 12.0, 20.0, 1.0, 1.5,
                       ("worker 1: a 0.1–9.0 s", "makespan 9.0 s"))
    slow = CommandTime("crane-sym generate --check", 31.0, 20.0, 2.0, 2.5)
    papers = [PaperTimes("a", 3, 1.0, 2.0, 0.5, 10, 0), PaperTimes("b", 2, 2.0, 1.0, 0.5, 4, 1)]
    text = as_markdown([fast, slow], papers)
    assert "| `crane-sym audit` | 12.0 | ≤ 20 s | met | 1.00 / 1.50 |" in text
    assert "| `crane-sym generate --check` | 31.0 | ≤ 20 s | not met |" in text
    assert "| all | 5 | 3.00 | 3.00 | 1.00 | 14 / 1 | 7.00 |" in text
    assert "- worker 1: a 0.1–9.0 s\n- makespan 9.0 s" in text


def test_generates_stages_are_tabled_with_each_papers_slowest_scene():
    shares = [ShareTimes("a", (("build", 1.0), ("module", 2.0), ("scene x", 0.5),
                               ("scene y", 1.5), ("machine reading", 0.25))),
              ShareTimes("b", (("build", 2.0), ("machine reading", 0.5)))]
    assert shares[0].seconds("scene") == 2.0 and shares[0].total == 5.25
    text = as_markdown([], [], shares)
    assert "## Where generate --check's time goes (one fresh process, paper by paper)" in text
    assert "| a | 1.00 | 2.00 | 2.00 | 0.25 | y 1.50 | 5.25 |" in text
    assert "| b | 2.00 | 0.00 | 0.00 | 0.50 | — | 2.50 |" in text
    assert "| all | 3.00 | 2.00 | 2.00 | 0.75 |  | 7.75 |" in text
    assert "generate --check's time" not in as_markdown([], [])


def test_a_papers_share_of_generate_is_timed_in_a_fresh_process():
    (share,) = share_times(["travel_braking"])
    names = [name for name, _ in share.stages]
    assert names == ["build", "module", "scene overhead_crane_50t", "machine reading"]
    assert all(t > 0 for _, t in share.stages)


def test_a_papers_stages_are_timed():
    (times,) = paper_times(["travel_braking"])
    assert times.formulas > 0 and min(times.build, times.checks, times.reading) > 0
    assert times.from_table + times.parsed_fresh > 0


def test_audit_profile_prints_the_schedule(capsys):
    from crane_sym.cli.main import main
    assert main(["audit", "000", "--format", "json", "--quiet", "--profile"]) == 0
    err = capsys.readouterr().err.splitlines()
    schedule = [line for line in err if line.startswith("schedule: ")]
    assert schedule[0].startswith("schedule: this process: travel_braking 0.0–")
    assert schedule[-1].startswith("schedule: makespan ")
