"""The roofline beside the sweep's parallel efficiency: trials interleaved
round by round, the controls measured on small arrays, Amdahl's serial
fraction fitted with its range over the rounds (and called unstable where
it is), the scaling curve's measured and modelled parts, and the verdict's
reason. No timing is asserted."""
import os

import numpy as np
import pytest

from crane_sym.bench import interleaved as il
from crane_sym.bench import roofline as rl


def _roof(sin, add, cores=2, rounds=(None, None)):
    sin_rounds = [sin if r is None else r for r in rounds]
    return {"cores": cores, "elements": 8, "rounds": len(rounds), "loads": [1.0, 1.5],
            "sin": {"one_s": 2.0, "two_s": 1.0, "one_median_s": 2.0, "two_median_s": 1.0,
                    "efficiency": sin, "efficiency_rounds": sin_rounds},
            "add": {"one_s": 1.0, "two_s": 1.0, "one_median_s": 1.0, "two_median_s": 1.0,
                    "efficiency": add, "efficiency_rounds": [add, add],
                    "gb_per_s_one": 10.0, "gb_per_s_two": 20 * add},
            "copy": {"one_s": 1.0, "two_s": 1.0, "one_median_s": 1.0, "two_median_s": 1.0,
                     "efficiency": 0.5, "efficiency_rounds": [0.5, 0.5],
                     "gb_per_s_one": 5.0, "gb_per_s_two": 5.0}}


def _sweep(least, rounds):
    return {"least": least, "rounds": list(rounds), "median": float(np.median(rounds)),
            "low": min(rounds), "high": max(rounds)}


def test_rounds_run_every_trial_once_a_round_in_a_rotated_order():
    order = []
    trials = [il.Trial(name, lambda n=name: order.append(n)) for name in "abc"]
    r = il.run_rounds(trials, 3)
    assert order[:3] == list("abc")                     # the untimed first calls
    assert order[3:] == list("abc") + list("bca") + list("cab")
    assert r.count == 3 and all(len(r.seconds[n]) == 3 for n in "abc")
    assert r.least("a") == min(r.seconds["a"]) and r.median("a") > 0
    with pytest.raises(ValueError, match="at least 1, got 0"):
        il.run_rounds(trials, 0)


def test_efficiency_from_the_minima_and_round_by_round():
    r = il.Rounds({"one": [2.0, 4.0, 3.0], "two": [2.0, 1.0, 1.5]}, {}, [1.0, 1.0, 1.0])
    e = il.efficiency(r, "one", "two")
    assert e["least"] == pytest.approx(2.0 / (2 * 1.0))
    assert e["rounds"] == pytest.approx([0.5, 2.0, 1.0])
    assert (e["low"], e["median"], e["high"]) == pytest.approx((0.5, 1.0, 2.0))


def test_roofline_measures_each_control_on_one_and_two_threads():
    from concurrent.futures import ThreadPoolExecutor
    with ThreadPoolExecutor(2) as pool:
        measured = il.run_rounds(rl.control_trials(pool, 2**12), 2)
    r = rl.roofline(measured, 2**12)
    assert r["rounds"] == 2 and len(r["loads"]) == 2
    for name in ("copy", "add", "sin"):
        m = r[name]
        assert m["one_s"] > 0 and m["two_s"] > 0 and len(m["efficiency_rounds"]) == 2
        assert m["efficiency"] == pytest.approx(m["one_s"] / (2 * m["two_s"]))
        assert m["one_s"] <= m["one_median_s"]
    assert r["add"]["gb_per_s_one"] == pytest.approx(3 * 8 * 2**12 / 1e9 / r["add"]["one_s"])


def test_control_trials_run_the_kernel_on_both_halves():
    from concurrent.futures import ThreadPoolExecutor
    with ThreadPoolExecutor(2) as pool:
        trials = {t.name: t for t in rl.control_trials(pool, 10)}
        trials["sin, 2 threads"].run()
        trials["sin, 1 thread"].run()
    assert trials["sin, 2 threads"].workers == 2 and trials["sin, 1 thread"].workers == 1


