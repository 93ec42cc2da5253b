"""What a reviewer checks of a component model: a few quantities derived from
its equations of motion, symbolic in the parts' symbols, beside its
parameters by name (:mod:`crane_sym.components.parameters`).

A parameter is named ``<component>.<key>`` as the component file writes it
(``gearbox_mesh.stiffness``, ``hook.mass``, ``tackle.radius``); a quantity
``<component>.<what>``:

========================== ===========================================================
``<body>.reduced_inertia`` the inertia of the body's rigid group referred to the body:
                           ∂²T/∂q̇² of the group over κ_body² (kg·m² or kg)
``<link>.static``          the link's load in the steady motion at the start (all motors
                           on, brakes off, gaps on their flank): each rigid group's
                           equilibrium Σ_k F_k ∂u_k/∂q = Q, solved for the link loads
                           (and a ``steady`` motor's torque)
``<link>.frequency``       a natural angular frequency ω_k of the mode the run is in
                           (:mod:`crane_sym.components.vibration`: bodies a speed law
                           moves and brakes that hold fixed, gaps as they are; the
                           lowest, the k-th, or the one loading a link most)
``<link>.period``          its period 2π/ω_k
``<link>.damping_ratio``   its modal damping ratio ζ_k = φᵀDφ / (2 ω_k φᵀMφ)
``<link>.damped_frequency`` its damped angular frequency ω_k √(1 − ζ_k²)
``<link>.response``        the link's load F(t) in closed form after a start at rest
                           with zero twist (:func:`crane_sym.components.closed.link_response`;
                           a model that never switches)
``<link>.peak``            the largest load of the link over the file's run, a number
``<link>.factor``          its dynamic factor (peak over the reference or static load)
``<contact>.reaction``     a ground contact's reaction at rest at the start, every link
                           unstretched: R = s Q/κ of its body's group (s = ±1, the
                           ground's side)
``<contact>.reaction_peak`` its largest reaction over the file's run, a number
``<span>.force_peak``      a span's largest force ∂Π/∂u + ∂Φ/∂u̇ over the file's run, a
                           number (``<span>.torque_peak``: a span of angles, its torque)
``<motor>.time_constant``  a DC motor's mechanical time constant τ = J_red / (−∂F/∂ω),
                           F its force with the armature's current at rest
                           (L di/dt = 0 solved for i): J_red R / k²
========================== ===========================================================

A parameter whose value is zero (a shaft without inertia, an undamped link)
is put to zero in every symbolic quantity, as the derivation drops it; one
the file gives negative (a resistance, a gear that turns the other way) is
its negative twin, a symbol of the same name declared negative
(:func:`~crane_sym.components.parameters.signed`), so that a quantity keeps the sign the file gives.
"""
from __future__ import annotations

from dataclasses import dataclass

import sympy as sp
from sympy.physics.units import Dimension, time

from crane_sym.components import kinds
from crane_sym.components.closed import acting_parts, link_response
from crane_sym.components.model import Model
from crane_sym.components.parameters import signed
from crane_sym.components.parts import DIMENSIONS, ROTATING, UNITS, ComponentError
from crane_sym.components.reported import reported_peak
from crane_sym.components.vibration import MODAL, ModeChoice, modal_quantity

__all__ = ["NUMERIC", "QUANTITIES", "Quantity", "UNITS", "derived_quantity", "quantity_table",
           "static_loads"]

_ONE = Dimension(1)
#: Each quantity by its name: the kind of component it belongs to, and what it is.
QUANTITIES = {"reduced_inertia": ("body", "the inertia of its rigid group referred to it"),
              "static": ("link", "its load in the steady motion at the start"),
              **{what: ("link", text) for what, text in MODAL.items()},
              "response": ("link", "its load F(t) in closed form after a start at rest"),
              "peak": ("link", "its largest load over the file's run"),
              "factor": ("link", "its dynamic factor: peak over reference or static load"),
              "reaction": ("contact", "the ground's reaction at rest at the start, the links "
                                      "unstretched"),
              "reaction_peak": ("contact", "the ground's largest reaction over the file's run"),
              "force_peak": ("span", "its largest force over the file's run"),
              "torque_peak": ("span", "its largest torque over the file's run (a span of "
                                      "angles)")}


def quantity_table() -> dict[str, tuple[str, str]]:
    """:data:`QUANTITIES`, then each quantity a kind declares for its parts
    (``Kind.quantities``: a DC motor's ``time_constant``), by name: the kind
    of component it belongs to, and what it is."""
    return QUANTITIES | {q.name: (kind.part_kind, q.text) for kind in kinds.KINDS
                         for q in kind.quantities}


#: Quantities that are numbers of the file's run, not symbolic.
NUMERIC = ("peak", "factor", "reaction_peak", "force_peak", "torque_peak")


