"""Published formulas of paper 002, transcribed as printed: (1)–(31).

The LaTeX of each record is copied verbatim from ``002_f8509f3826f601de.txt``
(a chain of equalities gives one record per member worth checking, each with
the whole printed display). Ukrainian words in the prints: "дин" =
dynamic, "ст" = static, "п" (in t_п) = start, "У (50)" = "In (50)".
Notation: the OCR writes the subscript t_п as t_n; "x_{cr}" and "x_{cm}"
in (50), (53) are the OCR's reading of x_ст (Cyrillic "ст", italic "т"
looks like "m"). The integration variable θ of (15)–(39) is ``vartheta``;
θ of (43)–(53) is the duration of the load.

The transcriptions keep the print's errors; fixes are ``Convention``s only
where the matter is one of reading or notation.

This module holds the records of (1)–(31) and the helpers that make a record
(``_printed``, ``_cell``); ``published_load_cases`` holds (32)–(53),
``published_optimum`` (54)–(66) and the maxima after (66), ``tables`` the
printed cells of Tables 1–2.
"""
from __future__ import annotations

from decimal import Decimal

import sympy as sp

from crane_sym.readings import Meaning, SignOnce

from crane_sym.published import (ASSUMPTION, DEFINITION, INTERNAL, LINE_BREAK_SIGN, LOST_MARK,
                                 RECONSTRUCTED, Cause, Convention, PublishedFormula, printed)

from .model import (A_LAW, C1, C2, INT_S, INT_S_COS, INT_S_Y, K, K1, K2, PAPER, P, P_at0,
                    P_d, Q, Q_0, Q_at0, S, S_at0, C, K_cell, Omega, T, Y, a, a_at0, g, m1,
                    m2, t, t_n, tau0, v0, x, x0, x0_dot, x1, x2, x_s, x_s0, x_s0_dot)

_W = Omega
# (9), (10), (13) break a line after a minus and repeat it on the next line.
_LINE_BREAK = ("the minus before the line break is repeated after it, so the literal "
               "print subtracts a negative term")
_ONE_MINUS = "the minus repeated at the line break is one minus"
MINUS_AT_LINE_BREAK = Cause(
    "002-line-break-minus", "(9), (10) and (13) repeat the minus at a line break; read "
    "literally, the two minuses make the last term positive")
FULL_WEIGHT_FROM_START = Cause(
    "002-28-full-weight", "(28) has the drive pull the full weight m2·g from t = 0, "
    "while by its own Q(t) the load rests on the ground until τ_0; the rigid-hoist law "
    "(55) gives (m1 + m2)·a_i + Q(t)")
#: The laws (30) are shapes taken from ref. [7]; the check is their scaling.
#: Where the paper states its modelling choices (quoted by the assumption records).
CASE1 = ('"Випадок 1. Якщо початкові умови мають вигляд (7)" ("case 1: if the initial '
         'conditions are (7)"), before (7)')
CASE2 = ('"Випадок 2. Якщо до початку пуску система знаходилась під навантаженням ... то '
         'початкові умови будуть наступними" (before (11))')
PICKUP = ('"У першому випадку при підйомі вантажу «з підхватом» маємо (28)" ("in the first '
          'case, lifting with pick-up, we have (28)")')
LAWS = ('"ці значення прискорень наведені у [7] і відповідають певним (оптимальним) режимам '
        'функціонування привідного механізму" and "У (30) t_n – тривалість перехідного '
        'процесу (пуску)" (around (30))')
_SHAPE = {"stated": LAWS, "basis": INTERNAL,
          "basis_note": "the shape is ref. [7]'s; checked is the scaling the text "
                        "states, ∫₀^tп a dt = v0"}


def _printed(label: str, latex: str, relation: sp.Eq | None, note: str = "",
             **kwargs) -> PublishedFormula:
    return printed(PAPER, label, latex, relation, note, **kwargs)


# The displays, verbatim (raw strings).
L1 = (r"\begin{cases} m_1 \cdot \frac{d^2 x_1}{dt^2} + C(x_1 - x_2) = P(t), \\ m_2 \cdot "
      r"\frac{d^2 x_2}{dt^2} - C(x_1 - x_2) = -Q(t), \end{cases} \quad (1)")
