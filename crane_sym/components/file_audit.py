"""Verdicts on the formulas a component file lists, from the papers' checks.

Each ``[[formula]]`` (:mod:`crane_sym.components.formulas`) becomes a small
derivation of its own: the symbols it maps (each with the dimension of its
parameter and a sampling range about the file's value, a factor of 2 each
way), the derived quantity it names as the one step
(:mod:`crane_sym.components.quantities`), and the formula as a published
one. The print is read by the machine reader of the papers' prints
(:mod:`crane_sym.audit.latex_parse` and :mod:`crane_sym.audit.print_names`:
SymPy's lark LaTeX parser, names mapped, nothing evaluated), within the
bounds of :mod:`crane_sym.components.formula_limits` (a formula over one is
not_checkable, "too large to check", and the audit goes on); then
:func:`crane_sym.audit.verdicts.audit_formula` decides exactly as for a paper:
symbolic identity first, mpmath at seeded physical points second, dimensions
third, the record naming the check that decided, its basis (the model derived
from the components) and, for a finding, its cause (the file's ``cause``, or
a sentence saying it gives none).

A number of the file's run (a link's peak or dynamic factor) is compared at
the file's values only: its parameters are sampled at exactly their value, and
the relative tolerance is the formula's (at least 1e-9, the run's accuracy).
"""
from __future__ import annotations

import re
from dataclasses import replace

import sympy as sp
from sympy.physics.units import time

from crane_sym.audit.latex_parse import Unreadable, bound_variables, candidates, parse
from crane_sym.audit.machine_read import AGREES, UNREADABLE, MachineRead
from crane_sym.audit.print_names import calls_pass, map_symbols, names_pass, vocabulary
from crane_sym.audit.verdicts import DISCREPANCY, AuditRecord, audit_formula
from crane_sym.components import formula_limits as limits
from crane_sym.components.formula_limits import Refused, TooLarge, bounded, check_print
from crane_sym.components.formulas import TIME, FileFormula
from crane_sym.components.parts import ComponentError, value
from crane_sym.components.parameters import parameters
from crane_sym.components.quantities import NUMERIC, derived_quantity, quantity_table
from crane_sym.components.component_file import ComponentFile
from crane_sym.components.vibration import ModeChoice, mode_at
from crane_sym.derivation import Derivation, Step
from crane_sym.latex import latex
from crane_sym.published import Cause, PublishedFormula
from crane_sym.symbols import DEFINED, PARAMETER, TIME as TIME_ROLE, PhysicalSymbol, SymbolTable

__all__ = ["NUMERIC_TOLERANCE", "audit_file", "formula_derivation", "not_checkable"]

#: The relative tolerance of a comparison with a number of the run.
NUMERIC_TOLERANCE = 1e-9
#: How far about its value a parameter is sampled for a symbolic quantity.
SPREAD = 2.0


def _choice(read: ComponentFile, f: FileFormula) -> ModeChoice | None:
    """Which natural frequency the formula means, of the run's mode at its ``at``."""
    if not f.modal:
        return None
    end = value("run", "duration", read.duration, time).si
    state, instant = mode_at(read.model, f.at, end, read.body, read.speed, read.rest)
    return ModeChoice(f.mode, state, instant)


def _numeric(read: ComponentFile, f: FileFormula) -> bool:
    """Whether the formula reads a number of the run."""
    paths = [f.quantity] + [t for _, t in f.symbols]
    return any(p.partition(".")[2] in NUMERIC for p in paths)


