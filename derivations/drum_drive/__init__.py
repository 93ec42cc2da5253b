"""Dynamic model of a drive with a driving drum (conveyors, rope installations).

Source: ``004_f118c513e0426caf.txt`` — M.P. Martyntsiv, O.M. Udovytskyi,
B.V. Sologub, "Dynamic model of the drive of transporting and hoisting machines
with a driving drum" (Lviv, 2010; in Ukrainian). The file opens with the tail
of an unrelated article on steering linkages, which is out of scope.

The paper writes Lagrange's equations (1) with a Rayleigh function, the
kinetic energy (2) with the traction element's share (3)–(7) under a linear
velocity distribution, the potential energy (8), the generalized forces
(9)–(10), the dissipation (11), the equations of motion (12), a relative
vibration equation (13)–(14), a drum-shaft bending equation (15)–(17), the drum
torque (18), the traction condition (19) and a pulsating load (20)–(21), then a
numerical example (Fig. 3). Fig. 1 is lost, and the printed energies and forces
do not fit together; this package builds one consistent model from the text
(``MODEL``), derives its equations, audits every printed formula against it and
against the paper's own preceding lines (``published``), and adds what a user
needs: drum torque, traction margin, pulsating load, natural frequencies, the
steady running state and a simulation of the example.

Files:

- ``model.py``: symbols, symbol table, LaTeX names, the model text (``MODEL``)
  and the model's energies T, Π, Φ and generalized forces.
- ``steps.py``: the derivation steps (1)–(21), in the paper's order.
- ``published.py``: the printed formulas, transcribed with their LaTeX.
- ``printed_items.py``: ``PRINTED_ITEMS``, the inventory of the print the audit's recall counts.
- ``outputs.py``: generated functions, state derivative and Jacobian, the
  "damping" switch, bench parameters and the ODE system the bench integrates.
- ``hard_cases.py``: seeded hard cases for ``crane-sym accuracy``.
- ``report.py``: ``scene_report`` — the simulation of the example (Fig. 3).
- ``report_state.py``: a scene of the state derivative alone, simulated.
- ``sweep_outputs.py``: ``SWEEP_OUTPUTS``, responses a design sweep simulates
  per design (``crane-sym sweep``).

The package does nothing on import; ``build()`` returns the ``Derivation``.
"""
from __future__ import annotations

from crane_sym.derivation import Derivation
from crane_sym.symbols import SymbolTable

from .printed_items import PRINTED_ITEMS
from . import published as pub
from .print_notation import PRINT_LATEX_NAMES, PRINT_SYMBOLS
from . import steps
from .hard_cases import hard_cases
from .model import AUTHORS, HANDOUT_WORDS, LATEX_NAMES, MODEL, MODEL_SYMBOLS, PAPER, model_energies
from .options import SCENE_CHECKS, SCENE_OPTIONS
from .outputs import BENCH_PARAMETERS, damping_switch, load_response, outputs
from .report import VALUE_UNITS, scene_report
from .sweep_outputs import SWEEP_OUTPUTS

#: What the registry, the CLI and the walkthrough read from the module.
__all__ = ["ID", "PAPER", "TITLE", "AUTHORS", "HANDOUT_WORDS", "LATEX_NAMES", "SCENE_CHECKS",
           "SCENE_OPTIONS", "SWEEP_OUTPUTS", "build", "hard_cases", "scene_report", "VALUE_UNITS"]

ID = "drum_drive"
TITLE = "Dynamic model of a drive with a driving drum"


def build(code: bool = True) -> Derivation:
    """Rebuild eqs (1)–(21) of the drum-drive model; attach the print and outputs.

    ``code=False`` leaves out the parts only code and the bench read (the audit's
    build, ``Derivation.code``).
    """
    d = Derivation(id=ID, paper=PAPER, title=TITLE,
                   citation="M.P. Martyntsiv, O.M. Udovytskyi, B.V. Sologub, Lviv, 2010",
                   model=MODEL, symbols=SymbolTable(MODEL_SYMBOLS + PRINT_SYMBOLS),
                   latex_names=LATEX_NAMES | PRINT_LATEX_NAMES, code=code)
    e = model_energies()
    eqs = steps.lagrange(d, e)                # (1)
    steps.kinetic_energy(d, e)                # (2)–(7)
    steps.potential_and_forces(d, e)          # (8)–(10)
    steps.dissipation(d, e)                   # (11)
    steps.equations_of_motion(d, eqs)         # (12)
    rest = steps.steady_running(d, eqs)
    steps.frequencies(d, eqs)                 # (13)–(14)
    steps.torque_traction_load(d, e)          # (17)–(21)
    steps.initial_state(d, rest)
    d.published.extend(pub.published(e))
    d.printed_items.extend(PRINTED_ITEMS)
    if code:
        d.outputs.extend(outputs(d))
        d.switches["damping"] = damping_switch()
        d.ode_systems.append(load_response(d))
        d.bench_parameters.update(BENCH_PARAMETERS)
    return d
