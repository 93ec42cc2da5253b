"""Spans: elastic elements with a mass of their own between points that move as
linear combinations of several coordinates (``[[span]]``), so a full mass
matrix. Paper 004's drum drive written whole (examples/drive_trains/
drum_drive_004.toml): its M, C, K and forces are 004's (12) symbolically, and
its run over 004's 10 s is (12) integrated with the derivation's generated
right-hand side (the free drive's phase in the precise form that sums its
slow pair); a two-mass span against its closed form; the run's solver with a full M against
solve_ivp; the bad tables refused in one line are rows of
tests/test_component_faults.py."""
from __future__ import annotations

import importlib

import numpy as np
import pytest
import sympy as sp

from crane_sym import registry
from crane_sym.components import Inertia, Mass, Model, Motor
from crane_sym.components.kinds.span import Span
from crane_sym.components.parts import ComponentError
from crane_sym.components.component_file import read_component_file
from crane_sym.mechanics import closed_forms
from crane_sym.mechanics.exact_phases import exact_table
from crane_sym.mechanics.phase_table import values

from test_components_laws import EXAMPLES, generated

FILE = EXAMPLES / "drum_drive_004.toml"
#: The example's values (SI) by 004's symbol names (its scene drum_drive_example).
DRUM = {"I1": 13.0, "I2": 3.0, "I3": 50.0, "C1": 2e4, "C2": 5e4, "nu1": 20.0, "nu2": 50.0,
        "m3": 800.0, "m_L": 2500.0, "C_y": 2e7, "nu_y": 1.3e4, "C_t": 5e4, "C_z": 5e4,
        "nu_z": 500.0, "nu_t": 400.0, "q": 2.4, "L": 600.0, "r": 0.25, "M0": 440.0,
        "F0": 2e4, "W": 1e3}


@pytest.fixture(scope="module")
def read():
    return read_component_file(FILE)


def _paper():
    return importlib.import_module("crane_sym.derivations.drum_drive.model")


def _matrices(rows, coordinates, t):
    """(M, C, K, f) of rows lhs − rhs = 0 linear in q, q̇, q̈."""
    accs, rates, plain = (sp.symbols(f"{k}0:{len(coordinates)}") for k in "avq")
    swap = {}
    for c, a, v in zip(coordinates, accs, rates):
        swap.update({c.diff(t, 2): a, c.diff(t): v})
    res = sp.Matrix([sp.expand(r.subs(swap).subs(dict(zip(coordinates, plain))))
                     for r in rows])
    M, C, K = (res.jacobian(list(v)) for v in (accs, rates, plain))
    return M, C, K, -res.subs({s: 0 for s in (*accs, *rates, *plain)})


def _renaming(eq, p):
    """The component model's symbols as 004's."""
    s = {x.name: x for x in [*eq.values, *eq.switches, *eq.motor_loads, *eq.slopes]}
    return {s["J_motor"]: p.I1, s["J_gearbox"]: p.I2, s["J_drum"]: p.I3,
            s["m_centre"]: p.m3, s["m_run"]: p.m_L, s["c_shaft1"]: p.C1, s["d_shaft1"]: p.nu1,
            s["c_shaft2"]: p.C2, s["d_shaft2"]: p.nu2, s["c_bending"]: p.C_y,
            s["d_bending"]: p.nu_y, s["m_bending"]: 0, s["c_tight"]: p.C_t, s["d_tight"]: 0,
            s["m_tight"]: p.q * p.L, s["c_slack"]: p.C_z, s["d_slack"]: p.nu_z,
            s["m_slack"]: p.q * p.L, s["a_drum_250_mm"]: p.r,
            s["R_pretension"]: 2 * p.F0, s["R_load"]: -p.W,
            s["beta_running"]: p.nu_t, s["v0_running"]: 0, s["M_drive"]: p.M0,
            s["on_drive"]: 1}


