"""The piecewise-linear system of a component model: its modes, their
x' = A x + b, the events between them, and a run solved phase by phase.

The state is x = (q_1, q̇_1, …, q_n, q̇_n, β…, w…, s…): each rigid group's
coordinate and speed, then the build-up 0 ≤ β ≤ 1 of each brake whose torque
ramps or rises exponentially (a step brake has β = 1 once engaged), then the
clock states w_j = τ^j of each law in time
(:class:`crane_sym.components.laws.LawClock`), then the parts' first-order
states s (a DC motor's current), whose rates the equations give
(:attr:`crane_sym.components.equations.Equations.first_order`) and which
enter the generalized forces linearly. A :class:`Mode` fixes what
makes the equations of :mod:`crane_sym.components.equations` linear:

- each link with backlash: on its upper flank (+1), in its gap (0) or on its
  lower flank (−1); it opens where its twist returns to the flank, it closes
  where the twist reaches the other end of the gap;
- each group: ``free`` (no brake engaged), sliding ``+`` or ``-`` against its
  brakes (friction −sign(q̇)·Σ |κ| M β), or held ``0`` (q̇ = 0): a sliding group
  is held when its speed reaches zero while the rest of its load N stays
  within the brakes' capacity Σ |κ| M β, and slides again when N reaches it;
  a group a ground contact holds is held at x = 0 while the reaction
  R = s N/κ the rest needs is ≥ 0 (s = ±1, the side the ground is on), lifts
  off (``free``) where R falls through 0, and is set down (held, at rest:
  an inelastic touch) where its body returns to x = 0;
- each brake engaged or not (at its delay), each ramp under way or done,
  each motor on or off (at its instant), each characteristic on its step,
  each motor law on its piece (at its breakpoints);
- each limit on a first-order state free (0) or at its bound (±1, ±2 once
  its tracking state slides): a controller's torque limit
  (:mod:`crane_sym.components.first_order`).

This module is the generic machinery: the groups' motion (free, sliding
against what holds them by friction, held) and the laws' pieces. A kind that
switches the model declares it in its own module (``Kind.events``,
:class:`crane_sym.components.kinds.events.Events`: a brake, a motor, a
characteristic, a ground contact, a gapped elastic link): the system loops
over those kinds for the mode's values they own, their guards, their rules,
what they hold by friction and their own states, and asks no part its class.

Between events the model is linear, so :func:`crane_sym.mechanics.piecewise_linear.simulate`
solves each phase in closed form and finds the events on those closed forms.
"""
from __future__ import annotations

from dataclasses import replace
from functools import cached_property
from typing import Sequence

import numpy as np

from crane_sym.components.design_arrays import (DesignArray, free_limits, mode_guards,
                                                mode_matrices, net_load)
from crane_sym.components.design_family import DesignFamily
from crane_sym.components.design_outputs import LinkLoad
from crane_sym.components.design_switches import switched
from crane_sym.components.equations import Equations
from crane_sym.components.first_order import FirstOrder
from crane_sym.components.laws import LawClock, clocked
from crane_sym.components.layout import layout
from crane_sym.components.mode_numbers import ModeNumbers
from crane_sym.components.modes import BACKWARD, FORWARD, FREE, HELD, Mode
from crane_sym.components.template_forms import one_template
from crane_sym.mechanics.piecewise_linear import Guard

__all__ = ["BACKWARD", "FORWARD", "FREE", "HELD", "ComponentSystem", "Mode"]


