"""Response of a single oscillator to a load, by Duhamel's integral (Chovnyuk et al.).

For the relative coordinate of a two-mass drive,

.. math::

    \\ddot u + 2n\\dot u + \\omega^2 u = S(t), \\qquad u(0) = u_0, \\quad
    \\dot u(0) = v_0,

the solution is the free response plus the convolution of the load with the
unit-impulse response :math:`h` (Chovnyuk et al., eqs (15)–(17), (33)):

.. math::

    u(t) = u_{\\mathrm{free}}(t) + \\int_0^t h(t - \\tau)\\, S(\\tau)\\, d\\tau .

Everything is computed by SymPy: :math:`h` and :math:`u_{\\mathrm{free}}` by
solving the homogeneous equation, the convolution piece by piece of a
``PiecewiseLoad`` by closed-form antiderivatives (``duhamel``,
``exp_trig_integrals``), or, as an independent route, by
the Laplace transform of the whole problem (``duhamel_laplace``). Note the
convention: ``damping`` is :math:`n`, half the coefficient of
:math:`\\dot u` (``elimination.RelativeEquation.damping`` is :math:`2n`).
"""
from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache

import sympy as sp

from crane_sym.mechanics.exp_trig_integrals import definite_integral
from crane_sym.mechanics.loads import Piece, PiecewiseLoad, as_expression
from crane_sym.mechanics.verification import Verification, _verify_pieces


@dataclass(frozen=True)
class _Oscillator:
    """The caller's ω and n, and the positive dummies ``w``, ``n``, ``wd``
    (:math:`\\omega_d^2 = \\omega^2 - n^2`) the computation runs in."""

    omega: sp.Expr
    damping: sp.Expr
    w: sp.Dummy
    n: sp.Expr
    wd: sp.Dummy

    @classmethod
    def of(cls, omega: object, damping: object) -> "_Oscillator":
        """The oscillator of ``omega`` and ``damping``: one per pair, so that its
        solutions are solved once (``_homogeneous`` is memoized on it)."""
        return cls._of(as_expression(omega, "omega"), as_expression(damping, "damping"))

    @classmethod
    @lru_cache(maxsize=64)
    def _of(cls, omega: sp.Expr, damping: sp.Expr) -> "_Oscillator":
        if omega.is_positive is False or omega.is_zero:
            raise ValueError(f"omega must be positive, got {omega}")
        if damping.is_negative:
            raise ValueError(f"damping must be >= 0, got {damping}")
        if damping != 0 and sp.simplify(omega ** 2 - damping ** 2) == 0:
            raise ValueError("critical damping (damping = omega) is not supported")
        n = sp.Integer(0) if damping == 0 else sp.Dummy("n", positive=True)
        return cls(omega, damping, sp.Dummy("omega", positive=True), n,
                   sp.Dummy("omega_d", positive=True))

    def back(self, expr: sp.Expr) -> sp.Expr:
        """Replace the dummies by the caller's ω and n."""
        wd = sp.sqrt(self.omega ** 2 - self.damping ** 2)
        return expr.xreplace({self.wd: wd, self.n: self.damping}).xreplace(
            {self.w: self.omega})

    def inward(self, expr: sp.Expr) -> sp.Expr:
        """Replace the caller's ω and n, where they are symbols, by the dummies."""
        return expr.xreplace({s: d for s, d in ((self.omega, self.w), (self.damping, self.n))
                              if isinstance(s, sp.Symbol)})