def test_the_drum_drive_is_004s_12_symbolically(read):
    """M, C, K and the forces of the file's Lagrange equations, renamed to 004's
    symbols, equal those of 004's (12) in (φ1, φ2, φ3, y, z): simplify of each
    difference is the zero matrix. M is not diagonal (the element's mass couples
    φ3 and z; its φ3–y and y–z terms cancel between the branches); with the elements massless it is not 004's."""
    p, eq = _paper(), read.model.equations
    d = registry.get("drum_drive")
    theirs = _matrices([(e.lhs - e.rhs).doit() for e in
                        (d.step(f"(12), {n}").statement for n in ("φ1", "φ2", "φ3", "y", "z"))],
                       p.COORDS, p.t)
    names = _renaming(eq, p)
    ours = _matrices([(e.lhs - e.rhs).doit() for e in eq.lagrange.equations],
                     eq.coordinates, eq.t)
    ours = [m.xreplace(names) for m in ours]
    assert [g.name for g in read.model.assembly.groups] == ["motor", "gearbox", "drum",
                                                            "centre", "run"]
    for mine, paper, what in zip(ours, theirs, "MCKf"):
        assert sp.simplify(mine - paper) == sp.zeros(*paper.shape), what
    M, p_ = ours[0], _paper()
    assert not M.is_diagonal()                   # the element's mass couples φ3 and z:
    assert sp.simplify(M[2, 4] - p_.q * p_.L * p_.r / 3) == 0     # 2 × q L r/6
    massless = ours[0].xreplace({p.q: 0})
    assert sp.simplify(massless - theirs[0]) != sp.zeros(5, 5)


def test_the_drum_drives_matrices_are_the_generated_modules(read):
    """The same at the example's values, against 004's generated mass, damping and
    stiffness matrices and forces (the functions a scene prints)."""
    module = generated("drum_drive")
    v = DRUM
    M, D, K, f = read.model.equations.numeric()([], [], [1.0], [], [v["nu_t"]])
    np.testing.assert_allclose(M, module.mass_matrix(v["I1"], v["I2"], v["I3"], v["m3"],
                                                     v["m_L"], v["q"], v["L"], v["r"]),
                               rtol=1e-14, atol=1e-12)
    np.testing.assert_allclose(D, module.damping_matrix(v["nu1"], v["nu2"], v["nu_y"],
                                                        v["nu_z"], v["nu_t"], v["r"]),
                               rtol=1e-14, atol=1e-12)
    np.testing.assert_allclose(K, module.stiffness_matrix(v["C1"], v["C2"], v["C_y"], v["C_t"],
                                                          v["C_z"], v["r"]),
                               rtol=1e-14, atol=1e-9)
    np.testing.assert_allclose(f, np.ravel(module.generalized_forces(v["M0"], v["F0"], v["W"])),
                               rtol=1e-14)
    assert np.count_nonzero(M - np.diag(np.diag(M))) == 2       # M[φ3, z] = M[z, φ3]


def _integrated(values: dict, times: np.ndarray) -> dict:
    """004's (12) from rest by DOP853 at rtol 1e-12 with the derivation's
    generated state_derivative: the shafts' torques and y at ``times``."""
    from scipy.integrate import solve_ivp
    module = generated("drum_drive")
    v = values
    args = [v[k] for k in ("I1", "I2", "I3", "C1", "C2", "nu1", "nu2", "m3", "m_L", "C_y",
                           "nu_y", "C_t", "C_z", "nu_z", "nu_t", "q", "L", "r", "M0", "F0", "W")]
    sol = solve_ivp(lambda _, s: np.ravel(module.state_derivative(*args, *s)),
                    (0.0, times[-1]), [0.0] * 10, method="DOP853", rtol=1e-12, atol=1e-15,
                    t_eval=times)
    phi1, phi2, phi3, y, z, w1, w2, w3, _, _ = sol.y
    return {"shaft1": v["C1"] * (phi2 - phi1) + v["nu1"] * (w2 - w1),
            "shaft2": v["C2"] * (phi3 - phi2) + v["nu2"] * (w3 - w2), "y": y}


