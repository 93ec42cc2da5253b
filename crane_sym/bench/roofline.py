"""Why two workers do or do not do the work of two: a roofline of this
machine beside the batched sweep's parallel efficiency (``bench
--parallel``; issue 39, item 2).

Three controls, each on one thread and then on two plain threads over the
same data split in halves (NumPy releases the GIL in its loops), timed in the
same interleaved rounds as the sweep (:mod:`crane_sym.bench.interleaved`):

- memory bandwidth: ``np.copyto`` of a large array (read + write counted)
  and ``np.add`` of two into a third (two reads and a write counted);
- a compute-bound kernel: ``np.sin`` into a preallocated output;
- a memory-bound kernel: the ``np.copyto`` and ``np.add`` above, as
  parallel efficiencies.

From them and the sweep's own efficiency :func:`fit_serial` gives Amdahl's
serial fraction once the machine's share (the np.sin control, round by
round) is taken out: from the minimum times, with its range over the rounds,
and *not stable* where that range is wider than :data:`STABLE_WIDTH`.
:func:`scaling_curve` gives the speed-up of 1..16 workers: *measured* up to
the cores present, *modelled* beyond by Amdahl (a range from the fit's
range), capped for a memory-bound kernel by this machine's measured
bandwidth ratio. :func:`verdict` says met / not met and why.
"""
from __future__ import annotations

import os
from concurrent.futures import Executor
from typing import Any, Callable, Sequence

import numpy as np

from crane_sym.bench.interleaved import Rounds, Trial, efficiency

__all__ = ["ELEMENTS", "KERNELS", "STABLE_WIDTH", "WORKERS", "amdahl", "control_trials",
           "fit_serial", "markdown_rows", "roofline", "scaling_curve", "serial_fraction",
           "verdict"]

#: float64 elements of each large array (128 MiB: far beyond any cache).
ELEMENTS = 2**24
#: The scaling curve's worker counts.
WORKERS = tuple(range(1, 17))
#: The widest range of the serial fraction over the rounds still called stable.
STABLE_WIDTH = 0.10
#: The controls: name -> (what it is, arrays it moves).
KERNELS = {"copy": ("np.copyto (memory bandwidth: read + write)", 2),
           "add": ("np.add (memory-bound: two reads + a write)", 3),
           "sin": ("np.sin (compute-bound)", 2)}


def _name(kernel: str, workers: int) -> str:
    return f"{kernel}, {workers} thread{'s' if workers > 1 else ''}"


