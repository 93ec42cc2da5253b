"""The equations of motion of an assembled model, derived with Lagrange's
equations in the components' symbols.

One coordinate q_g per rigid group (:mod:`crane_sym.components.topology`),
body b of group g at κ_b·q_g. From the components:

.. math::

    T = \\tfrac12 \\sum_b J_b (\\kappa_b \\dot q_{g(b)})^2, \\qquad
    \\Pi = \\tfrac12 \\sum_k \\chi_k c_k (u_k - \\delta_k)^2, \\qquad
    \\Phi = \\tfrac12 \\sum_k \\chi_k d_k \\dot u_k^2,

    Q_g = \\sum_{\\text{loads on } b \\in g} \\kappa_b\\, F,

with u_k = κ_second q − κ_first q the twist of elastic link k, χ_k its
contact (1 on a flank, 0 in its gap) and δ_k the flank it rests on (0, or the
gap's other end), F a motor's torque times its switch ``on``, a
characteristic's β (v0 − v), a weight m g, a resistance, or a brake's signed
friction B. Lagrange's equations with Rayleigh
dissipation (:func:`crane_sym.mechanics.lagrange.lagrange_equations`) give
M q̈ + D q̇ + K q = f, linear in the state: χ, δ, ``on`` and B are what a mode
of the hybrid system fixes (:mod:`crane_sym.components.hybrid`).
"""
from __future__ import annotations

from dataclasses import dataclass
from functools import cached_property
from typing import Callable

import numpy as np
import sympy as sp

from crane_sym.components.loads import Brake, Characteristic, Gravity, Motor, Resistance
from crane_sym.components.parts import Gear
from crane_sym.components.topology import Assembly
from crane_sym.mechanics.lagrange import LagrangeEquations, lagrange_equations

__all__ = ["Equations", "derive"]

T_SYMBOL = sp.Symbol("t", real=True)


def _p(name: str) -> sp.Symbol:
    return sp.Symbol(name, positive=True)


def _r(name: str) -> sp.Symbol:
    return sp.Symbol(name, real=True)


@dataclass(frozen=True, eq=False)
class Equations:
    """The model's energies, forces and equations of motion, symbolic.

    Attributes
    ----------
    coordinates : q_g(t), one per rigid group
    T, V, dissipation : kinetic energy, potential energy, Rayleigh function
    forces : generalized force of each coordinate
    lagrange : the equations of motion
    twists : u_k of each elastic link, in the coordinates
    link_loads : the force (torque) of each elastic link, F_k = χ_k (c_k (u_k − δ_k) + d_k u̇_k)
    contact, flank : χ_k and δ_k of the links with backlash (the others have χ = 1, δ = 0)
    switches : the ``on`` symbol of each motor
    friction : the signed friction B of each brake
    slopes : the slope β of each characteristic (its step is the mode's)
    values : every parameter symbol's SI value (a steady motor's torque once solved: not here)
    """

    assembly: Assembly
    coordinates: tuple[sp.Expr, ...]
    T: sp.Expr
    V: sp.Expr
    dissipation: sp.Expr
    forces: dict[sp.Expr, sp.Expr]
    lagrange: LagrangeEquations
    twists: tuple[sp.Expr, ...]
    link_loads: tuple[sp.Expr, ...]
    contact: tuple[sp.Symbol, ...]
    flank: tuple[sp.Symbol, ...]
    switches: tuple[sp.Symbol, ...]
    friction: tuple[sp.Symbol, ...]
    motor_loads: tuple[sp.Symbol, ...]
    values: dict[sp.Symbol, float]
    slopes: tuple[sp.Symbol, ...] = ()

    @property
    def t(self) -> sp.Symbol:
        return T_SYMBOL

    @cached_property
    def linear(self) -> tuple[sp.Matrix, sp.Matrix, sp.Matrix, sp.Matrix]:
        """(M, D, K, f) of M q̈ + D q̇ + K q = f, from the Lagrange equations."""
        t, qs = T_SYMBOL, self.coordinates
        plain = [sp.Dummy(f"q{i}") for i in range(len(qs))]
        rates = [sp.Dummy(f"v{i}") for i in range(len(qs))]
        accs = [sp.Dummy(f"a{i}") for i in range(len(qs))]
        swap = {}
        for q, x, v, a in zip(qs, plain, rates, accs):
            swap.update({q.diff(t, 2): a, q.diff(t): v})
        rows = []
        for eq in self.lagrange.equations:
            expr = (eq.lhs - eq.rhs).subs(swap)
            rows.append(expr.subs(dict(zip(qs, plain))))
        rows = sp.Matrix(rows)
        zero = {s: 0 for s in [*plain, *rates, *accs]}
        M, D, K = (rows.jacobian(v) for v in (accs, rates, plain))
        f = -rows.subs(zero)
        return M, D, K, sp.expand(f)

    @cached_property
    def _numeric(self) -> dict:
        return {}

    def numeric(self, extra: dict[sp.Symbol, float] | None = None) -> Callable:
        """(χ, δ, on, B, β) -> (M, D, K, f) as arrays, the parameters' values put in
        (and ``extra``: a steady motor's solved torque). Kept per ``extra``: a run
        builds three systems (two probes of the steady start), and a repeated run
        the same three, whose lambdify was most of its time."""
        key = tuple(sorted(((str(k), float(v)) for k, v in (extra or {}).items())))
        if key not in self._numeric:
            self._numeric[key] = self._numeric_uncached(extra)
        return self._numeric[key]

    def _numeric_uncached(self, extra: dict[sp.Symbol, float] | None) -> Callable:
        values = {**self.values, **(extra or {})}
        M, D, K, f = (m.xreplace(values) for m in self.linear)
        args = [list(self.contact), list(self.flank), list(self.switches), list(self.friction),
                list(self.slopes)]
        fn = sp.lambdify(args, (M, D, K, f), "numpy")

        def evaluate(chi, delta, on, friction, slopes=()):
            out = fn(list(chi), list(delta), list(on), list(friction), list(slopes))
            return tuple(np.array(m, dtype=float) for m in out[:3]) + \
                (np.array(out[3], dtype=float).reshape(-1),)
        return evaluate

    def latex(self) -> list[str]:
        """The equations of motion in LaTeX, one per coordinate."""
        return [sp.latex(e) for e in self.lagrange.equations]


