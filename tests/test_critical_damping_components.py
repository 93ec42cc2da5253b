"""Critical damping (a Jordan pair) through the spectral clusters: exp(A t)
of x'' + 2ω x' + ω² x = 0 against its closed form, and continuous with its
neighbours at 1 ± 1e-8 and 1 ± 1e-6 of critical."""
import math

import numpy as np
import pytest

from crane_sym.mechanics.spectral_clusters import numpy_terms


def _exp(A: np.ndarray, t: float) -> np.ndarray:
    """exp(A t) from its terms; a complex λ's term carries its conjugate's too."""
    return sum((2 if lam.imag > 0 else 1) * t**j * np.exp(lam * t) * C
               for j, lam, C in numpy_terms(A)).real


def _critical(omega: float, factor: float) -> np.ndarray:
    return np.array([[0.0, 1.0], [-omega**2, -2 * factor * omega]])


@pytest.mark.parametrize("omega", [7.0710678118654755, 1.0, 30.0])
def test_exact_critical_step_response_is_the_closed_form(omega):
    A = _critical(omega, 1.0)
    for t in (0.05, 0.3, 1.0, 2.0):
        # x(0) = -1, x'(0) = 0: x = -(1 + ωt) e^{-ωt}, so 1 + x is 1 − (1 + ωt) e^{−ωt}
        x = _exp(A, t) @ np.array([-1.0, 0.0])
        closed = 1 - (1 + omega * t) * math.exp(-omega * t)
        assert 1 + x[0] == pytest.approx(closed, rel=1e-9, abs=1e-12)


@pytest.mark.parametrize("factor", [1 - 1e-6, 1 - 1e-8, 1 + 1e-8, 1 + 1e-6])
def test_exact_critical_is_continuous_with_its_neighbours(factor):
    omega, t = 7.0710678118654755, 0.4
    at = _exp(_critical(omega, 1.0), t)
    near = _exp(_critical(omega, factor), t)
    assert np.max(np.abs(near - at)) <= 10 * abs(factor - 1) * np.max(np.abs(at)) + 1e-9


def test_a_drive_train_at_exact_critical_damping_runs_between_its_neighbours(tmp_path):
    """bridge_travel.toml with the trolley's link damped exactly at 2√(c m):
    its held-bridge phases have a Jordan pair (the Schur form once refused
    it). Each peak lies on the line through the runs at 1 ± 1e-8 of critical,
    to 1e-9 of the peak."""
    from pathlib import Path

    from crane_sym.components.component_file import read_component_file
    src = (Path(__file__).parents[1] / "examples" / "drive_trains" /
           "bridge_travel.toml").read_text(encoding="utf-8")
    assert 'damping = "1.4 kN*s/m"' in src
    critical = 2 * math.sqrt(2e6 * 40e3)
    peaks = []
    for factor in (1 - 1e-8, 1.0, 1 + 1e-8):
        path = tmp_path / "critical.toml"
        path.write_text(src.replace('damping = "1.4 kN*s/m"',
                                    f'damping = "{critical * factor!r} N*s/m"'), encoding="utf-8")
        f = read_component_file(path)
        run = f.model.run(f.duration, f.body, f.speed, rest=f.rest)
        peaks.append([p.value for p in run.peaks])
    below, at, above = (np.array(p) for p in peaks)
    assert np.all(np.abs(at - (below + above) / 2) <= 1e-9 * np.abs(at))