def formula_derivation(read: ComponentFile, f: FileFormula, run=None) -> tuple[
        Derivation, PublishedFormula]:
    """The derivation one formula is audited in, and the formula as published.

    Parameters
    ----------
    read : ComponentFile
        The read component file.
    f : FileFormula
        One of its formulas.
    run : ComponentRun, optional
        The file's run, for a formula that reads a number of it.
    """
    model = read.model
    where = f"{read.path.name}: [[formula]] {f.name!r}"
    try:
        choice = _choice(read, f)
        quantity = derived_quantity(model, f.quantity, run, choice)
    except ComponentError as exc:
        raise ComponentError(f"{where}: {exc}") from None
    exact = _numeric(read, f)
    params = {p.symbol: p for p in parameters(model, (read.body, read.speed)).values()}
    by_path = {p.path: p for p in params.values()}
    zero = {s: 0 for s, p in params.items() if p.value == 0}
    entries: dict[sp.Basic, PhysicalSymbol] = {}
    names: dict[sp.Basic, str] = {}
    inserted: dict[sp.Symbol, sp.Expr] = {}

    def entry(symbol: sp.Symbol) -> None:
        if symbol in entries:
            return
        p = params.get(symbol)
        if p is None or not p.value == p.value:          # a steady motor's torque: no value
            raise ComponentError(f"{where}: {symbol} has no value in the file")
        v = abs(p.value)
        if v == 0:         # put to zero before any check (``zero``): its name is only read
            entries[symbol] = PhysicalSymbol(symbol, p.dimension, p.unit, p.description,
                                             PARAMETER, "positive")
            return
        low, high = (v, v) if exact else (v / SPREAD, v * SPREAD)
        # drawn at the sign the file gives it: a real symbol (a motor's torque)
        # never at its mirror, a negative one as its negative twin (parameters.signed)
        sign = "negative" if p.value < 0 else "positive"
        entries[symbol] = PhysicalSymbol(symbol, p.dimension, p.unit, p.description,
                                         PARAMETER, sign, (low, high))

    t = model.equations.t
    for printed, target in f.symbols:
        if target == TIME:
            symbol = t
            end = value("run", "duration", read.duration, time).si
            entries[t] = PhysicalSymbol(t, time, "s", "time", TIME_ROLE, "nonnegative",
                                        (end / 100, end))
        elif target in by_path:
            symbol = by_path[target].symbol
            entry(symbol)          # a zero value too: its name is read, then put to 0
        else:
            inner = derived_quantity(model, target, run, choice)
            what = f"{target}: {quantity_table()[target.partition('.')[2]][1]}"
            if inner.numeric:        # a number of the run: a parameter at its magnitude
                symbol = sp.Symbol(f"quantity_{len(names)}", positive=True)
                size = abs(float(inner.expr))
                entries[symbol] = PhysicalSymbol(symbol, inner.dimension, inner.unit, what,
                                                 PARAMETER, "positive", (size, size))
                if inner.expr < 0:
                    inserted[symbol] = -symbol
            else:                    # a symbolic quantity: its expression put in
                symbol = sp.Symbol(f"quantity_{len(names)}", real=True)
                inserted[symbol] = inner.expr
                entries[symbol] = PhysicalSymbol(symbol, inner.dimension, inner.unit, what,
                                                 DEFINED, "real")
        if symbol in names:
            raise ComponentError(f"{where}: symbols: {printed!r} and {names[symbol]!r} name "
                                 f"one {target}")
        names[symbol] = printed
    used = set().union(quantity.expr.free_symbols, *(e.free_symbols for e in inserted.values()))
    for symbol in sorted(used - {t}, key=str):
        entry(symbol)
    if t in used and t not in entries:
        end = value("run", "duration", read.duration, time).si
        entries[t] = PhysicalSymbol(t, time, "s", "time", TIME_ROLE, "nonnegative",
                                    (end / 100, end))
    lhs = sp.Symbol("Q_" + re.sub(r"\W", "_", f.quantity), real=True)
    lhs_entry = PhysicalSymbol(lhs, quantity.dimension, quantity.unit,
                               f"{f.quantity}: {quantity_table()[f.quantity.partition('.')[2]][1]}",
                               DEFINED, "real")
    d = Derivation(model.name, read.path.name, model.title or model.name, str(read.path),
                   "", SymbolTable([*entries.values(), lhs_entry]), latex_names=names)
    d.steps.append(Step(f.quantity, sp.Eq(lhs, quantity.expr), quantity.how,
                        title=quantity_table()[f.quantity.partition(".")[2]][1]))
    where_printed, cause = _printed_where(read, f), _cause(read, f)
    tolerance = max(f.tolerance, NUMERIC_TOLERANCE) if exact else f.tolerance
    try:
        with limits.budget(limits.PARSE_SECONDS, "reading it"):
            relation, shown = _read(f, d, lhs, inserted, zero)
    except Refused as why:          # formula_limits: the bound it broke
        return d, PublishedFormula(f.name, f.latex, None, where_printed, compare_to=f.quantity,
                                   not_checkable=f"{why.prefix}: {why}", cause=cause)
    except Unreadable as why:       # a name as the parser's token shows it: as text
        reason = re.sub(r"Token\('\w+', ('[^']*')\)", r"\1", str(why))
        return d, PublishedFormula(f.name, f.latex, None, where_printed, compare_to=f.quantity,
                                   not_checkable=f"the print cannot be read by machine: "
                                                 f"{reason}", cause=cause)
    d.latex_names[lhs] = shown
    return d, PublishedFormula(f.name, f.latex, relation, where_printed,
                               compare_to=f.quantity, tolerance=tolerance, cause=cause)


def _printed_where(read: ComponentFile, f: FileFormula) -> str:
    return f"{read.path.name}, [[formula]] {f.name}"


def _cause(read: ComponentFile, f: FileFormula) -> Cause:
    """The file's cause of a finding, or a cause saying it gives none."""
    if f.cause:
        return Cause(f"{read.model.name}-{re.sub(r'[^A-Za-z0-9]+', '-', f.name).strip('-')}",
                     f.cause)
    return Cause("unexplained", f"{_printed_where(read, f)}: the file gives no cause for this "
                 "finding (a cause = \"...\" line in the [[formula]] states one)")


