"""Core machinery: dimensions, checks that can fail, the audit's verdict logic,
and the builders (Lagrange, elimination, ODE solution)."""
import pytest
import sympy as sp
from sympy.physics.mechanics import LagrangesMethod, dynamicsymbols
from sympy.physics.units import force, length, mass, time

from crane_sym.audit import verdicts as A
from crane_sym.audit.checks import (FAIL, PASS, dimension_consistency, numeric_equivalence,
                                    symbolic_equivalence)
from crane_sym.derivation import Derivation, Output
from crane_sym.dimensions import check_equation, dimension_of, format_vector, vector
from crane_sym.mechanics.elimination import relative_coordinate
from crane_sym.mechanics.lagrange import lagrange_equations
from crane_sym.mechanics.odes import solve_constant_coefficient
from crane_sym.published import ASSUMPTION, SYMBOL_FOR_ANOTHER, Convention, PublishedFormula
from crane_sym.symbols import COORDINATE, DEFINED, TIME, PhysicalSymbol, SymbolTable

t = sp.Symbol("t", nonnegative=True)
m, k, F0 = sp.symbols("m k F0", positive=True)
x = sp.Function("x")(t)
w, y = sp.symbols("w y", positive=True)
TABLE = SymbolTable([
    PhysicalSymbol(t, time, "s", "time", TIME, "nonnegative", (1e-3, 10)),
    PhysicalSymbol(m, mass, "kg", "mass", sample_range=(1, 1e3)),
    PhysicalSymbol(k, force / length, "N/m", "stiffness", sample_range=(1e2, 1e6)),
    PhysicalSymbol(F0, force, "N", "force", sample_range=(1, 1e3)),
    PhysicalSymbol(x, length, "m", "position", COORDINATE, "real"),
    PhysicalSymbol(w, 1 / time, "rad/s", "frequency", DEFINED),
    PhysicalSymbol(y, length, "m", "static deflection", DEFINED),
])
MOTION = sp.Eq(m * x.diff(t, 2) + k * x, F0)


def test_dimension_vectors_and_format():
    assert vector(force) == vector(mass * length / time ** 2)
    assert format_vector(vector(force)) == "kg·m/s²"
    dims = {e.expr: vector(e.dimension) for e in TABLE}
    assert dimension_of(x.diff(t, 2), dims) == vector(length / time ** 2)
    assert dimension_of(sp.sqrt(k / m), dims) == vector(1 / time)


def test_dimension_check_names_the_offending_term():
    dims = {e.expr: vector(e.dimension) for e in TABLE}
    report = check_equation(m * x.diff(t, 2) + k * x + m * x, F0, dims)
    assert not report.consistent
    assert report.offending == ("$m x$ [kg·m]",)
    assert report.message.count("m x") == 1     # named once
    # One term on the left sets the dimension: the terms that differ from it are
    # blamed, even when they are the majority.
    defined = check_equation(F0, m * x + k * x.diff(t), dims)
    assert len(defined.offending) == 2 and "$m x$ [kg·m]" in defined.offending
    assert "left-hand side $F_{0}$" in defined.message
    bad = check_equation(y, sp.cos(k * t), dims)
    assert not bad.consistent and "must be dimensionless" in bad.message


def test_symbolic_check_accepts_rearranged_and_scaled_equations():
    scaled = sp.Eq(x.diff(t, 2) + k / m * x, F0 / m)
    assert symbolic_equivalence(scaled, MOTION, TABLE).status == PASS
    swapped = sp.Eq(F0, m * x.diff(t, 2) + k * x)
    assert symbolic_equivalence(swapped, MOTION, TABLE).status == PASS


def test_symbolic_and_numeric_checks_fail_on_a_wrong_coefficient():
    wrong = sp.Eq(m * x.diff(t, 2) + 2 * k * x, F0)
    assert symbolic_equivalence(wrong, MOTION, TABLE).status != PASS
    outcome = numeric_equivalence(wrong, MOTION, TABLE)
    assert outcome.status == FAIL and "ratio" in outcome.detail


