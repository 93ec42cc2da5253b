"""Published formulas of paper 004, transcribed as printed.

The LaTeX of each record is copied verbatim from ``004_f118c513e0426caf.txt``; a
display that makes several claims gives one record per claim (labels such as
``(10), Q2`` or ``(12), row 1``), each with the whole display. Ukrainian words
in the prints: "кг" = kg, "м" = m, "мм" = mm, "Нм" = N·m, "кН" = kN, "рад" =
rad, "с" = s, "екв" = equivalent, "T.OP." = тягового органу (traction element).

Notation. The OCR reads the drum index б as σ or δ (M_oσ, m_σ, r_σ, M_oδ) and
the Greek ν of the resistance coefficients as v; here M_oб is the driving torque
M0, m_б the drum's mass m3 and r_б the radius r. Symbols the paper uses but
never defines (φ4, x_i, the y_i, z_i of (8), (11), (12), m1, m2, C3, ν3, C_екв,
ω, ε of (12), ϑ_z) are kept as printed (``print_notation.PRINT_SYMBOLS``). A Σ is written out
term by term, since the checks do not take a Sum.

The transcriptions keep the print's errors. A ``Convention`` is a reading of the
policy (``crane_sym.published.READINGS``): it is tried only when the literal print
fails, and a reading that does not match is kept in the record as well, to show
that the print's error is more than the lost mark.

Basis. Fig. 1 (the design scheme) is lost, so the model's pairing of coordinates
and the directions of the branch forces are reconstructed (``MODEL``): a record
measured against them has the basis ``reconstructed model``. A record decided by
dimensions or by the paper's own earlier line is ``internal``; one whose derived
step restates the print (a definition, a hypothesis adopted, a textbook form) is
``definition`` and can only be ``restated``, never confirmed. Every finding has a
``Cause`` (``causes.CAUSES``); records that fail for the same reason share one.
"""
from __future__ import annotations

import sympy as sp

from crane_sym.readings import Meaning

from crane_sym.published import (
    ASSUMPTION, DEFINITION, INTERNAL, LOST_MARK, RECONSTRUCTED, SYMBOL_FOR_ANOTHER,
    Convention, PublishedFormula)

from .model import (a_v, b_v, C1, C2, C_t, C_y, C_z, F1, F2, g, I1, I2, I3, L, M0, m3, nu1, nu2,
                    nu_t, nu_y, nu_z, phi1, phi2, phi3, Phi_, Pi_, q, r, t, T_, T_el, v_xi, vy, vz,
                    xi, y, z)
from .print_notation import (C3, dA1, dA2, dA3, delta_y, DIMENSIONS, dl, dm, dot, dT, dt, dy, eps,
                             k, m1, m2, n_q, nu3, omega_f, phi4, Q1, Q2, Q3, record, s_tg, v_z,
                             vphi, xs, y_h, yp, zp)
from .causes import (C_ARM, C_COORDINATES, C_DRUM_PULL, C_KINETIC, C_MIXED_12, C_MOMENTUM,
                     C_NOTHING, C_Q1_MOMENT, C_Q2_NOT_FROM_9, C_RAYLEIGH_DOT, C_ROOT, C_RUN_FORCE,
                     C_UNDEFINED_RATES, C_VELOCITY_POTENTIAL, FIG1)
from .published_late import late_rows


# --- The displays, verbatim --------------------------------------------------------
L1 = (r"\left. \begin{aligned} \frac{d}{dt} \left(\frac{\partial T}{\partial \dot{\varphi}} "
       r"\right) - \frac{\partial T}{\partial \varphi} + \frac{\partial \Pi}{\partial "
       r"\varphi} &= Q_1 - \frac{\partial \Phi}{\partial \varphi} \\ \frac{d}{dt} "
       r"\left(\frac{\partial T}{\partial \dot{z}} \right) - \frac{\partial T}{\partial z} + "
       r"\frac{\partial \Pi}{\partial z} &= Q_2 - \frac{\partial \Phi}{\partial z} \\ "
       r"\frac{d}{dt} \left(\frac{\partial T}{\partial \dot{y}} \right) - \frac{\partial "
       r"T}{\partial y} + \frac{\partial \Pi}{\partial y} &= Q_3 - \frac{\partial "
       r"\Phi}{\partial y} \end{aligned} \right\}, \quad (1)")
