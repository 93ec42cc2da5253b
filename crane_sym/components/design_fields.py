"""The fields of a component file a sweep may vary, and a design's values read
as the file's own reader reads them.

A *field* is one value a component's table gives, or may give, named
``<component>.<key>`` with the key the file writes (``gearbox_mesh.stiffness``,
``hook.mass``, ``safety_brakes.delay``); a design gives it in SI, and the
part is rebuilt from the table's text with that value, so every check of the
file applies (:class:`crane_sym.components.designs.Designs`).
"""
from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache

from sympy.physics.units import Dimension
from sympy.physics.units.systems.si import dimsys_SI

from crane_sym import units
from crane_sym.components.kinds import by_table
from crane_sym.components.parts import Value

__all__ = ["Field", "given", "read_entry", "si_unit"]


@dataclass(frozen=True)
class Field:
    """A value of one component that a sweep may vary: ``<component>.<key>``,
    the file's text for it (None: not given, its default), its dimension, the
    sign it must keep (``positive``, ``nonnegative``, ``nonzero`` or ``""``)."""

    component: str
    table: str
    key: str
    text: str | None
    dimension: Dimension
    sign: str

    @property
    def name(self) -> str:
        return f"{self.component}.{self.key}"

    @property
    def unit(self) -> str:
        """The unit the file writes it in ("1" for a bare number), else SI."""
        if self.text is not None:
            return units.unit_text(self.text) or "1"
        return si_unit(self.dimension)


@lru_cache(maxsize=None)
def si_unit(dimension: Dimension) -> str:
    """The SI unit of ``dimension`` as :mod:`crane_sym.units` reads it
    (``kg*m^2*s^-2``; ``1`` for none): its factor to SI is exactly 1.

    Parameters
    ----------
    dimension : Dimension
        A dimension of mass, length, time and current.
    """
    deps = dimsys_SI.get_dimensional_dependencies(dimension)
    names = {"mass": "kg", "length": "m", "time": "s", "current": "A"}
    parts = [f"{names[str(k.name)]}" + ("" if p == 1 else f"^{int(p)}")
             for k, p in deps.items() if p]
    return "*".join(parts) or "1"


def _text(value: float, field: Field) -> str | float:
    """A value in SI as the file's reader takes it."""
    if by_table()[field.table].key(field.key).form == "number":
        return float(value)
    unit = si_unit(field.dimension)
    return repr(float(value)) + ("" if unit == "1" else f" {unit}")


def given(value: float, field: Field) -> Value | float:
    """:func:`_text` read as the parts' constructors read it (a :class:`Value`
    of its number in SI, its dimension and the text)."""
    text = _text(value, field)
    if not isinstance(text, str):
        return text
    q = units.parse_quantity(text)
    return Value(q.value, q.dimension, text)


def read_entry(kind: str, entry: dict) -> dict:
    """A table ``entry`` with each quantity's text read once into a
    :class:`Value` (a design's parts are built from it without parsing the
    keys it does not change); a text that is no quantity stays text."""
    forms = {k.name: k.form for k in by_table()[kind].keys}
    out = dict(entry)
    for key, v in entry.items():
        if forms.get(key) == "quantity" and isinstance(v, str):
            try:
                q = units.parse_quantity(v)
            except units.UnitError:
                continue                      # a word ("steady"), or refused as before
            out[key] = Value(q.value, q.dimension, v)
    return out
