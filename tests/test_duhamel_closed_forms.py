"""The Duhamel convolution's closed-form antiderivatives (mechanics.exp_trig_integrals)
against SymPy's ``integrate``: the same expression where paper 002 uses them,
and equal at 50 digits (or by a difference that simplifies to 0) on the hard
cases: resonance, a repeated root, damping, products of waves, t -> 0."""
from __future__ import annotations

import pytest
import sympy as sp

from crane_sym.mechanics import exp_trig_integrals
from crane_sym.mechanics.duhamel import duhamel
from crane_sym.mechanics.exp_trig_integrals import definite_integral
from crane_sym.mechanics.loads import PiecewiseLoad, ramp, rectangular_pulse

tau = sp.Symbol("tau", real=True)
t, w, n, theta, p = sp.symbols("t omega n theta p", positive=True)
wd = sp.Symbol("omega_d", positive=True)

#: Sampled points (exact rationals, evaluated at 50 digits).
POINTS = [{t: sp.Rational(7, 5), w: sp.Rational(13, 4), n: sp.Rational(3, 10),
           wd: sp.Rational(9, 4), theta: sp.Rational(2, 3), p: sp.Rational(17, 5)},
          {t: sp.Rational(1, 9), w: sp.Rational(31, 2), n: sp.Rational(11, 7),
           wd: sp.Rational(5, 3), theta: sp.Rational(1, 20), p: sp.Rational(2, 7)}]


def _agree_at_50_digits(mine: sp.Expr, reference: sp.Expr) -> None:
    """Equal at every sampled point to 1e-30 (relative, or absolute near 0)."""
    for point in POINTS:
        a, b = (sp.N(e.subs(point), 50) for e in (mine, reference))
        assert abs(a - b) <= sp.Float("1e-30", 50) * max(1, abs(b)), (point, a, b)


@pytest.mark.parametrize("j", range(6))
@pytest.mark.parametrize("bounds", [(0, t), (0, theta), (theta, t)])
def test_002s_terms_are_the_expression_integrate_gives(j, bounds):
    """τ^j sin(ωτ − ωt), the undamped kernel times a polynomial load: the very
    expression SymPy's ``integrate`` returns, so generated modules print the same."""
    integrand = tau ** j * sp.sin(w * tau - w * t)
    mine = definite_integral(integrand, tau, *bounds)
    assert mine == sp.integrate(integrand, (tau, *bounds))


@pytest.mark.parametrize("integrand", [
    tau ** 2 * sp.exp(n * tau) * sp.sin(wd * tau - wd * t),          # damped kernel
    tau * sp.exp(n * tau) * sp.cos(wd * tau - wd * t) * sp.exp(-2 * n * tau),
    tau * sp.sin(w * tau - w * t) * sp.cos(2 * w * tau),              # a wave load
    sp.sin(w * tau) ** 2 * sp.cos(3 * w * tau),                       # three waves
    tau ** 3 * sp.exp(-n * tau),                                      # no wave
], ids=["damped", "damped-exp-load", "wave-load", "three-waves", "exponential"])
def test_general_terms_agree_with_integrate_at_50_digits(integrand):
    mine = definite_integral(integrand, tau, theta, t)
    assert not mine.has(sp.Integral, sp.Piecewise)
    _agree_at_50_digits(mine, sp.integrate(integrand, (tau, theta, t)))


@pytest.mark.parametrize("j, integrand", [
    (1, tau * sp.sin(w * tau - w * t) * sp.cos(w * tau)),             # undamped, a = ±iω
    (2, tau ** 2 * sp.exp(n * tau) * sp.sin(wd * tau - wd * t)
     * sp.exp(-n * tau) * sp.sin(wd * tau)),                          # damped, repeated root
], ids=["undamped", "damped-repeated-root"])
def test_resonance_gives_the_secular_term(j, integrand):
    """Load at the kernel's own frequency: the wave pairs into a constant, whose
    term integrates to τ^{j+1}/(j+1); the difference from integrate simplifies to 0."""
    mine = definite_integral(integrand, tau, 0, t)
    reference = sp.integrate(integrand, (tau, 0, t))
    assert sp.simplify(mine - reference) == 0
    waves = {f(v * t): sp.Dummy() for f in (sp.sin, sp.cos) for v in (w, wd)}
    growth = sp.Poly(sp.expand(mine).subs(waves), t).degree()
    assert growth == j + 1                   # the secular term t^{j+1}


def test_a_frequency_that_may_be_resonant_is_a_piecewise_of_both():
    """cos(pτ) against the kernel: p = ω is undecidable, so both branches, each
    exact where it holds."""
    integrand = sp.sin(w * tau - w * t) * sp.cos(p * tau)
    mine = definite_integral(integrand, tau, 0, t)
    assert mine.has(sp.Piecewise)
    _agree_at_50_digits(mine, sp.integrate(integrand, (tau, 0, t)))
    at_resonance = sp.simplify(mine.subs(p, w))
    assert sp.simplify(at_resonance - sp.integrate(integrand.subs(p, w), (tau, 0, t))) == 0


def test_the_response_starts_from_rest_as_t_to_0():
    """u(0) = u'(0) = 0, u''(0) = S(0), u'''(0) = S'(0) − 2n S(0): the response
    starts from rest as t → 0."""
    load = 3 + 2 * t + t ** 2
    u = duhamel(load, sp.sqrt(w ** 2 + n ** 2), t, damping=n, simplify=False).pieces[0].expr
    taylor = [sp.simplify(u.diff(t, k).subs(t, 0)) for k in range(4)]
    assert taylor == [0, 0, 3, 2 - 6 * n]


def _solves_at_50_digits(result, damping) -> None:
    """The residual of u'' + 2n u' + ω² u = S on each piece, and the jumps of u
    and u' at each breakpoint, vanish at the sampled points."""
    for piece, load in zip(result.pieces, result.load.intervals):
        u = piece.expr
        residual = u.diff(t, 2) + 2 * damping * u.diff(t) + w ** 2 * u - load.expr
        for point in POINTS:
            inside = {**point, t: point[theta] * (1 if piece.start == 0 else 3)}
            assert abs(sp.N(residual.subs(inside), 50)) < 1e-30, (piece, point)
    for before, after in zip(result.pieces, result.pieces[1:]):
        for order in (0, 1):
            jump = (after.expr - before.expr).diff(t, order).subs(t, after.start)
            assert all(abs(sp.N(jump.subs(point), 50)) < 1e-30 for point in POINTS)


def test_piecewise_loads_call_no_integrate(monkeypatch):
    """Polynomial, ramp, pulse and wave loads, damped or not: the closed forms
    alone, and each result solves its equation."""
    def refuse(*args):
        raise AssertionError(f"sympy.integrate called on {args[0]}")
    monkeypatch.setattr(exp_trig_integrals, "_by_sympy", refuse)
    loads = [ramp(1, theta, t=t), rectangular_pulse(2, theta, t=t),
             PiecewiseLoad((0, theta), (t ** 3 - t, sp.cos(w * t)), t)]
    for load in loads:
        assert duhamel(load, w, t, simplify=False).verify().ok, load
        _solves_at_50_digits(duhamel(load, w, t, damping=n, simplify=False), n)


def test_a_term_outside_the_class_goes_to_integrate():
    """√τ is no polynomial: SymPy integrates it, and the result is still exact."""
    mine = definite_integral(sp.sqrt(tau) * sp.cos(w * t), tau, 0, t)
    assert sp.simplify(mine - 2 * t ** sp.Rational(3, 2) * sp.cos(w * t) / 3) == 0