L2 = (r"T = \frac{1}{2} \sum_{i=1}^3 (I_i \cdot \dot{\varphi}_i^2 + m_i \cdot \dot{x}_i^2) "
       r"+ \frac{1}{2} m_3 (\dot{y} - r \dot{\varphi}_3)^2 + T_{T.OP.}, \quad (2)")
L3 = (r"dT_{T.OP.} = \frac{dm}{2} \sqrt{\left(\frac{dz}{dt} \right)^2 + \frac{dy}{dt^2}} = "
       r"\frac{dm dl}{2 dt}. \quad (3)")
L4 = r"dm = q \cdot dl. \quad (4)"
L5 = r"v_{(z)} = \frac{dl}{dt}. \quad (5)"
L6 = r"v_{\xi} = a + b \cdot \xi. \quad (6)"
L7 = (r"\begin{aligned} T_{T.OP.} &= \int_0^{z(t)} \frac{qy^2}{2z^2} \cdot \xi^2 \sqrt{1 + "
       r"(\dot{y})^2} d\xi + \int_{z(t)}^L \frac{qy^2}{2(z-L)^2} \cdot (\xi-L)^2 \times \\ "
       r"&\times \sqrt{1 + (\dot{y})^2} d\xi + \int_0^{y(t)} \frac{qz^2}{2y^2} \cdot (\xi "
       r"\cdot \operatorname{tg} \varphi)^2 \sqrt{1 + (\dot{z})^2} d(\xi \cdot "
       r"\operatorname{tg} \varphi) + \\ &+ \int_{y(t)}^{\delta y} \frac{qz^2}{2(y-\delta "
       r"y)^2} \cdot (\xi \cdot \operatorname{tg} \varphi - \delta y)^2 \sqrt{1 + "
       r"(\dot{z})^2} d(\xi \cdot \operatorname{tg} \varphi), \end{aligned} \quad (7)")
L8 = (r"\Pi = \frac{1}{2} \sum_{i=1}^3 C_i (\dot{\varphi}_i - \dot{\varphi}_{(i+1)})^2 + "
       r"\frac{1}{2} C_y (\dot{y}_1 - \dot{y}_2)^2 + \frac{1}{2} C_z (\dot{z}_1 - "
       r"\dot{z}_2)^2 + \frac{1}{2} C_t (\dot{\varphi}_3 \cdot r_\sigma - \dot{z})^2, \quad "
       r"(8)")
L9 = (r"Q_1 = \frac{\delta A_\varphi}{\delta \varphi}; Q_2 = \frac{\delta A_{Fz}}{\delta "
       r"z}; Q_3 = \frac{\delta A_{Fy}}{\delta y}, \quad (9)")
L9b = (r"\begin{aligned} \delta \varphi > 0; y = const; z = const; & \quad \delta A_1 = "
       r"(M_{o\sigma} - m_\sigma g) \delta \varphi; \\ \delta y > 0; \varphi = const; y = "
       r"const; & \quad \delta A_2 = (F_1 - F_2 - C_y y) \delta y; \\ \delta z > 0; \varphi "
       r"= const; y = const; & \quad \delta A_3 = (m_3 \cdot g - C_z z) \delta z. "
       r"\end{aligned}")
L10 = (r"\left. \begin{aligned} Q_1 &= M_{o\sigma} - m_\sigma \cdot g \cdot r_\sigma; \\ Q_2 "
       r"&= (F_1 + F_2) - C_z z; \\ Q_3 &= (F_1 - F_2) - C_y y. \end{aligned} \right\} \quad "
       r"(10)")
