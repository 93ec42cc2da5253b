"""Steps (32)–(53) of paper 002: the classic load cases.

Instantaneous load (35)–(38), linearly growing load (39)–(42), rectangular
pulse (43)–(47), load rising over θ and then held (48)–(53); ``load_cases``
returns the dynamic coefficients the generated code takes from them.
"""
from __future__ import annotations

import sympy as sp

from crane_sym.derivation import Derivation
from crane_sym.mechanics.duhamel import duhamel, free_response, impulse_response
from crane_sym.mechanics.exp_trig_integrals import definite_integral
from crane_sym.mechanics.loads import linear, ramp, rectangular_pulse, step
from crane_sym.codegen.rewriting import cos_pair_to_sin_squared

from .model import (C, K, Omega, Pbar, Pbar0, Pbar_f, S, Y, Y2, convolution, d_max, k, m,
                    t, t_max, t_n, theta, theta_half, vt, x, x0, x0_dot, x_max, x_s, x_st)
from .steps import pull_constants, rhs


def _amplitude(expr: sp.Expr) -> sp.Expr:
    """Amplitude R of ``A cos Ωt + B sin Ωt``, written with |sin| where it can."""
    wave = sp.expand(sp.expand_trig(sp.expand(expr)))
    coeffs = sp.collect(wave, [sp.cos(Omega * t), sp.sin(Omega * t)], evaluate=False)
    if set(coeffs) - {sp.cos(Omega * t), sp.sin(Omega * t)}:
        raise ValueError(f"not a pure sinusoid in Ωt: {expr}")
    A, B = (coeffs.get(f, 0) for f in (sp.cos(Omega * t), sp.sin(Omega * t)))
    square = cos_pair_to_sin_squared(sp.trigsimp(sp.expand(A ** 2 + B ** 2)))
    return sp.sqrt(sp.factor(square))


def _static(load: sp.Expr) -> sp.Expr:
    """Static deflection under a constant ``load`` P̄: (32) with ẍ = 0."""
    (value,) = sp.solve(sp.Eq(Omega ** 2 * x, load / m), x)
    return value


def _in_stiffness(expr: sp.Expr) -> sp.Expr:
    """Write m Ω² as C (the print's step after (35))."""
    return sp.simplify(expr.subs(m, C / Omega ** 2))


