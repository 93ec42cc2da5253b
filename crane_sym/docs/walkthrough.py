"""A derivation as a Markdown walkthrough a teacher can hand out.

The walkthrough goes from the mechanical model, through every step in the
paper's order (what was done, why, the formula as the paper printed it beside
its verdict), to a summary of the verdicts. Formulas are LaTeX: ``$...$``
inline and ``$$...$$`` on lines of their own for displays. A derived number
is shown as a decimal (beside a print, to the print's digits); a long closed
form is written with named intermediate quantities (``docs.numbers``); the
verdicts are said in words (``docs.verdicts``).

Both functions are pure: they return text and neither print nor write files.
"""
from __future__ import annotations

import re

import sympy as sp

from crane_sym import registry
from crane_sym.audit.verdicts import AuditRecord, audit
from crane_sym.derivation import Derivation, Step
from crane_sym.docs.numbers import (broken_lines, decimal, escape_specials, is_number, is_value,
                                    named_lines, printed_digits)
from crane_sym.docs.verdicts import Voice, verdict_name
from crane_sym.latex import cyrillic_as_text, latex
from crane_sym.markdown import fenced, markdown_table
from crane_sym.symbols import COORDINATE, DEFINED, PARAMETER, TIME

__all__ = ["render", "walkthrough"]

#: Roles whose symbols are always listed; DEFINED ones only when a step uses them.
_LISTED_ROLES = (PARAMETER, TIME, COORDINATE)


def _tex(expr: sp.Basic, latex_names: dict) -> str:
    """LaTeX of ``expr`` as a mechanics text writes it, with the paper's names."""
    return latex(expr, symbol_names=latex_names)


def _display(tex: str) -> str:
    """A display formula with ``$$`` on lines of their own."""
    return f"$$\n{cyrillic_as_text(tex.strip())}\n$$"


def _relation(statement: sp.Basic, names: dict) -> list[str]:
    """A derived relation as displays: the relation, then "with" its named
    intermediate quantities when it is long."""
    main, defs = named_lines(statement, names)
    return [_display(main)] + (["with"] + [_display(d) for d in defs] if defs else [])


def _cell(text: str) -> str:
    """Text safe inside a Markdown table cell."""
    return " ".join(str(text).split()).replace("|", r"\|")


def _math_cell(tex: str) -> str:
    """Inline math safe inside a table cell (``|`` written as ``\\vert``)."""
    return "$" + " ".join(cyrillic_as_text(tex).split()).replace("|", r"\vert ") + "$"


def _model(model: str, voice: Voice | None = None) -> str:
    """The model: prose paragraphs as text (in the handout's words), indented
    paragraphs (the diagram) verbatim in a code block."""
    blocks = []
    for para in re.split(r"\n[ \t]*\n", model.strip("\n")):
        lines = [line.rstrip() for line in para.split("\n")]
        if not any(lines):
            continue
        if all(line[:1] in (" ", "\t") for line in lines if line):
            blocks.append(fenced("\n".join(lines)))
        else:
            text = " ".join(line.strip() for line in lines if line.strip())
            blocks.append(voice.say(text) if voice else text)
    return "\n\n".join(blocks)


def _symbols(d: Derivation, latex_names: dict) -> str:
    """Table of the symbols the student meets (unused defined ones skipped); two
    symbols a paper writes alike, in one unit, share a row with both meanings."""
    rows: list[list[str]] = []
    by_tex: dict[tuple[str, str], list[str]] = {}
    for entry in d.symbols:
        used = entry.role in _LISTED_ROLES or (
            entry.role == DEFINED and any(s.statement.has(entry.expr) for s in d.steps))
        if used:
            tex = _tex(entry.expr, latex_names)
            if isinstance(entry.expr, sp.core.function.AppliedUndef):
                tex += r"(" + ", ".join(latex(a) for a in entry.expr.args) + ")"
            key = (_math_cell(tex), _cell(entry.unit))
            if key in by_tex:
                by_tex[key][1] += "; " + _cell(entry.description)
                continue
            by_tex[key] = [key[0], _cell(entry.description), key[1]]
            rows.append(by_tex[key])
    return markdown_table(["Symbol", "Meaning", "Unit"], rows)


