"""Paper 000 end to end: verdicts, generated code against mpmath and against an
independent numerical integration of (1)-(2), hard cases, bad inputs."""
import json
import subprocess
import sys

import numpy as np
import pytest
import sympy as sp

from crane_sym import registry
from crane_sym.codegen import module as codegen
from crane_sym.codegen import files as module_files
from crane_sym.cli.main import main
from crane_sym.bench.accuracy import accuracy

integrate = pytest.importorskip("scipy.integrate")

ID = "travel_braking"
EXPECTED = {
    "(1)": "confirmed", "(2)": "confirmed", "(3)": "confirmed", "(4)": "confirmed",
    "(5)": "confirmed", "(6)": "confirmed_with_convention",
    "(7)": "confirmed_with_convention", "(8)": "confirmed", "(9)": "confirmed",
    "initial stretch": "remark", "initial relative velocity": "restated",
    "(10)": "confirmed", "(11)": "confirmed", "(12)": "confirmed", "(13)": "confirmed",
    "(14)": "confirmed",
}


DERIVATION = ID


@pytest.fixture(scope="module")
def gen():
    import crane_sym.generated.travel_braking as module
    return module


def test_every_verdict(records):
    assert {label: r.verdict for label, r in records.items()} == EXPECTED


def test_conventions_say_what_the_print_gets_wrong(records):
    assert "P in (6) is the frequency p" in records["(6)"].detail
    seven = records["(7)"].detail
    assert "dimensions: the term" in seven and "kg²·m/s⁴" in seven
    assert "W/c" in records["initial stretch"].detail.replace("\\frac{W}{c}", "W/c")


def test_every_step_is_labelled_and_every_printed_formula_targets_a_step(derivation):
    labels = [s.label for s in derivation.steps]
    assert len(labels) == len(set(labels)) and all(s.how for s in derivation.steps)
    for f in derivation.published:
        derivation.step(f.target)
    numbered = {s.label for s in derivation.steps if s.numbered}
    assert numbered == {f"({i})" for i in range(1, 15)}


def test_audit_json_has_the_required_records(capsys):
    assert main(["audit", "000", "--format", "json"]) == 0
    rows = json.loads(capsys.readouterr().out)
    assert {"derivation", "label", "verdict", "method", "detail"} <= set(rows[0])
    labels = {r["label"] for r in rows}
    assert {"(1)", "(2)", "(3)", "(4)", "(6)", "(8)", "(11)", "(12)", "(13)", "(14)"} <= labels
    assert all(r["method"] in ("symbolic", "numeric", "dimension", "none") for r in rows)


def test_list_json(capsys):
    assert main(["list", "--format", "json"]) == 0
    rows = {r["id"]: r for r in json.loads(capsys.readouterr().out)}
    assert rows[ID] == {"id": ID, "number": "000", "paper": "000_4ef6efc8a81a3b06.txt",
                        "authors": ["V.F. Semenyuk", "A.N. Vudvud"],
                        "title": registry.module(ID).TITLE}


@pytest.mark.parametrize("case", list(registry.module(ID).hard_cases()))
def test_generated_functions_on_hard_cases_against_mpmath(derivation, gen, case):
    """Each point within max(1e-15, 2·cond·u): the error the inputs' own rounding
    allows (long times near a zero of sin, v0 − a·t → 0, P_t·m2 ≈ W·m1)."""
    columns = registry.module(ID).hard_cases()[case]
    for out in derivation.outputs:
        row = accuracy(out, getattr(gen, out.name), case, columns)
        assert row.excess <= 1.0, (out.name, row)


def test_elastic_force_to_an_ulp_or_two_where_p_t_is_at_most_one(derivation, gen):
    columns = registry.module(ID).hard_cases()["p·t from 1e-9 to 1e3"]
    p = gen.natural_frequency(columns["m1"], columns["m2"], columns["c"])
    small = {k: v[p * columns["t"] <= 1.0] for k, v in columns.items()}
    row = accuracy(derivation.output("elastic_force"), gen.elastic_force, "p·t ≤ 1", small)
    assert row.points > 100 and row.max_rel_error <= 1e-15