def control_trials(pool: Executor, elements: int = ELEMENTS) -> list[Trial]:
    """The controls as trials: each kernel over ``slice(0, elements)`` on
    this thread, and on its two halves in two threads of ``pool`` (started
    by the caller, so no trial pays for starting threads).

    Parameters
    ----------
    pool : Executor
        A pool of (at least) two threads.
    elements : int
        float64 elements of each array (the default is far beyond any cache).

    >>> from concurrent.futures import ThreadPoolExecutor
    >>> with ThreadPoolExecutor(2) as pool:
    ...     [t.name for t in control_trials(pool, 8)][:2]
    ['copy, 1 thread', 'copy, 2 threads']
    """
    a = np.linspace(0.0, 1.0, elements)
    b = np.linspace(1.0, 2.0, elements)
    c = np.empty(elements)
    kernels: dict[str, Callable[[slice], object]] = {
        "copy": lambda s: np.copyto(c[s], a[s]),
        "add": lambda s: np.add(a[s], b[s], out=c[s]),
        "sin": lambda s: np.sin(a[s], out=c[s])}
    halves = [slice(0, elements // 2), slice(elements // 2, elements)]
    trials = []
    for name, kernel in kernels.items():
        trials += [Trial(_name(name, 1), lambda k=kernel: k(slice(0, elements))),
                   Trial(_name(name, 2), lambda k=kernel: list(pool.map(k, halves)), 2)]
    return trials


def roofline(rounds: Rounds, elements: int = ELEMENTS) -> dict[str, Any]:
    """Bandwidth of ``np.copyto`` and ``np.add`` [GB/s] and the parallel
    efficiency T₁/(2·T₂) of each control, from the least times of the
    rounds of :func:`control_trials`, with the median and each round's.

    Parameters
    ----------
    rounds : Rounds
        The interleaved measurement holding the controls.
    elements : int
        Elements of each array the controls ran on.
    """
    out: dict[str, Any] = {"elements": elements, "cores": os.cpu_count(),
                           "rounds": rounds.count, "loads": list(rounds.loads)}
    for name, (_, arrays) in KERNELS.items():
        one, two = _name(name, 1), _name(name, 2)
        moved = arrays * 8 * elements / 1e9
        e = efficiency(rounds, one, two)
        out[name] = {"one_s": rounds.least(one), "two_s": rounds.least(two),
                     "one_median_s": rounds.median(one), "two_median_s": rounds.median(two),
                     "efficiency": e["least"], "efficiency_rounds": e["rounds"],
                     "gb_per_s_one": moved / rounds.least(one),
                     "gb_per_s_two": moved / rounds.least(two)}
    return out


def serial_fraction(efficiency: float, control: float) -> float:
    """Amdahl's serial fraction f that two workers at ``efficiency`` imply,
    once the machine's own share (``control``, the np.sin efficiency at the
    same moment) is taken out: E = efficiency / control (at most 1), the
    speed-up 2E = 1 / (f + (1 - f)/2), so f = 1/E - 1, kept in [0, 1].

    >>> serial_fraction(0.5, 1.0), serial_fraction(0.45, 0.9)
    (1.0, 1.0)
    >>> round(serial_fraction(0.8, 1.0), 3)
    0.25
    """
    relative = min(1.0, efficiency / control) if control > 0 else 0.0
    return 1.0 if relative <= 0.5 else min(1.0, max(0.0, 1.0 / relative - 1.0))


def fit_serial(sweep: dict[str, Any], roof: dict[str, Any]) -> dict[str, Any]:
    """The serial fraction of the sweep: from the minimum times (the
    sweep's efficiency from its least times over np.sin's from its own),
    and round by round, whose range is the fit's interval. ``stable`` when
    that range is at most :data:`STABLE_WIDTH` wide and no round's sweep
    beat its np.sin control by more than that (there the fraction is a
    clamp at 0, not a fit: the machine's share was not taken out); ``why``
    says which failed.

    Parameters
    ----------
    sweep : dict
        :func:`crane_sym.bench.interleaved.efficiency` of the sweep.
    roof : dict
        :func:`roofline` of the same rounds.

    >>> roof = {"sin": {"efficiency": 1.0, "efficiency_rounds": [1.0, 0.9]}}
    >>> fit = fit_serial({"least": 0.8, "rounds": [0.8, 0.72]}, roof)
    >>> round(fit["fraction"], 3), fit["stable"]
    (0.25, True)
    >>> fit_serial({"least": 0.8, "rounds": [0.8, 0.72]},
    ...            {"sin": {"efficiency": 0.5, "efficiency_rounds": [0.5, 0.5]}})["why"]
    'a round where the sweep beat np.sin by more than 0.1'
    """
    sin = roof["sin"]
    pairs = list(zip(sweep["rounds"], sin["efficiency_rounds"]))
    each = [serial_fraction(e, c) for e, c in pairs]
    low, high = min(each), max(each)
    why = []
    if high - low > STABLE_WIDTH:
        why.append(f"the range is wider than {STABLE_WIDTH:g}")
    if any(e > (1 + STABLE_WIDTH) * c for e, c in pairs):
        why.append(f"a round where the sweep beat np.sin by more than {STABLE_WIDTH:g}")
    return {"fraction": serial_fraction(sweep["least"], sin["efficiency"]), "low": low,
            "high": high, "rounds": each, "stable": not why, "why": "; ".join(why)}


def amdahl(workers: int, fraction: float) -> float:
    """Amdahl's speed-up of ``workers`` with serial fraction ``fraction``.

    >>> amdahl(1, 0.3), amdahl(4, 0.0)
    (1.0, 4.0)
    """
    return 1.0 / (fraction + (1.0 - fraction) / workers)


def scaling_curve(efficiency: float, fit: dict[str, Any], roof: dict[str, Any],
                  workers: Sequence[int] = WORKERS) -> list[dict[str, Any]]:
    """Speed-up of 1..16 workers: the *measured* one where this machine has
    the cores (the sweep's ``efficiency`` on 2; None beyond), the *modelled*
    one by Amdahl with the fitted serial fraction and its range over the
    rounds (``low`` with the largest fraction), and the memory-bound ceiling
    on this machine's memory (its measured ``np.add`` bandwidth on two
    threads over one: more cores on this memory system get no more).

    Parameters
    ----------
    efficiency : float
        The sweep's T₁/(2·T₂) from its least times.
    fit : dict
        :func:`fit_serial` of the same rounds.
    roof : dict
        :func:`roofline` of the same rounds.
    workers : sequence of int
        Worker counts.

    >>> roof = {"cores": 2, "add": {"gb_per_s_one": 10.0, "gb_per_s_two": 12.0}}
    >>> fit = {"fraction": 0.25, "low": 0.2, "high": 0.3}
    >>> [(c["measured"], round(c["modelled"], 2), c["memory_ceiling"])
    ...  for c in scaling_curve(0.8, fit, roof, (1, 2, 4))]
    [(1.0, 1.0, 1.0), (1.6, 1.6, 1.2), (None, 2.29, 1.2)]
    """
    cores = min(roof["cores"] or 1, 2)
    memory = roof["add"]["gb_per_s_two"] / roof["add"]["gb_per_s_one"]
    return [{"workers": p, "measured": (1.0 if p == 1 else 2 * efficiency) if p <= cores
             else None, "modelled": amdahl(p, fit["fraction"]),
             "low": amdahl(p, fit["high"]), "high": amdahl(p, fit["low"]),
             "memory_ceiling": min(float(p), memory if p > 1 else 1.0)} for p in workers]


def verdict(efficiency: float, target: float, roof: dict[str, Any]) -> str:
    """'met', or 'not met' and which measurement of the same rounds says
    why: the machine (the compute-bound np.sin control is itself below the
    target: another job holds a core), the memory (np.add below it while
    np.sin reaches it), or the code (both controls reach it); ``efficiency``
    and the controls' from the minimum times."""
    if efficiency >= target:
        return "met"
    sin, add = roof["sin"]["efficiency"], roof["add"]["efficiency"]
    if sin < target:
        return (f"not met: the machine, not the code (the compute-bound np.sin control "
                f"reached only {100 * sin:.0f} % in the same rounds: another job holds "
                "the second core)")
    if add < target:
        return (f"not met: memory bandwidth (np.add on two threads {100 * add:.0f} %, "
                f"np.sin {100 * sin:.0f} %)")
    return (f"not met: the code (np.sin {100 * sin:.0f} % and np.add {100 * add:.0f} % "
            "reach the target; Python between NumPy calls holds the GIL)")


def _fit_text(fit: dict[str, Any], rounds: int) -> str:
    state = ("stable" if fit["stable"] else
             f"NOT STABLE ({fit['why']}): the modelled rows are not a prediction")
    return (f"serial fraction {fit['fraction']:.3f} from the minimum times, "
            f"{fit['low']:.3f} to {fit['high']:.3f} over the {rounds} rounds: {state}")


def markdown_rows(efficiency: float, target: float, roof: dict[str, Any],
                  fit: dict[str, Any]) -> list[str]:
    """The roofline table, the scaling curve of 1..16 workers (which rows
    are measured, which modelled, and whether the fit is stable) and the
    verdict.

    Parameters
    ----------
    efficiency : float
        The sweep's T₁/(2·T₂) from its least times.
    target : float
        The efficiency asked for.
    roof : dict
        :func:`roofline` of the same rounds.
    fit : dict
        :func:`fit_serial` of the same rounds.
    """
    r = roof
    lines = ["", f"Roofline of this machine ({r['cores']} cores; arrays of {r['elements']} "
             f"float64; the same {r['rounds']} interleaved rounds as the sweep, min "
             "(median) seconds):", "",
             "| control | 1 thread [s] | 2 threads [s] | GB/s, 1 → 2 threads (min) | "
             "T₁/(2·T₂) from the minima (range over the rounds) |",
             "| --- | --- | --- | --- | --- |"]
    for name, (what, _) in KERNELS.items():
        m = r[name]
        rate = "—" if name == "sin" else f"{m['gb_per_s_one']:.1f} → {m['gb_per_s_two']:.1f}"
        lines.append(f"| {what} | {m['one_s']:.4f} ({m['one_median_s']:.4f}) | "
                     f"{m['two_s']:.4f} ({m['two_median_s']:.4f}) | {rate} | "
                     f"{100 * m['efficiency']:.0f} % ({100 * min(m['efficiency_rounds']):.0f}"
                     f"–{100 * max(m['efficiency_rounds']):.0f} %) |")
    curve = scaling_curve(efficiency, fit, r)
    lines += ["", f"Scaling of the sweep, 1..{len(curve)} workers: *measured* on this machine "
              "up to its cores; *modelled* by Amdahl, the sweep's efficiency over the np.sin "
              "control's in the same rounds (the other jobs' share taken out: a quiet machine "
              f"of p cores), {_fit_text(fit, r['rounds'])}; the memory-bound ceiling is "
              "*modelled* from this machine's measured np.add bandwidth ratio.", "",
              "| workers | measured speed-up | modelled speed-up (efficiency) | modelled range "
              "over the rounds | memory-bound ceiling |", "| --- | --- | --- | --- | --- |"]
    flag = "" if fit["stable"] else " (unstable fit)"
    lines += [f"| {c['workers']} | "
              f"{'—' if c['measured'] is None else format(c['measured'], '.2f')} | "
              f"{c['modelled']:.2f} ({100 * c['modelled'] / c['workers']:.0f} %){flag} | "
              f"{c['low']:.2f}–{c['high']:.2f} | {c['memory_ceiling']:.2f} |" for c in curve]
    lines += ["", f"Parallel efficiency target ≥ {100 * target:.0f} %: "
              f"{verdict(efficiency, target, r)}."]
    return lines
