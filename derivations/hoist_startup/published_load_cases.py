"""Published formulas of paper 002, transcribed as printed: the load cases (32)–(53).

See ``published`` for the conventions of the transcription.
"""
from __future__ import annotations

import sympy as sp

from crane_sym.readings import Scaled

from crane_sym.published import (ASSUMPTION, DEFINITION, SYMBOL_FOR_ANOTHER, Cause, Convention,
                                 PublishedFormula)

from .model import (INT_P, INT_P_REV, INT_P_Y16, K, Pbar, Pbar0, S, C, Y, Y2,
                    d_max, k, m, m1, m2, t, t_n, theta, theta_half, vt, x, x0, x0_dot,
                    x_max, x_s, x_st)
from .published import L16, _W, _cos, _printed, _sin

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

_half = sp.sin(_W * theta / 2)
_FORCE_Y = ("from (33) on, Y is the response to a unit impulse of the force P̄, "
            "sin(Ωt)/(mΩ), and Y_1, Y_2 its integrals — not Y of (16)")


Y_TWO_MEANINGS = Cause("002-Y-two-meanings", "from (33) on the paper uses the name Y "
                       "of (16) (unit impulse of S) for the response to a unit impulse of "
                       "the force P̄, which is smaller by the mass m")


#: How (39) is transcribed where its print keeps Y(θ) under the integral.
_Y_OUT = "Y(θ) of (16) written out under the integral, and the integral evaluated"


#: Y per unit force is Y of (16) over m, and a member written with Y, Y_1 or Y_2
#: is linear in it: the reading is the transcription over m.
_PER_FORCE = Convention(_FORCE_Y, Scaled(1 / m), SYMBOL_FOR_ANOTHER)


def _via_y(label: str, latex: str, printed_with_16, target: str,
           note: str, read_as: str = "") -> PublishedFormula:
    """A member written with Y, Y_1 or Y_2: as printed Y is that of (16)."""
    return _printed(label, latex, sp.Eq(x, printed_with_16), note,
                    compare_to=target, read_as=read_as, conventions=(_PER_FORCE,),
                    cause=Y_TWO_MEANINGS)


def _y_integrals(scale):
    """Y_1, Y_2 of the text after (39) for Y = sin(Ωt)/(Ω·scale)."""
    y = sp.sin(_W * vt) / (_W * scale)
    y1 = sp.integrate(y, (vt, 0, t))
    y2 = sp.integrate(y1.subs(t, vt), (vt, 0, t))
    return y1, y2


_Y1, _Y2 = _y_integrals(1)            # Y of (16)

