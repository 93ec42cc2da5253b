"""Textbook formulas for natural frequencies, as users write them in a
component file, audited against the mode the run is in: each right one
confirmed, each wrong variant (a factor 2, swapped masses, a missing term) a
discrepancy. The frequencies themselves are checked against the run's own
x' = A x + b (its eigenvalues), an independent route."""
from __future__ import annotations

import json
import math
from pathlib import Path

import numpy as np
import pytest
import scipy.linalg

from crane_sym.components import ComponentError
from crane_sym.components.file_audit import audit_file
from crane_sym.components.parameters import signed
from crane_sym.components.quantities import derived_quantity
from crane_sym.components.component_file import read_component_file
from crane_sym.components.vibration import ModeChoice, mode_at

MASS = '\n[[mass]]\nname = "{}"\nmass = "{}"\n'
LINK = '\n[[elastic]]\nname = "{}"\nbetween = ["{}", "{}"]\nstiffness = "{}"\n{}'
#: A body moved by an ideal speed control at a constant 0.5 m/s.
SPEED_LAW = ('\n[[motor_law]]\nname = "control"\nbody = "{}"\nlaw = "speed"\nunit = "m/s"\n'
             'breakpoints = [0.0, 5.0]\ncoefficients = [[0.5]]\n')

#: The issue's hoist: a rope lifting 10 t with a speed-controlled (rigid) drive,
#: period 2π √(m/c) = 0.562 s.
RIGID = ('[model]\nname = "rigid_drive"\n' + MASS.format("drive", "2 t")
         + MASS.format("load", "10 t")
         + LINK.format("rope", "load", "drive", "1.25e6 N/m", 'damping = "2.2e4 N*s/m"\n')
         + '\n[[gravity]]\nname = "weight"\nbody = "load"\ndirection = "-"\n'
         + SPEED_LAW.format("drive")
         + '\n[run]\nduration = "1 s"\nbody = "drive"\nspeed = "0.5 m/s"\n')
TWO_FREE = ('[model]\nname = "two_free"\n' + MASS.format("one", "4 t")
            + MASS.format("two", "20 t") + LINK.format("link", "one", "two", "1e6 N/m", "")
            + '\n[run]\nduration = "1 s"\nstart = "rest"\n')
#: m1 -c1- m2 -c2- m3, free: one rigid-body root, two elastic ones.
CHAIN = ('[model]\nname = "chain"\n' + MASS.format("one", "1 t") + MASS.format("two", "3 t")
         + MASS.format("three", "8 t") + LINK.format("c_a", "one", "two", "2e6 N/m", "")
         + LINK.format("c_b", "two", "three", "5e5 N/m", "")
         + '\n[run]\nduration = "1 s"\nstart = "rest"\n')
#: A bob of 500 kg on a spring of m g / L (L = 2 m) from a support held by a law.
G, L_PENDULUM, M_BOB = 9.81, 2.0, 500.0
PENDULUM = ('[model]\nname = "pendulum"\n' + MASS.format("support", "1 t")
            + MASS.format("bob", f"{M_BOB:g} kg")
            + LINK.format("arm", "support", "bob", f"{M_BOB * G / L_PENDULUM!r} N/m", "")
            + '\n[[motor_law]]\nname = "fixed"\nbody = "support"\nlaw = "speed"\n'
              'unit = "m/s"\nbreakpoints = [0.0, 5.0]\ncoefficients = [[0.0]]\n'
            + '\n[run]\nduration = "1 s"\nstart = "rest"\n')


def _formula(name: str, latex: str, quantity: str, symbols: str, extra: str = "") -> str:
    return (f'\n[[formula]]\nname = "{name}"\nlatex = {json.dumps(latex)}\n'
            f'symbols = {{ {symbols} }}\nquantity = "{quantity}"\n{extra}')


def _audit(tmp_path: Path, text: str, *formulas: str) -> dict[str, tuple[str, str]]:
    path = tmp_path / "model.toml"
    path.write_text(text + "".join(formulas), encoding="utf-8")
    return {r.label: (r.verdict, r.method) for r in audit_file(read_component_file(path))}


def _run_frequencies(path: Path) -> np.ndarray:
    """The imaginary parts > 0 of the eigenvalues of the first mode's A, sorted."""
    read = read_component_file(path)
    run = read.model.run(read.duration, read.body, read.speed, rest=read.rest)
    A, _ = run.system.matrices(run.mode)
    rates = np.linalg.eigvals(A)
    return np.sort(rates.imag[rates.imag > 1e-6 * np.abs(rates).max()])


