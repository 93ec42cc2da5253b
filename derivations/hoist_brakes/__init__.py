"""Hoists with safety brakes: gearbox torque in an emergency stop.

Source: ``001_544065b666a6bc39.txt`` — S. Vöth, M.A. Tyulenev, "Hoists with
safety brakes" (Kuzbass State Technical University, 2016; in Russian).

The paper cuts a hoist drive at the gearbox input and gives the relative
gearbox torque of the rigid drive (2)–(5) in the inertia factor MF, the load
factor LF, the safety-brake factor BF_SB and the dynamic factor φ5 of EN
13001-2, an elasto-kinetic peak with backlash (Fig. 9), and coordinated brake
factors (6)–(7) (Figs 11–12). Its formulas are badly damaged by OCR: this
package rebuilds them from the physics of Table 1's hoist, keeps the OCR
beside each labelled reconstruction, and checks every printed number.

Files:

- ``model.py``: identity, symbols, Table 1, model text.
- ``steps.py``: kinematics, reduced inertia, static torque, (1)–(7).
- ``steps_numbers.py``: the printed numbers from Table 1, one step per reading.
- ``drive_train.py``: the hoist of Fig. 9 as components (``crane_sym.components``):
  the one hybrid model of the emergency stop with coupling backlash.
- ``elastic.py``: Fig. 9's peak as steps, from that model.
- ``elastic_batched.py``: the same model reduced to the motor shaft for an array of
  designs (the batched solver); its per-design route the reduced model as components.
- ``hybrid.py``: ``HYBRID_MODELS``, that run as scenes, sweeps and the bench reach it.
- ``published.py``: the printed formulas and numbers (``PUBLISHED``).
- ``printed_items.py``: ``PRINTED_ITEMS``, the inventory of the print the audit's recall
  counts, and Table 1's cells as printed.
- ``outputs.py``: the Outputs for code generation (and the tabulated Fig. 9 response).
- ``hard_cases.py``: the seeded hard cases for ``crane-sym accuracy``.
- ``options.py``: ``SCENE_OPTIONS``, ``SCENE_CHECKS``.
- ``report.py``: ``scene_report`` for ``crane-sym run``.
- ``sweep_outputs.py``: ``SWEEP_OUTPUTS``, the Fig. 9 peak for design sweeps.
- ``bench_cases.py``: ``BATCHED_BENCH_CASES``, the Fig. 9 peak's batched bench.

The package does nothing on import; ``build()`` returns the ``Derivation``.
"""
from __future__ import annotations

import sympy as sp

from crane_sym.derivation import Derivation

from . import elastic, steps, steps_numbers
from .bench_cases import BATCHED_BENCH_CASES
from .hard_cases import hard_cases
from .hybrid import HYBRID_MODELS
from .model import (AUTHORS, BF_SB, CITATION, HANDOUT_WORDS, ID, LATEX_NAMES, LF, MF, MODEL, PAPER, SYMBOLS,
                    TITLE, phi5)
from .options import SCENE_CHECKS, SCENE_OPTIONS
from .outputs import outputs, physical, tabulated
from .printed_items import PRINTED_ITEMS
from .published import PUBLISHED
from .report import VALUE_UNITS, scene_report
from .sweep_outputs import SWEEP_OUTPUTS

__all__ = ["BATCHED_BENCH_CASES", "ID", "AUTHORS", "HANDOUT_WORDS", "HYBRID_MODELS",
           "LATEX_NAMES", "PAPER", "SCENE_CHECKS", "SCENE_OPTIONS", "SWEEP_OUTPUTS", "TITLE",
           "build", "hard_cases", "scene_report", "VALUE_UNITS"]


def build(code: bool = True) -> Derivation:
    """Rebuild (1)–(7) and the printed numbers from the physics of Table 1's hoist.

    ``code=False`` leaves out the parts only code and the bench read (the audit's
    build, ``Derivation.code``).
    """
    d = Derivation(id=ID, paper=PAPER, title=TITLE, citation=CITATION,
                   model=MODEL, symbols=SYMBOLS, latex_names=LATEX_NAMES, code=code)
    steps.drive(d)
    steps.rigid_drive(d)                 # (1)–(5)
    steps.coordinated_brakes(d)          # (6)–(7)
    steps.elastic_no_backlash(d)         # Fig. 9 without backlash
    steps_numbers.numbers(d)             # Table 1, after (5), Figs 8, 11, 12
    elastic.fig9_steps(d)                # Fig. 9
    d.published.extend(PUBLISHED)
    d.printed_items.extend(PRINTED_ITEMS)
    if not code:
        return d
    d.outputs.extend(outputs(d))
    d.tabulated.extend(tabulated())
    # The bench's values of the factors: Table 1's own (from the scene's data), φ5 = 1.5.
    d.bench_parameters.update({s: physical(d, d.step(str(s)).statement.rhs)
                               for s in (MF, LF, BF_SB)})
    d.bench_parameters[phi5] = sp.Rational(3, 2)
    return d
