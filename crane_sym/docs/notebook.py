"""A derivation as a runnable Jupyter notebook: the walkthrough's text in
Markdown cells, and a code cell per step that shows the step crane_sym derived.

The first code cell rebuilds the whole derivation from the physics
(``registry.get``); each step's cell then shows that step's relation once, in
the walkthrough's notation (ẋ, the paper's symbols, a long form with named
quantities), and, with the values of the parameter cell (SI units), the same
relation evaluated in numbers, so a student can change a value and rerun.
``show`` returns nothing, so Jupyter shows no raw SymPy result beside it. The
notebook is written as nbformat 4 JSON by hand: writing one needs no Jupyter
package.
"""
from __future__ import annotations

import json
from typing import Any

import sympy as sp
from sympy.core.function import AppliedUndef

from crane_sym import registry
from crane_sym.audit.verdicts import AuditRecord, audit
from crane_sym.derivation import Derivation, Step
from crane_sym.docs.verdicts import Voice
from crane_sym.docs.walkthrough import (_model, handout_words, printed_blocks, printed_table,
                                        relation_tex, step_head, table_row, table_steps)
from crane_sym.latex import latex
from crane_sym.markdown import markdown_table
from crane_sym.scenes.reading import load_scene, scenes_directory
from crane_sym.symbols import PARAMETER

__all__ = ["notebook", "numbers_tex", "render_notebook", "show", "show_table"]

#: Significant digits of the numbers line.
DIGITS = 6


def numbers_tex(statement: sp.Basic, values: dict[str, float], names: dict) -> str:
    """The relation with ``values`` (SI, by symbol name) put in and evaluated to
    ``DIGITS`` significant digits; "" when no symbol of it has a value.

    A symbol the relation differentiates by, or that an unknown function takes
    (the t of x(t)), keeps its letter: the relation holds at every value of it,
    and x(0.07) with ẋ by 0.07 is no relation at all."""
    running = {v for d in statement.atoms(sp.Derivative) for v in d.variables} | {
        s for f in statement.atoms(AppliedUndef) for s in f.free_symbols}
    subs = {s: sp.Float(values[s.name]) for s in statement.free_symbols
            if s.name in values and s not in running}
    if not subs:
        return ""

    def side(expr: sp.Basic) -> str:
        expr = expr.xreplace(subs)
        try:
            expr = sp.N(expr, DIGITS)
        except Exception:   # noqa: BLE001 (a function with no evalf, e.g. inv⁻¹): its
            expr = expr.xreplace({f: sp.Float(f, DIGITS)       # numbers to the digits
                                  for f in expr.atoms(sp.Float)})
        return latex(expr, symbol_names=names)

    if isinstance(statement, sp.Equality):
        return f"{side(statement.lhs)} = {side(statement.rhs)}"
    return side(statement)


def show(step: Step, values: dict[str, float] | None = None,
         names: dict | None = None) -> None:
    """Display a step's relation once, in the walkthrough's notation, and with
    ``values`` the same relation evaluated in numbers.

    Parameters
    ----------
    step : Step
        A step of a built derivation.
    values : dict of str to float, optional
        Parameter values in SI units, by symbol name; symbols without a value
        stay symbols.
    names : dict, optional
        The paper's LaTeX names of symbols.

    Returns
    -------
    None
        Nothing, so that Jupyter adds no raw SymPy result to the cell.
    """
    from IPython.display import Math, display  # only inside a notebook

    names = dict(names or {})
    main, defs = relation_tex(step.statement, names)
    display(Math(main), metadata={"crane_sym": "relation"})
    for definition in defs:
        display(Math(r"\text{with } " + definition), metadata={"crane_sym": "named"})
    numbers = numbers_tex(step.statement, dict(values or {}), names)
    if numbers:
        display(Math(numbers), metadata={"crane_sym": "numbers"})


def show_table(d: Derivation, name: str) -> None:
    """Display a printed table of the paper once: each cell as printed beside the
    value the rebuilt derivation gives it, as a decimal to one digit more than
    printed (the handout's table, without the verdicts the audit gives).

    Parameters
    ----------
    d : Derivation
        A built derivation.
    name : str
        The table's name as its steps give it ("Table 2").

    Returns
    -------
    None
        Nothing, so that Jupyter adds no raw result to the cell.
    """
    from IPython.display import Markdown, display  # only inside a notebook

    tables, _ = table_steps(d)
    voice = Voice(d, handout_words(d.id))
    rows = [table_row(name, f, d, voice) for f in tables[name]]
    display(Markdown(markdown_table(["cell", "printed", "derived"], rows)),
            metadata={"crane_sym": "table"})


