"""The bounds on a model's size and on its run, checked before it is solved.

A component file is read from anyone: twenty links with backlash, fifty
brakes, two hundred bodies or a run of 10⁵ s would each keep the solver busy
for hours, with no word of why. Each bound is a named constant, chosen from
what a run takes on a shared two-core machine (the shipped chain of 21
damped masses in 55 s; the Fig. 9 hoist with eight more ramp brakes in six,
sixteen in 25; the 000 example over 8470 periods in 48), stated in the README and named in the one-line error:

============================  =================  ===================================
what                          bound              why
============================  =================  ===================================
bodies (inertias, masses)     :data:`MAX_BODIES`  the derivation and the eigenproblem
elastic links                 :data:`MAX_LINKS`   each is a stiffness of the eigenproblem
links with backlash (gaps)    :data:`MAX_GAPS`    each triples the contact modes
brakes                        :data:`MAX_BRAKES`  each adds a state and stick/slip modes
the run's cycles              :data:`MAX_CYCLES`  each crest of a link's load is searched
phases of a run               ``MAX_PHASES``      a chattering contact never ends
============================  =================  ===================================

The run's cycles are its duration over the shortest period the links can
have, ω ≤ √(Σ c κ²/J) over the links and their two ends (an upper bound on
the fastest natural frequency: the largest eigenvalue of a sum is at most the
sum of the largest): a stiffness of 1e20 N/m and a run of 10⁵ s are the same
fault, too many oscillations to follow one by one. The phase limit is the
solver's (:data:`crane_sym.mechanics.piecewise_linear.MAX_PHASES`).
"""
from __future__ import annotations

import math
from typing import Sequence

from crane_sym.components.parts import Component, ComponentError
from crane_sym.components.topology import Assembly
from crane_sym.mechanics.piecewise_linear import MAX_PHASES

__all__ = ["MAX_BODIES", "MAX_BRAKES", "MAX_CYCLES", "MAX_GAPS", "MAX_LINKS", "MAX_PHASES",
           "check_counts", "check_cycles", "fastest_frequency"]

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

#: What each count covers: (kinds of component, its bound, how a message names it).
_COUNTS = ((("inertia", "mass"), MAX_BODIES, "bodies (inertias and masses)"),
           (("elastic link",), MAX_LINKS, "elastic links"),
           (("brake",), MAX_BRAKES, "brakes"))


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
    for kinds, bound, what in _COUNTS:
        n = sum(p.kind in kinds for p in parts)
        if n > bound:
            raise ComponentError(f"{where}: {n} {what}, at most {bound}")
    gaps = sum(p.kind == "elastic link" and p.backlash.si != 0 for p in parts)
    if gaps > MAX_GAPS:
        raise ComponentError(f"{where}: {gaps} elastic links with backlash, at most {MAX_GAPS}")


def fastest_frequency(assembly: Assembly) -> float:
    """An upper bound on the fastest natural frequency (rad/s): the square
    root of Σ c (κ_a²/J_a + κ_b²/J_b) over the elastic links, J the inertia of
    the rigid group at each end and κ the end's factor in it (a group without
    inertia adds nothing).

    Parameters
    ----------
    assembly : Assembly
        The assembled model.
    """
    total = 0.0
    for link in assembly.links:
        for end in link.part.ends:
            group, kappa = assembly.place[end][:2]
            inertia = assembly.groups[group].inertia
            if inertia > 0:
                total += link.stiffness * kappa * kappa / inertia
    return math.sqrt(total)


def check_cycles(assembly: Assembly, duration: float) -> None:
    """Refuse a run of more than :data:`MAX_CYCLES` periods of the fastest
    mode (:func:`fastest_frequency`), in one line naming the duration, the
    period and the bound (ComponentError).

    Parameters
    ----------
    assembly : Assembly
        The assembled model.
    duration : float
        The run's end, s.
    """
    omega = fastest_frequency(assembly)
    cycles = duration * omega / (2 * math.pi)
    if cycles > MAX_CYCLES:
        raise ComponentError(f"run: duration {duration:g} s spans {cycles:.3g} periods of the "
                             f"fastest mode ({2 * math.pi / omega:.3g} s), at most {MAX_CYCLES}; "
                             "shorten the run or soften the stiffest link")
