"""Designs that differ only in values the equations alone read, as one block
of arrays (:class:`DesignBlock`): no model, assembly or system a design.

A sweep that varies an elastic link's stiffness or damping changes nothing
but values of the equations (a kind's ``Symbolic.equations_only``): the
parts, their words, the rigid groups, the gaps, the laws, the start at rest
are the template's. The block holds one design's model and system and the
varied values as columns: a mode's numbers are one call of the template's
lambdified equations on them (:func:`column_numbers`), the links' loads
take the varied coefficients per design, the bound on the run's periods
decomposes K = Σ c b bᵀ of every design in one stack, and the designs' starts
at rest are settled together. A design's own run is built only where the
per-design route takes it (a design the batched closed forms refuse, a
kind's rule without a form for k designs): by the caller's ``build``, the
route the block replaces, so each design is solved as it was.

Where the designs differ in anything else, or the model has what a block
does not take (a start that is not at rest, a steady motor, a ground
contact, a group without inertia, a link's load that is no varied value
alone), :func:`plain_block` gives None and the caller builds a model a design.
"""
from __future__ import annotations

from typing import Callable, Hashable, Mapping, Sequence

import numpy as np
import sympy as sp

from crane_sym.components import kinds
from crane_sym.components.design_arrays import DesignArray
from crane_sym.components.template_forms import evaluated, numbers_of
from crane_sym.components.design_family import DesignFamily
from crane_sym.components.design_outputs import link_loads
from crane_sym.components.hybrid import ComponentSystem
from crane_sym.components.model_limits import first_beyond_stiffness
from crane_sym.components.parts import ComponentError
from crane_sym.components.start import rest_starts
from crane_sym.mechanics.batched import BatchedLargest
from crane_sym.mechanics.batched_runs import RunFamily, largest_of_starts
from crane_sym.mechanics.phase_table import HybridRun

__all__ = ["DesignBlock", "column_numbers", "plain_block"]


def column_numbers(system: ComponentSystem, columns: Mapping[sp.Symbol, np.ndarray]
                   ) -> Callable:
    """``template_numbers`` of k designs that are ``system`` but for the
    parameters ``columns`` (symbol -> k values): its row of parameter values
    repeated, those columns put in. The lambdified form works entry by entry,
    so each design's numbers are the bits its own system would give."""
    k = len(next(iter(columns.values())))
    row = {**system.equations.values, **system.extra}

    def given(parameters: tuple[sp.Symbol, ...]) -> np.ndarray:
        out = np.repeat(np.array([[row.get(p, np.nan) for p in parameters]], dtype=float), k,
                        axis=0)
        for symbol, values in columns.items():
            out[:, parameters.index(symbol)] = values
        return out
    return numbers_of(system.equations, given)


def plain_block(model, varied: Mapping[tuple[str, str], np.ndarray]) -> "DesignBlock | None":
    """The designs of ``model`` with ``varied`` ((component, key) -> k values
    in SI) as one :class:`DesignBlock` started at rest, or None where one
    of them is not a value the equations alone read, or the model has what
    a block does not take (see the module docstring).

    Parameters
    ----------
    model : Model
        A design of the block (its template's derivation shared).
    varied : mapping
        The values that differ between the designs, one array each.
    """
    a, equations = model.assembly, model.equations
    if (not varied or model.steady_motor is not None or a.contacts or not a.links
            or not all(g.inertia > 0 for g in a.groups)):
        return None
    links = {l.part.name: l for l in a.links}
    columns: dict[sp.Symbol, np.ndarray] = {}
    for (name, key), values in varied.items():
        link = links.get(name)
        declared = None if link is None else next(
            (d for d in kinds.of(link.part).symbols if d.key == key and d.equations_only), None)
        if declared is None or declared.symbol(name) not in equations.values:
            return None
        columns[declared.symbol(name)] = np.asarray(values, dtype=float).ravel()
    if len({v.size for v in columns.values()}) != 1:
        return None
    # each link's load coefficients: the template's, or ± a varied value
    for derivatives in equations.link_derivatives:
        for d in derivatives:
            if d.free_symbols & set(columns) and _signed(d, columns) is None:
                return None
    return DesignBlock(model, columns)


def _signed(d: sp.Expr, columns: Mapping[sp.Symbol, np.ndarray]) -> tuple[int, sp.Symbol] | None:
    """(±1, s) where ``d`` is ±s of a varied s (its value per design ±the
    column, exactly as ``float(d.xreplace(values))``), else None."""
    if d in columns:
        return 1, d
    if -d in columns:
        return -1, -d
    return None


