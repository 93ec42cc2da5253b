"""A linear response with no closed form: integrators against a modal solution.

For an ODE system M·q̈ + C·q̇ + K·q = F0 + F_W·W(t) whose quantities are no
generated function (Martyntsiv et al.'s drum drive), the bench integrates the first-order form
with the generated ``state_derivative`` and ``state_jacobian`` (evaluated
once: the model is linear) and W(t) lambdified from its law, with SciPy's
methods at each tolerance, and measures the quantities against an mpmath
solution at 40 digits:

    x' = A·x + b0 + b_W·W(t),   A = V·Λ·V⁻¹  (mpmath.eig),

solved exactly mode by mode on the pieces where W(t) is a sum of exponentials
c·e^{μt} (between the zeros of its |…| terms, found by mpmath.findroot):
∫_a^t e^{λ(t−s)}·e^{μs} ds = e^{μa}·τ·e^{λτ}·φ1((μ − λ)τ), τ = t − a,
φ1(z) = (e^z − 1)/z. A load of another form makes the target not apply.
"""
from __future__ import annotations

import importlib
import time
from typing import Sequence

import mpmath
import numpy as np
import sympy as sp

from crane_sym.bench.rows import INTEGRATOR, REFERENCE, BenchRow, Target
from crane_sym.bench.odes import integrate, parameters, time_symbol
from crane_sym.derivation import Derivation, ODESystem

DPS = 40


class NotApplicable(ValueError):
    """The system or its load is not of the form this reference solves."""


def matrices(system: ODESystem) -> tuple[sp.Matrix, ...]:
    """M, C, K and the forcing F (in the input symbols) of ``system``."""
    t = time_symbol(system)
    n = len(system.coordinates)
    acc, vel, pos = (sp.symbols(f"{k}0:{n}", cls=sp.Dummy) for k in ("a", "v", "q"))
    frozen = {**{c.diff(t, 2): a for c, a in zip(system.coordinates, acc)},
              **{c.diff(t): v for c, v in zip(system.coordinates, vel)}}
    res = [sp.expand((e.lhs - e.rhs).xreplace(frozen).xreplace(
        dict(zip(system.coordinates, pos)))) for e in system.equations]
    M, C, K = (sp.Matrix([[r.diff(s) for s in group] for r in res]) for group in (acc, vel, pos))
    F = -sp.Matrix([r.xreplace({s: 0 for s in (*acc, *vel, *pos)}) for r in res])
    if any(m.has(t, *acc, *vel, *pos) for m in (M, C, K)):
        raise NotApplicable(f"{system.name}: not linear with constant coefficients")
    return M, C, K, F


def _mp(expr, values: dict) -> mpmath.mpf:
    free = sorted(sp.sympify(expr).free_symbols, key=str)
    return sp.lambdify(free, expr, modules="mpmath")(*(mpmath.mpf(values[str(s)]) for s in free))


def _pieces(law: sp.Expr, t: sp.Symbol, end: float) -> list[tuple[mpmath.mpf, list]]:
    """[(start, [(c, μ), ...]), ...]: W(t) = Σ c·e^{μt} from each start on."""
    if law.has(sp.Piecewise, sp.Heaviside, sp.Min, sp.Max, sp.sign):
        raise NotApplicable("the load is piecewise in a form the modal reference does not split")
    roots = set()
    for arg in {a.args[0] for a in law.atoms(sp.Abs)}:
        f = sp.lambdify(t, arg, modules="mpmath")
        grid = [mpmath.mpf(end) * k / 4000 for k in range(4001)]
        signs = [mpmath.sign(f(x)) for x in grid]
        for a, b, sa, sb in zip(grid, grid[1:], signs, signs[1:]):
            if sa == 0:
                roots.add(a)
            elif sa * sb < 0:
                roots.add(mpmath.findroot(f, (a, b), solver="anderson"))
    edges = [mpmath.mpf(0), *sorted(r for r in roots if 0 < r < end), mpmath.mpf(end)]
    pieces = []
    for a, b in zip(edges, edges[1:]):
        mid = sp.Float((a + b) / 2, DPS)
        local = law.replace(lambda e: isinstance(e, sp.Abs),
                            lambda e: e.args[0] * sp.sign(e.args[0].subs(t, mid)))
        terms: dict = {}
        for term in sp.Add.make_args(sp.expand(local.rewrite(sp.exp))):
            c, part = term.as_independent(t, as_Add=False)
            if part == 1:
                mu = sp.Integer(0)
            elif isinstance(part, sp.exp) and sp.diff(part.args[0], t, 2) == 0:
                mu, c = sp.diff(part.args[0], t), c * sp.exp(part.args[0].subs(t, 0))
            else:
                raise NotApplicable(f"the load is not a sum of exponentials: {term}")
            terms[mu] = terms.get(mu, 0) + c
        pieces.append((a, [(mpmath.mpmathify(sp.lambdify((), c, "mpmath")()),
                            mpmath.mpmathify(sp.lambdify((), mu, "mpmath")()))
                           for mu, c in terms.items()]))
    return pieces


def _phi1(z):
    return mpmath.expm1(z) / z if z != 0 else mpmath.mpf(1)


