"""Code generation: rewrite rules -> printer -> template -> file.

``render_module`` is pure (derivation in, source text out); ``write``,
``compare`` and ``stale`` are the only functions that touch files. Generated
modules import NumPy only, validate every argument, and evaluate
parameter-only parts once as scalars before the array work.
"""
from __future__ import annotations

import inspect
import re
import textwrap
from typing import Iterable, Sequence

import sympy as sp
from sympy.printing.numpy import NumPyPrinter

from . import __version__, cell_kernels, gear_kernels, kernels
from .cells import pieces, statements
from .derivation import Derivation, Output, TabulatedOutput
from .entire import Z, plan
from .inplace import chain
from .involute import ACOS_MESSAGES
from .phase_table import PhaseTable
from .rewriting import Rule, cos_phase, optimize, rules_for, sin_phase
from .scalar_path import fast_path
from .symbols import TIME, SymbolTable
from .tabulated import render_tabulated
from .wave_sums import merge_waves
from .windows import phase_cos, phase_sin


class _Printer(NumPyPrinter):
    """NumPy printer that writes ``np.`` and full double precision floats;
    ``entire`` nodes become calls of module helpers named in ``helpers``."""

    _default_settings = {**NumPyPrinter._default_settings, "helpers": None}

    def _module_format(self, fqn: str, register: bool = True) -> str:
        if fqn.startswith("numpy."):
            fqn = "np." + fqn[len("numpy."):]
        return super()._module_format(fqn, register=False)

    def _print_Float(self, expr: sp.Float) -> str:
        return repr(float(expr))

    def _print_Pi(self, expr: sp.Basic) -> str:
        return "np.pi"

    def _print_joined_sqrt(self, expr: sp.Basic) -> str:
        return f"np.sqrt({self._print(expr.args[0])})"

    def _print_diff_of_products(self, expr: sp.Basic) -> str:
        return "_diff_of_products(" + ", ".join(self._print(a) for a in expr.args) + ")"

    def _print_cos_remainder(self, expr: sp.Basic) -> str:
        return f"_cos_remainder({self._print(expr.args[0])}, {int(expr.args[1])})"

    def _print_sin_remainder(self, expr: sp.Basic) -> str:
        return f"_sin_remainder({self._print(expr.args[0])}, {int(expr.args[1])})"

    def _print_sin_phase(self, expr: sp.Basic) -> str:
        return f"_sin_phase({self._print(expr.args[0])}, {self._print(expr.args[1])})"

    def _print_cos_phase(self, expr: sp.Basic) -> str:
        return f"_cos_phase({self._print(expr.args[0])}, {self._print(expr.args[1])})"

    def _print_Pow(self, expr: sp.Pow, rational: bool = False) -> str:
        if expr.exp == -1:
            return "1/" + self.parenthesize(expr.base, 1000)
        base = expr.base
        if (expr.exp == 2 and isinstance(base, (phase_sin, phase_cos))
                and base.args[1] == sp.Rational(1, 2)):   # from the sine and cosine of z
            kind = "sin" if isinstance(base, phase_sin) else "cos"
            return f"_{kind}_half_squared({self._print(base.args[0])})"
        return super()._print_Pow(expr, rational=rational)

    def _print_offset_wave(self, expr: sp.Basic) -> str:
        return "_offset_wave(" + ", ".join(self._print(a) for a in expr.args) + ")"

    def _print_wave(self, expr: sp.Basic) -> str:
        return "_wave(" + ", ".join(self._print(a) for a in expr.args) + ")"

    def _print_exact_phase(self, expr: sp.Basic) -> str:
        k, t, c = (self._print(a) for a in expr.args)
        return f"_exact_phase({k}, {t})" if expr.args[2] == 0 else f"_exact_phase({k}, {t}, {c})"

    def _print_phase_sin(self, expr: sp.Basic) -> str:
        return f"_sin_pair({self._print(expr.args[0])}, {float(expr.args[1])!r})"

    def _print_phase_cos(self, expr: sp.Basic) -> str:
        return f"_cos_pair({self._print(expr.args[0])}, {float(expr.args[1])!r})"

    def _print_involute(self, expr: sp.Basic) -> str:
        return f"_involute({self._print(expr.args[0])})"

    def _print_inverse_involute_fn(self, expr: sp.Basic) -> str:
        message = ACOS_MESSAGES[int(expr.args[1])]
        return f"_inverse_involute({self._print(expr.args[0])}, {message!r})"

    def _print_acos_checked(self, expr: sp.Basic) -> str:
        message = ACOS_MESSAGES[int(expr.args[1])]
        return f"_acos_checked({self._print(expr.args[0])}, {message!r})"

    def _print_tip_half_angle(self, expr: sp.Basic) -> str:
        args = ", ".join(self._print(a) for a in expr.args[:5])
        return f"_tip_half_angle({args}, {ACOS_MESSAGES[int(expr.args[5])]!r})"

    def _print_tip_shift(self, expr: sp.Basic) -> str:
        return "_tip_shift(" + ", ".join(self._print(a) for a in expr.args) + ")"

    def _print_entire(self, expr: sp.Basic) -> str:
        helpers = self._settings["helpers"]
        key = int(expr.args[1])
        if key not in helpers:
            helpers[key] = f"_entire_{len(helpers) + 1}"
        return f"{helpers[key]}({self._print(expr.args[0])})"


