"""Designs of one component model as arrays (:class:`DesignArray`): a mode's
M, D, K, f, its x' = A x + b and its guards for k designs at once, a leading
axis of designs on every array.

Designs of one template share Lagrange's equations (``Model.with_parts``,
``Equations.for_design``); they differ in their parts' values. The numbers a
mode needs are then one call of the template's lambdified equations on the
designs' parameter values stacked
(:func:`~crane_sym.components.template_forms.template_numbers`), and (A, b) is
solved for all of them together (:func:`mode_matrices`). One design is the
case k = 1: :class:`~crane_sym.components.hybrid.ComponentSystem` asks this
module for its own matrices and guards, so a design solved alone and in a
batch take one route. The kinds' hooks (``Events.friction_capacity``,
``rates``, ``value``, ``guards``) answer for the whole array: they read the
structure from :attr:`DesignArray.model` and each design's numbers through
:meth:`DesignArray.gather` (asked of the designs once, then sliced as the
solver takes designs apart), so no hook runs once per design and phase.
"""
from __future__ import annotations

from dataclasses import dataclass, field, replace
from typing import Any, Callable, Hashable, Sequence

import numpy as np

from crane_sym.components.first_order import fill_rates, hold_limits, limit_guards
from crane_sym.components.modes import BACKWARD, FORWARD, HELD, Mode, solved
from crane_sym.components.template_forms import evaluated, template_numbers

__all__ = ["DesignArray", "free_limits", "mode_guards", "mode_matrices", "net_load", "pushes"]

def _padded(pieces: Sequence[Sequence[tuple[float, tuple[float, ...]]]], width: int
            ) -> np.ndarray:
    """Each design's pieces of a law, (designs, pieces, ``width``): a piece's
    coefficients of τ^j, zeros past its degree (they add nothing)."""
    out = np.zeros((len(pieces), len(pieces[0]), width))
    for d, design in enumerate(pieces):
        for p, (_, row) in enumerate(design):
            out[d, p, :len(row)] = row
    return out