class DesignBlock:
    """k designs of ``model`` that differ only in ``columns`` (symbol -> k
    values the equations alone read; :func:`plain_block` checks that)."""

    def __init__(self, model, columns: Mapping[sp.Symbol, np.ndarray]) -> None:
        self.model, self.columns = model, dict(columns)
        self.k = len(next(iter(self.columns.values())))
        self.system = ComponentSystem(model.equations)
        self.array = _array(self.system, column_numbers(self.system, self.columns), self.k,
                            self._coefficients())
        self._starts: tuple[list, np.ndarray] | None = None

    def _coefficients(self) -> dict[Hashable, np.ndarray]:
        """Each link's (a, b, e) per design (what ``DesignArray.gather`` asks
        a design's system): the template's, a varied value's column in its
        place."""
        s, out = self.system, {}
        for index, derivatives in enumerate(s.equations.link_derivatives):
            row = np.repeat(np.array([s.equations.link_coefficients(index, s.extra)]), self.k,
                            axis=0)
            for j, d in enumerate(derivatives):
                signed = _signed(d, self.columns)
                if signed is not None:
                    row[:, j] = signed[0] * self.columns[signed[1]]
            out[("link coefficients", index)] = row
        return out

    def first_beyond(self, duration: float) -> tuple[int, ComponentError] | None:
        """The first design whose run of ``duration`` spans more periods than
        the bound (``model_limits.first_beyond``, the same arithmetic): K of
        every design from the links' weights and stiffness, varied or not."""
        a = self.model.assembly
        n = len(a.groups)
        K = np.zeros((self.k, n, n))
        for link in a.links:
            b = np.zeros(n)
            for g, weight in a.weights(link):
                b[g] += weight
            declared = next((d for d in kinds.of(link.part).symbols if d.key == "stiffness"),
                            None)
            c = link.stiffness if declared is None else \
                self.columns.get(declared.symbol(link.part.name), link.stiffness)
            K += np.asarray(c, dtype=float)[..., None, None] * np.outer(b, b)
        inertia = np.repeat(np.array([[g.inertia for g in a.groups]], dtype=float), self.k,
                            axis=0)
        return first_beyond_stiffness(K, inertia, duration)

    def starts(self) -> tuple[list, np.ndarray]:
        """Each design's first mode and state at rest (``start.rest_starts``,
        the designs settled together on the block's array; found once)."""
        if self._starts is None:
            found = rest_starts([self.model] * self.k, [self.system] * self.k, self.array)
            self._starts = [mode for mode, _ in found], np.array([x for _, x in found])
        return self._starts

    def largest(self, links: Sequence[int], duration: float,
                build: Callable[[int, object, np.ndarray], HybridRun],
                **options) -> BatchedLargest:
        """The largest summed load of links ``links`` over each design's run
        from rest to ``duration`` (``largest_of_runs`` of the designs' runs,
        the same numbers); ``build(i, mode, x0)``: design i's own run from
        that start, asked only where the per-design route takes it."""
        modes, x0 = self.starts()
        array = self.array
        runs = _Built(lambda i: build(i, modes[i], x0[i]), self.k)
        family = RunFamily(runs, DesignFamily(array),
                           lambda mode, index: link_loads(array.take(index), links, mode))
        return largest_of_starts(family, modes, x0, duration, self.model.schedule(True),
                                 **options)


def _array(system: ComponentSystem, evaluate: Callable, k: int,
           gathered: Mapping[Hashable, np.ndarray]) -> DesignArray:
    """k designs that are ``system`` but for some of its parameters, their
    numbers by ``evaluate`` (:func:`column_numbers`) and ``gathered`` what
    else differs of them (each (k, ...)); the flanks, pieces, rates, bounds
    and κ, and what else ``DesignArray.gather`` asks, ``system``'s for every
    design."""
    one = DesignArray.of([system], shared=False)

    def every(a: np.ndarray) -> np.ndarray:
        return np.repeat(a, k, axis=0)
    return DesignArray((system,), evaluated(system, evaluate), every(one.flanks),
                       tuple(map(every, one.pieces)), tuple(map(every, one.rates)),
                       every(one.bounds), every(one.kappas), np.arange(k), dict(gathered),
                       designs=k)


class _Built(Sequence):
    """Design i's run, built by ``build(i)`` the first time it is asked."""

    def __init__(self, build: Callable[[int], HybridRun], size: int) -> None:
        self.build, self.size, self.made = build, size, {}

    def __len__(self) -> int:
        return self.size

    def __getitem__(self, i):
        if i not in self.made:
            self.made[i] = self.build(i)
        return self.made[i]