def _dd_literal(value: sp.Expr) -> str:
    """A number as an exact double-double literal ``(hi, lo)``, from 50 digits."""
    exact = sp.N(value, 50)
    hi = float(exact)
    lo = float(sp.N(exact - sp.Float(hi, 50), 50))
    return f"({hi!r}, {lo!r})"


class _DoubleDoublePrinter(_Printer):
    """Prints a parameter-only expression as double-double kernel calls."""

    def _print(self, expr: sp.Basic, **kwargs) -> str:
        if isinstance(expr, sp.Basic) and expr.is_number:
            return _dd_literal(expr)
        return super()._print(expr, **kwargs)

    def _print_Symbol(self, expr: sp.Symbol) -> str:
        return f"_dd({expr.name})"

    def _chain(self, kernel: str, args: Sequence[sp.Expr]) -> str:
        text = self._print(args[0])
        for arg in args[1:]:
            text = f"{kernel}({text}, {self._print(arg)})"
        return text

    def _print_Add(self, expr: sp.Add, order: str | None = None) -> str:
        return self._chain("_dd_add", sp.Add.make_args(expr))

    def _print_Mul(self, expr: sp.Mul) -> str:
        num, den = sp.fraction(expr)
        text = self._chain("_dd_mul", sp.Mul.make_args(num))
        return text if den == 1 else f"_dd_div({text}, {self._print(den)})"

    def _print_Pow(self, expr: sp.Pow, rational: bool = False) -> str:
        base, e = expr.base, expr.exp
        if e == sp.S.Half:
            return f"_dd_sqrt({self._print(base)})"
        if e.is_Integer and e > 0:
            return self._chain("_dd_mul", [base] * int(e))
        if e.is_Rational and e < 0:
            return f"_dd_div(_dd(1.0), {self._print(base ** -e)})"
        raise ValueError(f"no double-double form for {expr}")


class _Ternary(_Printer):
    """Prints a Piecewise as a conditional expression (a call on scalars)."""

    def _print_Piecewise(self, expr: sp.Piecewise) -> str:
        text = self._print(expr.args[-1].expr)
        for branch, cond in reversed(expr.args[:-1]):
            text = f"{self._print(branch)} if {self._print(cond)} else {text}"
        return f"({text})"


def _printer(helpers: dict[int, str] | None = None, kind: type = _Printer) -> _Printer:
    return kind({"fully_qualified_modules": True, "inline": True,
                     "allow_unknown_functions": False,
                     "helpers": {} if helpers is None else helpers})