def test_the_drum_drive_runs_004s_12(read):
    """The file's run (its duration, 004's 10 s of Fig. 3, from rest) against
    (12) integrated by solve_ivp (:func:`_integrated`): the shafts' torques of the
    run in double precision and of its generated tables (phases replayed in
    mpmath) to 1e-9 of their peaks; and the drum shaft's deflection y. The
    drive runs free beside the stiff shaft (a rigid drift in the kernel); the
    double form's kernel term, projected onto ker M, now passes its residual
    check at 10 s (2.9e-10; it missed it by more than 1e-8 before), so the run
    is the double form's."""
    from crane_sym.mechanics.piecewise_linear import RESIDUAL
    assert read.duration == "10 s"
    run = read.model.run(read.duration, rest=read.rest)
    [phase] = run.result.segments
    A, b = run.system.matrices(phase.mode)
    assert closed_forms.closed_form(A, b, None).residual(10.0, phase.x0, A, b) <= RESIDUAL
    times = np.linspace(0.0, 10.0, 10_001)
    theirs = _integrated(DRUM, times)
    links = [l.part.name for l in run.system.assembly.links]
    for name in ("shaft1", "shaft2"):
        curve = theirs[name]
        peak = np.max(np.abs(curve))
        assert peak > 700.0, name                     # the start's torque peak, ~800 N·m
        assert abs(curve[-1] + DRUM["M0"]) < 5.0      # settled to the drive's M0 by 10 s
        ours = values(run.result, times, run.system.link_load(links.index(name)))
        assert np.max(np.abs(ours - curve)) <= 1e-9 * peak, name
        exact = exact_table(run.hybrid_run(name))(times)
        assert np.max(np.abs(exact - curve)) <= 1e-9 * peak, name
    centre = run.result.state(times)[:, run.system.q(3)]
    y = theirs["y"]
    assert np.max(np.abs(y)) > 1e-3                # the pretension's 2 F0 / C_y, ~2 mm
    assert np.max(np.abs(centre - y)) <= 1e-9 * np.max(np.abs(y))


def test_the_free_drives_precise_form_sums_its_slow_pair(read):
    """Why the run once stopped at ~0.5 s: A's doubles put the free drive's
    rigid-body zero at 4.6e-13, beside the constant input's exact 0. Split
    into e^{λt} C_λ + C_0 (the precise form with no horizon to sum them over)
    the pair's coefficients are ~3e13 and cancel to O(1), so rounded to double
    the form starts 4.9e-4 off x(0) = 0; summed as one series over the phase
    (exact_forms.SLOW) its coefficients stay O(100) and it starts at x0 and
    solves its equations to 1e-8 over 10 s."""
    import math
    from crane_sym.mechanics import exact_forms
    from crane_sym.mechanics.piecewise_linear import RESIDUAL
    run = read.model.run(1.0, rest=True)
    [phase] = run.result.segments
    A, b = run.system.matrices(phase.mode)
    keys = tuple(map(float, A.ravel())), tuple(map(float, b))
    split = exact_forms._exact_form_cached(*keys, exact_forms.DPS, math.inf).double
    summed = exact_forms.precise_closed_form(A, b, 10.0)
    x0 = phase.x0
    assert np.abs(split.coefficients).max() > 1e13
    assert np.abs(split.state(0.0, x0)).max() > 1e-4
    assert split.start_miss(1.0, x0, A, b) > 1.0
    assert np.abs(summed.coefficients).max() < 1e3
    for t in (0.4, 1.0, 10.0):
        assert summed.residual(t, x0, A, b) <= RESIDUAL
        assert summed.start_miss(t, x0, A, b) <= RESIDUAL


def test_a_span_with_mass_between_two_bodies_is_its_closed_form():
    """Two masses m1, m2 joined by a span of stiffness c and own mass m (speed
    linear along it): M = [[m1 + m/3, m/6], [m/6, m2 + m/3]], and the elastic
    mode's ω² = c (1/M1 + 1/M2) ... checked as the eigenvalue of M⁻¹K, and the
    run of a force on m1 against solve_ivp of M q̈ + K q = f."""
    from scipy.integrate import solve_ivp
    m1, m2, m, c, F = 10.0, 30.0, 6.0, 1e4, 50.0
    model = Model([Mass("a", m1), Mass("b", m2), Span("rope", {"a": 1}, {"b": 1}, c, 0.0, m),
                   Motor("push", "a", F)])
    eq = model.equations
    M, D, K, f = eq.numeric()([], [], [1.0], [])
    np.testing.assert_allclose(M, [[m1 + m / 3, m / 6], [m / 6, m2 + m / 3]], rtol=1e-15)
    np.testing.assert_allclose(K, [[c, -c], [-c, c]], rtol=1e-15)
    Mexact = sp.Matrix([[m1 + sp.Rational(m) / 3, sp.Rational(m) / 6],
                        [sp.Rational(m) / 6, m2 + sp.Rational(m) / 3]])
    lam = sp.Symbol("lam")
    roots = sp.solve((lam * Mexact - sp.Matrix([[c, -c], [-c, c]])).det(), lam)
    omega2 = float(max(roots))
    assert omega2 == pytest.approx(c * (m1 + m2 + m) / (m1 * m2 + m * (m1 + m2) / 3
                                                         + m * m / 12), rel=1e-12)
    run = model.run(1.0, rest=True)
    form_omegas = sorted({round(w, 9) for w in run.result.segments[0].form.omegas if w > 0})
    assert form_omegas == pytest.approx([np.sqrt(omega2)], rel=1e-9)
    times = np.linspace(0.0, 1.0, 401)
    Minv = np.linalg.inv(M)
    sol = solve_ivp(lambda _, s: [*s[2:], *(Minv @ (f - K @ s[:2]))], (0.0, 1.0), [0.0] * 4,
                    method="DOP853", rtol=1e-12, atol=1e-15, t_eval=times)
    stretch = values(run.result, times, _weights(run, [-1.0, 1.0]))
    assert np.max(np.abs(stretch - (sol.y[1] - sol.y[0]))) <= 1e-9 * np.max(np.abs(sol.y[1]
                                                                                 - sol.y[0]))


