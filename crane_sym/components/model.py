"""A drive train from components: assembled, derived, started in its steady
motion and run phase by phase.

.. code-block:: text

    motor J1 --[ c, d, backlash s ]-- shaft --gear i-- drum J2 --drum r, n-- hook m
      motor torque, switched off        (no inertia)       brake             gravity
      service brake                                                          payload

>>> from crane_sym.components import (Brake, Drum, ElasticLink, Gear, Gravity,
...     Inertia, Mass, Model, Motor)
>>> model = Model([Inertia("motor", "20 kg*m^2"), Inertia("shaft", 0),
...     Inertia("drum", "500 kg*m^2"), Mass("hook", "62 t"),
...     Gear("gearbox", "shaft", "drum", 26.2), Drum("rope", "drum", "hook", "0.5 m", 4),
...     ElasticLink("coupling", "motor", "shaft", "4e4 N*m/rad", backlash="78.6 deg"),
...     Gravity("weight", "hook"), Motor("drive", "motor", "steady", off_at="0 s"),
...     Brake("safety", "drum", "130 kN*m", delay="0.1 s"),
...     Brake("service", "motor", "5.8 kN*m", delay="0.4 s")])
>>> run = model.run("1 s", start_body="motor", start_speed="1500 rpm")
>>> round(run.peaks[0].value)            # the coupling's torque at its largest, N·m
-16819

:meth:`Model.run` finds the steady state at the start (every group moving at
the speed the given body's speed implies, every elastic link at the twist
that balances the constant loads, a ``steady`` motor's torque solved with
them) and hands the :class:`~crane_sym.components.hybrid.ComponentSystem` to
:func:`crane_sym.mechanics.piecewise_linear.simulate`.
"""
from __future__ import annotations

from dataclasses import dataclass, replace
from functools import cached_property, partial
from typing import Sequence

import numpy as np

from crane_sym.components.contacts import ContactPeak, contact_peaks, resting
from crane_sym.components.equations import Equations, derive
from crane_sym.components.hybrid import BACKWARD, FORWARD, FREE, HELD, ComponentSystem, Mode
from crane_sym.components.initial import apply, shifts
from crane_sym.components.laws import LawClock, clocked
from crane_sym.components.loads import Brake, Characteristic, Motor
from crane_sym.components.model_limits import MAX_PHASES, check_cycles
from crane_sym.components.parts import (DIMENSIONS, ROTATING, Component, ComponentError, Given,
                                        value)
from crane_sym.components.pruning import Dropped, Scope, needed
from crane_sym.components.steady import balance
from crane_sym.components.topology import Assembly, assemble
from crane_sym.mechanics.phase_table import HybridRun, largest
from crane_sym.mechanics.piecewise_linear import (PhaseFormError, PhaseLimitError, PiecewiseResult,
                                                  simulate)

__all__ = ["ComponentRun", "LinkPeak", "Model", "start_load"]


@dataclass(frozen=True)
class LinkPeak:
    """The largest load of an elastic link over a run (signed), when it
    occurs, its load at the start and the dynamic factor (peak over
    ``reference``: the link's given reference load, else its load at the start)."""

    link: str
    time: float
    value: float
    unit: str
    static: float
    reference: float | None
    positive: str | None = None       # what a positive load is: "tension", "compression"
    angle: bool = False               # its factor is a sway angle in rad (a pendulum's)

    @property
    def factor(self) -> float | None:
        return None if not self.reference else self.value / self.reference


