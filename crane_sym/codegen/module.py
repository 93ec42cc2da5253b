"""Code generation: rewrite rules -> printer -> template -> file.

``render_module`` is pure (derivation in, source text out); the files are
written and compared by :mod:`crane_sym.codegen.files`. Generated
modules import NumPy only, validate every argument, and evaluate
parameter-only parts once as scalars before the array work.
"""
from __future__ import annotations

import inspect
import re
import textwrap
from typing import Iterable, Mapping, Sequence

import sympy as sp

from crane_sym import __version__
from crane_sym.kernels import cells as cell_kernels
from crane_sym.kernels import gears as gear_kernels
from crane_sym.kernels import arithmetic as kernels
from crane_sym.kernels import phase as phase_kernels
from crane_sym.codegen.cells import pieces, statements
from crane_sym.derivation import Derivation, Output, TabulatedOutput
from crane_sym.codegen.inplace import blocked, chain
from crane_sym.mechanics.phase_table import PhaseTable
from crane_sym.codegen.printers import DoubleDoublePrinter, TernaryPrinter, printer_for, render_helper
from crane_sym.codegen.rewriting import Rule, cos_phase, optimize, rules_for, sin_phase
from crane_sym.codegen.scalar_path import fast_path, literal, serves_literal
from crane_sym.repeatable import fixed_sympy_draws
from crane_sym.symbols import TIME, SymbolTable
from crane_sym.codegen.tabulated import render_tabulated
from crane_sym.codegen.wave_sums import merge_waves


#: Modules whose kernels generated code may call, in the order they are copied.
KERNEL_MODULES = (kernels, phase_kernels, gear_kernels, cell_kernels)


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


def _rules(out: Output, table: SymbolTable, rules: Sequence[Rule] | None
           ) -> tuple[set[sp.Symbol], Sequence[Rule]]:
    """The time-like arguments of ``out`` and the rewrite rules it is printed with."""
    varying = {e.expr for e in table.with_role(TIME)} & set(out.args)
    scales = frozenset(a for a in out.args if a not in varying and any(
        table[a].dimension == table[v].dimension for v in varying))
    return varying, (rules_for(varying, scales) if rules is None else rules)


def used_arguments(out: Output, table: SymbolTable) -> tuple[sp.Symbol, ...]:
    """The arguments of a scalar ``out`` its generated function computes
    with: those left in the expression the printer receives. An exact rewrite
    may cancel one (a ratio of two masses written with Ω); the function still
    accepts and validates it.

    Parameters
    ----------
    out : Output
        A scalar output.
    table : SymbolTable
        The derivation's symbols.
    """
    free = optimize(out.expr, _rules(out, table, None)[1]).free_symbols
    return tuple(a for a in out.args if a in free)


