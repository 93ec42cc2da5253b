"""Published formulas of paper 002, transcribed as printed.

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
"""
from __future__ import annotations

from decimal import Decimal

import sympy as sp

from crane_sym.derivations.hoist_startup import (
    A_LAW, C1, C2, INT_P, INT_P_REV, INT_P_Y16, INT_P_YF, INT_S, INT_S_COS,
    INT_S_Y, K, K1, K2, K_OPT, PAPER, P, P_at0, P_d, Pbar, Pbar0, Q, Q_0, Q_at0,
    S, S_at0, TABLE2_BLOCKS, TABLE2_ROWS, TABLE_COLUMNS, C, F_ref, Omega, T, Y,
    Y2, a, a_at0, col, d_max, dk_tau0, dQdot_tau0, g, k, k3_max, k4_max, k_d, kt_d,
    m, m1, m2, t, t3_star, t4_star, t_a, t_n, table1_label, table2_label, tau0,
    theta, theta_half, v0, vt, x, x0, x0_dot, x1, x2, x_max, x_s, x_s0, x_s0_dot,
    x_st, K_cell)
from crane_sym.published import ASSUMPTION, Convention, PublishedFormula

_W = Omega


def _printed(label: str, latex: str, printed: sp.Eq | None, note: str = "",
             **kwargs) -> PublishedFormula:
    where = f"{PAPER}, eq {label}" if label.startswith("(") else f"{PAPER}, {label}"
    return PublishedFormula(label, latex, printed, where + (f"; {note}" if note else ""),
                            **kwargs)


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
L32 = r"\ddot{x} + \Omega^2 \cdot x = \frac{\bar{P}(t)}{m}, \quad (32)"
L32b = r"\bar{P}(t) = S(t)m, m = \frac{m_1 m_2}{m_1 + m_2}."
L33 = (r"x(t) = x_0 \cos \Omega \cdot t + \frac{1}{\Omega} \dot{x}_0 \cdot \sin(\Omega t) + "
       r"\frac{1}{\Omega m} \cdot \int_0^t \bar{P}(\theta) \cdot \sin[\Omega(t - \theta)] "
       r"d\theta, \quad (33)")
L34 = (r"x_*(t) = \int_0^t \bar{P}(t - \theta) \cdot Y(\theta) d\theta = \frac{1}{\Omega "
       r"m} \cdot \int_0^t \bar{P}(t - \theta) \cdot \sin[\Omega\theta] d\theta. \quad (34)")
L35 = r"x(t) = \frac{\bar{P}_0}{m\Omega^2} \cdot (1 - \cos \Omega t). \quad (35)"
L36 = (r"x(t) = \frac{2\bar{P}_0}{m\Omega^2} \cdot \left(\sin^2 \left[\frac{\Omega t}{2} "
       r"\right] \right). \quad (36)")
L37 = (r"K_{\text{дин}}(t) = \frac{C \cdot x(t)}{C \cdot x_{\text{ст}}} \Leftrightarrow "
       r"\frac{x(t)}{x_{\text{ст}}}, \quad (37)")
L37b = r"K_{\text{дин}}(t) = \frac{x(t)}{x_{\text{ст}}},"
L38 = r"K_{\text{дин}}(t) = 2 \sin^2 \left(\frac{\Omega(t)}{2} \right). \quad (38)"
L39a = r"x(t) = \int_0^t k(t-\theta) \cdot Y(\theta) d\theta = kY_2(t),"
L39b = r"Y_2(t) = \int_0^t (t-\theta) \cdot Y(\theta) d\theta. \quad (39)"
L40 = (r"x(t) = \frac{(kt)}{m\Omega^2} \cdot [1 - \sin(\Omega t) / (\Omega t)] = "
       r"\frac{(kt)}{C} \cdot [1 - \sin(\Omega t) / (\Omega t)]. \quad (40)")
L41 = r"x_{\text{ст}} = \frac{k \cdot t_{\text{п}}}{C}. \quad (41)"
L42 = (r"K_{\text{дин}}(t) = \frac{(t)}{(t_{\text{п}})} \cdot [1 - \sin(\Omega t) / "
       r"(\Omega t)]. \quad (42)")
L43 = (r"x(t) = \bar{P}_0 \cdot Y_1(t) = \frac{\bar{P}_0}{C} (1 - \cos \Omega t); "
       r"\quad (43)")
L44 = (r"\begin{aligned} x(t) &= \bar{P}_0 \cdot Y_1(t) - \bar{P}_0 \cdot Y_1(t - \theta) "
       r"= \\ &= \frac{\bar{P}_0}{C} \cdot [\cos \{ \Omega(t - \theta) \} - \cos(\Omega t)] "
       r"= \quad (44) \\ &= 2\bar{P}_0 C^{-1} \cdot \sin \left\{ \frac{\Omega \theta}{2} "
       r"\right\} \cdot \sin \left\{ \Omega \left(t - \frac{\theta}{2} \right) \right\}. "
       r"\end{aligned}")
