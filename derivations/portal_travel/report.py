"""What ``crane-sym run`` prints and plots for a scene of paper 003.

Four kinds of scene (``REPORTS``), told apart by the outputs they name: Fig. 10
(the shift limits against the tooth number), a gear pair checked like Form 1,
the support loads with Table 3's exceedance probabilities, and the start-up
with backlash (Fig. 12, Table 1; phases in closed form, the drive of
``drive_train.py``, run through ``hybrid.STARTUP``). Numbers come from the scene's generated module,
never from SymPy; the reports import NumPy and the generated modules only
when run.
"""
from __future__ import annotations

from crane_sym.scenes.kinds import SceneKind, report_for

from .options import FIG10_SCENES, PAIR_SCENES, STARTUP_SCENES, SUPPORT_SCENES

#: The unit of each number of the reports (SI; ``"1"`` for a profile shift
#: coefficient, a ratio or a log10 of a probability), for ``crane-sym run
#: --format json`` (``fnmatch`` patterns, the first that matches).
VALUE_UNITS = {"x_*": "1", "x1": "1", "x2": "1", "alpha_tw_deg": "deg", "d_a*": "m",
               "s_a*_over_m": "1", "s_a*": "m", "epsilon_alpha": "1", "R_max": "N",
               "log10_P_6sigma_*": "1", "m_d": "kg", "b": "N*s/m", "v0": "m/s",
               "beta_1": "N*s/m", "q": "1", "a0_rigid": "m/s^2", "v_close_*": "m/s",
               "F_max_*": "N", "psi_*": "1", "t_max_*": "s", "a[0-9]_*": "m/s^2"}


def fig10_report(scene, module):
    """Fig. 10: curves 1–4 over the tooth numbers z_min..z_max (settings,
    z_min < z_max checked on load)."""
    import numpy as np

    from crane_sym.scenes.reading import Panel, SceneError, SceneReport, format_quantity as fq

    z_min, z_max = scene.settings["z_min"], scene.settings["z_max"]
    z = np.arange(z_min, z_max + 1, dtype=float)
    curves = [("1: $s_a = 0$", module.pointed_tip_shift(z)),
              ("2: $s_a = 0.3\\,m$", module.tip_thickness_shift(z, 0.3)),
              ("3: $s_a = 0.4\\,m$", module.tip_thickness_shift(z, 0.4)),
              ("4: no undercut, $x_{\\min}$", module.undercut_limit(z))]
    if not all(np.all(np.isfinite(c)) for _, c in curves):
        raise SceneError(f"scene {scene.name!r}: a curve of Fig. 10 is not finite")
    at10 = {name: float(c[list(z).index(10.0)]) for name, c in curves} if z_min <= 10 <= \
        z_max else {}
    values = {"x_pointed_z10": at10.get(curves[0][0], float("nan")),
              "x_03m_z10": at10.get(curves[1][0], float("nan")),
              "x_04m_z10": at10.get(curves[2][0], float("nan")),
              "x_min_z10": at10.get(curves[3][0], float("nan")),
              "x_pointed_zmax": float(curves[0][1][-1]), "x_min_zmax": float(curves[3][1][-1])}
    lines = [f"tooth numbers          z = {z_min}…{z_max}",
             f"pointed tip at z = 10  x = {fq(values['x_pointed_z10'])} (the paper prints 0.7)",
             f"s_a = 0.3m at z = 10   x = {fq(values['x_03m_z10'])}",
             f"s_a = 0.4m at z = 10   x = {fq(values['x_04m_z10'])}",
             f"no undercut at z = 10  x >= {fq(values['x_min_z10'])}"]
    # the y axis keeps curves 1-3 legible, as the paper's figure does: curve 4
    # (x_min = (z_min - z)/z_min, a line) leaves it below, which its label says
    upper = max(float(np.max(c)) for _, c in curves[:3])
    lower = min(-1.0, min(float(np.min(c)) for _, c in curves[:3]))
    below = z[curves[3][1] < lower]
    if below.size:
        curves[3] = (curves[3][0] + f" (below ${lower:g}$ from $z = {below[0]:g}$)",
                     curves[3][1])
    panel = Panel("Fig. 10: shift coefficient limits", "shift coefficient $x$",
                  [(name, z, c) for name, c in curves], xlabel="number of teeth $z$",
                  ylim=(lower, upper + 0.1 * (upper - lower)))
    return SceneReport(lines=lines, values=values, panels=[panel])


