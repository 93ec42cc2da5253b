"""The piecewise-linear run in mpmath (crane_sym.mechanics.exact_phases): the numbers a
scene's module prints do not depend on the machine's floating-point libraries."""
import math
import types
from dataclasses import replace

import mpmath
import numpy as np
import pytest

from crane_sym.mechanics import closed_forms
from crane_sym.mechanics import exact_forms, exact_phases
from crane_sym.mechanics import event_search
from crane_sym.derivations.hoist_brakes.drive_train import emergency_stop, table1_values
from crane_sym.derivations.hoist_brakes.hybrid import EMERGENCY_STOP
from crane_sym.derivations.portal_travel.hybrid import STARTUP, rim_values
from crane_sym.derivations.portal_travel.startup import BACKLASH, CHOSEN, HOLDS
from crane_sym.mechanics.exact_phases import exact_form, exact_table, illinois, simulate_exact
from crane_sym.mechanics.phase_table import HybridRun
from crane_sym.scenes.reading import load_scene
from crane_sym.codegen.tabulated import render_tabulated


def _hoist_run() -> HybridRun:
    scene = load_scene("hoist_table1")
    return EMERGENCY_STOP.run(scene.parameters, scene.options)


def _portal_run(backlash: str) -> HybridRun:
    run = STARTUP.run(rim_values(CHOSEN, BACKLASH[backlash]), {"holds": HOLDS, "end": 4.0})
    return replace(run, scale=1e3)


def _other_libm(ulps: int) -> types.SimpleNamespace:
    """A libm whose sin, cos and exp are ``ulps`` units in the last place off."""
    f = 1 + ulps * 2.0 ** -52
    return types.SimpleNamespace(sin=lambda x: math.sin(x) * f, cos=lambda x: math.cos(x) / f,
                                 exp=lambda x: math.exp(x) * f, sqrt=math.sqrt)


def _same(a, b) -> bool:
    return a.events == b.events and all(np.array_equal(x, y)
                                        for x, y in zip(a.arrays(), b.arrays()))


@pytest.mark.parametrize("make", [_hoist_run, lambda: _portal_run("0"),
                                  lambda: _portal_run("2pi")], ids=["001", "003-0", "003-2pi"])
@pytest.mark.parametrize("ulps", [1, 4])
def test_table_does_not_depend_on_libm(monkeypatch, make, ulps):
    """With a libm a few ulps off, the double run's table changes (the defect
    this module removes) and the mpmath run's printed table does not."""
    run = make()
    exact, double = exact_table(run), run.table()
    text = render_tabulated(_output(), exact, "note")
    for module in (event_search, exact_phases):
        monkeypatch.setattr(module, "math", _other_libm(ulps))
    closed_forms.clear_cache()
    exact_forms._exact_form_cached.cache_clear()
    exact_other = exact_table(run)
    assert not _same(run.table(), double)
    assert _same(exact_other, exact)
    assert render_tabulated(_output(), exact_other, "note") == text


def _output():
    from crane_sym.derivations.hoist_brakes.outputs import tabulated
    return tabulated()[0]


@pytest.mark.parametrize("payload,stiffness,backlash_deg", [
    (0.0, 4e4, 3.0), (52e3, 4e4, 3.0), (0.0, 4e2, 3.0), (0.0, 4e7, 3.0),
    (0.0, 4e4, 1e-9), (52e3, 4e4, 0.0)])
def test_exact_run_against_mpmath_expm_on_hard_cases(payload, stiffness, backlash_deg):
    """Payload -> 0, stiffness over five decades, backlash -> 0: the table from
    the mpmath run against exp(Mt) by mpmath.expm carried over its event
    times, in error relative to the peak; the double run's table within its
    own accuracy of it (97 phases at 4e7 N·m/rad carry 1e-10)."""
    q = table1_values(payload, backlash_deg=backlash_deg, stiffness=stiffness)
    run = emergency_stop({**q, "omega1": 50 * np.pi}, 1.0)
    table = exact_table(run)
    times = np.linspace(0.0, 1.0, 61)
    ref = _expm_reference(run, times)
    peak = np.max(np.abs(ref))
    assert np.max(np.abs(table(times) - ref)) < 1e-14 * peak
    double = run.table()
    dense = np.linspace(0.0, 1.0, 20_001)
    assert np.max(np.abs(table(dense) - double(dense))) < 1e-9 * np.max(np.abs(double(dense)))


