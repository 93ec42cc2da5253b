"""A component model's run as a generated NumPy module, through the route every
piecewise-linear run takes to a scene's module: the run replayed in mpmath
(:func:`crane_sym.mechanics.exact_phases.exact_table`), each elastic link's
load as a table of closed forms, one per phase, printed by
:func:`crane_sym.codegen.tabulated.render_tabulated`.

The module's header names the model and how to write it again; the model's
name and title, text a user gave, reach it only through
``docstring_text`` (in the docstring) and ``repr`` (as constants).
"""
from __future__ import annotations

import sympy as sp

from crane_sym import __version__
from crane_sym.codegen.module import _kernel_source, docstring_text
from crane_sym.codegen.tabulated import render_tabulated
from crane_sym.components.model import ComponentRun
from crane_sym.derivation import TabulatedOutput
from crane_sym.mechanics.exact_phases import exact_table

__all__ = ["module_name", "render_component_module"]


def module_name(run: ComponentRun) -> str:
    """File name of the model's module."""
    return f"model_{run.model.name}.py"


def render_component_module(run: ComponentRun) -> str:
    """Source of the module of ``run``: ``load_<link>(t)`` for every elastic
    link (pure; deterministic: the tables come from the mpmath replay)."""
    model = run.model
    outputs = []
    for peak in run.peaks:
        out = TabulatedOutput(f"load_{peak.link}", (), ("component model",),
                              f"Load of the elastic link {peak.link} over the run.", peak.unit,
                              lambda values, options, link=peak.link: run.hybrid_run(link))
        outputs.append((out, exact_table(run.hybrid_run(peak.link))))
    note = ("Solved for this model phase by phase in mpmath "
            "(crane_sym.mechanics.exact_phases).")
    functions = ["\n" + render_tabulated(o, table, note) for o, table in outputs]
    listing = "\n".join(f"    {o.name}(t) -> [{o.unit}]" for o, _ in outputs)
    header = (f'"""Numeric functions of the component model {docstring_text(model.name)!s}. '
              "Generated; do not edit.\n\n"
              f"{docstring_text(model.title)}\n"
              f"Printed by SymPy {sp.__version__} with crane_sym {__version__}; regenerate "
              "with `crane-sym run FILE --out <folder>`.\n\n"
              f"Functions and argument order:\n{listing}\n"
              '"""\n')
    names = ", ".join(repr(o.name) for o, _ in outputs)
    constants = f"MODEL_NAME = {model.name!r}\nMODEL_TITLE = {model.title!r}\n"
    parts = [header, "import numpy as np\n", f"__all__ = [{names}]\n\n{constants}",
             "\n" + _kernel_source(functions), *functions]
    return "\n".join(parts)
