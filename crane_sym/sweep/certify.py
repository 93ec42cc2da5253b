"""The worst case over a whole parameter box, certified (``crane-sym sweep --certify``).

A grid maximum is the largest value at the grid's points; between them the
output may be larger. This module encloses the maximum over the whole box
(every swept parameter over its [start, stop], the others fixed) by
branch-and-bound over boxes with the toolkit's interval arithmetic
(:func:`crane_sym.mechanics.intervals.enclosure`, ``mpmath.iv``, outward rounding) on
the derivation's SymPy expression of the output:

* a box's enclosure gives an upper bound of the output on it;
* the enclosure at the box's midpoint, a point interval, gives a lower bound
  of the output there, hence of the maximum;
* boxes whose upper bound falls below the best lower bound are dropped; the
  others with the largest upper bounds are halved along their widest side
  (relative to the box's initial width), evaluated in parallel on Dask, until
  ``upper − lower <= rel_tol · |lower|``.

The result [lower, upper] encloses the maximum over the box (the minimum, for
a ``>=`` limit), so the grid's worst value lies inside it up to the grid's own
rounding. Outputs with no interval extension (a simulated response, a
``Piecewise``) are refused by name: no Lipschitz or sampling fallback is used,
since a bound from a derivative would need an enclosure of the derivative all
the same.
"""
from __future__ import annotations

import heapq
from dataclasses import dataclass
from functools import lru_cache
from typing import Any

import sympy as sp
from mpmath import iv

from crane_sym import registry
from crane_sym.mechanics.intervals import enclosure
from crane_sym.sweep.grid import SweepResult, connect, scheduler_lost
from crane_sym.sweep.plan import SweepError, SweepPlan

__all__ = ["Certified", "CertifyTask", "certify", "certify_result", "prepare"]

#: Boxes halved per round (each round is one parallel Dask computation).
BATCH = 64
#: Evaluated boxes after which the search stops and reports what it has.
MAX_BOXES = 200_000
#: Below this many boxes in a round the local scheduler runs them in this
#: process (spawning worker processes costs seconds; a box costs ~0.1 ms).
_PARALLEL_FROM = 2048


@dataclass(frozen=True)
class CertifyTask:
    """What to certify: ``sign · expr`` over the box of ``variables`` (SI)."""

    output: str
    expr: sp.Expr
    variables: tuple[str, ...]
    box: tuple[tuple[float, float], ...]
    sign: int
    rel_tol: float
    unit: str
    factor: float


@dataclass(frozen=True)
class Certified:
    """An enclosure [lower, upper] of the worst value (SI) over the box."""

    lower: float
    upper: float
    tolerance: float
    boxes: int
    converged: bool


def prepare(plan: SweepPlan, rel_tol: float) -> CertifyTask:
    """The task for the limited output (else the first); SweepError naming
    ``--certify`` for an output with no interval enclosure.

    Parameters
    ----------
    plan : SweepPlan
        The checked sweep.
    rel_tol : float
        Width of the certified enclosure, relative to its value.
    """
    if not 1e-12 <= rel_tol <= 0.1:
        raise SweepError(f"--certify-tol {rel_tol!r}: expected a relative width in [1e-12, 0.1]")
    name = plan.limit.output if plan.limit else plan.outputs[0].name
    spec = plan.output(name)
    if spec.kind != "closed":
        own = "component_file" in plan.options    # a drive train's outputs: its hybrid run's
        batched = own or getattr(registry.sweep_outputs(plan.derivation).get(name), "batched",
                                 False)
        if batched:                               # a hybrid run: phases ending at events
            raise SweepError(f"--certify: {name} is a hybrid run (phases that end at events "
                             "found numerically): no interval enclosure of its event times "
                             "is tight enough to bound its maximum over the box; certify a "
                             + ("paper's closed-form output (a component file's outputs "
                                "are all hybrid)" if own else "closed-form output"))
        raise SweepError(f"--certify: {name} is a simulated response, it has no interval "
                         "enclosure; certify a closed-form output")
    output = registry.get(plan.derivation).output(name)
    axes = {a.name for a in plan.axes}
    symbols = {str(a): a for a in output.args}
    variables = tuple(a.name for a in plan.axes if a.name in symbols)
    box = tuple((float(a.si().min()), float(a.si().max())) for a in plan.axes
                if a.name in variables)
    window = plan.window
    if window is not None and window.name in symbols:     # time is one more box side
        samples = window.si()
        variables += (window.name,)
        box += ((float(samples[0]), float(samples[-1])),)
        axes = axes | {window.name}
    values = {a: sp.Float(plan.fixed[str(a)]) for a in output.args if str(a) not in axes}
    sign = -1 if plan.limit and plan.limit.output == name and plan.limit.op == ">=" else 1
    if sign < 0 and window is not None:
        raise SweepError(f"--certify: a '>=' limit asks for the least {name} over the designs, "
                         "the window for its largest over time; certify one at a time")
    expr = sign * output.expr.xreplace(values)
    try:
        enclosure(expr, [symbols[v] for v in variables])
    except ValueError as exc:
        raise SweepError(f"--certify: {name}: {exc}") from None
    expr = expr.xreplace({symbols[v]: sp.Symbol(v) for v in variables})
    unit, factor = plan.unit_of(name)
    return CertifyTask(name, expr, variables, box, sign, rel_tol, unit, factor)