def modal_solution(system: ODESystem, values: dict, times: np.ndarray
                   ) -> tuple[dict[str, list], np.ndarray]:
    """Each quantity of ``system`` at ``times`` (sorted), mpf at DPS digits, and
    the first-order matrix A (float)."""
    t = time_symbol(system)
    (w, law), = system.inputs
    with mpmath.workdps(DPS):
        M, C, K, F = matrices(system)
        n = M.shape[0]
        num = lambda m: mpmath.matrix([[_mp(e, values) for e in row] for row in m.tolist()])  # noqa: E731,E501
        Mi = mpmath.inverse(num(M))
        A = mpmath.zeros(2 * n)
        A[:n, n:] = mpmath.eye(n)
        A[n:, :n], A[n:, n:] = -Mi * num(K), -Mi * num(C)
        b0 = mpmath.matrix([0] * n + list(Mi * num(F.subs(w, 0))))
        bw = mpmath.matrix([0] * n + list(Mi * num(F.diff(w))))
        lam, V = mpmath.eig(A)
        Vi = mpmath.inverse(V)
        g0, gw = Vi * b0, Vi * bw
        init = dict(system.initial)
        start = [init[c] for c in system.coordinates] + [init[c.diff(t)] for c in system.coordinates]
        y = Vi * mpmath.matrix([_mp(e, values) for e in start])
        known = {s: sp.Float(mpmath.mpf(values[str(s)]), DPS) for s in law.free_symbols - {t}}
        pieces = _pieces(law.xreplace(known), t, float(times[-1]))
        state = sp.symbols(f"y0:{2 * n}")
        to_state = {**{c.diff(t): s for c, s in zip(system.coordinates, state[n:])},
                    **dict(zip(system.coordinates, state[:n]))}
        params = parameters(system)
        quantities = {name: sp.lambdify((state, *params), q.subs(to_state), modules="mpmath")
                      for name, q in system.quantities}
        p = [mpmath.mpf(values[str(s)]) for s in params]

        def advance(y0, a, terms, tt):
            tau = tt - a
            out = []
            for i in range(2 * n):
                li = lam[i]
                grow = mpmath.exp(li * tau)
                forced = g0[i] * tau * grow * _phi1(-li * tau)
                forced += gw[i] * sum(c * mpmath.exp(mu * a) * tau * grow * _phi1((mu - li) * tau)
                                      for c, mu in terms)
                out.append(grow * y0[i] + forced)
            return mpmath.matrix(out)

        result: dict[str, list] = {name: [] for name in quantities}
        k = 0
        bounds = [a for a, _ in pieces[1:]] + [mpmath.inf]
        for (a, terms), b in zip(pieces, bounds):
            while k < len(times) and mpmath.mpf(times[k]) <= b:
                x = V * advance(y, a, terms, mpmath.mpf(times[k]))
                xr = [mpmath.re(v) for v in x]
                for name, q in quantities.items():
                    result[name].append(q(xr, *p))
                k += 1
            if b != mpmath.inf:
                y = advance(y, a, terms, b)
        return result, np.array(A.tolist(), dtype=float)


def _generated_rhs(d: Derivation, system: ODESystem, values: dict):
    """f(t, x) and the constant Jacobian from the generated state derivative and
    Jacobian (the model is linear), W(t) from its law (``math``)."""
    gen = importlib.import_module(f"crane_sym.generated.{d.id}")
    rhs, jac = d.output("state_derivative"), d.output("state_jacobian")
    (w, law), = system.inputs
    n = 2 * len(system.coordinates)
    state = [str(a) for a in rhs.args[-n:]]

    def call(out, **more):
        given = {**values, **{s: 0.0 for s in state}, **more}
        return np.asarray(getattr(gen, out.name)(*[given[str(a)] for a in out.args]), float)

    J = call(jac).reshape(n, n)
    f0 = call(rhs, **{str(w): 0.0}).ravel()
    fw = call(rhs, **{str(w): 1.0}).ravel() - f0
    free = sorted(law.free_symbols - {time_symbol(system)}, key=str)
    load = sp.lambdify((time_symbol(system), *free), law, modules="math")
    p = [float(values[str(s)]) for s in free]
    return (lambda tt, x: J @ x + f0 + load(tt, *p) * fw), (lambda tt, x: J), J


def linear_rows(d: Derivation, system: ODESystem, grid: dict, check: np.ndarray,
                methods: Sequence[str], rtols: Sequence[float]) -> list[BenchRow]:
    """Integrator rows for each quantity of ``system`` against the modal solution,
    and one row for the reference itself; [] when the target does not apply."""
    t = grid["t"]
    try:
        t0 = time.perf_counter()
        exact, A = modal_solution(system, grid, t[check])
        ref_seconds = time.perf_counter() - t0
        f, jac, J = _generated_rhs(d, system, grid)
    except (NotApplicable, KeyError):
        return []
    if not np.allclose(J, A, rtol=1e-9, atol=1e-12 * np.abs(A).max()):
        raise ValueError(f"{d.id}: generated state_jacobian differs from {system.name} "
                         "(state order?)")
    targets = {name: Target(d.id, f"{name} (no closed form)", check, values)
               for name, values in exact.items()}
    params = parameters(system)
    state = sp.symbols(f"y0:{J.shape[0]}")
    n = len(system.coordinates)
    tt = time_symbol(system)
    to_state = {**{c.diff(tt): s for c, s in zip(system.coordinates, state[n:])},
                **dict(zip(system.coordinates, state[:n]))}
    read = {name: sp.lambdify((state, *params), q.subs(to_state), modules="numpy")
            for name, q in system.quantities}
    p = [float(grid[str(s)]) for s in params]
    rows = [BenchRow(d.id, target.name, "mpmath modal solution (40 digits)", ref_seconds,
                     len(check), float("nan"), float("nan"), kind=REFERENCE)
            for target in targets.values()]
    y0 = np.zeros(J.shape[0])
    for label, seconds, states in integrate(f, jac, y0, t, (), methods, rtols,
                                            "generated RHS+Jacobian"):
        for name, target in targets.items():
            values = read[name](states[:, check], *p)
            rows.append(target.row(label, seconds, len(t), values, INTEGRATOR))
    return rows