L45 = (r"K_{дин}(t) = (1 - \cos \Omega t) = 2 \sin^2 \left(\frac{\Omega t}{2} \right); "
       r"\quad (45)")
L46 = (r"K_{дин}(t) = 2 \sin \left(\frac{\Omega \theta}{2} \right) \cdot \sin "
       r"\left[\Omega \left(t - \frac{\theta}{2} \right) \right]. \quad (46)")
L47a = r"x_{max} = \frac{2\bar{P}_0}{C} = 2x_{ст}"
L47 = (r"x_{max} = \frac{2\bar{P}_0}{C} \cdot \sin \left\{ \frac{\Omega \theta}{2} "
       r"\right\} = 2x_{ст} \cdot \sin \left\{ \frac{\Omega \theta}{2} \right\}. \quad (47)")
L48 = (r"x(t) = \left(\frac{\bar{P}_0}{\theta} \right) Y_2(t) = \frac{\bar{P}_0}{(m\Omega^3"
       r"\theta)} (\Omega t - \sin[\Omega t]), \quad (48)")
L49 = (r"\begin{aligned} x(t) &= \left(\frac{\bar{P}_0}{\theta} \right) \cdot [Y_2(t) - "
       r"Y_2(t - \theta)] = \\ &= \frac{\bar{P}_0}{(m\Omega^3\theta)} [\Omega\theta - "
       r"\sin(\Omega t) + \sin\{\Omega(t - \theta)\}]. \end{aligned} \quad (49)")
L50 = (r"x(t) = x_{cr} \left[1 - 2 \cos \left\{ \Omega \left(t - \frac{\theta}{2} \right) "
       r"\right\} \cdot \sin \{ \Omega\theta / 2 \} / (\Omega\theta) \right]. \quad (50)")
L50b = r"\text{У (50) } x_{cr} = \bar{P}_0 [m\Omega^2]^{-1}."
L51 = r"K_{дин}(t) = \frac{(\Omega t - \sin(\Omega t))}{(\Omega\theta)}, \quad (51)"
L52 = (r"K_{дин}(t) = 1 - 2 \cos \left[\Omega \left(t - \frac{\theta}{2} \right) \right] "
       r"\frac{\sin(\Omega\theta / 2)}{(\Omega\theta)}. \quad (52)")
L53 = (r"\left[(x - x_{cr}) / x_{cm} \right]_{max} = 2 \sin \left(\frac{\Omega\theta}{2} "
       r"\right) / (\Omega\theta). \quad (53)")
L54 = (r"x_2^{(IV)} + \Omega^2 \cdot \ddot{x}_2 = \frac{P(t) - Q(t)}{\left[\frac{m_1 m_2}"
       r"{C} \right]}, \quad (54)")
L55 = r"P(t) = (m_1 + m_2) \cdot a_i(t) + Q(t), \quad (55)"
L56 = r"x_2^{(IV)} + \Omega^2 \cdot \ddot{x}_2 = \Omega^2 \cdot a_i(t). \quad (56)"
L57 = (r"k_{дин}(t) = \left\{ \frac{m_2 \cdot \ddot{x}_2 + Q(t)}{\left(m_2 \cdot "
       r"\frac{v_0}{t_n} \right)} \right\} = \left\{ \frac{C(x_1 - x_2)}{\left(m_2 \cdot "
       r"\frac{v_0}{t_n} \right)} \right\}, \quad (57)")
L58 = r"\int_0^{t_n} k_{дин}^2(t) dt \Rightarrow \min. \quad (58)"
L59 = r"x_2^{(IV)} \cdot m_2 + \ddot{Q}(t) = 0. \quad (59)"
L60 = r"x_2^{(IV)} = 0. \quad (60)"
L61 = (r"\begin{cases} x_2^{(IV)} + \Omega^2 \ddot{x}_2 = \Omega^2 a_i(t), \\ x_2^{(IV)} "
       r"= 0; \end{cases} \Leftrightarrow \ddot{x}_2 = a_i(t). \quad (61)")
L62 = (r"k_{\text{дин}}(t) = \frac{m_2 \cdot a_i(t) + Q(t)}{\left(m_2 \cdot \frac{v_0}"
       r"{t_n}\right)}, \quad (62)")
L63 = (r"\tilde{k}_{\text{дин}}(t) = \frac{m_2 \cdot a_i(t)}{\left(m_2 \cdot "
       r"\frac{v_0}{t_n}\right)}, \quad t_n \geq t > 0 \quad (63)")