@dataclass(frozen=True, eq=False)
class DesignArray:
    """k designs of one component model, with what differs between them
    stacked once: their parameter values (through ``numbers``), flanks, laws'
    pieces, first-order rates and bounds, and the κ of each group a speed law
    moves. :meth:`take` keeps some of the designs: ``rows`` are their places
    among ``systems``, the ``ComponentSystem`` of every design of the whole
    array (not sliced: :meth:`gather` asks them once). Designs that are one
    system but for some of its parameters
    (:class:`~crane_sym.components.design_block.DesignBlock`) hold that
    system alone and their count, ``designs``."""

    systems: tuple
    numbers: Callable                       # (mode, array) -> (M, D, K, f, E, G, S)
    flanks: np.ndarray                      # (k, gapped links, 2): lower, upper
    pieces: tuple[np.ndarray, ...]          # per law: (k, pieces, coefficients)
    rates: tuple[np.ndarray, ...]           # (R_q, R_v, R_s, R_L, r_0), each (k, ...)
    bounds: np.ndarray                      # (k, limits)
    kappas: np.ndarray                      # (k, speed laws)
    rows: np.ndarray = field(default=None)  # the designs' rows in the whole array
    #: What :meth:`gather` asked of the whole array's designs, by key (shared by
    #: the arrays :meth:`take` makes).
    gathered: dict = field(default_factory=dict, repr=False)
    #: The numbers of the modes asked of these designs (:meth:`linear`, not
    #: changed by its callers; :meth:`take` starts afresh).
    numbered: dict = field(default_factory=dict, repr=False)
    #: How many designs share ``systems[0]`` but for their parameters (a
    #: ``DesignBlock``); None: one system a design.
    designs: int | None = None

    @classmethod
    def of(cls, systems: Sequence, shared: bool = True) -> "DesignArray":
        """The designs ``systems``; ``shared``: their numbers from the
        template's lambdified form in one call, else (one system alone) from
        its own :class:`~crane_sym.components.mode_numbers.ModeNumbers`."""
        systems = tuple(systems)
        first = systems[0]
        if shared:
            numbers = evaluated(first, template_numbers(systems))
        else:
            def numbers(mode: Mode, array: "DesignArray"):
                return tuple(m[None] for m in first.linear(mode))
        flanks = np.array([[l.part.flanks for l in s.backlash] for s in systems],
                          dtype=float).reshape(len(systems), len(first.backlash), 2)
        pieces = tuple(_padded([s.clock.pieces[m] for s in systems], law.degree + 1)
                       for m, law in enumerate(first.laws))
        rates = tuple(np.array([s.first_order.rates[j] for s in systems])
                      for j in range(len(first.first_order.rates)))
        bounds = np.array([[l.bound for l in s.limits] for s in systems],
                          dtype=float).reshape(len(systems), -1)
        kappas = np.array([[kappa for _, kappa in s.moved.values()] for s in systems],
                          dtype=float).reshape(len(systems), -1)
        return cls(systems, numbers, flanks, pieces, rates, bounds, kappas,
                   np.arange(len(systems)))

    @property
    def k(self) -> int:
        return len(self.rows)

    @property
    def model(self):
        """The first design's system: what the designs share (sizes, places, structure)."""
        return self.systems[0]

    def take(self, index: np.ndarray) -> "DesignArray":
        """The designs at ``index`` (positions in this array)."""
        return replace(self, flanks=self.flanks[index],
                       pieces=tuple(p[index] for p in self.pieces),
                       rates=tuple(r[index] for r in self.rates), bounds=self.bounds[index],
                       kappas=self.kappas[index], rows=self.rows[index], numbered={})

    def gather(self, key: Hashable, ask: Callable[[Any], Any]) -> np.ndarray:
        """``ask(system)`` of each design as one float array, (k, ...): asked
        of the whole array's designs the first time ``key`` is met, kept, and
        sliced to this array's designs after."""
        if key not in self.gathered:
            if self.designs is None:
                self.gathered[key] = np.array([ask(s) for s in self.systems], dtype=float)
            else:                                # one system: asked once, every design's
                self.gathered[key] = np.repeat(np.array([ask(self.systems[0])], dtype=float),
                                               self.designs, axis=0)
        return self.gathered[key][self.rows]

    def linear(self, mode: Mode):
        """(M, D, K, f, E, G, S) of ``mode``, a leading axis of designs (kept:
        a mode's matrices, guards and loads each ask for them)."""
        if mode not in self.numbered:
            self.numbered[mode] = self.numbers(mode, self)
        return self.numbered[mode]

    def contact(self, contacts: tuple[int, ...]) -> tuple[list[float], np.ndarray]:
        """(χ, δ): each gapped link in contact (1) or not (0), the flank it is on."""
        chi = [0.0 if c == 0 else 1.0 for c in contacts]
        delta = np.zeros((self.k, len(contacts)))
        for j, c in enumerate(contacts):
            if c:
                delta[:, j] = self.flanks[:, j, 1 if c > 0 else 0]
        return chi, delta

    def inputs(self, mode: Mode) -> tuple[np.ndarray, np.ndarray]:
        """(switches, slopes), (k, values) each: the kinds' ``Events.value`` per design."""
        by_role: dict[str, list] = {"switches": [], "slopes": []}
        for events, _, parts in self.model.switching:
            if events.role:
                by_role[events.role] += [np.broadcast_to(events.value(self, mode, i), (self.k,))
                                         for i in range(len(parts))]
        return tuple(np.array(by_role[r], dtype=float).T.reshape(self.k, -1)
                     for r in ("switches", "slopes"))

    def signals(self, steps: Sequence[int]) -> tuple[np.ndarray, np.ndarray]:
        """(W, c): law m's value W[:, m]·x + c[:, m] on the pieces ``steps``."""
        rows = [self._row(m, k) for m, k in enumerate(steps)]
        return self.model.clock.signals_of(rows, self.model.size, (self.k,))

    def derivative(self, steps: Sequence[int], m: int) -> tuple[np.ndarray, np.ndarray]:
        """(w, c): the rate of law m on its piece, dp/dτ = w·x + c, per design."""
        return self.model.clock.derivative_of(self._row(m, steps[m]), m, self.model.size)

    def _row(self, m: int, step: int) -> np.ndarray:
        """Law m's coefficients on piece ``step`` (its last past the end), per design."""
        return self.pieces[m][:, min(step, self.pieces[m].shape[1] - 1)]

    def capacity(self, mode: Mode, g: int) -> tuple[np.ndarray, np.ndarray]:
        """What holds group g by friction (the kinds' ``friction_capacity``), as
        w·x + k per design."""
        w, k = np.zeros((self.k, self.model.size)), np.zeros(self.k)
        for events, _, loads in self.model.switching:
            if events.friction_capacity is None:
                continue
            for i in range(len(loads)):
                held = events.friction_capacity(self, mode, i)
                if held is not None and held[0] == g:
                    if held[1] is None:
                        k += held[2]
                    else:
                        w[:, held[1]] += held[2]
        return w, k

    def settled(self, mode: Mode, g: int, x: np.ndarray) -> list[str]:
        """How group g moves from rest in each design's state x (k, size):
        held while its load is within what holds it, else sliding the way
        the load pushes."""
        held = mode.moving(g, HELD)
        (wn, kn), (wc, kc) = net_load(self, held, g), self.capacity(held, g)
        net, cap = (wn * x).sum(axis=1) + kn, (wc * x).sum(axis=1) + kc
        return [HELD if abs(float(a)) <= float(c) else FORWARD if float(a) > 0 else BACKWARD
                for a, c in zip(net, cap)]

    def reaction(self, mode: Mode, j: int) -> tuple[np.ndarray, np.ndarray]:
        """The ground's reaction on the body of contact ``j`` as w·x + k per
        design: what holds its group at rest, R = s N/κ (0 off the ground)."""
        contact = self.model.contacts[j]
        if mode.motion[contact.group] != HELD:
            return np.zeros((self.k, self.model.size)), np.zeros(self.k)
        w, k = net_load(self, mode, contact.group)
        scale = contact.part.sign / self.gather(("contact kappa", j),
                                                lambda s: s.contacts[j].kappa)
        return scale[:, None] * w, scale * k