def gear_pair_report(scene, module):
    """A gear pair checked like Form 1: x_Σ from a_w, put on the pinion by the
    setting ``pinion_share`` (Form 1: 1.0). A centre distance the mesh cannot
    have, and undercut when ``forbid_undercut`` is true, were refused on load
    (``options.py``)."""
    import numpy as np

    from crane_sym.scenes.reading import Panel, SceneReport, format_quantity as fq

    q, share = scene.parameters, scene.settings["pinion_share"]
    angle = float(module.operating_pressure_angle())
    x_sum = float(module.shift_sum())
    x1, x2 = share * x_sum, (1 - share) * x_sum
    limits = [float(module.undercut_limit(q[zn])) for zn in ("z1", "z2")]
    m = q["m"]
    tips = [float(module.tip_diameter(q[zn], xi, q["dy1" if zn == "z1" else "dy2"]))
            for zn, xi in (("z1", x1), ("z2", x2))]
    thick = [float(module.tip_thickness(q[zn], xi, q["dy1" if zn == "z1" else "dy2"]))
             for zn, xi in (("z1", x1), ("z2", x2))]
    eps = float(module.contact_ratio(x1, x2))
    values = {"alpha_tw_deg": float(np.degrees(angle)), "x_sum": x_sum, "x1": x1, "x2": x2,
              "d_a1": tips[0], "d_a2": tips[1], "s_a1": thick[0], "s_a2": thick[1],
              "s_a1_over_m": thick[0] / m, "s_a2_over_m": thick[1] / m,
              "epsilon_alpha": eps, "x_min1": limits[0], "x_min2": limits[1]}
    lines = [f"operating pressure angle α_tw = {fq(values['alpha_tw_deg'], 'deg')}",
             f"sum of shifts           x_Σ = {fq(x_sum)} (x1 = {fq(x1)}, x2 = {fq(x2)})",
             f"tip diameters           d_a1 = {fq(tips[0] * 1e3, 'mm')}, "
             f"d_a2 = {fq(tips[1] * 1e3, 'mm')}",
             f"tip thickness           s_a1 = {fq(thick[0] * 1e3, 'mm')} "
             f"(s_a1/m = {fq(thick[0] / m)}), s_a2/m = {fq(thick[1] / m)}; need >= 0.4",
             f"contact ratio           ε_α = {fq(eps)}; need > 1.2",
             f"undercut limits         x_min1 = {fq(limits[0])}, x_min2 = {fq(limits[1])}"]
    shares = np.linspace(0.0, 1.0, 101)
    xs1, xs2 = shares * x_sum, (1 - shares) * x_sum
    panels = [
        Panel("Tip thickness against the pinion's share of $x_\\Sigma$", "$s_a/m$", [
            ("pinion $s_{a1}/m$", shares, module.tip_thickness(q["z1"], xs1, q["dy1"]) / m),
            ("wheel $s_{a2}/m$", shares, module.tip_thickness(q["z2"], xs2, q["dy2"]) / m),
            ("least $0.4$", shares, np.full_like(shares, 0.4))],
            xlabel="pinion share $x_1/x_\\Sigma$"),
        Panel("Contact ratio against the pinion's share", "$\\varepsilon_\\alpha$", [
            ("$\\varepsilon_\\alpha$", shares, module.contact_ratio(xs1, xs2)),
            ("least $1.2$", shares, np.full_like(shares, 1.2))],
            xlabel="pinion share $x_1/x_\\Sigma$"),
    ]
    return SceneReport(lines=lines, values=values, panels=panels)