PUBLISHED = [
    _printed("(32)", L32, sp.Eq(x.diff(t, 2) + _W ** 2 * x, Pbar / m)),
    _printed("(32), P̄", L32b, sp.Eq(Pbar, S * m), "unnumbered line after (32)",
             basis=DEFINITION, basis_note="the line defines P̄"),
    _printed("(32), m", L32b, sp.Eq(m, m1 * m2 / (m1 + m2)), "unnumbered line after (32)"),
    _printed("(33)", L33, sp.Eq(x, x0 * _cos + x0_dot * _sin / _W + INT_P / (_W * m)),
             "x_0 cos Ω·t read as x_0 cos(Ωt)",
             read_as="x_0 cos Ω·t read as x_0 cos(Ωt): the dot leaves the scope of cos "
             "open (operator scope), and cos of a frequency alone has no meaning"),
    _printed("(34)", L34, sp.Eq(x_s, INT_P_REV / (_W * m)), "outer members"),
    _printed("(34), via Y", L34, sp.Eq(x_s, INT_P_Y16),
             "first equality, with Y of (16)", compare_to="(34)",
             conventions=(_PER_FORCE,),
             cause=Y_TWO_MEANINGS),
    _printed("Y in (33)–(49)", L16, sp.Eq(Y, _sin / _W),
             "whole-paper remark: (16) defines Y as the response to a unit impulse of "
             "S (m/s² · s); (34), (39), (43), (44), (48), (49) use the same name for the "
             "response to a unit impulse of the force P̄ = m S, smaller by the factor m",
             compare_to="Y per unit force", kind=ASSUMPTION,
             stated='"де Y(t) – реакція системи на одиничний імпульс" (16) ("Y(t), the '
             'response of the system to a unit impulse"), the name (33)–(49) use',
             cause=Y_TWO_MEANINGS),
    _printed("(35)", L35, sp.Eq(x, Pbar0 / (m * _W ** 2) * (1 - _cos)),
             "cos Ω t read as cos(Ωt)"),
    _printed("m Ω² = C (after (35))", r"m \cdot \Omega^2 = C", sp.Eq(m * _W ** 2, C),
             "text after (35)"),
    _printed("x_ст (after (35))", r"\bar{P}_0 / (m\Omega^2) = x_{\text{ст}}",
             sp.Eq(x_st, Pbar0 / (m * _W ** 2)), "text after (35)"),
    _printed("(36)", L36, sp.Eq(x, 2 * Pbar0 / (m * _W ** 2) * sp.sin(_W * t / 2) ** 2)),
    _printed("(37)", L37, sp.Eq(K, C * x / (C * x_st)), "first member",
             basis=DEFINITION, basis_note="(37) defines K_дин of the load cases"),
    _printed("(37), second line", L37b, sp.Eq(K, x / x_st),
             "unnumbered line repeating (37)", compare_to="(37)",
             basis=DEFINITION, basis_note="(37) defines K_дин of the load cases"),
    _printed("(38)", L38, sp.Eq(K, 2 * sp.sin(_W * t / 2) ** 2), "Ω(t) read as Ωt"),
    _via_y("(39)", L39a, k * _Y2, "(39)",
           "x = ∫ k(t − θ) Y(θ) dθ = k Y_2(t) with Y_2 of the next line; the "
           "integral evaluated by SymPy", read_as=_Y_OUT),
    _printed("(39), Y_2", L39b, sp.Eq(Y2, sp.integrate((t - vt) * sp.sin(_W * vt) / _W,
                                                      (vt, 0, t))),
             "Y of (16); evaluated by SymPy. The text then defines Y_2 again as "
             "∫ Y_1 with Y_1 = ∫ Y: the two agree", compare_to="Y_2 (after (39))",
             read_as=_Y_OUT),
    _printed("(40)", L40, sp.Eq(x, k * t / C * (1 - _sin / (_W * t))), "outer members"),
    _printed("(40), in m and Ω", L40, sp.Eq(x, k * t / (m * _W ** 2)
                                            * (1 - _sin / (_W * t))), "first equality"),
    _printed("(41)", L41, sp.Eq(x_st, k * t_n / C),
             "the text calls x_ст 'the displacement at t = t_п'; it is the static "
             "deflection under the load reached at t_п"),
    _printed("(42)", L42, sp.Eq(K, t / t_n * (1 - _sin / (_W * t)))),
    _printed("(43)", L43, sp.Eq(x, Pbar0 / C * (1 - _cos)), "outer members"),
    _via_y("(43), via Y_1", L43, Pbar0 * _Y1, "(43), in m and Ω",
           "first equality"),
    _printed("(44)", L44, sp.Eq(x, 2 * Pbar0 / C * _half
                                * sp.sin(_W * (t - theta / 2))), "last member"),
    _printed("(44), middle", L44, sp.Eq(x, Pbar0 / C * (sp.cos(_W * (t - theta)) - _cos)),
             "second member", compare_to="(44)"),
    _via_y("(44), via Y_1", L44, Pbar0 * (_Y1 - _Y1.subs(t, t - theta)), "(44), in m and Ω",
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
    _via_y("(48), via Y_2", L48, Pbar0 / theta * _Y2, "(48)",
           "first equality"),
    _printed("(49)", L49, sp.Eq(x, Pbar0 / (m * _W ** 3 * theta) * (
        _W * theta - _sin + sp.sin(_W * (t - theta)))), "outer members"),
    _via_y("(49), via Y_2", L49, Pbar0 / theta * (_Y2 - _Y2.subs(t, t - theta)), "(49)",
           "first equality"),
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
             "Ωθ ≤ 2π only and turns negative beyond", reconstructed=True,
             cause=Cause("002-53-abs", "(53) gives the amplitude as 2 sin(Ωθ/2)/(Ωθ), "
                         "which is negative for 2π < Ωθ < 4π, …; the amplitude is "
                         "2|sin(Ωθ/2)|/(Ωθ)")),
]