def derive(assembly: Assembly) -> Equations:
    """T, Π, Φ and Q of the components, and Lagrange's equations of them."""
    t = T_SYMBOL
    coords = []
    for g in assembly.groups:
        letter = "theta" if g.motion == "rotating" else "x"
        coords.append(sp.Function(f"{letter}_{g.name}", real=True)(t))
    values: dict[sp.Symbol, float] = {}
    where: dict[str, tuple[sp.Expr, sp.Expr]] = {}      # body -> (κ symbolic, q)
    T = sp.Integer(0)
    for g, q in zip(assembly.groups, coords):
        for (body, _), kappa in zip(g.members, g.factors):
            where[body.name] = (kappa, q)
            J = _p(f"{'J' if body.motion == 'rotating' else 'm'}_{body.name}")
            values[J] = body.inertia
            T += J * (kappa * q.diff(t)) ** 2 / 2
    for part in assembly.rigid:
        if isinstance(part, Gear):
            values[_p(f"i_{part.name}")] = part.ratio
        else:
            values[_p(f"r_{part.name}")] = part.radius
            values[_p(f"n_{part.name}")] = part.reeving
    V = D = sp.Integer(0)
    twists, loads, contact, flank = [], [], [], []
    for link in assembly.links:
        name = link.part.name
        (ka, qa), (kb, qb) = (where[e] for e in link.part.ends)
        u = kb * qb - ka * qa
        c, d = _p(f"c_{name}"), sp.Symbol(f"d_{name}", nonnegative=True)
        values[c], values[d] = link.stiffness, link.damping
        chi, delta = sp.Integer(1), sp.Integer(0)
        if link.backlash > 0:
            chi, delta = _r(f"chi_{name}"), _r(f"delta_{name}")
            contact.append(chi)
            flank.append(delta)
        V += chi * c * (u - delta) ** 2 / 2
        D += chi * d * u.diff(t) ** 2 / 2
        twists.append(u)
        loads.append(chi * (c * (u - delta) + d * u.diff(t)))
    forces = {q: sp.Integer(0) for q in coords}
    switches, friction, motors, slopes = [], [], [], []
    for load in assembly.loads:
        part = load.part
        kappa, q = where[part.body]
        if isinstance(part, Motor):
            on, M = _r(f"on_{part.name}"), _r(f"M_{part.name}")
            switches.append(on)
            motors.append(M)
            if load.load is not None:
                values[M] = load.load
            F = on * M
        elif isinstance(part, Gravity):
            m, g = _p(f"m_{part.body}"), _p(f"g_{part.name}")
            values[g] = part.g
            F = m * g * (1 if part.direction == "+" else -1)
        elif isinstance(part, Resistance):
            F = _r(f"R_{part.name}")
            values[F] = load.load
        elif isinstance(part, Brake):
            F = _r(f"B_{part.name}")
            friction.append(F)
        elif isinstance(part, Characteristic):
            beta, v0 = _p(f"beta_{part.name}"), _r(f"v0_{part.name}")
            values[v0] = load.values[0]
            slopes.append(beta)
            F = beta * (v0 - kappa * q.diff(t))
        forces[q] += kappa * F
    eqs = lagrange_equations(T, V, coords, t, forces, D)
    return Equations(assembly, tuple(coords), T, V, D, forces, eqs, tuple(twists),
                     tuple(loads), tuple(contact), tuple(flank), tuple(switches),
                     tuple(friction), tuple(motors), values, tuple(slopes))

