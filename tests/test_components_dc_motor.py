"""A DC motor's armature as a component: its current a first-order state of
the component system (L di/dt = V − R i − k ω, torque k i), checked against
the closed form of the motor alone on an inertia, derived here with SymPy."""
from __future__ import annotations

import tempfile
from pathlib import Path

import numpy as np
import pytest
import sympy as sp

from crane_sym.components import Inertia, Model
from crane_sym.components.laws import MotorLaw
from crane_sym.components.loads import DCMotor
from crane_sym.mechanics.phase_table import values

#: The motor alone: J [kg m²], R [Ω], L [H], k [N m/A], V [V] (a step at t = 0).
J, R, L, K, V = (sp.Rational(4, 5), sp.Rational(1, 2), sp.Rational(1, 50), sp.Rational(6, 5),
                 sp.Integer(100))


def motor_alone(voltage: MotorLaw) -> Model:
    return Model([Inertia("rotor", float(J)),
                  DCMotor("m", "rotor", f"{float(R)} ohm", f"{float(L)} H",
                          f"{float(K)} N*m/A", voltage)])


def state(run, index: int, times: np.ndarray) -> np.ndarray:
    """Component ``index`` of the run's state at ``times``."""
    unit = np.eye(run.system.size)[index]
    return values(run.result, times, lambda mode: (unit, 0.0))


def closed_form() -> tuple[sp.Expr, sp.Expr, sp.Symbol]:
    """(ω(t), i(t)) of J ω' = k i, L i' = V − R i − k ω from rest, V a step:
    the second-order linear system solved by Laplace's transform."""
    t, s = sp.symbols("t", positive=True), sp.Symbol("s")
    i_s = (V / s) * J * s / (L * J * s**2 + R * J * s + K**2)
    omega_s = K * i_s / (J * s)
    back = [sp.inverse_laplace_transform(sp.apart(f, s), s, t) for f in (omega_s, i_s)]
    return (*(sp.simplify(f.subs(sp.Heaviside(t), 1)) for f in back), t)


def test_the_current_is_a_first_order_state_with_its_rate_from_the_part():
    model = motor_alone(MotorLaw("m", "rotor", [0.0, 10.0], [[float(V)]], "V", "voltage"))
    eq = model.equations
    i, volts = sp.Symbol("i_m", real=True), sp.Symbol("V_m", real=True)
    Rs, Ls, Ks = (sp.Symbol(f"{x}_m", positive=True) for x in "RLk")
    theta = eq.coordinates[0]
    assert eq.states == (i,)
    assert sp.simplify(eq.rates[0] - (volts - Rs * i - Ks * theta.diff(eq.t)) / Ls) == 0
    assert sp.simplify(eq.forces[theta] - Ks * i) == 0


def test_dc_motor_on_an_inertia_against_its_closed_form():
    """A voltage step on the motor alone: speed and current against the
    closed form to 1e-10 of their peaks."""
    omega, current, t = closed_form()
    model = motor_alone(MotorLaw("m", "rotor", [0.0, 10.0], [[float(V)]], "V", "voltage"))
    run = model.run(0.5, rest=True)
    system = run.system
    assert system.size == 3 and system.first == 2          # (θ, ω, i)
    times = np.linspace(0.0, 0.5, 201)
    theirs_w = np.array([float(omega.subs(t, x)) if x else 0.0 for x in times])
    theirs_i = np.array([float(current.subs(t, x)) if x else 0.0 for x in times])
    ours_w, ours_i = state(run, system.v(0), times), state(run, system.first, times)
    assert np.max(np.abs(ours_w - theirs_w)) <= 1e-10 * np.max(np.abs(theirs_w))
    assert np.max(np.abs(ours_i - theirs_i)) <= 1e-10 * np.max(np.abs(theirs_i))
    # the steady speed V/k is where the back-emf meets the voltage
    assert abs(float(sp.limit(omega, t, sp.oo)) - float(V / K)) < 1e-12


# --- the example: a DC-motor hoist with a PI speed loop -------------------------------

