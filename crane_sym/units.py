"""Physical quantities written as text in scene files, converted to SI.

A quantity is a number followed by an optional unit expression, e.g.
``"50 t"``, ``"80 m/min"``, ``"20 kN*m/rad"``, ``"13 kg·m²"``, ``"1.2"``.

The text is read by a small hand-written parser; it is never passed to
``eval``, ``exec``, ``sympify`` or ``ast.literal_eval``.

Grammar of the unit expression
------------------------------
* unit names come from the explicit table :data:`UNITS` (no prefix magic);
* units are joined by ``*``, ``·``, ``⋅`` or ``.`` (multiply) and ``/`` (divide);
* a unit may carry an integer exponent: ``^2``, ``**2``, ``^-1``, ``²``, ``³``,
  ``⁻¹``;
* ``/`` applies only to the single unit right after it (with its exponent):
  ``"m/s/s"`` is m·s⁻², ``"kg/m*s"`` is kg·s/m, ``"kN*m/rad"`` is kN·m per rad;
* ``"1"`` or an empty unit means dimensionless.

Angles are dimensionless (rad = 1), so ``"kN*m/rad"`` has the dimension of a
torque, force*length.
"""
from __future__ import annotations

import difflib
import functools
import math
import numbers
import re
from dataclasses import dataclass

from sympy.physics.units import Dimension, current, force, length, mass, time
from sympy.physics.units.systems.si import dimsys_SI

__all__ = ["UNITS", "Quantity", "UnitError", "convert", "describe_dimension",
           "format_dimension", "parse_quantity", "parse_unit", "same_dimension", "unit_text"]

_ONE = Dimension(1)
_PI, _G0 = math.pi, 9.80665  # _G0: standard gravity in m/s^2

#: Every unit name the parser knows: name -> (factor to SI, dimension).
UNITS: dict[str, tuple[float, Dimension]] = {
    "1": (1.0, _ONE),
    # length (micrometre as um, micro sign µm or Greek mu μm)
    "m": (1.0, length), "km": (1e3, length), "cm": (1e-2, length), "mm": (1e-3, length),
    "um": (1e-6, length), "µm": (1e-6, length), "μm": (1e-6, length),
    # mass
    "kg": (1.0, mass), "g": (1e-3, mass), "mg": (1e-6, mass), "t": (1e3, mass),
    # time
    "s": (1.0, time), "ms": (1e-3, time), "min": (60.0, time), "h": (3600.0, time),
    # force
    "mN": (1e-3, force), "N": (1.0, force), "kN": (1e3, force), "MN": (1e6, force),
    "GN": (1e9, force), "kgf": (_G0, force), "tf": (1e3 * _G0, force),
    # pressure, energy, power
    "Pa": (1.0, force / length**2), "kPa": (1e3, force / length**2),
    "MPa": (1e6, force / length**2), "GPa": (1e9, force / length**2),
    "J": (1.0, force * length), "kJ": (1e3, force * length),
    "W": (1.0, force * length / time), "kW": (1e3, force * length / time),
    "MW": (1e6, force * length / time),
    # angles (dimensionless) and rotational speed / frequency
    "rad": (1.0, _ONE), "deg": (_PI / 180.0, _ONE), "rev": (2.0 * _PI, _ONE),
    "rpm": (2.0 * _PI / 60.0, 1 / time), "Hz": (1.0, 1 / time),
    # electrical (a DC motor's armature): current, voltage, resistance, inductance
    "A": (1.0, current), "V": (1.0, force * length / (time * current)),
    "kV": (1e3, force * length / (time * current)),
    "ohm": (1.0, force * length / (time * current**2)),
    "H": (1.0, force * length / current**2), "mH": (1e-3, force * length / current**2),
}


class UnitError(ValueError):
    """Every error raised by this module (bad text, unknown unit, wrong dimension)."""


@dataclass(frozen=True)
class Quantity:
    """A parsed quantity: ``value`` in SI, its SymPy ``dimension``, the original ``text``."""

    value: float
    dimension: Dimension
    text: str


_MAX_TEXT = 200
_NUMBER = re.compile(
    r"\s*([+-]?(?:(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?|(?:inf(?:inity)?|nan)(?![A-Za-z])))",
    re.IGNORECASE)
_NAME = re.compile(r"[A-Za-zµμ]+|1(?![\d.])")
_POWER = re.compile(r"\s*(?:\^|\*\*)\s*([+-]?\d+)")
_MAX_POWER = 12
_SUPERSCRIPT = re.compile(r"⁻?[⁰¹²³⁴⁵⁶⁷⁸⁹]+")
_SUP_DIGITS = str.maketrans("⁻⁰¹²³⁴⁵⁶⁷⁸⁹", "-0123456789")
_MULTIPLY = re.compile(r"\s*([*·⋅.]|/)\s*")


def parse_unit(text: str) -> tuple[float, Dimension]:
    """Parse a unit expression such as ``"kN*m/rad"``.

    Parameters
    ----------
    text : str
        Unit expression; empty or ``"1"`` means dimensionless.

    Returns
    -------
    tuple of (float, Dimension)
        Factor to SI and dimension, e.g. ``(1000.0, force*length)``.
    """
    num, den, dim = _parse_unit(text)
    return num / den, dim


