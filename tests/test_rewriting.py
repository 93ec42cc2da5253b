"""Rewrite rules of crane_sym.codegen.rewriting that are not covered by a paper's tests."""
import sympy as sp
from sympy.codegen.cfunctions import log1p

from crane_sym.codegen.rewriting import log1p_form


def test_log1p_form_keeps_log_of_a_ratio_whole():
    """log(a/b) must not become log(a) − log(b) (it cancels when a ≈ b)."""
    a, b, x = sp.symbols("a b x", positive=True)
    assert log1p_form(sp.log(a / b)) == sp.log(a / b)
    assert log1p_form(sp.log(1 + x) * sp.log(a / b)) == log1p(x) * sp.log(a / b)
