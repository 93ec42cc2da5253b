"""What ``crane-sym run`` prints and plots for a scene of paper 001: the paper's
Figs 5, 8, 9, 11 and 12 for the scene's hoist.

Curves of the rigid drive come from the scene's own generated module, the
factor sweeps from the general module ``crane_sym.generated.hoist_brakes``,
Fig. 9 from the piecewise closed forms of ``hybrid.EMERGENCY_STOP`` (the
scene's payload tabulated in its module, the hook alone solved here); never
from SymPy.
"""
from __future__ import annotations

from crane_sym.scenes.kinds import SceneKind, report_for

#: The unit of each number of :func:`scene_report` (SI; ``"1"`` for a ratio such
#: as M_G/M_st), for ``crane-sym run --format json`` (``fnmatch`` patterns, the
#: first that matches).
VALUE_UNITS = {"t_*": "s", "p": "rad/s", "backlash_motor": "rad", "peak_fig9*": "1",
               "v0": "m/s"}


def hoist_report(scene, module):
    """Numbers and figures of a scene (see ``crane_sym.scenes.reading``) for this model.

    Parameters
    ----------
    scene : crane_sym.scenes.reading.Scene
        SI parameters of the hoist (Table 1's names), settings ``duration`` [s]
        and ``points`` (a payload above the rated one was refused on load,
        ``options.py``).
    module : module
        The scene's generated module (``scene_<name>.py``).

    Returns
    -------
    crane_sym.scenes.reading.SceneReport
        ``values`` (SI): ``t_stop_hoisting``, ``t_stop_lowering``, ``p``,
        ``backlash_motor``, ``peak_fig9``, ``t_peak_fig9``, ``peak_fig9_payload``;
        panels in the groups "Fig. 5", "Fig. 8", "Fig. 9", "Fig. 11", "Fig. 12" (one PNG each).
    """
    import numpy as np

    from crane_sym.generated import hoist_brakes as gen
    from crane_sym.scenes.run import time_function
    from crane_sym.scenes.reading import Panel, SceneReport, format_quantity as fq

    from .hybrid import EMERGENCY_STOP

    q = scene.parameters               # a payload above the rated one is refused on load
    times = scene.times()
    hoist = {k: q[k] for k in ("J1", "J2", "m_h", "r", "i_g", "i_t", "g", "omega1",
                               "M_SB", "M_BB", "t_SB", "t_BB")}
    kmh = 60.0  # m/s -> m/min

    # Fig. 5: rigid drive, hook speed, hoisting (+) and lowering (-)
    fig5 = Panel("Fig. 5: hook speed of the rigid drive after an emergency stop",
                 r"$v$ [m/min]", group="Fig. 5")
    stops = {}
    for payload, name in ((0.0, "hook only"), (q["m_p"], f"payload {q['m_p'] / 1e3:g} t")):
        up = gen.rigid_hook_speed_hoisting(times, m_p=payload, **hoist)
        down = gen.rigid_hook_speed_lowering(times, m_p=payload, **hoist)
        fig5.curves += [(f"hoisting, {name}", times, kmh * up),
                        (f"lowering, {name}", times, -kmh * down)]
    stops["hoisting"] = float(gen.rigid_stopping_time_hoisting(m_p=q["m_p"], **hoist))
    stops["lowering"] = float(gen.rigid_stopping_time_lowering(m_p=q["m_p"], **hoist))
    speed = time_function(scene, module, "rigid_hook_speed_hoisting")(times)

    # Fig. 8: relative gearbox torque (3) against the relative safety-brake torque
    bf = np.linspace(1.0, 3.5, 251)
    fig8 = []
    for phi in (2.0, 1.5, 1.0):
        panel = Panel(rf"Fig. 8: eq. (3), $\varphi_5 = {phi:g}$", r"$M_{G,rel,\max}$",
                      xlabel=r"$M_{SB}/M_{st}$ (relative safety-brake torque $BF_{SB}$)",
                      group="Fig. 8")
        for mf in (1.0, 0.95, 0.90, 0.0):
            panel.curves.append((rf"$MF = {mf:.2f}$", bf,
                                 gen.peak_relative_gearbox_torque_hoisting(phi, mf, 1.0, bf)))
        fig8.append(panel)

    # Fig. 9: elasto-kinetic, lowering, backlash, closed form per phase; the
    # scene's payload from its module's table, the hook alone solved here
    backlash = float(module.backlash_at_motor_shaft())
    # negative, as Fig. 9 plots it (the drum side drives the motor shafts while
    # lowering); the text quotes the peak's magnitude, 8.9: the legend says both
    fig9 = Panel("Fig. 9: relative gearbox torque, elastic drive, emergency stop lowering",
                 r"$M_G/M_{st}$ (sign as in Fig. 9)", group="Fig. 9")
    peaks = {}
    for payload, name in ((0.0, "hook only"), (q["m_p"], f"payload {q['m_p'] / 1e3:g} t")):
        run = EMERGENCY_STOP.solve({**q, "m_p": payload}, scene.settings)
        torque = (module.elastic_gearbox_torque(times) if payload == q["m_p"]
                  else run.values("relative_torque", times))
        peaks[name] = run.peak("relative_torque")
        low = float(np.min(torque))
        fig9.curves.append((f"lowering, {name}: peak {low:.1f}"
                            + (" (the text: 8.9 in magnitude)" if payload == 0.0 else ""),
                            times, torque))
    hook_peak = peaks["hook only"]
    load_peak = [v for k, v in peaks.items() if k != "hook only"][0]

    # Figs 11-12: coordinated brake factors over the payload
    payload = np.linspace(0.0, q["m_r"], 201)
    coord = {k: q[k] for k in ("J1", "J2", "m_h", "m_r", "r", "i_g", "i_t", "g", "omega1",
                               "d_t")}
    sb = gen.safety_brake_factor(payload, **coord)
    figs = []
    for mode, number, fn in (("hoisting", 11, gen.service_brake_factor_hoisting),
                             ("lowering", 12, gen.service_brake_factor_lowering)):
        bb = fn(payload, **coord)
        figs.append(Panel(f"Fig. {number}: coordinated brake factors, braking from {mode}",
                          "brake factor", [(r"$BF_{BB}$ (service brakes)", payload / 1e3, bb),
                                           (r"$BF_{SB}$ (safety brakes)", payload / 1e3, sb),
                                           (r"$BF_{BB} + BF_{SB}$", payload / 1e3, bb + sb)],
                          xlabel=r"payload $m_p$ [t]", group=f"Fig. {number}"))
    values = {"t_stop_hoisting": stops["hoisting"], "t_stop_lowering": stops["lowering"],
              "p": float(module.elastic_natural_frequency()), "backlash_motor": backlash,
              "peak_fig9": hook_peak[1], "t_peak_fig9": hook_peak[0],
              "peak_fig9_payload": load_peak[1], "v0": float(speed[0])}
    lines = [
        f"hook speed before the stop   v0 = {fq(kmh * values['v0'], 'm/min')}",
        f"rigid stop, hoisting         t = {fq(stops['hoisting'], 's')}",
        f"rigid stop, lowering         t = {fq(stops['lowering'], 's')}",
        f"elastic drive                p = {fq(values['p'], 'rad/s')}, backlash at the "
        f"motor shaft {fq(backlash, 'rad')}",
        f"Fig. 9 peak, hook only       M_G/M_st = {fq(hook_peak[1])} at "
        f"t = {fq(hook_peak[0], 's')} (printed: 8.9)",
        f"Fig. 9 peak, payload         M_G/M_st = {fq(load_peak[1])} at "
        f"t = {fq(load_peak[0], 's')}",
        f"Figs 11-12 at 0 t / rated    BF_SB = {fq(100 * sb[0], '%')} / "
        f"{fq(100 * sb[-1], '%')}",
    ]
    return SceneReport(lines=lines, values=values, panels=[fig5] + fig8 + [fig9] + figs)


#: The kinds of scene of paper 001: one, the Table 1 hoist and its figures.
REPORTS = (SceneKind("emergency stop of a hoist (Figs 5, 8, 9, 11, 12)", hoist_report),)


def scene_report(scene, module):
    """Numbers and figures of a scene of paper 001: the report of its kind
    (``REPORTS``; one kind, :func:`hoist_report`)."""
    return report_for(REPORTS, scene, module)