def _weights(run, per_group):
    w = np.zeros(run.system.size)
    w[0:2 * len(per_group):2] = per_group

    def affine(mode):
        return w, 0.0
    return affine


def test_a_full_mass_matrix_is_solved_not_divided():
    """The mode's A has M⁻¹ K in its speed rows: a coupled M gives what
    np.linalg.solve gives, and a diagonal one exactly K / m (the rows of the
    models before spans: unchanged to the last bit)."""
    from crane_sym.components.hybrid import ComponentSystem
    model = Model([Mass("a", 10.0), Mass("b", 30.0),
                   Span("rope", {"a": 1}, {"b": 1}, 1e4, 2.0, 6.0), Motor("push", "a", 50.0)])
    mode, x, extra = model.start(None, 0.0, True)
    system = ComponentSystem(model.equations, extra)
    A, b = system.matrices(mode)
    M, D, K, f = model.equations.numeric()([], [], [1.0], [])
    np.testing.assert_allclose(A[1::2, 0::2], -np.linalg.solve(M, K), rtol=1e-13)
    np.testing.assert_allclose(b[1::2], np.linalg.solve(M, f), rtol=1e-13)
    plain = Model([Mass("a", 10.0), Mass("b", 30.0),
                   Span("rope", {"a": 1}, {"b": 1}, 1e4, 2.0), Motor("push", "a", 50.0)])
    mode, x, extra = plain.start(None, 0.0, True)
    A, b = ComponentSystem(plain.equations, extra).matrices(mode)
    assert A[1, 0] == -1e4 / 10.0 and A[3, 2] == -1e4 / 30.0 and b[1] == 50.0 / 10.0


def test_a_steady_start_with_a_span_is_refused_in_one_line():
    """The steady start sets the speeds through the elastic links, not spans."""
    model = Model([Inertia("a", 1.0), Mass("b", 2.0),
                   Span("rope", {"a": "0.5 m"}, {"b": 1}, 1e4), Motor("m", "a", 1.0)])
    with pytest.raises(ComponentError, match=r"^start: a steady start sets the speeds through "
                       r"the elastic links, not through span 'rope'; start at rest$"):
        model.start(None, 0.0, False)


def test_the_natural_frequency_of_a_full_mass_matrix(read):
    """ω1 and ζ1 of the drum drive (M full, one rigid-body root) from the
    vibration module's mpmath route (L⁻¹ K L⁻ᵀ, M = L Lᵀ) against SciPy's
    generalized eigenproblem K φ = ω² M φ and φᵀDφ / (2 ω φᵀMφ)."""
    import scipy.linalg
    from crane_sym.components.vibration import ModeChoice, natural_frequency
    eq = read.model.equations
    f = natural_frequency(read.model, ModeChoice())
    assert "1 rigid-body root(s) dropped, 4 elastic" in f.how
    M, D, K, _ = eq.numeric()([], [], [1.0], [], [DRUM["nu_t"]])
    lam, phi = scipy.linalg.eigh(K, M)
    shape = phi[:, 1]
    omega = np.sqrt(lam[1])
    zeta = shape @ D @ shape / (2 * omega * (shape @ M @ shape))
    assert float(f.omega.xreplace(eq.values)) == pytest.approx(omega, rel=1e-10)
    assert float(f.zeta.xreplace(eq.values)) == pytest.approx(zeta, rel=1e-8)