def test_symbolic_check_reads_a_printed_abs_as_its_cases():
    """A print's |u| transcribed as its two cases against a derived Abs (004's
    (21)) is a symbolic identity; with a sign changed in one case it is not."""
    u = y - 2 * w
    cases = sp.Piecewise((u, u >= 0), (-u, True))
    printed = sp.Eq(F0, (w - cases) / 4)
    outcome = symbolic_equivalence(printed, sp.Eq(F0, (w - sp.Abs(u)) / 4), TABLE)
    assert outcome.status == PASS and "read as |x|" in outcome.detail
    wrong = sp.Eq(F0, (w - sp.Piecewise((u, u >= 0), (u, True))) / 4)
    assert symbolic_equivalence(wrong, sp.Eq(F0, (w - sp.Abs(u)) / 4), TABLE).status != PASS


def test_numeric_check_reports_values_for_definitions():
    outcome = numeric_equivalence(sp.Eq(w, sp.sqrt(k / m) * 1.001), sp.Eq(w, sp.sqrt(k / m)), TABLE)
    assert outcome.status == FAIL and "right-hand side" in outcome.detail
    ok = numeric_equivalence(sp.Eq(w, sp.sqrt(k) / sp.sqrt(m)), sp.Eq(w, sp.sqrt(k / m)), TABLE)
    assert ok.status == PASS


def test_dimension_check_on_relations():
    assert dimension_consistency(MOTION, TABLE).status == PASS
    assert dimension_consistency(sp.Eq(y, F0 * k), TABLE).status == FAIL


def _toy(published):
    d = Derivation("toy", "toy.txt", "toy", "", "", TABLE)
    d.add("(1)", MOTION, "Newton's second law.")
    d.add("(2)", sp.Eq(w, sp.sqrt(k / m)), "Coefficient of x over m.")
    d.add("(3)", sp.Eq(y, F0 / k), "Static solution.")
    d.published.extend(published)
    return d


def _verdicts(published):
    return [(r.verdict, r.method) for r in A.audit(_toy(published))]


def test_each_verdict_kind_comes_from_its_check():
    W = sp.Symbol("W", positive=True)  # a printed name for w
    TABLE.entries.append(PhysicalSymbol(W, 1 / time, "rad/s", "printed w", DEFINED))
    try:
        got = _verdicts([
            PublishedFormula("(1)", "...", sp.Eq(m * x.diff(t, 2), F0 - k * x), "toy"),
            PublishedFormula("(2)", "...", sp.Eq(W, sp.sqrt(k / m)), "toy",
                             conventions=(Convention("W is w", sp.Eq(w, sp.sqrt(k / m)),
                                                       SYMBOL_FOR_ANOTHER),)),
            PublishedFormula("(3)", "...", sp.Eq(y, 2 * F0 / k), "toy"),
            PublishedFormula("(3)", "...", sp.Eq(y, F0 * k), "toy"),
            PublishedFormula("(3)", "...", None, "toy", not_checkable="OCR lost it"),
            PublishedFormula("(3)", "...", sp.Eq(y, 0, evaluate=False), "toy", kind=ASSUMPTION,
                             stated='toy: "we take y = 0"'),
        ])
    finally:
        TABLE.entries.pop()
    assert got == [(A.CONFIRMED, "symbolic"), (A.CONFIRMED_WITH_CONVENTION, "symbolic"),
                   (A.DISCREPANCY, "numeric"), (A.DIMENSION_ERROR, "dimension"),
                   (A.NOT_CHECKABLE, "none"), (A.REMARK, "numeric")]


def test_an_assumption_is_a_remark_only_where_the_paper_states_it():
    """No quote, no remark: an unstated 'assumption' is refused, so a mismatch cannot
    be turned into a remark without the paper's words; the remark quotes them."""
    with pytest.raises(ValueError, match="stated"):
        PublishedFormula("(3)", "...", sp.Eq(y, 0, evaluate=False), "toy", kind=ASSUMPTION)
    (record,) = A.audit(_toy([PublishedFormula(
        "(3)", "...", sp.Eq(y, 0, evaluate=False), "toy", kind=ASSUMPTION,
        stated='toy: "we take y = 0"')]))
    assert record.verdict == A.REMARK and 'toy: "we take y = 0"' in record.detail


