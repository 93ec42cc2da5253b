"""The first-order states of a drive train in its walkthrough (a DC motor's
current, a speed controller's integral): their equations, their places in the
state x and the modes of their limits
(:mod:`crane_sym.components.first_order`)."""
from __future__ import annotations

import sympy as sp

from crane_sym.components.hybrid import ComponentSystem, Mode
from crane_sym.components.model import Model
from crane_sym.docs.walkthrough import _display
from crane_sym.latex import latex

__all__ = ["limit_words", "state_names", "states_section"]

#: A limit's mode in words.
_AT = {0: "within its limit", 1: "at + limit, integral frozen", -1: "at − limit, integral frozen",
       2: "at + limit, integral tracking", -2: "at − limit, integral tracking"}


def states_section(model: Model) -> list[str]:
    """The first-order equations ds/dt = r(q̇, s, signals), one display each;
    nothing for a model without such states.

    Parameters
    ----------
    model : Model
        The derived model.
    """
    eq = model.equations
    if not eq.states:
        return []
    names = eq.latex_names
    out = ["Beside the coordinates, parts bring states of first order, each with its "
           "rate from the part (a state two parts drive takes the sum of their rates):"]
    for s, rate in zip(eq.states, eq.rates):
        out.append(_display(f"\\frac{{d {latex(s, symbol_names=names)}}}{{dt}} = "
                            f"{latex(sp.expand(rate), symbol_names=names)}"))
    for part, s, bound, z in eq.limits:
        out.append(f"The limit of {part} keeps ${latex(s, symbol_names=names)}$ within "
                   f"$\\pm {latex(bound, symbol_names=names)}$: at a bound "
                   f"${latex(s, symbol_names=names)}$ stands still and "
                   f"${latex(z, symbol_names=names)}$ is frozen (conditional integration), "
                   "or, where integrating again would push past the bound at once, follows "
                   "the value that keeps the loop's demand on it; released where the free "
                   "loop would move back inside.")
    return out


def state_names(system: ComponentSystem) -> list[str]:
    """The LaTeX of the first-order states, in their order in x."""
    eq = system.equations
    return [latex(s, symbol_names=eq.latex_names) for s in eq.states]


def limit_words(system: ComponentSystem, mode: Mode) -> list[str]:
    """Each limit's mode in words."""
    return [f"{limit.name} {_AT[at]}" for limit, at in zip(system.limits, mode.limits)]