def _parse_unit(text: str) -> tuple[float, float, Dimension]:
    """Return (numerator, denominator, dimension); kept apart for exact rounding."""
    if not isinstance(text, str):
        raise UnitError(f"unit must be text, got {type(text).__name__}")
    return _parse_unit_text(text)


@functools.lru_cache(maxsize=1024)
def _parse_unit_text(text: str) -> tuple[float, float, Dimension]:
    """:func:`_parse_unit` of a text, cached (SymPy's powers of dimensions cost
    ~0.1 ms each; a sweep of a component file reads its units once a design)."""
    if len(text) > _MAX_TEXT:
        raise UnitError(f"text longer than {_MAX_TEXT} characters")
    text, num, den, dim = text.strip(), 1.0, 1.0, _ONE
    pos, sign = 0, 1
    while pos < len(text):
        m = _NAME.match(text, pos)
        if m is None:
            raise UnitError(f"expected a unit name at {text[pos:]!r}")
        name = m.group()
        if name not in UNITS:
            close = difflib.get_close_matches(name, list(UNITS), n=5, cutoff=0.5)
            hint = ("did you mean " + ", ".join(repr(c) for c in close) + "?" if close
                    else "known units: " + ", ".join(sorted(UNITS)))
            raise UnitError(f"unknown unit {name!r}; {hint}")
        pos, power = m.end(), 1
        m = _POWER.match(text, pos) or _SUPERSCRIPT.match(text, pos)
        if m is not None:
            digits = m.group(1) if m.re is _POWER else m.group().translate(_SUP_DIGITS)
            power, pos = int(digits), m.end()  # text is <= 200 characters
            if not 0 < abs(power) <= _MAX_POWER:
                raise UnitError(f"exponent {digits} of {name!r} not in 1..{_MAX_POWER}")
        f, d = UNITS[name]
        power *= sign
        if power >= 0:
            num *= f ** power
        else:
            den *= f ** -power
        dim = dim * d ** power
        if pos == len(text):
            break
        m = _MULTIPLY.match(text, pos)
        if m is None or m.end() == len(text):
            raise UnitError(f"expected '*', '·', '.' or '/' then a unit at {text[pos:]!r}")
        sign = -1 if m.group(1) == "/" else 1
        pos = m.end()
    return num, den, dim


def parse_quantity(text: str) -> Quantity:
    """Parse ``"<number> [unit]"`` into a :class:`Quantity` in SI.

    Parameters
    ----------
    text : str
        E.g. ``"50 t"``, ``"80 m/min"``, ``"-2.5e-3 m"``, ``"1.2"``.

    Returns
    -------
    Quantity
    """
    if not isinstance(text, str):
        raise UnitError(f"quantity must be text, got {type(text).__name__}")
    if not text.strip():
        raise UnitError("empty quantity")
    if len(text) > _MAX_TEXT:
        raise UnitError(f"text longer than {_MAX_TEXT} characters")
    m = _NUMBER.match(text)
    if m is None:
        raise UnitError(f"{text!r} must start with a number, e.g. '50 t'")
    number = float(m.group(1))  # the regex admits only float literals
    if not math.isfinite(number):
        raise UnitError(f"{text!r}: value must be finite")
    try:
        num, den, dim = _parse_unit(text[m.end():])
    except UnitError as exc:
        raise UnitError(f"{text!r}: {exc}") from None
    value = number * num / den
    if not math.isfinite(value):
        raise UnitError(f"{text!r}: value must be finite (overflow in SI)")
    return Quantity(value, dim, text)


def unit_text(text: str) -> str:
    """The unit part of a quantity as written: ``"4.4 t"`` -> ``"t"``, ``"1.2"`` -> ``""``
    (checked by :func:`parse_quantity` first).

    Parameters
    ----------
    text : str
        A quantity as written, e.g. ``"4.4 t"``.
    """
    parse_quantity(text)
    return text[_NUMBER.match(text).end():].strip()


#: :func:`_dependencies` by the identity of a dimension met before (a part's
#: declared dimension is one object; SymPy's ``==`` on a cache hit costs ~10 µs).
_BY_ID: dict[int, tuple[Dimension, tuple[tuple[str, int], ...]]] = {}


def _deps(d: Dimension) -> dict[str, int]:
    kept = _BY_ID.get(id(d))
    if kept is None or kept[0] is not d:
        if len(_BY_ID) > 4096:          # parsed texts' dimensions are new objects
            _BY_ID.clear()
        kept = _BY_ID[id(d)] = (d, _dependencies(d))
    return dict(kept[1])


@functools.lru_cache(maxsize=1024)
def _dependencies(d: Dimension) -> tuple[tuple[str, int], ...]:
    """SI base dimensions of ``d`` (cached: SymPy takes ~0.15 ms a call, and a
    sweep of a component file checks every part's dimension once a design)."""
    return tuple((str(k.name), int(v))
                 for k, v in dimsys_SI.get_dimensional_dependencies(d).items() if v != 0)


