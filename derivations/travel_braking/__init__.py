"""Braking of the travel mechanism of an overhead (bridge) crane.

Source: ``000_4ef6efc8a81a3b06.txt`` — V.F. Semenyuk, A.N. Vudvud, "Analytical
determination of the dynamic loads arising when the travel mechanism of an
overhead crane brakes" (Odessa National Polytechnic University; in Russian).

The paper models the drive as two masses joined by an elastic link and
reduces the system to one equation in the relative coordinate x2 − x1
(Komarov's method), eqs (1)–(14). This package rebuilds every step from the
energies and forces of that model, transcribes the printed formulas as
printed, and adds what a user of the result needs: the peak force, its time,
the dynamic factor and the velocities of the two masses.

Files:

- ``model.py``: the paper's identity, symbols, symbol table, LaTeX names, model text.
- ``steps.py``: the derivation steps (1)–(14) and beyond, in the paper's order.
- ``published.py``: the published formulas as printed (``PUBLISHED``).
- ``printed_items.py``: ``PRINTED_ITEMS``, the inventory of the print the audit's recall
  counts.
- ``outputs.py``: the Outputs for code generation and the ODE systems.
- ``bench_cases.py``: the cases the sweep and sampled-load benches run.
- ``hard_cases.py``: the seeded hard cases for ``crane-sym accuracy``.
- ``report.py``: ``scene_report`` for ``crane-sym run``.

The package does nothing on import; ``build()`` returns the ``Derivation``.
"""
from __future__ import annotations

import sympy as sp

from crane_sym.derivation import Derivation

from . import steps
from .bench_cases import SAMPLED_BENCH_CASES, SWEEP_BENCH_CASES
from .hard_cases import hard_cases
from .model import AUTHORS, CITATION, ID, LATEX_NAMES, MODEL, PAPER, SYMBOLS, TITLE
from .outputs import ode_systems, outputs
from .printed_items import PRINTED_ITEMS
from .published import PUBLISHED
from .report import VALUE_UNITS, scene_report

__all__ = ["SAMPLED_BENCH_CASES", "SWEEP_BENCH_CASES", "ID", "AUTHORS", "LATEX_NAMES", "PAPER", "TITLE", "build", "hard_cases",
           "scene_report", "VALUE_UNITS"]


def build(code: bool = True) -> Derivation:
    """Rebuild eqs (1)–(14) from the energies and forces of the two-mass model.

    ``code=False`` leaves out the parts only code and the bench read (the audit's
    build, ``Derivation.code``).
    """
    d = Derivation(id=ID, paper=PAPER, title=TITLE, citation=CITATION,
                   model=MODEL, symbols=SYMBOLS, latex_names=LATEX_NAMES, code=code)
    T, V, forces = steps.energies(d)
    eq1, eq2 = steps.equations_of_motion(d, T, V, forces)              # (1)–(3)
    rel = steps.relative_equation(d, eq1, eq2)                         # (4)
    ode, free = steps.general_solution(d, rel)                         # (5)–(9)
    steps.initial_conditions(d, eq2)                                   # t = 0
    stretch, force_t = steps.integration_constants(d, ode, rel, free)  # (10)–(14)
    steps.preloaded_start(d, ode, rel)                                 # beyond the paper
    steps.peak_force(d, eq1, eq2, force_t)
    steps.velocities(d, eq1, eq2, stretch)

    d.published.extend(PUBLISHED)
    d.printed_items.extend(PRINTED_ITEMS)
    if code:
        d.outputs.extend(outputs(d, sp.sqrt(rel.omega2)))
        d.ode_systems.extend(ode_systems(eq1, eq2, rel))
    return d
