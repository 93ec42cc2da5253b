"""A span's force as an output: derived from its own energies
(``components.coupling_loads``: ∂Π/∂u + ∂Φ/∂u̇), reported by ``run`` and
``run --format json``, swept (batched) as ``<span>.force.peak`` and named by
a [[formula]] as ``<span>.force_peak``; checked against a two-mass closed form
and against paper 004's (12) integrated by solve_ivp."""
from __future__ import annotations

import json

import numpy as np
import pytest
import sympy as sp

from crane_sym.components import Mass, Model, Motor
from crane_sym.components.kinds.span import Span
from crane_sym.components.report import part_peaks
from crane_sym.mechanics.phase_table import values

from test_components_laws import generated
from test_components_spans import DRUM, FILE

#: Two masses joined by a massless span, a constant force on the first from rest.
M1, M2, C, P = 10.0, 30.0, 1e4, 50.0
TWO = f'''[model]
name = "two_masses"

[[mass]]
name = "a"
mass = "{M1} kg"

[[mass]]
name = "b"
mass = "{M2} kg"

[[span]]
name = "rope"
start = {{ a = 1 }}
end = {{ b = 1 }}
stiffness = "{C} N/m"

[[motor]]
name = "push"
body = "a"
force = "{P} N"

[run]
duration = "0.5 s"
start = "rest"

[[formula]]
name = "twice the static share"
latex = "F = -\\\\frac{{2 P m_2}}{{m_1 + m_2}}"
symbols = {{ P = "push.force", m_1 = "a.mass", m_2 = "b.mass" }}
quantity = "rope.force_peak"

[[formula]]
name = "once"
latex = "F = -\\\\frac{{P m_2}}{{m_1 + m_2}}"
symbols = {{ P = "push.force", m_1 = "a.mass", m_2 = "b.mass" }}
quantity = "rope.force_peak"
'''


def test_a_span_s_force_is_derived_from_its_energies():
    """F = ∂Π/∂u + ∂Φ/∂u̇ of the span's own share: c u + d u̇, u = x_B − x_A."""
    model = Model([Mass("a", 1.0), Mass("b", 2.0), Span("rope", {"a": 1}, {"b": 1}, 1e4, 5.0, 3.0)])
    eq = model.equations
    (part, what, unit, force), = eq.outputs
    xa, xb = eq.coordinates
    c, d = (sp.Symbol(f"{k}_rope", **{"positive" if k == "c" else "nonnegative": True})
            for k in "cd")
    assert (part, what, unit) == ("rope", "force", "N")
    assert sp.expand(force - (c * (xb - xa) + d * (xb - xa).diff(eq.t))) == 0


def test_a_two_mass_span_s_peak_is_its_closed_form(tmp_path, capsys):
    """A force P on m1 from rest: the span's force −P m2/(m1+m2) (1 − cos ωt),
    its peak −2 P m2/(m1+m2) at π/ω; printed by run, in its JSON, and
    the [[formula]] naming rope.force_peak confirmed (the half refuted)."""
    from crane_sym.cli.main import main
    from crane_sym.components.file_audit import audit_file
    from crane_sym.components.component_file import read_component_file
    path = tmp_path / "two.toml"
    path.write_text(TWO)
    read = read_component_file(str(path))
    run = read.model.run(0.5, rest=True)
    peak, = part_peaks(run)
    omega = np.sqrt(C * (1 / M1 + 1 / M2))
    closed = -2 * P * M2 / (M1 + M2)
    assert (peak.part, peak.what, peak.unit) == ("rope", "force", "N")
    assert abs(peak.value - closed) <= 1e-12 * abs(closed)
    assert abs(peak.time - np.pi / omega) <= 1e-9
    times = np.linspace(0.0, 0.5, 201)
    w = run.system.first_order.weights(run.model.equations.outputs[0][3])
    curve = values(run.result, times, lambda mode: (w, 0.0))
    theirs = -P * M2 / (M1 + M2) * (1 - np.cos(omega * times))
    assert np.max(np.abs(curve - theirs)) <= 1e-12 * abs(closed)
    right, half = audit_file(read)
    assert (right.verdict, half.verdict) == ("confirmed", "discrepancy")
    from crane_sym.components.parts import ComponentError
    from crane_sym.components.quantities import derived_quantity
    with pytest.raises(ComponentError, match=r"^quantity 'rope\.torque_peak': no part 'rope' "
                       r"reports a torque$"):
        derived_quantity(read.model, "rope.torque_peak", run)
    assert main(["run", str(path), "--out", str(tmp_path / "out"), "--format", "json",
                 "-q"]) == 0
    found = json.loads(capsys.readouterr().out)["results"]
    assert found["rope.force.peak"]["unit"] == "N"
    assert abs(found["rope.force.peak"]["value"] - closed) <= 1e-12 * abs(closed)
    assert main(["run", str(path), "--out", str(tmp_path / "text")]) == 0
    assert "peak force of rope: -75.00 N at t = 0.08604 s" in capsys.readouterr().out