def test_against_numerical_integration_of_1_and_2(gen):
    m1, m2, c, P_t, W, v0 = 4.4e3, 110e3, 3.0e6, 24e3, 11e3, 80 / 60

    def rhs(_, s):
        x1, x2, v1, v2 = s
        spring = c * (x2 - x1)
        return [v1, v2, (-P_t + spring) / m1, (-W - spring) / m2]   # (1), (2)

    t = np.linspace(0, 2.0, 401)
    sol = integrate.solve_ivp(rhs, (0, 2.0), [0, 0, v0, v0], method="DOP853",
                              t_eval=t, rtol=1e-13, atol=1e-16)
    x1, x2, v1, v2 = sol.y
    F = gen.elastic_force(t, m1, m2, c, P_t, W)
    scale = np.max(np.abs(F))
    assert np.max(np.abs(c * (x2 - x1) - F)) <= 1e-9 * scale
    assert np.max(np.abs(v1 - gen.velocity_m1(t, m1, m2, c, P_t, W, v0))) <= 1e-10 * v0
    assert np.max(np.abs(v2 - gen.velocity_m2(t, m1, m2, c, P_t, W, v0))) <= 1e-10 * v0
    first_period = t < 2 * np.pi / gen.natural_frequency(m1, m2, c)
    i = np.argmax(np.where(first_period, F, -np.inf))
    assert abs(F[i] - gen.peak_elastic_force(m1, m2, P_t, W)) <= 1e-3 * scale
    assert abs(t[i] - gen.peak_time(m1, m2, c)) <= t[1] - t[0]


def test_limits_and_invariants(gen):
    m1, m2, c, P_t, W = 2e3, 5e4, 1e7, 3e4, 5e3
    p = gen.natural_frequency(m1, m2, c)
    # Quadratic start: F ~ F_r p^2 t^2 / 2 for p t -> 0, no 0/0 or cancellation.
    tiny = 1e-9 / p
    F_r = gen.rigid_link_force(m1, m2, P_t, W)
    assert gen.elastic_force(tiny, m1, m2, c, P_t, W) == pytest.approx(F_r * 1e-18 / 2, rel=1e-15)
    assert gen.elastic_force(0.0, m1, m2, c, P_t, W) == 0.0
    # Dynamic factor 2 and peak at pi/p.
    t_max = gen.peak_time(m1, m2, c)
    assert gen.elastic_force(t_max, m1, m2, c, P_t, W) == pytest.approx(2 * F_r, rel=1e-14)
    # Symmetry: swapping the masses swaps the roles of P_t and W and flips F.
    assert gen.natural_frequency(m1, m2, c) == pytest.approx(gen.natural_frequency(m2, m1, c), rel=1e-15)
    assert gen.rigid_link_force(m1, m2, P_t, W) == pytest.approx(-gen.rigid_link_force(m2, m1, W, P_t), rel=1e-15)
    # Momentum: m1 v1 + m2 v2 falls at the rate P_t + W.
    t = np.linspace(0, 3, 50)
    mom = m1 * gen.velocity_m1(t, m1, m2, c, P_t, W, 1.0) + m2 * gen.velocity_m2(t, m1, m2, c, P_t, W, 1.0)
    assert np.allclose(mom, (m1 + m2) - (P_t + W) * t, rtol=1e-13, atol=1e-9)


def test_vectorized_and_broadcast(gen):
    t = np.linspace(0, 1, 7)[:, None]
    m2 = np.array([1e4, 1e5, 1e6])
    out = gen.elastic_force(t, 1e3, m2, 1e6, 1e4, 1e3)
    assert out.shape == (7, 3)
    assert out[3, 1] == gen.elastic_force(t[3, 0], 1e3, 1e5, 1e6, 1e4, 1e3)


@pytest.mark.parametrize("bad, message", [
    ({"m1": 0.0}, r"m1 must be > 0"), ({"m2": -1.0}, r"m2 must be > 0"),
    ({"c": np.nan}, r"c must be finite"), ({"P_t": np.inf}, r"P_t must be finite"),
    ({"W": -1.0}, r"W must be >= 0"), ({"t": [0.1, -0.1]}, r"t must be >= 0"),
])
def test_bad_inputs_raise_naming_the_parameter(gen, bad, message):
    args = {"t": 0.1, "m1": 1e3, "m2": 1e5, "c": 1e6, "P_t": 1e4, "W": 1e3} | bad
    with pytest.raises(ValueError, match=message):
        gen.elastic_force(**args)


def test_strings_are_rejected_not_evaluated(gen, tmp_path):
    canary = tmp_path / "evaluated"
    payload = f"__import__('pathlib').Path({str(canary)!r}).touch() or 1.0"
    with pytest.raises(TypeError, match="m1 must be a number"):
        gen.elastic_force(0.1, payload, 1e5, 1e6, 1e4, 1e3)
    with pytest.raises(TypeError, match="c must be a number"):
        gen.natural_frequency(1e3, 1e5, "1e6")
    assert not canary.exists()


def test_generate_is_deterministic_and_fresh(derivation):
    """Two renders of the module are the same text, and it is the committed one
    (which another process wrote: the folder as a whole is checked by
    tests/test_cli.py and, in a fresh process, by `generate --check` in CI)."""
    first = codegen.render_module(derivation)
    assert codegen.render_module(derivation) == first
    assert (module_files.default_directory() / f"{ID}.py").read_text(encoding="utf-8") == first


