"""Responses of paper 001 that a design sweep maps over its grid.

The emergency stop with coupling backlash (Fig. 9) has phases whose number
and ends depend on the design, so a sweep solves each design's run phase by
phase in closed form, with the numeric eigenvector route of the closed forms
(each design has new matrices; SymPy's exact Jordan form would cost ~0.2 s a
design). A block of the grid is solved at once by the batched solver
(``elastic_batched.py``, ``crane_sym.mechanics.batched``): every design its
own mode, state and clock, the phases' closed forms from batched
eigen-decompositions, the events of all designs in one vectorised search;
it agrees with the per-design run (``hybrid.EMERGENCY_STOP``, the hoist as
components, ``crane_sym.mechanics.piecewise_linear``, kept here as
:func:`peak_per_design` for the bench) to 1e-9 of the peak
(``tests/test_batched.py``, ``tests/test_components.py``). Its block is
NumPy-bound (``threads=True``): a sweep runs it on threads in blocks of
4·10⁴ to 5·10⁴ designs (``crane_sym.sweep.blocks``).
"""
from __future__ import annotations

import numpy as np

from crane_sym.derivation import SweepOutput

from .elastic_batched import family_from
from .hybrid import EMERGENCY_STOP

_PARAMETERS = ("J1", "J2", "m_h", "m_p", "m_r", "r", "i_g", "i_t", "g", "c", "delta",
               "M_SB", "M_BB", "t_SB", "t_BB", "omega1")


#: The most phases of a design's emergency stop before it is stopped (a
#: contact that chatters): the design's peak is NaN, flagged in the sweep's dataset.
MAX_PHASES = 10_000


def _peak_elastic_gearbox_torque(values, options) -> np.ndarray:
    """max |M_G/M_st| of the emergency stop while lowering m_p, over the
    scene's duration: the block's designs solved together, phase by phase in
    closed form; NaN for a design stopped at :data:`MAX_PHASES` phases."""
    names = list(values)
    arrays = np.broadcast_arrays(*[np.asarray(values[n], dtype=float) for n in names])
    family = family_from(dict(zip(names, arrays)), options["duration"])
    result = family.peaks(max_events=MAX_PHASES)
    return np.abs(result.value).reshape(arrays[0].shape)


def peak_per_design(values, options) -> np.ndarray:
    """:func:`_peak_elastic_gearbox_torque` one design at a time (the
    per-design solver in a loop, ``hybrid.EMERGENCY_STOP``): the bench's reference."""
    return EMERGENCY_STOP.peak_sweep("relative_torque")(values, options)


SWEEP_OUTPUTS = {
    "peak_elastic_gearbox_torque": SweepOutput(
        "peak_elastic_gearbox_torque", "1",
        "Largest |M_G/M_st| of the emergency stop while lowering, elastic drive with the "
        "coupling backlash (Fig. 9), phases in closed form", _PARAMETERS, (),
        _peak_elastic_gearbox_torque, batched=True, threads=True, cap=MAX_PHASES),
}
