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
``--vary``. Where the designs of a block differ only in the links' stiffness
and damping (C_пр and ζ swept), the block is one
``crane_sym.components.design_block.DesignBlock``: one model, its values as
arrays, a design's own model built only where the per-design route takes it
(the same numbers, ``tests/test_design_block.py``); elsewhere each design's
parts are assembled in Python. A block of the first kind is NumPy-bound,
and a sweep runs such blocks on threads (``threads``: only C_пр and ζ
swept); a block of the second is Python-bound, on processes, a grid of at
most 10⁴ designs as one block in this process (``crane_sym.sweep.blocks``).
"""
from __future__ import annotations

from dataclasses import replace
from functools import partial

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


#: The rim values a block of designs may vary (``drive_train.fig11_parts``:
#: both links' stiffness and damping); any other varied value, a model a design.
_LINK_KEYS = {"c_l": "stiffness", "b": "damping"}
#: The parameters a sweep may vary for its blocks to be solved as one
#: (:func:`_block`: the links' stiffness and damping ratio). Such a block is
#: NumPy-bound: two of 5 000 designs on two threads took 0.57 of one of
#: 10 000 (measured), so a sweep runs them on threads, 2 500 to 10 000 designs
#: each (a block's fixed cost ~0.05 s; ~50 kB a design while it runs).
_BLOCK_AXES = ("c_l", "zeta")


def _block(values):
    """(shape, a ``DesignBlock`` of the start-up, its first design's model)
    where the designs' rim values differ only in :data:`_LINK_KEYS`, or None."""
    from crane_sym.components.design_block import plain_block
    from .drive_train import fig11_design
    from .hybrid import rim_values
    from .startup import HOLDS
    names = list(values)
    arrays = np.broadcast_arrays(*[np.asarray(values[n], dtype=float) for n in names])
    p = {n: (float(a.flat[0]) if np.all(a == a.flat[0]) else a.ravel())
         for n, a in zip(names, arrays)}
    if isinstance(p["phi_b"], np.ndarray) or any(
            isinstance(p[n], np.ndarray) for n in _PARAMETERS if n not in ("c_l", "zeta")):
        return None
    rim = rim_values(p, p["phi_b"])         # arithmetic on the arrays, design by design
    if any(np.ndim(v) and k not in _LINK_KEYS for k, v in rim.items()) or \
            not (np.all(np.asarray(rim["c_l"]) > 0) and np.all(np.asarray(rim["b"]) >= 0)):
        return None
    size = arrays[0].size
    varied = {(f"link_{side}", key): np.broadcast_to(rim[name], (size,))
              for side in ("left", "right") for name, key in _LINK_KEYS.items()}
    first = {k: float(np.asarray(v).flat[0]) for k, v in rim.items()}
    model = fig11_design(first, HOLDS)
    block = plain_block(model, varied)
    return None if block is None else (arrays[0].shape, block, rim)


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
    found = _block(values)
    if found is None:
        shape, runs = _designs(values)
        result = largest_of_runs(runs, magnitude=False, max_events=MAX_PHASES)
        return result.value.reshape(shape)
    shape, block, rim = found
    t_end = block.model.end(END, rest=True)
    beyond = block.first_beyond(t_end)
    if beyond is not None:
        raise beyond[1]
    return block.largest((0, 1), t_end, partial(_own_run, rim, t_end), magnitude=False,
                         max_events=MAX_PHASES).value.reshape(shape)


def _own_run(rim, t_end: float, d: int, mode, x0):
    """Design d's own run of a block (:func:`_block`) from its start: its
    model and system, as :func:`_designs` builds them."""
    from crane_sym.components.hybrid import ComponentSystem
    from crane_sym.mechanics.phase_table import HybridRun
    from .drive_train import fig11_design, total_load
    from .startup import HOLDS
    model = fig11_design({k: float(np.asarray(v).ravel()[d]) if np.ndim(v) else v
                          for k, v in rim.items()}, HOLDS)
    system = ComponentSystem(model.equations)
    return HybridRun(system, mode, x0, t_end, model.schedule(True), total_load(system))


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
        _peak_startup_link_force, batched=True, cap=MAX_PHASES,
        threads=_BLOCK_AXES, thread_block=(2_500, 10_000)),
}