EXAMPLE = Path(__file__).resolve().parents[1] / "examples" / "drive_trains" / "dc_hoist_pi.toml"
#: The example's values in SI: motor side (J_m, J_d, gear, rope end, radius, reeving),
#: rope, hook, armature, loop; read here from the file's text, not from the model.
JM, JD, GEAR, M_END, RADIUS, REEVING = 2.0, 200.0, 30.0, 50.0, 0.4, 2.0
C_ROPE, D_ROPE, M_HOOK, G = 2e6, 2e3, 1e4, 9.81
R_A, L_A, K_A, KP, KI, T_MAX = 0.1, 5e-3, 4.0, 20.0, 200.0, 1000.0
RHO = RADIUS / (GEAR * REEVING)                     # rope end per rad of the motor
J_RED = JM + JD / GEAR**2 + M_END * RHO**2
#: The steady start at speed 0: the current that holds the load, m g ρ / k, and
#: the integral that keeps it, R i = k_i z (L di/dt = 0 at ω = ω_ref = 0).
I_0 = M_HOOK * G * RHO / K_A
Z_0 = R_A * I_0 / KI


def reference(t: float) -> tuple[float, float]:
    """The speed reference and its rate: a ramp to 100 rad/s in 1 s."""
    return (100.0 * t, 100.0) if t < 1.0 else (100.0, 0.0)


def hoist_rhs(t: float, y: np.ndarray, mode: int) -> list[float]:
    """(θ, ω, x, v, i, z)' of the hoist: mode 0 free, 1 at the limit with z
    frozen, 2 at the limit with z keeping the loop's demand on the limit."""
    theta, omega, x, v, i, z = y
    rope = C_ROPE * (RHO * theta - x) + D_ROPE * (RHO * omega - v)
    domega = (K_A * i - RHO * rope) / J_RED
    ref, dref = reference(t)
    error = ref - omega
    di = (KP * error + KI * z - R_A * i - K_A * omega) / L_A
    if mode == 0:
        return [omega, domega, v, (rope - M_HOOK * G) / M_HOOK, di, error]
    dz = 0.0 if mode == 1 else ((KP + K_A) * domega - KP * dref) / KI
    return [omega, domega, v, (rope - M_HOOK * G) / M_HOOK, 0.0, dz]


def demand(t: float, y: np.ndarray) -> float:
    """r = L di/dt of the free loop."""
    return KP * (reference(t)[0] - y[1]) + KI * y[5] - R_A * y[4] - K_A * y[1]


def demand_rate(t: float, y: np.ndarray) -> float:
    """ṙ of the free loop where r = 0 (di/dt = 0 there)."""
    domega = hoist_rhs(t, y, 0)[1]
    ref, dref = reference(t)
    return KP * (dref - domega) + KI * (ref - y[1]) - K_A * domega


def hoist_reference(t_end: float, limited: bool) -> tuple[list[tuple[float, str]], object]:
    """solve_ivp (DOP853, rtol 1e-12) of the hoist from the load held still on
    the stretched rope by the current I_0 and the integral Z_0, with events for
    the limit's modes; (events, dense solution)."""
    from scipy.integrate import solve_ivp
    y = np.array([0.0, 0.0, -M_HOOK * G / C_ROPE, 0.0, I_0, Z_0])
    t, mode, events, pieces = 0.0, 0, [], []
    while t < t_end:
        stop = 1.0 if t < 1.0 else t_end
        crossing = {0: lambda s, q: q[4] - T_MAX / K_A, 1: demand, 2: demand_rate}[mode]

        def event(s, q, _mode, crossing=crossing):
            return crossing(s, q)
        event.terminal, event.direction = True, (1 if mode == 0 else -1)
        sol = solve_ivp(hoist_rhs, (t, stop), y, method="DOP853", rtol=1e-12, atol=1e-12,
                        args=(mode,), events=event if limited else None, dense_output=True)
        pieces.append((t, sol.t[-1], sol.sol))
        t, y = sol.t[-1], sol.y[:, -1].copy()
        if limited and sol.t_events[0].size:
            if mode == 0:
                mode, y[4] = 1, T_MAX / K_A
                events.append((t, "speed_loop limited +"))
            elif mode == 1:
                mode = 2 if demand_rate(t, y) > 0 else 0
                events.append((t, "speed_loop demand within"))
            else:
                mode = 0
                events.append((t, "speed_loop released"))
        elif t == 1.0:
            events.append((t, "speed_loop next piece"))

    def at(times):
        """The state at ``times``, from the piece that holds each."""
        return np.array([next(p[2](s) for p in pieces if p[0] <= s <= p[1]) for s in times])
    return events, at


def example_run(limited: bool):
    """The example file run, with or without its limit line."""
    from crane_sym.components.component_file import read_component_file
    text = EXAMPLE.read_text()
    if not limited:
        text = "\n".join(l for l in text.splitlines() if not l.startswith("limit ="))
    with tempfile.TemporaryDirectory() as folder:
        path = Path(folder) / "dc_hoist_pi.toml"
        path.write_text(text)
        model = read_component_file(str(path)).model
    return model.run(2.0)


