"""The two shipped drive trains no paper has, checked: the hoist with rope
stretch and the bridge travel drive with its trolley, each against its
equations of motion written out here by hand and integrated by ``solve_ivp``
(DOP853, rtol 1e-13) with the backlash's contacts and the brakes' sticking and
slipping as events (tests/hand_hybrid.py); and each against its limits: the
gap closed (backlash → 0, and for the hoist the closed form that
components/closed.py derives in the symbols), the rope or the trolley's drive
made rigid (stiffness → ∞)."""
from __future__ import annotations

import re
from dataclasses import dataclass
from pathlib import Path
from typing import Callable

import numpy as np
import pytest
import sympy as sp
from scipy.optimize import minimize_scalar

import hand_hybrid
from crane_sym.components.component_file import read_component_file
from crane_sym.mechanics.phase_table import values

EXAMPLES = Path(__file__).resolve().parents[1] / "examples" / "drive_trains"


def _variant(tmp_path: Path, name: str, *subs: tuple[str, str], drop: tuple[str, ...] = ()):
    """The example ``name`` with text replaced and tables dropped (each must be
    there), read and run."""
    text = (EXAMPLES / f"{name}.toml").read_text()
    for old, new in subs:
        assert old in text, old
        text = text.replace(old, new)
    for block in drop:
        assert block in text, block
        text = text.replace(block, "")
    path = tmp_path / f"{name}_{abs(hash(text))}.toml"
    path.write_text(text)
    read = read_component_file(path)
    return read.model.run(read.duration, read.body, read.speed, rest=read.rest)


def _example(name: str):
    read = read_component_file(EXAMPLES / f"{name}.toml")
    return read.model.run(read.duration, read.body, read.speed, rest=read.rest)


def _table(name: str, link: str) -> str:
    """The [[elastic]] table named ``link`` of an example, as written."""
    text = (EXAMPLES / f"{name}.toml").read_text()
    return re.search(rf'\[\[elastic\]\]\nname = "{link}".*?\n\n', text, re.S).group(0)


def _curve(run, index: int, times: np.ndarray) -> np.ndarray:
    return values(run.result, times, run.system.link_load(index))


