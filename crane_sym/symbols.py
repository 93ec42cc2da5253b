"""Physical symbols: a SymPy symbol with its dimension, unit, role and range.

A derivation's symbol table is what the audit samples from, what the dimension
check reads, and what the code generator turns into validated parameters.
"""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import Iterator

import sympy as sp
from sympy.physics.units import Dimension

#: Roles a symbol plays in a derivation.
PARAMETER = "parameter"    # data of the problem (masses, stiffness, forces)
TIME = "time"              # the independent variable
COORDINATE = "coordinate"  # an unknown function of time, x(t)
DEFINED = "defined"        # a quantity a step defines (p, A, B, F, ...)
STATE = "state"            # a component of the state vector a solver passes in

_ROLES = (PARAMETER, TIME, COORDINATE, DEFINED, STATE)
_SIGNS = ("positive", "nonnegative", "real", "negative")
#: How far beyond a symbol's physical range its generated functions serve.
SERVE_FACTOR = 1e6


@dataclass(frozen=True)
class PhysicalSymbol:
    """One symbol of a derivation.

    Parameters
    ----------
    expr : sympy.Symbol or applied sympy.Function
        The SymPy object, e.g. ``Symbol('m1', positive=True)`` or ``x1(t)``.
    dimension : sympy.physics.units.Dimension
        Physical dimension, e.g. ``mass`` or ``force/length``.
    unit : str
        SI unit used in documentation and generated docstrings.
    description : str
        What the symbol is, in the paper's words.
    role : str
        One of ``parameter``, ``time``, ``coordinate``, ``defined``.
    sign : str
        ``positive``, ``nonnegative``, ``real`` or ``negative`` (a value a
        component file gives below zero, sampled at its own sign): the
        admissible sign, checked by generated code and used when sampling.
    sample_range : (float, float)
        Physical range (SI) sampled log-uniformly by the numeric check.
    serve_range : (float, float), optional
        Magnitudes (SI) the generated functions accept (:attr:`serves`), where
        the physics bounds them more tightly than the default (a friction
        coefficient, a profile angle below π/2).
    """

    expr: sp.Expr
    dimension: Dimension
    unit: str
    description: str
    role: str = PARAMETER
    sign: str = "positive"
    sample_range: tuple[float, float] = (0.5, 2.0)
    serve_range: tuple[float, float] | None = None

    def __post_init__(self) -> None:
        if self.role not in _ROLES:
            raise ValueError(f"role must be one of {_ROLES}, got {self.role!r}")
        if self.sign not in _SIGNS:
            raise ValueError(f"sign must be one of {_SIGNS}, got {self.sign!r}")
        lo, hi = self.sample_range
        if not 0 < lo <= hi:
            raise ValueError(f"sample_range of {self.name} must satisfy 0 < lo <= hi")
        if self.serve_range is not None and not 0 < self.serve_range[0] <= lo <= hi \
                <= self.serve_range[1]:
            raise ValueError(f"serve_range of {self.name} must hold sample_range")

    @property
    def serves(self) -> tuple[float, float]:
        """(low, high): the values (SI) a generated function accepts for this
        symbol and returns a finite value for. ``serve_range``, or
        ``SERVE_FACTOR`` times beyond ``sample_range`` each way; from 0 for a
        nonnegative symbol, from −high for a real one, −high to −low for a negative one."""
        lo, hi = self.serve_range or (float(f"{self.sample_range[0] / SERVE_FACTOR:.6g}"),
                                      float(f"{self.sample_range[1] * SERVE_FACTOR:.6g}"))
        return {"positive": (lo, hi), "nonnegative": (0.0, hi),
                "negative": (-hi, -lo)}.get(self.sign, (-hi, hi))

    @property
    def name(self) -> str:
        """The name used in generated code (``m1``, ``P_t``)."""
        if isinstance(self.expr, sp.Symbol):
            return self.expr.name
        return type(self.expr).__name__


@dataclass
class SymbolTable:
    """Ordered table of the physical symbols of one derivation."""

    entries: list[PhysicalSymbol] = field(default_factory=list)

    def __iter__(self) -> Iterator[PhysicalSymbol]:
        return iter(self.entries)

    def __len__(self) -> int:
        return len(self.entries)

    def __getitem__(self, key: sp.Basic | str) -> PhysicalSymbol:
        for entry in self.entries:
            if entry.expr == key or entry.name == key:
                return entry
        raise KeyError(f"no symbol {key!r} in the table")

    def __contains__(self, key: object) -> bool:
        return any(e.expr == key or e.name == key for e in self.entries)

    def with_role(self, *roles: str) -> list[PhysicalSymbol]:
        """Entries with any of the given roles, in table order."""
        return [e for e in self.entries if e.role in roles]

    def dimensions(self) -> dict[sp.Basic, Dimension]:
        """Map from SymPy object to dimension, for the dimension check."""
        return {e.expr: e.dimension for e in self.entries}
