"""Fig. 9's emergency stop for an array of designs at once: the two-mass
hoist described to ``crane_sym.mechanics.batched``.

The model of ``drive_train.py`` reduced to the motor shaft, mode by mode, as
arrays over the designs: a mode (contact, motor brake, drum brake, motor
torque on) is an integer code; the matrices, guards, switching rule and the
relative gearbox torque M_G/M_st are written here by hand for every design in
one mode together, from the paper's two equations of motion (J1 θ̈_m = T − M_M
+ brake, J_d θ̈_d = −T + M_L − brake; T = c (θ_d − θ_m + off) + b (ω_d − ω_m)
on a flank, 0 in the gap). A design the batched route refuses is run by the
per-design route: the same drive as components (:func:`reduced_model`, two
inertias at the motor shaft, the load as a constant torque), its mode the
component model's (:meth:`HoistFamily.mode`); ``tests/test_batched.py``
checks the two against each other.
"""
from __future__ import annotations

from dataclasses import dataclass, replace
from itertools import product
from typing import Mapping

import numpy as np

from crane_sym.mechanics.batched import BatchedGuard, BatchedLargest, largest_batched
from crane_sym.mechanics.phase_table import HybridRun

from crane_sym.components import Brake, ElasticLink, Inertia, Model, Motor, Resistance
from crane_sym.components.hybrid import Mode

from .drive_train import relative_torque

#: Brake states of one side: no brake yet, sliding forward/backward, stuck.
OFF, FORWARD, BACKWARD, STUCK = "off", "+", "-", "0"
#: Contact states: holding flank (twist u >= 0), gap (-s < u < 0), other flank (u <= -s).
HOLD, GAP, OTHER = 1, 0, -1
#: The component model's motion of a group by its brake state, and its scheduled events.
_MOTION = {OFF: "free", FORWARD: "+", BACKWARD: "-", STUCK: "0"}
_SCHEDULE = ("drive off", "safety engages", "service engages")

#: Every mode (contact, motor brake, drum brake, motor torque on); its code is its index.
MODES = tuple(product((HOLD, GAP, OTHER), (OFF, FORWARD, BACKWARD, STUCK),
                      (OFF, FORWARD, BACKWARD, STUCK), (True, False)))
_CODE = {m: i for i, m in enumerate(MODES)}
_BRAKES = (OFF, FORWARD, BACKWARD, STUCK)
_PUSH = {OFF: 0.0, FORWARD: -1.0, BACKWARD: 1.0, STUCK: 0.0}
_U = np.array([-1.0, 0.0, 1.0, 0.0])
_DU = np.array([0.0, -1.0, 0.0, 1.0])
_FIELDS = ("J1", "J_d", "c", "s", "M_L", "M_st", "M_SB", "M_BB", "M_M", "b")


def _codes(contact, motor, drum, driven) -> np.ndarray:
    """Mode codes of component arrays (contacts, brake states as indices)."""
    return ((np.asarray(contact) * 4 + motor) * 4 + drum) * 2 + np.where(driven, 0, 1)


_CONTACT = {HOLD: 0, GAP: 1, OTHER: 2}


