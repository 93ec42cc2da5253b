"""Why the findings of paper 004 are findings: one ``Cause`` per reason.

Records that fail for the same reason share one cause (``CAUSES``, by id).
"""
from __future__ import annotations

from crane_sym.published import Cause

# --- Why the findings are findings (one Cause per reason) ---------------------------
FIG1 = ("Fig. 1 is lost: the coordinates and the directions of the branch forces are "
        "reconstructed (MODEL: both branches leave the drum toward the line)")
C_COORDINATES = Cause(
    "004-1-three-coordinates",
    "(1) has Lagrange equations for three coordinates φ, z, y only, while the paper's own "
    "T (2), Π (8) and Φ (11) depend on three separate angles φ1, φ2, φ3 besides y and z, "
    "so they need at least five.")
C_RAYLEIGH_DOT = Cause(
    "004-1-rayleigh-dot",
    "(1) prints the Rayleigh term as ∂Φ/∂q, which is zero for a Φ of velocities; read "
    "with the dot lost from q, ∂Φ/∂q̇, it is Lagrange's equation with dissipation.")
C_KINETIC = Cause(
    "004-2-undefined-translations",
    "(2) gives the masses m_i translations ẋ_i that the paper never defines and counts "
    "the drum's mass twice (in Σ m_i·ẋ_i² and in ½·m3·(ẏ − r·φ̇3)²), where the "
    "reconstructed drive moves the drum by ẏ alone and the loaded run by ż.")
C_MOMENTUM = Cause(
    "004-3-speed-not-squared",
    "(3) writes the kinetic energy of a piece dm as dm/2 times a speed, the root "
    "√(ż² + ẏ²) (with dy/dt² printed for (dy/dt)²) and dl/dt, not times its square, so "
    "both members are a momentum [kg·m/s], not an energy.")
C_ROOT = Cause(
    "004-7-velocity-in-root",
    "(7) multiplies every integrand by √(1 + ẏ²) or √(1 + ż²), a number plus a squared "
    "speed; with the dots the numerators lost (q·ẏ², q·ż² for q·y², q·z²) it is the "
    "derived (7) times these roots, which would be 1 only as the arc-length factor "
    "√(1 + slope²) of a flat span, a slope and not a velocity.")
C_VELOCITY_POTENTIAL = Cause(
    "004-8-velocities-in-potential",
    "(8) builds the potential energy from velocity differences (φ̇_i − φ̇_(i+1), "
    "ẏ1 − ẏ2, ż1 − ż2, φ̇3·r − ż) where the shafts' twists and the branches' stretches "
    "belong, so every elastic term is in J/s², not J.")
C_NOTHING = Cause(
    "004-only-a-definition",
    "The display only defines a symbol (Q_i = δA/δq_i in (9), y = y(x, t) in (15)), so "
    "it states no relation to check; what (9) defines is checked in the δA lines after "
    "it and in (10).")
C_CONTINUUM = Cause(
    "004-16-continuum-not-stated",
    "(16) sets z = ϑ_z·t for the continuum model (17) of the drum's axis, which the paper "
    "does not derive, with ϑ_z not defined, so the lumped model has nothing to compare "
    "it with.")
C_ARM = Cause(
    "004-dA1-weight-without-arm",
    "(9)'s δA_1 = (M_oб − m_б·g)·δφ subtracts the drum's weight [N] from a torque "
    "[N·m]; (10) writes the same term m_б·g·r_б, so the two lines disagree by the arm "
    "r_б.")
C_DRUM_PULL = Cause(
    "004-y-force-difference",
    "For the drum's displacement y the print takes F1 − F2, but with both branches "
    "leaving the drum toward the line (as reconstructed) both pull the drum the same "
    "way, and the force is F1 + F2.")
C_RUN_FORCE = Cause(
    "004-z-force",
    "For the run's displacement z the print has no F1 − F2 against the load resistance "
    "W: its δz line after (9) has the drum's weight m3·g, (10)'s Q2 the sum F1 + F2, and "
    "both subtract C_z·z, which the branch force F2 already holds.")
C_Q1_MOMENT = Cause(
    "004-10-Q1-weight-moment",
    "(10)'s Q1 = M_oб − m_б·g·r_б gives the drum's weight a moment about the drum's own "
    "axis, where it has none, and leaves out the moment −(F1 − F2)·r of the branch "
    "forces on the drum.")