L64 = (r"\left\{ \begin{aligned} \tilde{k}_{\text{дин}}(t) &= \left\{ \frac{m_2 a_i(t) + "
       r"m_2 g \frac{t}{\tau_0}}{\left(m_2 \frac{v_0}{t_n}\right)} \right\}, & 0 \leq t "
       r"\leq \tau_0; \\ \tilde{k}_{\text{дин}}(t) &= \left\{ \frac{m_2 a_i(t)}{\left(m_2 "
       r"\frac{v_0}{t_n}\right)} \right\}, & \tau_0 < t \leq t_n, \end{aligned} \right. "
       r"\quad (64)")
L65 = (r"\left\{ \begin{aligned} i = 1 - \tilde{k}_{\text{дин1}}^{(\text{opt})} &= 1; "
       r"\quad i = 2 - \tilde{k}_{\text{дин2}}^{(\text{opt})} = \left(1 - \frac{t}{t_n}"
       r"\right); \\ i = 3 - \tilde{k}_{\text{дин3}}^{(\text{opt})} &= 12 \frac{t}{t_n} "
       r"\left(1 - \frac{t}{t_n}\right)^2; \\ i = 4 - \tilde{k}_{\text{дин4}}^{(\text{opt})}"
       r" &= 60 \left(\frac{t}{t_n}\right)^2 \left(1 - \frac{t}{t_n}\right)^3. "
       r"\end{aligned} \right. \quad (65)")
L66 = (r"\left\{ \begin{aligned} i = 1 - \tilde{k}_{\text{дин1}}^{(\text{opt})} &= 1 + "
       r"\frac{gt}{\tau_0 \left(\frac{v_0}{t_n}\right)}; \\ i = 2 - "
       r"\tilde{k}_{\text{дин2}}^{(\text{opt})} &= 1 - \frac{t}{t_n} + \frac{gt}{\tau_0 "
       r"\left(\frac{v_0}{t_n}\right)}; \\ i = 3 - \tilde{k}_{\text{дин3}}^{(\text{opt})} "
       r"&= 12 \frac{t}{t_n} \left(1 - \frac{t}{t_n}\right)^2 + \frac{gt}{\tau_0 "
       r"\left(\frac{v_0}{t_n}\right)}; \\ i = 4 - \tilde{k}_{\text{дин4}}^{(\text{opt})} "
       r"&= 60 \left(\frac{t}{t_n}\right)^2 \left(1 - \frac{t}{t_n}\right)^3 + "
       r"\frac{gt}{\tau_0 \left(\frac{v_0}{t_n}\right)}. \end{aligned} \right. \quad (66)")
L_MAX3 = (r"\tilde{k}_{\text{дин3}}^{(\text{opt})}\left(\frac{t_n}{3}\right) = 1,7778, "
          r"\text{ а максимальне значення}")
L_MAX4 = r"\tilde{k}_{\text{дин3}}^{(\text{opt})}(0,4t_n) = 2,0736."

_sin, _cos = sp.sin(_W * t), sp.cos(_W * t)
_half = sp.sin(_W * theta / 2)
_FORCE_Y = ("from (33) on, Y is the response to a unit impulse of the force P̄, "
            "sin(Ωt)/(mΩ), and Y_1, Y_2 its integrals — not Y of (16)")


def _via_y(label: str, latex: str, printed_with_16, reading_per_force, target: str,
           note: str) -> PublishedFormula:
    """A member written with Y, Y_1 or Y_2: as printed Y is that of (16)."""
    return _printed(label, latex, sp.Eq(x, printed_with_16), note,
                    compare_to=target,
                    conventions=(Convention(_FORCE_Y, sp.Eq(x, reading_per_force)),))


def _y_integrals(scale):
    """Y_1, Y_2 of the text after (39) for Y = sin(Ωt)/(Ω·scale)."""
    y = sp.sin(_W * vt) / (_W * scale)
    y1 = sp.integrate(y, (vt, 0, t))
    y2 = sp.integrate(y1.subs(t, vt), (vt, 0, t))
    return y1, y2


