"""Responses of paper 003 that a design sweep maps over its grid.

The start-up of the travel drive with backlash in both links (Fig. 12, Table
1) has phases whose number and ends depend on the design: each design is the
component model of ``drive_train.py`` (``hybrid.STARTUP``) on Table 1's hold
times, and a
block of the grid is solved at once by the batched solver
(``crane_sym.mechanics.batched_runs``: the designs' starts from rest, their
modes' matrices, guards, switches and loads for all the designs of one
template at once, the closed forms, events and extrema batched; the two
equal sides' repeated eigenvalues clustered). It agrees with the per-design run of each design to 1e-9
(``tests/test_batched.py``). The backlash φ_b is no scene parameter (the
scene's report runs each value of its options): give it with ``--at`` or
``--vary``. Its block is Python-bound (each design's parts assembled in
Python, ``threads`` not set): a sweep runs its blocks on processes, a grid of
at most 10⁴ designs as one block in this process (``crane_sym.sweep.blocks``).
"""
from __future__ import annotations

from dataclasses import replace

import numpy as np

from crane_sym.derivation import SweepOutput

_PARAMETERS = ("P_m", "omega_n", "omega_0", "J_r", "n_m", "v_n", "lambda_p", "c_l", "zeta",
               "m_k", "W_f", "W_w", "phi_b")
#: The start-up's end [s]: Table 1's plotted 4 s, past the last step (1.6 s).
END = 4.0


def _models(values):
    """(shape, the start-up's model per design: hybrid.STARTUP's, its
    derivation shared by the designs of one structure)."""
    from .drive_train import fig11_design
    from .hybrid import rim_values
    from .startup import HOLDS
    names = list(values)
    arrays = np.broadcast_arrays(*[np.asarray(values[n], dtype=float) for n in names])
    models = []
    for index in np.ndindex(arrays[0].shape):
        p = {n: float(a[index]) for n, a in zip(names, arrays)}
        models.append(fig11_design(rim_values(p, p["phi_b"]), HOLDS))
    return arrays[0].shape, models


def _designs(values, together: bool = True):
    """(shape, one HybridRun per design) of the start-up, its output ("load")
    hybrid.STARTUP's; ``together``: the designs' starts found together
    (``rest_runs``), else each design's own ``hybrid_run`` (the reference)."""
    from crane_sym.components.model import rest_runs
    from .drive_train import total_load
    shape, models = _models(values)
    runs = rest_runs(models, END) if together else \
        [model.hybrid_run(END, rest=True) for model in models]
    return shape, [replace(run, output=total_load(run.system)) for run in runs]


#: The most phases of a design's start-up before it is stopped (a contact that
#: chatters): its peak is NaN, flagged in the sweep's dataset.
MAX_PHASES = 10_000


def _peak_startup_link_force(values, options) -> np.ndarray:
    """The largest F1 + F2 of the start-up from rest over Table 1's hold times,
    the block's designs solved together; NaN for a design stopped at
    :data:`MAX_PHASES` phases."""
    from crane_sym.mechanics.batched_runs import largest_of_runs
    shape, runs = _designs(values)
    result = largest_of_runs(runs, magnitude=False, max_events=MAX_PHASES)
    return result.value.reshape(shape)


def peak_per_design(values, options) -> np.ndarray:
    """:func:`_peak_startup_link_force` one design at a time (the reference)."""
    shape, runs = _designs(values, together=False)
    from crane_sym.mechanics.phase_table import largest
    return np.array([largest(r.solve(), r.system, r.output)[1] for r in runs]).reshape(shape)


SWEEP_OUTPUTS = {
    "peak_startup_link_force": SweepOutput(
        "peak_startup_link_force", "N",
        "Largest F1 + F2 of the two links in the start-up with backlash (Fig. 12, Table 1's "
        "hold times, over 4 s), phases in closed form", _PARAMETERS, (),
        _peak_startup_link_force, batched=True, cap=MAX_PHASES),
}
