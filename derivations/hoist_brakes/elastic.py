"""The elasto-kinetic emergency stop of Fig. 9: two inertias, gearbox stiffness,
coupling backlash, brakes as delayed steps that stick, solved phase by phase in
closed form by ``crane_sym.mechanics.piecewise_linear``.

Everything is reduced to the motor shaft; the direction of lowering is +.

    motor shafts J1 ----[ c, backlash s ]---- drum side J_d (drums, hook, payload)
      M_M (lost at t = 0)                       M_L (weight, lowers)
      M_BB after t_BB (sticks at ω = 0)         M_SB/i_g after t_SB (sticks at ω = 0)

State x = (θ_m, ω_m, θ_d, ω_d); twist u = θ_d − θ_m. Contact: u ≥ 0 the
holding flank (the drum drives the motor, torque c·u), −s < u < 0 the gap (no
torque), u ≤ −s the other flank (torque c·(u + s)). The relative gearbox torque
is the flank torque over the rated static torque M_st (the paper's M_G,rel).

Fig. 9's steps build the hoist here (:func:`fig9_peak`); scenes, sweeps and
the bench reach it through ``hybrid.py`` (``EMERGENCY_STOP``).
"""
from __future__ import annotations

from dataclasses import dataclass, replace
from typing import Mapping

import numpy as np

from crane_sym.derivation import Derivation
from crane_sym.mechanics.phase_table import HybridRun, largest, values
from crane_sym.mechanics.piecewise_linear import Guard, PiecewiseResult
from crane_sym.sensitivity import Chosen, sweep

#: Brake states of one side: no brake yet, sliding forward/backward, stuck.
OFF, FORWARD, BACKWARD, STUCK = "off", "+", "-", "0"
#: Contact states: holding flank, gap, other flank.
HOLD, GAP, OTHER = 1, 0, -1


