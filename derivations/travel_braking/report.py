"""What ``crane-sym run`` prints and plots for a scene of paper 000.

Curves come from the scene's own generated module (the outputs it names),
scalars from the general module ``crane_sym.generated.travel_braking``;
never from SymPy. Imports happen only when a scene is run.
"""
from __future__ import annotations

from crane_sym.scenes.kinds import SceneKind, report_for

#: The unit of each number of :func:`scene_report` (SI; ``"1"`` for a ratio),
#: for ``crane-sym run --format json`` (``fnmatch`` patterns, the first that matches).
VALUE_UNITS = {"p": "rad/s", "f": "Hz", "F_r": "N", "F_max": "N", "F_max_valid": "N",
               "t_*": "s", "dynamic_factor": "1", "F_max_over_P_t": "1", "v1_min": "m/s",
               "v2_min": "m/s"}


def braking_report(scene, module):
    """Numbers and curves of a scene (see ``crane_sym.scenes.reading``) for this model.

    Uses the generated NumPy modules, not SymPy.

    Parameters
    ----------
    scene : crane_sym.scenes.reading.Scene
        With SI parameters ``m1, m2, c, P_t, W, v0`` and options
        ``duration`` [s] and ``points``.
    module : module
        The scene's generated module (``scene_<name>.py``): the curves of the
        outputs the scene names come from it.

    Returns
    -------
    crane_sym.scenes.reading.SceneReport
        Lines to print; ``values`` (SI): ``p``, ``f``, ``F_r``, ``F_max``,
        ``t_max``, ``dynamic_factor``, ``F_max_over_P_t``, ``v1_min``,
        ``v2_min``, ``t_slip_end`` and ``t_v2_zero`` (NaN when not reached
        within the duration), ``t_stop_rigid``; panels "Elastic link force"
        and "Velocities".
    """
    import math

    import numpy as np

    from crane_sym.generated import travel_braking as gen
    from crane_sym.scenes.run import time_function
    from crane_sym.scenes.panels import outside, valid_mask
    from crane_sym.scenes.reading import Panel, SceneReport, format_quantity as fq

    q = scene.parameters
    rigid = {k: q[k] for k in ("m1", "m2", "P_t", "W")}
    duration = scene.settings["duration"]
    times = scene.times()
    force, vel1, vel2 = (time_function(scene, module, name)(times)
                         for name in ("elastic_force", "velocity_m1", "velocity_m2"))

    def first_zero(v):
        """First time ``v`` reaches 0 on the grid (linear interpolation), or NaN."""
        hits = np.flatnonzero(v <= 0.0)
        if hits.size == 0:
            return math.nan
        i = int(hits[0])
        if i == 0:
            return float(times[0])
        return float(times[i - 1] + (times[i] - times[i - 1]) * v[i - 1] / (v[i - 1] - v[i]))

    freq = float(gen.natural_frequency(q["m1"], q["m2"], q["c"]))
    link_rigid = float(gen.rigid_link_force(**rigid))
    peak = float(gen.peak_elastic_force(**rigid))
    peak_at = float(gen.peak_time(q["m1"], q["m2"], q["c"]))
    # The model holds while the brake slips (v1 > 0) and the crane moves (v2 > 0):
    # it ends at the first of the two zeros.
    t_slip_end, t_v2_zero = first_zero(vel1), first_zero(vel2)
    ends = [(t, why) for t, why in ((t_slip_end, "the brake stops slipping (v1 = 0)"),
                                    (t_v2_zero, "the crane stops (v2 = 0)"))
            if not math.isnan(t)]
    t_valid, why_end = min(ends) if ends else (duration, "")
    valid = valid_mask(times, outside(0.0, t_valid, after="x"))
    values = {
        "p": freq, "f": freq / (2 * math.pi), "F_r": link_rigid, "F_max": peak,
        "t_max": peak_at, "dynamic_factor": peak / link_rigid,
        "F_max_over_P_t": peak / q["P_t"],
        "v1_min": float(vel1[valid].min()), "v2_min": float(vel2[valid].min()),
        "t_slip_end": t_slip_end, "t_v2_zero": t_v2_zero, "t_valid_end": t_valid,
        "t_stop_rigid": q["v0"] * (q["m1"] + q["m2"]) / (q["P_t"] + q["W"]),
    }
    def validity(at: float, event: str, throughout: str, name: str) -> str:
        if math.isnan(at):
            return (f"{throughout} throughout 0…{fq(duration, 's')}: {name} > 0 "
                    f"(min {name} = {fq(values[name + '_min'], 'm/s')})")
        if at > t_valid:         # reached by the model's curve after it stops holding
            return (f"{event} ({name} = 0) not while the model holds (its {name} "
                    f"reaches 0 at t = {fq(at, 's')}, past t = {fq(t_valid, 's')})")
        return f"{event} ({name} = 0) at t = {fq(at, 's')}; the model is not valid after that"

    slip = validity(t_slip_end, "brake stops slipping", "brake slips", "v1")
    moving = validity(t_v2_zero, "crane stops", "crane moves", "v2")
    lines = [
        f"natural frequency      p = {fq(freq, 'rad/s')}, f = p/2π = {fq(values['f'], 'Hz')}",
        f"rigid-drive link force F_r = {fq(link_rigid / 1e3, 'kN')}",
        f"peak elastic force     F_max = {fq(peak / 1e3, 'kN')} "
        f"at t_max = {fq(peak_at, 's')}",
        f"dynamic factor         F_max/F_r = {fq(values['dynamic_factor'])}",
        f"peak over brake force  F_max/P_t = {fq(values['F_max_over_P_t'])}",
        f"validity               {slip}",
        f"                       {moving}",
        f"rigid crane stops after v0·(m1 + m2)/(P_t + W) = "
        f"{fq(values['t_stop_rigid'], 's')}",
    ]
    invalid = []
    if ends:
        invalid = outside(0.0, t_valid, after=rf"model not valid ($t > {t_valid:.4g}$ s): "
                          + why_end.split(" (")[0].replace("the ", "", 1))
        lines.append(f"warning: the duration {fq(duration, 's')} runs past the model's "
                     f"validity: {why_end} at t = {fq(t_valid, 's')}; the plots grey "
                     f"t > {fq(t_valid, 's')} and the minima are taken before it")
    if peak_at > duration:
        lines.append(f"note: t_max lies beyond the plotted duration {fq(duration, 's')}")
    elif peak_at > t_valid:
        reached = float(force[valid].max())
        values["F_max_valid"] = reached
        lines.append(f"note: t_max comes after the model stops holding; the peak is not "
                     f"reached: largest force while it holds {fq(reached / 1e3, 'kN')}")
    panels = [
        Panel("Elastic link force", "$F$ [kN]", [
            ("$F(t)$ (14)", times, force / 1e3),
            (r"$F_\mathrm{r}$ (rigid drive)", times, np.full_like(times, link_rigid / 1e3)),
        ], invalid=invalid),
        Panel("Velocities", "$v$ [m/s]", [
            ("$v_1$ (motor side, $m_1$)", times, vel1),
            ("$v_2$ (crane side, $m_2$)", times, vel2),
        ], invalid=invalid),
    ]
    return SceneReport(lines=lines, values=values, panels=panels)


#: The kinds of scene of paper 000: one, a crane braking its travel.
REPORTS = (SceneKind("braking the travel of a crane", braking_report),)


def scene_report(scene, module):
    """Numbers and curves of a scene of paper 000: the report of its kind
    (``REPORTS``; one kind, :func:`braking_report`)."""
    return report_for(REPORTS, scene, module)