def _id(k: int) -> str:
    return f"cell-{k:04d}"


def _markdown(k: int, text: str) -> dict[str, Any]:
    return {"cell_type": "markdown", "id": _id(k), "metadata": {},
            "source": text.splitlines(keepends=True)}


def _code(k: int, source: str) -> dict[str, Any]:
    return {"cell_type": "code", "execution_count": None, "id": _id(k), "metadata": {},
            "outputs": [], "source": source.splitlines(keepends=True)}


def _scene_values(d: Derivation) -> tuple[str, dict[str, float]]:
    """The first shipped scene of the paper and its SI values (none: empty)."""
    files = sorted(scenes_directory(d.id).glob("*.toml"))
    if not files:
        return "", {}
    scene = load_scene(files[0])
    return scene.name, dict(scene.parameters)


def _parameters(d: Derivation) -> str:
    """The parameter cell: the paper's first scene, else the middle of each
    parameter's sampling range."""
    scene, given = _scene_values(d)
    lines = ["# Parameter values in SI units, by symbol name: change one and rerun the",
             "# cells below to see each step in numbers. "
             + (f"Values from the scene {scene!r}; the others at the middle of their "
                "physical range." if scene else "Each at the middle of its physical range."),
             "values = {"]
    for e in d.symbols.with_role(PARAMETER):
        if isinstance(e.expr, sp.Symbol):
            lo, hi = e.sample_range
            value = given.get(e.expr.name, float(sp.sqrt(sp.Float(lo) * sp.Float(hi))))
            what = " ".join(e.description.split())
            lines.append(f"    {e.expr.name!r}: {value:.6g},   # {e.unit}: {what}")
    lines.append("}")
    return "\n".join(lines)


def render_notebook(d: Derivation, records: list[AuditRecord] | None = None,
                    latex_names: dict | None = None, words: dict | None = None) -> str:
    """The notebook of a built derivation as nbformat 4 JSON text.

    Each step's code cell is tagged in its metadata with the step's label
    (``crane_sym_step``), so a test can compare what it shows with the step.
    ``latex_names`` and ``words`` are the paper's ``LATEX_NAMES`` and
    ``HANDOUT_WORDS``, as for :func:`crane_sym.docs.walkthrough.render`.
    """
    by_label = {r.label: r for r in records or []}
    names = dict(d.latex_names) | dict(latex_names or {})
    voice = Voice(d, dict(words or {}))
    cells: list[dict[str, Any]] = []

    def add(cell_maker, text: str) -> dict[str, Any]:
        cell = cell_maker(len(cells), text)
        cells.append(cell)
        return cell

    add(_markdown, f"# {d.title}\n\nPaper: {d.citation}\n\n"
        f"## The model\n\n{_model(d.model, voice)}")
    add(_code, "from crane_sym import registry\n"
        "from crane_sym.docs.notebook import show, show_table\n\n"
        f"d = registry.get({d.id!r})   # rebuilds every step from the physics\n"
        f"names = d.latex_names | getattr(registry.module({d.id!r}), 'LATEX_NAMES', {{}})")
    add(_code, _parameters(d))
    tables, in_table = table_steps(d)
    shown: set[str] = set()
    k = 0
    for step in d.steps:
        if step.label in in_table:     # a printed table's cell: one table for all
            name = in_table[step.label]
            if name not in shown:
                shown.add(name)
                add(_markdown, "\n\n".join(
                    printed_table(name, tables[name], d, by_label, voice)))
                cell = add(_code, f"show_table(d, {name!r})")
                cell["metadata"]["crane_sym_table"] = name
            continue
        k += 1
        text = step_head(k, step, voice) + printed_blocks(
            [f for f in d.published if f.target == step.label], by_label, names, voice,
            step)
        add(_markdown, "\n\n".join(text))
        cell = add(_code, f"show(d.step({step.label!r}), values, names)")
        cell["metadata"]["crane_sym_step"] = step.label
    notebook = {"cells": cells, "metadata": {
        "kernelspec": {"display_name": "Python 3", "language": "python", "name": "python3"},
        "language_info": {"name": "python"}}, "nbformat": 4, "nbformat_minor": 5}
    return json.dumps(notebook, indent=1, ensure_ascii=False) + "\n"


def notebook(name: str) -> str:
    """The notebook of a registered derivation, audited (see :func:`render_notebook`).

    Parameters
    ----------
    name : str
        A derivation id or paper number.
    """
    key = registry.resolve(name)
    d = registry.get(key)
    return render_notebook(d, audit(d), getattr(registry.module(key), "LATEX_NAMES", {}),
                           handout_words(key))
