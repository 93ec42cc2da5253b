"""A template's lambdified equations over arrays of designs: the designs of one
template (``Model.with_parts``, ``Equations.for_design``) share Lagrange's
equations and differ in their parts' values, so a mode's M, D, K and f for all
of them are one call of the template's flattened lambdified form on their
parameter values stacked, a column each (:func:`template_numbers`,
:func:`numbers_of`), which :class:`~crane_sym.components.design_arrays.DesignArray`
takes as its ``numbers`` (:func:`evaluated`).
"""
from __future__ import annotations

from typing import Any, Callable, Sequence

import numpy as np
import sympy as sp

from crane_sym.components.mode_numbers import mode_linear
from crane_sym.components.modes import Mode

__all__ = ["evaluated", "numbers_of", "one_template", "template", "template_numbers"]

#: The flattened lambdified form of each template's (M, D, K, f), by the
#: identity of its ``Equations.linear`` (kept with it, so the key stays its own).
_FLAT: dict[int, tuple[Any, tuple[sp.Symbol, ...], Callable]] = {}


def _flat_form(equations) -> tuple[tuple[sp.Symbol, ...], Callable]:
    """(parameters, fn): fn(χ, δ, on, B, β, L, s, parameter values) -> the
    entries of M, D, K and f in a flat list, each a number or an array of
    designs (SymPy prints a constant entry as a number: broadcast by the caller)."""
    linear = equations.linear
    kept = _FLAT.get(id(linear))
    if kept is None or kept[0] is not linear:
        parameters = tuple(sorted({*equations.values, *equations.motor_loads}, key=str))
        entries = [e for m in linear for e in m]
        arguments = [list(equations.contact), list(equations.flank), list(equations.switches),
                     list(equations.friction), list(equations.slopes), list(equations.signals),
                     list(equations.states), list(parameters)]
        kept = _FLAT[id(linear)] = (linear, parameters, sp.lambdify(arguments, entries, "numpy"))
    return kept[1], kept[2]


def template(system) -> int | None:
    """The template a design's system shares with the other designs of it (the
    identity of its equations' lambdified form, ``Equations.for_design``), or
    None for a model derived on its own."""
    equations = system.equations
    return id(equations.linear) if equations.shared else None


def one_template(systems: Sequence) -> bool:
    """Whether ``systems`` are designs of one template (:func:`template`):
    what :class:`DesignArray` stacks."""
    first = template(systems[0])
    return first is not None and all(template(s) == first for s in systems)


def template_numbers(systems: Sequence) -> Callable:
    """The (M, D, K, f) of ``systems`` (designs of one template) as one
    evaluation: (χ, δ, on, B, β, L, s) -> arrays with a leading axis of
    designs; δ, on and β arrays of (designs, values)."""
    return numbers_of(systems[0].equations, lambda parameters: np.array(
        [[{**s.equations.values, **s.extra}.get(p, np.nan) for p in parameters]
         for s in systems], dtype=float))


def numbers_of(equations, given: Callable[[tuple[sp.Symbol, ...]], np.ndarray]) -> Callable:
    """:func:`template_numbers` of designs whose parameter values
    ``given(parameters)`` gives, (designs, parameters) in the order of the
    template's lambdified form."""
    parameters, fn = _flat_form(equations)
    return _evaluator(fn, given(parameters), equations)


def _evaluator(fn: Callable, given: np.ndarray, equations) -> Callable:
    linear = equations.linear
    shapes = [m.shape for m in linear]
    laws, states_ = len(equations.signals), len(equations.states)

    def evaluate(chi, delta, on, friction, slopes, signals=(), states=(), rows=None):
        signals = list(signals) or [0.0] * laws
        states = list(states) or [0.0] * states_
        values = given if rows is None else given[rows]
        k = len(values)
        columns = [values[:, j] for j in range(values.shape[1])]
        flat = fn(list(chi), list(np.asarray(delta, float).T), list(np.asarray(on, float).T),
                  list(friction), list(np.asarray(slopes, float).T), list(signals),
                  list(states), columns)
        out, at = [], 0
        for rows_, cols in shapes:
            block = np.empty((k, rows_ * cols))
            for j in range(rows_ * cols):
                block[:, j] = flat[at + j]
            at += rows_ * cols
            out.append(block.reshape(k, rows_, cols))
        return out[0], out[1], out[2], out[3].reshape(k, -1)
    return evaluate


def evaluated(system, evaluate: Callable) -> Callable:
    """A :class:`DesignArray`'s ``numbers`` from ``evaluate``, the designs'
    numbers as :func:`template_numbers` gives them (``system``: one of them)."""
    counts = (len(system.equations.friction), len(system.laws), len(system.equations.states))

    def numbers(mode: Mode, array: "DesignArray"):
        chi, delta = array.contact(mode.contacts)
        on, slopes = array.inputs(mode)
        return mode_linear(lambda *a, **k: evaluate(*a, **k, rows=array.rows),
                           chi, delta, on, slopes, counts)
    return numbers
