"""Code generation: rewrite rules -> printer -> template -> file.

``render_module`` is pure (derivation in, source text out); ``write`` and
``stale`` are the only functions that touch files. Generated modules import
NumPy only, validate every argument, and evaluate parameter-only parts once
as scalars before the array work.
"""
from __future__ import annotations

from pathlib import Path
from typing import Iterable, Sequence

import sympy as sp
from sympy.printing.numpy import NumPyPrinter

from . import __version__
from .derivation import Derivation, Output
from .rewriting import DEFAULT_RULES, Rule, optimize
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

    def _print_Pow(self, expr: sp.Pow, rational: bool = False) -> str:
        if expr.exp == -1:
            return "1/" + self.parenthesize(expr.base, 1000)
        return super()._print_Pow(expr, rational=rational)


def _printer() -> _Printer:
    return _Printer({"fully_qualified_modules": True, "inline": True,
                     "allow_unknown_functions": False})


def hoist(expr: sp.Expr, varying: set[sp.Symbol]) -> tuple[list[tuple[sp.Symbol, sp.Expr]], sp.Expr]:
    """Pull every parameter-only factor or term out of the array expression.

    Returns ``(assignments, expr)``: scalar assignments ``k_i = ...`` that do
    not depend on ``varying``, and the remaining expression in the ``k_i``.
    """
    names = sp.numbered_symbols("k")
    assignments: list[tuple[sp.Symbol, sp.Expr]] = []

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
        if isinstance(e, (sp.Add, sp.Mul)):
            consts = [a for a in e.args if fixed(a)]
            moving = [visit(a) for a in e.args if not fixed(a)]
            head = [name(e.func(*consts))] if consts else []
            return e.func(*head, *moving)
        if isinstance(e, sp.Pow) and fixed(e.exp):
            return sp.Pow(visit(e.base), e.exp)
        return e.func(*[visit(a) for a in e.args])

    if fixed(expr):
        return [], expr
    return assignments, visit(expr)


_VALIDATE = '''
def _checked(name, value, sign, what):
    """``value`` as a float array; ValueError naming ``name`` if it is not a
    finite number of the required sign, TypeError if it is not a number."""
    if isinstance(value, (str, bytes)):
        raise TypeError(f"{name} must be a number or array of numbers "
                        f"({what}), got a string {value!r}")
    array = np.asarray(value)
    if array.dtype.kind not in "iuf":
        raise TypeError(f"{name} must be a number or array of numbers "
                        f"({what}), got dtype {array.dtype}")
    array = array.astype(float, copy=False)
    if array.size == 0:
        return array
    low, high = array.min(), array.max()
    if not (np.isfinite(low) and np.isfinite(high)):
        raise ValueError(f"{name} must be finite ({what}), got a NaN or inf")
    if sign == "positive" and not low > 0:
        raise ValueError(f"{name} must be > 0 ({what}), got {low!r}")
    if sign == "nonnegative" and not low >= 0:
        raise ValueError(f"{name} must be >= 0 ({what}), got {low!r}")
    return array
'''


def _signature(out: Output) -> str:
    return f"{out.name}({', '.join(map(str, out.args))})"


def render_function(out: Output, table: SymbolTable,
                    rules: Sequence[Rule] = DEFAULT_RULES) -> str:
    """Source of one validated, vectorized NumPy function."""
    printer = _printer()
    expr = optimize(out.expr, rules)
    varying = {e.expr for e in table.with_role(TIME)} & set(out.args)
    assignments, body = hoist(expr, varying)
    subs, reduced = sp.cse([e for _, e in assignments] + [body],
                           symbols=sp.numbered_symbols("x"), order="canonical")
    entries = [table[a] for a in out.args]
    width = max(len(e.name) for e in entries)
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
             f"        [{out.unit}], broadcast over the arguments.",
             '    """']
    for e in entries:
        what = f"{e.description}, {e.unit}".replace('"', "'")
        lines.append(f"    {e.name:<{width}} = _checked({e.name!r}, {e.name}, "
                     f"{e.sign!r}, {what!r})")
    # A scalar that CSE reduced to a bare name is inlined, not re-assigned.
    alias = {k: v for (k, _), v in zip(assignments, reduced[:-1]) if v.is_Atom}
    for sym, value in subs:
        lines.append(f"    {sym} = {printer.doprint(value)}")
    for (k, _), value in zip(assignments, reduced[:-1]):
        if k not in alias:
            lines.append(f"    {k} = {printer.doprint(value)}")
    lines.append(f"    return {printer.doprint(reduced[-1].xreplace(alias))}")
    return "\n".join(lines) + "\n"


def render_module(d: Derivation, outputs: Iterable[Output] | None = None,
                  rules: Sequence[Rule] = DEFAULT_RULES) -> str:
    """Full source of ``generated/<d.id>.py``; deterministic for a given
    derivation and SymPy version."""
    outputs = list(d.outputs if outputs is None else outputs)
    labels = sorted({lab for o in outputs for lab in o.labels},
                    key=lambda s: (not s.startswith("("), len(s), s))
    listing = "\n".join(f"    {_signature(o)} -> [{o.unit}]    eq {', '.join(o.labels)}"
                        for o in outputs)
    header = (f'"""Numeric functions for derivation {d.id!r}. Generated; do not edit.\n\n'
              f"Source: crane_sym.derivations.{d.id} (paper {d.paper}:\n"
              f"{d.title}).\n"
              f"Equations: {', '.join(labels)}.\n"
              f"Printed by SymPy {sp.__version__} with crane_sym {__version__}; "
              "regenerate with `crane-sym generate`.\n\n"
              f"Functions and argument order:\n{listing}\n"
              '"""\n')
    names = ", ".join(repr(o.name) for o in outputs)
    parts = [header, "import numpy as np\n", f"__all__ = [{names}]\n", _VALIDATE]
    parts += ["\n" + render_function(o, d.symbols, rules) for o in outputs]
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


def rendered(derivations: Sequence[Derivation]) -> dict[str, str]:
    """File name -> source for every derivation with outputs."""
    files = {f"{d.id}.py": render_module(d) for d in derivations if d.outputs}
    files["__init__.py"] = render_package_init([d.id for d in derivations if d.outputs])
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
