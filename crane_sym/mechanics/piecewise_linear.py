"""Piecewise-linear systems: x' = A x + b between events, each phase in closed form.

A drive with backlash, brakes that stick and forces switched on at given
instants is linear between the instants at which a contact changes; this
module solves each phase exactly and finds the switching instants by root
finding on those closed forms, never by a time-stepping integrator.

Each phase's exp(Mt) comes from :mod:`crane_sym.mechanics.closed_forms`.

Each phase's end is the first crossing of its guards, found without
skipping one by :mod:`crane_sym.mechanics.event_search`.

Switching
---------
:func:`simulate` runs a :class:`HybridSystem`: a set of modes (any hashable
key), each with its (A, b), its guards, and a rule that maps a fired guard or
a scheduled instant to the next mode and state (e.g. a brake that sticks sets
a speed to zero). Vöth and Tyulenev's two-mass hoist with coupling backlash and
Andrianov and Ivanov's three-mass travel drive with backlash in two stages are
such systems.
"""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import Callable, Hashable, Iterator, Protocol, Sequence

import numpy as np

from crane_sym.mechanics.closed_forms import ClosedForm, JordanFormError, closed_form
from crane_sym.mechanics.event_search import first_crossing

__all__ = ["ClosedForm", "Guard", "HybridSystem", "MAX_PHASES", "PhaseFormError",
           "PhaseLimitError", "PiecewiseResult", "Segment", "by_phase", "closed_form",
           "simulate"]


#: Largest relative residual of a phase's closed form at the phase's end
#: (:meth:`ClosedForm.residual`) before it is taken from :func:`precise_form`.
RESIDUAL = 1e-8
#: The provider of precise closed forms (mpmath: ``exact_forms`` registers it).
_PRECISE: list[Callable[[np.ndarray, np.ndarray, float], ClosedForm]] = []


def use_precise_forms(provider: Callable[[np.ndarray, np.ndarray, float], ClosedForm]) -> None:
    """Register (A, b, the phase's longest) -> the form :func:`precise_form` takes."""
    _PRECISE[:] = [provider]


def precise_form(A: np.ndarray, b: np.ndarray, length: float, x0: np.ndarray,
                 horizon: float) -> ClosedForm:
    """The closed form, from the precise provider, of a phase at most ``horizon``
    long whose double one does not solve its equations to :data:`RESIDUAL` over
    ``length``; refused by name where none is registered or it does not either,
    or not from x0."""
    form = _PRECISE[0](A, b, horizon) if _PRECISE else None
    if form is None or max(form.residual(length, x0, A, b),
                           form.start_miss(length, x0, A, b)) > RESIDUAL:
        raise PhaseFormError(f"a phase of {length:g} s: its closed form does not solve its"
                             f" equations to {RESIDUAL:g} (time scales too far apart for"
                             " double precision)")
    return form


class PhaseFormError(RuntimeError):
    """A phase whose closed form neither route computes to :data:`RESIDUAL`."""


def _next_event(system: "HybridSystem", mode: Hashable, form: ClosedForm, x: np.ndarray,
                end: float, event: str, h_min: float) -> tuple[float, str]:
    """The phase's end: the first guard crossed before ``end``, else ``event``."""
    for guard in system.guards(mode):
        hit = first_crossing(form, x, np.array(guard.weights), guard.constant,
                             end, direction=guard.direction, h_min=h_min)
        if hit is not None and hit < end:
            end, event = hit, guard.name
    return end, event


@dataclass(frozen=True)
class Guard:
    """An affine event function g(x) = weights·x + constant of a mode; it fires
    when g changes sign."""

    name: str
    weights: tuple[float, ...]
    constant: float = 0.0
    direction: int = 0     # +1: fires as g rises through 0, -1: as it falls, 0: either


class HybridSystem(Protocol):
    """What :func:`simulate` needs from a piecewise-linear model."""

    def matrices(self, mode: Hashable) -> tuple[np.ndarray, np.ndarray]:
        """(A, b) of the mode."""

    def guards(self, mode: Hashable) -> list[Guard]:
        """The events that end the mode."""

    def switch(self, mode: Hashable, event: str, t: float,
               x: np.ndarray) -> tuple[Hashable, np.ndarray]:
        """The next mode and state after ``event`` (a guard's or a scheduled name)."""


@dataclass(frozen=True)
class Segment:
    """One phase: mode, start and end time, the state at its start, its closed form."""

    mode: Hashable
    t0: float
    t1: float
    x0: np.ndarray
    form: ClosedForm
    event: str

    def state(self, t: np.ndarray) -> np.ndarray:
        """x(t) for absolute times t in [t0, t1]."""
        return self.form.state(np.asarray(t, dtype=float) - self.t0, self.x0)