def test_a_held_body_feels_its_neighbours_acceleration_through_a_full_m():
    """A brake holds mass a; a span with a mass of its own joins it to mass b,
    which a force pushes. The load the brake must hold (net_load) is the
    reaction of the constraint q̈_a = 0 solved with a Lagrange multiplier,
    [[M, e_a], [e_aᵀ, 0]] [q̈; λ] = [R x + r; 0] (λ = R_a x + r_a − M_ab q̈_b: the
    load the brake takes), at a state where the span is stretched and moving;
    its −M_ab q̈_b is 0 only with a massless span."""
    from crane_sym.components import Brake
    from crane_sym.components.hybrid import HELD, ComponentSystem
    model = Model([Mass("a", 10.0), Mass("b", 30.0),
                   Span("rope", {"a": 1}, {"b": 1}, 1e4, 20.0, 6.0),
                   Motor("push", "b", 50.0), Brake("hold", "a", 1e3)])
    mode, x, extra = model.start(None, 0.0, True)
    assert mode.motion[0] == HELD
    system = ComponentSystem(model.equations, extra)
    x = np.array(x, dtype=float)
    x[system.q(1)], x[system.v(1)] = 0.003, -0.2
    M, D, K, f = model.equations.numeric()([], [], [1.0], [0.0])
    push = f - K @ x[0:4:2] - D @ x[1:4:2]
    kkt = np.block([[M, np.array([[1.0], [0.0]])], [np.array([[1.0, 0.0, 0.0]])]])
    acc_b, lam = np.linalg.solve(kkt, [*push, 0.0])[1:]
    w, k = system.net_load(mode, 0)
    assert float(w @ x + k) == pytest.approx(lam, rel=1e-12)
    assert abs(M[0, 1] * acc_b) > 0.5                  # the coupling is felt, not rounding
    A, b = system.matrices(mode)
    assert float(A[system.v(1)] @ x + b[system.v(1)]) == pytest.approx(acc_b, rel=1e-12)
    assert not A[system.v(0)].any() and b[system.v(0)] == 0.0


def _variant(tmp_path, *subs: tuple[str, str]):
    """The example with text replaced (each must be there), read."""
    text = FILE.read_text(encoding="utf-8")
    for old, new in subs:
        assert old in text, old
        text = text.replace(old, new, 1)
    path = tmp_path / f"variant_{abs(hash(text))}.toml"
    path.write_text(text, encoding="utf-8")
    return read_component_file(path)


def test_the_design_with_c1_doubled_runs_004s_12(tmp_path):
    """The drum drive with C1 doubled over 0.5 s, once refused (its mpmath form
    started ~3e13 off; before that, run: shaft1 −841.5 N·m where solve_ivp
    gives −769.5): its torques are (12) integrated to 1e-9 of the peaks."""
    doubled = _variant(tmp_path, ('stiffness = "20 kN*m/rad"', 'stiffness = "40 kN*m/rad"'),
                       ('duration = "10 s"', 'duration = "0.5 s"'))
    run = doubled.model.run(doubled.duration, rest=True)
    times = np.linspace(0.0, 0.5, 1001)
    theirs = _integrated({**DRUM, "C1": 4e4}, times)
    links = [l.part.name for l in run.system.assembly.links]
    for name in ("shaft1", "shaft2"):
        peak = np.max(np.abs(theirs[name]))
        ours = values(run.result, times, run.system.link_load(links.index(name)))
        assert np.max(np.abs(ours - theirs[name])) <= 1e-9 * peak, name
    assert np.min(theirs["shaft1"]) == pytest.approx(-769.5, abs=0.05)


def test_a_phase_no_form_certifies_is_refused_in_one_line(tmp_path):
    """The drum shaft 1e15 times stiffer (C_y = 2e22 N/m: a bending mode at
    3.4e9 rad/s beside the free drive): neither the double form (residual 1.1)
    nor the precise one rounded to double (1.5e-7: ω t eps) solves the phase's
    equations to 1e-8, and the run is refused by name."""
    stiff = _variant(tmp_path, ('stiffness = "2e7 N/m"', 'stiffness = "2e22 N/m"'),
                     ('duration = "10 s"', 'duration = "1 s"'))
    with pytest.raises(ComponentError, match=r"^run: a phase of 1 s: its closed form does "
                       r"not solve its equations to 1e-08 \(time scales too far apart for "
                       r"double precision\)$"):
        stiff.model.run(stiff.duration, rest=True)