@dataclass
class ThreeMassDrive:
    """Both examples by hand: a motor group (J0, angle θ0) and a gearbox group
    (J1, θ1: the gearbox input, everything rigid behind it referred to it)
    joined by a mesh of stiffness c, damping d on a flank and a gap −s < u < 0
    in u = θ1 − θ0; a third mass m at x2 on a spring k and damper dk to the
    point κ θ1 of the gearbox group, pulled by ``weight``. The motor's torque
    ``motor`` while on; each group has a brake of capacity ``caps[g](t)``
    (Σ|κ| M β referred to the group) that opposes sliding and holds the group
    at rest while the rest of its load stays within it.

    State (θ0, ω0, θ1, ω1, x2, v2); torques T0 = M on + F, T1 = −F + κ F2, the
    third mass m v2' = weight − F2, F = c (u + s[contact < 0]) + d u̇ on a
    flank, F2 = k (x2 − κ θ1) + dk (v2 − κ ω1).
    """

    J: tuple[float, float]
    c: float
    d: float
    s: float
    kappa: float
    k: float
    dk: float
    m: float
    weight: float
    motor: float
    caps: tuple[Callable[[float, dict], float], Callable[[float, dict], float]]
    names: tuple[str, str]
    mesh_name: str
    brakes: dict          # scheduled engagement name -> group

    def mesh(self, x, contact: int) -> float:
        u, du = x[2] - x[0], x[3] - x[1]
        return 0.0 if contact == 0 else self.c * (u + (self.s if contact < 0 else 0.0)) \
            + self.d * du

    def rope(self, x) -> float:
        return self.k * (x[4] - self.kappa * x[2]) + self.dk * (x[5] - self.kappa * x[3])

    def torques(self, x, mode) -> tuple[float, float]:
        F = self.mesh(x, mode["contact"])
        return self.motor * mode["on"] + F, -F + self.kappa * self.rope(x)

    def rhs(self, t, x, mode):
        dx = np.zeros(6)
        for g, T in enumerate(self.torques(x, mode)):
            state = mode["motion"][g]
            if state == "0":
                continue
            sign = {"free": 0.0, "+": 1.0, "-": -1.0}[state]
            dx[2 * g], dx[2 * g + 1] = x[2 * g + 1], (T - sign * self.caps[g](t, mode)) / self.J[g]
        dx[4], dx[5] = x[5], (self.weight - self.rope(x)) / self.m
        return dx

    def events(self, mode):
        contact, u = mode["contact"], (lambda t, x: x[2] - x[0])
        shifted = (lambda t, x: x[2] - x[0] + self.s)
        if contact == 0:
            out = [(f"{self.mesh_name} closes +", u, 1), (f"{self.mesh_name} closes -", shifted, -1)]
        elif contact > 0:
            out = [(f"{self.mesh_name} opens", u, -1)]
        else:
            out = [(f"{self.mesh_name} opens", shifted, 1)]
        for g, state in enumerate(mode["motion"]):
            name = self.names[g]
            if state in ("+", "-"):
                out.append((f"{name} rests", lambda t, x, g=g: x[2 * g + 1],
                            -1 if state == "+" else 1))
            elif state == "0":
                out += [(f"{name} slips +", lambda t, x, g=g: self.torques(x, mode)[g]
                         - self.caps[g](t, mode), 1),
                        (f"{name} slips -", lambda t, x, g=g: self.torques(x, mode)[g]
                         + self.caps[g](t, mode), -1)]
        return out

    def _rest(self, mode, g, t, x):
        x[2 * g + 1] = 0.0
        T, cap = self.torques(x, mode)[g], self.caps[g](t, mode)
        motion = list(mode["motion"])
        motion[g] = "0" if abs(T) <= cap else ("+" if T > 0 else "-")
        return {**mode, "motion": tuple(motion)}, x

    def switch(self, mode, name, t, x):
        if name.startswith(self.mesh_name):
            contact = {"closes +": 1, "closes -": -1, "opens": 0}[name[len(self.mesh_name) + 1:]]
            return {**mode, "contact": contact}, x
        if name in self.brakes:                      # a brake engages
            g = self.brakes[name]
            mode = {**mode, "engaged": mode["engaged"] | {name}}
            if x[2 * g + 1] == 0:
                return self._rest(mode, g, t, x)
            motion = list(mode["motion"])
            motion[g] = "+" if x[2 * g + 1] > 0 else "-"
            return {**mode, "motion": tuple(motion)}, x
        if name.endswith(" off"):
            return {**mode, "on": False}, x
        if name.endswith("ramp done"):
            return mode, x
        g = self.names.index(name.split()[0])
        if name.endswith("rests"):
            return self._rest(mode, g, t, x)
        motion = list(mode["motion"])
        motion[g] = name[-1]
        return {**mode, "motion": tuple(motion)}, x

    def run(self, mode, x0, t_end, schedule):
        return hand_hybrid.run(self.rhs, self.events, self.switch, mode, x0, t_end, schedule)

    def loads(self, hand, times) -> tuple[np.ndarray, np.ndarray]:
        """The mesh's and the spring's load at ``times``."""
        X = hand.state(times)
        starts = np.array([p[0] for p in hand.pieces])
        which = np.clip(np.searchsorted(starts, times, side="right") - 1, 0, None)
        mesh = np.array([self.mesh(X[:, j], hand.pieces[w][3]["contact"])
                         for j, w in enumerate(which)])
        return mesh, np.array([self.rope(X[:, j]) for j in range(times.size)])


def _ramp(size: float, start: float, time: float, name: str):
    return lambda t, mode: size * min(max((t - start) / time, 0.0), 1.0) \
        if name in mode["engaged"] else 0.0