def render_helper(key: int, name: str) -> str:
    """Source of the module-level function that evaluates one ``entire`` node:
    the closed form where it is accurate, the Taylor series below the cutoff."""
    p = plan(key)
    zs = sp.Symbol("z_")
    # each sin(q z), cos(q z) pair is taken of the caller's phase once, and
    # shared with the other kernels called on it (_Phase); z_ keeps the
    # closed form finite where the series replaces it
    multiples = sorted({sp.cancel(f.args[0] / Z) for f in p.printed.atoms(sp.sin, sp.cos)})
    names = {q: (sp.Symbol(f"s{i}"), sp.Symbol(f"c{i}")) for i, q in enumerate(multiples)}
    closed = p.printed.replace(
        lambda e: isinstance(e, (sp.sin, sp.cos)),
        lambda e: names[sp.cancel(e.args[0] / Z)][0 if isinstance(e, sp.sin) else 1])
    trig = ""
    for q, (s, c) in names.items():
        half = sp.Symbol(f"h{s.name[1:]}")
        squared = closed.subs(s ** 2, half)
        if q == sp.Rational(1, 2) and not squared.has(s, c):   # sin(z/2)**2 from sin z, cos z
            closed = squared
            trig += f"    {half} = _sin_half_squared(w)\n"
        else:
            trig += f"    {s}, {c} = _sincos_pair(w, {float(q)!r})\n"
    closed = _printer().doprint(closed.xreplace({Z: zs}))
    coeffs = ", ".join(repr(c) for c in p.coeffs)
    lead = f"z**{p.power}" if p.power else "1"
    return (f"def {name}(z):\n"
            f'    """{sp.sstr(p.printed)}:\n'
            f"    entire, ~{lead} at 0; its Taylor series where |z| < {p.cutoff!r}.\n"
            f'    z is a phase: a pair (hi, lo) or a double."""\n'
            f"    w = z\n"
            f"    z = _pair(w)[0]\n"
            f"    small = np.abs(z) < {p.cutoff!r}\n"
            f"    z_ = np.where(small, {p.cutoff!r}, z)\n"
            + trig +
            f"    return _taylor_where({closed}, small, z, {p.power}, {p.step},\n"
            f"                         ({coeffs},))\n")


class joined_sqrt(sp.Function):  # noqa: N801 (a SymPy function node)
    """√x kept whole: SymPy would split the root of a product of positive symbols."""

    nargs = 1


def _one_root(e: sp.Expr) -> sp.Expr:
    """√a·√b/(√c·√d) as one √(a·b/(c·d)): one rounding of the root instead of
    one per factor."""
    if not isinstance(e, sp.Mul):
        return e
    roots = [f for f in e.args if isinstance(f, sp.Pow) and f.exp in (sp.S.Half, -sp.S.Half)]
    if len(roots) < 2:
        return e
    inside = sp.Mul(*[f.base ** (2 * f.exp) for f in roots])
    rest = [f for f in e.args if f not in roots]
    return sp.Mul(*rest, joined_sqrt(inside))


def _in_order(pairs: list[tuple[sp.Symbol, sp.Expr]]) -> list[tuple[sp.Symbol, sp.Expr]]:
    """``pairs`` (name, value) with each value after the names it uses; else
    in the given order."""
    pending, done, ordered = list(pairs), set(), []
    defined = {k for k, _ in pairs}
    while pending:
        ready = next(p for p in pending if not (p[1].free_symbols & defined) - done)
        pending.remove(ready)
        done.add(ready[0])
        ordered.append(ready)
    return ordered


def hoist(expr: sp.Expr, varying: set[sp.Symbol]
          ) -> tuple[list[tuple[sp.Symbol, sp.Expr]], list[tuple[sp.Symbol, sp.Expr]], sp.Expr]:
    """Pull every parameter-only factor or term out of the array expression.

    Returns ``(assignments, phases, expr)``: scalar assignments ``k_i = ...``
    that do not depend on ``varying``; double-double assignments for the
    phase factors of ``sin_phase``/``cos_phase``; the remaining expression.
    """
    names = sp.numbered_symbols("k")
    phases_names = sp.numbered_symbols("q")
    assignments: list[tuple[sp.Symbol, sp.Expr]] = []
    phases: list[tuple[sp.Symbol, sp.Expr]] = []

    def fixed(e: sp.Expr) -> bool:
        return not (e.free_symbols & varying)

    def name(e: sp.Expr) -> sp.Expr:
        if e.is_Symbol or e.is_Number:
            return e
        value = _one_root(e)
        for k, known in assignments:       # one name for one value: sin(k·t) once
            if known == value:
                return k
        k = next(names)
        assignments.append((k, value))
        return k

    def visit(e: sp.Expr) -> sp.Expr:
        if fixed(e):
            return name(e)
        if e.is_Atom:
            return e
        if isinstance(e, sp.Piecewise):  # conditions stay as printed
            return sp.Piecewise(*[(visit(branch), cond) for branch, cond in e.args])
        if isinstance(e, (sin_phase, cos_phase)):
            for q, value in phases:
                if value == e.args[1]:
                    return e.func(e.args[0], q)
            q = next(phases_names)
            phases.append((q, e.args[1]))
            return e.func(e.args[0], q)
        if isinstance(e, (sp.Add, sp.Mul)):
            consts = [a for a in e.args if fixed(a)]
            moving = [visit(a) for a in e.args if not fixed(a)]
            head = [name(e.func(*consts))] if consts else []
            return e.func(*head, *moving)
        if isinstance(e, sp.Pow) and fixed(e.exp):
            return sp.Pow(visit(e.base), e.exp)
        return e.func(*[visit(a) for a in e.args])

    if fixed(expr):
        return [], [], expr
    reduced = visit(expr)
    return assignments, phases, reduced


