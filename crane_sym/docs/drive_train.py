"""The walkthrough of a drive train of the user's own (a component file), as
a handout: Markdown with LaTeX, or the printable page of :mod:`crane_sym.docs.page`.

It goes the way the papers' walkthroughs go, from the model to the numbers:
the components as written; their symbols and values; the rigid groups with
their reduced inertias; the energies T, Π, the dissipation Φ and the
generalised forces Q; Lagrange's equations (the LaTeX of
:meth:`crane_sym.components.equations.Equations.latex`); what switches, and
each mode the run passes through with its x' = A x + b; the phases of the run
with their event times; the peak and dynamic factor of every elastic link;
and the verdicts on the file's formulas, if it lists any.

:func:`render` is pure (text in, text out); :func:`drive_train_walkthrough`
reads the file and runs it.
"""
from __future__ import annotations

import io
import re
from pathlib import Path

from crane_sym.components.kinds import by_table
from crane_sym.components.model import ComponentRun
from crane_sym.components.parts import ComponentError
from crane_sym.components.parameters import parameters
from crane_sym.components.quantities import derived_quantity, static_loads
from crane_sym.components.component_file import ComponentFile, read_component_file
from crane_sym.docs.drive_train_modes import _Markup, _math, _modes, _number, _phases, _table
from crane_sym.docs.drive_train_states import states_section
from crane_sym.docs.numbers import math_errors
from crane_sym.docs.rows import aligned_rows, sum_terms
from crane_sym.docs.walkthrough import _display
from crane_sym.latex import latex
from crane_sym.markdown import fenced, markdown_text
from crane_sym.scenes.panels import format_quantity

__all__ = ["drive_train_page", "drive_train_walkthrough", "render"]

def _tex(expr, model) -> str:
    """LaTeX of a model's expression with its handout names (``Equations.latex_names``)."""
    return latex(expr, symbol_names=model.equations.latex_names)


def _sum(lhs: str, expr, model, tail: str = "") -> str:
    """``lhs = expr [tail]`` in aligned rows a page holds
    (:func:`crane_sym.docs.rows.aligned_rows`)."""
    return aligned_rows(lhs, sum_terms(expr, lambda t: _tex(t, model)), tail)


def _symbol(p, model) -> str:
    """A parameter's symbol: its handout name, or for a value that only switches
    the model (a gap, a brake's delay: no symbol of the equations) its path upright."""
    if p.symbol in model.equations.latex_names:
        return _tex(p.symbol, model)
    return "\\mathrm{" + p.path.replace("_", "\\_") + "}"


def _point(terms: dict) -> str:
    """A span's point as written: ``250 mm · drum − centre``, or the frame."""
    if not terms:
        return "frame"
    return " + ".join(f"{f} · {b}" for b, f in terms.items()).replace("+ -", "− ")


def _connects(kind: str, entry: dict) -> str:
    keys = by_table()[kind].places
    if not keys:
        return "—"
    if keys[0].form == "terms":
        return " → ".join(_point(entry.get(k.name) or {}) for k in keys)
    if keys[0].form == "ends":
        return " – ".join(entry.get(keys[0].name, []))
    if len(keys) == 2:
        return f"{entry.get(keys[0].name, '')} → {entry.get(keys[1].name, '')}"
    return entry.get(keys[0].name, "—")


def _value_text(v) -> str:
    return ", ".join(map(str, v)) if isinstance(v, list) else str(v)


def _components(read: ComponentFile) -> str:
    rows = []
    for kind in by_table():
        for entry in read.tables.get(kind, []):
            places = {k.name for k in by_table()[kind].places}
            values = "; ".join(f"{k} = {_value_text(v)}" for k, v in entry.items()
                               if k != "name" and k not in places)
            rows.append([entry.get("name", ""), kind, _connects(kind, entry), values or "—"])
    return _table(["component", "kind", "joins / acts on", "values as written"], rows)


def _symbols(read: ComponentFile, run: ComponentRun) -> list[str]:
    solved = run.system.extra
    rows = [[_math(_symbol(p, read.model)), p.description, p.path,
             f"{p.value:.6g}" if p.value == p.value else
             f"{float(solved[p.symbol]):.6g} (solved at the start)", p.unit]
            for p in parameters(read.model).values()]
    eq = read.model.equations
    rows += [[_math(_tex(q, read.model)), f"coordinate of the rigid group of {g.name}", "—", "—",
              "rad" if g.motion == "rotating" else "m"]
             for g, q in zip(read.model.assembly.groups, eq.coordinates)]
    for law, signal in zip(run.system.clock.laws, eq.signals):
        assert signal.name.endswith("_" + law.name), (signal, law.name)
        rows.append([_math(_tex(signal, read.model)),
                     f"{law.law} of the law {law.name} at time t (its pieces: the "
                     "components above)", law.name, "law in t", law.unit])
    return ["Every symbol is named after its component. A value 0 (a shaft end without "
            "inertia, an undamped link) is kept in the equations below and drops out of the "
            "numbers.",
            _table(["symbol", "meaning", "name in the file", "value (SI)", "unit"],
                           rows)]