L2 = r"\ddot{x} + \Omega^2 \cdot x = S(t), \quad \ddot{x} = d^2 x / dt^2, \quad (2)"
L2b = (r"\Omega^2 = \frac{(m_1 + m_2) \cdot C}{m_1 \cdot m_2}, \quad S(t) = \frac{m_2 "
       r"\cdot P(t) + m_1 \cdot Q(t)}{m_1 \cdot m_2}.")
L3 = r"P_{\text{дин}}(t) = C \cdot (x_1 - x_2) = C \cdot x(t). \quad (3)"
L4 = r"x = x_* + C_1 \cos(\Omega \cdot t) + C_2 \sin(\Omega \cdot t), \quad (4)"
L5 = r"P_{\text{дин}}(t) = C [x_* + C_1 \cos(\Omega t) + C_2 \sin(\Omega t)] \quad (5)"
L6 = r"T = \frac{2\pi}{\Omega}. \quad (6)"
L7 = (r"\dot{x}(t)|_{t=0} = 0, \quad P_{\text{дин}}(t)|_{t=0} = 0 \Leftrightarrow "
      r"x(t)|_{t=0} = 0, \quad (7)")
L8 = (r"\begin{aligned} C_1 &= -x_*(t)|_{t=0} = \tilde{x}_*; \\ C_2 &= -\frac{\dot{x}_*(t)"
      r"|_{t=0}}{\Omega} = -\frac{1}{\Omega} \cdot \dot{\tilde{x}}_*. \end{aligned} \quad (8)")
L9 = (r"\begin{aligned} x(t) &= x_*(t) - \tilde{x}_* \cdot \cos(\Omega t) - \\ "
      r"&-\frac{1}{\Omega} \cdot \dot{\tilde{x}}_* \cdot \sin(\Omega t), \end{aligned} \quad (9)")
L10 = (r"\begin{aligned} P_{\text{дин}}(t) &= C \cdot x_*(t) - C \cdot \tilde{x}_* "
       r"\cos(\Omega t) - \\ &-\frac{C}{\Omega} \cdot \dot{\tilde{x}}_* \sin(\Omega t). "
       r"\end{aligned} \quad (10)")
L11 = r"\dot{x}(t)|_{t=0} = \frac{Q(0)}{C}, \quad \dot{x}(t)|_{t=0} = 0. \quad (11)"
L12 = (r"C_1 = \frac{Q(0)}{C} - \tilde{x}_*; \quad C_2 = -\frac{1}{\Omega} \cdot "
       r"\dot{\tilde{x}}_*. \quad (12)")
L13 = (r"\begin{aligned} x(t) &= x_*(t) - \tilde{x}_* \cdot \cos(\Omega t) + "
       r"\frac{Q(0)}{C} \cos(\Omega t) - \\ &-\frac{1}{\Omega} \cdot \dot{\tilde{x}}_* "
       r"\cdot \sin(\Omega t), \end{aligned} \quad (13)")
L14 = (r"P_{\text{дин}}(t) = C \cdot x_*(t) - C \cdot \tilde{x}_* \cos(\Omega t) + Q(0) "
       r"\cos(\Omega t) - \frac{C}{\Omega} \cdot \dot{\tilde{x}}_* \sin(\Omega t). \quad (14)")
L15 = r"x_*(t) = \int_0^t S(\theta) \cdot Y(t-\theta) d\theta, \quad (15)"
L16 = r"Y(t) = \frac{1}{\Omega} \cdot \sin(\Omega t). \quad (16)"
L17 = (r"x_*(t) = \frac{1}{\Omega} \cdot \int_0^t S(\theta) \cdot \sin[\Omega(t-\theta)] "
       r"d\theta, \quad (17)")
L18 = r"\dot{x}_*(t) = \int_0^t S(\theta) \cdot \cos[\Omega(t-\theta)] d\theta \quad (18)"
L19 = (r"\begin{aligned} \ddot{x}_*(t) &= S(t) - \Omega^2 \cdot x_*(t) = \\ &= S(t) - "
       r"\Omega \int_0^t S(\theta) \cdot \sin[\Omega(t-\theta)] d\theta. \end{aligned} \quad (19)")
L20 = r"\tilde{x}_* = 0, \quad \dot{\tilde{x}}_* = 0. \quad (20)"
L21 = (r"x(t) = x_*(t) = \frac{1}{\Omega} \int_0^t S(\theta) \sin[\Omega(t-\theta)] "
       r"d\theta, \quad (21)")