def test_serial_fraction_inverts_amdahl():
    for f in (0.0, 0.1, 0.4):
        efficiency = rl.amdahl(2, f) / 2
        assert rl.serial_fraction(efficiency, 1.0) == pytest.approx(f)
        assert rl.serial_fraction(0.9 * efficiency, 0.9) == pytest.approx(f)
    assert rl.serial_fraction(0.3, 1.0) == 1.0            # slower on two: all serial
    assert rl.serial_fraction(0.99, 0.9) == 0.0           # above the control: none


def test_fit_is_stable_only_where_the_rounds_agree():
    f = 0.2
    e = rl.amdahl(2, f) / 2
    steady = rl.fit_serial(_sweep(e, [e, 0.9 * e]), _roof(1.0, 0.9, rounds=(1.0, 0.9)))
    assert steady["fraction"] == pytest.approx(f) and steady["stable"] and not steady["why"]
    assert steady["low"] == pytest.approx(f) and steady["high"] == pytest.approx(f)
    moving = rl.fit_serial(_sweep(e, [e, 0.55]), _roof(1.0, 0.9, rounds=(1.0, 0.9)))
    assert not moving["stable"] and "wider than 0.1" in moving["why"]
    assert moving["high"] - moving["low"] > rl.STABLE_WIDTH
    beaten = rl.fit_serial(_sweep(e, [e, e]), _roof(1.0, 0.9, rounds=(1.0, 0.5)))
    assert not beaten["stable"] and "beat np.sin" in beaten["why"]


def test_scaling_curve_measured_only_where_the_cores_are():
    fit = {"fraction": 0.25, "low": 0.2, "high": 0.3}
    curve = rl.scaling_curve(0.8, fit, _roof(1.0, 0.6), workers=rl.WORKERS)
    assert [c["workers"] for c in curve] == list(range(1, 17))
    assert curve[1]["measured"] == pytest.approx(1.6)
    assert all(c["measured"] is None for c in curve[2:])
    speedups = [c["modelled"] for c in curve]
    assert speedups == sorted(speedups) and speedups[-1] < 1 / 0.25   # Amdahl's bound
    assert all(c["low"] <= c["modelled"] <= c["high"] for c in curve)
    assert curve[-1]["high"] < 1 / 0.2 and curve[-1]["low"] < curve[-1]["high"]
    assert curve[-1]["memory_ceiling"] == pytest.approx(1.2)


@pytest.mark.parametrize("sin, add, reason", [(0.6, 0.9, "the machine"),
                                               (0.95, 0.6, "memory bandwidth"),
                                               (0.95, 0.9, "the code")])
def test_verdict_names_why_the_target_is_not_met(sin, add, reason):
    assert rl.verdict(0.5, 0.7, _roof(sin, add)).startswith(f"not met: {reason}")
    assert rl.verdict(0.75, 0.7, _roof(sin, add)) == "met"


def test_markdown_says_which_rows_are_measured_and_which_modelled():
    stable = {"fraction": 0.2, "low": 0.18, "high": 0.22, "stable": True, "why": ""}
    text = "\n".join(rl.markdown_rows(0.5, 0.7, _roof(0.6, 0.9), stable))
    assert "| 2 | 1.00 |" in text and "| 3 | — |" in text
    assert "*measured*" in text and "*modelled*" in text and ": stable;" in text
    assert "not met: the machine" in text and "unstable" not in text
    shaky = dict(stable, low=0.0, high=0.7, stable=False, why="the range is wider than 0.1")
    text = "\n".join(rl.markdown_rows(0.5, 0.7, _roof(0.6, 0.9), shaky))
    assert "NOT STABLE (the range is wider than 0.1)" in text
    assert all("(unstable fit)" in line for line in text.splitlines() if line.startswith("| 16 "))


