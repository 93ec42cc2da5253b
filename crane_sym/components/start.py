"""The state of a component model at t = 0 (:meth:`crane_sym.components.model.Model.start`):
steady, every group at the speed one body's speed implies and every link at
the twist that balances the loads (a ``steady`` motor's torque solved with
them), or at rest, every gap open; then the ``[[initial]]`` states.

The mode's values the kinds own (a brake engaged, a motor on) are each
kind's at the start (``Events.start``,
:meth:`~crane_sym.components.hybrid.ComponentSystem.start`); at rest, a
group that something holds by friction from t = 0 (a brake without delay)
is held while the loads at rest are within what holds it.
"""
from __future__ import annotations

from typing import Sequence

import numpy as np

from crane_sym.components.contacts import resting
from crane_sym.components.design_arrays import DesignArray
from crane_sym.components.template_forms import one_template
from crane_sym.components.hybrid import BACKWARD, FORWARD, FREE, ComponentSystem, Mode
from crane_sym.components.initial import apply
from crane_sym.components.parts import DIMENSIONS, ComponentError, Given, value
from crane_sym.components.steady import balance

__all__ = ["rest_start", "rest_starts", "start_mode", "steady_start"]


def start_mode(system: ComponentSystem, contacts: tuple[int, ...], n: int, rest: bool) -> Mode:
    """The mode at the start: ``contacts``, every group free, the kinds'
    values at the start (steady, or at ``rest``), every law on its first
    piece, every limit free.

    Parameters
    ----------
    system : ComponentSystem
        The model's system.
    contacts : tuple of int
        Each gapped link's contact.
    n : int
        The number of rigid groups.
    rest : bool
        Whether the run starts at rest.
    """
    mode = Mode(contacts, tuple(FREE for _ in range(n)), (), (), (),
                pieces=tuple(0 for _ in system.laws), limits=tuple(0 for _ in system.limits))
    return mode.setting(**system.start(rest))


def steady_start(model, body: str | None, speed: Given,
                 probe: ComponentSystem | None = None) -> tuple[Mode, np.ndarray, dict]:
    """The steady state at t = 0: (mode, state, solved values).

    Every group moves at the speed ``body``'s ``speed`` implies (no link
    twisting), every link rests at the twist that balances the loads with all
    motors on, on the flank its load pushes it to; a ``steady`` motor's
    torque is solved with the twists, and so is every first-order state, at
    rest (a DC motor's current, a PI loop's integral:
    :func:`~crane_sym.components.steady.balance`); every motor law at its
    value just before t = 0 (0; an acceleration law's a = 0: its motor then holds the
    drive against the other loads). Then each ``[[initial]]`` state moves
    its body and sets its speed (:func:`~crane_sym.components.initial.apply`).

    Parameters
    ----------
    model : Model
        The model.
    body : str or None
        The body whose speed is given (None: the first).
    speed : str or float
        Its speed.
    probe : ComponentSystem, optional
        The model's system, where the model has no ``steady`` motor (built
        here if not given).
    """
    a = model.assembly
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
    steady = model.steady_motor
    if probe is None or steady is not None:
        probe = ComponentSystem(model.equations, {steady: 0.0} if steady is not None else {})
    unit = ComponentSystem(model.equations, {steady: 1.0}) if steady is not None else None
    contacts = tuple(1 for _ in probe.backlash)
    for _ in range(2 * len(contacts) + 2):
        solved = balance(probe, unit, start_mode(probe, contacts, n, False),
                         np.asarray(rates, dtype=float), 0 if a.grounded else 1)
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
    mode = start_mode(probe, contacts, n, False)
    return (*apply(model.initial, probe, mode, x, v), extra)