L22 = (r"\begin{aligned} P_{\text{дин}}(t) &= C \cdot x_*(t) = \\ &= \frac{C}{\Omega} "
       r"\cdot \int_0^t S(\theta) \cdot \sin[\Omega(t-\theta)] d\theta; \end{aligned} \quad (22)")
L23 = (r"\begin{aligned} x(t) &= x_*(t) + \frac{Q(0)}{C} \cdot \cos(\Omega t) = \\ &= "
       r"\frac{1}{\Omega} \cdot \int_0^t S(\theta) \cdot \sin[\Omega(t-\theta)] d\theta + "
       r"\\ &+ \frac{Q(0)}{C} \cdot \cos(\Omega t), \end{aligned} \quad (23)")
L24 = (r"\begin{aligned} P_{\text{дин}}(t) &= C \cdot x(t) = \\ &= \frac{C}{\Omega} \cdot "
       r"\int_0^t S(\theta) \cdot \sin[\Omega(t-\theta)] d\theta + \\ &+ Q(0) \cdot "
       r"\cos(\Omega t). \end{aligned} \quad (24)")
L25 = (r"\begin{aligned} K_{\text{дин}}(t) &= \frac{P_{\text{дин}}(t)}{\left\{ "
       r"\frac{m_1 \cdot m_2}{(m_1 + m_2)} \cdot S(0) \right\}} = \\ &= "
       r"\frac{P_{\text{дин}}(t)}{\left\{ \frac{m_2 \cdot P(0) + m_1 \cdot Q(0)}{(m_1 + "
       r"m_2)} \right\}}. \end{aligned} \quad (25)")
L26 = (r"K_{\text{дин}}^{(1)}(t) = \frac{\left(\frac{C}{\Omega} \right) \int_0^t "
       r"S(\theta) \cdot \sin[\Omega \cdot (t-\theta)] d\theta}{\left[\frac{m_2 \cdot P(0) "
       r"+ m_1 \cdot Q(0)}{(m_1 + m_2)} \right]}; \quad (26)")
L27 = (r"\begin{aligned} K_{\text{дин}}^{(2)}(t) &= \left(\frac{C}{\Omega} \right) \cdot "
       r"\\ &\frac{\int_0^t S(\theta) \cdot \sin[\Omega(t-\theta)] d\theta + Q(0) "
       r"\cos(\Omega t)}{\left[\frac{m_2 P(0) + m_1 Q(0)}{(m_1 + m_2)} \right]}. "
       r"\end{aligned} \quad (27)")
L28 = (r"\begin{cases} P(t) = (m_1 + m_2) \cdot a_i(t) + m_2 g; \\ P(0) = (m_1 + m_2) "
       r"\cdot a_i(0) + m_2 g; Q(t) = 0. \\ Q_0 \cdot \frac{t}{\tau_0}, 0 \leq t \leq "
       r"\tau_0; \\ Q_0, t \geq \tau_0. \end{cases} \quad (28)")
L29 = r"\tau_0 = \frac{m_2 g}{C \cdot v_0}, \quad (29)"
L30 = (r"\begin{cases} a_1(t) = \frac{v_0}{t_n}; a_2(t) = \frac{v_0}{t_n} \left(1 - "
       r"\frac{t}{t_n}\right); \\ a_3(t) = 12 \frac{v_0 t}{t_n^2} \left(1 - "
       r"\frac{t}{t_n}\right)^2; \\ a_4(t) = 60 \frac{v_0}{t_n} \left(\frac{t}{t_n}"
       r"\right)^2 \cdot \left(1 - \frac{t}{t_n}\right)^3. \end{cases} \quad (30)")
L31 = (r"\begin{cases} P(t) = (m_1 + m_2) \cdot a_i(t) + m_2 g; \\ P(0) = (m_1 + m_2) "
       r"\cdot a_i(0) + m_2 g; \\ Q(t) = Q(0) = m_2 g. \end{cases} \quad (31)")
L_S = r"S(t) = \frac{P(t)}{m_1} + \frac{Q(t)}{m_2}."

_sin, _cos = sp.sin(_W * t), sp.cos(_W * t)

