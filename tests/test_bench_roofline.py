"""The roofline beside the sweep's parallel efficiency: the controls measured
on small arrays, Amdahl's serial fraction, the scaling curve's measured and
modelled parts, and the verdict's reason. No timing is asserted."""
import numpy as np
import pytest

from crane_sym.bench import roofline as rl


def _roof(sin, add, cores=2):
    return {"cores": cores, "elements": 8, "load_before": 1.0, "load_after": 1.0,
            "sin": {"one_s": 2.0, "two_s": 1.0, "efficiency": sin},
            "add": {"one_s": 1.0, "two_s": 1.0, "efficiency": add, "gb_per_s_one": 10.0,
                    "gb_per_s_two": 20 * add},
            "copy": {"one_s": 1.0, "two_s": 1.0, "efficiency": 0.5, "gb_per_s_one": 5.0,
                     "gb_per_s_two": 5.0}}


def test_roofline_measures_each_control_on_one_and_two_threads():
    r = rl.roofline(elements=2**12, repeats=1)
    for name in ("copy", "add", "sin"):
        m = r[name]
        assert m["one_s"] > 0 and m["two_s"] > 0
        assert m["efficiency"] == pytest.approx(m["one_s"] / (2 * m["two_s"]))
    assert r["add"]["gb_per_s_one"] == pytest.approx(3 * 8 * 2**12 / 1e9 / r["add"]["one_s"])


def test_pair_seconds_runs_the_kernel_on_both_halves():
    seen = []
    rl.pair_seconds(lambda s: seen.append((s.start, s.stop)), 10, repeats=1)
    assert (0, 10) in seen and (0, 5) in seen and (5, 10) in seen


def test_serial_fraction_inverts_amdahl():
    for f in (0.0, 0.1, 0.4):
        efficiency = rl.amdahl(2, f) / 2
        assert rl.serial_fraction(efficiency, 1.0) == pytest.approx(f)
        assert rl.serial_fraction(0.9 * efficiency, 0.9) == pytest.approx(f)
    assert rl.serial_fraction(0.3, 1.0) == 1.0            # slower on two: all serial
    assert rl.serial_fraction(0.99, 0.9) == 0.0           # above the control: none


def test_scaling_curve_measured_only_where_the_cores_are():
    curve = rl.scaling_curve(0.8, _roof(1.0, 0.6), workers=rl.WORKERS)
    assert [c["workers"] for c in curve] == list(range(1, 17))
    assert curve[1]["measured"] == pytest.approx(1.6)
    assert all(c["measured"] is None for c in curve[2:])
    speedups = [c["modelled"] for c in curve]
    assert speedups == sorted(speedups) and speedups[-1] < 1 / 0.25   # Amdahl's bound
    assert curve[-1]["memory_ceiling"] == pytest.approx(1.2)


@pytest.mark.parametrize("sin, add, reason", [(0.6, 0.9, "the machine"),
                                               (0.95, 0.6, "memory bandwidth"),
                                               (0.95, 0.9, "the code")])
def test_verdict_names_why_the_target_is_not_met(sin, add, reason):
    assert rl.verdict(0.5, 0.7, _roof(sin, add)).startswith(f"not met: {reason}")
    assert rl.verdict(0.75, 0.7, _roof(sin, add)) == "met"


def test_markdown_says_which_rows_are_measured_and_which_modelled():
    text = "\n".join(rl.markdown_rows(0.5, 0.7, _roof(0.6, 0.9)))
    assert "| 2 | 1.00 |" in text and "| 3 | — |" in text
    assert "*measured*" in text and "*modelled*" in text
    assert "not met: the machine" in text
    assert np.isfinite(rl.amdahl(16, 0.2))


def test_parallel_section_alone_from_the_command_line(monkeypatch, capsys):
    from crane_sym.bench import batched_targets
    from crane_sym.cli.main import main
    row = {"designs": 4, "output": "y", "blocks": 2, "block_designs": [2, 2],
           "scheduler": "threads", "efficiency": 0.5, "no_dask_seconds": 1.0,
           "dask_seconds": 1.0, "dask_seconds_all": [1.0], "dask_cores": 1.0,
           "sin": {"efficiency": 0.6, "one_thread_s": 1.0, "two_threads_s": 0.8},
           "load_before": 1.0, "load_after": 1.0, "same_worst": True, "target": 0.7,
           "met": False, "roofline": _roof(0.6, 0.9)}
    monkeypatch.setattr(batched_targets, "thread_row", lambda case: row)
    assert main(["bench", "--parallel", "--quiet"]) == 0
    out = capsys.readouterr().out
    assert "efficiency 50 %" in out and "| 16 | — |" in out
    assert "not met: the machine" in out
