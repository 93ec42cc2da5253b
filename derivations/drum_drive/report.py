"""What ``crane-sym run`` prints and plots for a scene of paper 004.

A scene that asks for ``pulsating_force`` is the example of the paper
(Fig. 3): simulated with the consistent model through the generated state
derivative, Jacobian and system matrices of (12), under the load of the
scene's own module. A scene that asks for ``state_derivative`` is simulated
with its own module alone (``report_state``). ``REPORTS`` holds the two kinds.
"""
from __future__ import annotations

import sympy as sp

from crane_sym.derivation import Derivation
from crane_sym.scenes.kinds import SceneKind, report_for

from .model import COORDS, STATE
from .options import SIM_OPTIONS
from .report_state import state_report

#: The unit of each number of the reports (this one's and ``report_state``'s;
#: SI, ``"1"`` for a ratio), for ``crane-sym run --format json`` (``fnmatch``
#: patterns, the first that matches).
VALUE_UNITS = {"omega_*": "rad/s", "f_*": "Hz", "y_*": "m", "running_y": "m", "rest_y": "m",
               "t_valid_end": "s", "run_time": "s", "F1_*": "N", "F2_*": "N",
               "running_F*": "N", "v_end": "m/s", "running_speed": "m/s", "margin_min": "1",
               "design_margin": "1", "least_mu_alpha": "1", "drum_torque": "N*m",
               "energy_error": "1", "max_real_over_abs": "1", "integrator_gap": "1"}


def argument_orders(generated) -> dict[str, list[str]]:
    """Function name -> argument names, read from the generated module's
    signatures (the keyword-only ``out`` left off): no build needed."""
    import inspect
    return {name: [p.name for p in inspect.signature(getattr(generated, name)).parameters
                   .values() if p.kind is p.POSITIONAL_OR_KEYWORD]
            for name in generated.__all__}


def _rhs_functions(d: Derivation):
    """:func:`rhs_functions` of the derivation's generated module."""
    import importlib
    return rhs_functions(importlib.import_module(f"crane_sym.generated.{d.id}"))


def rhs_functions(generated):
    """Right-hand side, Jacobian and energy of (12) from the generated module.

    The state is (q, q̇, E_in, E_d): q̇ and q̈ come from the generated
    ``state_derivative``; E_in = ∫F·q̇ dt is the work of the given forces and
    E_d = ∫q̇·C·q̇ dt = ∫2Φ dt the dissipated energy.

    Returns
    -------
    make(values, load) -> (rhs, jac, energy, matrices)
        ``values``: SI values by symbol name; ``load``: W as a function of t.
    """
    import numpy as np

    order = argument_orders(generated)
    n = len(COORDS)

    def make(values: dict, load):
        def call(name: str, **more) -> np.ndarray:
            given = {**values, **more}
            return getattr(generated, name)(*[given[a] for a in order[name]])

        Mn, Cn, Kn = (call(name) for name in ("mass_matrix", "damping_matrix",
                                             "stiffness_matrix"))
        Jn = call("state_jacobian")
        # The model is linear: f(x, W) = J·x + f0 + W·fW and F(W) = F0 + W·FW, all
        # taken from the generated functions once per parameter set.
        rest = {str(s_): 0.0 for s_ in STATE}
        f0 = call("state_derivative", W=0.0, **rest).ravel()
        fW = call("state_derivative", W=1.0, **rest).ravel() - f0
        F0n = call("generalized_forces", W=0.0).ravel()
        FWn = call("generalized_forces", W=1.0).ravel() - F0n

        def force(tt):
            return F0n + load(tt) * FWn

        def rhs(tt, x):
            dx = np.empty(2 * n + 2)
            dx[:2 * n] = Jn @ x[:2 * n] + f0 + load(tt) * fW
            v = x[n:2 * n]
            dx[2 * n], dx[2 * n + 1] = force(tt) @ v, v @ Cn @ v
            return dx

        def jac(tt, x):
            J = np.zeros((2 * n + 2, 2 * n + 2))
            J[:2 * n, :2 * n] = Jn
            J[2 * n, n:2 * n], J[2 * n + 1, n:2 * n] = force(tt), 2 * Cn @ x[n:2 * n]
            return J

        def energy(x):
            qq, v = x[:n], x[n:2 * n]
            return 0.5 * np.einsum("i...,ij,j...->...", v, Mn, v) + \
                0.5 * np.einsum("i...,ij,j...->...", qq, Kn, qq)

        return rhs, jac, energy, (Mn, Cn, Kn)

    return make