RIGID_NAMES = 'c = "rope.stiffness", m = "load.mass", m_d = "drive.mass", d = "rope.damping"'


def test_rigid_drive_frequency_is_the_rope_and_load_alone(tmp_path):
    """ω = √(c/m) under a speed law: confirmed (the issue's false finding gone);
    the two-free-masses formula, a factor 2 and the drive's mass instead of the
    load's: each a discrepancy. Period and damped frequency likewise."""
    zeta = r"\frac{d}{2 \sqrt{c m}}"
    printed = {
        "w": (r"\omega = \sqrt{\frac{c}{m}}", "frequency"),
        "w free": (r"\omega = \sqrt{\frac{c (m + m_d)}{m m_d}}", "frequency"),
        "w 2": (r"\omega = \sqrt{\frac{2 c}{m}}", "frequency"),
        "w swapped": (r"\omega = \sqrt{\frac{c}{m_d}}", "frequency"),
        "T": (r"T = 2 \pi \sqrt{\frac{m}{c}}", "period"),
        "T half": (r"T = \pi \sqrt{\frac{m}{c}}", "period"),
        "zeta": (rf"\zeta = {zeta}", "damping_ratio"),
        "zeta 2": (r"\zeta = \frac{d}{\sqrt{c m}}", "damping_ratio"),
        "wd": (rf"\omega_d = \sqrt{{\frac{{c}}{{m}}}} \sqrt{{1 - \left({zeta}\right)^2}}",
               "damped_frequency"),
        "wd no square": (rf"\omega_d = \sqrt{{\frac{{c}}{{m}}}} \sqrt{{1 - {zeta}}}",
                         "damped_frequency")}
    verdicts = _audit(
        tmp_path, RIGID,
        *(_formula(label, tex, f"rope.{what}", RIGID_NAMES)
          for label, (tex, what) in printed.items()),
        _formula("wd quantities", r"\nu = \omega \sqrt{1 - \zeta^2}",
                 "rope.damped_frequency",
                 '"\\\\omega" = "rope.frequency", "\\\\zeta" = "rope.damping_ratio"'),
        _formula("wd missing", r"\nu = \omega", "rope.damped_frequency",
                 '"\\\\omega" = "rope.frequency"'))
    assert verdicts == {
        "w": ("confirmed", "symbolic"), "w free": ("discrepancy", "numeric"),
        "w 2": ("discrepancy", "numeric"), "w swapped": ("discrepancy", "numeric"),
        "T": ("confirmed", "symbolic"), "T half": ("discrepancy", "numeric"),
        "zeta": ("confirmed", "symbolic"), "zeta 2": ("discrepancy", "numeric"),
        "wd": ("confirmed", "symbolic"), "wd no square": ("discrepancy", "numeric"),
        "wd quantities": ("confirmed", "symbolic"), "wd missing": ("discrepancy", "numeric")}


def test_rigid_drive_frequencies_are_the_runs(tmp_path):
    """The quantities at the file's values against the run's own A: its damped
    rate is ω √(1 − ζ²); the period is the issue's 0.562 s."""
    path = tmp_path / "rigid.toml"
    path.write_text(RIGID, encoding="utf-8")
    model = read_component_file(path).model
    state, _ = mode_at(model, None, 1.0, "drive", "0.5 m/s")
    choice = ModeChoice(state=state)
    values = model.equations.values

    def at_values(what: str) -> float:
        return float(derived_quantity(model, f"rope.{what}", choice=choice).expr.xreplace(values))
    assert at_values("frequency") == pytest.approx(math.sqrt(1.25e6 / 1e4), rel=1e-14)
    assert at_values("period") == pytest.approx(0.562, abs=5e-4)
    (damped,) = _run_frequencies(path)
    assert at_values("damped_frequency") == pytest.approx(damped, rel=1e-12)
    assert at_values("damping_ratio") == pytest.approx(2.2e4 / (2 * math.sqrt(1.25e10)),
                                                       rel=1e-14)