def rest_start(model, probe: ComponentSystem | None = None) -> tuple[Mode, np.ndarray, dict]:
    """At rest, every gap open (a link with backlash at the end of its gap
    where its twist is zero; a link that only fails, its gap of width 0, on
    its flank), whatever the loads; what holds a group by friction from t = 0
    (a brake without delay) holds it while the loads at rest are within its
    capacity (decided here, not at an event), and it slides if an initial
    state moves it.

    Parameters
    ----------
    model : Model
        The model.
    probe : ComponentSystem, optional
        The model's system (built here if not given).
    """
    if probe is None:
        _no_steady_motor(model)
        probe = ComponentSystem(model.equations)
    return (*rest_starts([model], [probe], probe.alone)[0], {})


def rest_starts(models: Sequence, systems: Sequence[ComponentSystem],
                array: DesignArray | None = None) -> list[tuple[Mode, np.ndarray]]:
    """:func:`rest_start` of each of ``models``, designs of one template with
    their ``systems``: (mode, state) each. Whether a group is held, and how
    it settles, is decided for the designs that share a mode at once, on
    ``array`` (default: the designs' :class:`DesignArray`, their numbers from
    the template's lambdified form; one design alone passes its own).
    ValueError for systems of different templates without ``array``.

    Parameters
    ----------
    models : sequence of Model
        The designs.
    systems : sequence of ComponentSystem
        Their systems.
    array : DesignArray, optional
        The designs as one array.
    """
    _no_steady_motor(models[0])
    if array is None:
        if not one_template(systems):
            raise ValueError("rest_starts: the designs are not of one template")
        array = DesignArray.of(systems)
    starts, made = [], {}
    for model, probe in zip(models, systems):
        key = (id(model), id(probe))                 # designs of a block share both
        if key not in made:
            mode = start_mode(probe, tuple(0 if l.part.opens else 1 for l in probe.backlash),
                              len(model.assembly.groups), True)
            x = np.zeros(probe.size)
            for k, (g, kappa) in probe.moved.items():    # a speed law starts at its own value
                x[probe.v(g)] = probe.laws[k].value_at(0.0) / kappa
            made[key] = tuple(apply(model.initial, probe, mode, x))
        starts.append([made[key][0], made[key][1].copy()])
    held = _held(array, [mode for mode, _ in starts], len(models[0].assembly.groups))
    first = systems[0]
    for g, designs in held:
        for mode, index in _by_mode([mode for mode, _ in starts], designs).items():
            moving = [d for d in index if starts[d][1][first.v(g)] != 0]
            for d in moving:                  # given a velocity: it slides that way
                speed = starts[d][1][first.v(g)]
                starts[d][0] = mode.moving(g, FORWARD if speed > 0 else BACKWARD)
            still = [d for d in index if d not in moving]
            if still:
                motions = array.take(np.array(still)).settled(
                    mode, g, np.array([starts[d][1] for d in still]))
                for d, motion in zip(still, motions):
                    starts[d][0] = mode.moving(g, motion)
    return [(resting(probe, mode, x) if probe.contacts else mode, x)
            for probe, (mode, x) in zip(systems, starts)]


def _no_steady_motor(model) -> None:
    if model.steady_motor is not None:
        raise ComponentError("start at rest: a 'steady' motor has no steady motion to "
                             "hold; give its torque")


def _by_mode(modes: Sequence[Mode], designs: Sequence[int]) -> dict[Mode, list[int]]:
    """The designs among ``designs`` by their mode in ``modes``."""
    out: dict[Mode, list[int]] = {}
    for d in designs:
        out.setdefault(modes[d], []).append(d)
    return out


def _held(array: DesignArray, modes: Sequence[Mode], n: int) -> list[tuple[int, list[int]]]:
    """(group, the designs something holds it in by friction in their mode
    at the start) of each group held in some design."""
    out, by_mode = [], _by_mode(modes, range(len(modes))).items()
    for g in range(n):
        designs: list[int] = []
        for mode, index in by_mode:
            w, k = array.take(np.array(index)).capacity(mode, g)
            designs += [d for d, on in zip(index, w.any(axis=1) | (k != 0)) if on]
        if designs:
            out.append((g, sorted(designs)))
    return out