def support_report(scene, module):
    """(3)–(4) at the scene's crane; Table 3's exceedance probabilities."""
    import math

    import numpy as np

    from crane_sym.mechanics.load_statistics import log_exceedance_probability
    from crane_sym.scenes.reading import Panel, SceneReport, format_quantity as fq

    from .options import REACH_FROM
    from .tables import table3_normal

    largest = scene.settings["largest_reach_m"]
    load = float(module.max_support_load(largest))
    reach = np.linspace(REACH_FROM * largest, largest, 101)
    along = module.max_support_load(reach)
    values = {"R_max": load}
    lines = [f"largest leg load (3)–(4), derived portal, at L = {fq(largest, 'm')}: "
             f"R_max = {fq(load / 1e3, 'kN')}"]
    curves = []
    # Table 3 prints no unit: the level is read against each variant's mean,
    # r/m_R, up to six standard deviations of the wider law (P down to ~1e-9)
    laws = {v: table3_normal("vertical pressure", v) for v in ("ship-to-store", "mixed")}
    ratio = np.linspace(1.0, 1.0 + 6.0 * max(s / m for m, s in laws.values()), 121)
    for variant, (mean, std) in laws.items():
        log10p = log_exceedance_probability(ratio * mean, mean, std) / math.log(10)
        curves.append((f"{variant}: $m_R = {mean:g}$, $\\sigma_R = {std:g}$", ratio,
                       log10p))
        key = variant.replace("-", "_")
        values[f"log10_P_6sigma_{key}"] = float(
            log_exceedance_probability(mean + 6 * std, mean, std) / math.log(10))
        lines.append(f"Table 3, vertical, {variant}: P(R > m_R + 6σ_R) = "
                     f"10^{fq(values[f'log10_P_6sigma_{key}'])}")
    panels = [
        Panel("Largest leg load against the reach", "$R_{\\max}$ [kN]",
              [("$R_{\\max}$ by (3)–(4), derived", reach, along / 1e3)],
              xlabel="reach $L$ [m]"),
        Panel("Table 3: exceedance of the vertical support load", "$\\log_{10} P(R > r)$",
              curves, xlabel="level over the variant's mean, $r/m_R$ (Table 3 prints no unit)",
              ylim=(-10.0, 0.5)),
    ]
    return SceneReport(lines=lines, values=values, panels=panels)