L11 = (r"\Phi = \frac{1}{2} \sum_{i=1}^3 v_i (\dot{\varphi}_i - \dot{\varphi}_{(i+1)})^2 + "
       r"\frac{1}{2} v_y (\dot{y}_1 - \dot{y}_2)^2 + \frac{1}{2} v_z (\dot{z}_1 - "
       r"\dot{z}_2)^2 + \frac{1}{2} v_t \dot{z}^2, \quad (11)")
L12 = (r"\left. \begin{aligned} \sum_{i=1}^3 [(m_i \cdot \ddot{\varphi}_i - m_i \cdot "
       r"\ddot{y}_i) + C_i (\ddot{\varphi}_i - \ddot{\varphi}_{(i+1)})] - m_3 \ddot{y} + "
       r"\sum_{i=1}^3 v_i (\dot{\varphi}_i - \dot{\varphi}_{(i+1)}) &= \frac{M_{o\sigma}}{r} "
       r"- m_3 g; \\ \sum_{i=1}^3 [(m_i \cdot \ddot{z}_i) + C_i (\ddot{z}_i - "
       r"\ddot{z}_{(i+1)})] - m_3 \ddot{z} + \sum_{i=1}^3 v_i (\dot{z}_i - \dot{z}_{(i+1)}) "
       r"&= -(F_1 + F_2) \cdot \sin(\omega t + \varepsilon); \\ \sum_{i=1}^3 [(m_i \cdot "
       r"\ddot{y}_i) + C_i (\ddot{y}_i - \ddot{y}_{(i+1)})] + \sum_{i=1}^3 v_i (\dot{y}_i - "
       r"\dot{y}_{(i+1)}) &= (F_1 - F_2) \cdot \sin(\omega t + \varepsilon). \end{aligned} "
       r"\right\} \quad (12)")


def printed_virtual_work() -> list[tuple[str, sp.Symbol, sp.Expr]]:
    """The print's δA lines after (9), each divided by its virtual displacement
    and named by (1)'s pairing (Q1: φ, Q2: z, Q3: y): what (10) should repeat."""
    return [("(9) ⇒ Q1, as printed", Q1, M0 - m3 * g),
            ("(9) ⇒ Q2, as printed", Q2, m3 * g - C_z * z),
            ("(9) ⇒ Q3, as printed", Q3, F1 - F2 - C_y * y)]


def printed_homogeneous() -> tuple[str, sp.Eq]:
    """The print's (13) with its right-hand side set to zero: what (14) solves."""
    return ("(13) as printed, homogeneous",
            sp.Eq(dot(y_h, 2) + C3 * dot(y_h) + k**2 * y_h, 0))


def _chain(f: list, coeffs: list) -> sp.Expr:
    """Σ_{i=1}^{3} c_i (f_i − f_{i+1}) written out."""
    return sp.Add(*[c * (f[i] - f[i + 1]) for i, c in enumerate(coeffs)])


def _sum(terms) -> sp.Expr:
    return sp.Add(*terms)


LAGRANGE_FORM = (
    "(1) restates Lagrange's equations of the second kind with Rayleigh's function, a "
    "textbook form; both sides are built from the model's T, Π, Φ (the printed operator "
    "on one, the toolkit's Lagrange equations on the other), so the record tests only the printed "
    "operator, not the paper's energies")


def _lagrange_rows(e: dict) -> list[PublishedFormula]:
    T, V, R = e["T"], e["Pi"], e["Phi"]
    rows = []
    for label, qq, Q in (("(1), φ", phi3, Q1), ("(1), z", z, Q2), ("(1), y", y, Q3)):
        lhs = sp.expand(sp.diff(sp.diff(T, dot(qq)), t) - sp.diff(T, qq) + sp.diff(V, qq))
        rows.append(record(
            label, L1, sp.Eq(lhs, Q - sp.diff(R, qq)),
            "the printed operator applied to the model's T, Π, Φ of (2)–(11); the "
            "Rayleigh term is printed as ∂Φ/∂q, which is 0 since Φ has velocities only"
            + ("; φ stands for each angle and is checked for the drum's φ3" if qq is phi3
               else ""),
            conventions=(Convention(
                "∂Φ/∂q in (1) means ∂Φ/∂q̇ (the Rayleigh term)",
                sp.Eq(lhs, Q - sp.diff(R, dot(qq))), LOST_MARK),),
            basis=DEFINITION, basis_note=LAGRANGE_FORM, cause=C_RAYLEIGH_DOT))
    return rows


