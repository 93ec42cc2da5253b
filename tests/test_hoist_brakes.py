"""Paper 001 end to end: verdicts and their readings, the rigid drive against an
independent integration, the coordinated brakes against the cut, hard cases,
bad scene data."""
import numpy as np
import pytest

from crane_sym import registry
from crane_sym.bench.accuracy import accuracy
from crane_sym.scenes.run import run_scene
from crane_sym.scenes.reading import SceneError, load_scene

integrate = pytest.importorskip("scipy.integrate")

DERIVATION = "hoist_brakes"
CWC = "confirmed_with_convention"
EXPECTED = {
    "(1)": "restated", "(2), hoisting": "confirmed", "(2), lowering": "confirmed",
    "(3)": "confirmed", "(4)": "confirmed", "(5)": "confirmed",
    "(6), hoisting": "confirmed", "(6), lowering": "confirmed",
    "(7), hoisting": "confirmed", "(7), lowering": "confirmed",
    "Table 1, v = 45 m/min": "confirmed",
    # the prints that fix the reading of Table 1 match under it only: consistent
    "Fig. 8 legend, MF = 0.90": "consistent", "Fig. 8 legend, MF = 0.95": "consistent",
    "after (5), BF_SB = 1.7": "consistent", "after (5), BF_SB = 3.3": "not_checkable",
    "after (5), 2.4": "confirmed", "after (5), 4.2": "confirmed",
    "after (5), 3.9": "confirmed", "after (5), 7.2": "confirmed",
    "typical 2.6": "confirmed", "in some cases 4.4": "not_checkable",
    "Fig. 9 peak 8.9": "consistent", "conclusions 890 %": "consistent",
    **{f"Fig. {n}, {f}, {m} (text)": CWC for n in (11, 12) for f in ("BF_SB", "BF_BB")
       for m in ("0 t", "52 t")},
    **{f"Table 1, {name}": "not_checkable" for name in
       ("n1", "J1", "J2", "m_GM", "m_L", "r", "i_g", "i_t", "M_BB", "t_BB", "M_SB", "t_SB",
        "c", "delta")},     # the reference hoist's data: inputs
}
#: The reading each confirmed_with_convention record needed, and its cause.
READING = {"Fig. 1": ("fitted value", "001-unstated-braking-time")}
HOIST = dict(J1=20.0, J2=500.0, m_h=1e4, r=0.5, i_g=26.2, i_t=4.0, g=9.81,
             omega1=50 * np.pi)
BRAKES = dict(M_SB=130e3, M_BB=5.8e3, t_SB=0.1, t_BB=0.4)


@pytest.fixture(scope="module")
def gen():
    import crane_sym.generated.hoist_brakes as module
    return module


def test_every_verdict(records):
    assert {label: r.verdict for label, r in records.items()} == EXPECTED


def test_each_reading_is_the_named_one(records):
    for label, r in records.items():
        if r.verdict != CWC:
            continue
        kind, cause = next(v for k, v in READING.items() if label.startswith(k))
        assert r.reading.reading == kind, label
        assert r.cause.id == cause, label
        assert not r.literal.matches, label


def test_reconstructed_formulas_keep_the_ocr(derivation):
    damaged = [f for f in derivation.published if f.label.startswith("(")]
    assert all(f.reconstructed for f in damaged)
    assert "ZJ7" in next(f.latex for f in damaged if f.label == "(2), hoisting")


def test_a_wrong_counting_or_time_fails(derivation):
    """The numbers decide between the readings: the ones not chosen are refuted."""
    step = lambda label: float(derivation.step(label).statement.rhs)  # noqa: E731
    assert abs(step("MF rated load, per train") - 0.90) > 0.02
    assert abs(step("MF rated load, totals") - 0.90) < 0.005
    assert abs(step("Fig. 11, BF_BB, 0 t, Δt = 1 s") - 0.92) < 0.005
    expr = derivation.step("Fig. 11, BF_BB, 0 t").statement.rhs
    (dt,) = expr.free_symbols
    assert abs(float(expr.subs(dt, 1.2)) - 0.92) > 0.1


