"""The start-up of the travel drive with backlash (Fig. 11, Table 1, Fig. 12): three
masses, two elastic links with backlash, a stepped rheostat start, solved phase by
phase in closed form by ``crane_sym.mechanics.piecewise_linear``.

Everything is reduced to the rim of the running wheels; travel is +.

    motors, left  m_d --[ c, b, gap s1 ]--\\
                                            crane m_k   <- wind W_w, friction W_f
    motors, right m_d --[ c, b, gap s2 ]--/

State x = (x1, v1, x2, v2, x_k, v_k). Opening of link i: u_i = x_i − x_k. At
t = 0 every gap is fully open on the trailing side (u_i = 0): the driving flank
closes at u_i = s_i (link force F_i = c(u_i − s_i) + b·u̇_i), the trailing flank at
u_i = 0 (F_i = c·u_i + b·u̇_i), no force in between; with s_i = 0 the link is
linear. A side's motor force on characteristic k is β_k(v0 − v_i): lines through
the no-load speed v0 (rheostat steps switched at the hold times, then the natural
characteristic). The crane stands while the link forces minus the wind stay
within the friction (first stage); it moves forward (second stage) or back against
W_w ± W_f, and sticks again when its speed returns to zero inside that band.

The model's Table 1 builds the drive here (:func:`table1_results`); scenes
and the bench reach it through ``hybrid.py`` (``STARTUP``).
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from crane_sym.mechanics.phase_table import largest, values
from crane_sym.mechanics.piecewise_linear import Guard, PiecewiseResult, simulate
from crane_sym.sensitivity import Chosen, Sensitivity, sweep

#: Crane states: standing, moving forward, moving back. Link states: driving
#: flank, gap, trailing flank, linear (no backlash).
STAND, FORWARD, BACK = "0", "+", "-"
DRIVE, GAP, TRAIL, LINEAR = 1, 0, -1, 2
_U = ((1.0, 0, 0, 0, -1.0, 0), (0, 0, 1.0, 0, -1.0, 0))      # u_1, u_2 as weights
_DU = ((0, 1.0, 0, 0, 0, -1.0), (0, 0, 0, 1.0, 0, -1.0))


@dataclass(frozen=True)
class ThreeMassTravel:
    """Data of the three-mass travel drive, SI, reduced to the wheel rim.

    Attributes
    ----------
    m_d : motor masses of one side [kg]; m_k : crane [kg]
    c : stiffness of one link [N/m]; b : its damping [N s/m]
    s1, s2 : backlash of the left and right link [m] (>= 0)
    v0 : no-load speed of the motors [m/s]
    slopes : β_k of the characteristics, start steps then natural [N s/m, one side]
    holds : hold time of each start step [s] (one fewer than ``slopes``)
    W_f : friction resistance, W_w : wind resistance of the crane [N]
    """

    m_d: float
    m_k: float
    c: float
    b: float
    s1: float
    s2: float
    v0: float
    slopes: tuple[float, ...]
    holds: tuple[float, ...]
    W_f: float
    W_w: float

    def __post_init__(self) -> None:
        for name in ("m_d", "m_k", "c", "v0"):
            if not getattr(self, name) > 0:
                raise ValueError(f"{name} must be > 0, got {getattr(self, name)!r}")
        for name in ("b", "s1", "s2", "W_f", "W_w"):
            if not getattr(self, name) >= 0:
                raise ValueError(f"{name} must be >= 0, got {getattr(self, name)!r}")
        if not all(k > 0 for k in self.slopes) or len(self.holds) != len(self.slopes) - 1:
            raise ValueError("slopes must be > 0, one more than the hold times")
        if not all(h > 0 for h in self.holds):
            raise ValueError(f"holds must be > 0, got {self.holds!r}")

    # --- the hybrid system ------------------------------------------------------
    def link(self, side: int, contact: int) -> tuple[np.ndarray, float]:
        """Force of link ``side`` (0, 1) as weights·x + constant."""
        if contact == GAP:
            return np.zeros(6), 0.0
        gap = (self.s1, self.s2)[side] if contact == DRIVE else 0.0
        return self.c * np.array(_U[side]) + self.b * np.array(_DU[side]), -self.c * gap

    def total(self, mode: tuple) -> tuple[np.ndarray, float]:
        """F1 + F2 as weights·x + constant."""
        (w1, k1), (w2, k2) = self.link(0, mode[0]), self.link(1, mode[1])
        return w1 + w2, k1 + k2

    def matrices(self, mode: tuple) -> tuple[np.ndarray, np.ndarray]:
        """(A, b) of a mode (link 1, link 2, crane, characteristic)."""
        contact1, contact2, crane, step = mode
        beta = self.slopes[step]
        A, b = np.zeros((6, 6)), np.zeros(6)
        for side, contact, row in ((0, contact1, 1), (1, contact2, 3)):
            w, k = self.link(side, contact)
            A[row - 1, row] = 1.0
            A[row] = -w / self.m_d
            A[row, row] -= beta / self.m_d
            b[row] = (beta * self.v0 - k) / self.m_d
        if crane != STAND:
            w, k = self.total(mode)
            A[4, 5] = 1.0
            A[5] = w / self.m_k
            b[5] = (k - self.W_w - (self.W_f if crane == FORWARD else -self.W_f)) / self.m_k
        return A, b

    def guards(self, mode: tuple) -> list[Guard]:
        """Flanks opening and closing; the crane breaking away or coming to rest."""
        out = []
        for side, contact in enumerate(mode[:2]):
            gap, u = (self.s1, self.s2)[side], _U[side]
            out += {DRIVE: [Guard(f"open {side}", u, -gap, -1)],
                    TRAIL: [Guard(f"open {side}", u, 0.0, 1)],
                    GAP: [Guard(f"drive {side}", u, -gap, 1), Guard(f"trail {side}", u, 0.0, -1)],
                    LINEAR: []}[contact]
        w, k = self.total(mode)
        if mode[2] != STAND:
            out.append(Guard("rests", tuple(np.eye(6)[5]), 0.0, -1 if mode[2] == FORWARD else 1))
        elif w.any():                        # both gaps open: the force cannot change
            out += [Guard("away +", tuple(w), k - self.W_w - self.W_f, 1),
                    Guard("away -", tuple(w), k - self.W_w + self.W_f, -1)]
        return out

    def switch(self, mode: tuple, event: str, t: float,
               x: np.ndarray) -> tuple[tuple, np.ndarray]:
        """Next mode and state after a guard or a scheduled change of characteristic."""
        contact = list(mode[:2])
        crane, step = mode[2], mode[3]
        x = x.copy()
        if event.startswith(("open", "drive", "trail")):
            side = int(event[-1])
            contact[side] = {"open": GAP, "drive": DRIVE, "trail": TRAIL}[event.split()[0]]
        elif event == "next step":
            step += 1
        elif event == "away +":
            crane = FORWARD
        elif event == "away -":
            crane = BACK
        elif event == "rests":
            x[5] = 0.0
            w, k = self.total((*contact, STAND, step))
            net = float(w @ x + k) - self.W_w
            crane = STAND if abs(net) <= self.W_f else FORWARD if net > 0 else BACK
        return (contact[0], contact[1], crane, step), x

    # --- runs -------------------------------------------------------------------
    def start_mode(self) -> tuple:
        """At rest, gaps open on the trailing side, first characteristic."""
        initial = [LINEAR if s == 0 else GAP for s in (self.s1, self.s2)]
        return (initial[0], initial[1], STAND, 0)

    def schedule(self) -> list[tuple[float, str]]:
        """The instants at which the start panel switches to the next characteristic."""
        return [(float(t), "next step") for t in np.cumsum(self.holds)]

    def run(self, t_end: float) -> PiecewiseResult:
        """The start-up from rest over [0, t_end]."""
        return simulate(self, self.start_mode(), np.zeros(6), t_end, self.schedule())

    def load(self, result: PiecewiseResult, times: np.ndarray) -> np.ndarray:
        """F1 + F2 at ``times`` [N], from the phases' closed forms."""
        return values(result, times, self.total)

    def link_load(self, result: PiecewiseResult, times: np.ndarray, side: int) -> np.ndarray:
        """F_side at ``times`` [N]."""
        return values(result, times, lambda mode: self.link(side, mode[side]))

    def peak(self, result: PiecewiseResult) -> tuple[float, float]:
        """(time, value) of the largest F1 + F2: per phase at the ends and at the zeros
        of its rate d/dt(w·x + k) = w·(A x + b), found like any event."""
        return largest(result, self, self.total)

    def step_accelerations(self, result: PiecewiseResult) -> np.ndarray:
        """The crane's mean acceleration over each start step: Δv_k / hold time."""
        edges = np.concatenate([[0.0], np.cumsum(self.holds)])
        speeds = result.state(edges)[:, 5]
        return np.diff(speeds) / np.diff(edges)


