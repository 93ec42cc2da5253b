"""Where paper 002's two-mass model describes the hoist: the load lifted, the rope taut.

The model (1)-(2) takes both masses as free and joined by a rope that pulls
and pushes alike. A rope only pulls: the model holds while the stretch
:math:`x \\ge 0` (the MODEL text: no slack rope after the start). How the
start is modelled decides where it begins to hold.

Lifting from weight, (11) and (31): the rope carries the weight from
:math:`t = 0`, the load hangs free; the model holds from 0 until the rope
goes slack.

Lifting with pick-up, (7) and (28)-(29): the load rests on the ground until
the rope force :math:`C x` reaches its weight :math:`m_2 g`. The print does
not model that contact: (28) gives the load the resistance
:math:`Q = m_2 g\\,t/\\tau_0` -- the force of a rope stretched at the final
speed :math:`v_0` from :math:`t = 0`, which is what (29) assumes -- and
leaves it free to move. With a drive that starts from rest, and from the
slack rope of (7), the rope force is not that ramp, so during the contact the
model's load accelerates, :math:`(C x - Q)/m_2 \\ne 0`, where the real one
rests. Once the contact is over (:math:`t \\ge \\tau_0`, :math:`Q = m_2 g`)
and the rope holds the weight (:math:`C x \\ge m_2 g`) the model's
equations are those of the lifted load: it holds from that instant,
:math:`t_{lift}`, from the state it reached there, until the rope goes
slack. Before :math:`t_{lift}` it does not describe the hoist, and its state
at :math:`t_{lift}` carries what the contact phase got wrong.

:func:`model_span` finds both instants by interval arithmetic
(``crane_sym.mechanics.crossings``), not by sampling.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
import sympy as sp

from crane_sym.mechanics.crossings import first_reaching
from crane_sym.mechanics.loads import exact_number
from crane_sym.scenes.panels import WARNING, Span, outside
from crane_sym.scenes.reading import format_quantity as fq

from .drive_law import PICKUP, DriveLawResponse

__all__ = ["ModelSpan", "model_span"]

_CONTACT_SAMPLES = 2001   # the model's load acceleration on [0, tau_0], for the warning


@dataclass(frozen=True)
class ModelSpan:
    """Where the model describes one response on ``[0, duration]``: from
    ``start`` to ``end`` [s] (``start`` is None when the load never lifts
    within the duration).

    ``slack``: the rope goes slack at ``end`` (before the duration);
    ``lift_force``: the rope force at ``start`` with pick-up [N];
    ``contact``: the model's load acceleration on ``[0, tau_0]`` with pick-up,
    (lowest, highest) on a grid [m/s²]; ``certified``: both instants proved.
    """

    lifting: str
    duration: float
    start: float | None
    end: float
    slack: bool
    certified: bool
    weight: float
    contact_time: float | None = None
    lift_force: float | None = None
    contact: tuple[float, float] | None = None

    @property
    def whole(self) -> bool:
        """True when the model holds on all of ``[0, duration]``."""
        return self.start == 0.0 and not self.slack

    @property
    def empty(self) -> bool:
        """True when it holds nowhere on ``[0, duration]``."""
        return self.start is None or self.start >= self.end

    def spans(self) -> list[Span]:
        """Where it does not hold, for ``Panel.invalid``."""
        if self.empty:
            return [Span(-math.inf, math.inf, "model not valid: the load never lifts")]
        before = (rf"load on the ground ($t < {self.start:.4g}$ s): model not valid"
                  if self.start > 0 else "")
        after = (rf"rope slack ($t > {self.end:.4g}$ s): model not valid"
                 if self.slack else "")
        return outside(self.start, self.end, before, after)

    def interval(self) -> str:
        """The valid part as text, e.g. ``"[0.1570 s, 2.500 s]"``."""
        return f"[{fq(self.start, 's')}, {fq(self.end, 's')}]"

    def warnings(self, law: str = "") -> list[str]:
        """The report's ``warning:`` lines (none when the model holds
        throughout), each after ``law`` (e.g. ``"a1: "``) when given."""
        lines = []
        if self.lifting == PICKUP:
            low, high = self.contact
            lines.append(
                f"{WARNING} with pick-up the load rests on the ground until the rope force "
                f"reaches its weight {fq(self.weight / 1e3, 'kN')}; (28) does not hold it "
                f"there: on [0, tau_0] the model's load accelerates at {fq(low, digits=3)}"
                f" to {fq(high, 'm/s^2', digits=3)} (sampled), not 0")
            if self.empty:
                lines.append(f"{WARNING} the load never lifts within [0, "
                             f"{fq(self.duration, 's')}]: the model is valid nowhere here")
            else:
                lines.append(
                    f"{WARNING} the model holds only after lift-off, t >= "
                    f"{fq(self.start, 's')} (tau_0 of (29) over, rope force "
                    f"{fq(self.lift_force / 1e3, 'kN')} >= weight), from the state it "
                    f"reached there; t < {fq(self.start, 's')} is greyed")
        if self.slack:
            lines.append(f"{WARNING} the rope goes slack at t = {fq(self.end, 's')} (stretch "
                         f"x = 0): a rope cannot push, the model does not hold after it; "
                         f"t > {fq(self.end, 's')} is greyed")
        return [line.replace(WARNING, f"{WARNING} {law}".rstrip(), 1) for line in lines]


def model_span(response: DriveLawResponse, duration: float) -> ModelSpan:
    """Where ``response`` describes the hoist on ``[0, duration]`` (module text)."""
    t, x = response.t, response.rope_stretch()
    end = exact_number(duration, "duration")
    weight = response.m2 * response.g
    certified, lift_force, contact, tau0 = True, None, None, None
    start: sp.Expr | float | None = sp.Integer(0)
    if response.lifting == PICKUP:
        tau0 = response.contact_time
        accel = sp.lambdify(t, response.load_acceleration(), "numpy")
        grid = np.linspace(0.0, float(min(tau0, end)), _CONTACT_SAMPLES)
        sampled = np.asarray(accel(grid), dtype=float) * np.ones_like(grid)
        contact = (float(sampled.min()), float(sampled.max()))
        start = None
        if tau0 < end:
            lift = first_reaching(response.C * x, t, tau0, end, weight)
            certified = lift.certified
            if lift.location is not None:
                start = lift.location if lift.location > tau0 else tau0
                lift_force = float(response.C * x.subs(t, exact_number(start, "t")))
    if start is None:
        return ModelSpan(response.lifting, float(end), None, float(end), False, certified,
                         float(weight), None if tau0 is None else float(tau0), None, contact)
    slack = first_reaching(x, t, start, end, 0, above=False)
    stop = float(end) if slack.location is None else slack.location
    return ModelSpan(response.lifting, float(end), float(start), stop,
                     slack.location is not None, certified and slack.certified,
                     float(weight), None if tau0 is None else float(tau0), lift_force,
                     contact)