_Y1, _Y2 = _y_integrals(1)            # Y of (16)
_Y1m, _Y2m = _y_integrals(m)          # Y per unit force

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
             + _x_ic, kind=ASSUMPTION),
    _printed("(7), velocity", L7, sp.Eq(x0_dot, 0), "first condition " + _x_ic,
             kind=ASSUMPTION),
    _printed("(8)", L8, sp.Eq(C1, x_s0),
             "outer members of the first line, C_1 = x̃_*; its middle member −x_*(0) "
             "and (9), (12), (13), (14) all take x̃_* = x_*(0), so the last member "
             "lacks a minus sign"),
    _printed("(8), middle", L8, sp.Eq(C1, -x_s0),
             "first line, C_1 = −x_*(t)|_{t=0}, with x_*(0) written x̃_*", compare_to="(8)"),
    _printed("(8), C2", L8, sp.Eq(C2, -x_s0_dot / _W), "second line, outer members"),
    _printed("(9)", L9, sp.Eq(x, x_s - x_s0 * _cos - x_s0_dot * _sin / _W)),
    _printed("(10)", L10, sp.Eq(P_d, C * x_s - C * x_s0 * _cos - C / _W * x_s0_dot * _sin)),
    _printed("(11)", L11, sp.Eq(x0_dot, Q_at0 / C),
             "the first condition is printed on ẋ(0), dimensionally impossible "
             "(m/s against m); (12) uses x(0) = Q(0)/C",
             conventions=(Convention("the first condition of (11) is on x(t)|_{t=0}; "
                                     "its dot is a slip (of print or OCR)",
                                     sp.Eq(x0, Q_at0 / C)),)),
    _printed("(11), velocity", L11, sp.Eq(x0_dot, 0), "second condition",
             kind=ASSUMPTION),
    _printed("(12)", L12, sp.Eq(C1, Q_at0 / C - x_s0)),
    _printed("(12), C2", L12, sp.Eq(C2, -x_s0_dot / _W)),
    _printed("(13)", L13, sp.Eq(x, x_s - x_s0 * _cos + Q_at0 / C * _cos
                                - x_s0_dot * _sin / _W)),
    _printed("(14)", L14, sp.Eq(P_d, C * x_s - C * x_s0 * _cos + Q_at0 * _cos
                                - C / _W * x_s0_dot * _sin)),
    _printed("(15)", L15, sp.Eq(x_s, INT_S_Y), "Y(t − θ) written out with (16)"),
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
    _printed("(23)", L23, sp.Eq(x, INT_S / _W + Q_at0 / C * _cos), "outer members"),
    _printed("(24)", L24, sp.Eq(P_d, C / _W * INT_S + Q_at0 * _cos), "outer members"),
    _printed("(25)", L25, sp.Eq(K, P_d / ((m2 * P_at0 + m1 * Q_at0) / (m1 + m2))),
             "outer members"),
    _printed("(25), via S(0)", L25, sp.Eq(K, P_d / (m1 * m2 / (m1 + m2) * S_at0)),
             "first equality"),
    _printed("(26)", L26, sp.Eq(K1, C / _W * INT_S / ((m2 * P_at0 + m1 * Q_at0)
                                                      / (m1 + m2)))),
    _printed("(27)", L27, sp.Eq(K2, C / _W * (INT_S + Q_at0 * _cos)
                                / ((m2 * P_at0 + m1 * Q_at0) / (m1 + m2))),
             "the factor C/Ω stands before the whole fraction, so it multiplies "
             "Q(0) cos Ωt as well; (24) has it on the integral only"),
    _printed("(28)", L28, sp.Eq(P, (m1 + m2) * a + m2 * g),
             "first line: the drive pulls the full weight m2 g from t = 0 while the "
             "load still rests on the ground (Q < m2 g for t < τ_0); the rigid-hoist "
             "law, the paper's own (55), gives (m1 + m2)·a_i + Q(t)", kind=ASSUMPTION),
    _printed("(28), P(0)", L28, sp.Eq(P_at0, (m1 + m2) * a_at0 + m2 * g),
             "second line; with Q(0) = 0 the rigid-hoist law gives (m1 + m2)·a_i(0)",
             kind=ASSUMPTION),
    _printed("(28), Q(0)", L28, sp.Eq(Q_at0, 0),
             "reconstructed: the OCR reads 'Q(t) = 0.' and then the two branches "
             "without their left-hand side; read as Q(0) = 0 and Q(t) = {...}, the "
             "only reading consistent with (29) and the text after it",
             reconstructed=True),
    _printed("(28), Q(t)", L28, sp.Eq(Q, Q_0 * t / tau0),
             "reconstructed (see (28), Q(0)): Q(t) = Q_0 t/τ_0 for 0 ≤ t ≤ τ_0",
             reconstructed=True),
    _printed("(28), Q(t), t ≥ τ_0", L28, sp.Eq(Q, Q_0),
             "reconstructed (see (28), Q(0)): Q(t) = Q_0 for t ≥ τ_0",
             reconstructed=True),
    _printed("(28), Q_0", r"Q_0 = m_2 g", sp.Eq(Q_0, m2 * g), "text after (28)"),
    _printed("(29)", L29, sp.Eq(tau0, m2 * g / (C * v0))),
    _printed("(30), a_1", L30, sp.Eq(A_LAW[1], v0 / t_n), kind=ASSUMPTION),
    _printed("(30), a_2", L30, sp.Eq(A_LAW[2], v0 / t_n * (1 - t / t_n)),
             "this a_2 brings the drive to v0/2 only by t_п (step '(30), speed of "
             "a_2'), while the text says t_п is the duration of the start to the steady "
             "speed v0; the steps after (30) use the law as printed", kind=ASSUMPTION),
    _printed("(30), a_3", L30, sp.Eq(A_LAW[3], 12 * v0 * t / t_n ** 2 * (1 - t / t_n) ** 2),
             kind=ASSUMPTION),
    _printed("(30), a_4", L30, sp.Eq(A_LAW[4], 60 * v0 / t_n * (t / t_n) ** 2
                                     * (1 - t / t_n) ** 3), kind=ASSUMPTION),
    _printed("(31)", L31, sp.Eq(P, (m1 + m2) * a + m2 * g), "first line"),
    _printed("(31), P(0)", L31, sp.Eq(P_at0, (m1 + m2) * a_at0 + m2 * g), "second line"),
    _printed("(31), Q", L31, sp.Eq(Q, m2 * g), "third line, outer members"),
    _printed("(31), Q(0)", L31, sp.Eq(Q_at0, m2 * g), "third line, Q(0) = m2 g"),
    _printed("S(t) after (31)", L_S, sp.Eq(S, P / m1 + Q / m2), "unnumbered",
             compare_to="(2), S(t)"),
    _printed("(32)", L32, sp.Eq(x.diff(t, 2) + _W ** 2 * x, Pbar / m)),
    _printed("(32), P̄", L32b, sp.Eq(Pbar, S * m), "unnumbered line after (32)"),
    _printed("(32), m", L32b, sp.Eq(m, m1 * m2 / (m1 + m2)), "unnumbered line after (32)"),
    _printed("(33)", L33, sp.Eq(x, x0 * _cos + x0_dot * _sin / _W + INT_P / (_W * m)),
             "x_0 cos Ω·t read as x_0 cos(Ωt)"),
    _printed("(34)", L34, sp.Eq(x_s, INT_P_REV / (_W * m)), "outer members"),
    _printed("(34), via Y", L34, sp.Eq(x_s, INT_P_Y16),
             "first equality, with Y of (16)", compare_to="(34)",
             conventions=(Convention(_FORCE_Y, sp.Eq(x_s, INT_P_YF)),)),
    _printed("Y in (33)–(49)", L16, sp.Eq(Y, _sin / _W),
             "whole-paper remark: (16) defines Y as the response to a unit impulse of "
             "S (m/s² · s); (34), (39), (43), (44), (48), (49) use the same name for the "
             "response to a unit impulse of the force P̄ = m S, smaller by the factor m",
             compare_to="Y per unit force", kind=ASSUMPTION),
    _printed("(35)", L35, sp.Eq(x, Pbar0 / (m * _W ** 2) * (1 - _cos)),
             "cos Ω t read as cos(Ωt)"),
    _printed("m Ω² = C (after (35))", r"m \cdot \Omega^2 = C", sp.Eq(m * _W ** 2, C),
             "text after (35)"),
    _printed("x_ст (after (35))", r"\bar{P}_0 / (m\Omega^2) = x_{\text{ст}}",
             sp.Eq(x_st, Pbar0 / (m * _W ** 2)), "text after (35)"),
    _printed("(36)", L36, sp.Eq(x, 2 * Pbar0 / (m * _W ** 2) * sp.sin(_W * t / 2) ** 2)),
    _printed("(37)", L37, sp.Eq(K, C * x / (C * x_st)), "first member"),
    _printed("(37), second line", L37b, sp.Eq(K, x / x_st),
             "unnumbered line repeating (37)", compare_to="(37)"),
    _printed("(38)", L38, sp.Eq(K, 2 * sp.sin(_W * t / 2) ** 2), "Ω(t) read as Ωt"),
    _via_y("(39)", L39a, k * _Y2, k * _Y2m, "(39)",
           "x = ∫ k(t − θ) Y(θ) dθ = k Y_2(t) with Y_2 of the next line; the "
           "integral evaluated by SymPy"),
    _printed("(39), Y_2", L39b, sp.Eq(Y2, sp.integrate((t - vt) * sp.sin(_W * vt) / _W,
                                                      (vt, 0, t))),
             "Y of (16); evaluated by SymPy. The text then defines Y_2 again as "
             "∫ Y_1 with Y_1 = ∫ Y: the two agree", compare_to="Y_2 (after (39))"),
    _printed("(40)", L40, sp.Eq(x, k * t / C * (1 - _sin / (_W * t))), "outer members"),
    _printed("(40), in m and Ω", L40, sp.Eq(x, k * t / (m * _W ** 2)
                                            * (1 - _sin / (_W * t))), "first equality"),
    _printed("(41)", L41, sp.Eq(x_st, k * t_n / C),
             "the text calls x_ст 'the displacement at t = t_п'; it is the static "
             "deflection under the load reached at t_п"),
    _printed("(42)", L42, sp.Eq(K, t / t_n * (1 - _sin / (_W * t)))),
    _printed("(43)", L43, sp.Eq(x, Pbar0 / C * (1 - _cos)), "outer members"),
    _via_y("(43), via Y_1", L43, Pbar0 * _Y1, Pbar0 * _Y1m, "(43), in m and Ω",
           "first equality"),
    _printed("(44)", L44, sp.Eq(x, 2 * Pbar0 / C * _half
                                * sp.sin(_W * (t - theta / 2))), "last member"),
    _printed("(44), middle", L44, sp.Eq(x, Pbar0 / C * (sp.cos(_W * (t - theta)) - _cos)),
             "second member", compare_to="(44)"),
    _via_y("(44), via Y_1", L44, Pbar0 * (_Y1 - _Y1.subs(t, t - theta)),
           Pbar0 * (_Y1m - _Y1m.subs(t, t - theta)), "(44), in m and Ω",
           "first member"),
    _printed("x_ст (before (45))", r"x_{ст} = \frac{\bar{P}_0}{C}",
             sp.Eq(x_st, Pbar0 / C), "text before (45)"),
    _printed("(45)", L45, sp.Eq(K, 2 * sp.sin(_W * t / 2) ** 2), "outer members"),
    _printed("(45), middle", L45, sp.Eq(K, 1 - _cos), "first equality",
             compare_to="(45)"),
    _printed("(46)", L46, sp.Eq(K, 2 * _half * sp.sin(_W * (t - theta / 2)))),
    _printed("half period (before (47))", r"\theta > \pi/\Omega",
             sp.Eq(theta_half, sp.pi / _W),
             "text before (47): a pulse longer than half a period (θ > π/Ω) gives its "
             "maximum while it acts"),
    _printed("x_max for θ ≥ π/Ω (before (47))", L47a, sp.Eq(x_max, 2 * Pbar0 / C),
             "text before (47), for θ > π/Ω, first equality"),
    _printed("x_max for θ ≥ π/Ω, in x_ст", L47a, sp.Eq(x_max, 2 * x_st),
             "text before (47), for θ > π/Ω, second equality"),
    _printed("(47)", L47, sp.Eq(x_max, 2 * Pbar0 / C * _half),
             "first equality; stated for pulses shorter than half a period, θ < π/Ω"),
    _printed("(47), in x_ст", L47, sp.Eq(x_max, 2 * x_st * _half),
             "second member; θ < π/Ω"),
    _printed("(48)", L48, sp.Eq(x, Pbar0 / (m * _W ** 3 * theta) * (_W * t - _sin)),
             "outer members"),
    _via_y("(48), via Y_2", L48, Pbar0 / theta * _Y2, Pbar0 / theta * _Y2m, "(48)",
           "first equality"),
    _printed("(49)", L49, sp.Eq(x, Pbar0 / (m * _W ** 3 * theta) * (
        _W * theta - _sin + sp.sin(_W * (t - theta)))), "outer members"),
    _via_y("(49), via Y_2", L49, Pbar0 / theta * (_Y2 - _Y2.subs(t, t - theta)),
           Pbar0 / theta * (_Y2m - _Y2m.subs(t, t - theta)), "(49)", "first equality"),
    _printed("(50)", L50, sp.Eq(x, x_st * (1 - 2 * sp.cos(_W * (t - theta / 2)) * _half
                                           / (_W * theta))),
             "reconstructed: the OCR's x_{cr} is x_ст", reconstructed=True),
    _printed("(50), x_ст", L50b, sp.Eq(x_st, Pbar0 / (m * _W ** 2)),
             "reconstructed: the OCR's x_{cr} is x_ст", reconstructed=True),
    _printed("(51)", L51, sp.Eq(K, (_W * t - _sin) / (_W * theta))),
    _printed("(52)", L52, sp.Eq(K, 1 - 2 * sp.cos(_W * (t - theta / 2)) * _half
                                / (_W * theta))),
    _printed("(53)", L53, sp.Eq(d_max, 2 * _half / (_W * theta)),
             "reconstructed: the OCR's x_{cr} and x_{cm} are x_ст. The maximum over t "
             "of −2 cos(...)·sin(Ωθ/2)/(Ωθ) is 2|sin(Ωθ/2)|/(Ωθ); the print holds for "
             "Ωθ ≤ 2π only and turns negative beyond", reconstructed=True),
    _printed("(54)", L54, sp.Eq(x2.diff(t, 4) + _W ** 2 * x2.diff(t, 2),
                                (P - Q) / (m1 * m2 / C)),
             "the term −Q̈/m2 is missing: (54) follows from (1) only where Q is linear "
             "in t, which the paper assumes later, at (60)"),
    _printed("(55)", L55, sp.Eq(P, (m1 + m2) * a + Q)),
    _printed("(56)", L56, sp.Eq(x2.diff(t, 4) + _W ** 2 * x2.diff(t, 2), _W ** 2 * a),
             "inherits the missing −Q̈/m2 of (54)"),
    _printed("(57)", L57, sp.Eq(k_d, (m2 * x2.diff(t, 2) + Q) / (m2 * v0 / t_n)),
             "first member"),
    _printed("(57), rope force", L57, sp.Eq(k_d, C * (x1 - x2) / (m2 * v0 / t_n)),
             "second member"),
    _printed("K_дин normalisations", r"\left(m_2 \cdot \frac{v_0}{t_n} \right)",
             sp.Eq(F_ref, m2 * v0 / t_n),
             "whole-paper remark: one name, three references. (25) divides the rope "
             "force by the rigid hoist's rope force at t = 0, m2(a_i(0) + g) when "
             "lifting from weight; (37) by the static force C x_ст of the load case; "
             "(57)–(64) by m2 v0/t_п, which leaves the weight out of the reference but "
             "not out of the force, so k̃ of (64) reaches 1 + g t_п/v0 at τ_0 (20 to 80 "
             "in Table 2): the 'very large values' of conclusion 3",
             compare_to="reference of (25), from weight", kind=ASSUMPTION),
    _printed("(58)", L58, None,
             not_checkable="a criterion to be minimised (⇒ min), not a relation; its "
             "Euler–Poisson equation (59) is checked"),
    _printed("(59)", L59, sp.Eq(x2.diff(t, 4) * m2 + Q.diff(t, 2), 0)),
    _printed("Q̈ ≡ 0 (before (60))", r"\ddot{Q}(t) \equiv 0", sp.Eq(Q.diff(t, 2), 0),
             "text before (60), on each piece of Q", compare_to="Q̈ = 0 (before (60))"),
    _printed("Q̈ ≡ 0 at τ_0", r"\ddot{Q}(t) \equiv 0", sp.Eq(dQdot_tau0, 0),
             "text before (60): 'for any method of lifting'. With pick-up Q̇ jumps at "
             "τ_0, so Q̈ is a delta there and (60) holds on each side of τ_0 only",
             compare_to="Q̇ at τ_0 (before (60))", kind=ASSUMPTION),
    _printed("(60)", L60, sp.Eq(x2.diff(t, 4), 0)),
    _printed("(61)", L61, sp.Eq(x2.diff(t, 2), a), "the conclusion after ⇔"),
    *[_printed(f"(61), i = {i}", L61, sp.Eq(x2.diff(t, 4), 0),
               f"the ⇔ of (61) for the law a_{i}: ẍ2 = a_{i} must leave x2^(IV) = 0. "
               + (f"It does: a_{i} is linear in t." if i < 3 else
                  f"It does not: ä_{i} ≠ 0, so (56) and (60) have no common solution "
                  f"for a_{i}, and (65), i = {i} is no extremal of (58)"),
               compare_to=f"(61), i = {i}", kind=ASSUMPTION) for i in range(1, 5)],
    _printed("(62)", L62, sp.Eq(k_d, (m2 * a + Q) / (m2 * v0 / t_n))),
    _printed("(63)", L63, sp.Eq(kt_d, m2 * a / (m2 * v0 / t_n)), "lifting from weight"),
    _printed("(64)", L64, sp.Eq(kt_d, (m2 * a + m2 * g * t / tau0) / (m2 * v0 / t_n)),
             "first line, with pick-up, 0 ≤ t ≤ τ_0"),
    _printed("(64), τ_0 < t", L64, sp.Eq(kt_d, m2 * a / (m2 * v0 / t_n)), "second line"),
    _printed("(64), jump at τ_0", r"\tilde{k}_{\text{дин}}(t)", sp.Eq(dk_tau0, 0),
             "text before (63): k̃ is introduced as 'accounting only for the changes in "
             "the dynamic component of the rope force' (який враховує лише зміни у "
             "динамічній складовій пружної сили у канаті), which is continuous at τ_0; "
             "(64) keeps the weight before τ_0 and drops it after, a jump of g t_п/v0",
             kind=ASSUMPTION),
    _printed("(65), i = 1", L65, sp.Eq(K_OPT[1], 1)),
    _printed("(65), i = 2", L65, sp.Eq(K_OPT[2], 1 - t / t_n)),
    _printed("(65), i = 3", L65, sp.Eq(K_OPT[3], 12 * t / t_n * (1 - t / t_n) ** 2)),
    _printed("(65), i = 4", L65, sp.Eq(K_OPT[4], 60 * (t / t_n) ** 2 * (1 - t / t_n) ** 3)),
    *[_printed(f"(66), i = {i}", L66, sp.Eq(K_OPT[i], law + g * t / (tau0 * (v0 / t_n))))
      for i, law in ((1, sp.Integer(1)), (2, 1 - t / t_n),
                     (3, 12 * t / t_n * (1 - t / t_n) ** 2),
                     (4, 60 * (t / t_n) ** 2 * (1 - t / t_n) ** 3))],
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


