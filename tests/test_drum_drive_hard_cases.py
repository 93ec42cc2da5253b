"""Paper 004's generated functions on hard cases: mpmath references on the
seeded grids of ``drum_drive.hard_cases``, and properties of the generated
system matrices and state derivative over parameter ratios 1e-8 … 1e8
(symmetry, definiteness, energy balance, the Jacobian's block structure)."""
import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import crane_sym.generated.drum_drive as gen
from crane_sym.derivations.drum_drive.hard_cases import hard_cases
from crane_sym.bench.accuracy import accuracy

EPS = np.finfo(float).eps

# Worst relative error allowed per function, in units of eps: a few roundings
# for the well-conditioned ones; the rest are checked against their condition
# number below.
WELL_CONDITIONED = {"branch_effective_mass": 2, "drive_chain_frequency_1": 6,
                    "drive_chain_frequency_2": 6, "running_tight_force": 4,
                    "drum_torque": 2}


DERIVATION = "drum_drive"


@pytest.fixture(scope="module")
def cases():
    return hard_cases(points=120)


@pytest.mark.parametrize("name", sorted(WELL_CONDITIONED))
def test_well_conditioned_functions_to_a_few_ulp(derivation, cases, name):
    out = derivation.output(name)
    for case, columns in cases.items():
        row = accuracy(out, getattr(gen, name), case, columns)
        assert row.max_rel_error <= WELL_CONDITIONED[name] * EPS, (case, row)


@pytest.mark.parametrize("name", ["running_slack_force", "running_drum_shaft_deflection",
                                  "traction_margin", "least_mu_alpha", "pulsating_force"])
def test_cancelling_functions_within_their_condition_bound(derivation, cases, name):
    """Each point within max(1e-15, 2·cond·u) (``reference.accuracy``): the
    error that rounding the inputs alone allows."""
    out = derivation.output(name)
    for case, columns in cases.items():
        row = accuracy(out, getattr(gen, name), case, columns)
        assert row.excess <= 1.0, (case, row)


def test_nearly_equal_chain_frequencies_are_finite_and_ordered(cases):
    cols = cases["chain frequencies nearly equal"]
    args = [cols[k] for k in ("I1", "I2", "I3", "C1", "C2")]
    w1, w2 = gen.drive_chain_frequency_1(*args), gen.drive_chain_frequency_2(*args)
    assert np.all(np.isfinite(w1)) and np.all(np.isfinite(w2))
    assert np.all(w1 <= w2)


# --- properties of the system matrices --------------------------------------------
# Six decades either way of the nominal values: inside every range the
# generated functions serve (PhysicalSymbol.serves); ratios over 12 decades.
ratio = st.floats(-6, 6).map(lambda e: 10.0 ** e)
MASS = ("I1", "I2", "I3", "m3", "m_L", "q", "L", "r")
DAMP = ("nu1", "nu2", "nu_y", "nu_z", "nu_t", "r")
STIFF = ("C1", "C2", "C_y", "C_t", "C_z", "r")
NOMINAL = {"I1": 2.0, "I2": 1.0, "I3": 50.0, "m3": 800.0, "m_L": 5e3, "q": 20.0, "L": 30.0,
           "r": 0.5, "nu1": 10.0, "nu2": 10.0, "nu_y": 1e3, "nu_z": 1e3, "nu_t": 1e3,
           "C1": 1e5, "C2": 2e5, "C_y": 1e7, "C_t": 1e6, "C_z": 1e6, "M0": 1e3, "F0": 1e4,
           "W": 2e4}


def _params(scales: dict[str, float]) -> dict[str, float]:
    return {k: v * scales.get(k, 1.0) for k, v in NOMINAL.items()}


def _scales(names):
    return st.fixed_dictionaries({k: ratio for k in names})


def _symmetric_semidefinite(A: np.ndarray, definite: bool) -> None:
    assert np.array_equal(A, A.T)
    # Scale to unit diagonal so the eigenvalue test is not swamped by the
    # largest entry (the ratios span 16 decades).
    d = np.sqrt(np.abs(np.diag(A)))
    d[d == 0] = 1.0
    w = np.linalg.eigvalsh(A / np.outer(d, d))
    assert w.min() >= -1e-10 * max(1.0, w.max())
    if definite:
        assert w.min() > 0


@settings(max_examples=60, deadline=None)
@given(_scales(MASS))
def test_mass_matrix_symmetric_positive_definite(scales):
    p = _params(scales)
    _symmetric_semidefinite(gen.mass_matrix(*(p[k] for k in MASS)), definite=True)


@settings(max_examples=60, deadline=None)
@given(_scales(DAMP))
def test_damping_matrix_symmetric_semidefinite(scales):
    p = _params(scales)
    _symmetric_semidefinite(gen.damping_matrix(*(p[k] for k in DAMP)), definite=False)


@settings(max_examples=60, deadline=None)
@given(_scales(STIFF))
def test_stiffness_matrix_symmetric_semidefinite(scales):
    p = _params(scales)
    _symmetric_semidefinite(gen.stiffness_matrix(*(p[k] for k in STIFF)), definite=False)


ALL = ("I1", "I2", "I3", "C1", "C2", "nu1", "nu2", "m3", "m_L", "C_y", "nu_y", "C_t",
       "C_z", "nu_z", "nu_t", "q", "L", "r")


@settings(max_examples=60, deadline=None)
@given(_scales(ALL + ("M0", "F0", "W")),
       st.lists(st.floats(-1, 1), min_size=10, max_size=10))
def test_state_derivative_balances_power_and_matches_the_matrices(scales, state):
    """d/dt (½ v·M·v + ½ q·K·q) = v·F − v·C·v along the generated derivative,
    and the Jacobian is [[0, I], [−M⁻¹K, −M⁻¹C]]."""
    p = _params(scales)
    s = np.array(state)
    M = gen.mass_matrix(*(p[k] for k in MASS))
    C = gen.damping_matrix(*(p[k] for k in DAMP))
    K = gen.stiffness_matrix(*(p[k] for k in STIFF))
    F = gen.generalized_forces(p["M0"], p["F0"], p["W"])[:, 0]
    q, v = s[:5], s[5:]
    rate = gen.state_derivative(*(p[k] for k in ALL), p["M0"], p["F0"], p["W"], *s)[:, 0]
    assert np.array_equal(rate[:5], v)
    a = rate[5:]
    terms = np.concatenate([v * (M @ a), v * (K @ q), v * F, v * (C @ v)])
    scale = np.sum(np.abs(terms)) + np.sum(np.abs(v * (M @ np.abs(a))))
    residual = v @ (M @ a) + q @ (K @ v) - (v @ F - v @ (C @ v))
    # M a is solved for, so the residual carries cond(M)·eps of the terms.
    assert abs(residual) <= 1e3 * np.linalg.cond(M) * EPS * scale
    J = gen.state_jacobian(*(p[k] for k in ALL))
    assert np.array_equal(J[:5, :5], np.zeros((5, 5)))
    assert np.array_equal(J[:5, 5:], np.eye(5))
    Minv = np.linalg.inv(M)
    for block, matrix in ((J[5:, :5], K), (J[5:, 5:], C)):
        tol = 1e3 * np.linalg.cond(M) * EPS * (np.abs(Minv) @ np.abs(matrix))
        assert np.all(np.abs(block + Minv @ matrix) <= tol)
