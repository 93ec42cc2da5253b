"""Tables, headline and work-precision plot of ``crane_sym.bench`` rows."""
from __future__ import annotations

import re
from pathlib import Path
from statistics import median
from typing import Sequence

from .bench_rows import DUHAMEL, GENERATED, INTEGRATOR, LAMBDIFY, REFERENCE, BenchRow

ALTERNATIVES = (INTEGRATOR, DUHAMEL)


def _num(x: float, spec: str) -> str:
    return "—" if x != x else format(x, spec)


def as_markdown(rows: Sequence[BenchRow]) -> str:
    """One Markdown table of ``rows``."""
    lines = ["| function | method | points | evals/s | max rel. error | max error / peak "
             "| time / generated (per evaluation) | time / np.cos |",
             "| --- | --- | ---: | ---: | ---: | ---: | ---: | ---: |"]
    for r in rows:
        lines.append(f"| {r.function} | {r.method} | {r.points} | "
                     f"{_num(r.points / r.seconds, '.3g')} | {_num(r.max_rel_error, '.2e')} | "
                     f"{_num(r.max_error_over_peak, '.2e')} | "
                     f"{_num(r.ratio_to_generated, '.3g')} | {_num(r.ratio_to_floor, '.3g')} |")
    return "\n".join(lines)


def not_applicable(d, rows: Sequence[BenchRow]) -> list[tuple[str, str, str]]:
    """(function, target, why) for each comparison that does not apply."""
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
    compare fairly; ratios are time per evaluation, from one run."""
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
    return re.sub(r": [A-Za-z_]\w*\]", "]", re.sub(r" (rtol|n)=\S+", "", method))


def plot(rows: Sequence[BenchRow], path: Path, title: str) -> list[Path]:
    """Work-precision plot: time per evaluation against error (max error over
    the peak), log-log, one panel per function that has alternatives; one
    colour per method, one line style per coordinate system. At most four
    panels to a PNG: ``path``, or ``<stem>_1.png`` ... when there are more."""
    from matplotlib import colormaps

    from .plots import MAX_PANELS, chunks, numbered, save

    names = [n for n in dict.fromkeys(r.function for r in rows)
             if any(r.function == n and r.kind in ALTERNATIVES for r in rows)]
    families = sorted({_family(r.method) for r in rows if r.kind in ALTERNATIVES})
    methods = sorted({f.split(" [")[0] for f in families})
    systems = sorted({f.split(" [")[-1] for f in families})
    colour = dict(zip(methods, colormaps["tab10"].colors * 2))
    style = dict(zip(systems, ("-", "--", ":", "-.") * 3))
    pages = chunks(names, MAX_PANELS)
    paths = numbered(path, len(pages))
    for k, (page, target) in enumerate(zip(pages, paths), start=1):
        heading = title if len(pages) == 1 else f"{title}, {k} of {len(pages)}"
        save(_figure(rows, page, families, colour, style, heading), target, dpi=100)
    return paths


def _figure(rows: Sequence[BenchRow], names: Sequence[str], families: Sequence[str],
            colour: dict, style: dict, title: str):
    """One work-precision figure of the functions ``names``, the legend below
    the panels (outside the data)."""
    from matplotlib.figure import Figure

    cols = 2 if len(names) > 1 else 1
    nrows = max(1, -(-len(names) // cols))
    legend_rows = -(-(len(families) + 2) // 3)
    legend = 0.2 * legend_rows + 0.35          # inches below the panels
    fig = Figure(figsize=(7 * cols, 3.6 * nrows + legend + 0.5))
    axes = fig.subplots(nrows, cols, squeeze=False)
    for ax in axes.ravel()[len(names):]:
        ax.set_visible(False)
    handles = {}
    for ax, name in zip(axes.ravel(), names):
        mine = [r for r in rows if r.function == name]
        for key in families:
            rs = [r for r in mine if r.kind in ALTERNATIVES and _family(r.method) == key]
            if rs:
                method, system = key.split(" [")[0], key.split(" [")[-1]
                handles[key], = ax.loglog([max(r.max_error_over_peak, 1e-17) for r in rs],
                                          [r.seconds / r.points for r in rs], marker="o",
                                          ms=3, lw=1, color=colour[method],
                                          linestyle=style[system], label=key)
        for kind, marker, label in ((GENERATED, "*", "generated closed form"),
                                    (LAMBDIFY, "D", "sympy.lambdify")):
            for r in (r for r in mine if r.kind == kind):
                handles[label], = ax.loglog(
                    [max(r.max_error_over_peak, 1e-17)], [r.seconds / r.points],
                    marker=marker, ms=12 if marker == "*" else 7, color="k",
                    mfc="k" if marker == "*" else "none", linestyle="none", label=label)
        ax.set_title(name, fontsize=9)
        ax.set(xlabel="max error / peak |value|", ylabel="s per evaluation")
        ax.grid(True, which="both", alpha=0.3)
    fig.legend(handles.values(), handles.keys(), loc="lower center", ncol=3, fontsize=7,
               frameon=False)
    fig.suptitle(title)
    fig.tight_layout(rect=(0, legend / fig.get_figheight(), 1, 0.98))
    return fig