def test_a_model_of_spans_only_draws_their_forces(tmp_path):
    """The two masses, joined by a span and no elastic link, write
    ``two_masses_loads.png``: one panel, the span's force in N along its closed
    form −P m2/(m1+m2) (1 − cos ωt) to 1e-12; the shaft's torque in N·m."""
    from crane_sym.cli.main import main
    from crane_sym.components.component_file import read_component_file
    from crane_sym.components.report import load_figures
    path = tmp_path / "two.toml"
    path.write_text(TWO)
    assert main(["run", str(path), "--out", str(tmp_path / "out"), "-q"]) == 0
    assert (tmp_path / "out" / "two_masses_loads.png").stat().st_size > 0
    run = read_component_file(str(path)).model.run(0.5, rest=True)
    fig, = load_figures(run, "two masses")
    ax, = fig.get_axes()
    line, = ax.get_lines()
    assert (ax.get_ylabel(), ax.get_xlabel()) == ("force [N]", "time [s]")
    omega = np.sqrt(C * (1 / M1 + 1 / M2))
    times, drawn = line.get_xdata(), line.get_ydata()
    theirs = -P * M2 / (M1 + M2) * (1 - np.cos(omega * times))
    assert times[-1] == 0.5 and np.max(np.abs(drawn - theirs)) <= 1e-12 * P
    path.write_text(SHAFT)
    run = read_component_file(str(path)).model.run(0.3, rest=True)
    fig, = load_figures(run, "two inertias")
    assert [ax.get_ylabel() for ax in fig.get_axes()] == ["torque [N·m]"]

def _peak_of(curve) -> float:
    """The largest |value| of a dense solution's curve, refined around its sample."""
    from scipy.optimize import minimize_scalar
    times = np.linspace(0.0, 0.4, 8001)
    k = int(np.argmax(np.abs(curve(times))))
    best = minimize_scalar(lambda t: -abs(curve(t)), bounds=(times[max(k - 1, 0)],
                           times[min(k + 1, len(times) - 1)]), method="bounded",
                           options={"xatol": 1e-13})
    return max(abs(curve(best.x)), float(np.max(np.abs(curve(times)))))