def test_dc_hoist_without_its_limit_against_solve_ivp():
    """The loop unlimited: speed, current and rope force of the phases' closed
    forms against DOP853 at rtol 1e-12, to 1e-8 of their peaks."""
    run = example_run(limited=False)
    assert [e for _, e in run.events] == ["speed_loop next piece"]
    events, theirs = hoist_reference(2.0, limited=False)
    times = np.linspace(0.0, 2.0, 401)
    y = theirs(times)
    system = run.system
    ours = {"speed": state(run, system.v(0), times), "current": state(run, system.first, times),
            "rope": values(run.result, times, system.link_load(0))}
    rope = C_ROPE * (RHO * y[:, 0] - y[:, 2]) + D_ROPE * (RHO * y[:, 1] - y[:, 3])
    for name, mine, ref in (("speed", ours["speed"], y[:, 1]),
                            ("current", ours["current"], y[:, 4]), ("rope", ours["rope"], rope)):
        assert np.max(np.abs(mine - ref)) <= 1e-8 * np.max(np.abs(ref)), name


def test_dc_hoist_with_its_limit_against_solve_ivp_with_events():
    """The torque limit: each time the current reaches limit / k and each time
    the loop's demand falls back, against solve_ivp with events, to 1e-8 s;
    the current never past the limit."""
    run = example_run(limited=True)
    events, theirs = hoist_reference(2.0, limited=True)
    ours = run.events
    assert [e for _, e in ours] == [e for _, e in events]
    assert sum(e == "speed_loop limited +" for _, e in ours) == 2
    for (t1, _), (t2, _) in zip(ours, events):
        assert abs(t1 - t2) <= 1e-8
    times = np.linspace(0.0, 2.0, 2001)
    current = state(run, run.system.first, times)
    assert current.max() <= T_MAX / K_A * (1 + 1e-12)
    assert np.max(np.abs(current - theirs(times)[:, 4])) <= 1e-7 * T_MAX / K_A


def test_the_example_audits_the_motors_time_constant():
    """J R / k² against the quantity armature.time_constant: confirmed
    symbolically; J R / k (k for k²) a dimension error."""
    from crane_sym.components.file_audit import audit_file
    from crane_sym.components.quantities import derived_quantity
    from crane_sym.components.component_file import read_component_file
    read = read_component_file(str(EXAMPLE))
    right, slip = audit_file(read)
    assert (right.label, right.verdict, right.method) == ("tau_m", "confirmed", "symbolic")
    assert slip.verdict == "dimension_error"
    tau = derived_quantity(read.model, "armature.time_constant")
    assert tau.unit == "s"
    assert float(tau.expr.xreplace(read.model.equations.values)) == pytest.approx(J_RED * R_A / K_A**2, rel=1e-12)


def test_a_sweep_of_the_armature_is_the_run_of_each_design(tmp_path, capsys):
    """The rope's and the armature current's peaks over R and the torque limit,
    each design against the file's run with those values written in, to 1e-9."""
    import json
    xr = pytest.importorskip("xarray")
    from crane_sym.cli.main import main
    from crane_sym.components.component_file import read_component_file
    from crane_sym.components.report import part_peaks
    argv = ["sweep", str(EXAMPLE), "--vary", "armature.resistance=0.05:0.2:2",
            "--vary", "speed_loop.limit=800:1200:2", "--output", "rope.peak",
            "--output", "armature.current.peak",
            "--out", str(tmp_path / "out"), "--format", "json", "--quiet",
            "--scheduler", "synchronous"]
    assert main(argv) == 0
    stored = xr.open_zarr(json.loads(capsys.readouterr().out)["dataset"]).load()
    swept, current = stored["rope.peak"].values, stored["armature.current.peak"].values
    text = EXAMPLE.read_text()
    for i, r in enumerate((0.05, 0.2)):
        for j, cap in enumerate((800, 1200)):
            path = tmp_path / f"d{i}{j}.toml"
            path.write_text(text.replace('resistance = "0.1 ohm"', f'resistance = "{r} ohm"')
                            .replace('limit = "1000 N*m"', f'limit = "{cap} N*m"'))
            run = read_component_file(str(path)).model.run(2.0)
            assert abs(swept[i, j] - abs(run.peaks[0].value)) <= 1e-9 * abs(run.peaks[0].value)
            peak = part_peaks(run)[0]
            assert (peak.part, peak.what, peak.unit) == ("armature", "current", "A")
            assert abs(current[i, j] - abs(peak.value)) <= 1e-9 * abs(peak.value)