def same_dimension(a: Dimension, b: Dimension) -> bool:
    """True if ``a`` and ``b`` reduce to the same SI base dimensions.

    Parameters
    ----------
    a, b : Dimension
        SymPy dimensions.
    """
    return _deps(a) == _deps(b)


_ORDER = ("mass", "length", "time")


def format_dimension(d: Dimension) -> str:
    """Canonical base form, e.g. ``"mass*length/time**2"`` or ``"dimensionless"``.

    Parameters
    ----------
    d : Dimension
        A SymPy dimension.
    """
    deps = _deps(d)
    names = sorted(deps, key=lambda n: (_ORDER.index(n) if n in _ORDER else 9, n))
    if not names:
        return "dimensionless"

    def part(ns: list[str], sgn: int) -> str:
        return "*".join(n if sgn * deps[n] == 1 else f"{n}**{sgn * deps[n]}" for n in ns)

    up = [n for n in names if deps[n] > 0]
    down = [n for n in names if deps[n] < 0]
    text = part(up, 1) if up else "1"
    if down:
        text += "/" + (part(down, -1) if len(down) == 1 else f"({part(down, -1)})")
    return text


# (mass, length, time) exponents -> (readable name, example unit), for messages.
_NAMED = {
    (0, 0, 0): ("dimensionless", "1 or rad"), (1, 0, 0): ("mass", "kg"),
    (0, 1, 0): ("length", "m"), (0, 0, 1): ("time", "s"),
    (0, 0, -1): ("1/time", "rad/s, rpm or Hz"), (0, 1, -1): ("velocity", "m/s"),
    (0, 1, -2): ("acceleration", "m/s^2"), (1, 1, -2): ("force", "N"),
    (1, 0, -2): ("force/length", "N/m"), (1, 2, -2): ("force*length", "N*m"),
    (1, 0, -1): ("force*time/length", "N*s/m"), (1, 2, -1): ("force*length*time", "N*m*s"),
    (1, -1, -2): ("pressure", "Pa"), (1, 2, -3): ("power", "W"),
    (1, 2, 0): ("mass*length**2", "kg*m^2"),
}


def describe_dimension(d: Dimension) -> str:
    """A dimension as messages name it: ``"mass (e.g. kg)"``, ``"force/length (e.g. N/m)"``.

    Parameters
    ----------
    d : Dimension
        A SymPy dimension.
    """
    return _describe(d)


def _describe(d: Dimension, example: bool = True) -> str:
    deps = _deps(d)
    key = tuple(deps.get(n, 0) for n in _ORDER)
    if set(deps) <= set(_ORDER) and key in _NAMED:
        name, unit = _NAMED[key]
        return f"{name} (e.g. {unit})" if example else name
    return format_dimension(d)


def _real(x: object) -> float:
    """A finite float from a real number (not bool), else UnitError."""
    if isinstance(x, bool) or not isinstance(x, numbers.Real):
        raise UnitError(f"expected a number, got {x!r}")
    try:
        f = float(x)
    except (OverflowError, ValueError, TypeError):
        f = math.inf
    if not math.isfinite(f):
        raise UnitError(f"value must be finite, got {x!r}")
    return f


def convert(name: str, value: object, expected: Dimension, what: str = "parameter") -> float:
    """Convert a scene parameter to an SI float, checking its dimension.

    Parameters
    ----------
    name : str
        Parameter name, used in every error message.
    value : str, dict or number
        ``"50 t"``, ``{"value": 50, "unit": "t"}``, or a bare int/float
        (only when ``expected`` is dimensionless).
    expected : Dimension
        Required dimension.
    what : str
        What ``name`` is, for the messages (``"parameter"``, ``"option"``).

    Returns
    -------
    float
        The value in SI units.
    """
    if isinstance(value, bool):
        raise UnitError(f"{what} {name!r} expects a quantity, got a boolean {value}")
    bare = isinstance(value, numbers.Real)
    try:
        if bare:
            text, number, dim = repr(value), _real(value), _ONE
        elif isinstance(value, dict):
            if set(value) - {"value", "unit"} or "value" not in value:
                raise UnitError("a dict needs the keys 'value' and 'unit', "
                                f"got {sorted(map(str, value))}")
            unit = value.get("unit", "")
            if not isinstance(unit, str):
                raise UnitError(f"'unit' must be text, got {unit!r}")
            factor, dim = parse_unit(unit)
            text = f"{value['value']} {unit}".strip()
            number = _real(_real(value["value"]) * factor)
        elif isinstance(value, str):
            q = parse_quantity(value)
            text, number, dim = value, q.value, q.dimension
        else:
            raise UnitError(f"expected text like '50 t', got {type(value).__name__}")
    except UnitError as exc:
        raise UnitError(f"{what} {name!r}: {exc}") from None
    if bare and not same_dimension(expected, _ONE):
        raise UnitError(f"{what} {name!r} needs a unit of {_describe(expected)}, "
                        f"got a bare number {value!r}")
    if not same_dimension(dim, expected):
        raise UnitError(f"{what} {name!r} expects {_describe(expected)}, got "
                        f"{text!r} which is {_describe(dim, example=False)}")
    return number
