"""Travel mechanisms of rail-mounted portal cranes: gear geometry and support loads.

Source: ``003_5e8a923a75d2f7ba.txt`` — E.N. Andrianov, A.N. Ivanov, "Topical
questions of raising the reliability of the travel mechanisms of rail-mounted
portal cranes" (Admiral Makarov State University of Maritime and Inland
Shipping; in Russian). The file ends with the start of an unrelated article
(explosions on tankers), which is out of scope.

Most of the paper is design practice. This package rebuilds its computations:
the Mathcad Form 1 check of a spur-gear pair cut by a rack (operating pressure
angle, shift sum, tip diameters and pressure angles, tip thickness, contact
ratio, the pointed-tip shift of its appendix) from the involute and the rack;
Fig. 10's four curves; the support loads (3)–(4) from the statics of a
reconstructed portal; Tables 1–3 as data, with Table 1's own arithmetic; the
three-mass start-up with backlash behind Table 1 and Fig. 12 (eqs (1)–(2) are
lost in the OCR: the model is built from the text's definitions), solved phase
by phase in closed form.

Files:

- ``model.py``: symbols, symbol table, LaTeX names, model text.
- ``steps.py``: the gear geometry and Form 1's numbers; ``steps_loads.py``:
  (3)–(4) and Table 1's arithmetic; ``steps_startup.py``: the start-up model.
- ``drive_train.py``: the three-mass drive with backlash of Fig. 11 as components
  (``crane_sym.components``): the one hybrid model of the start-up.
- ``startup.py``: the chosen parameters, their reduction to the rim, and the
  model's Table 1.
- ``hybrid.py``: ``HYBRID_MODELS``, that start-up as scenes reach it.
- ``sweep_outputs.py``: ``SWEEP_OUTPUTS``, the start-up's peak link force for design
  sweeps (batched).
- ``bench_cases.py``: ``BATCHED_BENCH_CASES``, that peak's batched bench.
- ``published.py``: Form 1 as printed; ``published_loads.py``: Fig. 10's z = 10
  value, (3)–(4), Table 1.
- ``published_measured.py``: (1)–(2), lost in the OCR, reconstructed and labelled;
  Tables 2–3 (measurements, nothing derives them).
- ``printed_items.py``: ``PRINTED_ITEMS``, the inventory of the print the audit's recall
  counts.
- ``tables.py``: Tables 1–3 as data.
- ``outputs.py``: generated functions; ``hard_cases.py``: hard cases.
- ``options.py``: ``SCENE_OPTIONS``, ``SCENE_CHECKS``.
- ``report.py``: ``scene_report`` (Fig. 10, a gear pair, support loads, start-up).

The package does nothing on import; ``build()`` returns the ``Derivation``.
"""
from __future__ import annotations

from crane_sym.derivation import Derivation

from . import steps, steps_loads, steps_startup
from .bench_cases import BATCHED_BENCH_CASES
from .hard_cases import hard_cases
from .hybrid import HYBRID_MODELS
from .model import AUTHORS, CITATION, HANDOUT_WORDS, ID, LATEX_NAMES, MODEL, PAPER, SYMBOLS, TITLE
from .options import SCENE_CHECKS, SCENE_OPTIONS
from .outputs import outputs, tabulated
from .printed_items import PRINTED_ITEMS
from .published import PUBLISHED
from .published_loads import PUBLISHED_LOADS
from .published_measured import PUBLISHED_MEASURED
from .report import VALUE_UNITS, scene_report
from .sweep_outputs import SWEEP_OUTPUTS

__all__ = ["BATCHED_BENCH_CASES", "ID", "AUTHORS", "HANDOUT_WORDS", "HYBRID_MODELS",
           "LATEX_NAMES", "PAPER", "SCENE_CHECKS", "SCENE_OPTIONS", "SWEEP_OUTPUTS", "TITLE",
           "build", "hard_cases", "scene_report", "VALUE_UNITS"]


def build(code: bool = True) -> Derivation:
    """Rebuild Form 1 from the involute and the rack, Fig. 10, and (3)–(4).

    ``code=False`` leaves out the parts only code and the bench read (the audit's
    build, ``Derivation.code``).
    """
    d = Derivation(id=ID, paper=PAPER, title=TITLE, citation=CITATION,
                   model=MODEL, symbols=SYMBOLS, latex_names=LATEX_NAMES, code=code)
    steps.involute_and_rack(d)
    steps.mesh(d)
    steps.tips(d)
    steps.tooth_limits(d)
    steps.form1_numbers(d)
    steps_loads.support_loads(d)
    steps_loads.table1_arithmetic(d)
    steps_startup.equations_of_motion(d)
    steps_startup.reduction(d)
    steps_startup.table1_model(d)
    d.published.extend(PUBLISHED + PUBLISHED_LOADS + PUBLISHED_MEASURED)
    d.printed_items.extend(PRINTED_ITEMS)
    if code:
        d.outputs.extend(outputs(d))
        d.tabulated.extend(tabulated())
    return d