def _groups(read: ComponentFile) -> list[str]:
    model = read.model
    a, eq = model.assembly, model.equations
    out = ["Bodies joined by gears and drums move as one rigid group with one "
           "coordinate $q$; body $b$ of the group sits at $\\kappa_b q$ ($\\kappa = 1$ for "
           "the group's first body, $1/i$ across a gear, $r/n$ across a drum). A body given "
           "no inertia (zero) is kept as a point of the group. The inertia of a group "
           "referred to its coordinate is $\\partial^2 T / \\partial \\dot q^2$."]
    rows = []
    M = eq.linear[0]
    for index, (g, q) in enumerate(zip(a.groups, eq.coordinates)):
        members = ", ".join(f"{b.name}: $\\kappa = {_tex(k, model)}$" for (b, _), k in
                            zip(g.members, g.factors))
        reduced = derived_quantity(model, f"{g.name}.reduced_inertia")
        rows.append([_math(_tex(q, model)), _Markup(members), _math(_tex(reduced.expr, model)),
                     format_quantity(float(M[index, index].xreplace(eq.values)),
                                     reduced.unit, 6)])      # a span's mass counts
    out.append(_table(["coordinate", "bodies", "reduced inertia", "value"], rows))
    return out


def _energies(read: ComponentFile) -> list[str]:
    eq = read.model.equations
    out = ["From the components: the kinetic energy of every body, the potential energy "
           "of every elastic link, its viscous dissipation (Rayleigh's function) and the "
           "generalised force of every load on each coordinate. $u_k$ is the twist of "
           "link $k$ (its second body's coordinate minus its first's); a link with "
           "backlash carries its contact $\\chi$ (1 on a flank, 0 in its gap) and the "
           "flank $\\delta$ it rests on; a motor's torque is multiplied by its switch "
           "$\\mathrm{on}$; a brake's friction $B$ is what the mode makes it.",
           "**Kinetic energy**", _display(_sum("T", eq.T, read.model)),
           "**Potential energy**", _display(_sum("\\Pi", eq.V, read.model)),
           "**Dissipation**", _display(_sum("\\Phi", eq.dissipation, read.model)),
           "**Generalised forces**"]
    out += [_display(_sum(f"Q_{{{_tex(q, read.model)}}}", eq.forces[q], read.model))
            for q in eq.coordinates]
    return out


def _lagrange(read: ComponentFile) -> list[str]:
    eq = read.model.equations
    out = ["Lagrange's equations with Rayleigh's dissipation, one per coordinate,",
           _display(r"\frac{d}{dt} \frac{\partial T}{\partial \dot q} - "
                    r"\frac{\partial T}{\partial q} + \frac{\partial \Phi}{\partial \dot q}"
                    r" + \frac{\partial \Pi}{\partial q} = Q,"),
           "give the equations of motion:"]
    out += [_display(_sum("", e.lhs, read.model, f"= {_tex(e.rhs, read.model)}"))
            for e in eq.lagrange.equations]
    out.append("They are linear in the state once a mode fixes $\\chi$, $\\delta$, "
               "$\\mathrm{on}$ and $B$: $M \\ddot q + D \\dot q + K q = f$.")
    return out


def _results(run: ComponentRun) -> list[str]:
    rows = [[p.link, format_quantity(p.value, p.unit, 6), format_quantity(p.time, "s", 6),
             format_quantity(p.static, p.unit, 6),
             "—" if p.reference is None else format_quantity(p.reference, p.unit, 6),
             "—" if p.factor is None else format_quantity(p.factor, "", 4)]
            for p in run.peaks]
    return ["For every elastic link: its largest load over the run (signed), when it "
            "occurs, its load at the start, the reference the dynamic factor divides by "
            "(the link's `reference`, else its load at the start) and the dynamic factor, "
            "peak over reference (EN 13001-2's φ5 for drive forces); a negative factor is a "
            "peak that acts against the load at the start.",
            _table(["link", "peak", "at", "at the start", "reference",
                            "dynamic factor"], rows)] + _reactions(run) + _static(run)


def _reactions(run: ComponentRun) -> list[str]:
    """Each ground contact's largest reaction, when, and its reaction at the start."""
    rows = [[r.contact, format_quantity(r.value, r.unit, 6), format_quantity(r.time, "s", 6),
             format_quantity(r.start, r.unit, 6)] for r in run.reactions]
    return ["For every ground contact: the ground's largest reaction over the run, when it "
            "occurs, and its reaction at the start (0 while the body is off the ground).",
            _table(["ground contact", "peak reaction", "at", "at the start"], rows)] \
        if rows else []