def _row(**changed):
    row = {"designs": 4, "output": "y", "blocks": 2, "block_designs": [2, 2],
           "scheduler": "threads", "rounds": 2, "loads": [1.0, 1.5], "efficiency": 0.5,
           "sweep": _sweep(0.5, [0.5, 0.45]), "no_dask_seconds": 1.0, "no_dask_median": 1.1,
           "dask_seconds": 1.0, "dask_median": 1.2, "dask_cores": 1.0,
           "relative": {"least": 0.83, "median": 0.8, "low": 0.75, "high": 0.83},
           "same_worst": True, "target": 0.7, "variants": [
               {"trial": "sweep, no Dask", "workers": 1, "least_s": 1.0, "median_s": 1.1,
                "ratio": 1.0, "low": 1.0, "high": 1.0},
               {"trial": "6 blocks, Dask's threads", "workers": 2, "least_s": 0.7,
                "median_s": 0.8, "ratio": 0.71, "low": 0.6, "high": 0.71,
                "relative": {"least": 1.18, "median": 1.0, "low": 0.9, "high": 1.18}}],
           "met": False, "roofline": _roof(0.6, 0.9),
           "fit": {"fraction": 0.4, "low": 0.3, "high": 0.6, "stable": False,
                   "why": "the range is wider than 0.1"}}
    return {**row, **changed}


def test_parallel_section_alone_from_the_command_line(monkeypatch, capsys):
    from crane_sym.bench import batched_targets
    from crane_sym.cli.main import main
    monkeypatch.setattr(batched_targets, "thread_row", lambda case: _row())
    assert main(["bench", "--parallel", "--quiet"]) == 0
    out = capsys.readouterr().out
    assert "efficiency 50 % from the minima" in out and "| 16 | — |" in out
    assert "83 % of what this machine gave np.sin" in out and "2 interleaved rounds" in out
    assert "not met: the machine" in out and "NOT STABLE" in out
    assert ("| 6 blocks, Dask's threads | 2 | 0.70 | 0.80 | 71 % (60–71 %) | "
            "118 % (90–118 %) |") in out


def test_thread_row_measures_the_sweep_its_variants_and_controls_in_the_same_rounds():
    from crane_sym.bench.cases import batched_cases
    from crane_sym.bench.thread_blocks import ALONE, THREADS, markdown_row, thread_row, variant_rows
    case = next(c for _, c in batched_cases() if c.targets)
    variants = (("2 blocks, no Dask", 2, None), ("2 blocks, Dask's threads", 2, "threads"))
    t = thread_row(case, designs=100, rounds=2, elements=2**10, variants=variants)
    assert t["rounds"] == 2 and len(t["sweep"]["rounds"]) == 2 and t["same_worst"]
    assert t["designs"] == 100 and sum(t["block_designs"]) == 100
    assert t["efficiency"] == pytest.approx(t["no_dask_seconds"] / (2 * t["dask_seconds"]))
    assert t["relative"]["least"] == pytest.approx(
        t["efficiency"] / t["roofline"]["sin"]["efficiency"])
    rows = {v["trial"]: v for v in t["variants"]}
    assert list(rows) == [ALONE, THREADS, "2 blocks, no Dask", "2 blocks, Dask's threads"]
    assert rows[ALONE]["ratio"] == 1.0 and "relative" not in rows[ALONE]
    assert rows[THREADS]["ratio"] == pytest.approx(t["efficiency"])
    assert rows["2 blocks, Dask's threads"]["workers"] == 2
    assert "interleaved rounds" in markdown_row(t)
    assert any(line.startswith("| 2 blocks, Dask's threads | 2 |") for line in variant_rows(t))


def _mark() -> None:
    os.environ["CRANE_SYM_TEST_WARM"] = str(os.getpid())


def _marked() -> bool:
    return os.environ.get("CRANE_SYM_TEST_WARM") == str(os.getpid())


def test_a_warm_pool_has_run_its_warm_call_in_every_worker_before_it_is_used():
    import dask.array as da

    from crane_sym.sweep.compute import compute_local, warm_pool
    warm = _mark
    with warm_pool("processes", warm) as pool:
        assert len(pool._processes) == 2
        assert all(pool.submit(_marked).result() for _ in range(4))
        x = da.arange(10, chunks=5)
        assert compute_local(lambda kept: [x.sum()], "processes", True, False,
                             pool=pool) == (45,)
        assert pool.submit(abs, -1).result() == 1          # the caller's pool, left running
    with pytest.raises(ValueError, match="'synchronous' has no pool"):
        with warm_pool("synchronous", warm):
            pass