PUBLISHED += [
    _printed("t3* (after (66))", r"t_3^* = \frac{1}{3}t_n", sp.Eq(t3_star, t_n / 3),
             "text after (66)"),
    _cell("max k̃3 (after (66))", "1,7778", "text after (66)", symbol=k3_max,
          latex=L_MAX3),
    _printed("t4* (after (66))", r"t_4^* = 0,4t_n",
             sp.Eq(t4_star, sp.Rational(2, 5) * t_n), "text after (66)"),
    _cell("max k̃4 (after (66))", "2,0736",
          "text after (66): printed as k̃_дин3, in the sentence about the maximum "
          "of k̃_дин4", symbol=k3_max, latex=L_MAX4,
          conventions=(Convention("the subscript 3 of the second maximum is a slip "
                                  "for 4", sp.Eq(k4_max, sp.Rational(20736, 10000))),)),
]

TABLE1 = {2: ("1,0", "0,75", "0,5", "0,25", "0"),
          3: ("0", "1,6875", "1,500", "0,5625", "0"),
          4: ("0", "1,5820", "1,8750", "0,5273", "0")}

# Rows in printed order k1, k3, k2, k4; blocks (v0, t_п) = (0.25, 1), (0.25, 2),
# (0.50, 1), (0.50, 2); columns 0, 0.25, 0.5, 0.75, 1.0.
TABLE2 = {
    1: (("1,000", "10,810", "20,620", "30,430", "40,240"),
        ("1,000", "20,620", "40,240", "59,860", "79,480"),
        ("1,000", "5,905", "10,810", "15,715", "20,620"),
        ("1,000", "10,810", "20,620", "30,430", "40,240")),
    3: (("1,012", "10,822", "20,632", "30,442", "40,252"),
        ("1,006", "20,626", "40,246", "59,8662", "79,486"),
        ("1,012", "5,917", "10,822", "15,727", "20,632"),
        ("1,006", "10,816", "20,626", "30,436", "40,246")),
    2: (("0,999", "10,809", "20,619", "30,429", "40,239"),
        ("0,9995", "20,6195", "40,2395", "59,8595", "79,4795"),
        ("0,999", "5,904", "10,809", "15,714", "20,619"),
        ("0,9995", "10,8095", "20,6195", "30,4295", "40,2395")),
    4: (("1,000", "10,810", "20,620", "30,430", "40,240"),
        ("1,000", "20,620", "40,240", "59,860", "79,480"),
        ("1,000", "5,905", "10,810", "15,715", "20,620"),
        ("1,000", "10,81", "20,620", "30,430", "40,240")),
}
#: Table 2 cells that (66) misses, and what they are instead.
TABLE2_NOTES = {
    3: "k̃_дин3 and k̃_дин4 of Table 2 are 1 + (66): the table adds 1 to both rows",
    4: "k̃_дин3 and k̃_дин4 of Table 2 are 1 + (66): the table adds 1 to both rows",
}

PUBLISHED += [_cell(table1_label(i, frac), text, "Table 1, from (65)")
              for i, row in TABLE1.items() for frac, text in zip(TABLE_COLUMNS, row)]
PUBLISHED += [
    _printed("Table 2, columns", r"\frac{t}{t_{\text{п}}}", sp.Eq(col, t / t_n),
             "Table 2 header; the caption says t ∈ [0, τ_0]", compare_to="Table 2, columns",
             kind=ASSUMPTION),
    _printed("Table 2, a_i term", r"t \in [0, \tau_0]", sp.Eq(t_a, t),
             "Table 2 caption: each cell is (66) at one instant t, in both terms",
             kind=ASSUMPTION),
]
PUBLISHED += [
    _cell(table2_label(i, speed, duration, frac), text,
          "Table 2, from (66)" + (f"; {TABLE2_NOTES[i]}" if i in TABLE2_NOTES else "")
          + ("; the printed 59,8662 has one digit too many: 1 + (66) is 59.865994"
             if text == "59,8662" else ""))
    for i in TABLE2_ROWS
    for (speed, duration), row in zip(TABLE2_BLOCKS, TABLE2[i])
    for frac, text in zip(TABLE_COLUMNS, row)
]