def startup_report(scene, module):
    """Fig. 12 and Table 1: the start-up for each backlash of the setting ``backlash``,
    start steps held for the setting ``holds``; loads and speeds up to ``end``
    from the tables of the scene's module (``startup_load_<k>``, ...), F_max,
    its time, the step accelerations and the closing of the flank from
    ``hybrid.STARTUP`` run on the module's rim quantities."""
    import numpy as np

    from crane_sym.scenes.reading import Panel, SceneReport, format_quantity as fq

    from crane_sym.generated import portal_travel as gen

    from .drive_train import step_accelerations
    from .hybrid import STARTUP
    from .startup import F_MEAN

    q, o = scene.parameters, scene.settings   # omega_0 > omega_n, end > sum(holds): on load
    gaps, holds, end = o["backlash"], o["holds"], o["end"][0]
    m_d, b = float(module.startup_motor_mass()), float(module.startup_link_damping())
    v0, ratio = float(module.startup_no_load_speed()), float(module.startup_slope_ratio())
    beta = float(module.startup_first_slope())
    times = scene.times(end)
    # the curves from the scene's module (tabulated per backlash); the numbers
    # from hybrid.STARTUP run here on the drive at the rim of the scene's module

    def curve(name: str, case: int) -> np.ndarray:
        return getattr(module, f"{name}_{case}")(times)

    rim = {"m_d": m_d, "m_k": q["m_k"], "c_l": q["c_l"], "b": b, "v0": v0, "beta_1": beta,
           "q": ratio, "W_f": q["W_f"], "W_w": q["W_w"]}
    # the gap's closed-form speed from the paper's general module (a scene module
    # specialized with t_s as an input takes SymPy minutes in codegen)
    gap_args = {k: q[k] for k in ("lambda_p", "P_m", "J_r", "v_n", "omega_0", "omega_n")}
    values = {"m_d": m_d, "b": b, "v0": v0, "beta_1": beta, "q": ratio,
              "a0_rigid": float(module.startup_rigid_breakaway())}
    lines = [f"motors of one side at the rim   m_d = {fq(m_d / 1e3, 't')}, "
             f"no-load speed v0 = {fq(v0, 'm/s')}",
             f"first characteristic           β1 = {fq(beta / 1e3, 'kN*s/m')}, slopes ×{fq(ratio)}"
             f" per step, holds {', '.join(fq(h, 's') for h in holds)}",
             f"rigid drive at break-away      a0 = {fq(values['a0_rigid'], 'm/s^2')}"]
    panels = []
    loads, speeds = [], []          # one y scale for each kind, across the cases
    for i, phi in enumerate(gaps):
        s = float(module.startup_backlash_at_rim(phi))
        run = STARTUP.solve({**rim, "s": s}, {"holds": holds, "end": end})
        when, peak = run.peak("load")
        acc = step_accelerations(run.result, run.system)
        closing = next((t for t, event, _ in run.events if event.endswith("closes +")), None)
        if closing is not None:      # the flank closes: the gap's closed-form speed
            values[f"v_close_{i}"] = float(gen.startup_gap_motor_speed(closing, **gap_args))
            lines.append(f"backlash {fq(phi, 'rad')}: the flank closes at t = "
                         f"{fq(closing, 's')}, motors at {fq(values[f'v_close_{i}'], 'm/s')}")
        values.update({f"F_max_{i}": peak, f"psi_{i}": peak / F_MEAN, f"t_max_{i}": when,
                       **{f"a{k + 1}_{i}": float(a) for k, a in enumerate(acc)}})
        lines.append(f"backlash {fq(phi, 'rad')} (s = {fq(s * 1e3, 'mm')} at the rim): "
                     f"F_max = {fq(peak / 1e3, 'kN')} at t = {fq(when, 's')}, "
                     f"ψ = F_max/150 kN = {fq(peak / F_MEAN)}; crane Δv/Δt per step "
                     + ", ".join(fq(a, 'm/s^2') for a in acc))
        tag = f"Fig. 12{'abcdef'[i]}"
        title = f"backlash {phi:.3g} rad of the fast shaft"
        panels += [
            Panel(f"{tag}: loads, {title}", "load [kN]",
                  [("$F_1 + F_2$", times, curve("startup_load", i) / 1e3),
                   ("$F_1$ (one side)", times, curve("startup_link_load", i) / 1e3),
                   ("$W_w + W_f$", times, np.full_like(times, (q["W_w"] + q["W_f"]) / 1e3))],
                  group=tag),
            Panel(f"{tag}: speeds", "speed at the rim [m/s]",
                  [("motors $v_1$", times, curve("startup_motor_speed", i)),
                   ("crane $v_к$", times, curve("startup_crane_speed", i)),
                   ("no-load $v_0$", times, np.full_like(times, v0))], group=tag)]
        loads.append(panels[-2])
        speeds.append(panels[-1])
    for same in (loads, speeds):
        ys = np.concatenate([np.asarray(y, dtype=float) for p in same for _, _, y in p.curves])
        low, high = float(np.min(ys)), float(np.max(ys))
        pad = 0.05 * (high - low or 1.0)
        for p in same:
            p.ylim = (low - pad, high + pad)
    return SceneReport(lines=lines, values=values, panels=panels)


#: The kinds of scene of paper 003, by the outputs that mark them (``options.py``;
#: its SCENE_CHECKS refuse a scene of none).
REPORTS = (
    SceneKind("start-up with backlash (Fig. 12, Table 1)", startup_report,
              outputs=STARTUP_SCENES),
    SceneKind("shift limits (Fig. 10)", fig10_report, outputs=FIG10_SCENES),
    SceneKind("gear pair (Form 1)", gear_pair_report, outputs=PAIR_SCENES),
    SceneKind("support loads ((3)-(4), Table 3)", support_report, outputs=SUPPORT_SCENES),
)


def scene_report(scene, module):
    """Numbers and panels of a scene of paper 003: the report of its kind
    (``REPORTS``, see the module docstring)."""
    return report_for(REPORTS, scene, module)