@dataclass(frozen=True, eq=False)
class ComponentRun:
    """One run: the system, its start, its phases in closed form, the peaks."""

    model: "Model"
    system: ComponentSystem
    mode: Mode
    x0: np.ndarray
    t_end: float
    schedule: tuple[tuple[float, str], ...]
    result: PiecewiseResult

    @property
    def events(self) -> list[tuple[float, str]]:
        """(time, event) of every event in order (the run's end left out)."""
        return [(t, e) for t, e, _ in self.result.events if e != "end"]

    @cached_property
    def peaks(self) -> list[LinkPeak]:
        """The peak of every elastic link, in the order the links were given."""
        out = []
        for i, link in enumerate(self.system.assembly.links):
            affine = self.system.link_load(i)
            when, peak = _largest(self.result, self.system, affine)
            static, reference = start_load(self.system, self.mode, self.x0, i,
                                           displaced=bool(self.model.initial))
            motion = self.system.assembly.motion(link)
            out.append(LinkPeak(link.part.name, when, peak,
                                "N*m" if motion == ROTATING else "N", static, reference,
                                link.part.positive, link.part.reports_angle))
        return out

    @cached_property
    def reactions(self) -> list[ContactPeak]:
        """The peak reaction of every ground contact, in the order given."""
        return contact_peaks(self.result, self.system, self.mode, self.x0)

    def hybrid_run(self, link: str) -> HybridRun:
        """The run with the load of ``link`` as its output (what a scene's module
        tabulates, :mod:`crane_sym.mechanics.phase_table`)."""
        names = [l.part.name for l in self.system.assembly.links]
        if link not in names:
            raise ComponentError(f"no elastic link {link!r}; links: {', '.join(names)}")
        return HybridRun(self.system, self.mode, self.x0, self.t_end, self.schedule,
                         self.system.link_load(names.index(link)))


def start_load(system: ComponentSystem, mode: Mode, x0: np.ndarray, index: int,
               displaced: bool = False) -> tuple[float, float | None]:
    """(load at the start, reference) of elastic link ``index``: the reference
    the dynamic factor divides by is the link's given ``reference``, else its
    load at the start (None where that is zero, or where an initial state
    displaced the start: a load at a displaced start is no static load).

    Parameters
    ----------
    system : ComponentSystem
        The run's system.
    mode, x0 : Mode, ndarray
        The run's first mode and state.
    index : int
        The link's position among the model's elastic links.
    displaced : bool
        Whether ``[[initial]]`` states moved the start.
    """
    w, k = system.link_load(index)(mode)
    static = float(np.asarray(w) @ x0 + k)
    given = system.assembly.links[index].reference
    if given is not None or displaced:
        return static, given
    return static, static or None


def _nothing(size: int, mode: Mode) -> tuple[np.ndarray, float]:
    return np.zeros(size), 0.0


def _largest(result: PiecewiseResult, system: ComponentSystem, affine) -> tuple[float, float]:
    """(time, value) of the largest |w·x + k| over the run
    (:func:`crane_sym.mechanics.phase_table.largest`: the time is the first at
    which the load comes within 1e-9 of its peak)."""
    return largest(result, system, affine, magnitude=True)


