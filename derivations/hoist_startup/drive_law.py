"""The hoist's response to a user's piecewise-polynomial drive law (paper 002).

The model is the two-mass hoist of this paper (derivation ``hoist_startup``):
drive m1 and load m2 on a rope of stiffness C, stretch :math:`x = x_1 - x_2`,

.. math::

    \\ddot x + \\Omega^2 x = S(t), \\qquad
    S(t) = \\frac{P(t)}{m_1} + \\frac{Q(t)}{m_2}, \\qquad
    P(t) = (m_1 + m_2)\\, a(t) + m_2 g                     \\quad (2), (28)-(31)

with :math:`Q = m_2 g` when lifting "from weight" (31) and
:math:`Q = m_2 g \\min(t/\\tau_0, 1)`, :math:`\\tau_0 = m_2 g/(C v_0)`, when
lifting "with pick-up" (28)-(29), :math:`v_0` the speed the law ends at. The
law :math:`a(t)` is given by numbers only (``law_tables.piecewise_law``); the
stretch follows by Duhamel's integral (15)-(24), once, symbolically, piece by
piece (``duhamel.duhamel``), the dynamic coefficient by (25)-(27), and
:func:`drive_law_outputs` gives them as functions of time only. A scene gives
such a law in a ``[drive_law]`` table (``drive_law_scene``).
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Any, Sequence

import sympy as sp

from crane_sym.derivation import Output
from crane_sym.mechanics.duhamel import DuhamelResult, duhamel
from crane_sym.scenes.law_tables import piecewise_law as drive_law
from crane_sym.mechanics.loads import Piece, PiecewiseLoad, exact_number

__all__ = ["DriveLawResponse", "FROM_WEIGHT", "PICKUP", "drive_law", "drive_law_outputs",
           "final_speed", "pickup_speed", "respond"]

FROM_WEIGHT = "from_weight"
PICKUP = "pickup"


# --- the law and the response ------------------------------------------------------
def _piece_of(load: PiecewiseLoad, time: sp.Expr) -> sp.Expr:
    """The expression of the piece of ``load`` holding at ``time`` (0 before it starts)."""
    for piece in load.intervals:
        if piece.start <= time < piece.end:
            return piece.expr
    return sp.Integer(0)


def _system(value: Any, what: str) -> sp.Expr:
    """A positive exact number (SymPy expressions with a known sign pass as given)."""
    number = value if isinstance(value, sp.Expr) and value.is_number else exact_number(
        value, what)
    if not number.is_positive:
        raise ValueError(f"{what} must be > 0, got {number}")
    return number


@dataclass(frozen=True)
class DriveLawResponse:
    """The hoist's response to one drive law; the methods give SymPy expressions in ``t``.

    Attributes: the data ``lifting``, ``m1, m2, C, g`` (exact, SI); ``omega``,
    :math:`\\Omega` of (2); the loads ``law`` :math:`a(t)`, ``resistance``
    :math:`Q(t)` of (28) or (31) and ``forcing`` :math:`S(t)` of (2) on the
    union of their breakpoints; ``final_speed`` :math:`v_0 = \\int a\\,dt`
    (``oo`` if the law never ends); ``contact_time`` :math:`\\tau_0` of (29)
    (pick-up only, else None); ``reference``, the force of (25),
    :math:`(m_2 P(0) + m_1 Q(0))/(m_1 + m_2)`; ``stretch``, the
    ``DuhamelResult`` :math:`x(t)` of (21) or (23), one piece per forcing piece.
    """

    t: sp.Symbol
    lifting: str
    m1: sp.Expr
    m2: sp.Expr
    C: sp.Expr
    g: sp.Expr
    omega: sp.Expr
    law: PiecewiseLoad
    resistance: PiecewiseLoad
    forcing: PiecewiseLoad
    final_speed: sp.Expr
    contact_time: sp.Expr | None
    reference: sp.Expr
    stretch: DuhamelResult

    def _assemble(self, per_piece) -> sp.Expr:
        """One Piecewise of ``per_piece(x_k, start_k)`` over the forcing's pieces."""
        exprs = [per_piece(x.expr, p.start)
                 for x, p in zip(self.stretch.pieces, self.forcing.intervals)]
        return _piecewise(exprs, self.forcing.intervals, self.t)

    def acceleration(self) -> sp.Expr:
        """:math:`a(t)` (0 before the law starts and after it ends)."""
        return self._assemble(lambda x, b: _piece_of(self.law, b))

    def speed(self) -> sp.Expr:
        """Drive speed :math:`v(t) = \\int_0^t a\\,d\\theta` of the rigid hoist."""
        exprs, start = [], sp.Integer(0)
        for p in self.forcing.intervals:
            exprs.append(sp.expand(start + sp.integrate(_piece_of(self.law, p.start),
                                                        (self.t, p.start, self.t))))
            start = exprs[-1].subs(self.t, p.end) if p.end != sp.oo else start
        return _piecewise(exprs, self.forcing.intervals, self.t)

    def relative_forcing(self) -> sp.Expr:
        """:math:`S(t)` of (2)."""
        return self._assemble(lambda x, b: _piece_of(self.forcing, b))

    def rope_stretch(self) -> sp.Expr:
        """:math:`x(t)` by Duhamel's integral, (21) or (23)."""
        return self._assemble(lambda x, b: x)

    def rope_stretch_rate(self) -> sp.Expr:
        """:math:`\\dot x(t)` (18)."""
        return self._assemble(lambda x, b: x.diff(self.t))

    def rope_force(self) -> sp.Expr:
        """:math:`P_{дин}(t) = C x(t)`, (22) or (24)."""
        return self._assemble(lambda x, b: self.C * x)

    def dynamic_coefficient(self) -> sp.Expr:
        """:math:`K_{дин}(t)`: the rope force over the reference of (25); (26), (27)."""
        return self._assemble(lambda x, b: self.C * x / self.reference)

    def load_acceleration(self) -> sp.Expr:
        """:math:`\\ddot x_2 = (C x - Q)/m_2`, the load's equation (1)."""
        return self._assemble(
            lambda x, b: (self.C * x - _piece_of(self.resistance, b)) / self.m2)