def _signature(out: Output, keyword: bool = False) -> str:
    """``name(a, b)``; with ``keyword``, the ``out`` keyword of array outputs too."""
    names = list(map(str, out.args))
    if keyword and not isinstance(out.expr, sp.MatrixBase):
        names += ["*", "out=None"]
    return f"{out.name}({', '.join(names)})"


def render_function(out: Output, table: SymbolTable,
                    rules: Sequence[Rule] | None = None,
                    helpers: dict[int, str] | None = None) -> str:
    """Source of one validated, vectorized NumPy function; the ``entire``
    helpers it calls are named in ``helpers`` (key -> name)."""
    printer = _printer(helpers)
    varying = {e.expr for e in table.with_role(TIME)} & set(out.args)
    scales = frozenset(a for a in out.args if a not in varying and any(
        table[a].dimension == table[v].dimension for v in varying))
    rules = rules_for(varying, scales) if rules is None else rules
    shape = out.expr.shape if isinstance(out.expr, sp.MatrixBase) else None
    if shape is None:
        expr = optimize(out.expr, rules)
        assignments, phases, body = hoist(expr, varying)
        split = bool(varying) and pieces(body) is not None     # window by window
        subs, reduced = sp.cse([e for _, e in assignments] + ([] if split else [body]),
                               symbols=sp.numbered_symbols("x"), order="canonical")
        reduced = reduced + [body] if split else reduced
    else:  # a matrix: its elements share one CSE, no hoisting
        assignments, phases, split = [], [], False
        subs, reduced = sp.cse([optimize(e, rules) for e in out.expr],
                               symbols=sp.numbered_symbols("x"), order="canonical")
    entries = [table[a] for a in out.args]
    width = max((len(e.name) for e in entries), default=0)
    params = "\n".join(
        f"    {e.name} : array_like\n        {e.description} [{e.unit}]"
        + {"positive": ", > 0", "nonnegative": ", >= 0"}.get(e.sign, "")
        for e in entries)
    if shape is None:
        params += ("\n    out : ndarray, optional\n        float64 array of the broadcast "
                   "shape; the result is written into it and returned.")
    lines = [f"def {_signature(out, keyword=True)}:",
             f'    """{out.summary} Eq {", ".join(out.labels)}.',
             "",
             "    Parameters",
             "    ----------",
             params,
             "",
             "    Returns",
             "    -------",
             "    ndarray",
             f"        [{out.unit}], " + (f"shape {tuple(shape)} followed by the broadcast "
                                        "shape of the arguments." if shape else
                                        "broadcast over the arguments."),
             *(["", "    Raises", "    ------", "    ValueError",
                *[f"        unless {what}." for _, what in out.requires]] if out.requires else []),
             '    """']
    alias = {k: v for (k, _), v in zip(assignments, reduced[:-1]) if v.is_Atom} \
        if shape is None else {}
    # A scalar that CSE reduced to a bare name is inlined, not re-assigned (alias).
    named = _in_order([(s, v.xreplace(alias)) for s, v in subs]
                      + [(k, v) for (k, _), v in zip(assignments, reduced[:-1]) if k not in alias])
    if shape is None and not phases and not split:     # plain numbers: math, no arrays
        lines += ["    " + s for s in fast_path(entries, named, reduced[-1].xreplace(alias),
                                                 [e for e, _ in out.requires]) or []]
    for e in entries:
        what = f"{e.description}, {e.unit}".replace('"', "'")
        lines.append(f"    {e.name:<{width}} = _checked({e.name!r}, {e.name}, "
                     f"{e.sign!r}, {what!r})")
    call = textwrap.wrap(", ".join(f"{e.name}={e.name}" for e in entries) + ")",
                         width=80, break_long_words=False, break_on_hyphens=False)
    lines.append("    shape = _broadcast(" + call[0])
    lines += [" " * 23 + rest for rest in call[1:]]
    lines += [f"    _required({printer.doprint(e)}, {what!r})" for e, what in out.requires]
    for sym, value in phases:
        lines.append(f"    {sym} = {_DoubleDoublePrinter().doprint(value)}")
    for sym, value in named:
        lines.append(f"    {sym} = {printer.doprint(value)}")
    if shape is not None:
        elements = ", ".join(printer.doprint(e) for e in reduced)
        lines.append(f"    return _matrix({tuple(shape)}, [{elements}])")
    else:
        final = reduced[-1].xreplace(alias)
        heavy = set(varying)
        for sym, value in subs:                  # array temporaries of the CSE
            if value.free_symbols & heavy:
                heavy.add(sym)
        taken = {e.name for e in entries} | {str(s) for s, _ in subs} | {
            str(k) for k, _ in assignments}
        merge = ((lambda cell: merge_waves(cell, next(iter(varying))))
                 if len(varying) == 1 else (lambda cell: None))
        cells = statements(final, printer.doprint, _printer(helpers, _Ternary).doprint,
                           taken, merge) if split else None
        steps = None if split else chain(final, heavy, printer.doprint)
        if cells is not None:                    # each window on its own points
            lines += [f"    {s}" for s in cells]
        elif steps is None:                      # not a chain: NumPy as printed
            lines.append(f"    return _into(out, shape, {printer.doprint(final)})")
        else:                                    # one buffer, one pass per node
            lines += ["    if out is None and not shape:",
                      f"        return {printer.doprint(final)}",
                      "    out = _out(out, shape)"]
            lines += [f"    {s}" for s in steps] + ["    return out"]
    return "\n".join(lines) + "\n"


