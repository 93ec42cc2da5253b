"""The equations of motion of an assembled model, derived with Lagrange's
equations in the components' symbols.

One coordinate q_g per rigid group (:mod:`crane_sym.components.topology`),
body b of group g at κ_b·q_g. From the components:

.. math::

    T = \\tfrac12 \\sum_b J_b (\\kappa_b \\dot q_{g(b)})^2 + \\sum_s T_s, \\qquad
    \\Pi = \\tfrac12 \\sum_k \\chi_k c_k (u_k - \\delta_k)^2 + \\sum_s \\Pi_s, \\qquad
    \\Phi = \\tfrac12 \\sum_k \\chi_k d_k \\dot u_k^2 + \\sum_s \\Phi_s,

    Q_g = \\sum_{\\text{loads on } b \\in g} \\kappa_b\\, F,

with u_k = κ_second q − κ_first q the twist of elastic link k, χ_k its
contact (1 on a flank, 0 in its gap) and δ_k the flank it rests on (0, or the
gap's other end), F a motor's torque times its switch ``on``, a
characteristic's β (v0 − v), a weight m g, a resistance, a brake's signed
friction B, or a law's value L(t) (:mod:`crane_sym.components.laws`; an
acceleration law's J_red a(t) − Σ ρ F of the weights, resistances and motors). Lagrange's equations with Rayleigh
dissipation (:func:`crane_sym.mechanics.lagrange.lagrange_equations`) give
M q̈ + D q̇ + K q = f, linear in the state. T is a general quadratic form in
the speeds: T_s, Π_s and Φ_s are the shares of a part that joins several
coordinates (a span, :mod:`crane_sym.components.kinds.span`: its element's
mass couples the speeds of its ends), so M, D and K are full matrices: χ, δ,
``on`` and B are what a mode of the hybrid system fixes (:mod:`crane_sym.components.hybrid`). A part may bring
states of first order (a DC motor's current i, its force k i in Q), each with
its rate (L di/dt = V − R i − k ω): f holds them linearly, and their rates are
:attr:`Equations.first_order` (:mod:`crane_sym.components.first_order`).
"""
from __future__ import annotations

from dataclasses import dataclass, replace
from functools import cached_property
from typing import Callable

import numpy as np
import sympy as sp

from crane_sym.components import kinds
from crane_sym.components.coupling_loads import load_of
from crane_sym.components.first_order import rate_matrices
from crane_sym.components.kinds.base import ROLES
from crane_sym.components.rigid_drive import inertia_symbol, rigid_drive_force
from crane_sym.components.topology import Assembly
from crane_sym.mechanics.lagrange import LagrangeEquations, lagrange_equations

__all__ = ["Equations", "derive", "parameter_values"]