def _printed_display(f) -> list[str]:
    """The paper's LaTeX as printed (TeX specials escaped, broken into lines)."""
    return [_display("\n".join(broken_lines(escape_specials(f.latex))))]


def _inline_print(f) -> bool:
    """A printed number (``0,90``, ``5%``) goes on the line that introduces it, and
    needs no transcription beside it."""
    return (is_value(f.printed) and not f.reconstructed
            and re.fullmatch(r"\s*-?[\d.,]+\s*(%|\\%)?\s*", f.latex) is not None)


def _transcribed(f, step: Step | None, names: dict) -> list[str]:
    """A transcription as displays: a printed number to its digits, a relation the
    same as the step's in words, else the relation (named quantities if long)."""
    relation = f.printed
    if step is not None and relation == step.statement:
        return ["(the relation derived above)"]
    if is_value(relation):
        places = printed_digits(relation.rhs, f.tolerance)
        return [_display(f"{_tex(relation.lhs, names)} = {decimal(relation.rhs, places)}")]
    if step is not None and named_lines(relation, names) == named_lines(step.statement, names):
        return ["(the relation derived above)"]
    return _relation(relation, names)


def printed_blocks(formulas: list, by_label: dict[str, AuditRecord], names: dict,
                   voice: Voice, step: Step | None = None) -> list[str]:
    """The paper's print of each formula with its verdict; a print rebuilt from
    OCR damage shows the OCR as text, then the reconstruction and why."""
    blocks = []
    for f in formulas:
        label = voice.say(f.label if f.label.startswith("(") else f"({f.label})")
        note = voice.say(f.provenance.partition("; ")[2])
        if _inline_print(f):
            blocks.append(f"**As printed in the paper** {label}: "
                          f"${escape_specials(f.latex.strip())}$")
        elif f.verbatim or (f.reconstructed and f.printed is not None):
            blocks.append(f"**As printed in the paper** {label}"
                          + (", the OCR verbatim:" if f.reconstructed else ":"))
            blocks.append(fenced(f.latex.strip()))
            if f.printed is not None:
                shown = _transcribed(f, step, names)
                head = ((f"**Read as** (a reconstruction; {note})" if note else
                         "**Read as** (a reconstruction)")
                        if f.reconstructed else "Transcribed")
                if shown[0].startswith("("):
                    blocks.append(f"{head}: {shown[0][1:-1]}.")
                else:
                    blocks += [head + ":"] + shown
        else:
            blocks.append(f"**As printed in the paper** {label}:")
            blocks += _printed_display(f)
        if f.label in by_label:
            blocks.append("\n".join(voice.verdict_lines(by_label[f.label], f)))
    return blocks


def step_head(k: int, step: Step, voice: Voice) -> list[str]:
    """Heading, what was done and why, of step ``k`` (walkthrough and notebook)."""
    head = [f"### Step {k} — {voice.say(step.label)}"
            + (f" · {voice.say(step.title)}" if step.title else ""),
            f"**What was done.** {voice.say(step.how)}"]
    return head + ([f"**Why.** {voice.say(step.why)}"] if step.why else [])


def relation_tex(statement: sp.Basic, names: dict) -> tuple[str, list[str]]:
    """A step's relation as LaTeX: a number as its decimal (with its exact form
    when that is short), a long closed form with named quantities (then their
    definitions)."""
    if is_value(statement):
        value, lhs = statement.rhs, _tex(statement.lhs, names)
        if value.is_Integer or (value.is_Rational and printed_digits(value) <= 4):
            return f"{lhs} = {decimal(value, printed_digits(value))}", []
        exact = _tex(value, names)
        short = len(re.findall(r"\d", exact)) <= 8 and len(exact) <= 40
        shown = f" = {exact}" if short and not value.has(sp.Float) else ""
        return f"{lhs}{shown} \\approx {decimal(value)}", []
    return named_lines(statement, names)