C_Q2_NOT_FROM_9 = Cause(
    "004-10-Q2-not-from-9",
    "(10)'s Q2 = (F1 + F2) − C_z·z does not repeat the δz line after (9) it is said to "
    "follow from ('Отже'), which gives m3·g − C_z·z.")
C_UNDEFINED_RATES = Cause(
    "004-11-undefined-coordinates",
    "(11) uses φ4, y1, y2, z1, z2, which the paper never defines; read as φ3 (no fourth "
    "body), the drum's y and the slack branch's stretch z − y − r·φ3, it is the "
    "reconstructed Φ.")
C_MIXED_12 = Cause(
    "004-12-mixed-dimensions",
    "(12) puts the torsional stiffnesses C_i on acceleration differences in every row (and "
    "the torsional ν_i on linear velocities in the z and y rows, the masses m_i on "
    "angular accelerations in the φ row), so no row has terms of one dimension.")
C_STIFFNESS_ON_VELOCITY = Cause(
    "004-13-stiffness-on-velocity",
    "(13), said to neglect dissipation, has C_3·ẏ, the drum's stiffness times a "
    "velocity, beside ÿ [m/s²]; no stiffness makes that term an acceleration.")
C_K_THREE_MASSES = Cause(
    "004-13-k-three-masses",
    "(13)'s k = √(C_екв·(m1 + m2 + m3)/(m1·m2·m3)) is in 1/(kg^½·s) for any stiffness "
    "C_екв: the two-mass formula √(C·(m1 + m2)/(m1·m2)) extended to three masses keeps "
    "one mass too many in the denominator.")
C_DROPS_C3 = Cause(
    "004-14-drops-C3",
    "The homogeneous equation after (14), ÿ1 + k²·y1 = 0, drops the C_3·ẏ term of the "
    "(13) it claims to solve.")
C_BARE_SECOND = Cause(
    "004-17-bare-second-derivative",
    "(17) adds ∂²y/∂x² [1/m] to ∂⁴y/∂x⁴ [1/m³] without a coefficient, so no choice of "
    "the unstated a and b makes it consistent.")
C_SAFETY = Cause(
    "004-19-safety-factor",
    "(19) is Euler's traction limit F1 ≤ F2·e^(μα) with an unnamed safety factor 1.25 "
    "on F1, and it calls μ the element's resistance coefficient though it is the "
    "friction coefficient on the drum.")
C_TRACTION_F1 = Cause(
    "004-20-traction-named-F1",
    "(20) equates the tight-branch force F1 of (18)–(19) with the loads' resistance "
    "Σ m_i·g·μ_оп, while the run's steady balance gives F1 − F2 = Σ m_i·g·μ_оп + "
    "ν_t·v_s: the print's F1 is the traction force, without the element's running "
    "resistance ν_t·ż of (11).")
C_ZERO_STATE = Cause(
    "004-zero-state-not-at-rest",
    "The example starts from y(0) = 0, but the pretension F0 of both branches pulls the "
    "drum toward the line, so the reconstructed drive rests with its shaft deflected by "
    "2·F0·(C_t + C_z)/(C_t·C_y + 4·C_t·C_z + C_y·C_z) and the zero state is not at "
    "rest.")
#: Every cause of paper 004, by id.
C_EXAMPLE_UNSTATED = Cause(
    "004-example-unstated-parameters",
    "The example prints the motor, drum and stiffness data but takes its other parameters "
    "'by the recommendations of [2,3]' without printing them, so the amplitude it reads "
    "off Fig. 3 cannot be recomputed.")
CAUSES = {c.id: c for c in (
    C_COORDINATES, C_RAYLEIGH_DOT, C_KINETIC, C_MOMENTUM, C_ROOT, C_VELOCITY_POTENTIAL,
    C_NOTHING, C_CONTINUUM, C_ARM, C_DRUM_PULL, C_RUN_FORCE, C_Q1_MOMENT, C_Q2_NOT_FROM_9,
    C_UNDEFINED_RATES, C_MIXED_12, C_STIFFNESS_ON_VELOCITY, C_K_THREE_MASSES, C_DROPS_C3,
    C_BARE_SECOND, C_SAFETY, C_TRACTION_F1, C_ZERO_STATE, C_EXAMPLE_UNSTATED)}