def test_the_drum_drive_s_span_forces_peak_as_004s_12():
    """The drum drive's three spans (the shaft's bending C_y y + ν_y ẏ, the
    tight branch C_t e1, the slack one C_z e2 + ν_z ė2, e1 = r φ3 − y − z,
    e2 = z − r φ3 − y) at their peaks against (12) integrated by DOP853 at
    rtol 1e-12 with the derivation's generated right-hand side, to 1e-9."""
    from scipy.integrate import solve_ivp
    from crane_sym.components.component_file import read_component_file
    module = generated("drum_drive")
    v = DRUM
    args = [v[k] for k in ("I1", "I2", "I3", "C1", "C2", "nu1", "nu2", "m3", "m_L", "C_y",
                           "nu_y", "C_t", "C_z", "nu_z", "nu_t", "q", "L", "r", "M0", "F0", "W")]
    sol = solve_ivp(lambda _, s: np.ravel(module.state_derivative(*args, *s)), (0.0, 0.4),
                    [0.0] * 10, method="DOP853", rtol=1e-12, atol=1e-15, dense_output=True)

    def branch(name):
        def curve(t):
            phi1, phi2, phi3, y, z, w1, w2, w3, dy, dz = sol.sol(t)
            e1, e2 = v["r"] * phi3 - y - z, z - v["r"] * phi3 - y
            de2 = dz - v["r"] * w3 - dy
            return {"bending": v["C_y"] * y + v["nu_y"] * dy, "tight": v["C_t"] * e1,
                    "slack": v["C_z"] * e2 + v["nu_z"] * de2}[name]
        return curve
    read = read_component_file(FILE)
    run = read.model.run(read.duration, rest=read.rest)
    ours = {p.part: p.value for p in part_peaks(run) if p.what == "force"}
    assert list(ours) == ["bending", "tight", "slack"]
    for name, mine in ours.items():
        theirs = _peak_of(branch(name))
        assert abs(abs(mine) - theirs) <= 1e-9 * theirs, (name, mine, theirs)


def test_a_sweep_of_a_span_s_force_is_each_design_s_run(tmp_path, capsys):
    """tight.force.peak over the drive's torque, batched: each design
    against the file's run with that value written in, to 1e-9."""
    xr = pytest.importorskip("xarray")
    from crane_sym.cli.main import main
    from crane_sym.components.component_file import read_component_file
    argv = ["sweep", str(FILE), "--vary", "drive.torque=400:480:2", "--output",
            "tight.force.peak", "--out", str(tmp_path / "out"), "--format", "json",
            "--quiet", "--scheduler", "synchronous"]
    assert main(argv) == 0
    stored = xr.open_zarr(json.loads(capsys.readouterr().out)["dataset"]).load()
    swept = stored["tight.force.peak"].values
    assert stored["tight.force.peak"].attrs.get("units", "N") == "N"
    text = FILE.read_text()
    for i, torque in enumerate((400, 480)):
        path = tmp_path / f"d{i}.toml"
        path.write_text(text.replace('torque = "440 N*m"', f'torque = "{torque} N*m"'))
        read = read_component_file(str(path))
        run = read.model.run(read.duration, rest=read.rest)
        peak = next(p for p in part_peaks(run) if p.part == "tight")
        assert abs(swept[i] - abs(peak.value)) <= 1e-9 * abs(peak.value)


# --- a span of angles: a twisting shaft with an inertia of its own -------------------

#: Two inertias [kg m²] joined by a shaft of stiffness C_T [N m/rad] and own inertia J_S
#: [kg m²], a constant torque T_D [N m] on the first from rest.
J1, J2, J_S, C_T, T_D = 2.0, 3.0, 0.6, 1e4, 10.0
SHAFT = f'''[model]
name = "two_inertias"

[[inertia]]
name = "a"
inertia = "{J1} kg*m^2"

[[inertia]]
name = "b"
inertia = "{J2} kg*m^2"

[[span]]
name = "shaft"
start = {{ a = 1 }}
end = {{ b = 1 }}
stiffness = "{C_T} N*m/rad"
damping = "0 N*m*s/rad"
mass = "{J_S} kg*m^2"

[[motor]]
name = "drive"
body = "a"
torque = "{T_D} N*m"

[run]
duration = "0.3 s"
start = "rest"

[[formula]]
name = "twice the far side's share"
latex = "M = -\\\\frac{{2 T (J_2 + J_s/2)}}{{J_1 + J_2 + J_s}}"
symbols = {{ T = "drive.torque", J_1 = "a.inertia", J_2 = "b.inertia", J_s = "shaft.mass" }}
quantity = "shaft.torque_peak"
'''


