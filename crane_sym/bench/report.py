"""Tables, headline and work-precision plot of ``crane_sym.bench.functions`` rows."""
from __future__ import annotations

import re
from itertools import cycle
from pathlib import Path
from statistics import median
from typing import Sequence

from crane_sym.bench.rows import DUHAMEL, GENERATED, INTEGRATOR, LAMBDIFY, REFERENCE, BenchRow
from crane_sym.markdown import markdown_table
from crane_sym.scenes.plots import chunks, numbered, save

ALTERNATIVES = (INTEGRATOR, DUHAMEL)


def _num(x: float, spec: str) -> str:
    return "—" if x != x else format(x, spec)


def as_markdown(rows: Sequence[BenchRow]) -> str:
    """One Markdown table of ``rows``.

    Parameters
    ----------
    rows : sequence of BenchRow
        The rows of one bench run.
    """
    return markdown_table(
        ["function", "method", "points", "evals/s", "max rel. error", "max error / peak",
         "time / generated (per evaluation)", "time / np.cos"],
        [[r.function, r.method, r.points, _num(r.points / r.seconds, ".3g"),
          _num(r.max_rel_error, ".2e"), _num(r.max_error_over_peak, ".2e"),
          _num(r.ratio_to_generated, ".3g"), _num(r.ratio_to_floor, ".3g")] for r in rows],
        align="llrrrrrr")


def not_applicable(d, rows: Sequence[BenchRow]) -> list[tuple[str, str, str]]:
    """(function, target, why) for each comparison that does not apply.

    Parameters
    ----------
    d : Derivation
        The built derivation (its outputs).
    rows : sequence of BenchRow
        The rows of its bench run.
    """
    kinds = {}
    for r in rows:
        kinds.setdefault(r.function, set()).add(r.kind)
    found = []
    for out in d.outputs:
        have = kinds.get(out.name, set())
        if INTEGRATOR not in have:
            found.append((out.name, "SciPy integrators, Duhamel alternatives",
                          "no ODE counterpart: the function is not a time response of "
                          "the equations of motion"))
        elif DUHAMEL not in have:
            found.append((out.name, "Duhamel alternatives",
                          "no declared system of the form x'' + Ω²x = S(t) computes it"))
    for name, have in kinds.items():
        if REFERENCE in have:
            found.append((name, "time / generated, np.cos floor",
                          "no closed form: integrators are compared with the mpmath "
                          "modal solution only"))
    return found


def _fastest(rows: Sequence[BenchRow], kinds: tuple, target: float) -> BenchRow | None:
    ok = [r for r in rows if r.kind in kinds and r.max_error_over_peak <= target]
    return min(ok, key=lambda r: r.seconds / r.points) if ok else None


def _spread(values: list[float]) -> str:
    return (f"{min(values):.3g}x … {max(values):.3g}x (median {median(values):.3g}x) "
            f"over {len(values)} functions")


def headline(rows: Sequence[BenchRow], target: float = 1e-9) -> list[str]:
    """The paper's summary line, then one line per function. Errors are
    normwise (max error over the peak |value|) so that quantities through zero
    compare fairly; ratios are time per evaluation, from one run.

    Parameters
    ----------
    rows : sequence of BenchRow
        The rows of one paper's bench run.
    target : float, optional
        The error over the peak an integrator has to reach to be compared.
    """
    if not rows:
        return []
    by_name: dict[str, list[BenchRow]] = {}
    for r in rows:
        by_name.setdefault(r.function, []).append(r)
    gens = {n: r for n, rs in by_name.items() for r in rs if r.kind == GENERATED}
    ratios, missed, lines = [], [], []
    for name, rs in by_name.items():
        gen = gens.get(name)
        best = _fastest(rs, (INTEGRATOR,), target)
        quad = _fastest(rs, (DUHAMEL,), target)
        if gen is None:
            text = f"{name}: no closed form"
            if best:
                text += (f"; fastest integrator within {target:g} of the peak: {best.method}, "
                         f"{best.seconds:.3g} s for {best.points} points (this machine)")
            elif any(r.kind == INTEGRATOR for r in rs):
                text += f"; no integrator came within {target:g} of the peak"
            lines.append(text)
            continue
        text = (f"{name}: {gen.points / gen.seconds:.3g} evals/s, max rel. error "
                f"{gen.max_rel_error:.1e}, {gen.ratio_to_floor:.3g}x np.cos")
        if any(r.kind == INTEGRATOR for r in rs):
            if best:
                ratios.append(best.ratio_to_generated)
                text += (f"; fastest integrator within {target:g} of the peak: {best.method}, "
                         f"{best.ratio_to_generated:.3g}x slower")
            else:
                missed.append(name)
                text += f"; no integrator came within {target:g} of the peak"
        if quad:
            text += (f"; fastest Duhamel alternative within {target:g}: {quad.method}, "
                     f"{quad.ratio_to_generated:.3g}x slower")
        lines.append(text)
    paper = rows[0].derivation
    if ratios:
        summary = (f"{paper}: generated closed form against the fastest SciPy integrator "
                   f"reaching {target:g} (max error / peak), at matched error: the "
                   f"integrator is slower by {_spread(ratios)}")
    elif missed:
        summary = f"{paper}: no SciPy integrator reached {target:g} of the peak"
    else:
        summary = (f"{paper}: no generated function is a time response of an ODE system, so "
                   "the generated-vs-integrator ratio does not apply")
    if missed and ratios:
        summary += f"; none reached it for {', '.join(missed)}"
    open_ended = [n for n, rs in by_name.items() if n not in gens
                  and any(r.kind == INTEGRATOR for r in rs)]
    if open_ended:
        best = [_fastest(by_name[n], (INTEGRATOR,), target) for n in open_ended]
        if all(best):
            slow = max(best, key=lambda r: r.seconds)
            summary += (f"; the {len(open_ended)} time responses have no closed form: the "
                        f"fastest integrator reaching {target:g} on all of them takes "
                        f"{slow.seconds:.3g} s for {slow.points} points ({slow.method}; "
                        "this machine)")
        else:
            summary += (f"; the {len(open_ended)} time responses have no closed form, and "
                        f"no integrator reached {target:g} on all of them")
    floors = [g.ratio_to_floor for g in gens.values()]
    plain = [r.ratio_to_generated for rs in by_name.values() for r in rs if r.kind == LAMBDIFY]
    if floors:
        summary += f". Generated vs one np.cos over the same array: {_spread(floors)}"
    if plain:
        summary += (f"; sympy.lambdify of the same expressions takes {_spread(plain)} "
                    "the generated time")
    return [summary + "."] + lines


