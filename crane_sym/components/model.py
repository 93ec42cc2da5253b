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

from dataclasses import dataclass
from functools import cached_property, partial
from typing import Hashable, Sequence

import numpy as np

from crane_sym.components.contacts import ContactPeak, contact_peaks
from crane_sym.components.template_forms import template
from crane_sym.components.design_assembly import reassemble
from crane_sym.components.equations import Equations, derive
from crane_sym.components.hybrid import ComponentSystem, Mode
from crane_sym.components.initial import shifts
from crane_sym.components.laws import LawClock, clocked
from crane_sym.components.layout import layout
from crane_sym.components.model_limits import MAX_PHASES, check_cycles, first_beyond
from crane_sym.components.parts import ROTATING, Component, ComponentError, Given, value
from crane_sym.components.pruning import Dropped, Scope, needed
from crane_sym.components.start import rest_start, rest_starts, steady_start
from crane_sym.components.topology import Assembly, assemble
from crane_sym.mechanics.phase_table import HybridRun, largest
from crane_sym.mechanics.piecewise_linear import (PhaseFormError, PhaseLimitError, PiecewiseResult,
                                                  simulate)

__all__ = ["ComponentRun", "LinkPeak", "Model", "rest_runs", "start_load", "started_at_rest"]


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
        return next((s for s in self.equations.motor_loads if s not in self.equations.values),
                    None)

    def start(self, body: str | None = None, speed: Given = 0.0, rest: bool = False
              ) -> tuple[Mode, np.ndarray, dict]:
        """The state at t = 0: (mode, state, solved values), steady or at
        ``rest`` (:func:`~crane_sym.components.start.steady_start`,
        :func:`~crane_sym.components.start.rest_start`)."""
        if rest:
            return rest_start(self)
        return steady_start(self, body, speed)

    def started(self, body: str | None = None, speed: Given = 0.0, rest: bool = False
                ) -> tuple[Mode, np.ndarray, ComponentSystem]:
        """:meth:`start` with the run's system: (mode, state, system). Where
        the start solves no value (no ``steady`` motor) the system the start
        was found with is the run's, not built a second time.

        Parameters
        ----------
        body, speed, rest
            The start, as :meth:`start` takes it.
        """
        if self.steady_motor is not None:
            mode, x0, extra = self.start(body, speed, rest)
            return mode, x0, ComponentSystem(self.equations, extra)
        system = ComponentSystem(self.equations)
        mode, x0, _ = (rest_start(self, system) if rest else
                       steady_start(self, body, speed, system))
        return mode, x0, system

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
        model.assembly = reassemble(model.components, self.components, self.assembly)
        model.initial = shifts(model.components, model.assembly)
        model.equations = self.equations.for_design(model.assembly)
        return model

    def schedule(self, rest: bool = False) -> tuple[tuple[float, str], ...]:
        """The events known in advance: each switching kind's (a brake
        engaging, its ramp ending, released; a motor switched off; a
        characteristic's steps; a link cut at ``fails_at``;
        :class:`~crane_sym.components.kinds.events.Events`) and motor laws' pieces; for a start at
        ``rest``, without those its mode has taken already."""
        a, shared = self.assembly, layout(self.equations)
        items = (*a.loads, *a.contacts, *a.links)
        contacts = range(len(a.loads), len(a.loads) + len(a.contacts))   # none scheduled
        out = [e for events, table in shared.switching for j in shared.of_kind[table]
               if j not in contacts for e in events.schedule(items[j].part, rest)]
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
        t_end = self.end(duration, rest)
        check_cycles(self.assembly, t_end)
        mode, x0, system = self.started(start_body, start_speed, rest)
        return self._hybrid(system, mode, x0, t_end, link, rest)

    def end(self, duration: Given, rest: bool = False) -> float:
        """The end of a run of ``duration`` in seconds, refused in one line
        where it is not > 0 or past what the model was built for (its scope).

        Parameters
        ----------
        duration : str or float
            The end of the run (a time with its unit, or seconds).
        rest : bool
            Whether the run starts at rest.
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
        return t_end

    def _hybrid(self, system: ComponentSystem, mode: Mode, x0: np.ndarray, t_end: float,
                link: str | None, rest: bool) -> HybridRun:
        """The run from a start found, with the load of ``link`` (default the
        first elastic link, none: a zero output) as its output."""
        names = [l.part.name for l in system.assembly.links]
        if link is not None and link not in names:
            raise ComponentError(f"no elastic link {link!r}; links: {', '.join(names)}")
        if names:
            output = system.link_load(names.index(link) if link is not None else 0)
        else:                                    # no link: a zero output
            output = partial(_nothing, system.size)
        return HybridRun(system, mode, x0, t_end, self.schedule(rest), output)

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


def started_at_rest(models: Sequence[Model]) -> list[tuple[Mode, np.ndarray, ComponentSystem]]:
    """:meth:`Model.started` at rest of the designs of a sweep's block:
    (mode, state, system) each, the starts of the designs of one template
    found together (:func:`~crane_sym.components.start.rest_starts`: a held
    group settled for the designs in one mode at once).

    Parameters
    ----------
    models : sequence of Model
        The designs.
    """
    systems = [ComponentSystem(model.equations) for model in models]
    templates: dict[Hashable, list[int]] = {}
    for d, system in enumerate(systems):           # a model of its own: alone
        templates.setdefault(template(system) or ("alone", d), []).append(d)
    starts: list = [None] * len(models)
    for index in templates.values():
        one = [systems[d] for d in index]
        found = rest_starts([models[d] for d in index], one,
                            None if template(one[0]) is not None else one[0].alone)
        for d, (mode, x0) in zip(index, found):
            starts[d] = (mode, x0, systems[d])
    return starts


def rest_runs(models: Sequence[Model], duration: Given, link: str | None = None
              ) -> list[HybridRun]:
    """:meth:`Model.hybrid_run` from rest of the designs of a sweep's block,
    each checked and run as alone, their starts found together
    (:func:`started_at_rest`).

    Parameters
    ----------
    models : sequence of Model
        The designs.
    duration : str or float
        The end of the runs.
    link : str, optional
        Name of the elastic link whose load is the output.
    """
    t_end = models[0].end(duration, rest=True)
    beyond = first_beyond([model.assembly for model in models], t_end)
    if beyond is not None:
        raise beyond[1]
    return [model._hybrid(system, mode, x0, t_end, link, True)
            for model, (mode, x0, system) in zip(models, started_at_rest(models))]