def bridge_by_hand() -> ThreeMassDrive:
    """examples/drive_trains/bridge_travel.toml, its values written again."""
    J_m, J_w, m_b, m_t, i, r = 0.6, 60.0, 60e3, 40e3, 60.0, 0.4
    kappa = r / i
    return ThreeMassDrive(
        J=(J_m, J_w / i**2 + m_b * kappa**2), c=250.0, d=1.0, s=np.radians(15.0), kappa=kappa,
        k=2e6, dk=1.4e3, m=m_t, weight=0.0, motor=230.0,
        caps=(_ramp(300.0, 4.2, 0.1, "motor_brakes engages"),
              lambda t, mode: kappa * 6870.0 if "rolling engages" in mode["engaged"] else 0.0),
        names=("motors", "shaft"), mesh_name="drive_line",
        brakes={"rolling engages": 1, "motor_brakes engages": 0})


def hoist_by_hand() -> ThreeMassDrive:
    """examples/drive_trains/hoist_rope_stretch.toml, its values written again."""
    J1, J2, m, g, i, r, n = 20.0, 500.0, 62e3, 9.81, 26.2, 0.5, 4.0
    kappa = r / (i * n)

    def service(t, mode):
        if "service_brakes engages" not in mode["engaged"]:
            return 0.0
        return 5.8e3 * (1 - np.exp(-(t - 0.4) / 0.05))
    return ThreeMassDrive(
        J=(J1, J2 / i**2), c=4e4, d=10.0, s=np.radians(78.6), kappa=kappa, k=2e7, dk=2e4,
        m=m, weight=m * g, motor=-kappa * m * g,        # the steady torque, holding the load
        caps=(service, lambda t, mode: _ramp(130e3 / i, 0.1, 0.05,
                                             "safety_brakes engages")(t, mode)),
        names=("motor", "shaft"), mesh_name="gearbox_mesh",
        brakes={"safety_brakes engages": 1, "service_brakes engages": 0})


def _peak(hand_model, hand, index: int, times: np.ndarray, curve: np.ndarray) -> float:
    """The hand run's peak |load|: the grid's largest, refined on the dense output."""
    j = int(np.argmax(np.abs(curve)))
    lo, hi = times[max(j - 1, 0)], times[min(j + 1, times.size - 1)]
    res = minimize_scalar(lambda t: -abs(hand_model.loads(hand, np.array([t]))[index][0]),
                          bounds=(lo, hi), method="bounded", options={"xatol": 1e-13})
    return max(-res.fun, abs(curve[j]))


def _check_against_hand(run, model: ThreeMassDrive, hand, t_end: float,
                        at_start: tuple[str, ...] = ()) -> list[float]:
    """Events (names, times to 1e-9 s) and both links' loads on a 0.1 ms grid
    and at their peaks, each to 1e-9 of the peak; the errors found, over the peak.
    ``at_start``: events of the hand-written run at t = 0 that the component
    run takes into its first mode (a brake without delay, engaged from the start)."""
    events = [(t, e) for t, e in hand.events if not (t == 0 and e in at_start)]
    assert len(events) == len(hand.events) - len(at_start)
    assert [e for _, e in events] == [e for _, e in run.events]
    assert np.allclose([t for t, _ in events], [t for t, _ in run.events],
                       rtol=0, atol=1e-9)
    times = np.linspace(0.0, t_end, int(round(t_end * 1e4)) + 1)
    errors = []
    for index, curve in enumerate(model.loads(hand, times)):
        peak = abs(run.peaks[index].value)
        errors.append(np.max(np.abs(_curve(run, index, times) - curve)) / peak)
        assert errors[-1] <= 1e-9, (run.peaks[index].link, errors[-1])
        assert _peak(model, hand, index, times, curve) == pytest.approx(peak, rel=1e-9)
    return errors