#: The parameters chosen for Table 1's drive (SI; reasons in the model text).
CHOSEN = {"J_r": 0.225, "n_m": 2.0, "omega_n": 935 * np.pi / 30, "omega_0": 1000 * np.pi / 30,
          "v_n": 32 / 60, "P_m": 13e3, "lambda_p": 2.0, "c_l": 5e6, "zeta": 0.05,
          "m_k": 250e3, "W_f": 30e3, "W_w": 30e3}
#: Table 1's hold times [s], its backlash values [rad of the fast shaft], F_ср [N].
HOLDS, BACKLASH, F_MEAN = (0.4, 0.8, 0.8), {"0": 0.0, "pi": np.pi, "2pi": 2 * np.pi}, 150e3


def reduced(p: dict[str, float], phi_b: float) -> dict[str, float]:
    """The rim quantities of the steps (m_d, P_n, v0, β1, q, s, b) from ``p``."""
    m_d = p["n_m"] * p["J_r"] * (p["omega_n"] / p["v_n"]) ** 2
    P_n = p["n_m"] * p["P_m"] / p["v_n"]
    v0 = p["v_n"] * p["omega_0"] / p["omega_n"]
    if not v0 > p["v_n"]:
        raise ValueError("omega_0 must exceed omega_n (the no-load speed is above the rated)")
    return {"m_d": m_d, "P_n": P_n, "v0": v0, "beta_1": p["lambda_p"] * P_n / v0,
            "q": (v0 / (p["lambda_p"] * (v0 - p["v_n"]))) ** (1 / 3),
            "s": phi_b * p["v_n"] / p["omega_n"], "b": 2 * p["zeta"] * np.sqrt(p["c_l"] * m_d)}