def load_cases(d: Derivation) -> dict:
    """(32)–(53): instantaneous, ramp, pulse and ramp-then-hold loads."""
    eq2 = d.step("(2)").statement
    d.add("(32)", sp.Eq(eq2.lhs, Pbar / m), "(2) with S = P̄/m.",
          "The classic load cases are written for a force P̄ on a reduced mass m.",
          "Classic load cases")
    d.add("(32), P̄", sp.Eq(Pbar, m * S), "Definition of P̄.")
    omega2 = rhs(d, "(2), Ω²")
    d.add("(32), m", sp.Eq(m, sp.factor(C / omega2)), "m = C/Ω² with Ω² of (2).")
    d.add("m Ω² = C (after (35))", sp.Eq(m * Omega ** 2, sp.factor(C / omega2 * omega2)),
          "(32), m times Ω² of (2).")
    free = free_response(Omega, t, x0, x0_dot)
    particular = pull_constants(convolution(Pbar_f(vt) / m * impulse_response(
        Omega, t).subs(t, t - vt)))
    d.add("(33)", sp.Eq(x, free + particular),
          "Free motion from x_0, ẋ_0 plus the Duhamel integral (17) with S = P̄/m.")
    swapped = particular.replace(
        lambda e: isinstance(e, sp.Integral),
        lambda e: _flip(e.transform(vt, (t - vt, vt))))
    d.add("(34)", sp.Eq(x_s, swapped), "θ → t − θ in the integral of (33).")
    y_force = free_response(Omega, t, 0, 1 / m)
    d.add("Y per unit force", sp.Eq(Y, y_force),
          "Free motion from x(0) = 0, ẋ(0) = 1/m: the response of (32) to a unit "
          "impulse of P̄.")

    out = {}
    # 1. Instantaneous load.
    inst = duhamel(step(Pbar0 / m, t=t), Omega, t).pieces[0].expr
    d.add("(35)", sp.Eq(x, inst), "Duhamel's integral of a constant P̄_0 from rest.",
          title="1. Instantaneous load")
    d.add("x_ст (after (35))", sp.Eq(x_st, _static(Pbar0)),
          "Static deflection under P̄_0: (32) with ẍ = 0.")
    d.add("(36)", sp.Eq(x, cos_pair_to_sin_squared(sp.expand(inst))),
          "1 − cos Ωt = 2 sin²(Ωt/2).")
    d.add("(37)", sp.Eq(K, x / x_st), "Definition: displacement over static deflection.")
    out["instant"] = cos_pair_to_sin_squared(sp.expand(sp.simplify(
        inst / rhs(d, "x_ст (after (35))"))))
    d.add("(38)", sp.Eq(K, out["instant"]), "(35) over x_ст.")

    # 2. Linear ramp.
    y2 = definite_integral((t - vt) * y_force.subs(t, vt), vt, 0, t)
    d.add("(39)", sp.Eq(x, k * y2), "∫ k(t − θ) Y(θ) dθ with Y per unit force.",
          title="2. Linearly growing load")
    y1_unit = definite_integral(impulse_response(Omega, t).subs(t, vt), vt, 0, t)
    d.add("Y_2 (after (39))", sp.Eq(Y2, definite_integral(y1_unit.subs(t, vt), vt, 0, t)),
        "Y of (16) integrated twice from 0.")
    rising = duhamel(linear(k / m, t=t), Omega, t).pieces[0].expr
    if sp.simplify(rising - k * y2) != 0:
        raise RuntimeError("(39) and Duhamel's integral of k t disagree")
    d.add("(40), in m and Ω", sp.Eq(x, rising), "Duhamel's integral of P̄ = k t.")
    rising_c = _in_stiffness(rising)
    d.add("(40)", sp.Eq(x, rising_c), "m Ω² = C.")
    d.add("(41)", sp.Eq(x_st, _in_stiffness(_static(k * t_n))),
          "Static deflection under P̄(t_п) = k t_п, with m Ω² = C.")
    out["ramp"] = sp.simplify(rising_c / rhs(d, "(41)"))
    d.add("(42)", sp.Eq(K, out["ramp"]), "(40) over (41).")

    # 3. Rectangular pulse.
    pulse = duhamel(rectangular_pulse(Pbar0 / m, theta, t=t), Omega, t)
    during, after = (p.expr for p in pulse.pieces)
    d.add("(43), in m and Ω", sp.Eq(x, during), "Duhamel's integral for 0 ≤ t ≤ θ.",
          title="3. Rectangular pulse")
    during_c, after_c = _in_stiffness(during), _in_stiffness(after)
    d.add("(43)", sp.Eq(x, during_c), "m Ω² = C.")
    d.add("(44), in m and Ω", sp.Eq(x, after),
          "Duhamel's integral for t ≥ θ: the load piece ends at θ.")
    d.add("(44)", sp.Eq(x, after_c), "m Ω² = C.")
    d.add("x_ст (before (45))", sp.Eq(x_st, _in_stiffness(_static(Pbar0))),
          "Static deflection under P̄_0, with m Ω² = C.")
    k_during = sp.simplify(during_c / rhs(d, "x_ст (before (45))"))
    k_after = sp.simplify(after_c / rhs(d, "x_ст (before (45))"))
    d.add("(45)", sp.Eq(K, k_during), "(43) over x_ст.")
    d.add("(46)", sp.Eq(K, k_after), "(44) over x_ст.")
    out["pulse"] = sp.Piecewise((k_during, t <= theta), (k_after, True))
    peak, when, half = _pulse_peak(k_during, k_after)
    d.add("half period (before (47))", sp.Eq(theta_half, half),
          "First maximum of (45) at Ωt = π; it falls within the pulse when θ ≥ π/Ω.")
    short, long_ = (branch for branch, _ in peak.args)
    d.add("(47)", sp.Eq(x_max, Pbar0 / C * short),
          "For θ < π/Ω the amplitude after the pulse exceeds the value at t = θ.")
    d.add("(47), in x_ст", sp.Eq(x_max, x_st * short), "The same with x_ст = P̄_0/C.")
    d.add("x_max for θ ≥ π/Ω (before (47))", sp.Eq(x_max, Pbar0 / C * long_),
          "For θ ≥ π/Ω the maximum of (45) at Ωt = π falls within the pulse.")
    d.add("x_max for θ ≥ π/Ω, in x_ст", sp.Eq(x_max, x_st * long_),
          "The same with x_ст = P̄_0/C.")
    d.add("(47), time", sp.Eq(t_max, when), "Where the larger maximum is reached.")
    out["pulse_peak"], out["pulse_peak_time"] = peak, when

    # 4. Rise over θ, then hold.
    rise = duhamel(ramp(Pbar0 / m, theta, t=t), Omega, t)
    up, hold = (p.expr for p in rise.pieces)
    d.add("(48)", sp.Eq(x, up), "Duhamel's integral for 0 ≤ t ≤ θ.",
          title="4. Load rising over θ, then held")
    d.add("(49)", sp.Eq(x, hold), "Duhamel's integral for t ≥ θ.")
    xst = _static(Pbar0)
    d.add("(50), x_ст", sp.Eq(x_st, xst), "Static deflection under P̄_0: (32) with ẍ = 0.")
    k_up, k_hold = sp.simplify(up / xst), sp.simplify(hold / xst)
    d.add("(50)", sp.Eq(x, x_st * k_hold), "(49) over x_ст.")
    d.add("(51)", sp.Eq(K, k_up), "(48) over x_ст.")
    d.add("(52)", sp.Eq(K, k_hold), "(49) over x_ст.")
    out["ramp_hold"] = sp.Piecewise((k_up, t <= theta), (k_hold, True))
    excess = _amplitude(k_hold - 1)
    d.add("(53)", sp.Eq(d_max, excess), "Amplitude of the oscillating part of (52).")
    out["ramp_hold_peak"] = 1 + excess
    return out