def example_report(scene, module):
    """Simulate the example of the paper (Fig. 3) with the consistent model.

    Parameters
    ----------
    scene : crane_sym.scenes.reading.Scene
        SI parameters of the outputs; settings (``options.SCENE_OPTIONS``, SI)
        ``duration``, ``points``, the simulation-only values ``SIM_OPTIONS``,
        ``m_L_empty`` (mass of the run without loads) and ``method`` of
        ``solve_ivp``.
    module : module
        The scene's generated module: its ``pulsating_force(t)`` is the load W(t)
        of (21) on the run.

    Returns
    -------
    crane_sym.scenes.reading.SceneReport
        ``values`` (SI): ``omega_1``, ``omega_2`` (chain), ``f_loaded_i``,
        ``f_empty_i`` (model frequencies, Hz), ``y_max``, ``y_swing`` (after 1 s),
        ``F1_max``, ``F2_min``, ``v_end``, ``margin_min``, ``running_*``,
        ``rest_y``, ``design_margin``, ``least_mu_alpha``, ``drum_torque``,
        ``energy_error``, ``run_time``; panels: drum-shaft displacement (Fig. 3),
        branch forces, load, speed.
    """
    import time as clock

    import numpy as np
    from scipy.integrate import solve_ivp

    from crane_sym import registry
    from crane_sym.scenes.panels import outside
    from crane_sym.scenes.reading import Panel, SceneReport, format_quantity as fq

    d = registry.get(scene.derivation)
    p, o = dict(scene.parameters), scene.settings
    p.update({n: o[n] for n in SIM_OPTIONS}, r=p["D"] / 2)
    empty = o["m_L_empty"]

    def ev(expr, **at):
        args = sorted(expr.free_symbols, key=str)
        return sp.lambdify(args, expr, "numpy")(*[({**p, **at})[str(a)] for a in args])

    load = module.pulsating_force                  # W(t) of (21), the scene's own module
    make = _rhs_functions(d)
    rhs, jac, energy, (Mn, _, Kn) = make(p, load)

    def hertz(M):
        lam = np.sort(np.linalg.eigvals(np.linalg.solve(M, Kn)).real)
        return np.sqrt(lam[lam > 1e-9 * lam.max()]) / (2 * np.pi)

    f_loaded, f_empty = hertz(Mn), hertz(make({**p, "m_L": empty}, load)[3][0])
    duration, method = o["duration"], o["method"]
    times = scene.times()
    implicit = {"jac": jac} if method in ("LSODA", "Radau", "BDF") else {}
    start = clock.perf_counter()
    sol = solve_ivp(rhs, (0.0, duration), np.zeros(12), method=method, t_eval=times,
                    rtol=1e-10, atol=1e-12, **implicit)
    run_time = clock.perf_counter() - start
    if not sol.success:
        raise RuntimeError(f"solve_ivp failed: {sol.message}")
    x = sol.y
    F1_sim = p["F0"] + p["C_t"] * (p["r"] * x[2] - x[3] - x[4])
    F2_sim = p["F0"] + p["C_z"] * (x[4] - x[3] - p["r"] * x[2])
    # The model holds while both branches pull (F2 > 0) and the element grips the
    # drum (Euler: F1 <= F2 e^(μα)); the peaks below are taken where it holds.
    slack, slip = F2_sim <= 0, F1_sim > F2_sim * np.exp(p["mu"] * p["alpha"])
    broken = np.flatnonzero(slack | slip)
    t_valid = float(times[broken[0]]) if broken.size else duration
    why = ("" if not broken.size else "the slack branch goes slack (F2 <= 0)"
           if slack[broken[0]] else "the element slips on the drum (F1 > F2 e^(μα))")
    invalid = outside(0.0, t_valid, after=rf"model not valid ($t \geq {t_valid:.4g}$ s): "
                      + ("branch slack" if "F2 <=" in why else "element slips")) \
        if broken.size else []
    ok = times < t_valid if broken.size else np.ones(times.shape, dtype=bool)
    W_mean = float(np.mean(load(np.linspace(0, 2 * p["t_3"], 2001)[:-1])))
    v = {"omega_1": ev(d.output("drive_chain_frequency_1").expr),
         "omega_2": ev(d.output("drive_chain_frequency_2").expr),
         **{f"f_loaded_{i}": f for i, f in enumerate(f_loaded, 1)},
         **{f"f_empty_{i}": f for i, f in enumerate(f_empty, 1)},
         "y_max": np.max(np.abs(x[3][ok]), initial=0.0),
         "y_swing": np.ptp(x[3][times > 1.0]), "t_valid_end": t_valid,
         "F1_max": F1_sim[ok].max(initial=-np.inf),
         "F2_min": F2_sim[ok].min(initial=np.inf), "v_end": x[9][-1],
         "margin_min": np.min(np.exp(p["mu"] * p["alpha"]) - 1.25 * F1_sim / F2_sim),
         **{f"running_{k}": ev(d.output(n).expr) for k, n in (
             ("F1", "running_tight_force"), ("F2", "running_slack_force"),
             ("y", "running_drum_shaft_deflection"))},
         "running_speed": ev(d.step("steady running").statement.rhs, W=W_mean),
         "rest_y": ev(d.step("initial state").statement.rhs),
         "design_margin": ev(d.output("traction_margin").expr),
         "least_mu_alpha": ev(d.output("least_mu_alpha").expr),
         "drum_torque": ev(d.output("drum_torque").expr),
         "energy_error": np.max(np.abs(x[10] - x[11] - energy(x[:10])))
         / max(np.max(np.abs(x[10])), 1e-300), "run_time": run_time}
    v = {k: float(val) for k, val in v.items()}
    hz = lambda fs: ", ".join(fq(f, "Hz") for f in fs)  # noqa: E731
    mm, kn = (lambda a: fq(a * 1e3, "mm")), (lambda a: fq(a / 1e3, "kN"))  # noqa: E731
    lines = [
        f"drive chain (free-free)  ω1 = {fq(v['omega_1'], 'rad/s')}, "
        f"ω2 = {fq(v['omega_2'], 'rad/s')}",
        f"model frequencies        loaded run ({fq(p['m_L'], 'kg')}): {hz(f_loaded)}",
        f"                         empty run ({fq(empty, 'kg')}): {hz(f_empty)}",
        f"drum-shaft displacement  max |y| = {mm(v['y_max'])} "
        f"({'within' if v['y_max'] <= 0.010 else 'NOT within'} the paper's 10 mm); "
        f"swing after 1 s {mm(v['y_swing'])}",
        f"                         at rest under 2·F0 {mm(v['rest_y'])}; steady running "
        f"{mm(v['running_y'])}",
        f"branch forces            F1 max {kn(v['F1_max'])}, F2 min {kn(v['F2_min'])}; "
        f"running {kn(v['running_F1'])} / {kn(v['running_F2'])}",
        f"traction (19)            margin at the scene's F1, F2 {fq(v['design_margin'])}, "
        f"least along the run {fq(v['margin_min'])}; least μα {fq(v['least_mu_alpha'])}",
        f"run speed                {fq(v['v_end'], 'm/s')} at {fq(duration, 's')}; "
        f"steady (mean load) {fq(v['running_speed'], 'm/s')}",
        f"energy balance           max |work − dissipation − (T + Π)| / work = "
        f"{v['energy_error']:.1e}",
        f"solve_ivp ({method})      {fq(run_time, 's')} for {fq(duration, 's')}",
        "paper, Fig. 3            'frequency rises as the load falls': the load force W(t) "
        "does not change the linear model's frequencies; a lighter run (fewer loads) "
        "raises the lowest one, as listed above",
    ]
    if invalid:
        lines.append(f"warning: at t = {fq(t_valid, 's')} {why}, which the model does "
                     "not cover; the plots grey what follows, max |y| and the branch "
                     "forces are taken before it")
    panels = [
        Panel("Drum-shaft displacement (Fig. 3)", "$y$ [mm]", [("$y(t)$", times, x[3] * 1e3)],
              invalid=invalid),
        Panel("Branch forces", "$F$ [kN]", [("$F_1$ (tight)", times, F1_sim / 1e3),
                                            ("$F_2$ (slack)", times, F2_sim / 1e3)],
              invalid=invalid),
        Panel("Load on the run, (21)", "$W$ [kN]",
              [("$W(t) = F'(t)$", times, load(times) / 1e3)]),
        Panel("Speed of the run", r"$\dot z$ [m/s]", [(r"$\dot z(t)$", times, x[9])],
              invalid=invalid),
    ]
    return SceneReport(lines=lines, values=v, panels=panels)


#: The kinds of scene of paper 004: the paper's example (Fig. 3), marked by
#: ``pulsating_force``, else a simulation of the scene's own state derivative.
REPORTS = (SceneKind("the example of the paper (Fig. 3)", example_report,
                     outputs=("pulsating_force",)),
           SceneKind("the scene's own state derivative", state_report))


def scene_report(scene, module):
    """Numbers and curves of a scene of paper 004: the report of its kind
    (``REPORTS``): the example of the paper (Fig. 3) when the scene asks for
    ``pulsating_force``, else the simulation of the scene's own state
    derivative (``report_state.state_report``)."""
    return report_for(REPORTS, scene, module)
