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

from crane_sym.components.hybrid import BACKWARD, FORWARD, HELD, ComponentSystem, Mode
from crane_sym.components.kinds import by_table
from crane_sym.components.model import ComponentRun
from crane_sym.components.parts import ComponentError
from crane_sym.components.quantities import derived_quantity, parameters, static_loads
from crane_sym.components.reading import ComponentFile, read_component_file
from crane_sym.docs.drive_train_states import limit_words, state_names, states_section
from crane_sym.docs.numbers import math_errors
from crane_sym.docs.rows import aligned_rows, column_blocks, sum_terms
from crane_sym.docs.walkthrough import _display, _math_cell
from crane_sym.latex import latex
from crane_sym.markdown import fenced, markdown_table, markdown_text
from crane_sym.scenes.panels import format_quantity

__all__ = ["drive_train_page", "drive_train_walkthrough", "render"]

#: Significant digits of the numbers in A and b.
MATRIX_DIGITS = 4
#: Significant digits of event times.
TIME_DIGITS = 9


class _Markup(str):
    """A table cell that is Markdown already: math, or the parts' checked names
    with math (``components.reading``'s ``_SAFE_NAME``)."""


def _math(tex: str) -> _Markup:
    """Inline math for a table cell."""
    return _Markup(_math_cell(tex))


def _table(header: list[str], rows: list[list[str]]) -> str:
    """A Markdown table whose text cells are text (:func:`markdown_text`: a
    ``*`` in ``N*m*s/rad`` as written, a ``<`` from a file as a ``<``); math
    and other :class:`_Markup` cells as they are."""
    return markdown_table(header, [[c if isinstance(c, _Markup) else markdown_text(c)
                                    for c in row] for row in rows])


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


def describe_mode(system: ComponentSystem, mode: Mode) -> str:
    """A mode in words: the gaps, the brakes, the groups held or sliding, the motors."""
    a = system.assembly
    words = []
    for j, (link, c) in enumerate(zip(system.backlash, mode.contacts)):
        if j in mode.cut or not link.part.opens:
            words.append(f"{link.part.name} " + ("cut" if j in mode.cut else "intact"))
        elif link.part.slack is not None:
            words.append(f"{link.part.name} " + ("taut" if c > 0 else "slack"))
        else:
            words.append(f"{link.part.name} " + ("on its upper flank" if c > 0 else
                                                 "on its lower flank" if c < 0 else "in its gap"))
    for brake, on, ramp in zip(system.brakes, mode.engaged, mode.ramping):
        words.append(f"{brake.part.name} " + (("building up" if ramp or
                                               brake.part.build_up == "exponential"
                                               else "engaged") if on else "off"))
    for g, motion in enumerate(mode.motion):
        if motion == HELD:
            words.append(f"group {a.groups[g].name} held by its brakes")
        elif motion in (FORWARD, BACKWARD):
            words.append(f"group {a.groups[g].name} sliding {motion}")
    for motor, on in zip(system.motors, mode.driven):
        words.append(f"{motor.part.name} {'on' if on else 'off'}")
    for law, k in zip(system.characteristics, mode.steps):
        words.append(f"{law.part.name} on step {k + 1}")
    return "; ".join(words + limit_words(system, mode)) or "one mode"


def _number(x: float) -> str:
    if x == 0:
        return "0"
    text = f"{x:.{MATRIX_DIGITS}g}"
    if "e" in text:
        mantissa, exponent = text.split("e")
        return f"{mantissa} \\cdot 10^{{{int(exponent)}}}"
    return text


def _matrices(A, b) -> list[str]:
    """A and b as displays: A whole while it fits the page, else by blocks of
    its columns (each said with the states it multiplies)."""
    numbers = [[_number(float(x)) for x in row] for row in A]
    blocks = column_blocks("A", numbers)
    column = column_blocks("b", [[_number(float(x))] for x in b])[0][1]
    if len(blocks) == 1:
        return [_display(f"{blocks[0][1]}, \\quad {column}")]
    out = [f"$A$ has {len(numbers[0])} columns, one for each entry of $x$; shown "
           f"{blocks[0][0].stop} at most at a time:"]
    for cols, tex in blocks:
        out += [f"columns {cols.start + 1}–{cols.stop} (of $x_{{{cols.start + 1}}}$ to "
                f"$x_{{{cols.stop}}}$):" if len(cols) > 1 else f"column {cols.start + 1}:",
                _display(tex)]
    return out + [_display(column)]


def _state(system: ComponentSystem) -> str:
    """The entries of the state x, numbered, each its own piece of math (a line
    of the page may break between them)."""
    eq = system.equations
    names = []
    for q in eq.coordinates:
        names += [latex(q, symbol_names=eq.latex_names),
                  latex(q.diff(eq.t), symbol_names=eq.latex_names)]
    names += ["\\beta_{\\mathrm{" + system.brakes[i].part.name.replace("_", "\\_") + "}}"
              for i in sorted(system.beta)]
    for law in system.clock.laws:        # w_j = τ^j of the law's current piece
        upright = "\\mathrm{" + law.name.replace("_", "\\_") + "}"
        names += [f"w_{{{upright},{j}}}" for j in range(1, law.degree + 1)]
    names += state_names(system)
    return ", ".join(f"$x_{{{k}}} = {n}$" for k, n in enumerate(names, start=1))