def _static(run: ComponentRun) -> list[str]:
    """The load of each link at the start in the symbols (each rigid group in
    equilibrium), when the loads do not depend on the speed."""
    try:
        loads = static_loads(run.model)
    except ComponentError as why:
        return [f"(No static load in the symbols: {markdown_text(why)}.)"]
    values = {**run.model.equations.values, **run.system.extra}
    out = ["In the steady motion at the start every rigid group is in equilibrium, "
           "$\\sum_k F_k \\, \\partial u_k / \\partial q = Q$ (motors on, brakes off); "
           "solved for the link loads:"]
    units = {p.link: p.unit for p in run.peaks}
    for name, expr in loads.items():
        if expr is None:
            out.append(f"**{name}**: in a loop of elastic links, its static load is not "
                       "fixed by equilibrium alone.")
            continue
        number = float(expr.xreplace(values))
        out.append(f"**{name}** ({units[name]}):")
        out.append(_display(_sum("F_{st}", expr, run.model, f"\\approx {_number(number)}")))
    return out


def _formulas(read: ComponentFile, records) -> list[str]:
    out = ["The formulas the file lists, read by machine and checked against the model "
           "above as the papers' prints are (`crane-sym audit FILE`): symbolic identity "
           "first, then mpmath at seeded physical points, then dimensions."]
    for f, r in zip(read.formulas, records):
        names = ", ".join(f"{markdown_text(printed)} = {markdown_text(target)}"
                          for printed, target in f.symbols)
        out.append(f"**{markdown_text(f.name)}**, for {markdown_text(f.quantity)}"
                   + (f" (with {names})" if names else "") + ":")
        shown = f.latex.replace("%", "\\%")
        plain = (r.machine_read.status == "unreadable" or math_errors(shown)
                 or re.search(r"[$<>]|\n\s*\n", f.latex))  # would leave the display
        out.append(fenced(f.latex) if plain else _display(shown))
        how = "no check could decide" if r.method == "none" else f"decided by {r.method}"
        detail = r.detail[:1].upper() + r.detail[1:]
        out.append(f"Verdict: **{r.verdict}** ({how}). {markdown_text(detail)}"
                   + ("" if detail.endswith(".") else "."))
    return out


def render(read: ComponentFile, run: ComponentRun, records=()) -> str:
    """The walkthrough of a read component file and its run, as Markdown.

    Parameters
    ----------
    read : ComponentFile
        The read file.
    run : ComponentRun
        Its run (:meth:`crane_sym.components.model.Model.run`).
    records : sequence of AuditRecord, optional
        Verdicts on its formulas (:func:`crane_sym.components.file_audit.audit_file`).
    """
    model = read.model
    parts = [f"# {markdown_text(model.title or model.name)}",
             f"Drive train `{model.name}` from the component file {markdown_text(read.path.name)}, "
             "derived by crane_sym from its components: every equation below is built "
             "from the energies of the parts, none is typed in.",
             "## The components", _components(read),
             "## Symbols", *_symbols(read, run),
             "## Rigid groups", *_groups(read),
             "## Energies and forces", *_energies(read),
             "## Lagrange's equations", *_lagrange(read), *states_section(model),
             "## Modes", *_modes(run),
             "## The run", *_phases(read, run),
             "## Results", *_results(run)]
    if records:
        parts += ["## The file's formulas", *_formulas(read, records)]
    return "\n\n".join(parts) + "\n"


def _read_and_run(path: str | Path) -> tuple[ComponentFile, ComponentRun, list]:
    read = read_component_file(path)
    run = read.model.run(read.duration, read.body, read.speed, rest=read.rest)
    records = []
    if read.formulas:       # a formula it cannot check gets its verdict; an error
        from crane_sym.components.file_audit import audit_file   # here is the file's,
        records = audit_file(read)       # and ends the walkthrough as `audit FILE`
    return read, run, records


def drive_train_walkthrough(path: str | Path) -> str:
    """The Markdown walkthrough of a component file (read, derived, run, its
    formulas audited).

    Parameters
    ----------
    path : str or Path
        The component TOML file.
    """
    return render(*_read_and_run(path))


def drive_train_page(path: str | Path) -> str:
    """The printable HTML page of a component file's walkthrough, with the plot
    of its links' loads.

    Parameters
    ----------
    path : str or Path
        The component TOML file.
    """
    from crane_sym.components.report import load_figures
    from crane_sym.docs.page import render_page
    read, run, records = _read_and_run(path)
    title = read.model.title or read.model.name
    figures = []
    for k, fig in enumerate(load_figures(run, title), start=1):
        buffer = io.BytesIO()
        fig.savefig(buffer, format="png", dpi=110, metadata={"Software": None})
        figures.append((f"Figure {k}: the loads of the elastic links, spans and ground "
                        "contacts over the run",
                        buffer.getvalue()))
    return render_page(render(read, run, records), title, figures,
                       "The loads of the elastic links, spans and ground contacts over "
                       "the run, from its phases in closed form.")