def test_bridge_travel_against_solve_ivp_with_events():
    """The bridge breaks away at 44.5 ms, the gaps close and open through the
    stop, the bridge comes to rest and is rocked by its trolley (21 events):
    every event by name and time, both loads (found: 1e-11 of the peaks
    539.9 N·m and 37.08 kN) to 1e-9."""
    run = _example("bridge_travel")
    model = bridge_by_hand()
    mode = {"contact": 0, "motion": ("free", "free"), "on": True, "engaged": frozenset()}
    hand = model.run(mode, np.zeros(6), 8.0, [(0.0, "rolling engages"), (4.0, "start off"),
                                               (4.2, "motor_brakes engages"),
                                               (4.3, "motor_brakes ramp done")])
    assert len(run.events) >= 20
    assert {"shaft slips +", "shaft slips -", "shaft rests", "motors rests",
            "drive_line closes +", "drive_line closes -"} <= {e for _, e in run.events}
    brakes = [b.part.name for b in run.system.of_kind["brake"]]
    assert run.mode.engaged[brakes.index("rolling")]          # from the start, at rest
    _check_against_hand(run, model, hand, 8.0, at_start=("rolling engages",))


def test_hoist_rope_stretch_against_solve_ivp_with_events():
    """The emergency stop while lowering: the mesh's gap opens and closes
    under the safety brakes' ramp, the service brakes rise exponentially;
    every event and both loads (mesh −15.07 kN·m, rope 716.6 kN) to 1e-9."""
    run = _example("hoist_rope_stretch")
    model = hoist_by_hand()
    w0 = 1500 * 2 * np.pi / 60
    th0 = model.kappa * model.weight / model.c          # the mesh carries the weight
    x0 = [0.0, w0, th0, w0, model.kappa * th0 + model.weight / model.k, model.kappa * w0]
    # the steady start (the twist to 8e-11: least squares with stiffnesses 2e7 and 4e4)
    assert np.allclose(run.x0[:6], x0, rtol=1e-9, atol=0)
    mode = {"contact": 1, "motion": ("free", "free"), "on": True, "engaged": frozenset()}
    hand = model.run(mode, x0, 0.5, [(0.0, "drive off"), (0.1, "safety_brakes engages"),
                                      (0.15, "safety_brakes ramp done"),
                                      (0.4, "service_brakes engages")])
    _check_against_hand(run, model, hand, 0.5)


# --- limits -------------------------------------------------------------------------

ROPE_END = '[[mass]]\nname = "rope_end"                  # where the rope leaves the tackle: ' \
           'no mass of its own\nmass = "0 kg"\n'
RIGID_ROPE = ('load = "rope_end"', 'load = "hook"')


def test_hoist_stiff_rope_tends_to_the_rigid_rope(tmp_path):
    """The rope's stiffness → ∞ gives the hoist whose drum carries the hook
    directly: the peak mesh torque approaches it as 1/k (272 N·m off at
    2e10 N/m, 27 at 2e11) and the events' times with it (the last one 2.0 ms
    and 0.26 ms off: each impact passes on the shift of the one before)."""
    rigid = _variant(tmp_path, "hoist_rope_stretch", RIGID_ROPE,
                     drop=(ROPE_END, _table("hoist_rope_stretch", "rope")))
    off = []
    for k in ("2e10", "2e11"):
        run = _variant(tmp_path, "hoist_rope_stretch", ('"2e7 N/m"', f'"{k} N/m"'))
        assert [e for _, e in run.events] == [e for _, e in rigid.events]
        off.append((abs(run.peaks[0].value - rigid.peaks[0].value),
                    max(abs(a - b) for (a, _), (b, _) in zip(run.events, rigid.events))))
    assert 8 < off[0][0] / off[1][0] < 12           # first order in 1/k
    assert off[1][0] < 2e-3 * abs(rigid.peaks[0].value)
    assert 6 < off[0][1] / off[1][1] < 14 and off[1][1] < 5e-4      # 2.0 ms, 0.26 ms


