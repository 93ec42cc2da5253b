"""Every paper's notebook runs top to bottom, each step's cell shows the step once
in the walkthrough's notation with its numbers, and no cell shows raw SymPy."""
from __future__ import annotations

import json

import pytest
import sympy as sp

nbclient = pytest.importorskip("nbclient")
nbformat = pytest.importorskip("nbformat")

from crane_sym import registry  # noqa: E402
from crane_sym.audit.verdicts import audit  # noqa: E402
from crane_sym.docs.notebook import numbers_tex, render_notebook  # noqa: E402
from crane_sym.docs.walkthrough import handout_words, relation_tex, table_steps  # noqa: E402


#: What raw SymPy output looks like in a cell: its repr, its default LaTeX.
RAW = ("Eq(", "Derivative(", "Symbol(", r"\frac{d}{d t}", r"{\left(t \right)}")


@pytest.mark.parametrize("paper", registry.ids())
def test_notebook_executes_and_each_step_cell_shows_the_step_once(paper, tmp_path):
    """Every cell runs; a step's cell shows its relation once, in the walkthrough's
    notation (ẋ, the paper's symbols), then its numbers; no cell shows raw SymPy."""
    d = registry.get(paper)
    names = d.latex_names | getattr(registry.module(paper), "LATEX_NAMES", {})
    text = render_notebook(d, audit(d), names, handout_words(paper))
    nb = nbformat.reads(text, as_version=4)
    nbformat.validate(nb)
    nbclient.NotebookClient(nb, timeout=600, kernel_name="python3",
                            resources={"metadata": {"path": str(tmp_path)}}).execute()
    tables, in_table = table_steps(d)
    checked, shown_tables = 0, []
    for cell in nb.cells:
        for out in cell.get("outputs", []):
            assert out.output_type != "error", (paper, out.get("evalue"))
            shown = json.dumps(out.get("data", {})) + out.get("text", "")
            for raw in RAW:
                assert raw not in shown, (paper, cell.metadata.get("crane_sym_step"), raw)
        table = cell.metadata.get("crane_sym_table")
        if table is not None:                  # a printed table: one cell, a row a cell
            kinds = [o.metadata.get("crane_sym") for o in cell.outputs]
            assert kinds == ["table"], (table, kinds)
            rows = cell.outputs[0].data["text/markdown"].splitlines()[2:]
            assert len(rows) == len(tables[table]), table
            shown_tables.append(table)
        label = cell.metadata.get("crane_sym_step")
        if label is None:
            continue
        assert not [o for o in cell.outputs if o.output_type == "execute_result"], label
        kinds = [o.metadata.get("crane_sym") for o in cell.outputs]
        assert kinds.count("relation") == 1, (label, kinds)
        main, defs = relation_tex(d.step(label).statement, names)
        assert main in cell.outputs[kinds.index("relation")].data["text/latex"], label
        assert kinds.count("named") == len(defs), label
        checked += 1
    assert checked == len([s for s in d.steps if s.label not in in_table])
    assert shown_tables == list(tables)


def test_a_printed_table_is_one_cell_of_decimals():
    """002's Tables 1 and 2 (95 printed cells, 177 steps) are two tables, each one
    Markdown cell and one code cell, not one step a cell; a derived value that
    keeps τ_0 shows its numbers as decimals, not as exact fractions."""
    d = registry.get("002")
    nb = json.loads(render_notebook(d, audit(d)))
    sources = ["".join(c["source"]) for c in nb["cells"]]
    tables, in_table = table_steps(d)
    assert list(tables) == ["Table 1", "Table 2"] and len(in_table) == 175
    assert [s.split("\n")[0] for s in sources if s.startswith("### Table")] == [
        "### Table 1", "### Table 2"]
    assert [c["metadata"].get("crane_sym_table") for c in nb["cells"]
            if "crane_sym_table" in c["metadata"]] == ["Table 1", "Table 2"]
    assert not any("Table 2, k" in s for s in sources if s.startswith("### Step"))
    assert len(nb["cells"]) == 3 + 2 * (len(d.steps) - len(in_table)) + 2 * len(tables)
    table2 = next(s for s in sources if s.startswith("### Table 2"))
    assert r"1 + \frac{9.8067}{\tau_{0}}" in table2 and "196133" not in table2


def test_a_changed_value_reaches_the_numbers(tmp_path):
    d = registry.get("000")
    nb = nbformat.reads(render_notebook(d), as_version=4)
    params = nb.cells[2]
    assert "'m1': 4400" in params.source
    params.source = params.source.replace("'m1': 4400", "'m1': 1234.5")
    nbclient.NotebookClient(nb, timeout=600, kernel_name="python3").execute()
    numbers = [o.data["text/latex"] for c in nb.cells
               if c.metadata.get("crane_sym_step") == "(4)"
               for o in c.outputs if o.output_type == "display_data"]
    omega2 = 3e6 * (1234.5 + 110e3) / (1234.5 * 110e3)        # c (m1 + m2)/(m1 m2)
    assert len(numbers) == 2 and f"{omega2:.6g}" in numbers[1]


def test_the_variable_of_a_derivative_keeps_its_letter():
    """A value given for t is not put into x(t) and its derivatives (003's t of
    (1)-(2) is in the parameter table); the other values are."""
    t, m, b = sp.symbols("t m b")
    x = sp.Function("x")(t)
    values = {"t": 0.07, "m": 2.0, "b": 3.0}
    assert numbers_tex(sp.Eq(m * x.diff(t, 2), -b * x.diff(t)), values, {}) \
        == r"2.0 \ddot{x} = - 3.0 \dot{x}"
    assert numbers_tex(sp.Eq(m * t, b), values, {}) == "0.14 = 3.0"


def test_an_exact_number_is_shown_evaluated(tmp_path):
    """A step whose relation is a number shows its decimal (001's MF of Table 1 is
    0.9034, not 274576/303951), and its cell shows nothing more."""
    d = registry.get("001")
    nb = nbformat.reads(render_notebook(d), as_version=4)
    nbclient.NotebookClient(nb, timeout=600, kernel_name="python3").execute()
    cell = next(c for c in nb.cells
                if c.metadata.get("crane_sym_step") == "MF rated load, totals")
    assert [o.data["text/latex"] for o in cell.outputs] == [
        r"$\displaystyle N \approx 0.9034$"]


def test_the_notebook_is_plain_json_and_deterministic():
    d = registry.get("000")
    a, b = render_notebook(d), render_notebook(d)
    assert a == b and json.loads(a)["nbformat"] == 4