@dataclass(frozen=True)
class TwoMassHoist:
    """Data of the two-mass hoist, SI, reduced to the motor shaft.

    Attributes
    ----------
    J1, J_d : motor-side and drum-side inertia [kg m²]
    c : gearbox stiffness [N m/rad]; s : backlash [rad] (≥ 0)
    M_L : static load torque; M_st : rated static torque [N m]
    M_SB, M_BB : safety- and service-brake torques at the motor shaft [N m]
    M_M : motor torque before the stop (holding: M_L) [N m]
    b : damping of the mesh in contact [N m s/rad] (default 0, the model's: the
        paper states none); with b > 0 a flank still opens where the twist
        returns to its flank, not where the damped torque reaches zero
    """

    J1: float
    J_d: float
    c: float
    s: float
    M_L: float
    M_st: float
    M_SB: float
    M_BB: float
    M_M: float
    b: float = 0.0

    def __post_init__(self) -> None:
        for name in ("J1", "J_d", "c", "M_st"):
            if not getattr(self, name) > 0:
                raise ValueError(f"{name} must be > 0, got {getattr(self, name)!r}")
        for name in ("s", "M_L", "M_SB", "M_BB", "b"):
            if not getattr(self, name) >= 0:
                raise ValueError(f"{name} must be >= 0, got {getattr(self, name)!r}")

    # --- the hybrid system ------------------------------------------------------
    def torque(self, contact: int) -> tuple[np.ndarray, float]:
        """Flank torque as weights·x + constant."""
        if contact == GAP:
            return np.zeros(4), 0.0
        off = 0.0 if contact == HOLD else self.s
        weights = self.c * np.array([-1.0, 0.0, 1.0, 0.0])
        if self.b:
            weights = weights + self.b * np.array([0.0, -1.0, 0.0, 1.0])
        return weights, self.c * off

    def matrices(self, mode: tuple) -> tuple[np.ndarray, np.ndarray]:
        """(A, b) of a mode (contact, motor brake, drum brake, motor torque on)."""
        contact, motor, drum, driven = mode
        w, k = self.torque(contact)
        A, b = np.zeros((4, 4)), np.zeros(4)
        brake = {OFF: 0.0, FORWARD: -1.0, BACKWARD: 1.0, STUCK: 0.0}
        if motor != STUCK:
            A[0, 1] = 1.0
            A[1] = w / self.J1
            b[1] = (k - (self.M_M if driven else 0.0) + brake[motor] * self.M_BB) / self.J1
        if drum != STUCK:
            A[2, 3] = 1.0
            A[3] = -w / self.J_d
            b[3] = (self.M_L - k + brake[drum] * self.M_SB) / self.J_d
        return A, b

    def guards(self, mode: tuple) -> list[Guard]:
        """Contact changes, a braked side coming to rest, a stuck side breaking free."""
        contact, motor, drum, driven = mode
        u = (-1.0, 0.0, 1.0, 0.0)
        out = {HOLD: [Guard("open", u, 0.0, -1)], OTHER: [Guard("open", u, self.s, 1)],
               GAP: [Guard("close hold", u, 0.0, 1),
                     Guard("close other", u, self.s, -1)]}[contact]
        w, k = self.torque(contact)
        for side, state, index, sign, limit, load in (
                ("motor", motor, 1, 1.0, self.M_BB, -(self.M_M if driven else 0.0)),
                ("drum", drum, 3, -1.0, self.M_SB, self.M_L)):
            if state in (FORWARD, BACKWARD):
                out.append(Guard(f"{side} rests", tuple(np.eye(4)[index]), 0.0,
                                 -1 if state == FORWARD else 1))
            elif state == STUCK:     # net torque sign*T + load reaches ±limit
                out.append(Guard(f"{side} slips +", tuple(sign * w), sign * k + load - limit, 1))
                out.append(Guard(f"{side} slips -", tuple(sign * w), sign * k + load + limit,
                                 -1))
        return out

    def switch(self, mode: tuple, event: str, t: float,
               x: np.ndarray) -> tuple[tuple, np.ndarray]:
        """Next mode and state after a guard or a scheduled event."""
        contact, motor, drum, driven = mode
        x = x.copy()
        if event == "open":
            contact = GAP
        elif event == "close hold":
            contact = HOLD
        elif event == "close other":
            contact = OTHER
        elif event == "motor torque lost":
            driven = False
        elif event == "safety brake":
            drum = self._engage(x[3])
        elif event == "service brake":
            motor = self._engage(x[1])
        elif event.endswith("rests") or " slips " in event:
            side = "motor" if event.startswith("motor") else "drum"
            index = 1 if side == "motor" else 3
            x[index] = 0.0
            new = self._rest(side, (contact, motor, drum, driven), x, event)
            motor, drum = (new, drum) if side == "motor" else (motor, new)
        return (contact, motor, drum, driven), x

    @staticmethod
    def _engage(speed: float) -> str:
        return FORWARD if speed > 0 else BACKWARD if speed < 0 else STUCK

    def _rest(self, side: str, mode: tuple, x: np.ndarray, event: str) -> str:
        """A braked side at rest: stuck while the net torque is within the brake."""
        if event.endswith("slips +"):
            return FORWARD
        if event.endswith("slips -"):
            return BACKWARD
        w, k = self.torque(mode[0])
        T = float(w @ x + k)
        net = T - (self.M_M if mode[3] else 0.0) if side == "motor" else self.M_L - T
        limit = self.M_BB if side == "motor" else self.M_SB
        return STUCK if abs(net) <= limit else FORWARD if net > 0 else BACKWARD

    # --- runs -------------------------------------------------------------------
    def start(self, omega0: float) -> tuple[tuple, np.ndarray]:
        """Steady lowering at ω0 with the motor holding: twist M_L/c on the holding
        flank (the gap, if any, is taken up)."""
        if not self.M_M == self.M_L:
            raise ValueError("steady lowering needs M_M = M_L")
        return (HOLD, OFF, OFF, True), np.array([0.0, omega0, self.M_L / self.c, omega0])

    def emergency_stop(self, omega0: float, t_end: float, t_M: float = 0.0,
                       t_SB: float = 0.1, t_BB: float = 0.4) -> HybridRun:
        """The emergency stop from steady lowering at ω0: motor torque lost at t_M,
        brakes after their delays; its output is M_G/M_st."""
        mode, x0 = self.start(omega0)
        schedule = ((t_M, "motor torque lost"), (t_SB, "safety brake"),
                    (t_BB, "service brake"))
        return HybridRun(self, mode, x0, t_end, schedule, self.relative)

    def run(self, omega0: float, t_end: float, t_M: float = 0.0, t_SB: float = 0.1,
            t_BB: float = 0.4) -> PiecewiseResult:
        """The phases of :meth:`emergency_stop`, each in closed form."""
        return self.emergency_stop(omega0, t_end, t_M, t_SB, t_BB).solve()

    def relative(self, mode: tuple) -> tuple[np.ndarray, float]:
        """M_G/M_st of a mode as weights·x + constant."""
        w, k = self.torque(mode[0])
        return w / self.M_st, k / self.M_st

    def relative_torque(self, result: PiecewiseResult, times: np.ndarray) -> np.ndarray:
        """The gearbox torque over M_st at ``times``, from the phases' closed forms."""
        return values(result, times, self.relative)

    def peak(self, result: PiecewiseResult) -> tuple[float, float]:
        """(time, value) of the largest |relative torque|: per phase at the closed
        form's extrema (zeros of the torque's rate, found like any event)."""
        return largest(result, self, self.relative, magnitude=True)