def _family(method: str) -> str:
    """A method label without its tolerance or grid size, and without the
    function name in its system tag (one curve per family)."""
    return re.sub(r": [A-Za-z_]\w*(?=[;\]])", "", re.sub(r" (rtol|n)=\S+", "", method))


#: Panels to a work-precision figure, curves to a panel, the page width in
#: inches it is drawn at, and the type size (points).
PANELS, CURVES, WIDTH, TYPE = 3, 6, 7.5, 9


def _system(family: str) -> str:
    """The coordinate system and right-hand side of a method family (``[…]``)."""
    return "[" + family.split(" [")[-1] if " [" in family else ""


def _errors(rows: Sequence[BenchRow], name: str) -> list[tuple[str, float]]:
    """The errors the curves of function ``name`` draw: (method, error over
    the peak) of every alternative, in order."""
    return sorted((r.method, r.max_error_over_peak) for r in rows
                  if r.function == name and r.kind in ALTERNATIVES)


def _same(a: list[tuple[str, float]], b: list[tuple[str, float]]) -> bool:
    """True when two functions' curves have the same methods and errors, as a
    log-log plot shows them: within 1 % of each other, or both at the
    rounding floor (1e-13 of the peak), where a constant factor moves them."""
    return len(a) == len(b) and all(
        m == n and abs(x - y) <= 0.01 * max(abs(x), abs(y)) + 1e-13
        for (m, x), (n, y) in zip(a, b))


def panels(rows: Sequence[BenchRow]) -> list[tuple[str, str, list[str]]]:
    """The work-precision panels of ``rows``: (title, the function whose rows
    it draws, its method families), one panel per function and coordinate
    system, at most ``CURVES`` families each. Functions with the same errors
    by every method (a force that is a constant times the displacement the
    same solve gives: its panels would differ only by the noise of the
    timings) share their panels, titled with every name; the times drawn are
    the first function's.

    Parameters
    ----------
    rows : sequence of BenchRow
        The rows of one paper's bench run.
    """
    names = [n for n in dict.fromkeys(r.function for r in rows)
             if any(r.function == n and r.kind in ALTERNATIVES for r in rows)]
    groups: list[list[str]] = []
    for name in names:
        mine = _errors(rows, name)
        found = next((g for g in groups if _same(_errors(rows, g[0]), mine)), None)
        if found is None:
            groups.append([name])
        else:
            found.append(name)
    out = []
    for group in groups:
        mine = sorted({_family(r.method) for r in rows
                       if r.function == group[0] and r.kind in ALTERNATIVES})
        for system in dict.fromkeys(_system(f) for f in mine):
            chosen = [f for f in mine if _system(f) == system]
            for part in chunks(chosen, CURVES):
                title = ", ".join(group) + (f" (the same errors; times of {group[0]})"
                                            if len(group) > 1 else "")
                out.append((f"{title}\n{system}", group[0], part))
    return out


