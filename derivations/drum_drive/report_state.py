"""``crane-sym run`` for a scene of paper 004 that asks for the state
derivative of (12) (e.g. ``drum_drive_undamped``): its own module, simulated.

The scene's module gives x' = f(W, x) and its Jacobian J, with the scene's
values (and switches) folded in. Under a constant load W on the run the
system is linear, x' = J x + f(W, 0), so its exact solution from rest is one
matrix exponential of the augmented matrix [[J, f0], [0, 0]]; the report
integrates the module with SciPy and states the gap to that solution, and
gives the natural frequencies (eigenvalues of J) with their largest relative
real part, 0 to rounding when the damping is switched off.
"""
from __future__ import annotations

from crane_sym.scenes.reading import Panel, SceneReport
from crane_sym.scenes.reading import format_quantity as fq

from .model import COORDS


def state_report(scene, module) -> SceneReport:
    """Simulation of the scene's ``state_derivative`` under a constant load.

    ``[options] W`` (a force with unit, default "1 kN") is the load on the run;
    the state starts at rest, x(0) = 0.
    """
    import numpy as np
    from scipy.integrate import solve_ivp
    from scipy.linalg import expm

    load = scene.settings["W"]           # read and checked on load (options.py)
    n = 2 * len(COORDS)
    jac = np.asarray(module.state_jacobian(), dtype=float).reshape(n, n)
    f0 = np.asarray(module.state_derivative(load, *np.zeros(n)), dtype=float).ravel()

    def rhs(_t, x):
        return np.asarray(module.state_derivative(load, *x), dtype=float).ravel()

    duration, times = scene.settings["duration"], scene.times()
    sol = solve_ivp(rhs, (0.0, duration), np.zeros(n), method="DOP853", t_eval=times,
                    rtol=1e-11, atol=1e-14)
    if not sol.success:
        raise RuntimeError(f"solve_ivp failed: {sol.message}")
    augmented = np.zeros((n + 1, n + 1))
    augmented[:n, :n], augmented[:n, n] = jac, f0
    exact = np.array([expm(augmented * t)[:n, n] for t in times]).T
    gap = float(np.max(np.abs(sol.y - exact)) / max(np.max(np.abs(exact)), 1e-300))

    lam = np.linalg.eigvals(jac)
    # the rigid motion of the run is a double zero eigenvalue, which rounding
    # splits into ±sqrt(eps)·|J|: not a vibration
    moving = lam[np.abs(lam) > 1e-6 * np.max(np.abs(lam))]
    freqs = np.sort(np.abs(moving.imag[moving.imag > 0])) / (2 * np.pi)
    real_ratio = float(np.max(np.abs(moving.real) / np.abs(moving)))
    y, z_dot = exact[3], exact[9]                         # y and dz/dt of (12)
    values = {**{f"f_{i}": float(f) for i, f in enumerate(freqs, 1)},
              "max_real_over_abs": real_ratio, "y_max": float(np.max(np.abs(y))),
              "v_end": float(z_dot[-1]), "integrator_gap": gap}
    lines = [f"load on the run      W = {fq(load / 1e3, 'kN')} (constant), from rest",
             f"natural frequencies  {', '.join(fq(f, 'Hz') for f in freqs)} "
             f"(eigenvalues of the scene's state_jacobian)",
             f"damping              max |Re λ|/|λ| = {real_ratio:.1e}"
             + (" (switched off)" if "damping" in scene.switched_off else ""),
             f"drum-shaft deflection max |y| = {fq(values['y_max'] * 1e3, 'mm')}",
             f"speed of the run     {fq(values['v_end'], 'm/s')} at {fq(duration, 's')}",
             f"DOP853 (rtol 1e-11) against the matrix exponential: {gap:.1e} of the "
             "largest state"]
    panels = _displacement_panels(augmented, n, times, y) + [
        Panel("Speed of the run", r"$\dot z$ [m/s]", [(r"$\dot z(t)$", times, z_dot)])]
    return SceneReport(lines=lines, values=values, panels=panels)


def _displacement_panels(augmented, n: int, times, y) -> list:
    """y(t) over a window of about eight of its periods, where each swing shows
    (a 25 Hz response over 10 s is a solid block at page width), then its
    envelope over the whole run; both from the exact solution on a fine grid."""
    import numpy as np
    from scipy.linalg import expm

    from crane_sym.scenes.reading import Panel

    duration = float(times[-1])
    centred = y - y.mean()
    crossings = np.count_nonzero(np.diff(np.sign(centred)) != 0)
    if crossings < 40:                               # slow enough to read as it is
        return [Panel("Drum-shaft displacement", "$y$ [mm]", [("$y(t)$", times, y * 1e3)])]
    period = 2 * duration / crossings
    step = expm(augmented * period / 40)             # 40 points a period, exactly
    count = min(int(duration / period * 40) + 1, 40_001)
    state = np.zeros(n + 1)
    state[n] = 1.0
    fine = np.empty(count)
    for k in range(count):
        fine[k] = state[3]
        state = step @ state
    t_fine = np.arange(count) * period / 40
    window = t_fine <= 8 * period
    blocks = fine[: count // 40 * 40].reshape(-1, 40)
    t_block = t_fine[: count // 40 * 40].reshape(-1, 40)[:, 20]
    return [Panel(f"Drum-shaft displacement, the first {8 * period:.2g} s "
                  f"(about {1 / period:.3g} Hz)", "$y$ [mm]",
                  [("$y(t)$", t_fine[window], fine[window] * 1e3)]),
            Panel(f"Drum-shaft displacement over {duration:g} s: envelope "
                  "(largest and least per period)", "$y$ [mm]",
                  [("largest", t_block, blocks.max(axis=1) * 1e3),
                   ("least", t_block, blocks.min(axis=1) * 1e3)])]
