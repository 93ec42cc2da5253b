"""Published formulas of paper 004, (13)–(21) and the example's initial state,
transcribed as printed (``004_f118c513e0426caf.txt``); the conventions are
those of :mod:`.published`, which lists these records after the others.
"""
from __future__ import annotations

import sympy as sp

from crane_sym.readings import Meaning

from crane_sym.published import (ASSUMPTION, DEFINITION, INTERNAL, RECONSTRUCTED,
                                 SYMBOL_FOR_ANOTHER, Convention, PublishedFormula)

from .model import (alpha, D, F1, F1_lim, F1_t, F2, F2_t, F3_t, F4_t, F_pulse, g, K1, K2, K3, K4,
                    M0, m3, M_d, m_sum, mu, mu_op, r, t, t_3, y, y0)
from .print_notation import (a17, a_ph, A_y, b17, C3, C_ekv, DIMENSIONS, dot, k, m1, m2, record, w,
                             x_ax, y_h, y_p)
from .causes import (C_EXAMPLE_UNSTATED, C_BARE_SECOND, C_CONTINUUM, C_DROPS_C3, C_K_THREE_MASSES, C_NOTHING, C_SAFETY,
                     C_STIFFNESS_ON_VELOCITY, C_TRACTION_F1, C_ZERO_STATE, FIG1)


# --- The displays, verbatim ------------------------------------------------------
L13 = r"\ddot{y} + C_3 \dot{y} + k^2 y = \frac{M_{o\sigma}}{m_3 r} + g, \quad (13)"
L14 = r"y = y_1 + y_2, \quad (14)"
L14b = r"\ddot{y}_1 + k^2 \cdot y_1 = 0; \quad y_1 = A \cdot \sin(kt + a);"
L15 = r"y = y(x, t). \quad (15)"
L16 = r"z = \vartheta_z \cdot t. \quad (16)"
L17 = (r"\frac{\partial^4 y}{\partial x^4} + a \frac{\partial^2 y}{\partial t^2} + b "
       r"\frac{\partial^2 y}{\partial x \cdot \partial t} + \frac{\partial^2 y}{\partial "
       r"x^2} = 0. \quad (17)")
L18 = r"M_{o\delta} = (F_1 - F_2) \cdot \frac{D}{2}. \quad (18)"
L19 = r"1.25 \frac{F_1}{F_2} < e^{\mu\alpha}, \quad (19)"
L20 = r"F_1 = F_i(t) = \sum_{i=1}^m m_i(t) \cdot g \cdot \mu_{on}, \quad (20)"
L21 = (r"F'(t) = \frac{F_1(t) \cdot \sin\left(\frac{\pi t}{t_3}\right) + K_1 - \left| F_2(t) "
       r"\cdot \sin\left(\frac{\pi t}{t_3}\right) - K_2 \right|}{4} + \frac{F_3(t) \cdot "
       r"\sin\left(\frac{\pi t}{t_3}\right) + K_3 - \left| F_4(t) \cdot \sin\left(\frac{\pi "
       r"t}{t_3}\right) - K_4 \right|}{4}, \quad (21)")
LINIT = (r"z(0) = 0; y(0) = 0; \varphi(0) = 0; \dot{z}(0) = 0; \dot{y}(0) = 0; "
       r"\dot{\varphi}(0) = 0.")
LK = r"k = \sqrt{C_{екв} \cdot \frac{m_1 + m_2 + m_3}{m_1 \cdot m_2 \cdot m_3}}"


def _bracket(Fa, Ka, Fb, Kb) -> sp.Expr:
    """One bracket of (21): (Fa·sin + Ka − |Fb·sin − Kb|)/4, |X| written out."""
    x = Fb * sp.sin(sp.pi * t / t_3) - Kb
    return (Fa * sp.sin(sp.pi * t / t_3) + Ka - sp.Piecewise((x, x >= 0), (-x, True))) / 4


