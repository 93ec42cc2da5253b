"""A drive train's walkthrough, its modes and phases: each mode the run
passes through in words with its x' = A x + b (wide matrices by column
blocks), its natural frequencies, and the phases of the run with their event
times; and the table helpers the walkthrough's other sections share.

:mod:`crane_sym.docs.drive_train` puts these sections in the page.
"""
from __future__ import annotations

from crane_sym.components.hybrid import BACKWARD, FORWARD, HELD, ComponentSystem, Mode
from crane_sym.components.model import ComponentRun
from crane_sym.components.component_file import ComponentFile
from crane_sym.docs.drive_train_states import limit_words, state_names
from crane_sym.docs.rows import column_blocks
from crane_sym.docs.walkthrough import _display, _math_cell
from crane_sym.latex import latex
from crane_sym.markdown import markdown_table, markdown_text
from crane_sym.scenes.panels import format_quantity

__all__ = ["describe_mode"]


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
    for brake, on, ramp in zip(system.of_kind["brake"], mode.engaged, mode.ramping):
        words.append(f"{brake.part.name} " + (("building up" if ramp or
                                               brake.part.build_up == "exponential"
                                               else "engaged") if on else "off"))
    for g, motion in enumerate(mode.motion):
        if motion == HELD:
            words.append(f"group {a.groups[g].name} held by its brakes")
        elif motion in (FORWARD, BACKWARD):
            words.append(f"group {a.groups[g].name} sliding {motion}")
    for motor, on in zip(system.of_kind["motor"], mode.driven):
        words.append(f"{motor.part.name} {'on' if on else 'off'}")
    for law, k in zip(system.of_kind["characteristic"], mode.steps):
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
    names += ["\\beta_{\\mathrm{" + system.of_kind["brake"][i].part.name.replace("_", "\\_") + "}}"
              for i in sorted(system.beta)]
    for law in system.clock.laws:        # w_j = τ^j of the law's current piece
        upright = "\\mathrm{" + law.name.replace("_", "\\_") + "}"
        names += [f"w_{{{upright},{j}}}" for j in range(1, law.degree + 1)]
    names += state_names(system)
    return ", ".join(f"$x_{{{k}}} = {n}$" for k, n in enumerate(names, start=1))


def _modes(run: ComponentRun) -> list[str]:
    system = run.system
    parts = system.of_kind
    out: list[str] = []
    lines = [f"{l.part.name}: {', '.join(l.part.contacts)}" for l in system.backlash]
    lines += [f"{b.part.name} on {b.part.body}: off, then engaged"
              + ("" if b.part.build_up == "step" else f", building up ({b.part.build_up})")
              for b in parts["brake"]]
    lines += [f"{m.part.name}: on, off" for m in parts["motor"] if m.part.off_at is not None]
    lines += [f"{c.part.name}: {len(c.part.slopes)} steps" for c in parts["characteristic"]]
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
