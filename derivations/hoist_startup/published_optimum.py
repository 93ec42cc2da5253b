"""Published formulas of paper 002, transcribed as printed: the optimum (54)–(66)
and the maxima stated after (66).

See ``published`` for the conventions of the transcription.
"""
from __future__ import annotations

import sympy as sp

from crane_sym.published import (ASSUMPTION, DEFINITION, INTERNAL, SYMBOL_FOR_ANOTHER, Cause,
                                 Convention)

from .model import (K_OPT, P, Q, C, F_ref, a, dQdot_tau0, dk_tau0, g, k3_max, k4_max, k_d,
                    kt_d, m1, m2, t, t3_star, t4_star, t_n, tau0, v0, x1, x2)
from .published import _W, _cell, _printed

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

MISSING_Q_DDOT = Cause("002-54-missing-Q-ddot", "(54) lacks the term −Q̈/m2 that "
                       "eliminating x1 from (1) leaves, and (56), built on it, inherits "
                       "the gap; both hold only where Q is linear in t")
NO_EXTREMAL = Cause("002-61-no-extremal", "the laws a_3, a_4 of (30) have ä ≠ 0, so "
                    "ẍ2 = a_i cannot satisfy (60), x2^(IV) = 0: (65), i = 3, 4 are no "
                    "extremals of (58)")

