"""Code generation: rewrite rules -> printer -> template -> file.

``render_module`` is pure (derivation in, source text out); ``write`` and
``stale`` are the only functions that touch files. Generated modules import
NumPy only, validate every argument, and evaluate parameter-only parts once
as scalars before the array work.
"""
from __future__ import annotations

import inspect
import re
from pathlib import Path
from typing import Iterable, Sequence

import sympy as sp
from sympy.printing.numpy import NumPyPrinter

from . import __version__, kernels
from .derivation import Derivation, Output
from .rewriting import Rule, cos_phase, optimize, rules_for, sin_phase
from .symbols import TIME, SymbolTable


class _Printer(NumPyPrinter):
    """NumPy printer that writes ``np.`` and full double precision floats."""

    def _module_format(self, fqn: str, register: bool = True) -> str:
        if fqn.startswith("numpy."):
            fqn = "np." + fqn[len("numpy."):]
        return super()._module_format(fqn, register=False)

    def _print_Float(self, expr: sp.Float) -> str:
        return repr(float(expr))

    def _print_Pi(self, expr: sp.Basic) -> str:
        return "np.pi"

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
        return super()._print_Pow(expr, rational=rational)


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


def _printer() -> _Printer:
    return _Printer({"fully_qualified_modules": True, "inline": True,
                     "allow_unknown_functions": False})


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
        k = next(names)
        assignments.append((k, e))
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


def _signature(out: Output) -> str:
    return f"{out.name}({', '.join(map(str, out.args))})"


def render_function(out: Output, table: SymbolTable,
                    rules: Sequence[Rule] | None = None) -> str:
    """Source of one validated, vectorized NumPy function."""
    printer = _printer()
    varying = {e.expr for e in table.with_role(TIME)} & set(out.args)
    rules = rules_for(varying) if rules is None else rules
    shape = out.expr.shape if isinstance(out.expr, sp.MatrixBase) else None
    if shape is None:
        expr = optimize(out.expr, rules)
        assignments, phases, body = hoist(expr, varying)
        subs, reduced = sp.cse([e for _, e in assignments] + [body],
                               symbols=sp.numbered_symbols("x"), order="canonical")
    else:  # a matrix: its elements share one CSE, no hoisting
        assignments, phases = [], []
        subs, reduced = sp.cse([optimize(e, rules) for e in out.expr],
                               symbols=sp.numbered_symbols("x"), order="canonical")
    entries = [table[a] for a in out.args]
    width = max((len(e.name) for e in entries), default=0)
    params = "\n".join(
        f"    {e.name} : array_like\n        {e.description} [{e.unit}]"
        + {"positive": ", > 0", "nonnegative": ", >= 0"}.get(e.sign, "")
        for e in entries)
    lines = [f"def {_signature(out)}:",
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
             '    """']
    for e in entries:
        what = f"{e.description}, {e.unit}".replace('"', "'")
        lines.append(f"    {e.name:<{width}} = _checked({e.name!r}, {e.name}, "
                     f"{e.sign!r}, {what!r})")
    # A scalar that CSE reduced to a bare name is inlined, not re-assigned.
    alias = {k: v for (k, _), v in zip(assignments, reduced[:-1]) if v.is_Atom}
    for sym, value in phases:
        lines.append(f"    {sym} = {_DoubleDoublePrinter().doprint(value)}")
    for sym, value in subs:
        lines.append(f"    {sym} = {printer.doprint(value)}")
    for (k, _), value in zip(assignments, reduced[:-1]):
        if k not in alias:
            lines.append(f"    {k} = {printer.doprint(value)}")
    if shape is not None:
        elements = ", ".join(printer.doprint(e) for e in reduced)
        lines.append(f"    return _matrix({tuple(shape)}, [{elements}])")
    else:
        lines.append(f"    return {printer.doprint(reduced[-1].xreplace(alias))}")
    return "\n".join(lines) + "\n"


def _kernel_source(functions: Sequence[str]) -> str:
    """Source of the kernels the function texts call, and their dependencies."""
    called = set(re.findall(r"\b(_[a-z_]+)\(", "\n".join(functions)))
    names = kernels.closure({"_checked"} | (called & set(kernels.DEPENDS)))
    return "\n\n".join(inspect.getsource(getattr(kernels, n)) for n in names)


def render_module(d: Derivation, outputs: Iterable[Output] | None = None,
                  rules: Sequence[Rule] | None = None, scene_note: str = "") -> str:
    """Full source of ``generated/<d.id>.py``; deterministic for a given
    derivation and SymPy version. ``scene_note`` describes a specialization."""
    outputs = list(d.outputs if outputs is None else outputs)
    labels = sorted({lab for o in outputs for lab in o.labels},
                    key=lambda s: (not s.startswith("("), len(s), s))
    listing = "\n".join(f"    {_signature(o)} -> [{o.unit}]    eq {', '.join(o.labels)}"
                        for o in outputs)
    header = (f'"""Numeric functions for derivation {d.id!r}. Generated; do not edit.\n\n'
              f"Source: crane_sym.derivations.{d.id} (paper {d.paper}:\n"
              f"{d.title}).\n"
              + (f"{scene_note}\n" if scene_note else "") +
              f"Equations: {', '.join(labels)}.\n"
              f"Printed by SymPy {sp.__version__} with crane_sym {__version__}; "
              "regenerate with `crane-sym generate`.\n\n"
              f"Functions and argument order:\n{listing}\n"
              '"""\n')
    names = ", ".join(repr(o.name) for o in outputs)
    functions = ["\n" + render_function(o, d.symbols, rules) for o in outputs]
    parts = [header, "import numpy as np\n", f"__all__ = [{names}]\n",
             "\n" + _kernel_source(functions), *functions]
    return "\n".join(parts)


def render_package_init(ids: Sequence[str]) -> str:
    """Source of ``generated/__init__.py``."""
    listing = "\n".join(f"    {i}" for i in ids)
    return ('"""Numeric modules generated by crane_sym. Do not edit; run\n'
            f'`crane-sym generate`.\n\nModules:\n{listing}\n"""\n')


def default_directory() -> Path:
    """The folder of ``crane_sym.generated`` (``generated/`` in a clone)."""
    import crane_sym.generated as package
    return Path(package.__file__).parent


def rendered(derivations: Sequence[Derivation],
             extra: dict[str, str] | None = None) -> dict[str, str]:
    """File name -> source for every derivation with outputs, plus ``extra``
    modules (scene-specialized ones), and the package's ``__init__``."""
    files = {f"{d.id}.py": render_module(d) for d in derivations if d.outputs}
    files.update(extra or {})
    files["__init__.py"] = render_package_init([name[:-3] for name in files])
    return files


def write(files: dict[str, str], directory: Path) -> list[Path]:
    """Write ``files`` into ``directory``; return the paths written."""
    directory.mkdir(parents=True, exist_ok=True)
    paths = []
    for name, text in sorted(files.items()):
        path = directory / name
        path.write_bytes(text.encode("utf-8"))
        paths.append(path)
    return paths


def stale(files: dict[str, str], directory: Path) -> list[str]:
    """Names of files that are missing or differ from what would be written."""
    out = []
    for name, text in sorted(files.items()):
        path = directory / name
        if not path.exists() or path.read_bytes() != text.encode("utf-8"):
            out.append(name)
    return out