def _energy_rows(e: dict) -> list[PublishedFormula]:
    half = sp.Rational(1, 2)
    inertias, masses = (I1, I2, I3), (m1, m2, m3)
    T2 = (half * _sum(I * dot(p)**2 + m * dot(x)**2 for I, p, m, x in
                      zip(inertias, (phi1, phi2, phi3), masses, xs))
          + half * m3 * (dot(y) - r * dot(phi3))**2 + T_el)
    # (7) as printed; the last two integrals run over s = ξ·tg φ, the variable
    # after d(...), so their limits are values of s.
    ry, rz = sp.sqrt(1 + dot(y)**2), sp.sqrt(1 + dot(z)**2)
    seven = (sp.Integral(q * y**2 / (2 * z**2) * xi**2 * ry, (xi, 0, z))
             + sp.Integral(q * y**2 / (2 * (z - L)**2) * (xi - L)**2 * ry, (xi, z, L))
             + sp.Integral(q * z**2 / (2 * y**2) * s_tg**2 * rz, (s_tg, 0, y))
             + sp.Integral(q * z**2 / (2 * (y - delta_y)**2) * (s_tg - delta_y)**2 * rz,
                           (s_tg, y, delta_y)))
    phis = [phi1, phi2, phi3, phi4]
    dotted = seven.xreplace({y**2: dot(y)**2, z**2: dot(z)**2})
    eight = (half * _sum(C * (dot(phis[i]) - dot(phis[i + 1]))**2
                         for i, C in enumerate((C1, C2, C3)))
             + half * C_y * (dot(yp[0]) - dot(yp[1]))**2
             + half * C_z * (dot(zp[0]) - dot(zp[1]))**2
             + half * C_t * (dot(phi3) * r - dot(z))**2)
    return [
        record("(2)", L2, sp.Eq(T_, T2),
                 "x_i are not defined; m3 is the drum's mass (I_i belong to m_i), so the "
                 "drum's mass enters twice, once with ẏ − r·φ̇3",
                 basis=RECONSTRUCTED, basis_note=FIG1 + "; the derived T moves the drum by "
                 "ẏ and the loaded run (mass m_L) by ż", cause=C_KINETIC),
        record("(3)", L3, sp.Eq(dT, dm / 2 * sp.sqrt(dot(z)**2 + dy / dt**2)),
                 "first member; dy/dt² is printed, not (dy/dt)², and the root gives the "
                 "speed, not its square: the lost bracket alone does not make it an energy",
                 conventions=(Convention(
                     "(dy/dt)² for the printed dy/dt² (a bracket lost)",
                     sp.Eq(dT, dm / 2 * sp.sqrt(dot(z)**2 + dot(y)**2)), LOST_MARK),),
                 basis=INTERNAL, basis_note=DIMENSIONS, cause=C_MOMENTUM),
        record("(3), second member", L3, sp.Eq(dT, dm * dl / (2 * dt)),
                 "the last member, dm·dl/(2·dt) = dm·v/2 by (5): half a momentum",
                 compare_to="(3)", basis=INTERNAL, basis_note=DIMENSIONS, cause=C_MOMENTUM),
        record("(4)", L4, sp.Eq(dm, q * dl), basis=DEFINITION,
                 basis_note="the definition of q (mass per metre), restated by step (4)"),
        record("(5)", L5, sp.Eq(v_z, dl / dt), basis=DEFINITION,
                 basis_note="the definition of the element's speed, restated by step (5)"),
        record("(6)", L6, sp.Eq(v_xi, a_v + b_v * xi),
                 "the hypothesis of a linear speed distribution", kind=ASSUMPTION,
                 stated='"За гіпотезою про лінійний розподіл швидкостей тягового '
                 'органу" ("by the hypothesis of a linear distribution of the speeds"), '
                 'before (6)',
                 basis=DEFINITION, basis_note="the paper's hypothesis, adopted as printed "
                 "by step (6); what it implies is checked in (7)"),
        record("(7)", L7, sp.Eq(T_el, seven),
                 "the four integrals as printed, the last two over s = ξ·tg φ; the × and + "
                 "repeated at the line breaks are read once, as the typesetting repeats "
                 "them; the numerators are printed q·y², q·z² (displacements, where (3) "
                 "needs ẏ², ż²) and the root holds a velocity, √(1 + ẏ²). The lost dots "
                 "(a reading) do not suffice: the print is then the derived (7) times "
                 "√(1 + ẏ²) or √(1 + ż²), and taking the root as 1 is the model's flat "
                 "span, not a reading of the print",
                 conventions=(Convention(
                     "q·ẏ², q·ż² for the printed q·y², q·z² (dots lost)",
                     sp.Eq(T_el, dotted), LOST_MARK),),
                 basis=INTERNAL, basis_note=DIMENSIONS, cause=C_ROOT),
        record("(8)", L8, sp.Eq(Pi_, eight),
                 "Σ written out (i = 3 needs an undefined φ4); every elastic term has "
                 "velocities where displacements belong, so each carries an extra 1/s² "
                 "against Π; r_σ = r. No reading of the policy removes a dot printed "
                 "too many, and even without the dots and with (11)'s reading of φ4, y_i, "
                 "z_i the tight branch's (φ3·r − z) lacks the drum's y",
                 basis=INTERNAL, basis_note=DIMENSIONS, cause=C_VELOCITY_POTENTIAL),
    ]