@lru_cache(maxsize=8)
def _compiled(expr: sp.Expr, variables: tuple[str, ...]):
    return enclosure(expr, [sp.Symbol(v) for v in variables])


def _evaluate(expr: sp.Expr, variables: tuple[str, ...], boxes: list) -> list:
    """(upper bound on the box, lower bound at its midpoint) for each box."""
    f = _compiled(expr, variables)
    out = []
    for box in boxes:
        whole = f([iv.mpf([lo, hi]) for lo, hi in box])
        middle = f([iv.mpf((lo + hi) / 2) for lo, hi in box])
        out.append((float(whole.b), float(middle.a)))
    return out


def _halves(box: tuple, widths: tuple) -> list[tuple]:
    k = max(range(len(box)), key=lambda i: (box[i][1] - box[i][0]) / widths[i])
    lo, hi = box[k]
    mid = (lo + hi) / 2
    left, right = list(box), list(box)
    left[k], right[k] = (lo, mid), (mid, hi)
    return [tuple(left), tuple(right)]


def _parallel(task: CertifyTask, boxes: list, client, workers: int) -> list:
    """:func:`_evaluate` over ``boxes`` in ``workers`` parts on Dask."""
    import dask
    if client is None and len(boxes) < _PARALLEL_FROM:
        return _evaluate(task.expr, task.variables, boxes)
    size = -(-len(boxes) // workers)
    parts = [dask.delayed(_evaluate)(task.expr, task.variables, boxes[i:i + size])
             for i in range(0, len(boxes), size)]
    done = client.gather(client.compute(parts)) if client is not None else \
        dask.compute(*parts, scheduler="processes")
    return [row for part in done for row in part]


def certify(task: CertifyTask, client=None, workers: int = 2) -> Certified:
    """Branch-and-bound for the maximum of ``task.sign · expr`` over the box."""
    widths = tuple(max(hi - lo, 1e-300) for lo, hi in task.box)
    (upper, lower), = _evaluate(task.expr, task.variables, [task.box])
    live = [(-upper, 0, task.box)]                 # a max-heap of upper bounds
    count, evaluated = 1, 1
    while live and -live[0][0] - lower > task.rel_tol * abs(lower) and evaluated < MAX_BOXES:
        chosen = [heapq.heappop(live) for _ in range(min(BATCH, len(live)))]
        children = [c for _, _, box in chosen for c in _halves(box, widths)]
        rows = _parallel(task, children, client, workers)
        evaluated += len(children)
        lower = max(lower, max(low for _, low in rows))
        for box, (up, _) in zip(children, rows):
            if up >= lower:
                count += 1
                heapq.heappush(live, (-up, count, box))
        live = [entry for entry in live if -entry[0] >= lower]
        heapq.heapify(live)
    upper = max([-live[0][0]] if live else [lower])
    tolerance = task.rel_tol * abs(lower)
    return Certified(lower, max(upper, lower), tolerance, evaluated,
                     upper - lower <= tolerance)


def certify_result(task: CertifyTask, result: SweepResult,
                   scheduler: str | None = None) -> dict[str, Any]:
    """Certify, and say whether the sweep's grid worst lies inside (user's units).

    Parameters
    ----------
    task : CertifyTask
        From :func:`prepare`.
    result : SweepResult
        The sweep, its grid worst.
    scheduler : str, optional
        As for :func:`crane_sym.sweep.grid.run_sweep`.
    """
    client = None
    if scheduler and scheduler not in ("synchronous", "threads", "processes"):
        client = connect(scheduler)
    try:
        workers = len(client.scheduler_info()["workers"]) if client else 2
        found = certify(task, client, workers)
    except Exception as exc:
        why = scheduler_lost(client, exc) if client is not None else None
        if why is None:
            raise
        raise SweepError(f"--scheduler {scheduler!r}: {why} (certifying)") from None
    finally:
        if client is not None:
            client.close()
    ends = sorted((task.sign * found.lower, task.sign * found.upper))
    grid = result.worst[task.output][0]
    return {"output": task.output, "kind": "max" if task.sign > 0 else "min",
            "lower": ends[0] / task.factor, "upper": ends[1] / task.factor,
            "unit": task.unit, "tolerance": found.tolerance / task.factor,
            "relative_tolerance": task.rel_tol, "boxes": found.boxes,
            "converged": found.converged, "method": "interval branch-and-bound (mpmath.iv)",
            "over": list(task.variables),
            "grid_worst_inside": ends[0] <= grid <= ends[1],
            # the grid can miss a peak between its points, never exceed it
            "grid_worst_short_by": max(0.0, (task.sign * found.lower - grid) * task.sign)
            / task.factor}