@dataclass(frozen=True)
class Quantity:
    """A derived quantity: its expression (symbolic, or the run's number), its
    dimension and how it was derived."""

    path: str
    expr: sp.Expr
    dimension: Dimension
    unit: str
    how: str
    numeric: bool = False


def _zeros(model: Model) -> dict[sp.Symbol, int]:
    return {s: 0 for s, v in model.equations.values.items() if v == 0}


def _load_dimension(model: Model, link) -> tuple[Dimension, str]:
    motion = model.assembly.motion(link)
    return DIMENSIONS["load"][motion], UNITS["load"][motion]


def static_loads(model: Model) -> dict[str, sp.Expr | None]:
    """Each link's load in the steady motion at the start, symbolic: every rigid
    group in equilibrium, Σ_k F_k ∂u_k/∂q_g = Q_g (motors on, brakes off);
    None for a link in a loop of elastic links (equilibrium alone does not fix
    its load).

    Parameters
    ----------
    model : Model
        The assembled and derived model; ComponentError when its loads depend
        on the speed or do not balance in the symbols.
    """
    a, eq = model.assembly, model.equations
    speeds = {q.diff(eq.t) for q in eq.coordinates}
    for part, acts in acting_parts(model):
        if acts.force is not None and acts.force.atoms(sp.Derivative) & speeds:
            raise ComponentError(f"a static load needs loads that do not depend on the "
                                 f"speed; {part.label} does")
    F = [sp.Symbol(f"F_{l.part.name}", real=True) for l in a.links]
    steady = model.steady_motor
    unknowns = F + ([steady] if steady is not None else [])
    fixed = {on: 1 for on in eq.switches} | {B: 0 for B in eq.friction}
    rows = [sum((Fk * sp.diff(u, q) for Fk, u in zip(F, eq.twists)), sp.Integer(0))
            - eq.forces[q].xreplace(fixed) for q in eq.coordinates]
    solved = sp.linsolve(rows, unknowns)
    if not solved:
        raise ComponentError("a static load: the constant loads do not balance in the "
                             "symbols; give one motor the torque 'steady'")
    (values,) = solved
    zero, twins = _zeros(model), signed(model)
    # A link in a loop of elastic links keeps a free unknown: its load is not
    # fixed by equilibrium alone (None); a link outside every loop still is.
    return {l.part.name: None if v.free_symbols & set(unknowns) else
            sp.simplify(v.xreplace(zero).xreplace(twins)) for l, v in zip(a.links, values)}


def _link(model: Model, name: str):
    for link in model.assembly.links:
        if link.part.name == name:
            return link
    raise ComponentError(f"no elastic link {name!r}")


def derived_quantity(model: Model, path: str, run=None,
                     choice: ModeChoice | None = None) -> Quantity:
    """The quantity named ``path`` (see the module docstring); ``run`` (a
    :class:`~crane_sym.components.model.ComponentRun`) for the numbers of the
    run, ``choice`` for a modal one. ComponentError, one line, for a name the
    model has not or a quantity it cannot derive.

    Parameters
    ----------
    model : Model
        The assembled and derived model.
    path : str
        ``<component>.<quantity>``.
    run : ComponentRun, optional
        The file's run (needed for ``peak`` and ``factor``).
    choice : ModeChoice, optional
        Which natural frequency of which mode of the run (default: the lowest,
        every gap closed, no brake holding).
    """
    name, _, what = path.partition(".")
    table = quantity_table()
    if what not in table:
        raise ComponentError(f"unknown quantity {path!r}; a quantity is <component>."
                             f"{{{', '.join(table)}}}")
    a, eq = model.assembly, model.equations
    zero, twins = _zeros(model), signed(model)
    if table[what][0] == "body":
        if name not in a.bodies:
            raise ComponentError(f"quantity {path!r}: no body {name!r}; bodies: "
                                 f"{', '.join(a.bodies)}")
        g, _, kappa = a.place[name]
        M = eq.linear[0]
        inertia = sp.simplify((M[g, g] / kappa**2).xreplace(zero).xreplace(twins))
        body = a.bodies[name]
        key = "inertia" if body.motion == ROTATING else "mass"
        return Quantity(path, inertia, DIMENSIONS[key][body.motion], UNITS[key][body.motion],
                        f"∂²T/∂q̇² of the rigid group of {body.label}, referred to it "
                        "(divided by its κ²)")
    if table[what][0] == "contact":
        return _contact_quantity(model, path, run)
    if table[what][0] == "span":
        p = reported_peak(model, path, run, what.removesuffix("_peak"))
        return Quantity(path, sp.Float(p.value, 17), p.dimension, p.unit, p.how, numeric=True)
    if what not in QUANTITIES:
        return _part_quantity(model, path, table[what][0])
    link = _link(model, name) if name in [l.part.name for l in a.links] else None
    if link is None:
        raise ComponentError(f"quantity {path!r}: no elastic link {name!r}; links: "
                             f"{', '.join(l.part.name for l in a.links) or 'none'}")
    load = _load_dimension(model, link)
    if what == "static":
        static = static_loads(model)[name]
        if static is None:
            raise ComponentError(f"{name} lies in a loop of elastic links, so its static "
                                 "load is not fixed by equilibrium alone")
        return Quantity(path, static, *load,
                        "each rigid group in equilibrium, Σ F_k ∂u_k/∂q = Q, motors on, "
                        "brakes off, solved for the link loads")
    if what in MODAL:
        try:
            expr, how = modal_quantity(model, what, choice or ModeChoice(), twins)
        except ComponentError as exc:
            raise ComponentError(f"quantity {path!r}: {exc}") from None
        dimension, unit = {"period": (time, "s"), "damping_ratio": (_ONE, "1")}.get(
            what, (1 / time, "rad/s"))
        return Quantity(path, expr, dimension, unit, how)
    if what == "response":
        try:
            force_t = link_response(model).force
        except ComponentError as exc:
            raise ComponentError(f"quantity {path!r}: {exc}") from None
        return Quantity(path, sp.simplify(force_t.xreplace(zero).xreplace(twins)), *load,
                        "the link's relative equation (Komarov's elimination) solved from "
                        "rest at zero twist, F = c u + d u̇")
    if run is None:
        raise ComponentError(f"quantity {path!r} needs the file's run")
    peak = next(p for p in run.peaks if p.link == name)
    if what == "peak":
        return Quantity(path, sp.Float(peak.value, 17), *load,
                        f"the largest load of the link over the run, at t = {peak.time:.6g} s",
                        numeric=True)
    if peak.factor is None:
        raise ComponentError(f"quantity {path!r}: the link has no reference load (its "
                             "load at the start is 0); give it reference = ...")
    return Quantity(path, sp.Float(peak.factor, 17), _ONE, "1",
                    f"the peak {peak.value:.6g} {peak.unit} over {peak.reference:.6g} "
                    f"{peak.unit}", numeric=True)



