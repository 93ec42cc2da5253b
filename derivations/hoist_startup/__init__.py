"""Duhamel's integral for the start-up of a crane hoist: rope loads and dynamic factors.

Source: ``002_f8509f3826f601de.txt`` — Yu. Chovnyuk, M. Dykteruk, S. Komotska,
"Use of Duhamel's integral in the analysis of forced vibrations and dynamic
loads of the elastic links of crane hoisting mechanisms at start-up"
(in Ukrainian).

The paper models the hoist as two masses (drive m1, load m2) joined by the
rope of stiffness C, reduces the system to one equation in the stretch
x = x1 − x2 (1)–(6), fixes the constants for lifting "with pick-up" (slack
rope) and "from weight" (preloaded rope) (7)–(14), writes the response as a
Duhamel integral (15)–(24), defines dynamic coefficients (25)–(27), the drive
laws (28)–(31), works four classic loads (32)–(53) and closes with an
Euler–Poisson "optimum" (54)–(66) and Tables 1–2.

This package rebuilds every step from the energies and forces of the model,
transcribes every printed formula, and emits the dynamic coefficient over time
for each load case and for each drive law a_i in both lifting cases. It does
nothing on import; ``build()`` returns the ``Derivation``.

- ``model.py``: ID, PAPER, TITLE, AUTHORS, symbols, symbol table, LaTeX names, the model
  text, the test laws, the print's Duhamel integrals, the drive laws of (30).
- ``steps.py``: steps (1)–(31); ``steps_load_cases.py``: (32)–(53);
  ``steps_optimum.py``: (54)–(66).
- ``published.py``: printed formulas (1)–(31); ``published_load_cases.py``:
  (32)–(53); ``published_optimum.py``: (54)–(66) and the maxima after (66).
- ``printed_items.py``: ``PRINTED_ITEMS``, the inventory of the print the audit's recall
  counts.
- ``tables.py``: Tables 1–2, derived and printed.
- ``outputs.py``: generated functions, ODE systems, bench parameters.
- ``bench_cases.py``: the cases the sweep and sampled-load benches run, and the
  hand-written NumPy floor of the piecewise target.
- ``hard_cases.py``: seeded hard cases for ``crane-sym accuracy``.
- ``report.py``: ``scene_report(scene)`` for ``crane-sym run``.
"""
from __future__ import annotations

from crane_sym.derivation import Derivation
from crane_sym.published import PublishedFormula

from .bench_cases import HAND_WRITTEN, SAMPLED_BENCH_CASES, SWEEP_BENCH_CASES
from .hard_cases import hard_cases
from .model import AUTHORS, ID, LATEX_NAMES, MODEL, PAPER, SYMBOLS, TITLE
from .drive_law_scene import DRIVE_LAW
from .options import SCENE_CHECKS, SCENE_OPTIONS
from .printed_items import PRINTED_ITEMS
from .report import VALUE_UNITS, scene_report
from .steps import (drive_laws, duhamel_integral, dynamic_coefficients,
                    equations_of_motion, initial_conditions)
from .steps_load_cases import load_cases
from .steps_optimum import optimum

#: Loads a scene may give as data (crane_sym.derivation.SceneLoad).
SCENE_LOADS = {DRIVE_LAW.table: DRIVE_LAW}

__all__ = ["ID", "PAPER", "TITLE", "AUTHORS", "HAND_WRITTEN", "LATEX_NAMES",
           "SAMPLED_BENCH_CASES",
           "SCENE_CHECKS", "SCENE_LOADS", "SCENE_OPTIONS", "SWEEP_BENCH_CASES", "build",
           "hard_cases", "published_formulas", "scene_report", "VALUE_UNITS"]


def published_formulas() -> list[PublishedFormula]:
    """Every printed formula and table cell, in the paper's order (the
    transcriptions are imported, and built, on the first call)."""
    from . import published, published_load_cases, published_optimum, tables
    return [*published.PUBLISHED, *published_load_cases.PUBLISHED,
            *published_optimum.PUBLISHED, *tables.PUBLISHED]


def build(code: bool = True) -> Derivation:
    """Rebuild eqs (1)–(66) and Tables 1–2 from the two-mass model.

    ``code=False`` leaves out the parts only code and the bench read (the audit's
    build, ``Derivation.code``).
    """
    d = Derivation(id=ID, paper=PAPER, title=TITLE,
                   citation="Yu. Chovnyuk, M. Dykteruk, S. Komotska (Kyiv)",
                   model=MODEL, symbols=SYMBOLS, latex_names=LATEX_NAMES, code=code)
    eq1, eq2 = equations_of_motion(d)
    initial_conditions(d, eq2)
    duhamel_integral(d)
    dynamic_coefficients(d, eq1, eq2)
    drive_laws(d)
    loads = load_cases(d)
    optimum(d, eq1, eq2)
    from . import outputs, tables
    tables.derive_tables(d)
    d.published.extend(published_formulas())
    d.printed_items.extend(PRINTED_ITEMS)
    if code:
        d.outputs.extend(outputs.code_outputs(d, loads))
        outputs.attach(d)   # ODE systems and bench parameters for `crane-sym bench`
    return d
