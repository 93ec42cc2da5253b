"""Shared fixtures: a test module names its paper with ``DERIVATION = "<id>"``;
``integrated`` runs a piecewise-linear hybrid system by solve_ivp with events."""
import numpy as np
import pytest

from crane_sym import registry
from crane_sym.audit import audit


@pytest.fixture(scope="module")
def derivation(request):
    """The module's derivation, built once per test run (``registry.get``)."""
    return registry.get(request.module.DERIVATION)


@pytest.fixture(scope="module")
def records(derivation):
    """Audit records of the module's derivation by label."""
    return {r.label: r for r in audit(derivation)}


class _Integrated:
    """The same hybrid system, integrated by solve_ivp with events."""

    def __init__(self, system, max_step=np.inf):
        self.system, self.max_step = system, max_step

    def run(self, mode, x0, t_end, schedule):
        from scipy.integrate import solve_ivp
        t, x, out_t, out_x = 0.0, np.asarray(x0, float), [], []
        pending = sorted(schedule)
        while t < t_end:
            A, b = self.system.matrices(mode)
            stop = pending[0][0] if pending else t_end
            events = []
            for guard in self.system.guards(mode):
                w, k = np.array(guard.weights), guard.constant

                def ev(_, y, w=w, k=k):
                    return w @ y + k
                ev.terminal, ev.direction = True, guard.direction
                events.append((ev, guard.name))
            sol = solve_ivp(lambda _, y: A @ y + b, (t, stop), x, method="DOP853",
                                      rtol=1e-12, atol=1e-12, dense_output=True,
                                      max_step=self.max_step,
                                      events=[e for e, _ in events])
            hits = [(te[0], name) for te, (_, name) in zip(sol.t_events, events)
                    if len(te) and te[0] > t + 1e-12]
            end, name = min(hits) if hits else (stop, None)
            if name is None:
                name = pending.pop(0)[1] if pending else "end"
            grid = np.linspace(t, end, 50)
            out_t.append(grid), out_x.append(sol.sol(grid).T)
            x = sol.sol(end)
            t = end
            if name == "end":
                break
            mode, x = self.system.switch(mode, name, t, x)
        return np.concatenate(out_t), np.concatenate(out_x)


@pytest.fixture
def integrated():
    """The class that integrates a ``HybridSystem`` by ``solve_ivp`` (DOP853, events)."""
    return _Integrated