def test_one_reading_of_table1_for_the_whole_paper(derivation, records):
    """Every record that needs Table 1's counting uses the one declared reading and
    is checked against it; the other reading is only ever the rejected one."""
    from crane_sym.derivations.hoist_brakes.published import TABLE1_COUNTING
    uses = [f for f in derivation.published if f.paper_reading is not None]
    assert len(uses) >= 18 and all(f.paper_reading is TABLE1_COUNTING for f in uses)
    for f in derivation.published:
        targets = [f.target] + [c.compare_to for c in f.conventions]
        assert not any("per train" in t or "per drum" in t for t in targets), f.label
    for label in ("Fig. 8 legend, MF = 0.90", "after (5), BF_SB = 1.7"):
        assert records[label].paper_reading == TABLE1_COUNTING.text
        assert records[label].rests_on == "on a reading"
    for label in TABLE1_COUNTING.fixed_by:      # the reading's evidence: one reading only
        r = records[label]
        assert r.verdict == "consistent" and r.cause.id == "001-one-reading-evidence"
        assert r.attempts[-1].reading == "rejected reading" and not r.attempts[-1].matches
    general = records["in some cases 4.4"]       # a claim about hoists in general
    assert general.verdict == "not_checkable" and general.cause.id == "001-4.4-case"
    assert not any(r.reading is not None and r.reading.reading == "fitted value"
                   and "Fig. 1" not in label for label, r in records.items())


def test_the_braking_time_is_fitted_and_the_fit_shown(records):
    from crane_sym.audit.fits import fit_of
    from crane_sym.derivations.hoist_brakes.published import BRAKING_FIT
    result = fit_of(registry.get(DERIVATION), BRAKING_FIT)
    assert len(result.each) == 8 and result.holds
    low, high = result.common
    assert 0.998 < low < 1.0 < high < 1.006
    r = records["Fig. 11, BF_BB, 0 t (text)"]
    assert "the 8 prints it is fitted to together [0.999" in r.reading.note


def test_a_moved_percentage_leaves_the_fit(derivation):
    """92 % printed as 95 % allows no Δt that the other prints allow: a finding."""
    from dataclasses import replace
    import sympy as sp
    from crane_sym.audit.verdicts import audit_formula
    f = next(f for f in derivation.published if f.label == "Fig. 11, BF_BB, 0 t (text)")
    moved = replace(f, printed=sp.Eq(f.printed.lhs, sp.Rational(95, 100)), conventions=(
        replace(f.conventions[0], reading=sp.Eq(f.printed.lhs, sp.Rational(95, 100))),))
    r = audit_formula(derivation, moved)
    assert r.verdict == "discrepancy" and "share no value" in r.detail


def test_fig9_peak_is_judged_by_its_sensitivity(derivation, records):
    step = derivation.step("Fig. 9 peak, hook only")
    low, high = step.sensitivity.band
    assert low < 8.9 < high and abs(step.sensitivity.value - 9.13) < 0.01
    assert {p.key for p in step.sensitivity.parameters} == {"zeta", "t_M"}
    r = records["Fig. 9 peak 8.9"]
    assert r.verdict == "consistent" and "inside the band" in r.detail
    assert records["conclusions 890 %"].duplicate_of == "Fig. 9 peak 8.9"


def _rigid_ivp(mode: str, m_p: float, times: np.ndarray) -> np.ndarray:
    """Hook speed by integrating J·dω/dt = Σ moments, written out independently."""
    k = HOIST["r"] / (HOIST["i_g"] * HOIST["i_t"])
    J = HOIST["J1"] + HOIST["J2"] / HOIST["i_g"] ** 2 + (HOIST["m_h"] + m_p) * k ** 2
    weight = (HOIST["m_h"] + m_p) * HOIST["g"] * k   # lowers the hook
    sign = 1.0 if mode == "hoisting" else -1.0         # weight along (-) or against

    def rhs(t, y):
        brakes = (BRAKES["M_SB"] / HOIST["i_g"] * (t >= BRAKES["t_SB"])
                  + BRAKES["M_BB"] * (t >= BRAKES["t_BB"]))
        if y[0] <= 0:
            return [0.0]
        return [(-sign * weight - brakes) / J]

    sol = integrate.solve_ivp(rhs, (0, times[-1]), [HOIST["omega1"]], t_eval=times,
                              max_step=1e-4, rtol=1e-10, atol=1e-12)
    return np.maximum(sol.y[0], 0.0) * k