def drive(r: dict[str, float], p: dict[str, float],
          holds: tuple[float, ...] = HOLDS) -> ThreeMassTravel:
    """The three-mass drive from the rim quantities ``r`` (see :func:`reduced`) and
    ``p``; both sides alike; one characteristic per hold time, then the natural one."""
    slopes = tuple(r["beta_1"] * r["q"] ** k for k in range(len(holds) + 1))
    return ThreeMassTravel(r["m_d"], p["m_k"], p["c_l"], r["b"], r["s"], r["s"], r["v0"],
                           slopes, tuple(holds), p["W_f"], p["W_w"])


#: The parameters of ``CHOSEN`` the paper does not state, with the range each could
#: plausibly take (the others follow from the text: the motor MTF311-6 and its
#: speeds, two per side to cover the stated 60 kN, 30 kN of friction and wind).
PLAUSIBLE = (
    Chosen("J_r", "rotor inertia J_r", "kg·m²", 0.225, 0.2, 0.3, "the MTF311-6 catalogue "
           "rotor, up to a coupling or brake pulley more on the fast shaft"),
    Chosen("v_n", "rated travel speed v_n", "m/min", 32, 25, 40, "portal cranes travel at "
           "25–40 m/min", scale=1 / 60),
    Chosen("lambda_p", "starting-force multiple λ", "", 2.0, 1.6, 2.4, "a relay start, "
           "below the MTF311-6's breakdown multiple of about 2.4"),
    Chosen("c_l", "link stiffness C_пр", "MN/m", 5, 2, 10, "10–50 mm of longitudinal "
           "deflection of a portal side under 100 kN", scale=1e6),
    Chosen("zeta", "damping ratio ζ of a link", "", 0.05, 0.02, 0.1, "a logarithmic "
           "decrement of about 0.1–0.6"),
    Chosen("m_k", "crane mass m_к", "t", 250, 200, 300, "the stated 30 kN of friction at a "
           "specific resistance of 0.010–0.015", scale=1e3),
)


def table1_results(t_end: float = 4.0,
                   p: dict[str, float] | None = None) -> dict[str, dict[str, float]]:
    """Per backlash of Table 1: F_max [kN], its time [s], ψ = F_max/F_ср, the crane's
    mean acceleration over each start step [m/s²]; with the parameters ``p``
    (default: ``CHOSEN``)."""
    p = CHOSEN if p is None else p
    out = {}
    for name, phi in BACKLASH.items():
        model = drive(reduced(p, phi), p)
        run = model.run(t_end)
        when, peak = model.peak(run)
        acc = model.step_accelerations(run)
        out[name] = {"F_max_kN": peak / 1e3, "t_max": when, "psi": peak / F_MEAN,
                     **{f"a{k + 1}": float(a) for k, a in enumerate(acc)}}
    return out


def table1_sensitivities() -> dict[str, Sensitivity]:
    """How far each of the model's Table 1 numbers moves when the parameters of
    ``PLAUSIBLE`` go over their ranges, alone and together: ``"F_max, <backlash>"``,
    ``"psi, <backlash>"``, ``"a<k>, <backlash>"`` -> Sensitivity."""
    def evaluate(p: dict[str, float]) -> dict[str, float]:
        out = {}
        for gap, r in table1_results(p=p).items():
            out |= {f"F_max, {gap}": r["F_max_kN"], f"psi, {gap}": r["psi"],
                    **{f"a{k}, {gap}": r[f"a{k}"] for k in (1, 2, 3)}}
        return out
    return sweep(evaluate, PLAUSIBLE, CHOSEN)