def late_rows() -> list[PublishedFormula]:
    """(13)–(21) and the example's initial state, as printed."""
    return [
        record("(13)", L13, sp.Eq(dot(y, 2) + C3 * dot(y) + k**2 * y, M0 / (m3 * r) + g),
                 "said to neglect dissipation, yet C3 (called the drum's stiffness) "
                 "multiplies ẏ", basis=INTERNAL, basis_note=DIMENSIONS + " (the derived "
                 "step is the model's y equation, which the print does not match either)",
                 cause=C_STIFFNESS_ON_VELOCITY),
        record("(13), k", LK, sp.Eq(k, sp.sqrt(C_ekv * (m1 + m2 + m3) / (m1 * m2 * m3))),
                 "the 'where' clause of (13)", basis=INTERNAL,
                 basis_note=DIMENSIONS + ", whatever the stiffness C_екв; the derived step "
                 "(13), k is chosen to have the printed shape (the geometric mean of the "
                 "drive chain's two frequencies) and is no evidence either way",
                 cause=C_K_THREE_MASSES),
        record("(14)", L14, sp.Eq(y, y_h + y_p), "y_1, y_2 of (14) are y_h, y_p here",
                 read_as="the print's y_1, y_2 in (14) are the homogeneous and the particular "
                 "solution (y_h, y_p), not the coordinates y_1, y_2 of (12)",
                 basis=DEFINITION, basis_note="y = y1 + y2 names the homogeneous and the "
                 "particular solution; step (14) restates it"),
        record("(14), homogeneous equation", L14b,
                 sp.Eq(dot(y_h, 2) + k**2 * y_h, 0),
                 "first member of the line after (14): the homogeneous equation of (13) "
                 "as the print states it", compare_to="(13) as printed, homogeneous",
                 basis=INTERNAL, basis_note="the print's own (13) with its right-hand side "
                 "set to zero", cause=C_DROPS_C3),
        record("(14), y1", L14b, sp.Eq(y_h, A_y * sp.sin(k * t + a_ph)),
                 "second member; A is the amplitude, a the initial phase", basis=INTERNAL,
                 basis_note="the general solution (dsolve) of the print's own homogeneous "
                 "equation ÿ1 + k²·y1 = 0, not of the model"),
        record("(15)", L15, None, not_checkable=(
            "notation: the drum's bent axis is a function y(x, t); nothing to check"),
            basis=DEFINITION, basis_note="notation for the deflection of the drum's axis",
            cause=C_NOTHING),
        record("(16)", L16, None, not_checkable=(
            "a kinematic assumption for (17), z = ϑ_z·t: the element's position moves "
            "uniformly; its z is not the lumped model's coordinate and ϑ_z is not "
            "defined"), cause=C_CONTINUUM),
        record("(17)", L17, sp.Eq(w.diff(x_ax, 4) + a17 * w.diff(t, 2)
                                    + b17 * w.diff(x_ax, t) + w.diff(x_ax, 2), 0),
                 "y(x, t) written w; a and b are not given, so they get the dimensions "
                 "that fit the first term; ∂²y/∂x² has no coefficient",
                 basis=INTERNAL, basis_note=DIMENSIONS, cause=C_BARE_SECOND),
        record("(18)", L18, sp.Eq(M_d, (F1 - F2) * D / 2), "M_oδ is the drum torque"),
        record("(19)", L19, sp.Eq(sp.Rational(5, 4) * F1_lim / F2, sp.exp(mu * alpha)),
                 "the boundary of the printed inequality, F1 at its largest value F1_lim; "
                 "1.25 is a traction safety factor the text does not name, and μ is called "
                 "the element's resistance coefficient though it is its friction on the drum",
                 kind=ASSUMPTION, stated='"При виборі натягу тягово-несучого елемента '
                 'необхідно задовольнити умову [1]" ("choosing the tension, the condition '
                 '[1] must be met"), before (19)', cause=C_SAFETY),
        record("(20)", L20, sp.Eq(F1, m_sum * g * mu_op),
                 "Σ m_i(t) written m_sum; the print calls F1 the traction force, while "
                 "(18)–(19) use it as the tight branch's force",
                 conventions=(Convention(
                     "F1 in (20) is the traction force F1 − F2 (one name for two forces)",
                     Meaning(((F1, F1 - F2),)), SYMBOL_FOR_ANOTHER),),
                 basis=RECONSTRUCTED, basis_note=FIG1 + "; the derived F1 is the run's "
                 "equation (12) in steady running, with the running resistance ν_t·ż of "
                 "(11)", cause=C_TRACTION_F1),
        record("(21)", L21, sp.Eq(F_pulse, _bracket(F1_t, K1, F2_t, K2)
                                    + _bracket(F3_t, K3, F4_t, K4)),
                 "an empirical load model, adopted by the model as step (21); |X| is written "
                 "as its definition, X for X ≥ 0 and −X otherwise, since the dimension "
                 "check does not take Abs; with F2 = F1, K2 = K1, F4 = F3, K4 = K3 it is "
                 "½·min(F1·sin, K1) + ½·min(F3·sin, K3), negative for half of each period "
                 "2·t3 (step '(21), min form')", kind=ASSUMPTION, basis=DEFINITION,
                 stated='"Дискретну пульсуючу силу можна подати у вигляді [9]" ("the '
                 'discrete pulsing force can be written as [9]"), before (21)',
                 basis_note="an empirical load model, adopted as printed by step (21); "
                 "what it implies is shown by step '(21), min form'"),
        record("initial state", LINIT, sp.Eq(y0, 0, evaluate=False),
                 "the zero initial state of the example; y(0) = 0 is checked",
                 kind=ASSUMPTION, stated='"Як початкові умови прийнято: z(0) = 0; y(0) = '
                 '0; φ(0) = 0; ..." ("taken as the initial conditions"), before Fig. 3',
                 basis=RECONSTRUCTED, basis_note=FIG1 + "; the "
                 "pretension F0 of both branches is the model's", cause=C_ZERO_STATE),
        record("Fig. 3, amplitude at most 10 mm", "амплітуда коливань вала барабана не "
               "перевищує 10 мм", None, "the text after Fig. 3, the example's one result",
               not_checkable="the example's other parameters are taken 'by the "
               "recommendations of [2,3]' and not printed (the traction element's masses "
               "and stiffness, the drum's mass and shaft stiffness), so no model of the "
               "printed data gives the amplitude", verbatim=True, cause=C_EXAMPLE_UNSTATED),
    ]