def test_the_walkthrough_shows_the_first_order_equations():
    from crane_sym.docs.drive_train import drive_train_walkthrough
    page = drive_train_walkthrough(EXAMPLE)
    assert "\\frac{d i_{\\mathrm{armature}}}{dt} = " in page
    assert "\\frac{d z_{\\mathrm{speed\\_loop}}}{dt} = " in page
    assert "speed_loop at + limit, integral frozen" in page
    assert "$x_{6} = i_{\\mathrm{armature}}$" in page


# --- the steady start: every first-order state at rest (components.steady) ------------

def _file_model(text: str):
    """The model of a component file's ``text``."""
    from crane_sym.components.component_file import read_component_file
    with tempfile.TemporaryDirectory() as folder:
        path = Path(folder) / "dc_hoist_pi.toml"
        path.write_text(text)
        return read_component_file(str(path)).model


def _still(run) -> np.ndarray:
    """|A x0 + b| of the start's mode in the rows of the accelerations and the
    first-order states' rates, each over the size of its terms |A| |x0| + |b|."""
    A, b = run.system.matrices(run.mode)
    s = run.system
    rows = [s.v(g) for g in range(s.n)] + list(range(s.first, s.size))
    size = np.abs(A) @ np.abs(run.x0) + np.abs(b)
    rate = A @ run.x0 + b
    return np.abs(rate[rows]) / np.where(size[rows] > 0, size[rows], 1.0)


def test_the_steady_start_solves_the_current_and_the_integral():
    """At speed 0 the current holds the load, i = m g ρ / k, and the integral
    keeps it, z = R i / k_i; the rope at its static stretch; every rate 0 to
    1e-12 of its terms."""
    run = example_run(limited=True)
    s = run.system
    assert run.x0[s.first] == pytest.approx(I_0, rel=1e-12)
    assert run.x0[s.first + 1] == pytest.approx(Z_0, rel=1e-12)
    assert run.x0[s.q(1)] == pytest.approx(-M_HOOK * G / C_ROPE, rel=1e-12)
    assert run.peaks[0].static == pytest.approx(M_HOOK * G, rel=1e-12)
    assert _still(run).max() <= 1e-12


def _peak(f, times: np.ndarray) -> float:
    """The largest |f| of a dense solution, the sampled largest refined."""
    from scipy.optimize import minimize_scalar
    k = int(np.argmax(np.abs(f(times))))
    lo, hi = times[max(k - 1, 0)], times[min(k + 1, len(times) - 1)]
    best = minimize_scalar(lambda t: -abs(f(np.array([t]))[0]), bounds=(lo, hi),
                           method="bounded", options={"xatol": 1e-12})
    return max(abs(f(np.array([best.x]))[0]), float(np.abs(f(times)).max()))


def test_the_started_hoist_s_peaks_against_solve_ivp():
    """From the solved start, the loop unlimited: the peaks of the rope's force,
    the current and the speed against solve_ivp (DOP853, rtol 1e-12) to 1e-9."""
    from crane_sym.components.report import part_peaks
    run = example_run(limited=False)
    _, theirs = hoist_reference(2.0, limited=False)
    times = np.linspace(0.0, 2.0, 4001)
    rope = lambda ts: (C_ROPE * (RHO * theirs(ts)[:, 0] - theirs(ts)[:, 2])
                       + D_ROPE * (RHO * theirs(ts)[:, 1] - theirs(ts)[:, 3]))
    ours = {p.what: abs(p.value) for p in part_peaks(run)}
    for name, mine, f in (("rope", abs(run.peaks[0].value), rope),
                          ("current", ours["current"], lambda ts: theirs(ts)[:, 4]),
                          ("speed", ours["speed"], lambda ts: theirs(ts)[:, 1])):
        ref = _peak(f, times)
        assert abs(mine - ref) <= 1e-9 * ref, (name, mine, ref)