def step_relation(step: Step, names: dict) -> list[str]:
    """A step's relation as displays (``relation_tex``), "with" its named
    quantities."""
    main, defs = relation_tex(step.statement, names)
    return [_display(main)] + (["with"] + [_display(d) for d in defs] if defs else [])


_TABLE_STEP = re.compile(r"^(Table \d+), ")


def _table_groups(d: Derivation) -> dict[str, list]:
    """Table name -> the printed cells checked against its steps, in order."""
    groups: dict[str, list] = {}
    for f in d.published:
        m = _TABLE_STEP.match(f.target)
        if m and f.printed is not None:
            groups.setdefault(m.group(1), []).append(f)
    return groups


def table_steps(d: Derivation) -> tuple[dict[str, list], dict[str, str]]:
    """The printed tables and the steps they take in: table name -> its printed
    cells, and step label -> table name (the steps a cell is checked against,
    as printed or as read). A handout shows such steps as one table, not one
    step a cell (walkthrough and notebook)."""
    tables = _table_groups(d)
    in_table = {c.target: name for name, cells in tables.items() for c in cells}
    in_table |= {v.compare_to: name for name, cells in tables.items()
                 for c in cells for v in c.conventions if v.compare_to}
    return tables, in_table


#: Significant digits of the numbers in a table cell's derived value that keeps
#: a symbol (a cell read "as headed", τ_0 not given: 1 + 9.8067/τ_0).
_CELL_DIGITS = 5


def table_number(step: Step, f) -> str:
    """A table cell's derived value, to the digits of its print; one that keeps a
    symbol with its numbers as decimals, not as exact fractions."""
    value = step.statement.rhs
    if not is_number(value):
        return "$" + latex(value.xreplace({r: sp.Float(r, _CELL_DIGITS)
                                           for r in value.atoms(sp.Rational)
                                           if not r.is_Integer})) + "$"
    places = printed_digits(f.printed.rhs, f.tolerance) if is_number(f.printed.rhs) else None
    return f"${decimal(value, None if places is None else places + 1)}$"


def table_row(name: str, f, d: Derivation, voice: Voice) -> list[str]:
    """A printed table's cell as a row: the cell's name, its print, its derived
    value (``table_number``)."""
    return [_cell(voice.say(f.label.removeprefix(name + ", "))),
            _cell(f.latex) if f.verbatim else _math_cell(escape_specials(f.latex)),
            table_number(d.step(f.target), f)]


def printed_table(name: str, cells: list, d: Derivation, by_label: dict[str, AuditRecord],
                  voice: Voice) -> list[str]:
    """A printed table as one table: each cell beside its derived value (one digit
    more than printed) and verdict."""
    readings = any(f.conventions for f in cells)
    header = ["cell", "printed", "derived", *(["derived, read as noted"] if readings else []),
              "verdict", "cause"]
    rows = []
    for f in cells:
        r = by_label.get(f.label)
        row = table_row(name, f, d, voice)
        if readings:
            row.append(table_number(d.step(f.conventions[0].compare_to or f.target), f)
                       if f.conventions else "—")
        row += [verdict_name(r.verdict) if r else "not audited",
                voice.letter(r) if r and r.cause else "—"]
        rows.append(row)
    notes = {f.conventions[0].note for f in cells if f.conventions}
    out = [f"### {name}", markdown_table(header, rows)]
    out += [f"*Read as noted:* {voice.say(n)}." for n in sorted(notes)]
    return out + _first_causes([r for f in cells if (r := by_label.get(f.label))], voice)