def pushes(array: DesignArray, mode: Mode) -> tuple[np.ndarray, np.ndarray]:
    """(R, r): the generalized forces on the groups but the brakes' friction,
    R x + r per design: the right-hand side of M q̈ = R x + r."""
    _, D, K, f, _, G, S = array.linear(mode)
    n, first = array.model.n, array.model.first
    W, c = array.signals(mode.pieces)
    R = G @ W
    R[:, :, 0:2 * n:2] -= K
    R[:, :, 1:2 * n:2] -= D
    R[:, :, first:] += S
    return R, f + (G @ c[:, :, None])[:, :, 0]


def net_load(array: DesignArray, mode: Mode, g: int) -> tuple[np.ndarray, np.ndarray]:
    """The generalized load on group g but its brakes' friction, w·x + k per
    design; a full M couples the others' accelerations in."""
    system = array.model
    M = array.linear(mode)[0]
    R, r = pushes(array, mode)
    w, k = R[:, g].copy(), r[:, g].copy()
    coupled = [j for j in range(system.n) if j != g and M[:, g, j].any()]
    if coupled:
        A, b = mode_matrices(array, mode)
        rows = [system.v(j) for j in coupled]
        m = M[:, g, coupled]
        w -= (m[:, None, :] @ A[:, rows])[:, 0]
        k -= (m * b[:, rows]).sum(axis=1)
    return w, k


def free_limits(mode: Mode) -> Mode:
    """``mode`` with every first-order limit free."""
    return replace(mode, limits=tuple(0 for _ in mode.limits))