def _contact_quantity(model: Model, path: str, run) -> Quantity:
    """``<contact>.reaction`` in the symbols, or ``<contact>.reaction_peak`` of
    the run (see the module docstring)."""
    a, eq = model.assembly, model.equations
    name, _, what = path.partition(".")
    found = [c for c in a.contacts if c.part.name == name]
    if not found:
        raise ComponentError(f"quantity {path!r}: no ground contact {name!r}; contacts: "
                             f"{', '.join(c.part.name for c in a.contacts) or 'none'}")
    contact = found[0]
    motion = a.bodies[contact.part.body].motion
    unit = (DIMENSIONS["load"][motion], UNITS["load"][motion])
    if what == "reaction_peak":
        if run is None:
            raise ComponentError(f"quantity {path!r} needs the file's run")
        peak = next(r for r in run.reactions if r.contact == name)
        return Quantity(path, sp.Float(peak.value, 17), *unit,
                        f"the largest reaction over the run, at t = {peak.time:.6g} s",
                        numeric=True)
    q = eq.coordinates[contact.group]
    load = eq.forces[q].xreplace({on: 1 for on in eq.switches} | {B: 0 for B in eq.friction})
    load = load.subs({c.diff(eq.t): 0 for c in eq.coordinates})
    if load.free_symbols & set(eq.signals):
        raise ComponentError(f"quantity {path!r}: a motor law acts on the body's group, so "
                             "its reaction at rest is no expression of the parts")
    kappa = a.place[contact.part.body][2]
    reaction = contact.part.sign * load / kappa
    return Quantity(path, sp.simplify(reaction.xreplace(_zeros(model)).xreplace(signed(model))),
                    *unit, "the group at rest, every link unstretched: R = s Q/κ, motors on, "
                    "brakes off")


def _part_quantity(model: Model, path: str, owner: str) -> Quantity:
    """A quantity a kind declares for its parts (``Kind.quantities``), of the
    part ``path`` names: derived from its body's κ, its group's coordinate and
    that group's inertia referred to the body (∂²T/∂q̇² over κ²)."""
    a, eq = model.assembly, model.equations
    name, _, what = path.partition(".")
    load = next((l for l in a.loads if l.part.name == name and l.part.kind == owner), None)
    if load is None:
        raise ComponentError(f"quantity {path!r}: no {owner} {name!r}")
    part = load.part
    declared = next(q for q in kinds.of(part).quantities if q.name == what)
    g, _, kappa = a.place[part.body]
    inertia = eq.linear[0][g, g] / kappa**2
    expr = declared.derive(part, kappa, eq.coordinates[g], inertia)
    return Quantity(path, sp.simplify(expr.xreplace(_zeros(model)).xreplace(signed(model))),
                    declared.dimension, declared.unit, declared.how)
