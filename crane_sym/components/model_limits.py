"""The bounds on a model's size and on its run, checked before it is solved.

A component file is read from anyone: twenty links with backlash, fifty
brakes, two hundred bodies or a run of 10⁵ s would each keep the solver busy
for hours, with no word of why. Each bound is a named constant, chosen from
what a run takes on a shared two-core machine (the shipped chain of 21
damped masses in 55 s; the Fig. 9 hoist with eight more ramp brakes in six,
sixteen in 25; the 000 example over 8470 periods in 48), stated in the
README and named in the one-line error:

============================  ===================  ===================================
what                          bound                why
============================  ===================  ===================================
bodies (inertias, masses)     :data:`MAX_BODIES`    the derivation and the eigenproblem
elastic links                 :data:`MAX_LINKS`     each is a stiffness of the eigenproblem
links with backlash (gaps)    :data:`MAX_GAPS`      each triples the contact modes
brakes                        :data:`MAX_BRAKES`    each adds a state and stick/slip modes
the run's cycles              :data:`MAX_CYCLES`    each crest of a link's load is searched
phases of a run               ``MAX_PHASES``        a chattering contact never ends
============================  ===================  ===================================

The run's cycles are its duration over the longest period of the model with
every link in contact and every body free (:func:`frequencies`): a
stiffness of 1e20 N/m on the two masses of paper 000 and a run of 10⁵ s are
the same fault, too many oscillations to follow one by one. The slowest mode,
not the fastest: a stiff link the run barely excites (a stiffness ratio of
1e8 under a slow speed law) is solved in seconds, its terms below the peak
search's tie; a fast mode that is excited over many slow periods is not
bounded here, only by the phase limit. The phase limit is the solver's
(:data:`crane_sym.mechanics.piecewise_linear.MAX_PHASES`).
"""
from __future__ import annotations

import math
from typing import Sequence

import numpy as np

from crane_sym.components import kinds
from crane_sym.components.parts import Component, ComponentError
from crane_sym.components.topology import Assembly
from crane_sym.mechanics.piecewise_linear import MAX_PHASES

__all__ = ["COUNTS", "MAX_BODIES", "MAX_BRAKES", "MAX_CYCLES", "MAX_GAPS", "MAX_LINKS", "MAX_PHASES",
           "check_counts", "check_cycles", "first_beyond", "first_beyond_stiffness",
           "frequencies"]

#: The most bodies (inertias and masses) a model may declare.
MAX_BODIES = 24
#: The most elastic links.
MAX_LINKS = 24
#: The most elastic links with backlash (each a gap with three contacts).
MAX_GAPS = 8
#: The most brakes.
MAX_BRAKES = 8
#: The most oscillations of the fastest mode a run may span.
MAX_CYCLES = 10_000

#: Each count a kind's parts may join (``Kind.counted``): its bound, and how a
#: message names it.
COUNTS = {"bodies": (MAX_BODIES, "bodies (inertias and masses)"),
          "links": (MAX_LINKS, "elastic links"),
          "brakes": (MAX_BRAKES, "brakes")}


def check_counts(parts: Sequence[Component], where: str) -> None:
    """Refuse a model with more bodies, links, gaps or brakes than its bounds
    allow, in one line naming the count and the bound (ComponentError).

    Parameters
    ----------
    parts : sequence of Component
        The components as read, before the model is assembled.
    where : str
        How the message names the model (``component model 'x'``).
    """
    counted = [kinds.of(p).counted for p in parts]
    for count, (bound, what) in COUNTS.items():
        n = counted.count(count)
        if n > bound:
            raise ComponentError(f"{where}: {n} {what}, at most {bound}")
    gaps = sum(c == "links" and p.gapped for p, c in zip(parts, counted))
    if gaps > MAX_GAPS:
        raise ComponentError(f"{where}: {gaps} elastic links with backlash, at most {MAX_GAPS}")


def frequencies(assembly: Assembly) -> np.ndarray:
    """The natural frequencies (rad/s) with every link in contact and every
    group free: the finite, nonzero roots of det(K − ω² M) = 0, K from the
    links (c b bᵀ, b the twist's factors κ on the groups at its ends) and M the
    groups' inertias (a group without inertia adds no finite frequency).
    Where every group has inertia, the roots are those of the symmetric
    M^-1/2 K M^-1/2 (NumPy's ``eigvalsh``, a tenth of SciPy's generalized
    solver's time: a sweep checks every design); else SciPy's ``eigvals(K, M)``.

    Parameters
    ----------
    assembly : Assembly
        The assembled model.
    """
    if not assembly.links:
        return np.zeros(0)
    K, inertia = _stiffness([assembly])
    if np.all(inertia > 0):
        squares = _scaled_squares(K, inertia)[0]
    else:
        import scipy.linalg                 # on use: SciPy's import costs ~0.5 s
        with np.errstate(all="ignore"):
            squares = scipy.linalg.eigvals(K[0], np.diag(inertia[0])).real
    return np.sqrt(squares[_kept(squares)])