class Model:
    """Components assembled (:func:`~crane_sym.components.topology.assemble`)
    and derived (:func:`~crane_sym.components.equations.derive`)."""

    def __init__(self, components: Sequence[Component], name: str = "model",
                 title: str = "", scope: Scope | None = None) -> None:
        self.components = tuple(components)
        self.name, self.title = name, title
        self.scope = scope
        self.assembly: Assembly = assemble(self.components)
        self.initial = shifts(self.components, self.assembly)
        self.equations: Equations = derive(self.assembly)

    @classmethod
    def for_run(cls, components: Sequence[Component], duration: Given, rest: bool = False,
                name: str = "model", title: str = "") -> "Model":
        """The model of only what a run of ``duration`` (from rest when
        ``rest``) needs: the components that cannot act over it dropped before
        the derivation (:func:`~crane_sym.components.pruning.needed`), named in
        ``scope.dropped``; a longer run, or a steady start where one at rest was
        assumed, is refused, and so is a run of more periods than
        :data:`~crane_sym.components.model_limits.MAX_CYCLES`, before the
        derivation."""
        from sympy.physics.units import time
        t_end = value("run", "duration", duration, time).si
        if not t_end > 0:
            raise ComponentError(f"run: duration must be > 0, got {duration!r}")
        kept, scope = needed(components, t_end, rest)
        check_cycles(assemble(kept), t_end)
        return cls(kept, name, title, scope)

    @property
    def dropped(self) -> tuple[Dropped, ...]:
        """The components left out for the run the model was built for."""
        return () if self.scope is None else self.scope.dropped

    @property
    def steady_motor(self):
        """The symbol of the torque of the ``steady`` motor, or None."""
        for load, symbol in zip([l for l in self.assembly.loads if isinstance(l.part, Motor)],
                                self.equations.motor_loads):
            if load.load is None:
                return symbol
        return None

    def start(self, body: str | None = None, speed: Given = 0.0, rest: bool = False
              ) -> tuple[Mode, np.ndarray, dict]:
        """The state at t = 0: (mode, state, solved values).

        Steady (the default): every group moves at the speed ``body``'s
        ``speed`` implies (no link twisting), every link rests at the twist that
        balances the loads with all motors on, on the flank its load pushes it
        to; a ``steady`` motor's torque is solved with the twists, and so is
        every first-order state, at rest (a DC motor's current, a PI loop's
        integral: :func:`~crane_sym.components.steady.balance`); every motor
        law at its value just before t = 0 (0; an acceleration law's a = 0: its
        motor then holds the drive against the other loads). ``rest``:
        everything at rest at zero twist, every gap open (a link with backlash
        at the end of its gap where its twist is zero; a link that only fails,
        its gap of width 0, on its flank), whatever the loads.
        Then each ``[[initial]]`` state moves its body and sets its speed
        (:func:`~crane_sym.components.initial.apply`).
        """
        a = self.assembly
        if rest:
            return self._rest_start()
        if a.contacts:
            raise ComponentError(f"{a.contacts[0].part.label}: a body on the ground starts at "
                                 "rest; give [run] start = \"rest\"")
        if a.couplings:
            raise ComponentError(f"start: a steady start sets the speeds through the elastic "
                                 f"links, not through {a.couplings[0].label}; start at rest")
        body = body or next(iter(a.bodies))
        if body not in a.bodies:
            raise ComponentError(f"start: unknown body {body!r}; bodies: {', '.join(a.bodies)}")
        v = value(f"start of {body!r}", "speed", speed,
                  DIMENSIONS["speed"][a.bodies[body].motion]).si
        n = len(a.groups)
        rates = [None] * n
        g0, k0, _ = a.place[body]
        rates[g0] = v / k0
        changed = True
        while changed:
            changed = False
            for link in a.links:
                for near, far in (ends := a.ends(link), ends[::-1]):
                    here = 0.0 if near.group is None else rates[near.group]
                    if here is not None and far.group is not None and rates[far.group] is None:
                        rates[far.group], changed = here * near.kappa / far.kappa, True
        for link in a.links:
            if sum(w * rates[g] for g, w in a.weights(link)) != 0:
                raise ComponentError(f"start: {link.part.label} holds a body to the ground, "
                                     f"which cannot move at the steady speed {v:g} of "
                                     f"{a.bodies[body].label}; start at speed 0")
        steady = self.steady_motor
        probe = ComponentSystem(self.equations, {steady: 0.0} if steady is not None else {})
        unit = ComponentSystem(self.equations, {steady: 1.0}) if steady is not None else None
        driven = tuple(True for _ in probe.motors)
        contacts = tuple(1 for _ in probe.backlash)
        for _ in range(2 * len(contacts) + 2):
            solved = balance(probe, unit, contacts, driven, np.asarray(rates, dtype=float),
                             0 if a.grounded else 1)
            x = np.zeros(probe.size)
            x[0:2 * n:2], x[1:2 * n:2] = solved.positions, rates
            x[probe.first:] = solved.states
            turned = []
            for link, c in zip(probe.backlash, contacts):
                u = float(probe.twist(link) @ x)
                lo, hi = link.part.flanks
                if c > 0 and u < hi and not np.isfinite(lo):
                    raise ComponentError(f"start: {link.part.label} is slack in the steady "
                                         f"state (twist {u:.6g} below its slack {hi:g}); "
                                         "start = \"rest\"")
                turned.append(c if (u >= hi if c > 0 else u <= lo) else -c)
            if tuple(turned) == contacts:
                break
            contacts = tuple(turned)
        else:
            raise ComponentError("no steady state at the start: the links with backlash "
                                 "cannot all rest on a flank")
        extra = {steady: solved.torque} if steady is not None else {}
        for k, (g, kappa) in probe.moved.items():
            law = probe.laws[k]
            if abs(law.value_at(0.0) - rates[g] * kappa) > 1e-9 * max(abs(law.value_at(0.0)),
                                                                      abs(rates[g] * kappa)):
                raise ComponentError(f"{law.label}: its speed at t = 0 is "
                                     f"{law.value_at(0.0):.6g}, the steady start's "
                                     f"{rates[g] * kappa:.6g}")
        mode = Mode(contacts, tuple(FREE for _ in range(n)),
                    tuple(False for _ in probe.brakes), driven,
                    tuple(False for _ in probe.brakes), tuple(0 for _ in probe.characteristics),
                    tuple(0 for _ in probe.laws), limits=tuple(0 for _ in probe.limits))
        return (*apply(self.initial, probe, mode, x, v), extra)

    def _at_once(self) -> tuple[bool, ...]:
        """Which brakes act at rest from t = 0 (a step without delay)."""
        return tuple(isinstance(l.part, Brake) and l.part.delay == 0
                     and l.part.build_up == "step"
                     for l in self.assembly.loads if isinstance(l.part, Brake))

    def _rest_start(self) -> tuple[Mode, np.ndarray, dict]:
        """At rest, every gap open; a brake without delay engaged from the
        start, its body held while the loads at rest are within its capacity
        (decided here, not at an event), sliding if an initial state moves it."""
        if self.steady_motor is not None:
            raise ComponentError("start at rest: a 'steady' motor has no steady motion to "
                                 "hold; give its torque")
        probe = ComponentSystem(self.equations)
        engaged = self._at_once()
        motion = [FREE for _ in self.assembly.groups]
        mode = Mode(tuple(0 if l.part.opens else 1 for l in probe.backlash), tuple(motion),
                    engaged,
                    tuple(True for _ in probe.motors), tuple(False for _ in probe.brakes),
                    tuple(0 for _ in probe.characteristics), tuple(0 for _ in probe.laws),
                    limits=tuple(0 for _ in probe.limits))
        x = np.zeros(probe.size)
        for k, (g, kappa) in probe.moved.items():    # a speed law starts at its own value
            x[probe.v(g)] = probe.laws[k].value_at(0.0) / kappa
        mode, x = apply(self.initial, probe, mode, x)
        for g in sorted({probe.brake_group[i] for i, on in enumerate(engaged) if on}):
            held = replace(mode, motion=tuple(HELD if j == g else m
                                              for j, m in enumerate(motion)))
            (wn, kn), (wc, kc) = probe.net_load(held, g), probe.capacity(held, g)
            net, cap = float(wn @ x + kn), float(wc @ x + kc)
            if x[probe.v(g)] != 0:           # given a velocity: it slides that way
                net, cap = float(x[probe.v(g)]), -1.0
            motion[g] = HELD if abs(net) <= cap else FORWARD if net > 0 else BACKWARD
        return resting(probe, replace(mode, motion=tuple(motion)), x), x, {}

    def with_parts(self, components: Sequence[Component]) -> "Model":
        """This model with other values of its parts (a design of a sweep): the
        parts assembled anew, the symbolic derivation shared
        (:meth:`~crane_sym.components.equations.Equations.for_design`, which
        raises ValueError for parts that differ in more than their values).

        Parameters
        ----------
        components : sequence of Component
            The parts, as :attr:`components` but for their values.
        """
        model = object.__new__(Model)
        model.components = tuple(components)
        model.name, model.title, model.scope = self.name, self.title, self.scope
        model.assembly = assemble(model.components)
        model.initial = shifts(model.components, model.assembly)
        model.equations = self.equations.for_design(model.assembly)
        return model

    def schedule(self) -> tuple[tuple[float, str], ...]:
        """The events known in advance: brakes engaging and their ramps ending,
        brakes released and links cut (``fails_at``), motors switched off,
        characteristics' steps and motor laws' pieces."""
        out = []
        for load in self.assembly.loads:
            part = load.part
            if isinstance(part, Brake):
                out.append((part.delay, f"{part.name} engages"))
                if part.fails_at is not None:
                    out.append((part.fails_at, f"{part.name} releases"))
                if part.build_up == "ramp":
                    out.append((part.delay + part.time, f"{part.name} ramp done"))
            elif isinstance(part, Motor) and part.off_at is not None:
                out.append((part.off_at, f"{part.name} off"))
            elif isinstance(part, Characteristic):
                out += [(float(t), f"{part.name} next step") for t in np.cumsum(part.holds)]
        out += [(l.part.fails_at, f"{l.part.name} breaks") for l in self.assembly.links
                if l.part.fails_at is not None]
        out += LawClock(clocked([l.part for l in self.assembly.loads]), 0).schedule()
        return tuple(sorted(out))

    def hybrid_run(self, duration: Given, link: str | None = None,
                   start_body: str | None = None, start_speed: Given = 0.0,
                   rest: bool = False) -> HybridRun:
        """The run of :meth:`run`, not yet solved: the system, the state of
        :meth:`start`, the end and the schedule, with the load of ``link``
        (default: the first elastic link) as its output. What a paper's
        ``HybridModel`` hands to scenes, sweeps and the bench.

        Parameters
        ----------
        duration : str or float
            The end of the run (a time with its unit, or seconds).
        link : str, optional
            Name of the elastic link whose load is the output.
        start_body, start_speed, rest
            The start, as :meth:`start` takes it.

        Returns
        -------
        HybridRun
        """
        from sympy.physics.units import time
        t_end = value("run", "duration", duration, time).si
        if not t_end > 0:
            raise ComponentError(f"run: duration must be > 0, got {duration!r}")
        scope = self.scope
        if scope is not None and scope.dropped and (t_end > scope.duration or
                                                    (scope.rest and not rest)):
            raise ComponentError(
                f"run: the model was built for a run of {scope.duration:g} s"
                f"{' from rest' if scope.rest else ''} without {scope.dropped[0].part.label}"
                f" ({scope.dropped[0].reason}); build it for this run (Model.for_run)")
        check_cycles(self.assembly, t_end)
        mode, x0, extra = self.start(start_body, start_speed, rest)
        system = ComponentSystem(self.equations, extra)
        names = [l.part.name for l in system.assembly.links]
        if link is not None and link not in names:
            raise ComponentError(f"no elastic link {link!r}; links: {', '.join(names)}")
        if names:
            output = system.link_load(names.index(link) if link is not None else 0)
        else:                                    # no link: a zero output
            output = partial(_nothing, system.size)
        schedule = self.schedule()
        if rest:             # the brakes engaged from the start are in its mode
            names = {f"{l.part.name} engages" for l, on in zip(
                [l for l in self.assembly.loads if isinstance(l.part, Brake)], self._at_once())
                if on}
            schedule = tuple(e for e in schedule if not (e[0] == 0 and e[1] in names))
        return HybridRun(system, mode, x0, t_end, schedule, output)

    def run(self, duration: Given, start_body: str | None = None,
            start_speed: Given = 0.0, exact: bool | None = None,
            rest: bool = False) -> ComponentRun:
        """The run from the state of :meth:`start` (steady, or at ``rest``) over
        ``duration``, phases in closed form
        (:func:`~crane_sym.mechanics.piecewise_linear.simulate`); a run past
        :data:`~crane_sym.mechanics.piecewise_linear.MAX_PHASES` phases is a
        ComponentError naming the instant it reached."""
        run = self.hybrid_run(duration, None, start_body, start_speed, rest)
        try:
            result = simulate(run.system, run.mode, run.x0, run.t_end, run.schedule, exact=exact,
                              max_events=MAX_PHASES)
        except (PhaseLimitError, PhaseFormError) as exc:
            raise ComponentError(f"run: {exc}") from None
        return ComponentRun(self, run.system, run.mode, run.x0, run.t_end,
                            tuple(run.schedule), result)