def _modes(run: ComponentRun) -> list[str]:
    system = run.system
    out: list[str] = []
    lines = [f"{l.part.name}: {', '.join(l.part.contacts)}" for l in system.backlash]
    lines += [f"{b.part.name} on {b.part.body}: off, then engaged"
              + ("" if b.part.build_up == "step" else f", building up ({b.part.build_up})")
              for b in system.brakes]
    lines += [f"{m.part.name}: on, off" for m in system.motors if m.part.off_at is not None]
    lines += [f"{c.part.name}: {len(c.part.slopes)} steps" for c in system.characteristics]
    braked = sorted({system.assembly.groups[g].name for g in system.brake_group})
    lines += [f"group {name}: free, sliding against its brakes, held" for name in braked]
    lines += [f"{limit.name}: within its limit, at it (integral frozen, then tracking)"
              for limit in system.limits]
    out.append("What switches: " + ("; ".join(lines) if lines else "nothing (one mode)")
               + ". A group held by its brakes has $\\dot q = 0$ until its load exceeds "
               "what they hold; a sliding group feels their friction against its motion.")
    first = "; then the parts' first-order states" if system.equations.states else ""
    out.append(f"The state is $x$: {_state(system)} (each group's coordinate and speed, "
               "then the build-up $0 \\le \\beta \\le 1$ of each brake that does not act at "
               "once, then for each law in time of degree $K$ the clock states "
               "$w_j = \\tau^j$, $j = 1 \\ldots K$, of the time $\\tau$ since its piece began: "
               "$w_j' = j\\,w_{j-1}$, restarted at every breakpoint, so the law stays "
               f"linear in the state{first}). Each mode the run passes through, with "
               f"$x' = A x + b$ in SI units ({MATRIX_DIGITS} significant digits):")
    seen = []
    for seg in run.result.segments:
        if seg.mode in seen:
            continue
        seen.append(seg.mode)
        A, b = system.matrices(seg.mode)
        out.append(f"**Mode {len(seen)}:** {markdown_text(describe_mode(system, seg.mode))}.")
        out += _matrices(A, b)
        out.append(_frequencies(A))
    return out


def _frequencies(A) -> str:
    """The eigenvalues of A in words: the damped angular frequencies and decay
    rates of the mode's oscillations (a mode without any: its rigid motion)."""
    import numpy as np
    roots = np.linalg.eigvals(A)
    scale = float(np.max(np.abs(roots), initial=0.0))     # a rigid motion's double zero
    waves = sorted({(round(float(-r.real), 9), round(float(r.imag), 9))   # splits by
                    for r in roots if r.imag > 1e-6 * scale}, key=lambda w: w[1])  # rounding
    if not waves:
        return "No oscillation in this mode (A has real eigenvalues only)."
    said = ", ".join(f"ω = {_plain(w)} rad/s" + (f" decaying at {_plain(n)} 1/s" if n else "")
                     for n, w in waves)
    return f"Its oscillations (eigenvalues −n ± iω of A): {said}."


def _plain(x: float) -> str:
    return f"{x:.{MATRIX_DIGITS}g}"


def _phases(read: ComponentFile, run: ComponentRun) -> list[str]:
    modes: list = []
    for seg in run.result.segments:
        if seg.mode not in modes:
            modes.append(seg.mode)
    rows = [[str(k), format_quantity(seg.t0, "s", TIME_DIGITS),
             format_quantity(seg.t1, "s", TIME_DIGITS), str(modes.index(seg.mode) + 1),
             seg.event if seg.event != "end" else "end of the run"]
            for k, seg in enumerate(run.result.segments, start=1)]
    body = read.body or next(iter(read.model.assembly.bodies))
    start = ("at rest, every link at zero twist and every gap open" if read.rest
             else f"in its steady motion ({body} at {read.speed}, every group at the speed "
                  "that implies, every link at the twist that balances the loads)")
    given = ["; ".join(f"{s.part.body} {k} {getattr(s.part, k).text}" for k in
                       ("displacement", "velocity") if getattr(s.part, k) is not None)
             for s in read.model.initial]
    if given:
        start += markdown_text(f", then given its initial states ({'; '.join(given)})")
    instants = [k for k, seg in enumerate(run.result.segments, start=1) if seg.t1 == seg.t0]
    note = ("" if not instants else
            f" A phase of zero length ({', '.join(map(str, instants))}) is an instant at "
            "which one event follows another at once.")
    return [f"The run starts {start} and is solved phase by phase in closed form: in "
            "each phase the mode is fixed and $x(t)$ is the exact solution of "
            "$x' = A x + b$; a phase ends at the first event (a gap closing or opening, a "
            "group coming to rest or slipping, a body lifting off the ground or set down "
            "on it, a brake engaging, a motor switched off), "
            f"found on that closed form.{note}",
            _table(["phase", "from", "to", "mode", "ended by"], rows)]


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
        figures.append((f"Figure {k}: the loads of the elastic links over the run",
                        buffer.getvalue()))
    return render_page(render(read, run, records), title, figures,
                       "The loads of the elastic links over the run, from its phases "
                       "in closed form.")