def test_discrepancy_gives_the_corrected_form():
    (record,) = A.audit(_toy([PublishedFormula("(3)", "...", sp.Eq(y, 2 * F0 / k), "toy")]))
    assert "Derived form" in record.detail and "\\frac{F_{0}}{k}" in record.detail
    assert "Printed − derived: $\\frac{F_{0}}{k}$" in record.detail  # the term that differs
    assert dict(record.point) .keys() == {"k", "F_{0}"}          # the point, every symbol


def test_a_transcription_must_be_a_sympy_equation_not_text():
    with pytest.raises(TypeError, match="built in code"):
        PublishedFormula("(1)", "x = 1", "__import__('os').system('echo no')", "toy")
    with pytest.raises(ValueError, match="no transcription"):
        PublishedFormula("(1)", "x = 1", None, "toy")


def test_output_rejects_free_symbols_that_are_not_arguments():
    with pytest.raises(ValueError, match=r"free symbols \['k'\]"):
        Output("f", k * m, (m,), ("(1)",), "f", "N")


def test_lagrange_matches_sympy_lagrangesmethod_on_conservative_part():
    m1, m2, c = sp.symbols("m1 m2 c", positive=True)
    q1, q2 = dynamicsymbols("q1 q2")
    tt = dynamicsymbols._t
    T = m1 * q1.diff(tt) ** 2 / 2 + m2 * q2.diff(tt) ** 2 / 2
    V = c * (q2 - q1) ** 2 / 2
    ours = lagrange_equations(T, V, [q1, q2], tt)
    lm = LagrangesMethod(T - V, [q1, q2])
    theirs = lm.form_lagranges_equations()
    for eq, ref in zip(ours.equations, theirs):
        assert sp.simplify(eq.lhs - eq.rhs - ref) == 0
    assert sp.simplify(ours.mass_matrix() - lm.mass_matrix) == sp.zeros(2)


def test_lagrange_dissipation_and_forces():
    b = sp.Symbol("b", positive=True)
    (eq,) = lagrange_equations(m * x.diff(t) ** 2 / 2, k * x ** 2 / 2, [x], t,
                               {x: F0}, dissipation=b * x.diff(t) ** 2 / 2).equations
    assert sp.expand(eq.lhs - (m * x.diff(t, 2) + b * x.diff(t) + k * x)) == 0
    assert eq.rhs == F0
    with pytest.raises(ValueError, match="non-coordinates"):
        lagrange_equations(m * x.diff(t) ** 2 / 2, 0, [x], t, {sp.Symbol("z"): 1})


def test_elimination_refuses_a_system_that_does_not_decouple():
    m1, m2, c = sp.symbols("m1 m2 c", positive=True)
    x1, x2, u = (sp.Function(n)(t) for n in ("x1", "x2", "u"))
    eq1 = sp.Eq(m1 * x1.diff(t, 2) - c * (x2 - x1) + k * x1, 0)   # x1 grounded
    eq2 = sp.Eq(m2 * x2.diff(t, 2) + c * (x2 - x1), 0)
    with pytest.raises(ValueError, match="does not cancel"):
        relative_coordinate(eq1, eq2, x1, x2, u)


def test_constant_coefficient_solution_meets_equation_and_initial_conditions():
    A_, B_ = sp.symbols("A B")
    eq = sp.Eq(x.diff(t, 2) + w ** 2 * x, F0 / m)
    sol = solve_constant_coefficient(eq, x, (A_, B_), initial={0: y, 1: 0})
    assert sol.basis == (sp.cos(w * t), sp.sin(w * t))
    u = sol.solution
    assert sp.simplify(u.diff(t, 2) + w ** 2 * u - F0 / m) == 0
    assert sp.simplify(u.subs(t, 0) - y) == 0 and u.diff(t).subs(t, 0) == 0