@lru_cache(maxsize=256)
def _homogeneous(osc: _Oscillator, t: sp.Symbol, u0: sp.Expr, v0: sp.Expr) -> sp.Expr:
    """Solve :math:`\\ddot u + 2n\\dot u + \\omega^2 u = 0`, :math:`u(0)=u_0,
    \\dot u(0)=v_0`, in the dummies of ``osc`` (0 from rest).

    With damping, :math:`u = e^{-nt} y` removes the :math:`\\dot y` term and
    leaves :math:`\\ddot y + (\\omega^2 - n^2) y = 0`, solved with
    :math:`\\omega_d^2 = \\omega^2 - n^2`. Memoized: a derivation asks for the
    same impulse response once per load.
    """
    if u0 == 0 and v0 == 0:
        return sp.Integer(0)
    u, y = sp.Function("u")(t), sp.Function("y")(t)
    operator = u.diff(t, 2) + 2 * osc.n * u.diff(t) + osc.w ** 2 * u
    if osc.n == 0:
        general = sp.dsolve(sp.Eq(operator, 0), u).rhs
    else:
        reduced = sp.expand(sp.exp(osc.n * t) * operator.subs(u, sp.exp(-osc.n * t) * y)
                            .doit())
        if reduced.coeff(y.diff(t)) != 0:
            raise RuntimeError(f"substitution u = exp(-n t) y left a y' term: {reduced}")
        stiffness = sp.expand(reduced - y.diff(t, 2)).coeff(y)
        if sp.expand(stiffness - (osc.w ** 2 - osc.n ** 2)) != 0:
            raise RuntimeError(f"unexpected reduced stiffness {stiffness}")
        general = sp.exp(-osc.n * t) * sp.dsolve(
            sp.Eq(y.diff(t, 2) + osc.wd ** 2 * y, 0), y).rhs
    constants = sorted(general.free_symbols - {t, osc.w, osc.n, osc.wd}, key=str)
    conditions = [general.subs(t, 0) - u0, general.diff(t).subs(t, 0) - v0]
    (values,) = sp.linsolve(conditions, constants)
    return sp.simplify(general.subs(dict(zip(constants, values))))


def impulse_response(omega: sp.Expr, t: sp.Symbol, damping: sp.Expr = 0) -> sp.Expr:
    """Unit-impulse response :math:`h(t)` (Chovnyuk et al., eq (16)) of

    .. math:: \\ddot u + 2n\\dot u + \\omega^2 u = \\delta(t),

    derived as the free motion from :math:`u(0) = 0`, :math:`\\dot u(0) = 1`:
    :math:`\\sin(\\omega t)/\\omega` undamped,
    :math:`e^{-nt}\\sin(\\omega_d t)/\\omega_d`,
    :math:`\\omega_d = \\sqrt{\\omega^2 - n^2}`, damped.

    Parameters
    ----------
    omega : positive expression or number
    t : Symbol
    damping : expression or number
        :math:`n \\ge 0` (not critical, :math:`n \\ne \\omega`).
    """
    osc = _Oscillator.of(omega, damping)
    return osc.back(_homogeneous(osc, t, sp.Integer(0), sp.Integer(1)))


def free_response(omega: sp.Expr, t: sp.Symbol, u0: sp.Expr, v0: sp.Expr,
                  damping: sp.Expr = 0) -> sp.Expr:
    """Free motion from :math:`u(0) = u_0`, :math:`\\dot u(0) = v_0`, the first
    two terms of Chovnyuk et al.'s eq (33):

    .. math:: u_{\\mathrm{free}}(t) = u_0 \\cos\\omega t + \\frac{v_0}{\\omega}\\sin\\omega t
              \\quad (n = 0).

    Parameters
    ----------
    omega : positive expression or number
        Natural circular frequency.
    t : Symbol
        Time.
    u0, v0 : expression or number
        Initial displacement and velocity.
    damping : expression or number
        :math:`n \\ge 0` (not critical).
    """
    osc = _Oscillator.of(omega, damping)
    u0, v0 = as_expression(u0, "u0"), as_expression(v0, "v0")
    return osc.back(_homogeneous(osc, t, osc.inward(u0), osc.inward(v0)))


def _convolve(h: sp.Expr, S: sp.Expr, t: sp.Symbol, tau: sp.Dummy,
              lower: sp.Expr, upper: sp.Expr) -> sp.Expr:
    """:math:`\\int_{lower}^{upper} h(t - \\tau) S(\\tau)\\,d\\tau` in closed form
    (``S`` is given in ``tau``).

    The kernel is split into products of functions of :math:`t` and of
    :math:`\\tau` (addition theorems, :math:`e^{a-b} = e^a e^{-b}`), so each
    term integrates only its :math:`\\tau` factor, by the antiderivatives of
    ``exp_trig_integrals`` (polynomial, exponential and trigonometric loads;
    SymPy's ``integrate`` only for a term outside that class).
    """
    kernel = sp.expand(sp.expand_trig(h.subs(t, t - tau)), power_exp=True)
    total = sp.Integer(0)
    for term in sp.Add.make_args(sp.expand(kernel * S)):
        outside, inside = term.as_independent(tau, as_Add=False)
        total += outside * definite_integral(inside, tau, lower, upper)
    return total


