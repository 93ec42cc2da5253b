"""A support with its own mass and stiffness (examples/drive_trains/girder_hoist.toml):
a [[mass]] held to the ground by an [[elastic]] link, a load lifted from it
through a rope. Its hoisting factor φ2 against the closed form of the two
modes, derived here with SymPy, and against solve_ivp with events."""
from __future__ import annotations

from pathlib import Path

import mpmath
import numpy as np
import pytest
import sympy as sp

from crane_sym.components.component_file import read_component_file
from hybrid_references import girder_reference

EXAMPLE = Path(__file__).resolve().parents[1] / "examples" / "drive_trains" / "girder_hoist.toml"
M_G, C_G, M, C, V, G = 8000.0, 2.0e7, 10000.0, 5.0e6, 0.4, 9.81     # the example's values
DURATION = 0.4                                                      # s


def _rope_response():
    """F(t) − m g of the rope from the instant of lift-off, by the two modes:
    x'' = −M⁻¹K x (x down, deviations), x(0) = 0, ẋ(0) = (0, v) in the frame
    moving up with the rope at v; F − m g = c (x_l − x_g). Returns the
    expression in t and its symbols."""
    m_g, c_g, m, c, v, t, lam = sp.symbols("m_g c_g m c v t lambda", positive=True)
    Mm, K = sp.diag(m_g, m), sp.Matrix([[c_g + c, -c], [-c, c]])
    force = sp.Integer(0)
    for square in sp.solve((K - lam * Mm).det(), lam):
        shape = (K - square * Mm).nullspace()[0]
        weight = (shape.T * Mm * sp.Matrix([0, v]))[0] / (shape.T * Mm * shape)[0]
        force += c * (shape[1] - shape[0]) * weight * sp.sin(sp.sqrt(square) * t) / \
            sp.sqrt(square)
    return force, (m_g, c_g, m, c, v, t)


def _closed_form_peak() -> tuple[mpmath.mpf, mpmath.mpf]:
    """(time, φ2) of the largest rope force over the run: the closed form's
    stationary points (F' = 0, found from a fine grid by mpmath at 30 digits)."""
    force, (m_g, c_g, m, c, v, t) = _rope_response()
    values = {m_g: M_G, c_g: C_G, m: M, c: C, v: V}
    here = force.subs(values)
    with mpmath.workdps(30):
        f = sp.lambdify(t, here, "mpmath")
        df = sp.lambdify(t, sp.diff(here, t), "mpmath")
        grid = [DURATION * k / 4000 for k in range(4001)]
        best = max(range(4001), key=lambda k: f(grid[k]))
        when = mpmath.findroot(df, grid[best])
        assert 0 < when < DURATION
        return when, 1 + f(when) / (M * G)


@pytest.fixture(scope="module")
def run():
    read = read_component_file(EXAMPLE)
    return read.model.run(read.duration, read.body, read.speed, rest=read.rest)


def test_the_example_holds_the_values_the_test_derives_with(run):
    a = run.system.assembly
    assert [b.inertia for b in a.bodies.values()] == [M_G, M]
    assert [l.stiffness for l in a.links] == [C_G, C]


def test_phi2_against_the_two_modes_closed_form(run):
    rope = next(p for p in run.peaks if p.link == "rope")
    when, phi2 = _closed_form_peak()
    assert rope.factor == pytest.approx(float(phi2), rel=1e-9)
    assert rope.value == pytest.approx(float(phi2) * M * G, rel=1e-9)
    assert rope.time == pytest.approx(float(when), rel=1e-9)
    assert rope.static == pytest.approx(M * G, rel=1e-12)


def test_phi2_against_solve_ivp_with_events(run):
    times, extra = girder_reference(M_G, C_G, M, C, V, DURATION)
    k = int(np.argmax(extra))
    rope = next(p for p in run.peaks if p.link == "rope")
    assert 0 < k < len(times) - 1                      # an event, not an end of the run
    assert rope.value == pytest.approx(M * G + extra[k], rel=1e-9)
    assert rope.time == pytest.approx(times[k], rel=1e-9)