def test_a_rounded_printed_number_is_judged_within_its_tolerance():
    K = sp.Symbol("K", positive=True)
    TABLE.entries.append(PhysicalSymbol(K, sp.S.One * time / time, "1", "factor", DEFINED))
    try:
        d = _toy([])
        d.add("K", sp.Eq(K, sp.sqrt(2)), "A factor.")
        printed = sp.Eq(K, sp.Float("1.414"))
        loose = A.audit_formula(d, PublishedFormula("K", "1.414", printed, "toy",
                                                    tolerance=5e-4))
        tight = A.audit_formula(d, PublishedFormula("K", "1.414", printed, "toy",
                                                    tolerance=1e-6))
        exact = A.audit_formula(d, PublishedFormula("K", "1.414", printed, "toy"))
    finally:
        TABLE.entries.pop()
    assert (loose.verdict, loose.method) == (A.CONFIRMED, "numeric")
    assert "not tried: the print is rounded" in loose.checks[0].detail
    assert (tight.verdict, tight.method) == (A.DISCREPANCY, "numeric")
    assert "1.414" in tight.detail and "1.41421356237" in tight.detail
    assert exact.verdict == A.DISCREPANCY
    with pytest.raises(ValueError, match="tolerance"):
        PublishedFormula("K", "1.414", printed, "toy", tolerance=2.0)


def test_dimensions_of_integrals_piecewise_and_functions_of_other_arguments():
    theta = sp.Symbol("theta", nonnegative=True)
    S = sp.Function("S")
    dims = {e.expr: vector(e.dimension) for e in TABLE}
    dims[S(t)] = vector(force)
    dims[theta] = vector(time)
    impulse = sp.Integral(S(theta) * sp.sin(w * (t - theta)), (theta, 0, t))
    assert dimension_of(impulse, dims) == vector(force * time)
    assert dimension_of(sp.Piecewise((F0, t < 1), (2 * F0, True)), dims) == vector(force)
    report = check_equation(y, sp.Piecewise((y, t < 1), (F0, True)), dims)
    assert not report.consistent


def test_rewrite_rules_produce_the_stable_forms():
    from crane_sym.codegen.rewriting import rules_for, optimize
    T, tn, th = sp.symbols("T t_n theta", positive=True)
    rules = rules_for({t})
    # x - sin x, and its higher analogues, become Taylor remainders
    assert "sin_remainder(t*w, 1)" in str(optimize((w * t - sp.sin(w * t)) / (w * tn), rules))
    assert "cos_remainder(t*w, 2)" in str(optimize(t ** 2 / 2 - (1 - sp.cos(w * t)) / w ** 2, rules))
    # a difference of cosines becomes a product with the small factor sin(w*theta/2)
    diff = optimize(sp.cos(w * (t - th)) - sp.cos(w * t), rules)
    assert "sin(theta*w/2)" in str(diff) and "cos(" not in str(diff)
    # a polynomial in t is factored at its roots
    assert optimize(12 * t ** 3 / tn ** 3 - 24 * t ** 2 / tn ** 2 + 12 * t / tn, rules) \
        == 12 * t * (t - tn) ** 2 / tn ** 3
    # and every rewrite is an identity
    for expr in [(w * t - sp.sin(w * t)) / (w * tn), sp.cos(w * (t - th)) - sp.cos(w * t),
                 t ** 3 / 6 - (w * t - sp.sin(w * t)) / w ** 3]:
        new = optimize(expr, rules)
        R = sp.Rational
        for point in [{t: R(3, 10), w: 2, tn: R(7, 10), th: R(1, 10)},
                      {t: R(17, 10), w: R(1, 2), tn: R(11, 10), th: R(9, 10)}]:
            assert abs(complex(new.subs(point).rewrite(sp.sin).rewrite(sp.cos).evalf(30))
                       - complex(expr.subs(point).evalf(30))) < 1e-25