def test_two_free_masses_as_users_write_them(tmp_path):
    """ω² = c (m1 + m2)/(m1 m2) (a left side squared: ω its principal root)."""
    names = 'c = "link.stiffness", m_1 = "one.mass", m_2 = "two.mass"'
    printed = {"right": r"\omega^2 = \frac{c (m_1 + m_2)}{m_1 m_2}",
               "factor 2": r"\omega^2 = \frac{2 c (m_1 + m_2)}{m_1 m_2}",
               "one mass": r"\omega^2 = \frac{c}{m_1}",
               "missing term": r"\omega^2 = \frac{c m_1}{m_1 m_2}"}
    verdicts = _audit(tmp_path, TWO_FREE, *(_formula(label, tex, "link.frequency", names)
                                            for label, tex in printed.items()))
    assert verdicts == {"right": ("confirmed", "symbolic"),
                        "factor 2": ("discrepancy", "numeric"),
                        "one mass": ("discrepancy", "numeric"),
                        "missing term": ("discrepancy", "numeric")}
    path = tmp_path / "model.toml"
    (omega,) = _run_frequencies(path)
    assert omega == pytest.approx(math.sqrt(1e6 * 24e3 / 80e6), rel=1e-12)


#: The chain's characteristic equation: A ω⁴ − B ω² + C = 0 (ω = 0 divided out).
_A = "m_1 m_2 m_3"
_B = "c_1 m_3 (m_1 + m_2) + c_2 m_1 (m_2 + m_3)"
_C = "c_1 c_2 (m_1 + m_2 + m_3)"
CHAIN_NAMES = ('m_1 = "one.mass", m_2 = "two.mass", m_3 = "three.mass", c_1 = "c_a.stiffness", '
               'c_2 = "c_b.stiffness"')


def _roots(sign: str, B: str = _B, C: str = _C) -> str:
    return (rf"\omega^2 = \frac{{{B} {sign} \sqrt{{\left({B}\right)^2 - 4 {_A} {C}}}}}"
            rf"{{2 {_A}}}")


def test_three_mass_chain_both_frequencies_from_its_characteristic_equation(tmp_path):
    """ω₁ (the lowest, the default) and ω₂ (mode = 2, or the mode that loads c_a
    most) as the roots of A ω⁴ − B ω² + C = 0; the branches swapped, a missing
    term of B, the end masses swapped: discrepancies."""
    B_missing = "c_1 m_3 (m_1 + m_2) + c_2 m_1 m_2"
    B_swapped = "c_1 m_1 (m_3 + m_2) + c_2 m_3 (m_2 + m_1)"
    verdicts = _audit(
        tmp_path, CHAIN,
        _formula("w1", _roots("-"), "c_a.frequency", CHAIN_NAMES),
        _formula("w2", _roots("+"), "c_a.frequency", CHAIN_NAMES, "mode = 2\n"),
        _formula("w2 by link", _roots("+"), "c_b.frequency", CHAIN_NAMES, 'mode = "c_a"\n'),
        _formula("w1 as w2", _roots("-"), "c_a.frequency", CHAIN_NAMES, "mode = 2\n"),
        _formula("w1 missing term", _roots("-", B_missing), "c_a.frequency", CHAIN_NAMES),
        _formula("w1 swapped", _roots("-", B_swapped), "c_a.frequency", CHAIN_NAMES))
    assert verdicts["w1"][0] == verdicts["w2"][0] == verdicts["w2 by link"][0] == "confirmed"
    assert {k: v[0] for k, v in verdicts.items() if k.startswith("w1 ")} == {
        "w1 as w2": "discrepancy", "w1 missing term": "discrepancy",
        "w1 swapped": "discrepancy"}
    # against the run's A, and the link's mode by scipy's generalized eigenproblem
    path = tmp_path / "model.toml"
    model = read_component_file(path).model
    values = model.equations.values
    run = _run_frequencies(path)
    for k, omega in enumerate(run, 1):
        q = derived_quantity(model, "c_a.frequency", choice=ModeChoice(k))
        assert float(q.expr.xreplace(values)) == pytest.approx(omega, rel=1e-12)
    m = np.diag([1e3, 3e3, 8e3])
    c_a, c_b = 2e6, 5e5
    K = np.array([[c_a, -c_a, 0], [-c_a, c_a + c_b, -c_b], [0, -c_b, c_b]])
    lam, shapes = scipy.linalg.eigh(K, m)
    share = [c_a * (shapes[1, j] - shapes[0, j]) ** 2 / lam[j] for j in (1, 2)]
    assert int(np.argmax(share)) + 1 == 2           # what mode = "c_a" confirmed above