def _force_rows() -> list[PublishedFormula]:
    from_nine = {lab.split(" ⇒ ")[1].split(",")[0]: lab for lab, _, _ in printed_virtual_work()}
    rows = [
        record("(9)", L9, None, not_checkable=(
            "definitions Q = δA/δq of the generalized forces (right as definitions); they "
            "pair Q2 with z and Q3 with y, while the lines that follow compute δA_2 for δy "
            "and δA_3 for δz"), basis=DEFINITION,
            basis_note="Q_i = δA_i/δq_i is the definition of a generalized force",
            cause=C_NOTHING),
        record("(9), δA_1", L9b, sp.Eq(dA1, (M0 - m3 * g) * vphi),
                 "first line after (9); m_σ (drum mass) read as m3",
                 basis=INTERNAL, basis_note=DIMENSIONS, cause=C_ARM),
        record("(9), δA_2", L9b, sp.Eq(dA2, (F1 - F2 - C_y * y) * vy),
                 "second line; its condition 'y = const' must mean z = const",
                 basis=RECONSTRUCTED, basis_note=FIG1, cause=C_DRUM_PULL),
        record("(9), δA_3", L9b, sp.Eq(dA3, (m3 * g - C_z * z) * vz),
                 "third line; C_y·y and C_z·z also stand in Π (8), so they count twice",
                 basis=RECONSTRUCTED, basis_note=FIG1, cause=C_RUN_FORCE),
    ]
    printed_q = {"Q1": (Q1, M0 - m3 * g * r), "Q2": (Q2, (F1 + F2) - C_z * z),
                 "Q3": (Q3, (F1 - F2) - C_y * y)}
    against_model = {"Q1": C_Q1_MOMENT, "Q2": C_RUN_FORCE, "Q3": C_DRUM_PULL}
    against_nine = {"Q1": C_ARM, "Q2": C_Q2_NOT_FROM_9, "Q3": None}
    for name, (sym, rhs) in printed_q.items():
        rows.append(record(f"(10), {name}", L10, sp.Eq(sym, rhs),
                             "against the model: the force of all given forces for the "
                             "coordinate (1) pairs with " + {"Q1": "φ", "Q2": "z",
                                                              "Q3": "y"}[name],
                             basis=RECONSTRUCTED, basis_note=FIG1,
                             cause=against_model[name]))
    for name, (sym, rhs) in printed_q.items():
        rows.append(record(f"(10), {name} vs (9)", L10, sp.Eq(sym, rhs),
                             "against the print's own δA line before it",
                             compare_to=from_nine[name], basis=INTERNAL,
                             basis_note="(10) against the print's own δA line after (9), "
                             "divided by its virtual displacement (step "
                             f"'{from_nine[name]}')", cause=against_nine[name]))
    return rows