@dataclass(frozen=True)
class DuhamelResult:
    """Solution :math:`u(t)` for :math:`t \\ge 0`, one expression per load piece.

    Attributes
    ----------
    t, omega, damping, u0, v0 : the problem (``damping`` is :math:`n`).
    load : PiecewiseLoad
        The load, with pieces covering all :math:`t \\ge 0`.
    impulse : sympy.Expr
        :math:`h(t)`.
    free : sympy.Expr
        The free response from :math:`(u_0, v_0)`.
    pieces : tuple of Piece
        ``u`` on each interval of the load.
    method : str
        ``"direct integration"`` or ``"laplace"``.
    """

    t: sp.Symbol
    omega: sp.Expr
    damping: sp.Expr
    u0: sp.Expr
    v0: sp.Expr
    load: PiecewiseLoad
    impulse: sp.Expr
    free: sp.Expr
    pieces: tuple[Piece, ...]
    method: str

    @property
    def velocity_pieces(self) -> tuple[Piece, ...]:
        """:math:`\\dot u` on each interval (Chovnyuk et al., eq (18))."""
        return tuple(Piece(p.start, p.end, sp.simplify(p.expr.diff(self.t)))
                     for p in self.pieces)

    @staticmethod
    def _as_piecewise(pieces: tuple[Piece, ...], t: sp.Symbol) -> sp.Expr:
        if len(pieces) == 1:
            return pieces[0].expr
        args = [(p.expr, t < p.end) for p in pieces[:-1]] + [(pieces[-1].expr, True)]
        return sp.Piecewise(*args)

    def piecewise(self) -> sp.Expr:
        """:math:`u(t)` as one ``sympy.Piecewise`` (a plain expression for one piece)."""
        return self._as_piecewise(self.pieces, self.t)

    def velocity(self) -> sp.Expr:
        """:math:`\\dot u(t)` as one ``sympy.Piecewise``."""
        return self._as_piecewise(self.velocity_pieces, self.t)

    def verify(self, equation: sp.Eq | None = None, u: sp.Expr | None = None,
               forcing: sp.Expr | None = None) -> Verification:
        """Substitute the solution back; never raises.

        Checks, on each piece, that the residual of ``equation`` simplifies to
        0; that :math:`u` and :math:`\\dot u` are continuous at every
        breakpoint; and the initial conditions.

        Parameters
        ----------
        equation : sympy.Eq, optional
            An ODE in an applied function ``u(t)``; default: the equation this
            result solves, in ``u(t)`` and ``S(t)``. The load stands in it as
            the applied function ``forcing``, replaced by each piece's
            expression, or is written out when it has one piece.
        u : applied function, optional
            The unknown; default: the one function of ``t`` under a derivative.
        forcing : applied function, optional
            The placeholder of the load in ``equation``.
        """
        if equation is None:
            u, forcing = sp.Function("u")(self.t), sp.Function("S")(self.t)
            equation = sp.Eq(u.diff(self.t, 2) + 2 * self.damping * u.diff(self.t)
                             + self.omega ** 2 * u, forcing)
        load = tuple(Piece(p.start, p.end, p.expr.subs(self.load.t, self.t))
                     for p in self.load.intervals)
        return _verify_pieces(equation, self.pieces, self.t, load, u, forcing,
                              {0: self.u0, 1: self.v0})


def _prepare(forcing: PiecewiseLoad | sp.Expr, t: sp.Symbol) -> PiecewiseLoad:
    if isinstance(forcing, PiecewiseLoad):
        return forcing.starting_at_zero()
    forcing = as_expression(forcing, "forcing")
    if forcing.has(sp.Piecewise, sp.Heaviside):
        raise ValueError("give a piecewise forcing as a loads.PiecewiseLoad")
    return PiecewiseLoad((0,), (forcing,), t)