def _expm_reference(run: HybridRun, times: np.ndarray) -> np.ndarray:
    """The output at ``times`` from mpmath.expm of each phase's M, the state
    carried phase to phase by expm and the model's switch rule, over the
    mpmath run's event times (checked to be roots in the test below)."""
    exact = simulate_exact(run.system, run.mode, run.x0, run.t_end, run.schedule)
    out = np.empty(times.shape)
    with mpmath.workdps(exact.dps):
        z = [mpmath.mpf(float(v)) for v in run.x0]
        for seg in exact.segments:
            A, b = run.system.matrices(seg.mode)
            n = len(b)
            M = mpmath.zeros(n + 1, n + 1)
            for i in range(n):
                M[i, :n] = mpmath.matrix([[mpmath.mpf(repr(float(v))) for v in A[i]]])
                M[i, n] = mpmath.mpf(repr(float(b[i])))
            w, k = run.output(seg.mode)
            for i in np.flatnonzero((times >= float(seg.t0)) & (times <= float(seg.t1))):
                zt = mpmath.expm(M * (mpmath.mpf(float(times[i])) - seg.t0)) * \
                    mpmath.matrix(z + [1])
                out[i] = float((mpmath.fdot([float(v) for v in w], zt[:n]) + k) / run.scale)
            zt = mpmath.expm(M * (seg.t1 - seg.t0)) * mpmath.matrix(z + [1])
            if seg.event == "end":
                break
            x = np.empty(n, dtype=object)
            x[:] = list(zt[:n])
            _, x = run.system.switch(seg.mode, seg.event, seg.t1, x)
            z = [mpmath.mpf(v) for v in x]
    return out


def test_event_times_are_roots_to_forty_digits():
    """Every guard event of the mpmath run is a root of its guard to ~1e-35."""
    run = _hoist_run()
    exact = simulate_exact(run.system, run.mode, run.x0, run.t_end, run.schedule)
    checked = 0
    with mpmath.workdps(exact.dps):
        for seg in exact.segments:
            guard = {g.name: g for g in run.system.guards(seg.mode)}.get(seg.event)
            if guard is None or seg.t1 == seg.t0:
                continue
            x = seg.form.state(seg.t1 - seg.t0, seg.z0)
            g = mpmath.fdot([mpmath.mpf(w) for w in guard.weights], x) + guard.constant
            scale = 1 + mpmath.fsum(abs(v) for v in x)
            assert abs(g) < mpmath.mpf("1e-33") * scale, seg.event
            checked += 1
    assert checked >= 20


def test_grazing_start_does_not_chatter():
    """Paper 003 with 2π backlash: the crane leaves rest with zero acceleration,
    its speed grows as t². The double run once read rounding noise as the
    speed coming back to rest ('rests' four times within 1e-9 s); its search
    now watches the speed shifted by its rounding band until it leaves the
    band (event_search.sign_change), so neither has a 'rests', and both
    describe the same load to ~1e-10."""
    run = _portal_run("2pi")
    double = run.table()
    exact = exact_table(run)
    assert not any("rests" in e for e in exact.events)
    assert not any("rests" in e for e in double.events) and "crane slips +" in double.events
    times = np.linspace(0.0, 4.0, 40_001)
    assert np.max(np.abs(exact(times) - double(times))) < 1e-9 * np.max(np.abs(exact(times)))


def test_jordan_and_eigenvector_routes_agree():
    """A four-state system by both routes of ExactForm (exact Jordan form,
    mpmath eigenvectors) gives the same state to 30 digits."""
    rng = np.random.default_rng(7)
    K = np.array([[2.0, -1.0], [-1.0, 1.0]]) * 1e4
    A = np.block([[np.zeros((2, 2)), np.eye(2)], [-K, -0.3 * np.eye(2)]])
    b = rng.normal(size=4)
    keys = tuple(map(float, A.ravel())), tuple(map(float, b))
    with mpmath.workdps(40):
        jordan = exact_forms._form_jordan(*keys)
        eig = exact_forms._form_eig(*keys)
        z0 = [mpmath.mpf(v) for v in rng.normal(size=4)]
        for tau in ("0", "0.013", "0.7"):
            a, e = jordan.state(mpmath.mpf(tau), z0), eig.state(mpmath.mpf(tau), z0)
            assert max(abs(u - v) for u, v in zip(a, e)) < mpmath.mpf("1e-30")