def test_hoist_backlash_to_zero_is_the_closed_form(tmp_path):
    """With the rope rigid and the mesh undamped, a gap s → 0 tends to the
    drive without backlash linearly in s (over the whole run, s = 1e-4 and
    1e-6 deg); until the safety brakes engage that drive is two groups on one
    link under the hook's weight: F(t) from components/closed.py in the
    symbols, its values put in, equals the run to 1e-12 of the static torque.
    (Undamped: closed.py's damped form in these nine symbols takes SymPy's
    simplify minutes.)"""
    from crane_sym.components import Model
    from crane_sym.components.closed import link_response
    drop = (ROPE_END, _table("hoist_rope_stretch", "rope"))
    undamped = ('"10 N*m*s/rad"', '"0 N*m*s/rad"')

    def hoist(gap: str):
        return _variant(tmp_path, "hoist_rope_stretch", RIGID_ROPE, undamped,
                        ('"78.6 deg"', f'"{gap}"'), drop=drop)
    solid = hoist("0 deg")
    times = np.linspace(0.0, 0.5, 5001)
    ref = _curve(solid, 0, times)
    off = [np.max(np.abs(_curve(hoist(s), 0, times) - ref)) for s in ("1e-4 deg", "1e-6 deg")]
    static = solid.peaks[0].static
    assert 80 < off[0] / off[1] < 120 and off[1] < 1e-6 * abs(static)
    # the closed form: the same parts without the motor (off at 0) and the brakes
    model = Model([p for p in solid.model.components if p.kind not in ("motor", "brake")])
    u0 = sp.Symbol("u0")
    force = link_response(model, u0).force.xreplace(model.equations.values)
    twist0 = float(solid.system.twist(solid.system.assembly.links[0]) @ solid.x0)
    closed = sp.lambdify(model.equations.t, force.subs(u0, twist0), "numpy")
    early = times[times < 0.1]
    assert closed(0.0) == pytest.approx(static, rel=1e-12)
    assert np.max(np.abs(closed(early) - ref[:early.size])) <= 1e-12 * abs(static)
    assert np.ptp(ref[:early.size]) > 0.05 * abs(static)      # it does move


TROLLEY = '[[mass]]\nname = "trolley"\nmass = "40 t"                      # trolley 15 t and ' \
          'payload 25 t\n'


def test_bridge_backlash_to_zero(tmp_path):
    """A gap s → 0 in the drive line tends to the drive without backlash,
    linearly in s: the drive line's torque over the whole run differs by
    ~1e-3 N·m at s = 1e-4 deg and 100 times less at 1e-6 deg."""
    solid = _variant(tmp_path, "bridge_travel", ('backlash = "15 deg"', 'backlash = "0 deg"'))
    times = np.linspace(0.0, 8.0, 8001)
    ref = _curve(solid, 0, times)
    off = []
    for s in ("1e-4 deg", "1e-6 deg"):
        run = _variant(tmp_path, "bridge_travel", ('"15 deg"', f'"{s}"'))
        off.append(np.max(np.abs(_curve(run, 0, times) - ref)))
    assert 80 < off[0] / off[1] < 120 and off[1] < 1e-7 * abs(solid.peaks[0].value)


def test_bridge_stiff_trolley_drive_tends_to_a_rigid_trolley(tmp_path):
    """The trolley's drive made stiff (k → ∞) gives the bridge carrying the
    trolley rigidly (100 t): over the start-up (the first 4 s) the drive line's
    torque approaches it as 1/k (5.5 N·m off at 2e8 N/m, 0.5 at 2e9)."""
    rigid = _variant(tmp_path, "bridge_travel", ('mass = "60 t"', 'mass = "100 t"'),
                     drop=(TROLLEY, _table("bridge_travel", "trolley_drive")))
    times = np.linspace(0.0, 3.999, 4000)
    ref = _curve(rigid, 0, times)
    off = []
    for k in ("2e8", "2e9"):
        run = _variant(tmp_path, "bridge_travel", ('"2e6 N/m"', f'"{k} N/m"'))
        off.append(np.max(np.abs(_curve(run, 0, times) - ref)))
    assert 7 < off[0] / off[1] < 15 and off[1] < 2e-3 * np.max(np.abs(ref))