def test_generated_module_imports_numpy_only():
    code = ("import sys, crane_sym.generated.travel_braking as g; "
            "bad = [m for m in ('sympy', 'mpmath', 'scipy', 'matplotlib') if m in sys.modules]; "
            "print(bad)")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert out.stdout.strip() == "[]"


def test_generated_header_names_source_labels_order_and_sympy_version():
    text = (module_files.default_directory() / f"{ID}.py").read_text()
    head = text.split('"""')[1]
    assert f"crane_sym.derivations.{ID}" in head and "000_4ef6efc8a81a3b06.txt" in head
    assert "elastic_force(t, m1, m2, c, P_t, W) -> [N]    eq (14)" in head
    assert f"SymPy {sp.__version__}" in head


def test_accuracy_command_prints_every_function_and_case(capsys):
    assert main(["accuracy", "000"]) == 0
    *lines, summary = capsys.readouterr().out.splitlines()[1:]
    assert summary.startswith("PASS: all ")
    derivation = registry.get(ID)
    assert len(lines) == len(derivation.outputs) * len(registry.module(ID).hard_cases())
    over = [float(line.split()[-2]) for line in lines if line.startswith("elastic_force")]
    assert len(over) == 3 and max(over) <= 1.0      # within max(1e-15, 2·cond·u)


def test_exact_phases_on_request_reach_an_ulp_at_long_times(derivation, tmp_path):
    """rules_for(..., exact_phases=True): the double-double phase, ~1 ulp even
    near the zeros of sin(p·t/2) at p·t up to 1e3 (the default rounds the phase
    once and stays within twice the condition bound)."""
    import importlib.util

    from crane_sym.codegen.module import render_module
    from crane_sym.codegen.rewriting import rules_for
    out = derivation.output("elastic_force")
    t = derivation.symbols["t"].expr
    path = tmp_path / "exact_phase_module.py"
    path.write_text(render_module(derivation, [out], rules_for({t}, exact_phases=True)))
    spec = importlib.util.spec_from_file_location("exact_phase_module", path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    assert "_sin_phase(" in path.read_text()
    columns = registry.module(ID).hard_cases()["p·t from 1e-9 to 1e3"]
    row = accuracy(out, module.elastic_force, "p·t from 1e-9 to 1e3", columns)
    assert row.max_rel_error <= 1e-15


def test_in_place_evaluation_writes_into_out_and_matches(gen):
    """elastic_force is a chain: with out= it fills the caller's buffer and
    returns it; the values equal those of a fresh call; a wrong buffer is named."""
    import numpy as np
    t = np.linspace(0.0, 1.5, 1001)
    args = (4.4e3, 110e3, 3e6, 24e3, 11e3)
    fresh = gen.elastic_force(t, *args)
    buf = np.full(t.shape, np.nan)
    assert gen.elastic_force(t, *args, out=buf) is buf
    np.testing.assert_array_equal(buf, fresh)
    assert np.ndim(gen.elastic_force(0.1, *args)) == 0       # scalars stay scalars
    with pytest.raises(ValueError, match="out must be a writeable float64 array"):
        gen.elastic_force(t, *args, out=np.empty(5))


def test_elastic_force_to_the_last_bit_on_random_designs(gen):
    """The frequency is one joined root (one rounding, not seven), so (14) holds
    1e-15 relative on random designs with p·t from 1e-9 to 1, against mpmath."""
    import mpmath
    import numpy as np
    rng = np.random.default_rng(7)
    n = 3000
    m1, m2 = 10 ** rng.uniform(2, 5, n), 10 ** rng.uniform(3, 6, n)
    c, P_t, W = 10 ** rng.uniform(5, 8, n), 10 ** rng.uniform(3, 5, n), 10 ** rng.uniform(2, 4, n)
    t = 10 ** rng.uniform(-9, 0, n) / np.sqrt(c * (m1 + m2) / (m1 * m2))
    got = gen.elastic_force(t, m1, m2, c, P_t, W)
    worst = 0.0
    with mpmath.workdps(40):
        for i in range(n):
            M1, M2, C, P, WW, T = (mpmath.mpf(float(a[i])) for a in (m1, m2, c, P_t, W, t))
            p = mpmath.sqrt(C * (M1 + M2) / (M1 * M2))
            ref = (P * M2 - WW * M1) / (M1 + M2) * (1 - mpmath.cos(p * T))
            worst = max(worst, float(abs((got[i] - ref) / ref)))
    assert worst <= 1e-15, worst