class ComponentSystem:
    """A :class:`crane_sym.mechanics.piecewise_linear.HybridSystem` built from
    the equations of a component model; ``extra`` gives values solved later
    (a steady motor's torque)."""

    def __init__(self, equations: Equations, extra: dict | None = None) -> None:
        self.equations = equations
        a = equations.assembly
        self.assembly = a
        self.extra = dict(extra or {})
        self.n = len(a.groups)
        self.backlash = [l for l in a.links if l.gapped]
        # the tables that rest on the structure alone, shared by a template's designs
        shared = layout(equations)
        items = (*a.loads, *a.contacts, *a.links)
        #: The parts of each kind as assembled (its loads, contacts or links),
        #: in the order given.
        self.of_kind = {table: [items[j] for j in places]
                        for table, places in shared.of_kind.items()}
        #: Each kind that switches (``Kind.events``): its events, table and
        #: parts, in the order of :data:`~crane_sym.components.kinds.KINDS`.
        self.switching = [(events, table, self.of_kind[table])
                          for events, table in shared.switching]
        #: The column of each part's own state, by (its kind's table, its place).
        self.columns: dict[tuple[str, int], int] = {
            key: 2 * self.n + column for key, column in shared.columns.items()}
        own = len(self.columns)
        self.beta = {i: col for (t, i), col in self.columns.items() if t == "brake"}
        self.laws = clocked([l.part for l in a.loads])
        self.clock = LawClock(self.laws, 2 * self.n + own)
        self.first = 2 * self.n + own + self.clock.size
        self.size = self.first + len(equations.states)
        self.first_order = FirstOrder(equations, self.n, self.first, self.size, self.extra)
        self.limits = self.first_order.limits
        self.moved = {k: a.place[law.body][:2] for k, law in enumerate(self.laws)
                      if law.law == "speed"}          # law -> (group, κ of its body)
        self.brake_group = [a.place[b.part.body][0] for b in self.of_kind["brake"]]
        self.contacts = list(a.contacts)
        self.events: dict[str, tuple[str, int]] = dict(shared.events)
        #: The rule of each kind's event, by its event's name: (rule, place).
        self.rules: dict[str, tuple] = shared.rules
        #: The kinds' events whose rule sets the mode from the mode alone.
        self.plain: frozenset[str] = shared.plain
        #: The kinds' events whose rule has a form for k designs at once.
        self.together: dict[str, tuple] = shared.together
        for m, law in enumerate(self.laws):
            self.events[f"{law.name} next piece"] = ("piece", m)
        self.events.update(self.first_order.events())
        # a mode's matrices and guards, kept (the copies handed out may be
        # changed) in plain dicts: nothing the system keeps refers back to it, so
        # a sweep's block of 10⁴ systems is freed by reference counts, no cycle
        # left for the collector
        self._kept_matrices: dict[Mode, tuple[np.ndarray, np.ndarray]] = {}
        self._kept_guards: dict[Mode, tuple[Guard, ...]] = {}
        self._twists: dict[str, np.ndarray] = {}

    @cached_property
    def numbers(self) -> ModeNumbers:
        """Its modes' (M, D, K, f, E, G, S) from its own lambdified numbers:
        made when this design is asked alone (the designs of a batch take the
        template's form together, :class:`DesignArray`)."""
        return ModeNumbers(self)

    def start(self, rest: bool) -> dict[str, tuple]:
        """Each field the kinds' parts own, with its values at the start
        (steady, or at ``rest``)."""
        out: dict[str, list] = {}
        for events, _, loads in self.switching:
            for f in events.fields:
                out.setdefault(f, [])
            for load in loads:
                for f, v in events.start(load.part, rest).items():
                    out[f].append(v)
        return {f: tuple(v) for f, v in out.items()}

    def place(self, load) -> tuple[int, float]:
        """(group, κ) of the body a load acts on."""
        return self.assembly.place[load.part.body][:2]

    # --- positions in the state -------------------------------------------------
    def q(self, g: int) -> int:
        return 2 * g

    def v(self, g: int) -> int:
        return 2 * g + 1

    def twist(self, link) -> np.ndarray:
        """Weights of a link's twist u = κ_b q_b − κ_a q_a (and, shifted by one,
        of its rate)."""
        if link.part.name not in self._twists:
            w = np.zeros(self.size)
            for g, weight in self.assembly.weights(link):
                w[self.q(g)] += weight
            self._twists[link.part.name] = w
        return self._twists[link.part.name].copy()

    # --- the linear pieces --------------------------------------------------------
    def linear(self, mode: Mode):
        """(M, D, K, f, E, G, S) of ``mode`` (:class:`ModeNumbers`)."""
        return self.numbers(mode)

    @cached_property
    def alone(self) -> DesignArray:
        """This design as an array of one (:mod:`crane_sym.components.design_arrays`):
        the route its matrices and guards take, the one a batch of designs takes."""
        return DesignArray.of([self], shared=False)

    def net_load(self, mode: Mode, g: int) -> tuple[np.ndarray, float]:
        """The generalized load on group g but its brakes' friction, as w·x + k."""
        w, k = net_load(self.alone, mode, g)
        return w[0], float(k[0])

    def capacity(self, mode: Mode, g: int) -> tuple[np.ndarray, float]:
        """What the parts holding group g by friction can hold (the engaged
        brakes' Σ |κ| M β), as w·x + k, from each kind's ``friction_capacity``."""
        w, k = self.alone.capacity(mode, g)
        return w[0], float(k[0])

    def settled(self, mode: Mode, g: int, x: np.ndarray) -> str:
        """How group g moves from rest in state x: held while its load is
        within what holds it, else sliding the way the load pushes."""
        return self.alone.settled(mode, g, np.asarray(x)[None])[0]

    def rests(self, mode: Mode, g: int, x: np.ndarray) -> tuple[Mode, np.ndarray]:
        """Group g brought to rest (its speed set to 0), then :meth:`settled`."""
        x[self.v(g)] = 0.0
        return mode.moving(g, self.settled(mode, g, x)), x

    def reaction(self, mode: Mode, j: int) -> tuple[np.ndarray, float]:
        """The ground's reaction on the body of contact ``j`` as w·x + k: what
        holds its group at rest, R = s N/κ (0 off the ground)."""
        contact = self.contacts[j]
        if mode.motion[contact.group] != HELD:
            return np.zeros(self.size), 0.0
        w, k = self.net_load(mode, contact.group)
        scale = contact.part.sign / contact.kappa
        return scale * w, scale * k

    def matrices(self, mode: Mode) -> tuple[np.ndarray, np.ndarray]:
        """(A, b) of a mode."""
        A, b = self._matrices(mode)
        return A.copy(), b.copy()

    def _matrices(self, mode: Mode) -> tuple[np.ndarray, np.ndarray]:
        if mode not in self._kept_matrices:
            self._kept_matrices[mode] = self._matrices_uncached(mode)
        return self._kept_matrices[mode]

    def _matrices_uncached(self, mode: Mode) -> tuple[np.ndarray, np.ndarray]:
        """(A, b) of ``mode``: :func:`~crane_sym.components.design_arrays.mode_matrices`
        of this design alone."""
        A, b = mode_matrices(self.alone, mode)
        return A[0], b[0]

    def guards(self, mode: Mode) -> list[Guard]:
        """Contacts that change, sliding groups that come to rest, held groups
        that slide again."""
        return list(self._guards(mode))

    def _guards(self, mode: Mode) -> tuple[Guard, ...]:
        if mode not in self._kept_guards:
            self._kept_guards[mode] = self._guards_uncached(mode)
        return self._kept_guards[mode]

    def _guards_uncached(self, mode: Mode) -> tuple[Guard, ...]:
        def free() -> tuple[np.ndarray, np.ndarray]:
            A, b = self._matrices(free_limits(mode))
            return A[None], b[None]
        return tuple(Guard(name, tuple(w[0]), float(k[0]), d) for name, w, k, d
                     in mode_guards(self.alone, mode, free))

    @staticmethod
    def family(systems: Sequence["ComponentSystem"]) -> "DesignFamily | None":
        """The designs ``systems`` as one :class:`DesignFamily` where they come
        from one template (their equations' shared lambdified form), else None."""
        if not (all(isinstance(s, ComponentSystem) for s in systems) and
                one_template(systems)):
            return None
        return DesignFamily(DesignArray.of(systems))

    def switch(self, mode: Mode, event: str, t: float, x: np.ndarray) -> tuple[Mode, np.ndarray]:
        """The next mode and state after a guard or a scheduled event: a
        kind's own rule, a limit's, or the generic events of
        :func:`~crane_sym.components.design_switches.switched`."""
        x = np.array(x)          # floats, or mpmath numbers in an exact replay: kept so
        if event in self.rules:                   # a kind's own event
            rule, i = self.rules[event]
            return rule(self, mode, i, x)
        kind, i = self.events[event]
        if kind in ("limit+", "limit-", "within", "release"):
            free = self._matrices(free_limits(mode))
            return replace(mode, limits=self.first_order.switch(kind, i, mode.limits, x,
                                                                free)), x
        modes, x = switched(self.alone, mode, event, x[None])     # rest, slip, piece
        return modes[0], x[0]

    # --- outputs ------------------------------------------------------------------
    def contact_load(self, j: int):
        """The reaction of ground contact ``j`` per mode, as (w, k), the
        output :func:`crane_sym.mechanics.phase_table.largest` takes."""
        return lambda mode: self.reaction(mode, j)

    def link_load(self, index: int):
        """The load of elastic link ``index`` per mode, as (w, k): the output of
        a run that :func:`crane_sym.mechanics.phase_table.largest` and
        ``tabulate`` take (not kept here: it refers to the system)."""
        return LinkLoad(self, (index,))

    def links_load(self, indices: Sequence[int]) -> LinkLoad:
        """The summed load of elastic links ``indices`` per mode, as (w, k)
        (:class:`~crane_sym.components.design_outputs.LinkLoad`)."""
        return LinkLoad(self, indices)