def _motion_rows(e: dict) -> list[PublishedFormula]:
    half = sp.Rational(1, 2)
    phis = [phi1, phi2, phi3, phi4]
    nus, Cs, ms = [nu1, nu2, nu3], [C1, C2, C3], [m1, m2, m3]
    eleven = (half * _sum(n * (dot(phis[i]) - dot(phis[i + 1]))**2 for i, n in enumerate(nus))
              + half * nu_y * (dot(yp[0]) - dot(yp[1]))**2
              + half * nu_z * (dot(zp[0]) - dot(zp[1]))**2 + half * nu_t * dot(z)**2)
    # the undefined names given the model's meaning: the reading made from (11)
    read = Meaning(((phi4, phi3), (yp[0], y + yp[1]), (zp[0], e["e2"] + zp[1])))
    acc = [dot(p, 2) for p in phis]
    row1 = sp.Eq(_sum(ms[i] * acc[i] - ms[i] * dot(yp[i], 2) for i in range(3))
                 + _chain(acc, Cs) - m3 * dot(y, 2) + _chain([dot(p) for p in phis], nus),
                 M0 / r - m3 * g)
    forcing = sp.sin(omega_f * t + eps)
    row2 = sp.Eq(_sum(ms[i] * dot(zp[i], 2) for i in range(3))
                 + _chain([dot(f, 2) for f in zp], Cs) - m3 * dot(z, 2)
                 + _chain([dot(f) for f in zp], nus), -(F1 + F2) * forcing)
    row3 = sp.Eq(_sum(ms[i] * dot(yp[i], 2) for i in range(3))
                 + _chain([dot(f, 2) for f in yp], Cs)
                 + _chain([dot(f) for f in yp], nus), (F1 - F2) * forcing)
    note = ("Σ written out; ν printed as v; m_i multiply angular accelerations and C_i "
            "accelerations; the y_i, z_i (i ≤ 4), φ4, ω, ε are not defined")
    return [
        record("(11)", L11, sp.Eq(Phi_, eleven), "Σ written out; ν printed as v",
                 conventions=(Convention(
                     "φ4 ≡ φ3 (no fourth body), y1 − y2 ≡ y (the drum against its "
                     "bearing), z1 − z2 ≡ the slack branch's stretch z − y − r·φ3",
                     read, SYMBOL_FOR_ANOTHER),),
                 basis=RECONSTRUCTED, basis_note=FIG1 + "; the reading gives the undefined "
                 "φ4, y1 − y2, z1 − z2 the meaning they have in that reconstruction",
                 cause=C_UNDEFINED_RATES),
        *[record(f"(12), row {i}", L12, row, note + what, compare_to=target,
                   basis=INTERNAL, basis_note=DIMENSIONS, cause=C_MIXED_12)
          for i, row, what, target in (
              (1, row1, "; the row for φ, checked against the drum's equation", "(12), φ3"),
              (2, row2, "; the row for z", "(12), z"), (3, row3, "; the row for y", "(12), y"))],
    ]


def published(e: dict) -> list[PublishedFormula]:
    """Every printed formula of paper 004, in the paper's order."""
    head = [record("(1), coordinates", L1, sp.Eq(n_q, 3),
                     "(1) has three equations, for φ, z, y ('φ, z, y – відповідні "
                     "узагальнені координати'), while (2), (8), (11) use φ1, φ2, φ3",
                     basis=INTERNAL, basis_note="(1) against the paper's own (2), (8), "
                     "(11), which use φ1, φ2, φ3, y, z: the model's five coordinates",
                     cause=C_COORDINATES)]
    return (head + _lagrange_rows(e) + _energy_rows(e) + _force_rows() + _motion_rows(e)
            + late_rows())