def hoist_from(q: Mapping[str, float], payload: float) -> TwoMassHoist:
    """The two-mass hoist of SI values by Table 1's names (J1, J2, m_h, m_r, r,
    i_g, i_t, g, c, delta, M_SB, M_BB; J1, J2 and the brake torques of the whole
    drive, see the model text), lowering ``payload`` kg."""
    gear = q["r"] / (q["i_g"] * q["i_t"])
    M_L = (q["m_h"] + payload) * q["g"] * gear
    return TwoMassHoist(q["J1"], q["J2"] / q["i_g"] ** 2 + (q["m_h"] + payload) * gear ** 2,
                        q["c"], q["delta"] * q["i_g"], M_L,
                        (q["m_h"] + q["m_r"]) * q["g"] * gear, q["M_SB"] / q["i_g"],
                        q["M_BB"], M_L)


def table1_hoist(payload: float, g: float = 9.81, backlash_deg: float | None = None,
                 stiffness: float | None = None) -> TwoMassHoist:
    """The two-mass hoist of Table 1, lowering ``payload`` kg on the hook."""
    from .model import TABLE1
    q = {k: float(v) for k, v in TABLE1.items()}
    q.update(g=g, delta=np.radians(q["backlash_deg"] if backlash_deg is None else backlash_deg))
    if stiffness is not None:
        q["c"] = stiffness
    return hoist_from(q, payload)


#: Table 1's motor speed [rad/s] and brake delays [s].
OMEGA1, T_SB, T_BB = 1500 * 2 * np.pi / 60, 0.1, 0.4


#: What Fig. 9's model needs and the paper does not state, with plausible ranges
#: (the stiffness's place, at the motor shaft, and the brakes that hold are
#: argued in the model text; these two are free).
FIG9_CHOSEN = (
    Chosen("zeta", "damping ratio ζ of the gearbox mesh", "", 0.0, 0.0, 0.05,
           "the paper states no losses; gear meshes damp a few per cent"),
    Chosen("t_M", "delay Δt_M of the motor's loss of torque", "s", 0.0, 0.0, 0.1,
           "Fig. 3 draws Δt_M without a value; at most the safety brake's 0.1 s"),
)


def fig9_peak(payload: float, zeta: float = 0.0, t_M: float = 0.0) -> tuple[float, float]:
    """(time, relative torque) of the largest gearbox torque, Table 1's hoist
    lowering ``payload``: motor torque lost at ``t_M``, brakes after Table 1's
    delays, the mesh damped at the ratio ``zeta`` (of the two-mass oscillator)."""
    h = table1_hoist(payload)
    if zeta:
        reduced = h.J1 * h.J_d / (h.J1 + h.J_d)
        h = replace(h, b=2 * zeta * float(np.sqrt(h.c * reduced)))
    return h.peak(h.run(OMEGA1, 1.0, t_M, T_SB, T_BB))


def fig9_steps(d: Derivation) -> None:
    """The peak of Fig. 9 as steps: the hook alone (the text, with its sensitivity
    to the unstated damping and motor delay) and the rated load."""
    import sympy as sp

    from .model import N
    for name, payload in (("hook only", 0.0), ("rated load", 52e3)):
        when, value = fig9_peak(payload)
        how = (f"|M_G/M_st| at its largest (t = {when:.4f} s), the two-mass hoist of "
               f"Table 1 lowering the {name}, phases in closed form.")
        swing = None
        if payload == 0:
            swing = sweep(lambda q: {"peak": abs(fig9_peak(0.0, q["zeta"], q["t_M"])[1])},
                          FIG9_CHOSEN)["peak"]
            how += (" The motor shafts J1 and the drum side J_d are joined by the gearbox "
                    "stiffness c through the coupling backlash s = δ·i_g: the flank torque "
                    "is c·u on the holding flank (twist u ≥ 0), 0 in the gap (−s < u < 0) "
                    "and c·(u + s) on the other flank. The brakes act as steps after their "
                    "delays and hold a side at rest while its net torque stays within "
                    "their limit. Between two contact changes the drive is linear, "
                    "x' = A x + b, so each phase is exp(Mt) in closed form, and the next "
                    "change is found on that closed form by a search whose steps are "
                    "bounded by the derivative, so no crossing is stepped over. A scene "
                    "carries the run of its payload as a table of those closed forms. "
                    "The paper states neither damping nor the motor's delay: with them "
                    f"over their plausible ranges the peak spans {swing.text()}.")
        d.add(f"Fig. 9 peak, {name}", sp.Eq(N, sp.Float(abs(value), 15)), how,
              "The elasto-kinetic result the paper prints as 8.9 (Fig. 9, conclusions: "
              "890 %).", "Fig. 9" if payload == 0 else "", sensitivity=swing)