def mode_matrices(array: DesignArray, mode: Mode) -> tuple[np.ndarray, np.ndarray]:
    """(A, b) of ``mode`` per design, (k, size, size) and (k, size): M q̈ =
    R x + r less each sliding group's friction, solved for the groups that
    move freely; a held group's acceleration is 0, a speed law's group's the
    law's (they enter the others' rows through a full M's off-diagonal
    entries); then the clocks', the parts' own and the first-order rows."""
    system = array.model
    n, size, k = system.n, system.size, array.k
    M = array.linear(mode)[0]
    R, r = pushes(array, mode)
    A0, b0 = np.zeros((size, size)), np.zeros(size)
    system.clock.fill(A0, b0, mode.pieces)          # the clocks' rows: the same for all
    A, b = np.repeat(A0[None], k, axis=0), np.repeat(b0[None], k, axis=0)
    W, c = array.signals(mode.pieces)
    fill_rates(array.rates, n, system.first, A, b, W, c)
    S, s = np.zeros_like(R), np.zeros_like(r)      # the sliding groups' friction
    for g in range(n):
        if mode.motion[g] in (FORWARD, BACKWARD):
            sign = 1.0 if mode.motion[g] == FORWARD else -1.0
            w, h = array.capacity(mode, g)
            S[:, g], s[:, g] = sign * w, sign * h
        if mode.motion[g] != HELD:
            A[:, system.q(g), system.v(g)] = 1.0
    for m, (law, (g, _)) in enumerate(system.moved.items()):      # a speed law's motion
        w, h = array.derivative(mode.pieces, law)
        A[:, system.v(g)], b[:, system.v(g)] = w / array.kappas[:, m, None], h / array.kappas[:, m]
    moved = {g for g, _ in system.moved.values()}
    fixed = [g for g in range(n) if mode.motion[g] == HELD or g in moved]
    free = [g for g in range(n) if g not in fixed]
    if free:
        rows, known = [system.v(g) for g in free], [system.v(g) for g in fixed]
        R, r = R[:, free], r[:, free]
        coupling = M[:, free][:, :, fixed]
        if coupling.any():                  # a known acceleration pushes through M
            R = R - coupling @ A[:, known]
            r = r - (coupling @ b[:, known, None])[:, :, 0]
        mass = M[:, free][:, :, free]
        A[:, rows], b[:, rows] = solved(mass, R, r)
        if S.any() or s.any():
            friction = solved(mass, S[:, free], s[:, free])
            A[:, rows] -= friction[0]
            b[:, rows] -= friction[1]
    for events, _, loads in system.switching:       # the parts' own states
        if events.rates is not None:
            for i in range(len(loads)):
                events.rates(array, mode, i, A, b)
    hold_limits(system.limits, A, b, mode.limits)
    return A, b


def mode_guards(array: DesignArray, mode: Mode,
                free: Callable[[], tuple[np.ndarray, np.ndarray]]
                ) -> list[tuple[str, np.ndarray, np.ndarray, int]]:
    """The guards of ``mode`` per design, (event, w (k, size), k (k,),
    direction) each: the kinds' own (for the whole array: a kind raises
    ValueError where its designs name different guards), sliding groups
    coming to rest, held groups slipping, the first-order limits (``free()``:
    (A, b) of the mode with every limit free)."""
    system, out, fixed = array.model, [], set()
    shape = (array.k, system.size)
    for events, _, loads in system.switching:        # the kinds' own guards
        for i in range(len(loads)):
            out += [(name, np.array(np.broadcast_to(np.asarray(w, float), shape)),
                     np.array(np.broadcast_to(np.asarray(c, float), shape[:1])), d)
                    for name, w, c, d in events.guards(array, mode, i)]
            if events.fixes is not None:
                fixed.add(events.fixes(system, mode, i))
    unit = np.eye(system.size)
    for g, state in enumerate(mode.motion):
        name = system.assembly.groups[g].name
        if g in fixed:                       # held by a part, not by friction
            continue
        if state in (FORWARD, BACKWARD):
            out.append((f"{name} rests", np.repeat(unit[None, system.v(g)], array.k, axis=0),
                        np.zeros(array.k), -1 if state == FORWARD else 1))
        elif state == HELD:
            (wn, kn), (wc, kc) = net_load(array, mode, g), array.capacity(mode, g)
            if (wn - wc).any():             # a constant load cannot come to slide
                out.append((f"{name} slips +", wn - wc, kn - kc, 1))
            if (wn + wc).any():
                out.append((f"{name} slips -", wn + wc, kn + kc, -1))
    return out + limit_guards(system.limits, array.bounds, mode.limits, system.size, free)

