"""The printers of generated code: NumPy source of an array expression, its
conditional form for one point, double-double source for the parameter-only
phase factors, and the module-level helper of each ``entire`` node (its
closed form above a cutoff, its Taylor series below)."""
from __future__ import annotations

from typing import Sequence

import sympy as sp
from sympy.printing.numpy import NumPyPrinter

from crane_sym.codegen.entire import Z, plan
from crane_sym.mechanics.involute import ACOS_MESSAGES
from crane_sym.codegen.waves import phase_cos, phase_sin

__all__ = ["Printer", "TernaryPrinter", "DoubleDoublePrinter", "printer_for", "render_helper"]


class Printer(NumPyPrinter):
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
        if expr.exp in (3, 4) and base.free_symbols:     # products, not the pow function
            return f"_{'cube' if expr.exp == 3 else 'fourth'}({self._print(base)})"
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


class DoubleDoublePrinter(Printer):
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


class TernaryPrinter(Printer):
    """Prints a Piecewise as a conditional expression (a call on scalars)."""

    def _print_Piecewise(self, expr: sp.Piecewise) -> str:
        text = self._print(expr.args[-1].expr)
        for branch, cond in reversed(expr.args[:-1]):
            text = f"{self._print(branch)} if {self._print(cond)} else {text}"
        return f"({text})"


def printer_for(helpers: dict[int, str] | None = None, kind: type = Printer) -> Printer:
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
    closed = printer_for().doprint(closed.xreplace({Z: zs}))
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