def duhamel(forcing: PiecewiseLoad | sp.Expr, omega: sp.Expr, t: sp.Symbol, *,
            u0: sp.Expr = 0, v0: sp.Expr = 0, damping: sp.Expr = 0,
            simplify: bool = True) -> DuhamelResult:
    """Solve :math:`\\ddot u + 2n\\dot u + \\omega^2 u = S(t)` by Duhamel's integral.

    For :math:`t` in piece :math:`k`, :math:`[b_k, b_{k+1})`,

    .. math::

        u(t) = u_{\\mathrm{free}}(t)
        + \\sum_{j<k} \\int_{b_j}^{b_{j+1}} h(t-\\tau) S_j(\\tau)\\,d\\tau
        + \\int_{b_k}^{t} h(t-\\tau) S_k(\\tau)\\,d\\tau

    (Chovnyuk et al., eqs (15), (33); for a pulse, eqs (44), (49)).

    Parameters
    ----------
    forcing : PiecewiseLoad or sympy.Expr
        The load :math:`S(t)`; an expression holds for all :math:`t \\ge 0`.
    omega : positive expression
        Natural frequency :math:`\\omega`.
    t : Symbol
        Time.
    u0, v0 : expressions
        Initial displacement and velocity.
    damping : expression
        :math:`n \\ge 0`, half the coefficient of :math:`\\dot u`.
    simplify : bool
        Simplify each piece (slower, shorter).
    """
    load = _prepare(forcing, t)
    osc = _Oscillator.of(omega, damping)
    u0, v0 = as_expression(u0, "u0"), as_expression(v0, "v0")
    h = _homogeneous(osc, t, sp.Integer(0), sp.Integer(1))
    free = _homogeneous(osc, t, osc.inward(u0), osc.inward(v0))
    tau = sp.Dummy("tau", real=True)
    exprs = [osc.inward(e.subs(load.t, tau)) for e in load.pieces]
    bounds = [osc.inward(b) for b in load.breakpoints]
    done = sp.Integer(0)                 # the completed earlier pieces
    pieces = []
    for k, interval in enumerate(load.intervals):
        expr = free + done + _convolve(h, exprs[k], t, tau, bounds[k], t)
        if simplify:
            expr = sp.simplify(expr)
        pieces.append(Piece(interval.start, interval.end, osc.back(expr)))
        if k + 1 < len(exprs):
            done += _convolve(h, exprs[k], t, tau, bounds[k], bounds[k + 1])
    return DuhamelResult(t, osc.omega, osc.damping, u0, v0, load, osc.back(h),
                         osc.back(free), tuple(pieces), "direct integration")


def duhamel_laplace(forcing: PiecewiseLoad | sp.Expr, omega: sp.Expr, t: sp.Symbol, *,
                    u0: sp.Expr = 0, v0: sp.Expr = 0,
                    damping: sp.Expr = 0) -> DuhamelResult:
    """The same problem solved by the Laplace transform (one-piece loads only).

    The transform of the equation, solved for :math:`U(s)`,

    .. math::

        U(s) = \\frac{\\mathcal L[S](s) + (s + 2n) u_0 + v_0}{s^2 + 2ns + \\omega^2},

    is inverted by ``sympy.inverse_laplace_transform`` (:math:`t > 0`). An
    independent check of ``duhamel``.
    """
    load = _prepare(forcing, t)
    if len(load.pieces) != 1:
        raise ValueError("duhamel_laplace takes a load with one piece; use duhamel "
                         "for piecewise loads")
    osc = _Oscillator.of(omega, damping)
    u0, v0 = as_expression(u0, "u0"), as_expression(v0, "v0")
    s = sp.Dummy("s")
    y = sp.Function("y")(t)
    S = osc.inward(load.pieces[0].subs(load.t, t))
    ode = y.diff(t, 2) + 2 * osc.n * y.diff(t) + osc.w ** 2 * y - S
    transformed = sp.laplace_transform(ode, t, s, noconds=True)
    transformed = transformed.subs({sp.Subs(y.diff(t), t, 0): osc.inward(v0)}).subs(
        y.subs(t, 0), osc.inward(u0))
    Y = sp.LaplaceTransform(y, t, s)
    (image,) = sp.solve(transformed, Y)
    solution = sp.inverse_laplace_transform(image, s, t).subs(sp.Heaviside(t), 1)
    if solution.has(sp.InverseLaplaceTransform):
        raise ValueError(f"SymPy cannot invert the transform {image}")
    expr = osc.back(sp.simplify(solution))
    h = osc.back(_homogeneous(osc, t, sp.Integer(0), sp.Integer(1)))
    free = osc.back(_homogeneous(osc, t, osc.inward(u0), osc.inward(v0)))
    return DuhamelResult(t, osc.omega, osc.damping, u0, v0, load, h, free,
                         (Piece(sp.Integer(0), sp.oo, expr),), "laplace")