def _kernel_source(functions: Sequence[str]) -> str:
    """Source of the kernels the function texts call, and their dependencies."""
    called = set(re.findall(r"\b(_[a-z_]+)\(", "\n".join(functions)))
    names = kernels.closure({"_checked"} | (called & set(kernels.DEPENDS)))
    sources = [inspect.getsource(getattr(kernels, n)) for n in names]
    gear = kernels.closure(called & set(gear_kernels.DEPENDS), gear_kernels.DEPENDS)
    sources += [inspect.getsource(getattr(gear_kernels, n)) for n in gear]
    cell = kernels.closure(called & set(cell_kernels.DEPENDS), cell_kernels.DEPENDS)
    sources += [inspect.getsource(getattr(cell_kernels, n)) for n in cell]
    return "\n\n".join(sources)


def render_module(d: Derivation, outputs: Iterable[Output] | None = None,
                  rules: Sequence[Rule] | None = None, scene_note: str = "",
                  tables: Sequence[tuple[TabulatedOutput, PhaseTable]] = ()) -> str:
    """Full source of ``generated/<d.id>.py``; deterministic for a given
    derivation and SymPy version. ``scene_note`` describes a specialization;
    ``tables`` are a scene's tabulated responses (``crane_sym.tabulated``)."""
    outputs = list(d.outputs if outputs is None else outputs)
    labels = sorted({lab for o in [*outputs, *(t for t, _ in tables)] for lab in o.labels},
                    key=lambda s: (not s.startswith("("), len(s), s))
    listing = "\n".join(f"    {_signature(o)} -> [{o.unit}]    eq {', '.join(o.labels)}"
                        for o in outputs)
    listing += "".join(f"\n    {o.name}(t) -> [{o.unit}]    eq {', '.join(o.labels)}"
                       for o, _ in tables)
    header = (f'"""Numeric functions for derivation {d.id!r}. Generated; do not edit.\n\n'
              f"Source: crane_sym.derivations.{d.id} (paper {d.paper}:\n"
              f"{d.title}).\n"
              + (f"{scene_note}\n" if scene_note else "") +
              f"Equations: {', '.join(labels)}.\n"
              f"Printed by SymPy {sp.__version__} with crane_sym {__version__}; "
              "regenerate with `crane-sym generate`.\n\n"
              f"Functions and argument order:\n{listing}\n"
              '"""\n')
    names = ", ".join(repr(o.name) for o in [*outputs, *(t for t, _ in tables)])
    helpers: dict[int, str] = {}
    functions = ["\n" + render_function(o, d.symbols, rules, helpers) for o in outputs]
    functions += ["\n" + render_tabulated(o, table, "Tabulated for this scene by "
                                           "crane_sym.phase_table.") for o, table in tables]
    helper_source = ["\n" + render_helper(key, name) for key, name in helpers.items()]
    kernel_source = _kernel_source(functions + helper_source)
    uses_math = any("math." in f for f in [*functions, kernel_source])
    parts = [header, ("import math\n\n" if uses_math else "") + "import numpy as np\n",
             f"__all__ = [{names}]\n",
             "\n" + kernel_source, *helper_source, *functions]
    return "\n".join(parts)
