"""Points inside the physics: defined symbols from their definitions, symbols of one
dimension a factor of 2 apart, and a mutated transcription of each paper caught by
the numeric check alone (no symbolic check run)."""
from __future__ import annotations

import math

import numpy as np
import pytest
import sympy as sp

from crane_sym import registry
from crane_sym.audit.verdicts import definitions
from crane_sym.audit.checks import FAIL, PASS, numeric_equivalence
from crane_sym.audit.sampling import SEPARATION, PointSampler, physical_definitions


def _formula(d, label):
    return next(f for f in d.published if f.label == label)


def _symbols(d, *names):
    return [d.symbols[n].expr for n in names]


def _swap(a, b):
    return lambda rel, d: rel.xreplace(dict(zip(_symbols(d, a, b), _symbols(d, b, a))))


def _sign(name):
    return lambda rel, d: rel.xreplace({d.symbols[name].expr: -d.symbols[name].expr})


def _twice(name):
    """The term holding ``name`` taken twice: M/(2c) printed as M/c."""
    def mutate(rel, d):
        sym = d.symbols[name].expr
        terms = [2 * t if t.has(sym) else t for t in sp.Add.make_args(rel.rhs)]
        return sp.Eq(rel.lhs, sp.Add(*terms), evaluate=False)
    return mutate


#: One transcription per paper and a mutation of it: a swap, a sign, a factor 2.
MUTATIONS = [
    ("travel_braking", "(13)", "swap m1 and m2", _swap("m1", "m2")),
    ("hoist_brakes", "(6), hoisting", "sign of LF", _sign("LF")),
    ("hoist_startup", "(2), S(t)", "swap m1 and m2", _swap("m1", "m2")),
    ("portal_travel", "(3)", "M_в/c for M_в/(2c)", _twice("M_v")),
    ("drum_drive", "(18)", "sign of F2", _sign("F2")),
]


@pytest.mark.parametrize("paper, label, what, mutate", MUTATIONS,
                         ids=[f"{m[0]}-{m[2]}" for m in MUTATIONS])
def test_the_numeric_check_alone_catches_a_mutation(paper, label, what, mutate):
    """The print passes the numeric check; its mutation fails it by more than 1 %
    at a sampled point, without the symbolic check."""
    d = registry.get(paper)
    f = _formula(d, label)
    derived = d.step(f.target).statement
    defs = definitions(d)
    ok = numeric_equivalence(f.printed, derived, d.symbols, definitions=defs)
    assert ok.status == PASS, ok.detail
    bad = mutate(f.printed, d)
    assert bad != f.printed, what
    caught = numeric_equivalence(bad, derived, d.symbols, tol=1e-2, definitions=defs)
    assert caught.status == FAIL, (what, caught.detail)


def test_a_defined_symbol_takes_its_definition():
    """003's M_в is the moment of the drawn loads, not a draw of its own."""
    d = registry.get("portal_travel")
    defs = physical_definitions(d.steps, d.symbols)
    M_v, psi, G_g, L_max, G_pch, x_o = _symbols(d, "M_v", "psi", "G_g", "L_max", "G_pch",
                                                "x_o")
    assert sp.simplify(defs[M_v] - (psi * G_g * L_max - G_pch * x_o)) == 0
    params = [d.symbols[s] for s in (psi, G_g, L_max, G_pch, x_o)]
    sampler = PointSampler(params, {M_v: defs[M_v]}, d.symbols)
    rng = np.random.default_rng(1)
    for _ in range(6):
        values, at = sampler.point(rng)
        v = dict(zip((psi, G_g, L_max, G_pch, x_o), values))
        assert at[M_v] == pytest.approx(float(v[psi] * v[G_g] * v[L_max] - v[G_pch] * v[x_o]))
        assert abs(at[M_v]) > 1e4      # N·m: a crane's moment, not −0.6 N·m


def test_defined_angles_stay_inside_the_physics():
    """α_tw of drawn gears is the operating angle of a real mesh (0 < α_tw < π/2)."""
    d = registry.get("portal_travel")
    defs = physical_definitions(d.steps, d.symbols)
    (a_tw,) = _symbols(d, "alpha_tw")
    params = [d.symbols[s] for s in sorted(defs[a_tw].free_symbols, key=str)]
    sampler = PointSampler(params, {a_tw: defs[a_tw]}, d.symbols)
    rng = np.random.default_rng(2)
    for _ in range(6):
        _, at = sampler.point(rng)
        assert 0 < at[a_tw] < math.pi / 2


def test_one_dimension_is_kept_a_factor_of_two_apart():
    d = registry.get("hoist_startup")
    m1, m2 = _symbols(d, "m1", "m2")
    sampler = PointSampler([d.symbols[m1], d.symbols[m2]], {}, d.symbols)
    rng = np.random.default_rng(3)
    for _ in range(20):
        (a, b), _ = sampler.point(rng)
        assert abs(math.log(a / b)) >= SEPARATION


def test_a_symbol_with_two_meanings_has_no_one_definition():
    """001's BF_SB is Table 1's factor in one step and the coordinated brake's in
    (7): no definition is taken, it is drawn from its own physical range."""
    d = registry.get("hoist_brakes")
    defs = physical_definitions(d.steps, d.symbols)
    (bf,) = _symbols(d, "BF_SB")
    assert bf not in defs and d.symbols[bf].sample_range == (1.0, 4.0)


def test_a_negative_symbol_is_drawn_at_its_own_sign():
    """A value a component file gives below zero is sampled there, never at its
    mirror; what generated code accepts for it is below zero too."""
    from sympy.physics.units import force
    from crane_sym.audit.sampling import draw
    from crane_sym.symbols import PhysicalSymbol
    R = sp.Symbol("R", negative=True)
    entry = PhysicalSymbol(R, force, "N", "a resistance", sign="negative",
                           sample_range=(1e3, 4e3))
    rng = np.random.default_rng(7)
    values = [draw(entry, rng) for _ in range(200)]
    assert all(-4e3 <= v <= -1e3 for v in values)
    low, high = entry.serves
    assert low < high < 0