#: The chain with 2 mm of backlash in c_a, pushed at its middle from rest: the
#: gap open at the start, closed from 0.050 s to 0.118 s, open again to 0.142 s.
GAP = (CHAIN.replace('name = "chain"', 'name = "gap"')
       .replace('"2e6 N/m"\n', '"2e6 N/m"\nbacklash = "2 mm"\n')
       + '\n[[resistance]]\nname = "push"\nbody = "two"\nforce = "-5 kN"\n')


def test_gaps_as_they_are(tmp_path):
    """The mode at the start has c_a's gap open: only m2 -c_b- m3 rings; at
    0.08 s the gap is closed and the chain's lower root is the frequency."""
    alone = r"\omega^2 = \frac{c_2 (m_2 + m_3)}{m_2 m_3}"
    verdicts = _audit(
        tmp_path, GAP,
        _formula("open", alone, "c_b.frequency", CHAIN_NAMES),
        _formula("chain at start", _roots("-"), "c_b.frequency", CHAIN_NAMES),
        _formula("closed", _roots("-"), "c_b.frequency", CHAIN_NAMES, 'at = "0.08 s"\n'),
        _formula("open at 0.08 s", alone, "c_b.frequency", CHAIN_NAMES, 'at = "0.08 s"\n'),
        _formula("open again", alone, "c_b.frequency", CHAIN_NAMES, 'at = "0.13 s"\n'))
    assert {k: v[0] for k, v in verdicts.items()} == {
        "open": "confirmed", "chain at start": "discrepancy", "closed": "confirmed",
        "open at 0.08 s": "discrepancy", "open again": "confirmed"}
    path = tmp_path / "model.toml"       # the model cannot check it: not_checkable, why
    path.write_text(GAP + _formula("by c_a", alone, "c_b.frequency", CHAIN_NAMES,
                                   'mode = "c_a"\n'), encoding="utf-8")
    (record,) = audit_file(read_component_file(path))
    assert record.verdict == "not_checkable"
    assert "the link 'c_a' is in its gap in this mode" in record.detail


#: A drive held by its speed law and three bodies on it: one rope alone, a chain
#: of two; three elastic roots, the rope's far above the chain's.
DECOUPLED = ('[model]\nname = "decoupled"\n' + MASS.format("drive", "1 t")
             + MASS.format("hook", "1 kg") + MASS.format("one", "2 t")
             + MASS.format("two", "5 t")
             + LINK.format("rope", "drive", "hook", "1e7 N/m", "")
             + LINK.format("first", "drive", "one", "4e5 N/m", "")
             + LINK.format("second", "one", "two", "3e5 N/m", "")
             + SPEED_LAW.format("drive")
             + '\n[run]\nduration = "1 s"\nbody = "drive"\nspeed = "0.5 m/s"\n')


def test_three_elastic_roots_evaluated_by_mpmath(tmp_path):
    """Three elastic roots: no closed form taken, mpmath's eigsy at each point.
    The rope's √(c/m), third from the lowest, is confirmed as mode = 3 and as the
    mode loading the rope most, a discrepancy as mode = 2."""
    names = 'c = "rope.stiffness", m = "hook.mass"'
    right = r"\omega = \sqrt{\frac{c}{m}}"
    verdicts = _audit(tmp_path, DECOUPLED,
                      _formula("3", right, "rope.frequency", names, "mode = 3\n"),
                      _formula("by link", right, "first.frequency", names, 'mode = "rope"\n'),
                      _formula("2", right, "rope.frequency", names, "mode = 2\n"))
    assert verdicts == {"3": ("confirmed", "numeric"), "by link": ("confirmed", "numeric"),
                        "2": ("discrepancy", "numeric")}
    path = tmp_path / "model.toml"
    read = read_component_file(path)
    state, _ = mode_at(read.model, None, 1.0, "drive", "0.5 m/s")
    values = read.model.equations.values
    for k, omega in enumerate(_run_frequencies(path), 1):
        q = derived_quantity(read.model, "second.frequency", choice=ModeChoice(k, state))
        assert "mpmath" in q.how
        assert float(q.expr.xreplace(values).evalf(30)) == pytest.approx(omega, rel=1e-12)
    # the rope damped: its mode's ζ is the one-mass d / (2 √(c m)), its damped
    # frequency the run's (the rope's mode is uncoupled, so the modal value is exact)
    path.write_text(DECOUPLED.replace('"1e7 N/m"\n', '"1e7 N/m"\ndamping = "30 N*s/m"\n'),
                    encoding="utf-8")
    model = read_component_file(path).model
    choice = ModeChoice("rope", state)
    zeta = derived_quantity(model, "rope.damping_ratio", choice=choice).expr
    damped = derived_quantity(model, "rope.damped_frequency", choice=choice).expr
    values = model.equations.values
    assert float(zeta.xreplace(values).evalf(30)) == pytest.approx(30 / (2 * math.sqrt(1e7)),
                                                                   rel=1e-12)
    assert float(damped.xreplace(values).evalf(30)) == pytest.approx(
        _run_frequencies(path)[2], rel=1e-12)