def final_speed(law: PiecewiseLoad) -> sp.Expr:
    """:math:`v_0 = \\int_0^\\infty a\\,dt`, the speed the law ends at (``oo`` when
    its last piece is not 0: it never ends)."""
    law = law.starting_at_zero()
    if law.intervals[-1].expr != 0:
        return sp.oo
    return sum((sp.integrate(p.expr, (law.t, p.start, p.end)) for p in law.intervals[:-1]),
               sp.Integer(0))


def pickup_speed(law: PiecewiseLoad) -> sp.Expr:
    """:math:`v_0` of (29) for lifting with pick-up; ``ValueError`` unless the law
    ends (last piece 0) at a speed :math:`v_0 > 0`."""
    final = final_speed(law)
    if final == sp.oo or not final.is_positive:
        raise ValueError("lifting with pick-up needs tau_0 = m2 g/(C v0) of (29): the "
                         f"law must end (last piece 0) at a speed v0 > 0, got {final}")
    return final


def _piecewise(exprs: list[sp.Expr], intervals: Sequence[Piece], t: sp.Symbol) -> sp.Expr:
    if len(exprs) == 1:
        return exprs[0]
    args = [(e, t < p.end) for e, p in zip(exprs[:-1], intervals[:-1])]
    return sp.Piecewise(*args, (exprs[-1], True))