@dataclass
class PiecewiseResult:
    """The phases of a run, in order; :meth:`state` evaluates x at any times."""

    segments: list[Segment] = field(default_factory=list)

    @property
    def events(self) -> list[tuple[float, str, Hashable]]:
        """(time, event that ended the phase, mode of the phase)."""
        return [(s.t1, s.event, s.mode) for s in self.segments]

    def state(self, times: np.ndarray) -> np.ndarray:
        """x at ``times`` (inside [0, end]), shape ``times.shape + (n,)``."""
        times = np.asarray(times, dtype=float)
        out = np.empty(times.shape + (self.segments[0].form.n,))
        for i, mask in by_phase([s.t0 for s in self.segments], times):
            out[mask] = self.segments[i].state(times[mask])
        return out


def by_phase(starts: Sequence[float], times: np.ndarray) -> Iterator[tuple[int, np.ndarray]]:
    """(i, mask) for each phase i (phases start at ``starts``, in order) that
    holds some of ``times``; a time before the first start goes to phase 0.

    Parameters
    ----------
    starts : sequence of float
        The phases' start times, increasing.
    times : ndarray
        The times to sort.
    """
    which = np.clip(np.searchsorted(starts, times, side="right") - 1, 0, None)
    for i in range(len(starts)):
        mask = which == i
        if np.any(mask):
            yield i, mask


#: The most phases a run may take (a chattering contact, a brake that sticks
#: and slips at every step, would otherwise never end): past it the run stops
#: with :class:`PhaseLimitError`.
MAX_PHASES = 10_000


class PhaseLimitError(RuntimeError):
    """A run past its phase limit: the limit, the instant reached and the end."""

    def __init__(self, limit: int, t: float, t_end: float, last: str) -> None:
        super().__init__(f"more than {limit} phases (events) by t = {t:.6g} s of {t_end:g} s "
                         f"(the phase limit; the last event {last!r})")
        self.limit, self.t, self.t_end, self.last = limit, t, t_end, last


def _phase(system: HybridSystem, mode: Hashable, x: np.ndarray, first: tuple[float, str],
           h_min: float, exact: bool | None) -> tuple[ClosedForm, float, str]:
    """The phase from ``x`` in ``mode``: its closed form, its length and the
    event that ends it (``first``: the next scheduled one); the precise form
    where the double one's rounding grew past :data:`RESIDUAL` over it."""
    A, b = system.matrices(mode)
    form = closed_form(A, b, exact)
    end, event = _next_event(system, mode, form, x, *first, h_min)
    if form.residual(end, x, A, b) > RESIDUAL:      # rounding grown past the phase
        form = precise_form(A, b, end, x, first[0])
        end, event = _next_event(system, mode, form, x, *first, h_min)
        form = precise_form(A, b, end, x, first[0])   # checked where it ends too
    return form, end, event


def simulate(system: HybridSystem, mode: Hashable, x0: Sequence[float], t_end: float,
             schedule: Sequence[tuple[float, str]] = (), *, h_min: float = 1e-10,
             max_events: int = MAX_PHASES, exact: bool | None = None) -> PiecewiseResult:
    """Run ``system`` from ``mode`` and ``x0`` at t = 0 to ``t_end``.

    ``schedule`` lists (time, name) events known in advance (a brake that
    engages after its delay); ``system.switch`` handles them like guards.
    Each phase is the closed form of its (A, b); its end is the earliest of its
    guards' first crossings (:func:`first_crossing`) and the next scheduled time.
    ``exact`` chooses the closed forms' route (:func:`closed_form`); False, the
    numeric eigenvectors, is what a sweep over many designs wants (each design
    has new matrices, and SymPy's Jordan form costs ~0.2 s a run).

    Parameters
    ----------
    system : HybridSystem
        The modes, their (A, b), guards and switch rule.
    mode : hashable
        The mode at t = 0.
    x0 : sequence of float
        The state at t = 0.
    t_end : float
        End of the run.
    schedule : sequence of (float, str), optional
        Events known in advance.
    h_min : float, optional
        Shortest step of the event search.
    max_events : int, optional
        The run fails beyond this many phases (:class:`PhaseLimitError`).
    exact : bool, optional
        The closed forms' route (None: the system's choice).
    """
    x = np.asarray(x0, dtype=float)
    pending = sorted((float(t), name) for t, name in schedule if 0 <= t < t_end)
    result, t, event = PiecewiseResult(), 0.0, "start"
    for _ in range(max_events):
        horizon = (pending[0][0] if pending else t_end) - t
        first = (horizon, pending[0][1] if pending else "end")
        try:
            form, end, event = _phase(system, mode, x, first, h_min, exact)
        except JordanFormError as exc:
            raise exc.in_phase(len(result.segments) + 1, t) from None
        result.segments.append(Segment(mode, t, t + end, x, form, event))
        x_end = form.state(end, x)
        t += end
        if event == "end":
            return result
        if pending and event == pending[0][1] and end == horizon:
            pending.pop(0)
        mode, x = system.switch(mode, event, t, x_end)
    raise PhaseLimitError(max_events, t, t_end, event)

