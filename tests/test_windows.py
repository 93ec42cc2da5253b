"""Window pieces and entire functions (crane_sym.codegen.windows, crane_sym.codegen.entire):
the rewritten expressions equal the derived ones, and the generated helpers
are accurate on both sides of their cutoff."""
import mpmath
import numpy as np
import pytest
import sympy as sp

from crane_sym.codegen import module as codegen
from crane_sym.mechanics.duhamel import duhamel
from crane_sym.codegen.entire import Z, closed_form, entire, entire_node, laurent, plan
from crane_sym.mechanics.loads import PiecewiseLoad, ramp
from crane_sym.bench.accuracy import reference_value
from crane_sym.codegen.windows import split_windows, window_pieces

t = sp.Symbol("t", nonnegative=True)
W, c, v = sp.symbols("Omega c v", positive=True)

CLOSED = [
    (1 - sp.cos(Z)) / Z ** 2,
    (Z - sp.sin(Z)) / Z ** 3,
    (Z ** 2 * sp.cos(Z) - 2 * Z * sp.sin(Z) - 2 * sp.cos(Z) + 2) / Z ** 4,
    -12 + 36 * sp.cos(Z) / Z ** 2 + 144 / Z ** 2 - 180 * sp.sin(Z) / Z ** 3,
    1 - sp.sin(Z / 2) ** 2 * 4 / Z ** 2,
]


@pytest.mark.parametrize("closed", CLOSED)
def test_laurent_coefficients_are_the_series(closed):
    exact = sp.series(closed, Z, 0, 12).removeO()
    got = laurent(closed, 11)
    for k in range(-4, 12):
        assert sp.Rational(got.get(k, 0)) == exact.coeff(Z, k), k


def _helper(closed):
    """The generated helper for ``closed``, executed with the kernels it calls."""
    node = entire_node(sp.Symbol("x"), closed)
    source = codegen.render_helper(int(node.args[1]), "_f")
    scope = {"np": np}
    scope.update(codegen.kernel_functions(source))
    exec(source, scope)                              # noqa: S102 (our own generated source)
    return scope["_f"], int(node.args[1])


@pytest.mark.parametrize("closed", CLOSED)
def test_generated_helper_against_mpmath_across_its_cutoff(closed):
    f, key = _helper(closed)
    cut = plan(key).cutoff
    z = np.concatenate([np.logspace(-12, 3, 150), cut * (1 + np.linspace(-1e-3, 1e-3, 11))])
    got = f(z)
    g = sp.lambdify(Z, closed, "mpmath")
    size = 1 + max(abs(float(g(mpmath.mpf(x)))) for x in (0.5, 1, 2))
    with mpmath.workdps(60):
        for zi, gi in zip(z, got):
            exact, _ = reference_value(g, [mpmath.mpf(float(zi))], 30)
            # a few ulp of the value, or of the function's size where it oscillates
            # through zero at large z (an absolute error of the sines)
            assert abs(gi - exact) <= 3e-15 * abs(exact) + 1e-15 * size / max(1, zi) ** 2 * 4, zi


def test_helper_accepts_a_phase_pair():
    f, _ = _helper(CLOSED[1])
    z = mpmath.mpf(1000) + mpmath.mpf("1e-13")
    hi = float(z)
    with mpmath.workdps(60):
        exact = (z - mpmath.sin(z)) / z ** 3
        assert abs(f((hi, float(z - hi))) - exact) <= 2e-16 * abs(exact)


def _windowed(result):
    """(1 − H(t − c))·x_before + H(t − c)·x_after of a two-piece response."""
    before, after = (p.expr for p in result.pieces)
    H = sp.Heaviside(t - c, 0)
    return (1 - H) * before + H * after


def _ramp_hold_response():
    """x of x'' + W² x = v·(t/c on [0, c), 1 after): a windowed expression."""
    return _windowed(duhamel(ramp(v, c, t=t), W, t))


def test_split_windows_reassembles_the_expression():
    expr = _ramp_hold_response()
    rest, pieces = split_windows(expr, t)
    H = sp.Heaviside(t - c, 0)
    before, after = pieces[c]
    again = rest + (1 - H) * before + H * after
    for values in ({t: 0.3, W: 7, c: 0.5, v: 2}, {t: 0.9, W: 7, c: 0.5, v: 2}):
        assert abs(sp.N((again - expr).subs(values), 30)) < 1e-25


def _numeric(expr):
    return expr.replace(lambda e: isinstance(e, entire),
                        lambda e: closed_form(int(e.args[1])).xreplace({Z: e.args[0]})).doit()


@pytest.mark.parametrize("times", [(1e-9, 0.2, 0.49), (0.5, 0.5000001, 3.0, 400.0)])
def test_window_pieces_equal_the_derived_expression(times):
    expr = _ramp_hold_response()
    new = window_pieces({t})(expr)
    assert new.has(sp.Piecewise) and not new.has(sp.Heaviside)
    plain = _numeric(new.rewrite(sp.Add).rewrite(sp.cos).rewrite(sp.sin))
    for time in times:
        values = {t: sp.Float(time, 40), W: sp.Float(7.25, 40), c: sp.Float(0.5, 40), v: 2}
        exact = sp.N(expr.subs(values), 30)
        assert abs(sp.N(plain.subs(values), 30) - exact) <= 1e-25 * abs(exact)


def test_polynomial_load_on_a_window_is_regrouped_at_the_window_end():
    # load s²(1 − s)³, s = t/c, on [0, c): before c its monomials cancel near
    # t = c; the rule writes it in powers of (c − t)/c with positive parts.
    law = (t / c) ** 2 * (1 - t / c) ** 3
    new = window_pieces({t})(_windowed(duhamel(PiecewiseLoad((0, c), (sp.expand(law), 0), t),
                                               W, t, simplify=False)))
    before = new.args[0][0] if isinstance(new, sp.Piecewise) else next(
        p for p in new.atoms(sp.Piecewise)).args[0][0]
    assert before.has(c - t) or before.has(-t + c)
    assert len(before.atoms(entire)) == 4