def respond(law: PiecewiseLoad, m1: Any, m2: Any, C: Any, g: Any, lifting: str, *,
            contact_time: Any = None) -> DriveLawResponse:
    """Solve the hoist's stretch equation (2) for the drive law ``law``.

    .. math:: x(t) = x_0 \\cos\\Omega t + \\frac{1}{\\Omega}
              \\int_0^t S(\\theta) \\sin\\Omega(t - \\theta)\\,d\\theta,
              \\qquad x_0 = Q(0)/C                              \\quad (21), (23)

    Parameters
    ----------
    law : PiecewiseLoad
        :math:`a(t)` [m/s²] with numeric breakpoints, e.g. from :func:`drive_law`
        (``law_tables.piecewise_law``).
    m1, m2, C, g : numbers (SI), > 0
        Drive mass, load mass, rope stiffness, gravity (strings are refused).
    lifting : {"from_weight", "pickup"}
        Rope preloaded by the weight (11) or slack (7) at the start.
    contact_time : number, optional
        :math:`\\tau_0` with pick-up; default (29) with the law's final speed.

    Returns
    -------
    DriveLawResponse
    """
    if lifting not in (FROM_WEIGHT, PICKUP):
        raise ValueError(f"lifting must be {FROM_WEIGHT!r} or {PICKUP!r}, got {lifting!r}")
    m1, m2, C, g = (_system(v, n) for v, n in ((m1, "m1"), (m2, "m2"), (C, "C"), (g, "g")))
    t = law.t
    law = law.starting_at_zero()
    omega = sp.sqrt((m1 + m2) * C / (m1 * m2))
    final = final_speed(law)
    weight = m2 * g
    tau0 = None
    if lifting == PICKUP:
        tau0 = (_system(contact_time, "contact_time") if contact_time is not None
                else weight / (C * pickup_speed(law)))
        resistance = PiecewiseLoad((0, tau0), (weight * t / tau0, weight), t)
    else:
        resistance = PiecewiseLoad((0,), (weight,), t)
    cuts = sorted(set(law.breakpoints) | set(resistance.breakpoints), key=lambda b: sp.N(b, 30))
    pieces = [sp.expand((m1 + m2) / m1 * _piece_of(law, b) + weight / m1
                        + _piece_of(resistance, b) / m2) for b in cuts]
    forcing = PiecewiseLoad(tuple(cuts), tuple(pieces), t)
    q0 = resistance.pieces[0].subs(t, 0)
    p0 = (m1 + m2) * _piece_of(law, sp.Integer(0)).subs(t, 0) + weight
    reference = (m2 * p0 + m1 * q0) / (m1 + m2)
    if not reference.is_positive:
        raise ValueError(f"the reference force of (25) must be > 0, got {reference}: "
                         "a(0) < 0 pulls the load down at the start")
    stretch = duhamel(forcing, omega, t, u0=q0 / C, simplify=False)
    return DriveLawResponse(t, lifting, m1, m2, C, g, omega, law, resistance, forcing,
                            final, tau0, reference, stretch)


def drive_law_outputs(response: DriveLawResponse) -> list[Output]:
    """The generated functions of a response: time is their only argument."""
    t = response.t
    pickup = response.lifting == PICKUP
    x_eq, f_eq, k_eq = ("(21)", "(22)", "(26)") if pickup else ("(23)", "(24)", "(27)")
    case = "lifting with pick-up" if pickup else "lifting from weight"
    spec = [
        ("drive_acceleration", response.acceleration(), ("(28)", "(31)"),
         "Drive acceleration a(t) of the scene's law.", "m/s^2"),
        ("drive_speed", response.speed(), ("(28)", "(31)"),
         "Drive speed v(t), the integral of a(t) (rigid hoist).", "m/s"),
        ("relative_forcing", response.relative_forcing(), ("(2)", "(28)" if pickup
                                                            else "(31)"),
         f"Load S(t) = P/m1 + Q/m2 of the stretch equation, {case}.", "m/s^2"),
        ("rope_stretch", response.rope_stretch(), ("(15)", x_eq),
         f"Rope stretch x(t) = x1 - x2 by Duhamel's integral, {case}.", "m"),
        ("rope_stretch_rate", response.rope_stretch_rate(), ("(18)", x_eq),
         f"Stretch rate dx/dt, {case}.", "m/s"),
        ("rope_force", response.rope_force(), (f_eq,), f"Rope force C x(t), {case}.", "N"),
        ("dynamic_coefficient", response.dynamic_coefficient(), ("(25)", k_eq),
         f"Dynamic coefficient K_din(t), {case}.", "1"),
        ("load_acceleration", response.load_acceleration(), ("(1)", "(57)"),
         f"Load acceleration (C x - Q)/m2, {case}.", "m/s^2"),
    ]
    return [Output(name, expr, (t,), labels, summary, unit)
            for name, expr, labels, summary, unit in spec]