T_SYMBOL = sp.Symbol("t", real=True)
#: The LaTeX of a symbol's letter, where it is no Latin letter.
_HEADS = {"chi": "\\chi", "delta": "\\delta", "beta": "\\beta", "theta": "\\theta",
          "on": "\\mathrm{on}"}


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
    link_loads : the force (torque) of each elastic link, derived from the energies,
        F_k = ∂Π/∂u_k + ∂Φ/∂u̇_k (= χ_k (c_k (u_k − δ_k) + d_k u̇_k)), in the coordinates
    link_laws : the same in each link's own stretch and rate (:attr:`stretches`)
    stretches : the symbols (u_k, u̇_k) of each link's stretch and its rate
    contact, flank : χ_k and δ_k of the links with backlash (the others have χ = 1, δ = 0)
    switches : the ``on`` symbol of each motor
    friction : the signed friction B of each brake
    slopes : the slope β of each characteristic (its step is the mode's)
    signals : the value of each motor law at time t (L_name for a torque law, a_name
        for an acceleration law): what the laws' clock states give; T_name, the
        torque a speed law takes, which its group's prescribed motion replaces
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
    signals: tuple[sp.Symbol, ...] = ()
    link_laws: tuple[sp.Expr, ...] = ()
    stretches: tuple[tuple[sp.Symbol, sp.Symbol], ...] = ()
    #: The parts' first-order states s (a DC motor's current i) and their
    #: rates ds/dt, affine in q̇, the states and the signals.
    states: tuple[sp.Symbol, ...] = ()
    rates: tuple[sp.Expr, ...] = ()
    #: (part, s, bound, z) of each limit on a first-order state, z its
    #: tracking state (:mod:`crane_sym.components.first_order`).
    limits: tuple[tuple[str, sp.Symbol, sp.Expr, sp.Symbol], ...] = ()
    #: (part, what, unit, value) of each value a part reports (``Acting.outputs``).
    outputs: tuple[tuple[str, str, str, sp.Expr], ...] = ()
    #: True for a design of a sweep (:meth:`for_design`): :meth:`numeric`
    #: evaluates the lambdified form shared by every design of the model.
    shared: bool = False

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
    def first_order(self) -> tuple[sp.Matrix, ...]:
        """(R_q, R_v, R_s, R_L, r_0) of the first-order states' rates
        (:func:`crane_sym.components.first_order.rate_matrices`), shared by
        every design of the model."""
        return rate_matrices(self.coordinates, T_SYMBOL, self.states, self.rates, self.signals)

    def _mode_arguments(self) -> list[list[sp.Symbol]]:
        return [list(self.contact), list(self.flank), list(self.switches), list(self.friction),
                list(self.slopes), list(self.signals), list(self.states)]

    @cached_property
    def _lambdified(self) -> tuple[tuple[sp.Symbol, ...], Callable]:
        """(parameters, (χ, δ, on, B, β, L, parameter values) -> (M, D, K, f)):
        lambdified once, shared by the designs of :meth:`for_design`."""
        parameters = tuple(sorted({*self.values, *self.motor_loads}, key=str))
        return parameters, sp.lambdify([*self._mode_arguments(), list(parameters)],
                                       self.linear, "numpy")

    @cached_property
    def _numeric(self) -> dict:
        return {}

    @cached_property
    def layouts(self) -> dict:
        """The system's tables by structure (:func:`crane_sym.components.layout.layout`),
        shared by the designs of :meth:`for_design`."""
        return {}

    def numeric(self, extra: dict[sp.Symbol, float] | None = None) -> Callable:
        """(χ, δ, on, B, β, L) -> (M, D, K, f) as arrays, the parameters' values put in
        (and ``extra``: a steady motor's solved torque). Kept per ``extra``: a run
        builds three systems (two probes of the steady start), and a repeated run
        the same three, whose lambdify was most of its time."""
        key = tuple(sorted(((str(k), float(v)) for k, v in (extra or {}).items())))
        if key not in self._numeric:
            self._numeric[key] = self._numeric_uncached(extra)
        return self._numeric[key]

    def _numeric_uncached(self, extra: dict[sp.Symbol, float] | None) -> Callable:
        values = {**self.values, **(extra or {})}
        if self.shared:
            parameters, shared = self._lambdified
            given = [values.get(p, float("nan")) for p in parameters]

            def fn(*mode):
                return shared(*mode, given)
        else:
            M, D, K, f = (m.xreplace(values) for m in self.linear)
            fn = sp.lambdify(self._mode_arguments(), (M, D, K, f), "numpy")

        def evaluate(chi, delta, on, friction, slopes=(), signals=(), states=()):
            signals = list(signals) or [0.0] * len(self.signals)
            states = list(states) or [0.0] * len(self.states)
            out = fn(list(chi), list(delta), list(on), list(friction), list(slopes), signals,
                     states)
            return tuple(np.array(m, dtype=float) for m in out[:3]) + \
                (np.array(out[3], dtype=float).reshape(-1),)
        return evaluate

    @cached_property
    def latex_names(self) -> dict[sp.Basic, str]:
        """How a handout writes each symbol: its letter, the component's name
        upright as its subscript (``c_{\\mathrm{gearbox\\_mesh}}``)."""
        names: dict[sp.Basic, str] = {}
        symbols = [*self.values, *self.contact, *self.flank, *self.switches,
                   *self.friction, *self.motor_loads, *self.slopes, *self.signals,
                   *self.states]
        for s in [*symbols, *self.coordinates]:
            text = s.name if isinstance(s, sp.Symbol) else type(s).__name__
            head, _, rest = text.partition("_")
            upright = "\\mathrm{" + rest.replace("_", r"\_") + "}"
            names[s] = (text if not rest else f"v_{{0,{upright}}}" if head == "v0" else
                        f"{_HEADS.get(head, head)}_{{{upright}}}")
        return names

    def for_design(self, assembly: Assembly) -> "Equations":
        """These equations for another design of the model: ``assembly`` has the
        same parts with other values (the same parameter symbols); the symbolic
        work and its lambdified form are shared, not redone (a design sweep
        builds one a design). ValueError if the parameters differ.

        Parameters
        ----------
        assembly : Assembly
            The design's parts, assembled.
        """
        values = parameter_values(assembly)
        if list(values) != list(self.values) or \
                [l.gapped for l in assembly.links] != \
                [l.gapped for l in self.assembly.links]:
            raise ValueError("for_design: the design's parts differ from the model's in "
                             "more than their values")
        design = replace(self, assembly=assembly, values=values, shared=True)
        design.__dict__["linear"] = self.linear              # cached_property: shared
        design.__dict__["first_order"] = self.first_order
        design.__dict__["_lambdified"] = self._lambdified
        design.__dict__["layouts"] = self.layouts
        # the links' symbolic loads too (SymPy's diff: a quarter of a design's assembly)
        design.__dict__["link_derivatives"] = self.link_derivatives
        return design

    @cached_property
    def link_derivatives(self) -> tuple[tuple[sp.Expr, sp.Expr, sp.Expr], ...]:
        """Each link's load on a flank (χ = 1) as ∂F/∂u, ∂F/∂u̇ and ∂F/∂δ: it is
        affine in the three (shared by every design of the model)."""
        out = []
        for k, (law, (u, rate)) in enumerate(zip(self.link_laws, self.stretches)):
            on = law.xreplace({c: 1 for c in self.contact})
            delta = self._flank_of(k)
            out.append((sp.diff(on, u), sp.diff(on, rate),
                        sp.diff(on, delta) if delta is not None else sp.Integer(0)))
        return tuple(out)

    def _flank_of(self, index: int) -> sp.Symbol | None:
        name = self.assembly.links[index].part.name
        return next((f for f in self.flank if f.name == f"delta_{name}"), None)

    def link_coefficients(self, index: int, extra: dict | None = None
                          ) -> tuple[float, float, float]:
        """(a, b, e) of link ``index``'s load on a flank, F = a u + b u̇ + e δ,
        in this model's values (and ``extra``): the derivatives of
        ∂Π/∂u + ∂Φ/∂u̇, so the load a run reports is the one its energies give.

        Parameters
        ----------
        index : int
            The link's position among ``assembly.links``.
        extra : dict, optional
            Values solved later (a steady motor's torque).
        """
        values = {**self.values, **(extra or {})}
        return tuple(float(c.xreplace(values)) for c in self.link_derivatives[index])

    def latex(self) -> list[str]:
        """The equations of motion in LaTeX, one per coordinate, as a mechanics
        text writes them (q̇, q̈; :func:`crane_sym.latex.latex`, with
        :attr:`latex_names`)."""
        from crane_sym.latex import latex
        return [latex(e, symbol_names=self.latex_names) for e in self.lagrange.equations]


def parameter_values(assembly: Assembly) -> dict[sp.Symbol, float]:
    """Every parameter symbol of :func:`derive`'s equations with its SI value in
    ``assembly`` (a steady motor's torque, solved later, left out), as each
    kind declares them (``Kind.symbols``), for the model and for each design
    of a sweep (:meth:`Equations.for_design`).

    Parameters
    ----------
    assembly : Assembly
        The assembled parts.
    """
    values: dict[sp.Symbol, float] = {}
    members = [body for g in assembly.groups for body, _ in g.members]
    for item in (*members, *assembly.rigid, *assembly.links, *assembly.loads,
                 *assembly.couplings):
        part = getattr(item, "part", item)
        kind = kinds.of(part)
        for declared in kind.symbols:
            v = declared.value(item)
            if v is not None:                   # a steady motor's, solved at the start
                values[declared.symbol(part.name)] = v
        if kind.couples is not None:            # a span's factors
            values.update((f.symbol, f.value) for f in kind.couples.factors(part,
                                                                             assembly.bodies))
    return values


def derive(assembly: Assembly) -> Equations:
    """T, Π, Φ and Q of the components, and Lagrange's equations of them."""
    t = T_SYMBOL
    coords = []
    for g in assembly.groups:
        letter = "theta" if g.motion == "rotating" else "x"
        coords.append(sp.Function(f"{letter}_{g.name}", real=True)(t))
    where: dict[str, tuple[sp.Expr, sp.Expr]] = {}      # body -> (κ symbolic, q)
    T = sp.Integer(0)
    for g, q in zip(assembly.groups, coords):
        for (body, _), kappa in zip(g.members, g.factors):
            where[body.name] = (kappa, q)
            T += inertia_symbol(body) * (kappa * q.diff(t)) ** 2 / 2
    V = D = sp.Integer(0)
    twists, stretches, contact, flank = [], [], [], []
    for link in assembly.links:
        name = link.part.name
        u = assembly.twist(link, coords)
        spring = kinds.of(link.part).stiffness
        c = _p(f"c_{name}") if spring is None else spring(link.part)
        d = sp.Symbol(f"d_{name}", nonnegative=True)
        chi, delta = sp.Integer(1), sp.Integer(0)
        if link.gapped:
            chi, delta = _r(f"chi_{name}"), _r(f"delta_{name}")
            contact.append(chi)
            flank.append(delta)
        s, rate = _r(f"u_{name}"), _r(f"udot_{name}")
        V += chi * c * (s - delta) ** 2 / 2
        D += chi * d * rate ** 2 / 2
        twists.append(u)
        stretches.append((s, rate))
    # a link's load is what the energies give: F_k = ∂Π/∂u_k + ∂Φ/∂u̇_k
    laws = [sp.factor_terms(sp.diff(V, s) + sp.diff(D, rate)) for s, rate in stretches]
    back = {}
    for (s, rate), u in zip(stretches, twists):
        back.update({s: u, rate: u.diff(t)})
    V, D = V.xreplace(back), D.xreplace(back)
    carried = []                            # (part, what, unit, F) of the couplings' loads
    for part in assembly.couplings:         # a span: its own T, Π, Φ in several coordinates
        couples = kinds.of(part).couples
        shares = couples.energies(part, where)
        T, V, D = T + shares[0], V + shares[1], D + shares[2]
        if couples.stretch is not None:     # its load from its own energies, ∂Π/∂u + ∂Φ/∂u̇
            u, what, unit = couples.stretch(part, where, assembly.bodies)
            carried.append((part.name, what, unit, load_of(shares, u, coords, t, part.label)))
    loads = [F.xreplace(back) for F in laws]
    forces = {q: sp.Integer(0) for q in coords}
    joined: dict[str, list[sp.Symbol]] = {role: [] for role in ROLES}
    acting: list[tuple[str, sp.Expr]] = []          # (body, F) the rigid drive feels
    states: dict[sp.Symbol, sp.Expr] = {}           # s -> ds/dt, summed over the parts
    limits, outputs = [], []
    balancing = None
    for load in assembly.loads:
        part = load.part
        kappa, q = where[part.body]
        acts = kinds.of(part).acts(part, kappa, q)
        for role, symbol in acts.joins:
            joined[role].append(symbol)
        for s, rate in acts.states:
            states[s] = states.get(s, sp.Integer(0)) + rate
        limits += [(part.name, *limit) for limit in acts.limits]
        outputs += [(part.name, *out) for out in acts.outputs]
        if acts.force is None:                  # an acceleration law: see rigid_drive_force
            balancing = (part, acts.joins[-1][1])
            continue
        if acts.constant:
            acting.append((part.body, acts.force))
        forces[q] += kappa * acts.force
    if balancing is not None:
        part, a_law = balancing
        kappa, q = where[part.body]
        forces[q] += kappa * rigid_drive_force(assembly, where, part.body, a_law, acting)
    outputs += carried
    eqs = lagrange_equations(T, V, coords, t, forces, D)
    values = parameter_values(assembly)
    return Equations(assembly, tuple(coords), T, V, D, forces, eqs, tuple(twists),
                     tuple(loads), tuple(contact), tuple(flank), tuple(joined["switches"]),
                     tuple(joined["friction"]), tuple(joined["motor_loads"]), values,
                     tuple(joined["slopes"]), tuple(joined["signals"]), tuple(laws),
                     tuple(stretches), tuple(states), tuple(states.values()), tuple(limits),
                     tuple(outputs))