@dataclass(frozen=True)
class HoistFamily:
    """Two-mass hoists reduced to the motor shaft, one per design: each
    attribute an array of shape (N,); ``omega0``, ``t_end``, ``t_M``, ``t_SB``,
    ``t_BB`` of each design's emergency stop.

    J1, J_d : motor-side and drum-side inertia [kg m²]; c : gearbox stiffness
    [N m/rad]; s : backlash [rad]; M_L : static load torque; M_st : rated static
    torque; M_SB, M_BB : safety- and service-brake torques; M_M : motor torque
    before the stop (M_L) [N m]; b : mesh damping [N m s/rad]."""

    J1: np.ndarray
    J_d: np.ndarray
    c: np.ndarray
    s: np.ndarray
    M_L: np.ndarray
    M_st: np.ndarray
    M_SB: np.ndarray
    M_BB: np.ndarray
    M_M: np.ndarray
    b: np.ndarray
    omega0: np.ndarray
    t_end: np.ndarray
    t_M: np.ndarray
    t_SB: np.ndarray
    t_BB: np.ndarray
    n: int = 4

    def __post_init__(self) -> None:
        for name in ("J1", "J_d", "c", "M_st"):
            bad = ~(getattr(self, name) > 0)
            if bad.any():
                raise ValueError(f"{name} must be > 0, got {getattr(self, name)[bad][0]!r}")
        for name in ("s", "M_L", "M_SB", "M_BB", "b"):
            bad = ~(getattr(self, name) >= 0)
            if bad.any():
                raise ValueError(f"{name} must be >= 0, got {getattr(self, name)[bad][0]!r}")
        if not np.array_equal(self.M_M, self.M_L):
            raise ValueError("steady lowering needs M_M = M_L")
        object.__setattr__(self, "_damped", bool(np.any(self.b)))

    # --- the family, mode by mode ---------------------------------------------------
    def _torque(self, contact, index) -> tuple[np.ndarray, np.ndarray]:
        k = index.size
        if contact == GAP:
            return np.zeros((k, 4)), np.zeros(k)
        off = 0.0 if contact == HOLD else self.s[index]
        w = self.c[index, None] * _U
        if self._damped:
            w += self.b[index, None] * _DU
        return w, self.c[index] * off

    def matrices(self, mode: int, index: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """(A, b) of each design in the mode."""
        contact, motor, drum, driven = MODES[mode]
        w, k = self._torque(contact, index)
        A, b = np.zeros((index.size, 4, 4)), np.zeros((index.size, 4))
        if motor != STUCK:
            J1 = self.J1[index]
            A[:, 0, 1] = 1.0
            A[:, 1] = w / J1[:, None]
            b[:, 1] = (k - (self.M_M[index] if driven else 0.0)
                       + _PUSH[motor] * self.M_BB[index]) / J1
        if drum != STUCK:
            J_d = self.J_d[index]
            A[:, 2, 3] = 1.0
            A[:, 3] = -w / J_d[:, None]
            b[:, 3] = (self.M_L[index] - k + _PUSH[drum] * self.M_SB[index]) / J_d
        return A, b

    def guards(self, mode: int, index: np.ndarray) -> list[BatchedGuard]:
        """Contact changes, a braked side coming to rest, a stuck side breaking
        free, for each design."""
        contact, motor, drum, driven = MODES[mode]
        k = index.size
        u = np.broadcast_to(_U, (k, 4))
        zero = np.zeros(k)
        out = {HOLD: [BatchedGuard("open", u, zero, -1)],
               OTHER: [BatchedGuard("open", u, self.s[index], 1)],
               GAP: [BatchedGuard("close hold", u, zero, 1),
                     BatchedGuard("close other", u, self.s[index], -1)]}[contact]
        w, kk = self._torque(contact, index)
        for side, state, axis, sign, limit, load in (
                ("motor", motor, 1, 1.0, self.M_BB[index],
                 -(self.M_M[index] if driven else zero)),
                ("drum", drum, 3, -1.0, self.M_SB[index], self.M_L[index])):
            if state in (FORWARD, BACKWARD):
                out.append(BatchedGuard(f"{side} rests", np.broadcast_to(np.eye(4)[axis], (k, 4)),
                                        zero, -1 if state == FORWARD else 1))
            elif state == STUCK:
                out.append(BatchedGuard(f"{side} slips +", sign * w, sign * kk + load - limit, 1))
                out.append(BatchedGuard(f"{side} slips -", sign * w, sign * kk + load + limit,
                                        -1))
        return out

    def switch(self, mode: int, event: str, index: np.ndarray, t: np.ndarray,
               x: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Next mode and state after a guard or a scheduled event, for each design."""
        contact, motor, drum, driven = MODES[mode]
        k = index.size
        x = x.copy()
        c_ = np.full(k, _CONTACT[contact])
        m_ = np.full(k, _BRAKES.index(motor))
        d_ = np.full(k, _BRAKES.index(drum))
        on = driven
        if event == "open":
            c_[:] = _CONTACT[GAP]
        elif event == "close hold":
            c_[:] = _CONTACT[HOLD]
        elif event == "close other":
            c_[:] = _CONTACT[OTHER]
        elif event == "drive off":
            on = False
        elif event == "safety engages":
            d_ = _engage(x[:, 3])
        elif event == "service engages":
            m_ = _engage(x[:, 1])
        elif event.endswith("rests") or " slips " in event:
            motor_side = event.startswith("motor")
            x[:, 1 if motor_side else 3] = 0.0
            new = self._rest(motor_side, contact, driven, index, x, event)
            if motor_side:
                m_ = new
            else:
                d_ = new
        else:
            raise ValueError(f"unknown event {event!r}")
        return _codes(c_, m_, d_, np.full(k, on)), x

    def _rest(self, motor_side: bool, contact, driven: bool, index: np.ndarray, x: np.ndarray,
              event: str) -> np.ndarray:
        """A braked side at rest: stuck while the net torque is within the brake."""
        k = index.size
        if event.endswith("slips +"):
            return np.full(k, _BRAKES.index(FORWARD))
        if event.endswith("slips -"):
            return np.full(k, _BRAKES.index(BACKWARD))
        w, kk = self._torque(contact, index)
        T = np.einsum("ki,ki->k", w, x) + kk
        if motor_side:
            net, limit = T - (self.M_M[index] if driven else 0.0), self.M_BB[index]
        else:
            net, limit = self.M_L[index] - T, self.M_SB[index]
        return np.where(np.abs(net) <= limit, _BRAKES.index(STUCK),
                        np.where(net > 0, _BRAKES.index(FORWARD), _BRAKES.index(BACKWARD)))

    def output(self, mode: int, index: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """M_G/M_st as weights·x + constant."""
        w, k = self._torque(MODES[mode][0], index)
        M_st = self.M_st[index]
        return w / M_st[:, None], k / M_st

    # --- runs -----------------------------------------------------------------------
    def model(self, i: int) -> Model:
        """Design ``i`` as components (:func:`reduced_model`)."""
        return reduced_model(*(float(getattr(self, f)[i]) for f in _FIELDS + (
            "t_M", "t_SB", "t_BB")))

    def run(self, i: int) -> HybridRun:
        """Design ``i``'s emergency stop for the per-design route (numeric closed
        forms, as a sweep runs it), its output M_G/M_st."""
        run = self.model(i).hybrid_run(float(self.t_end[i]), "coupling", "motor",
                                       float(self.omega0[i]))
        return replace(run, output=relative_torque(run.system), exact=False)

    def mode(self, code: int, i: int) -> Mode:
        """The component model's mode (:meth:`model`) of a mode code, design ``i``:
        its groups the motor side and the drum side, its brakes the safety and
        the service brake."""
        contact, motor, drum, driven = MODES[code]
        return Mode((contact,) if self.s[i] > 0 else (), (_MOTION[motor], _MOTION[drum]),
                    (drum != OFF, motor != OFF), (driven,), (False, False))

    def peaks(self, **options) -> BatchedLargest:
        """The largest |M_G/M_st| of every design's emergency stop."""
        N = self.J1.size
        modes = np.full(N, _CODE[(HOLD, OFF, OFF, True)])
        x0 = np.stack([np.zeros(N), self.omega0, self.M_L / self.c, self.omega0], axis=1)
        times = np.stack([self.t_M, self.t_SB, self.t_BB], axis=1)
        return largest_batched(self, modes, x0, self.t_end, _SCHEDULE, times, **options)


def _engage(speed: np.ndarray) -> np.ndarray:
    return np.where(speed > 0, _BRAKES.index(FORWARD),
                    np.where(speed < 0, _BRAKES.index(BACKWARD), _BRAKES.index(STUCK)))


def reduced_model(J1: float, J_d: float, c: float, s: float, M_L: float, M_st: float,
                  M_SB: float, M_BB: float, M_M: float, b: float, t_M: float, t_SB: float,
                  t_BB: float) -> Model:
    """The two-mass hoist at the motor shaft as components (the attributes of
    :class:`HoistFamily`, one design): the drum side lowered by the constant
    torque M_L, held by the steady motor (M_M = M_L) until ``t_M``."""
    if not M_M == M_L:
        raise ValueError("steady lowering needs M_M = M_L")
    return Model([Inertia("motor", J1), Inertia("drum", J_d),
                  ElasticLink("coupling", "motor", "drum", c, b, backlash=s, reference=M_st),
                  Resistance("load", "drum", M_L),
                  Motor("drive", "motor", "steady", off_at=t_M),
                  Brake("safety", "drum", M_SB, delay=t_SB),
                  Brake("service", "motor", M_BB, delay=t_BB)], name="hoist_reduced")


def family_from(q: Mapping[str, np.ndarray], t_end: float | np.ndarray,
                t_M: float | np.ndarray = 0.0, b: float | np.ndarray = 0.0) -> HoistFamily:
    """The reduced hoists of ``drive_train.fig9_model`` for arrays: the designs of Table 1's names
    (J1, J2, m_h, m_p, m_r, r, i_g, i_t, g, c, delta, M_SB, M_BB, t_SB, t_BB,
    omega1; SI, broadcast together), lowering m_p, stopped after ``t_end``."""
    names = ("J1", "J2", "m_h", "m_p", "m_r", "r", "i_g", "i_t", "g", "c", "delta", "M_SB",
             "M_BB", "t_SB", "t_BB", "omega1")
    arrays = np.broadcast_arrays(*[np.asarray(q[n], dtype=float) for n in names],
                                 np.asarray(t_end, float), np.asarray(t_M, float),
                                 np.asarray(b, float))
    v = {n: a.ravel() for n, a in zip(names + ("t_end", "t_M", "b"), arrays)}
    gear = v["r"] / (v["i_g"] * v["i_t"])
    M_L = (v["m_h"] + v["m_p"]) * v["g"] * gear
    J_d = v["J2"] / v["i_g"] ** 2 + (v["m_h"] + v["m_p"]) * gear ** 2
    return HoistFamily(v["J1"], J_d, v["c"], v["delta"] * v["i_g"], M_L,
                       (v["m_h"] + v["m_r"]) * v["g"] * gear, v["M_SB"] / v["i_g"], v["M_BB"],
                       M_L, v["b"], v["omega1"], v["t_end"], v["t_M"], v["t_SB"], v["t_BB"])