@pytest.mark.parametrize("mode", ["hoisting", "lowering"])
@pytest.mark.parametrize("m_p", [0.0, 52e3])
def test_rigid_speed_against_integration(gen, mode, m_p):
    times = np.linspace(0, 1.0, 401)
    fn = getattr(gen, f"rigid_hook_speed_{mode}")
    got = fn(times, m_p=m_p, **HOIST, **BRAKES)
    assert np.max(np.abs(got - _rigid_ivp(mode, m_p, times))) < 2e-4 * got[0]
    stop = getattr(gen, f"rigid_stopping_time_{mode}")(m_p=m_p, **HOIST, **BRAKES)
    assert fn(stop - 1e-6, m_p=m_p, **HOIST, **BRAKES) > 0
    assert fn(stop + 1e-6, m_p=m_p, **HOIST, **BRAKES) == 0


def test_coordinated_brakes_keep_the_static_torque(gen):
    """With (6)-(7) the cut at the gearbox input carries M_L while braking."""
    m_p = np.linspace(0, 52e3, 9)
    args = dict(**HOIST, m_r=52e3, d_t=1.0)
    k = HOIST["r"] / (HOIST["i_g"] * HOIST["i_t"])
    M_st = (HOIST["m_h"] + 52e3) * HOIST["g"] * k
    J = HOIST["J1"] + HOIST["J2"] / HOIST["i_g"] ** 2 + (HOIST["m_h"] + m_p) * k ** 2
    M_L = (HOIST["m_h"] + m_p) * HOIST["g"] * k
    for mode, sign in (("hoisting", 1.0), ("lowering", -1.0)):
        bb = getattr(gen, f"service_brake_factor_{mode}")(m_p, **args) * M_st
        sb = gen.safety_brake_factor(m_p, **args) * M_st * HOIST["i_g"]
        alpha = (-sign * M_L - bb - sb / HOIST["i_g"]) / J          # along travel
        assert np.allclose(alpha * args["d_t"], -HOIST["omega1"], rtol=1e-12)
        # the motor shafts: J1·α = (torque from the gearbox) − brake, along travel;
        # the gearbox holds the load in both directions: that torque is M_L.
        M_G = bb + HOIST["J1"] * alpha if sign < 0 else -bb - HOIST["J1"] * alpha
        assert np.allclose(M_G, M_L, rtol=1e-12)


def test_rigid_formulas_match_the_printed_numbers(gen):
    assert round(float(gen.relative_gearbox_torque_hoisting(0.9034, 1.0, 1.7)), 1) == 2.4
    assert round(float(gen.peak_relative_gearbox_torque_hoisting(2.0, 0.9544, 1, 3.3)), 1) == 7.2


def test_hard_cases_against_mpmath(derivation, gen):
    cases = registry.module(DERIVATION).hard_cases(points=40)
    for out in derivation.outputs:
        for case, columns in cases.items():
            row = accuracy(out, getattr(gen, out.name), case, columns)
            assert row.excess <= 1, (out.name, case, row)


@pytest.mark.parametrize("key, text, name", [
    ("t_SB", '"-0.1 s"', "t_SB"), ("delta", '"3 m"', "delta"), ("M_SB", '"130 kg"', "M_SB")])
def test_bad_scene_data_named(tmp_path, key, text, name):
    src = load_scene("hoist_table1").path.read_text(encoding="utf-8")
    lines = [f"{key} = {text}" if ln.startswith(f"{key} =") else ln
             for ln in src.splitlines()]
    bad = tmp_path / "bad.toml"
    bad.write_text("\n".join(lines), encoding="utf-8")
    with pytest.raises(SceneError, match=name):
        load_scene(bad)


def test_payload_above_rated_refused(tmp_path):
    src = load_scene("hoist_table1").path.read_text(encoding="utf-8")
    bad = tmp_path / "heavy.toml"
    bad.write_text(src.replace('m_p = "52 t"', 'm_p = "60 t"'), encoding="utf-8")
    with pytest.raises(SceneError, match="'m_p'"):
        run_scene(load_scene(bad), tmp_path)


def test_scene_writes_the_five_figures(tmp_path):
    report, paths = run_scene("hoist_table1", tmp_path)
    names = {p.name for p in tmp_path.glob("*.png")}
    assert names == {p.name for p in paths} == {f"hoist_table1_{n}.png" for n in range(1, 6)}
    assert abs(report.values["v0"] * 60 - 45) < 0.05
    assert abs(abs(report.values["peak_fig9"]) - 9.13) < 0.01
    for fig in ("Fig. 5", "Fig. 8", "Fig. 9", "Fig. 11", "Fig. 12"):
        assert 1 <= sum(p.group == fig for p in report.panels) <= 4