def test_pendulum_as_a_spring_of_m_g_over_L(tmp_path):
    """A link's stiffness is a number, so m g / L cannot be written as one: the
    linearized pendulum is a bob on a spring of that stiffness from a support a
    law holds still; T = 2π √(m/c), which is 2π √(L/g) at the file's values."""
    names = 'm = "bob.mass", c = "arm.stiffness"'
    verdicts = _audit(tmp_path, PENDULUM,
                      _formula("T", r"T = 2 \pi \sqrt{\frac{m}{c}}", "arm.period", names),
                      _formula("T swapped", r"T = 2 \pi \sqrt{\frac{c}{m}}", "arm.period", names),
                      _formula("T 2", r"T = 4 \pi \sqrt{\frac{m}{c}}", "arm.period", names))
    assert verdicts == {"T": ("confirmed", "symbolic"),
                        "T swapped": ("dimension_error", "dimension"),
                        "T 2": ("discrepancy", "numeric")}
    model = read_component_file(tmp_path / "model.toml").model
    T = float(derived_quantity(model, "arm.period").expr.xreplace(model.equations.values))
    assert T == pytest.approx(2 * math.pi * math.sqrt(L_PENDULUM / G), rel=1e-14)


def test_the_mode_at_an_instant_holds_a_braked_group(tmp_path):
    """at = ...: the run's mode then. Two masses on a link, the first braked from
    0.2 s until it rests and is held: at the start ω² = c (m1 + m2)/(m1 m2), once
    held ω² = c/m2."""
    text = (TWO_FREE.replace('start = "rest"', 'body = "one"\nspeed = "0.3 m/s"')
            + '\n[[brake]]\nname = "stop"\nbody = "one"\nforce = "200 kN"\ndelay = "0.2 s"\n')
    names = 'c = "link.stiffness", m_1 = "one.mass", m_2 = "two.mass"'
    verdicts = _audit(
        tmp_path, text,
        _formula("start", r"\omega^2 = \frac{c (m_1 + m_2)}{m_1 m_2}", "link.frequency", names),
        _formula("held", r"\omega^2 = \frac{c}{m_2}", "link.frequency", names, 'at = "0.9 s"\n'),
        _formula("held, free formula", r"\omega^2 = \frac{c (m_1 + m_2)}{m_1 m_2}",
                 "link.frequency", names, 'at = "0.9 s"\n'))
    assert verdicts == {"start": ("confirmed", "symbolic"), "held": ("confirmed", "symbolic"),
                        "held, free formula": ("discrepancy", "numeric")}
    read = read_component_file(tmp_path / "model.toml")
    state, instant = mode_at(read.model, 0.9, 1.0, "one", "0.3 m/s")
    assert state.motion[0] == "0" and instant == "the mode of the run at t = 0.9 s"