def _flip(integral: sp.Integral) -> sp.Expr:
    """``∫_t^0 −f`` written as ``∫_0^t f``."""
    (var, lo, hi), = integral.limits
    if lo == t and hi == 0:
        return sp.Integral(sp.expand(-integral.function), (var, 0, t))
    return integral


def _pulse_peak(k_during: sp.Expr, k_after: sp.Expr):
    """Largest K of the pulse, where it occurs, and the pulse length that
    separates the two cases."""
    first = min(sp.solveset(sp.diff(k_during, t), t, sp.Interval.open(0, 2 * sp.pi / Omega)),
                key=lambda r: sp.N(r.subs(Omega, 1)))
    top = sp.simplify(k_during.subs(t, first))
    amplitude = _amplitude(k_after)
    # For θ < π/Ω, 0 < sin(Ωθ/2) < 1: the amplitude after the pulse exceeds the
    # value (45) reaches at t = θ; check at one such pulse length.
    probe = {theta: sp.pi / (3 * Omega)}
    if not sp.simplify((amplitude - k_during.subs(t, theta)).subs(probe)) > 0:
        raise RuntimeError("the pulse maximum is not the amplitude after the pulse")
    # (46)'s rate at t = θ/2 + u/Ω, expanded and factored: 2Ω sin(Ωθ/2) cos u
    # (solve takes it in a tenth of the time it takes the sum of two sines)
    rate = sp.diff(k_after, t).subs(t, theta / 2 + sp.Symbol("u") / Omega)
    after_at = sp.solve(sp.factor(sp.expand_trig(sp.expand(rate))), sp.Symbol("u"))
    crest = min((u for u in after_at if u.is_positive), key=lambda u: sp.N(u))
    peak = sp.Piecewise((amplitude.subs(sp.Abs(sp.sin(Omega * theta / 2)),
                                        sp.sin(Omega * theta / 2)), theta < first),
                        (top, True))
    when = sp.Piecewise((theta / 2 + crest / Omega, theta < first), (first, True))
    return peak, when, first
