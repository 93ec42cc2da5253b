"""A mode of a component model's piecewise-linear system (:class:`Mode`)
and the small helpers the system is built from: a memo of its matrices and
the accelerations solved from a mass matrix.

A mode holds what makes the equations linear: each gapped link's contact,
each rigid group's motion (:data:`FREE`, sliding :data:`FORWARD` or
:data:`BACKWARD`, :data:`HELD`), and the values the kinds' parts own
(:class:`crane_sym.components.kinds.events.Events`): a brake's ``engaged``
and ``ramping``, a motor's ``driven``, a characteristic's ``steps``, a law's
``pieces``, a limit's ``limits``, and in ``own`` those of a kind that
declares a field of its own.
"""
from __future__ import annotations

from dataclasses import dataclass, fields, replace
from typing import Any, Callable

import numpy as np

from crane_sym.components.kinds.events import BACKWARD, FORWARD, FREE, HELD
from crane_sym.components.parts import ComponentError

__all__ = ["BACKWARD", "FORWARD", "FREE", "HELD", "Mode", "memo", "solved"]


@dataclass(frozen=True)
class Mode:
    """Contacts of the backlash links, motion of each group, brakes engaged,
    motors on, ramps under way (see the module docstring)."""

    contacts: tuple[int, ...]
    motion: tuple[str, ...]
    engaged: tuple[bool, ...]
    driven: tuple[bool, ...]
    ramping: tuple[bool, ...]
    steps: tuple[int, ...] = ()
    pieces: tuple[int, ...] = ()
    #: The gapped links cut for good (their places in ``contacts``; contact 0).
    cut: tuple[int, ...] = ()
    #: Each first-order limit free (0) or at its bound (see the module docstring).
    limits: tuple[int, ...] = ()
    #: The values of the kinds that own a field of their own, (field, values) each.
    own: tuple[tuple[str, tuple[Any, ...]], ...] = ()

    def of(self, field: str) -> tuple:
        """The values of ``field``, one a part: a field of the mode, or one of ``own``."""
        if field in _FIELDS:
            return getattr(self, field)
        return dict(self.own).get(field, ())

    def setting(self, **values: Any) -> "Mode":
        """This mode with the fields named set to ``values`` (each a sequence)."""
        given = tuple((k, tuple(v)) for k, v in values.items())
        key = (self, "setting", given)
        out = _DERIVED.get(key)
        if out is None:
            named = {k: v for k, v in given if k in _FIELDS}
            own = dict(self.own)
            own.update({k: v for k, v in given if k not in _FIELDS})
            out = _derived(key, replace(self, **named, own=tuple(sorted(own.items()))))
        return out

    def moving(self, g: int, motion: str) -> "Mode":
        """This mode with group ``g`` in ``motion``."""
        key = (self, g, motion)
        out = _DERIVED.get(key)
        if out is None:
            out = _derived(key, replace(self, motion=tuple(
                motion if j == g else m for j, m in enumerate(self.motion))))
        return out


#: The modes :meth:`Mode.setting` and :meth:`Mode.moving` made, by what they
#: were made from: the designs of a sweep switch into a few modes, and a
#: dataclass's ``replace`` costs several times a dict lookup.
_DERIVED: dict[tuple, Mode] = {}


def _derived(key: tuple, mode: Mode) -> Mode:
    if len(_DERIVED) > 100_000:
        _DERIVED.clear()
    _DERIVED[key] = mode
    return mode


_FIELDS = {f.name for f in fields(Mode)} - {"own"}


def memo(func: Callable) -> Callable:
    """``func`` with its results kept by arguments (a dict: a system is built
    per design of a sweep, and ``functools.lru_cache`` costs ~70 µs to make)."""
    kept: dict = {}

    def cached(*args):
        try:
            return kept[args]
        except KeyError:
            out = kept[args] = func(*args)
            return out
    return cached


def solved(M: np.ndarray, R: np.ndarray, r: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """(M⁻¹ R, M⁻¹ r), for one design or k at once (a leading axis on each):
    divided row by row where M is diagonal (rigid groups without a coupling
    of several coordinates: a division is exact to the last bit, where
    LAPACK may multiply by a reciprocal), else solved."""
    n = M.shape[-1]
    diagonal = np.diagonal(M, axis1=-2, axis2=-1)
    if not np.count_nonzero(M[..., ~np.eye(n, dtype=bool)]):
        return R / diagonal[..., None], r / diagonal
    if np.any(np.linalg.matrix_rank(M) < n):
        raise ComponentError("the mass matrix of the moving groups is singular: a coupling "
                             "leaves a coordinate without inertia")
    both = np.linalg.solve(M, np.concatenate([R, r[..., None]], axis=-1))
    return both[..., :-1], both[..., -1]