_x_ic = "(the transcription reads x(t)|_{t=0} as x_0, ẋ(t)|_{t=0} as ẋ_0)"

PUBLISHED = [
    _printed("(1)", L1, sp.Eq(m1 * x1.diff(t, 2) + C * (x1 - x2), P), "first line"),
    _printed("(1), load", L1, sp.Eq(m2 * x2.diff(t, 2) - C * (x1 - x2), -Q),
             "second line"),
    _printed("(2)", L2, sp.Eq(x.diff(t, 2) + _W ** 2 * x, S),
             "the second member only defines the dot notation"),
    _printed("(2), Ω²", L2b, sp.Eq(_W ** 2, (m1 + m2) * C / (m1 * m2)),
             "unnumbered line after (2)"),
    _printed("(2), S(t)", L2b, sp.Eq(S, (m2 * P + m1 * Q) / (m1 * m2)),
             "unnumbered line after (2)"),
    _printed("(3)", L3, sp.Eq(P_d, C * x), "outer members of the chain"),
    _printed("(3), in x1 and x2", L3, sp.Eq(P_d, C * (x1 - x2)), "first equality"),
    _printed("(4)", L4, sp.Eq(x, x_s + C1 * _cos + C2 * _sin)),
    _printed("(5)", L5, sp.Eq(P_d, C * (x_s + C1 * _cos + C2 * _sin))),
    _printed("(6)", L6, sp.Eq(T, 2 * sp.pi / _W)),
    _printed("(7)", L7, sp.Eq(x0, 0), "x(t)|_{t=0} = 0, equivalent to P_дин(0) = 0 "
             + _x_ic, kind=ASSUMPTION, stated=CASE1),
    _printed("(7), velocity", L7, sp.Eq(x0_dot, 0), "first condition " + _x_ic,
             kind=ASSUMPTION, stated=CASE1, basis=DEFINITION,
             basis_note="the model adopts the rest state the text states"),
    _printed("(8)", L8, sp.Eq(C1, x_s0),
             "outer members of the first line, C_1 = x̃_*; its middle member −x_*(0) "
             "and (9), (12), (13), (14) all take x̃_* = x_*(0), so the last member "
             "lacks a minus sign", cause=Cause(
                 "002-8-sign", "the last member of (8) drops the minus of its middle "
                 "member: C_1 = −x̃_*, as (9), (12)–(14) use it")),
    _printed("(8), middle", L8, sp.Eq(C1, -x_s0),
             "first line, C_1 = −x_*(t)|_{t=0}, with x_*(0) written x̃_*", compare_to="(8)"),
    _printed("(8), C2", L8, sp.Eq(C2, -x_s0_dot / _W), "second line, outer members"),
    _printed("(9)", L9, sp.Eq(x, x_s - x_s0 * _cos - (-(x_s0_dot * _sin / _W))),
             _LINE_BREAK, conventions=(Convention(
                 _ONE_MINUS, SignOnce(x_s0_dot * _sin / _W), LINE_BREAK_SIGN),),
             cause=MINUS_AT_LINE_BREAK),
    _printed("(10)", L10, sp.Eq(P_d, C * x_s - C * x_s0 * _cos - (-(C / _W * x_s0_dot * _sin))),
             _LINE_BREAK, conventions=(Convention(
                 _ONE_MINUS, SignOnce(C / _W * x_s0_dot * _sin), LINE_BREAK_SIGN),),
             cause=MINUS_AT_LINE_BREAK),
    _printed("(11)", L11, sp.Eq(x0_dot, Q_at0 / C),
             "the first condition is printed on ẋ(0), dimensionally impossible "
             "(m/s against m); (12) uses x(0) = Q(0)/C",
             conventions=(Convention("the first condition of (11) is on x(t)|_{t=0}; "
                                     "its dot is a slip (of print or OCR)",
                                     Meaning(((x0_dot, x0),)), LOST_MARK),),
             cause=Cause("002-dot-on-x0", "(11) puts a dot on the initial displacement "
                         "x(0): a velocity equated to a length")),
    _printed("(11), velocity", L11, sp.Eq(x0_dot, 0), "second condition",
             kind=ASSUMPTION, stated=CASE2, basis=DEFINITION,
             basis_note="the model adopts the rest state the text states"),
    _printed("(12)", L12, sp.Eq(C1, Q_at0 / C - x_s0)),
    _printed("(12), C2", L12, sp.Eq(C2, -x_s0_dot / _W)),
    _printed("(13)", L13, sp.Eq(x, x_s - x_s0 * _cos + Q_at0 / C * _cos
                                - (-(x_s0_dot * _sin / _W))),
             _LINE_BREAK, conventions=(Convention(
                 _ONE_MINUS, SignOnce(x_s0_dot * _sin / _W), LINE_BREAK_SIGN),),
             cause=MINUS_AT_LINE_BREAK),
    _printed("(14)", L14, sp.Eq(P_d, C * x_s - C * x_s0 * _cos + Q_at0 * _cos
                                - C / _W * x_s0_dot * _sin)),
    _printed("(15)", L15, sp.Eq(x_s, INT_S_Y), "Y(t − θ) written out with (16)",
             read_as="Y(t − θ) written out with its definition (16), sin(Ω(t − θ))/Ω"),
    _printed("(16)", L16, sp.Eq(Y, _sin / _W)),
    _printed("(17)", L17, sp.Eq(x_s, INT_S / _W)),
    _printed("(18)", L18, sp.Eq(x_s.diff(t), INT_S_COS)),
    _printed("(19)", L19, sp.Eq(x_s.diff(t, 2), S - _W * INT_S), "outer members"),
    _printed("(19), via (2)", L19, sp.Eq(x_s.diff(t, 2), S - _W ** 2 * x_s),
             "first equality"),
    _printed("(20)", L20, sp.Eq(x_s0, 0)),
    _printed("(20), velocity", L20, sp.Eq(x_s0_dot, 0)),
    _printed("(21)", L21, sp.Eq(x, INT_S / _W), "outer members"),
    _printed("(22)", L22, sp.Eq(P_d, C / _W * INT_S), "outer members"),
    _printed("(23)", L23, sp.Eq(x, INT_S / _W + Q_at0 / C * _cos),
             "outer members; the + repeated at the line break is +(+…), the same "
             "literally, so no reading is needed"),
    _printed("(24)", L24, sp.Eq(P_d, C / _W * INT_S + Q_at0 * _cos),
             "outer members; the + repeated at the line break is +(+…), the same "
             "literally, so no reading is needed"),
    _printed("(25)", L25, sp.Eq(K, P_d / ((m2 * P_at0 + m1 * Q_at0) / (m1 + m2))),
             "outer members", basis=DEFINITION,
             basis_note="(25) defines K_дин; the step writes the same definition"),
    _printed("(25), via S(0)", L25, sp.Eq(K, P_d / (m1 * m2 / (m1 + m2) * S_at0)),
             "first equality"),
    _printed("(26)", L26, sp.Eq(K1, C / _W * INT_S / ((m2 * P_at0 + m1 * Q_at0)
                                                      / (m1 + m2)))),
    _printed("(27)", L27, sp.Eq(K2, C / _W * (INT_S + Q_at0 * _cos)
                                / ((m2 * P_at0 + m1 * Q_at0) / (m1 + m2))),
             "the factor C/Ω stands before the whole fraction, so it multiplies "
             "Q(0) cos Ωt as well; (24) has it on the integral only",
             cause=Cause("002-27-factor-scope", "(27) puts the factor C/Ω before the "
                         "whole numerator, so it multiplies Q(0)·cos Ωt too, which (24) "
                         "does not")),
    _printed("(28)", L28, sp.Eq(P, (m1 + m2) * a + m2 * g),
             "first line: the drive pulls the full weight m2 g from t = 0 while the "
             "load still rests on the ground (Q < m2 g for t < τ_0); the rigid-hoist "
             "law, the paper's own (55), gives (m1 + m2)·a_i + Q(t)", kind=ASSUMPTION,
             stated=PICKUP, cause=FULL_WEIGHT_FROM_START),
    _printed("(28), P(0)", L28, sp.Eq(P_at0, (m1 + m2) * a_at0 + m2 * g),
             "second line; with Q(0) = 0 the rigid-hoist law gives (m1 + m2)·a_i(0)",
             kind=ASSUMPTION, stated=PICKUP, cause=FULL_WEIGHT_FROM_START),
    _printed("(28), Q(0)", L28, sp.Eq(Q_at0, 0),
             "reconstructed: the OCR reads 'Q(t) = 0.' and then the two branches "
             "without their left-hand side; read as Q(0) = 0 and Q(t) = {...}, the "
             "only reading consistent with (29) and the text after it",
             reconstructed=True, basis=RECONSTRUCTED,
             basis_note="the left-hand sides of (28)'s Q lines, lost in the OCR"),
    _printed("(28), Q(t)", L28, sp.Eq(Q, Q_0 * t / tau0),
             "reconstructed (see (28), Q(0)): Q(t) = Q_0 t/τ_0 for 0 ≤ t ≤ τ_0",
             reconstructed=True, basis=RECONSTRUCTED,
             basis_note="the left-hand sides of (28)'s Q lines, lost in the OCR"),
    _printed("(28), Q(t), t ≥ τ_0", L28, sp.Eq(Q, Q_0),
             "reconstructed (see (28), Q(0)): Q(t) = Q_0 for t ≥ τ_0",
             reconstructed=True, basis=DEFINITION,
             basis_note="the model adopts the print: a lifted load weighs Q_0"),
    _printed("(28), Q_0", r"Q_0 = m_2 g", sp.Eq(Q_0, m2 * g), "text after (28)",
             basis=DEFINITION, basis_note="Q_0 is named the load's weight"),
    _printed("(29)", L29, sp.Eq(tau0, m2 * g / (C * v0))),
    _printed("(30), a_1", L30, sp.Eq(A_LAW[1], v0 / t_n), kind=ASSUMPTION, **_SHAPE),
    _printed("(30), a_2", L30, sp.Eq(A_LAW[2], v0 / t_n * (1 - t / t_n)),
             "this a_2 brings the drive to v0/2 only by t_п (step '(30), speed of "
             "a_2'), while the text says t_п is the duration of the start to the steady "
             "speed v0; the steps after (30) use the law as printed", kind=ASSUMPTION,
             **_SHAPE, cause=Cause("002-a2-half-speed", "the printed a_2 integrates to "
                                   "v0/2 over t_п, while the text says every law reaches "
                                   "the steady speed v0 at t_п")),
    _printed("(30), a_3", L30, sp.Eq(A_LAW[3], 12 * v0 * t / t_n ** 2 * (1 - t / t_n) ** 2),
             kind=ASSUMPTION, **_SHAPE),
    _printed("(30), a_4", L30, sp.Eq(A_LAW[4], 60 * v0 / t_n * (t / t_n) ** 2
                                     * (1 - t / t_n) ** 3), kind=ASSUMPTION, **_SHAPE),
    _printed("(31)", L31, sp.Eq(P, (m1 + m2) * a + m2 * g), "first line"),
    _printed("(31), P(0)", L31, sp.Eq(P_at0, (m1 + m2) * a_at0 + m2 * g), "second line"),
    _printed("(31), Q", L31, sp.Eq(Q, m2 * g), "third line, outer members",
             basis=DEFINITION, basis_note="the model adopts the print: lifting from "
             "weight, the resistance is the weight"),
    _printed("(31), Q(0)", L31, sp.Eq(Q_at0, m2 * g), "third line, Q(0) = m2 g",
             basis=DEFINITION, basis_note="the model adopts the print: lifting from "
             "weight, the resistance is the weight"),
    _printed("S(t) after (31)", L_S, sp.Eq(S, P / m1 + Q / m2), "unnumbered",
             compare_to="(2), S(t)"),
]


def _number(text: str) -> tuple[sp.Rational, float]:
    """A number as printed (decimal comma) and the tolerance of its last digit:
    half a unit, relative to the value (0, i.e. exact, for a printed 0)."""
    value = Decimal(text.replace(",", "."))
    exact = sp.Rational(*value.as_integer_ratio())
    if value == 0:
        return exact, 0.0
    half_unit = Decimal(5).scaleb(value.as_tuple().exponent - 1)
    return exact, float(half_unit / abs(value))


def _cell(label: str, text: str, note: str, symbol=K_cell, latex: str = "",
          **kwargs) -> PublishedFormula:
    """A printed number against the derived value, within its last digit."""
    value, tolerance = _number(text)
    return _printed(label, latex or text, sp.Eq(symbol, value), note,
                    tolerance=tolerance, **kwargs)