PUBLISHED = [
    _printed("(54)", L54, sp.Eq(x2.diff(t, 4) + _W ** 2 * x2.diff(t, 2),
                                (P - Q) / (m1 * m2 / C)),
             "the term −Q̈/m2 is missing: (54) follows from (1) only where Q is linear "
             "in t, which the paper assumes later, at (60)", cause=MISSING_Q_DDOT),
    _printed("(55)", L55, sp.Eq(P, (m1 + m2) * a + Q)),
    _printed("(56)", L56, sp.Eq(x2.diff(t, 4) + _W ** 2 * x2.diff(t, 2), _W ** 2 * a),
             "inherits the missing −Q̈/m2 of (54)", cause=MISSING_Q_DDOT),
    _printed("(57)", L57, sp.Eq(k_d, (m2 * x2.diff(t, 2) + Q) / (m2 * v0 / t_n)),
             "first member"),
    _printed("(57), rope force", L57, sp.Eq(k_d, C * (x1 - x2) / (m2 * v0 / t_n)),
             "second member", basis=DEFINITION,
             basis_note="(57) defines k_дин as the rope force over m2·v0/t_п"),
    _printed("K_дин normalisations", r"\left(m_2 \cdot \frac{v_0}{t_n} \right)",
             sp.Eq(F_ref, m2 * v0 / t_n),
             "whole-paper remark: one name, three references. (25) divides the rope "
             "force by the rigid hoist's rope force at t = 0, m2(a_i(0) + g) when "
             "lifting from weight; (37) by the static force C x_ст of the load case; "
             "(57)–(64) by m2 v0/t_п, which leaves the weight out of the reference but "
             "not out of the force, so k̃ of (64) reaches 1 + g t_п/v0 at τ_0 (20 to 80 "
             "in Table 2): the 'very large values' of conclusion 3",
             compare_to="reference of (25), from weight", kind=ASSUMPTION,
             stated="(57) as printed: k_дин(t) = {m2·ẍ2 + Q(t)}/(m2·v0/t_п), the reference "
             "the paper chooses for (57)–(64)",
             basis=INTERNAL, basis_note="(57)'s reference against (25)'s",
             cause=Cause("002-three-references", "K_дин is normalised three ways: (25) by "
                         "the rigid rope force at t = 0, (37) by C·x_ст, (57)–(64) by "
                         "m2·v0/t_п, which keeps the weight in the force but not in the "
                         "reference")),
    _printed("(58)", L58, None,
             not_checkable="a criterion to be minimised (⇒ min), not a relation; its "
             "Euler–Poisson equation (59) is checked",
             cause=Cause("002-58-criterion", "(58) states a criterion to minimise, not a "
                         "relation; what it implies is checked at (59)")),
    _printed("(59)", L59, sp.Eq(x2.diff(t, 4) * m2 + Q.diff(t, 2), 0)),
    _printed("Q̈ ≡ 0 (before (60))", r"\ddot{Q}(t) \equiv 0", sp.Eq(Q.diff(t, 2), 0),
             "text before (60), on each piece of Q", compare_to="Q̈ = 0 (before (60))"),
    _printed("Q̈ ≡ 0 at τ_0", r"\ddot{Q}(t) \equiv 0", sp.Eq(dQdot_tau0, 0),
             "text before (60): 'for any method of lifting'. With pick-up Q̇ jumps at "
             "τ_0, so Q̈ is a delta there and (60) holds on each side of τ_0 only",
             compare_to="Q̇ at τ_0 (before (60))", kind=ASSUMPTION,
             stated='"Оскільки за будь-якого способу підйому вантажу («з ваги», «з '
             'підхватом») Q̈(t) ≡ 0" ("since for any method of lifting Q̈ ≡ 0"), before (60)',
             cause=Cause("002-Q-kink-at-tau0", "with pick-up Q̇ jumps at τ_0, so Q̈ ≡ 0 "
                         "'for any method of lifting' fails there: Q̈ holds a delta")),
    _printed("(60)", L60, sp.Eq(x2.diff(t, 4), 0)),
    _printed("(61)", L61, sp.Eq(x2.diff(t, 2), a), "the conclusion after ⇔"),
    *[_printed(f"(61), i = {i}", L61, sp.Eq(x2.diff(t, 4), 0),
               f"the ⇔ of (61) for the law a_{i}: ẍ2 = a_{i} must leave x2^(IV) = 0. "
               + (f"It does: a_{i} is linear in t." if i < 3 else
                  f"It does not: ä_{i} ≠ 0, so (56) and (60) have no common solution "
                  f"for a_{i}, and (65), i = {i} is no extremal of (58)"),
               compare_to=f"(61), i = {i}", kind=ASSUMPTION,
               stated='"Співставляючи рівняння (56) та умову Ейлера-Пуассона (60), матимемо '
               '(61)" ("comparing (56) with the Euler–Poisson condition (60) we get (61)")',
               cause=None if i < 3 else NO_EXTREMAL) for i in range(1, 5)],
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
             kind=ASSUMPTION, stated='"доцільно ввести k̃_дин(t), який враховує лише зміни '
             'у динамічній складовій пружної сили у канаті" (before (63))', cause=Cause(
                 "002-64-jump", "(64) keeps the weight in k̃ before τ_0 and drops it "
                 "after, a jump of g·t_п/v0, though k̃ is said to hold only the dynamic "
                 "part of the rope force")),
    _printed("(65), i = 1", L65, sp.Eq(K_OPT[1], 1)),
    _printed("(65), i = 2", L65, sp.Eq(K_OPT[2], 1 - t / t_n)),
    _printed("(65), i = 3", L65, sp.Eq(K_OPT[3], 12 * t / t_n * (1 - t / t_n) ** 2)),
    _printed("(65), i = 4", L65, sp.Eq(K_OPT[4], 60 * (t / t_n) ** 2 * (1 - t / t_n) ** 3)),
    *[_printed(f"(66), i = {i}", L66, sp.Eq(K_OPT[i], law + g * t / (tau0 * (v0 / t_n))))
      for i, law in ((1, sp.Integer(1)), (2, 1 - t / t_n),
                     (3, 12 * t / t_n * (1 - t / t_n) ** 2),
                     (4, 60 * (t / t_n) ** 2 * (1 - t / t_n) ** 3))],
]

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
                                  "for 4", sp.Eq(k4_max, sp.Rational(20736, 10000)),
                                  SYMBOL_FOR_ANOTHER),),
          cause=Cause("002-max-k4-subscript", "the text after (66) names the maximum of "
                      "k̃_дин4 with the subscript 3")),
]