def render_function(out: Output, table: SymbolTable,
                    rules: Sequence[Rule] | None = None,
                    helpers: dict[int, str] | None = None) -> str:
    """Source of one validated, vectorized NumPy function; the ``entire``
    helpers it calls are named in ``helpers`` (key -> name)."""
    printer = printer_for(helpers)
    varying, rules = _rules(out, table, rules)
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
        + f"; served from {literal(e.serves[0])} to {literal(e.serves[1])}"
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
                     f"{e.sign!r}, {what!r}, {serves_literal(e.serves)})")
    call = textwrap.wrap(", ".join(f"{e.name}={e.name}" for e in entries) + ")",
                         width=80, break_long_words=False, break_on_hyphens=False)
    lines.append("    shape = _broadcast(" + call[0])
    lines += [" " * 23 + rest for rest in call[1:]]
    lines += [f"    _required({printer.doprint(e)}, {what!r})" for e, what in out.requires]
    for sym, value in phases:
        lines.append(f"    {sym} = {DoubleDoublePrinter().doprint(value)}")
    heavy = set(varying)
    for sym, value in subs:                      # array temporaries of the CSE
        if value.free_symbols & heavy:
            heavy.add(sym)
    block = (shape is None and not split and not phases    # a block of points at a time
             and bool(reduced[-1].free_symbols & heavy))
    for sym, value in named:                     # a block's temporaries in its loop
        if not (block and sym in heavy):
            lines.append(f"    {sym} = {printer.doprint(value)}")
    if shape is not None:
        elements = ", ".join(printer.doprint(e) for e in reduced)
        lines.append(f"    return _matrix({tuple(shape)}, [{elements}])")
    elif block:
        final = reduced[-1].xreplace(alias)
        temporaries = [(sym, value) for sym, value in named if sym in heavy]
        read = final.free_symbols.union(*[v.free_symbols for _, v in temporaries])
        read = {str(r) for r in read}
        names = [n for n in [e.name for e in entries] + [str(s) for s, _ in named
                                                         if s not in heavy] if n in read]
        lines += [f"    {s}" for s in blocked(final, temporaries, names, heavy,
                                              printer.doprint)]
    else:
        final = reduced[-1].xreplace(alias)
        taken = {e.name for e in entries} | {str(s) for s, _ in subs} | {
            str(k) for k, _ in assignments}
        merge = ((lambda cell: merge_waves(cell, next(iter(varying))))
                 if len(varying) == 1 else (lambda cell: None))
        cells = statements(final, printer.doprint, printer_for(helpers, TernaryPrinter).doprint,
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


def kernel_functions(text: str) -> dict:
    """The kernels ``text`` calls (and ``_checked``), with the kernels they call:
    name -> function, in the order a module copies them."""
    called = set(re.findall(r"\b(_[a-z_A-Z]+)\(", text))
    home = {n: m for m in KERNEL_MODULES for n in m.DEPENDS}
    depends = {n: d for m in KERNEL_MODULES for n, d in m.DEPENDS.items()}
    names = kernels.closure({"_checked"} | (called & set(depends)), depends)
    return {n: getattr(home[n], n) for n in names}


def _kernel_source(functions: Sequence[str]) -> str:
    """Source of the kernels the function texts call, and their dependencies."""
    found = kernel_functions("\n".join(functions))
    return "\n\n".join(inspect.getsource(f) for f in found.values())


def docstring_text(text: str) -> str:
    """``text`` made safe inside a module's triple-quoted docstring: no
    backslash (no escape, no ``\\N{...}``), no double quote (nothing can close
    the docstring), no control character but the newline. Text a user gave is
    also kept whole, as a literal (:func:`render_module`'s ``constants``).

    Parameters
    ----------
    text : str
        Any text, a user's included.
    """
    text = text.replace("\\", "/").replace('"', "'")
    return "".join(c if c == "\n" or c.isprintable() else " " for c in text)


@fixed_sympy_draws()
def render_module(d: Derivation, outputs: Iterable[Output] | None = None,
                  rules: Sequence[Rule] | None = None, scene_note: str = "",
                  tables: Sequence[tuple[TabulatedOutput, PhaseTable]] = (),
                  regenerate: str = "crane-sym generate",
                  constants: Mapping[str, str] = {}) -> str:
    """Full source of ``generated/<d.id>.py``; deterministic for a given
    derivation and SymPy version. ``scene_note`` describes a specialization;
    ``tables`` are a scene's tabulated responses (``crane_sym.codegen.tabulated``);
    ``regenerate`` is the command the header names to write the file again.
    Both may carry a user's text: they pass :func:`docstring_text`.
    ``constants`` (name -> text) become module constants printed with
    ``repr``, a literal whatever the text (a scene's title).

    Parameters
    ----------
    d : Derivation
        The built derivation.
    outputs : iterable of Output, optional
        The functions to print (default: ``d.outputs``).
    rules : sequence of Rule, optional
        Rewrite rules (default: the printer's).
    scene_note : str, optional
        What the specialization fixed, for the header.
    tables : sequence of (TabulatedOutput, PhaseTable), optional
        A scene's tabulated responses.
    regenerate : str, optional
        The command the header names.
    constants : mapping of str to str, optional
        Module constants (name -> text).
    """
    if not d.code:                           # an empty module would pass for one
        raise ValueError(f"{d.id} was built without its outputs (code=False): "
                         "build it with registry.get(id) to print its module")
    scene_note, regenerate = docstring_text(scene_note), docstring_text(regenerate)
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
              f"regenerate with `{regenerate}`.\n\n"
              f"Functions and argument order:\n{listing}\n"
              '"""\n')
    names = ", ".join(repr(o.name) for o in [*outputs, *(t for t, _ in tables)])
    helpers: dict[int, str] = {}
    functions = ["\n" + render_function(o, d.symbols, rules, helpers) for o in outputs]
    functions += ["\n" + render_tabulated(o, table, "Solved for this scene phase by "
                                           "phase in mpmath (crane_sym.mechanics.exact_phases).") for o, table in tables]
    helper_source = ["\n" + render_helper(key, name) for key, name in helpers.items()]
    kernel_source = _kernel_source(functions + helper_source)
    uses_math = any("math." in f for f in [*functions, kernel_source])
    literals = "".join(f"{key} = {value!r}\n" for key, value in constants.items()
                       if key.isidentifier() and key.isupper())
    parts = [header, ("import math\n\n" if uses_math else "") + "import numpy as np\n",
             f"__all__ = [{names}]\n" + (f"\n{literals}" if literals else ""),
             "\n" + kernel_source, *helper_source, *functions]
    return "\n".join(parts)