def test_a_run_s_part_peaks_are_computed_once_for_its_lines_and_json(monkeypatch):
    """``crane-sym run`` finds the peaks of what the parts report once a run:
    the printed lines and the JSON read the same ``ComponentReport.parts``."""
    from crane_sym.components import report
    found = []
    original = report.part_peaks
    monkeypatch.setattr(report, "part_peaks", lambda run: found.append(run) or original(run))
    done = report.run_component_file(EXAMPLE, None)
    numbers = report.results(done)["results"]
    assert len(found) == 1 and found[0] is done.run
    assert [p.what for p in done.parts] == ["current", "torque", "speed"]
    for p in done.parts:
        assert numbers[f"{p.part}.{p.what}.peak"]["value"] == pytest.approx(p.value, rel=0)
        assert any(l.startswith(f"peak {p.what} of {p.part}: ") for l in done.lines)

def test_a_steady_start_at_speed_stays_steady():
    """Hoisting at 100 rad/s under a constant reference of 100 rad/s: the start
    solves z = (R i + k ω) / k_i; over 0.5 s speeds, current and integral stay
    put to 1e-12 and the hook rises at ρ ω."""
    text = (EXAMPLE.read_text().replace("coefficients = [[0.0, 100.0], [100.0]]",
                                        "coefficients = [[100.0], [100.0]]")
            .replace('speed = "0 rad/s"', 'speed = "100 rad/s"'))
    run = _file_model(text).run(0.5, start_body="motor", start_speed="100 rad/s")
    s = run.system
    assert run.x0[s.first + 1] == pytest.approx((R_A * I_0 + K_A * 100.0) / KI, rel=1e-12)
    assert _still(run).max() <= 1e-12
    times = np.linspace(0.0, 0.5, 51)
    for index, expected in ((s.v(0), 100.0), (s.v(1), RHO * 100.0), (s.first, I_0),
                            (s.first + 1, run.x0[s.first + 1])):
        assert np.max(np.abs(state(run, index, times) - expected)) <= 1e-12 * abs(expected)
    hook = state(run, s.q(1), times)
    assert np.max(np.abs(hook - (RHO * 100.0 * times - M_HOOK * G / C_ROPE))) <= 1e-12 * 50


def test_a_steady_start_the_limit_cannot_hold_is_refused():
    """A torque limit of 600 N·m under a load torque of 654 N·m: one line."""
    from crane_sym.components.parts import ComponentError
    model = _file_model(EXAMPLE.read_text().replace('limit = "1000 N*m"', 'limit = "600 N*m"'))
    with pytest.raises(ComponentError, match=r"^start: speed_loop's limit holds i_armature "
                       r"within ±150 A; the steady start needs 163\.5 A: the limit cannot "
                       r"hold the load$"):
        model.run(2.0)



def test_a_limited_state_s_unit_is_the_one_its_part_reports():
    """The refusal says a bound in the unit a part reports its state in (the
    current in A, not its torque in the load's unit); a state no part reports
    in a unit of its own is said in SI."""
    from types import SimpleNamespace
    from crane_sym.components.steady import _unit_of
    i, z = sp.symbols("i z")
    probe = SimpleNamespace(equations=SimpleNamespace(outputs=(
        ("m", "torque", "load", i), ("m", "current", "A", i))))
    assert (_unit_of(probe, i), _unit_of(probe, z)) == ("A", "(SI)")

def test_a_steady_start_that_cannot_rest_or_is_not_fixed_is_refused():
    """A reference of 10 rad/s at t = 0 against a start at speed 0: the
    integral cannot rest; a loop without integral (and limit): the current
    cannot; a 'steady' motor beside the armature: the load shared in any
    proportion. Each one line."""
    from crane_sym.components.parts import ComponentError
    moving = EXAMPLE.read_text().replace("coefficients = [[0.0, 100.0], [100.0]]",
                                         "coefficients = [[10.0, 90.0], [100.0]]")
    with pytest.raises(ComponentError, match=r"^start: z_speed_loop cannot rest at the steady "
                       r"start .*start = \"rest\"$"):
        _file_model(moving).run(2.0)
    proportional = "\n".join(line for line in EXAMPLE.read_text().replace(
        'integral = "200 V/rad"', 'integral = "0 V/rad"').splitlines()
        if not line.startswith("limit ="))
    with pytest.raises(ComponentError, match=r"^start: i_armature cannot rest at the steady "
                       r"start .*start = \"rest\"$"):
        _file_model(proportional).run(2.0)
    held = EXAMPLE.read_text().replace(
        "[[dc_motor]]", '[[motor]]\nname = "holding_brake"\nbody = "motor"\n'
        'torque = "steady"\n\n[[dc_motor]]')
    with pytest.raises(ComponentError, match=r"^start: the steady start does not fix the "
                       r"'steady' motor's torque and i_armature and z_speed_loop: "):
        _file_model(held).run(2.0)