def test_a_span_of_angles_between_two_inertias_is_its_closed_form(tmp_path, capsys):
    """M = [[J1 + J/3, J/6], [J/6, J2 + J/3]]; the elastic mode's ω² =
    c (J1 + J2 + J) / det M; from rest under a torque T on the first, the
    shaft's torque is c u = −T (J2 + J/2)/(J1 + J2 + J) (1 − cos ωt) (the
    uniformly accelerated twist, reached through the elastic mode alone):
    along the run to 1e-12, its peak printed in N·m, and the [[formula]] on
    shaft.torque_peak confirmed."""
    from crane_sym.cli.main import main
    from crane_sym.components.file_audit import audit_file
    from crane_sym.components.component_file import read_component_file
    path = tmp_path / "shaft.toml"
    path.write_text(SHAFT)
    read = read_component_file(str(path))
    span, = read.model.assembly.couplings
    assert span.motion == "rotating"
    M = read.model.equations.numeric()([], [], [1.0], [])[0]
    np.testing.assert_allclose(M, [[J1 + J_S / 3, J_S / 6], [J_S / 6, J2 + J_S / 3]], rtol=1e-15)
    run = read.model.run(0.3, rest=True)
    omega = np.sqrt(C_T * (J1 + J2 + J_S) / np.linalg.det(M))
    static = -T_D * (J2 + J_S / 2) / (J1 + J2 + J_S)
    times = np.linspace(0.0, 0.3, 301)
    w = run.system.first_order.weights(run.model.equations.outputs[0][3])
    curve = values(run.result, times, lambda mode: (w, 0.0))
    assert np.max(np.abs(curve - static * (1 - np.cos(omega * times)))) <= 1e-12 * abs(static)
    peak, = part_peaks(run)
    assert (peak.what, peak.unit) == ("torque", "N*m")
    assert abs(peak.value - 2 * static) <= 1e-12 * abs(2 * static)
    assert abs(peak.time - np.pi / omega) <= 1e-9
    formula, = audit_file(read)
    assert formula.verdict == "confirmed"
    assert main(["run", str(path), "--out", str(tmp_path / "out")]) == 0
    assert f"peak torque of shaft: {2 * static:.2f} N·m" in capsys.readouterr().out.replace(
        "N*m", "N·m")


def test_a_span_of_angles_refuses_a_value_of_a_length(tmp_path):
    """Its damping in N·s/m, its own mass in kg: one line each."""
    from crane_sym.components.parts import ComponentError
    from crane_sym.components.component_file import read_component_file
    for old, new, line in (('damping = "0 N*m*s/rad"', 'damping = "1 N*s/m"',
                            r"span 'shaft': damping '1 N\*s/m' is mass/time, expected "),
                           (f'mass = "{J_S} kg*m^2"', 'mass = "0.6 kg"',
                            r"span 'shaft': mass '0\.6 kg' is mass, expected ")):
        path = tmp_path / "bad.toml"
        path.write_text(SHAFT.replace(old, new))
        with pytest.raises(ComponentError, match=line):
            read_component_file(str(path))


def test_a_sweep_of_a_span_of_angles_is_its_closed_form(tmp_path, capsys):
    """shaft.torque.peak over its stiffness (N·m/rad) and own inertia (kg·m²),
    batched: 2 T (J2 + J/2)/(J1 + J2 + J) at every design, to 1e-12."""
    xr = pytest.importorskip("xarray")
    from crane_sym.cli.main import main
    path = tmp_path / "shaft.toml"
    path.write_text(SHAFT)
    argv = ["sweep", str(path), "--vary", "shaft.stiffness=1e4:2e4:2", "--vary",
            "shaft.mass=0.3:0.6:2", "--output", "shaft.torque.peak", "--out",
            str(tmp_path / "out"), "--format", "json", "--quiet", "--scheduler", "synchronous"]
    assert main(argv) == 0
    swept = xr.open_zarr(json.loads(capsys.readouterr().out)["dataset"]).load()
    for j, inertia in enumerate((0.3, 0.6)):
        closed = 2 * T_D * (J2 + inertia / 2) / (J1 + J2 + inertia)
        column = swept["shaft.torque.peak"].values[:, j]
        assert np.max(np.abs(column - closed)) <= 1e-12 * closed