def _kept(squares: np.ndarray) -> np.ndarray:
    """Which ω² of each row count: the finite ones above 1e-12 of the row's
    largest finite one (below it, eigvalsh's rounding)."""
    finite = np.isfinite(squares)
    top = np.max(np.where(finite, squares, -np.inf), axis=-1, keepdims=True)
    return finite & (squares > 1e-12 * top)


def _stiffness(assemblies: Sequence[Assembly]) -> tuple[np.ndarray, np.ndarray]:
    """(K, the groups' inertias) of designs with as many groups, (k, n, n)
    and (k, n): Σ c b bᵀ over the links, in the order of the links."""
    n = len(assemblies[0].groups)
    K = np.zeros((len(assemblies), n, n))
    inertia = np.array([[g.inertia for g in a.groups] for a in assemblies], dtype=float)
    for d, a in enumerate(assemblies):
        for link in a.links:
            b = np.zeros(n)
            for g, weight in a.weights(link):
                b[g] += weight
            K[d] += link.stiffness * np.outer(b, b)
    return K, inertia


def _scaled_squares(K: np.ndarray, inertia: np.ndarray) -> np.ndarray:
    """ω² of M^-1/2 K M^-1/2 per design (every inertia > 0), one ``eigvalsh``
    of the stack (each matrix decomposed alone: the same as one by one)."""
    scale = 1.0 / np.sqrt(inertia)
    return np.linalg.eigvalsh(K * (scale[:, :, None] * scale[:, None, :]))


def check_cycles(assembly: Assembly, duration: float) -> None:
    """Refuse a run of more than :data:`MAX_CYCLES` periods of the slowest
    mode (:func:`frequencies`), in one line naming the duration, the period
    and the bound (ComponentError).

    Parameters
    ----------
    assembly : Assembly
        The assembled model.
    duration : float
        The run's end, s.
    """
    beyond = first_beyond([assembly], duration)
    if beyond is not None:
        raise beyond[1]


def first_beyond(assemblies: Sequence[Assembly], duration: float
                 ) -> tuple[int, ComponentError] | None:
    """The first of ``assemblies`` (the designs of a sweep's block) whose run
    of ``duration`` spans more than :data:`MAX_CYCLES` periods of its slowest
    mode, with the error :func:`check_cycles` raises for it; None where none
    does. Designs with as many groups, all with inertia, are decomposed in
    one stack; the others by :func:`frequencies` one by one.

    Parameters
    ----------
    assemblies : sequence of Assembly
        The assembled designs.
    duration : float
        The runs' end, s.
    """
    slowest = np.full(len(assemblies), np.inf)
    by_size: dict[int, list[int]] = {}
    for d, a in enumerate(assemblies):
        if a.links and all(g.inertia > 0 for g in a.groups):
            by_size.setdefault(len(a.groups), []).append(d)
        elif a.links:
            omega = frequencies(a)
            slowest[d] = omega.min() if omega.size else np.inf
    for index in by_size.values():
        slowest[index] = _slowest(*_stiffness([assemblies[d] for d in index]))
    return _past(slowest, duration)


def first_beyond_stiffness(K: np.ndarray, inertia: np.ndarray, duration: float
                           ) -> tuple[int, ComponentError] | None:
    """:func:`first_beyond` of designs given by their K and their groups'
    inertias, (k, n, n) and (k, n), every inertia > 0 (a block of designs
    that differ only in their links' stiffness: no assembly a design).

    Parameters
    ----------
    K, inertia : ndarray
        Σ c b bᵀ over the links, in the order of the links, and the inertias.
    duration : float
        The runs' end, s.
    """
    return _past(_slowest(K, inertia), duration)


def _slowest(K: np.ndarray, inertia: np.ndarray) -> np.ndarray:
    """ω of the slowest mode that counts (:func:`_kept`) per design."""
    squares = _scaled_squares(K, inertia)
    least = np.min(np.where(_kept(squares), squares, np.inf), axis=1)
    with np.errstate(invalid="ignore"):              # a kept ω² < 0: NaN, as frequencies gives
        return np.sqrt(least)


def _past(slowest: np.ndarray, duration: float) -> tuple[int, ComponentError] | None:
    """The first design whose slowest ω spans more than :data:`MAX_CYCLES`
    periods in ``duration``, with its error."""
    with np.errstate(invalid="ignore"):
        past = np.flatnonzero(np.isfinite(slowest) &
                              (duration * slowest / (2 * math.pi) > MAX_CYCLES))
    if not past.size:
        return None
    d = int(past[0])
    omega = float(slowest[d])
    cycles = duration * omega / (2 * math.pi)
    return d, ComponentError(
        f"run: duration {duration:g} s spans {cycles:.3g} periods of the slowest "
        f"mode ({2 * math.pi / omega:.3g} s), at most {MAX_CYCLES}; shorten the "
        "run or soften the stiffest link")
