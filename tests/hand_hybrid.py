"""A hybrid run written by hand for the tests: ``solve_ivp`` (DOP853) between
events, each event a terminal event function with its direction, the mode
switched by a rule the test writes itself. Nothing of crane_sym is used, so a
component model checked against it is checked against an independent route.
"""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import Callable, Hashable

import numpy as np
from scipy.integrate import solve_ivp

#: An event of a mode: its name, g(t, x), and the direction it fires in
#: (+1 rising through 0, -1 falling).
Event = tuple[str, Callable[[float, np.ndarray], float], int]


@dataclass
class HandRun:
    """The pieces of the run (t0, t1, dense solution, mode) and its events."""

    pieces: list = field(default_factory=list)
    events: list[tuple[float, str]] = field(default_factory=list)

    def state(self, times: np.ndarray) -> np.ndarray:
        """x at ``times``, shape (n, len(times))."""
        times = np.asarray(times, float)
        starts = np.array([p[0] for p in self.pieces])
        which = np.clip(np.searchsorted(starts, times, side="right") - 1, 0, None)
        out = np.empty((len(self.pieces[0][2](starts[0])), times.size))
        for i, (t0, t1, sol, _) in enumerate(self.pieces):
            mask = which == i
            if mask.any():
                out[:, mask] = sol(times[mask])
        return out


def run(rhs: Callable[[float, np.ndarray, Hashable], np.ndarray],
        events: Callable[[Hashable], list[Event]],
        switch: Callable[[Hashable, str, float, np.ndarray], tuple[Hashable, np.ndarray]],
        mode: Hashable, x0, t_end: float, schedule: list[tuple[float, str]],
        rtol: float = 1e-13, atol: float = 1e-13) -> HandRun:
    """Integrate from ``mode``, ``x0`` to ``t_end``: each piece ends at the
    first event of its mode or the next scheduled (time, name); ``switch``
    gives the next mode and state."""
    out, t, x = HandRun(), 0.0, np.array(x0, float)
    pending = sorted(schedule)
    while t < t_end:
        while pending and pending[0][0] <= t:
            name = pending.pop(0)[1]
            out.events.append((t, name))
            mode, x = switch(mode, name, t, x)
        stop = pending[0][0] if pending else t_end
        fired = events(mode)
        fns = []
        for _, g, direction in fired:
            def fn(s, y, g=g):
                return g(s, y)
            fn.terminal, fn.direction = True, direction
            fns.append(fn)
        sol = solve_ivp(lambda s, y: rhs(s, y, mode), (t, stop), x, method="DOP853",
                        rtol=rtol, atol=atol, events=fns or None, dense_output=True)
        assert sol.success, sol.message
        out.pieces.append((t, sol.t[-1], sol.sol, mode))
        hits = [(te[0], i) for i, te in enumerate(sol.t_events or []) if len(te)]
        t, x = float(sol.t[-1]), sol.y[:, -1].copy()
        if hits:
            when, i = min(hits)
            name = fired[i][0]
            out.events.append((t, name))
            mode, x = switch(mode, name, t, x)
    return out