def _not_checkable(formulas: list, by_label: dict[str, AuditRecord],
                   voice: Voice) -> list[str]:
    """Printed items with nothing to check (inputs, claims in general) as one
    table: the item, its print and its cause; each cause said once below."""
    rows = [[_cell(voice.say(f.label)),
             _cell(" ".join(f.latex.split())) if f.verbatim
             else _math_cell(escape_specials(f.latex.strip())),
             voice.letter(r) if (r := by_label[f.label]).cause else "—"] for f in formulas]
    return (["### Printed items with nothing to check",
             markdown_table(["item", "printed", "cause"], rows)]
            + _first_causes([by_label[f.label] for f in formulas], voice))


def _first_causes(records: list[AuditRecord], voice: Voice) -> list[str]:
    """The sentence of each cause whose first record is among ``records``."""
    return [f"*Cause {voice.causes[r.cause.id]}:* {voice.say(r.cause.sentence)}"
            for r in records if r.cause and voice.cause_first.get(r.cause.id) == r.label]


def render(d: Derivation, records: list[AuditRecord] | None = None,
           latex_names: dict | None = None, words: dict | None = None) -> str:
    """The walkthrough of a derivation as Markdown with LaTeX.

    Parameters
    ----------
    d : Derivation
        The built derivation.
    records : list of AuditRecord, optional
        Verdicts from :func:`crane_sym.audit.verdicts.audit`; without them the printed
        formulas are shown without verdicts and the summary says "not audited".
    latex_names : dict, optional
        Map from SymPy symbol to the LaTeX the paper uses for it.
    words : dict of str to str, optional
        The paper's ``HANDOUT_WORDS``: the words a reader gets for a code name
        in its labels and notes.

    Returns
    -------
    str
        Markdown: title, model, symbols, every step in order (numbered without
        gaps), verdicts.
    """
    names = dict(d.latex_names) | dict(latex_names or {})
    voice = Voice(d, dict(words or {}))
    by_label = {r.label: r for r in records or []}
    tables, in_table = table_steps(d)
    shown: set[str] = set()
    parts = [f"# {d.title}", f"Paper: {d.citation}",
             "## The model", _model(d.model, voice),
             "## Symbols", _symbols(d, names),
             "## Derivation"]
    k = 0
    for step in d.steps:
        if step.label in in_table:              # a table cell: one table for all
            name = in_table[step.label]
            if name not in shown:
                shown.add(name)
                parts += printed_table(name, tables[name], d, by_label, voice)
            continue
        k += 1
        parts += step_head(k, step, voice)
        parts += step_relation(step, names)
        parts += printed_blocks([f for f in d.published if f.target == step.label
                                 and f.target not in in_table], by_label, names, voice, step)
    labels = {s.label for s in d.steps}
    orphans = [f for f in d.published if f.target not in labels]
    idle = [f for f in orphans if (r := by_label.get(f.label)) and r.verdict == "not_checkable"]
    if len(idle) < len(orphans):
        parts.append("### Printed formulas without a derived step")
        parts += printed_blocks([f for f in orphans if f not in idle], by_label, names, voice)
    if idle:
        parts += _not_checkable(idle, by_label, voice)
    parts += ["## Verdicts"] + voice.table(records)
    return "\n\n".join(parts) + "\n"


def handout_words(key: str) -> dict[str, str]:
    """The registered paper's ``HANDOUT_WORDS`` (empty when it declares none)."""
    return dict(getattr(registry.module(key), "HANDOUT_WORDS", {}))


def walkthrough(name: str) -> str:
    """The walkthrough of a registered derivation, audited.

    Parameters
    ----------
    name : str
        A derivation id or paper number accepted by
        :func:`crane_sym.registry.resolve`.

    Returns
    -------
    str
        :func:`render` of the built derivation, with its audit records, the
        module's ``LATEX_NAMES`` and ``HANDOUT_WORDS`` (empty when it defines none).
    """
    key = registry.resolve(name)
    d = registry.get(key)
    latex_names = getattr(registry.module(key), "LATEX_NAMES", {})
    return render(d, audit(d), latex_names, handout_words(key))