def not_checkable(read: ComponentFile, f: FileFormula, reason: str) -> tuple[
        Derivation, PublishedFormula]:
    """A formula the model cannot check (a quantity it cannot derive, a symbol
    without a value), as a published formula with the reason: its verdict is
    ``not_checkable`` and the audit goes on with the file's other formulas.

    Parameters
    ----------
    read : ComponentFile
        The read component file.
    f : FileFormula
        The formula.
    reason : str
        Why it cannot be checked (one line).
    """
    model = read.model
    d = Derivation(model.name, read.path.name, model.title or model.name, str(read.path),
                   "", SymbolTable([]))
    return d, PublishedFormula(f.name, f.latex, None, _printed_where(read, f),
                               compare_to=f.quantity, not_checkable=reason,
                               cause=_cause(read, f))


def _read(f: FileFormula, d: Derivation, lhs: sp.Symbol, inserted: dict,
          zero: dict) -> tuple[sp.Eq, str]:
    """The print read by machine as ``lhs = ...`` and the LaTeX of its left side;
    :class:`Unreadable` with the reason."""
    check_print(f.latex)
    vocab = vocabulary(d)
    tokens: dict[str, sp.Basic] = {}
    tex = calls_pass(names_pass(bound_variables(f.latex), vocab, tokens), vocab, tokens)
    found = candidates(tex)
    if len(found) != 1:
        raise Unreadable(f"it holds {len(found)} relations; a [[formula]] gives one")
    left, equals, right = found[0].partition("=")
    call = re.fullmatch(r"\s*(.+?)\s*\(\s*[A-Za-z]\s*\)\s*", left)  # F(t) = ...: F
    parsed = parse(call.group(1) + " =" + right if equals and call else found[0])
    if isinstance(parsed.rhs, sp.core.relational.Relational):
        raise Unreadable("an inequality, not a formula for the quantity")
    rhs = bounded(map_symbols(parsed.rhs, vocab, tokens).xreplace(inserted).xreplace(zero))
    shown = latex(lhs)
    if parsed.lhs is not None:
        head, power = parsed.lhs.as_base_exp()      # ω² = …: ω is its principal root
        if not isinstance(head, sp.Symbol) or not (power.is_Integer and power > 0) or str(
                head).replace("{", "").replace("}", "") in tokens:
            raise Unreadable("its left side must be the quantity's name alone or its power, "
                             f"got {latex(parsed.lhs)!r}")
        shown, rhs = latex(head), rhs ** (1 / power)
    return sp.Eq(lhs, rhs, evaluate=False), shown


def _with_ratio(record: AuditRecord, d: Derivation, published: PublishedFormula) -> AuditRecord:
    """A discrepancy of a symbolic quantity with the factor it is off by, when
    printed over derived simplifies to a short expression free of time."""
    if record.verdict != DISCREPANCY or published.tolerance > 0:
        return record
    derived = d.step(published.target).statement.rhs
    if derived == 0:
        return record
    ratio = sp.simplify(published.printed.rhs / derived)
    if ratio.has(d.steps[0].statement.lhs) or sp.count_ops(ratio) > 12 or any(
            e.role == TIME_ROLE and ratio.has(e.expr) for e in d.symbols):
        return record
    return replace(record, detail=record.detail + " Printed / derived: $"
                   + latex(ratio, symbol_names=d.latex_names) + "$ (a wrong factor).")


def audit_file(read: ComponentFile) -> list[AuditRecord]:
    """Verdicts on every [[formula]] of a read component file, in its order.

    Parameters
    ----------
    read : ComponentFile
        The file (:func:`crane_sym.components.component_file.read_component_file`).
    """
    if not read.formulas:
        raise ComponentError(f"{read.path.name}: no [[formula]] to audit (README, "
                             "\"Your own drive train\")")
    run = None
    if any(_numeric(read, f) for f in read.formulas):
        run = read.model.run(read.duration, read.body, read.speed, rest=read.rest)
    records = []
    for f in read.formulas:
        try:
            d, published = formula_derivation(read, f, run)
        except ComponentError as why:             # this formula only: the rest go on
            d, published = not_checkable(read, f, f"the model cannot check it: {why}")
        try:
            with limits.budget(limits.CHECK_SECONDS, "checking it"):
                record = _with_ratio(audit_formula(d, published), d, published)
        except TooLarge as why:
            published = replace(published, printed=None, not_checkable=f"{why.prefix}: {why}")
            record = audit_formula(d, published)
        seen = (MachineRead(AGREES, "read by machine (a file's formula has no hand "
                            "transcription: the parse is what is audited)",
                            latex(published.printed.rhs, symbol_names=d.latex_names))
                if published.printed is not None else
                MachineRead(UNREADABLE, published.not_checkable))
        records.append(replace(record, machine_read=seen))
    return records
