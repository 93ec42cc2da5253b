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
    """solve_ivp (DOP853, rtol 1e-12) of the hoist from the load held on the
    stretched rope, with events for the limit's modes; (events, dense solution)."""
    from scipy.integrate import solve_ivp
    y = np.array([0.0, 0.0, -M_HOOK * G / C_ROPE, 0.0, 0.0, 0.0])
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
    assert [e for _, e in run.events] == ["holding_brake off", "speed_loop next piece"]
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
    ours = [(t, e) for t, e in run.events if e != "holding_brake off"]
    assert [e for _, e in ours] == [e for _, e in events]
    assert sum(e == "speed_loop limited +" for _, e in ours) == 3
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