def plot(rows: Sequence[BenchRow], path: Path, title: str) -> list[Path]:
    """Work-precision plot: time per evaluation against error (max error over
    the peak), log-log, one panel per function with alternatives and
    coordinate system (:func:`panels`: at most six curves, functions with the
    same runs drawn once); one colour per method, the legend below the
    panels. Drawn at page width with 9-pt type, three panels to a PNG:
    ``path``, or ``<stem>_1.png`` ... when there are more; none when no
    function has an alternative (Vöth and Tyulenev's torque and brake factors).

    Parameters
    ----------
    rows : sequence of BenchRow
        The rows of one paper's bench run.
    path : Path
        The PNG to write (numbered when there are several).
    title : str
        The figure's title.
    """
    from matplotlib import colormaps

    found = panels(rows)
    if not found:                        # no function has an alternative: no plot
        return []
    methods = sorted({f.split(" [")[0] for _, _, fs in found for f in fs})
    colour = dict(zip(methods, cycle(colormaps["tab10"].colors)))
    pages = chunks(found, PANELS)
    paths = numbered(path, len(pages))
    for k, (page, target) in enumerate(zip(pages, paths), start=1):
        heading = title if len(pages) == 1 else f"{title}, {k} of {len(pages)}"
        save(_figure(rows, page, colour, heading), target, dpi=120)
    return paths


def _figure(rows: Sequence[BenchRow], page: Sequence[tuple[str, str, list[str]]],
            colour: dict, title: str):
    """One work-precision figure of the panels ``page``, one a row, the legend
    (colours: methods) below them."""
    from matplotlib.figure import Figure
    from matplotlib.lines import Line2D

    shown = sorted({f.split(" [")[0] for _, _, fs in page for f in fs})
    legend = 0.22 * -(-(len(shown) + 2) // 2) + 0.3          # inches below the panels
    fig = Figure(figsize=(WIDTH, 3.2 * len(page) + legend + 0.5))
    axes = fig.subplots(len(page), 1, squeeze=False).ravel()
    for ax, (name, function, families) in zip(axes, page):
        mine = [r for r in rows if r.function == function]
        for key in families:
            rs = [r for r in mine if r.kind in ALTERNATIVES and _family(r.method) == key]
            ax.loglog([max(r.max_error_over_peak, 1e-17) for r in rs],
                      [r.seconds / r.points for r in rs], marker="o", ms=3, lw=1,
                      color=colour[key.split(" [")[0]])
        for kind, marker in ((GENERATED, "*"), (LAMBDIFY, "D")):
            for r in (r for r in mine if r.kind == kind):
                ax.loglog([max(r.max_error_over_peak, 1e-17)], [r.seconds / r.points],
                          marker=marker, ms=12 if marker == "*" else 7, color="k",
                          mfc="k" if marker == "*" else "none", linestyle="none")
        ax.set_title(name, fontsize=TYPE + 1)
        ax.set_xlabel("largest error over the peak |value|", fontsize=TYPE)
        ax.set_ylabel("time per evaluation [s]", fontsize=TYPE)
        ax.tick_params(labelsize=TYPE)
        ax.grid(True, which="both", alpha=0.3)
    handles = [Line2D([], [], color=colour[m], lw=1.5, label=m) for m in shown]
    handles += [Line2D([], [], marker="*", ms=11, color="k", linestyle="none",
                       label="generated closed form"),
                Line2D([], [], marker="D", ms=6, color="k", mfc="none", linestyle="none",
                       label="sympy.lambdify")]
    fig.legend(handles=handles, loc="lower center", ncol=2, fontsize=TYPE, frameon=False)
    fig.suptitle(title, fontsize=TYPE + 1)
    fig.tight_layout(rect=(0, legend / fig.get_figheight(), 1, 0.98))
    return fig


def plot_scaling(scaled: Sequence[tuple], path: Path, title: str) -> list[Path]:
    """Time of the best tuned integrator over the closed form's against the
    number of points, one line per function (log-log; below 1 the integrator
    wins); the legend to the right of the panel. [] when there is nothing.

    Parameters
    ----------
    scaled : sequence of tuple
        (function, points, integrator, its seconds, closed form's seconds), as
        :func:`crane_sym.bench.targets.scaling` returns them.
    path : Path
        The PNG to write.
    title : str
        The figure's title.
    """
    if not scaled:
        return []
    from matplotlib.figure import Figure

    names = list(dict.fromkeys(f for f, *_ in scaled))
    fig = Figure(figsize=(WIDTH, 3.6))
    ax = fig.subplots()
    for k, name in enumerate(names):        # ten colours, then the next marker and dash
        mine = [(n, i / g) for f, n, _, i, g in scaled if f == name]
        ax.loglog(*zip(*mine), marker="os^D"[k // 10 % 4], ms=4, lw=1,
                  linestyle=("-", "--", ":", "-.")[k // 10 % 4], label=name)
    ax.axhline(1.0, color="k", lw=0.8, linestyle="--")
    ax.set_xlabel("points", fontsize=TYPE)
    ax.set_ylabel("integrator time / closed form", fontsize=TYPE)
    ax.tick_params(labelsize=TYPE)
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(loc="center left", bbox_to_anchor=(1.02, 0.5), fontsize=TYPE, frameon=False)
    ax.set_title(title, fontsize=TYPE + 1)
    fig.tight_layout()
    return [save(fig, path, dpi=120)]