def test_negative_parameters_keep_the_sign_the_file_gives(tmp_path):
    """A resistance of −2 kN as a formula's symbol: sampled negative, also where a
    number of the run is compared at the file's values (refused before); a gear
    that turns the other way (ratio −3) keeps its frequency positive."""
    text = TWO_FREE.replace('name = "two_free"', 'name = "negative"') + (
        '\n[[resistance]]\nname = "drag"\nbody = "two"\nforce = "-2 kN"\n')
    names = 'W = "drag.force", m_1 = "one.mass", m_2 = "two.mass"'
    verdicts = _audit(
        tmp_path, text,
        _formula("peak", r"F_{max} = \frac{2 W m_1}{m_1 + m_2}", "link.peak", names,
                 "tolerance = 1e-6\n"),
        _formula("peak, no 2", r"F_{max} = \frac{W m_1}{m_1 + m_2}", "link.peak", names,
                 "tolerance = 1e-6\n"),
        _formula("peak, sign", r"F_{max} = -\frac{2 W m_1}{m_1 + m_2}",
                 "link.peak", names, "tolerance = 1e-6\n"))
    assert verdicts["peak"] == ("confirmed", "numeric")
    assert verdicts["peak, no 2"][0] == verdicts["peak, sign"][0] == "discrepancy"
    geared = ('[model]\nname = "geared"\n[[inertia]]\nname = "motor"\ninertia = "2 kg*m^2"\n'
              '[[inertia]]\nname = "shaft"\ninertia = "0.5 kg*m^2"\n'
              '[[inertia]]\nname = "drum"\ninertia = "90 kg*m^2"\n'
              '[[gear]]\nname = "gearbox"\ninput = "shaft"\noutput = "drum"\nratio = -3\n'
              + LINK.format("coupling", "motor", "shaft", "5e4 N*m/rad", "")
              + '\n[run]\nduration = "1 s"\nstart = "rest"\n')
    names = ('c = "coupling.stiffness", J_1 = "motor.inertia", J_2 = "shaft.inertia", '
             'J_3 = "drum.inertia", i = "gearbox.ratio"')
    verdicts = _audit(
        tmp_path, geared,
        _formula("w", r"\omega^2 = \frac{c (J_1 + J_2 + J_3 / i^2)}{J_1 (J_2 + J_3 / i^2)}",
                 "coupling.frequency", names),
        _formula("w, i", r"\omega^2 = \frac{c (J_1 + J_2 + J_3 / i)}{J_1 (J_2 + J_3 / i)}",
                 "coupling.frequency", names))
    assert verdicts == {"w": ("confirmed", "symbolic"), "w, i": ("discrepancy", "numeric")}
    model = read_component_file(tmp_path / "model.toml").model
    (ratio,) = signed(model).values()
    assert ratio.is_negative and ratio.name == "i_gearbox"
    omega = derived_quantity(model, "coupling.frequency").expr
    values = model.equations.values | {ratio: -3.0}
    assert float(omega.xreplace(values)) == pytest.approx(
        _run_frequencies(tmp_path / "model.toml")[0], rel=1e-12) and float(
        omega.xreplace(values)) > 0


@pytest.mark.parametrize("extra, message", [
    ("mode = 0\n", "mode must be \"lowest\", a number k >= 1"),
    ('mode = "rop"\n', "mode must be \"lowest\", a number k >= 1 (the k-th from the lowest) "
                       "or an elastic link (rope), got 'rop'"),
    ('at = "-1 s"\n', "at must be an instant >= 0 s"),
])
def test_a_bad_choice_is_one_line(extra, message, tmp_path):
    path = tmp_path / "model.toml"
    path.write_text(RIGID + _formula("w", r"\omega = \sqrt{c/m}", "rope.frequency",
                                     RIGID_NAMES, extra), encoding="utf-8")
    with pytest.raises(ComponentError) as err:
        audit_file(read_component_file(path))
    assert message in str(err.value) and "\n" not in str(err.value)


def test_a_frequency_the_mode_has_not_is_not_checkable(tmp_path):
    """mode = 2 of a one-mode model: the file is fine, the model cannot check it."""
    path = tmp_path / "model.toml"
    path.write_text(RIGID + _formula("w", r"\omega = \sqrt{c/m}", "rope.frequency",
                                     RIGID_NAMES, "mode = 2\n"), encoding="utf-8")
    (record,) = audit_file(read_component_file(path))
    assert record.verdict == "not_checkable"
    assert ("natural frequency number 2 in the mode of the run's start: the mode has 1 "
            "(k from 1 to 1)") in record.detail


def test_mode_and_at_belong_to_a_frequency(tmp_path):
    path = tmp_path / "model.toml"
    path.write_text(RIGID + _formula("s", "F = c", "rope.static", 'c = "rope.stiffness"',
                                     "mode = 2\n"), encoding="utf-8")
    with pytest.raises(ComponentError, match="mode and at choose a natural frequency; the "
                                             "formula names none"):
        read_component_file(path)