def test_exact_form_is_the_matrix_exponential():
    A = np.array([[0.0, 1.0, 0.0], [-400.0, -2.0, 50.0], [0.0, 0.0, 0.0]])
    b = np.array([0.0, 3.0, 1.0])
    with mpmath.workdps(40):
        form = exact_form(A, b)
        M = mpmath.matrix([[0, 1, 0, 0], [-400, -2, 50, 3], [0, 0, 0, 1], [0, 0, 0, 0]])
        z0 = [mpmath.mpf(1), mpmath.mpf(-2), mpmath.mpf(0.5)]
        tau = mpmath.mpf("0.37")
        ref = mpmath.expm(M * tau) * mpmath.matrix(z0 + [1])
        got = form.state(tau, z0)
        assert max(abs(got[i] - ref[i]) for i in range(3)) < mpmath.mpf("1e-32")


def test_illinois_reaches_full_precision():
    with mpmath.workdps(40):
        root = illinois(lambda x: mpmath.cos(x) - x, mpmath.mpf(0), mpmath.mpf(1))
        assert abs(root - mpmath.findroot(lambda x: mpmath.cos(x) - x, 0.7)) < mpmath.mpf("1e-37")


def _jordan_fails(monkeypatch) -> None:
    """SymPy's Jordan form raising a MatrixError, the caches of earlier forms emptied."""
    import sympy as sp
    from sympy.matrices.exceptions import MatrixError

    def refuse(self, *args, **kwargs):
        raise MatrixError("Could not compute\nthe eigenvalues")
    monkeypatch.setattr(type(sp.zeros(1, 1)), "jordan_form", refuse)
    closed_forms.clear_cache()
    closed_forms.jordan.cache_clear()
    exact_forms._exact_form_cached.cache_clear()


def test_a_failed_jordan_fallback_names_the_phase(monkeypatch):
    """The exact run's fallback (mpmath's eigenvectors give up, SymPy's Jordan
    form raises a MatrixError) is one ValueError naming the phase and what to do."""
    _jordan_fails(monkeypatch)
    monkeypatch.setattr(exact_forms, "exact_is_cheap", lambda a, b: False)
    monkeypatch.setattr(exact_forms, "_form_eig", lambda a, b, horizon=None: None)
    with pytest.raises(closed_forms.JordanFormError) as caught:
        exact_table(_hoist_run())
    assert isinstance(caught.value, ValueError)
    assert str(caught.value) == (
        "phase 1 of the run (from t = 0 s): SymPy's exact Jordan form of its x' = A x + b "
        "failed (MatrixError: Could not compute the eigenvalues), so it has no closed form "
        "here: change a value of the model by a small fraction (its eigenvalues nearly "
        "coincide), or report the model")


def test_a_failed_jordan_form_is_one_line_from_the_command_line(monkeypatch, tmp_path, capsys):
    """A drive train whose phases take the exact Jordan form (``crane-sym run``):
    exit 2, one line naming the phase, nothing written."""
    from crane_sym.cli.main import main
    path = tmp_path / "spring.toml"
    path.write_text('[model]\nname = "spring"\n\n[[mass]]\nname = "m"\nmass = "10 kg"\n\n'
                    '[[elastic]]\nname = "k"\nbetween = ["ground", "m"]\n'
                    'stiffness = "1e4 N/m"\ndamping = "20 N*s/m"\n\n'
                    '[[resistance]]\nname = "push"\nbody = "m"\nforce = "50 N"\n\n'
                    '[run]\nduration = "0.5 s"\nstart = "rest"\n', encoding="utf-8")
    assert main(["run", str(path), "-q"]) == 0
    capsys.readouterr()
    _jordan_fails(monkeypatch)
    assert main(["run", str(path), "--out", str(tmp_path / "out"), "-q"]) == 2
    captured = capsys.readouterr()
    assert captured.out == "" and not (tmp_path / "out").exists()
    assert captured.err.startswith("crane-sym: error: phase 1 of the run (from t = 0 s): "
                                   "SymPy's exact Jordan form of its x' = A x + b failed "
                                   "(MatrixError: Could not compute the eigenvalues)")
    assert captured.err.count("\n") == 1
