"""Why two threads do or do not do the work of two: a roofline of this
machine beside the batched sweep's parallel efficiency (``bench --sweep``,
section (f); issue 39, item 2).

Three controls, each on one thread and then on two plain threads over the
same data split in halves (NumPy releases the GIL in its loops):

- memory bandwidth: ``np.copyto`` of a large array (read + write counted)
  and ``np.add`` of two into a third (two reads and a write counted);
- a compute-bound kernel: ``np.sin`` into a preallocated output;
- a memory-bound kernel: the ``np.add`` above, as a parallel efficiency.

From them and the sweep's own efficiency :func:`scaling_curve` gives the
speed-up of 1..16 workers: *measured* up to the cores present (the sweep's
own numbers), *modelled* beyond by Amdahl's law with the serial fraction
the measurement implies once the machine's share (the np.sin control) is
taken out, and, for a memory-bound kernel, capped by this machine's measured
bandwidth ratio (a roofline: a kernel that moves memory cannot run faster
than the memory does). :func:`verdict` says met / not met and why.
"""
from __future__ import annotations

import os
import time
from concurrent.futures import ThreadPoolExecutor
from typing import Any, Callable, Sequence

import numpy as np

__all__ = ["ELEMENTS", "WORKERS", "amdahl", "pair_seconds", "roofline", "scaling_curve",
           "serial_fraction", "verdict", "markdown_rows"]

#: float64 elements of each large array (128 MiB: far beyond any cache).
ELEMENTS = 2**24
#: The scaling curve's worker counts.
WORKERS = tuple(range(1, 17))
#: Runs of each measurement; the least is kept (others only ever add time).
REPEATS = 3


def _least(run: Callable[[], object], repeats: int = REPEATS) -> float:
    best = np.inf
    for _ in range(repeats):
        start = time.perf_counter()
        run()
        best = min(best, time.perf_counter() - start)
    return best


def pair_seconds(kernel: Callable[[slice], object], size: int,
                 repeats: int = REPEATS) -> tuple[float, float]:
    """(seconds on one thread, seconds on two threads) of ``kernel`` over
    ``slice(0, size)``: one call on the whole range, then two threads on its
    halves; the least of ``repeats`` runs each, after one warm call.

    >>> a = np.ones(1000); one, two = pair_seconds(lambda s: a[s].sum(), a.size, 1)
    >>> one > 0 and two > 0
    True
    """
    halves = [slice(0, size // 2), slice(size // 2, size)]

    def both() -> None:
        with ThreadPoolExecutor(2) as pool:
            list(pool.map(kernel, halves))
    kernel(slice(0, size))
    return (_least(lambda: kernel(slice(0, size)), repeats), _least(both, repeats))


def roofline(elements: int = ELEMENTS, repeats: int = REPEATS) -> dict[str, Any]:
    """Bandwidth of ``np.copyto`` and ``np.add`` [GB/s] and the parallel
    efficiency T₁/(2·T₂) of ``np.sin`` (compute-bound) and ``np.add``
    (memory-bound), each on one and on two threads.

    Parameters
    ----------
    elements : int
        float64 elements of each array (the default is far beyond any cache).
    repeats : int
        Runs of each measurement, the least kept.
    """
    a = np.linspace(0.0, 1.0, elements)
    b = np.linspace(1.0, 2.0, elements)
    c = np.empty(elements)
    load_before = os.getloadavg()[0]
    kernels = {"copy": (lambda s: np.copyto(c[s], a[s]), 2),
               "add": (lambda s: np.add(a[s], b[s], out=c[s]), 3),
               "sin": (lambda s: np.sin(a[s], out=c[s]), 2)}
    out: dict[str, Any] = {"elements": elements, "cores": os.cpu_count()}
    for name, (kernel, arrays) in kernels.items():
        one, two = pair_seconds(kernel, elements, repeats)
        moved = arrays * 8 * elements / 1e9
        out[name] = {"one_s": one, "two_s": two, "efficiency": one / (2 * two),
                     "gb_per_s_one": moved / one, "gb_per_s_two": moved / two}
    out["load_before"], out["load_after"] = load_before, os.getloadavg()[0]
    return out


def serial_fraction(efficiency: float, control: float) -> float:
    """Amdahl's serial fraction f that two workers at ``efficiency`` imply,
    once the machine's own share (``control``, the np.sin efficiency in the
    same run) is taken out: E = efficiency / control (at most 1), the speed-up
    2E = 1 / (f + (1 - f)/2), so f = 1/E - 1, kept in [0, 1].

    >>> serial_fraction(0.5, 1.0), serial_fraction(0.45, 0.9)
    (1.0, 1.0)
    >>> round(serial_fraction(0.8, 1.0), 3)
    0.25
    """
    relative = min(1.0, efficiency / control) if control > 0 else 0.0
    return 1.0 if relative <= 0.5 else min(1.0, max(0.0, 1.0 / relative - 1.0))


def amdahl(workers: int, fraction: float) -> float:
    """Amdahl's speed-up of ``workers`` with serial fraction ``fraction``.

    >>> amdahl(1, 0.3), amdahl(4, 0.0)
    (1.0, 4.0)
    """
    return 1.0 / (fraction + (1.0 - fraction) / workers)


def scaling_curve(efficiency: float, roof: dict[str, Any],
                  workers: Sequence[int] = WORKERS) -> list[dict[str, Any]]:
    """Speed-up of 1..16 workers: the *measured* one where this machine has
    the cores (the sweep's ``efficiency`` on 2; None beyond), the *modelled*
    one by Amdahl with :func:`serial_fraction` (the machine's share taken
    out: what a quiet machine with ``p`` cores gives), and the memory-bound
    ceiling on this machine's memory (its measured ``np.add`` bandwidth on two
    threads over one: more cores on this memory system get no more).

    Parameters
    ----------
    efficiency : float
        The sweep's measured T₁/(2·T₂).
    roof : dict
        :func:`roofline`'s measurements in the same run.
    workers : sequence of int
        Worker counts.

    >>> roof = {"cores": 2, "sin": {"efficiency": 1.0},
    ...         "add": {"gb_per_s_one": 10.0, "gb_per_s_two": 12.0}}
    >>> [(c["measured"], round(c["modelled"], 2), c["memory_ceiling"])
    ...  for c in scaling_curve(0.8, roof, (1, 2, 4))]
    [(1.0, 1.0, 1.0), (1.6, 1.6, 1.2), (None, 2.29, 1.2)]
    """
    cores = min(roof["cores"] or 1, 2)
    fraction = serial_fraction(efficiency, roof["sin"]["efficiency"])
    memory = roof["add"]["gb_per_s_two"] / roof["add"]["gb_per_s_one"]
    return [{"workers": p, "measured": (1.0 if p == 1 else 2 * efficiency) if p <= cores
             else None, "modelled": amdahl(p, fraction),
             "memory_ceiling": min(float(p), memory if p > 1 else 1.0)} for p in workers]


def verdict(efficiency: float, target: float, roof: dict[str, Any]) -> str:
    """'met', or 'not met' and which measurement of the same run says why:
    the machine (the compute-bound np.sin control is itself below the
    target: another job holds a core), the memory (np.add below it while
    np.sin reaches it), or the code (both controls reach it)."""
    if efficiency >= target:
        return "met"
    sin, add = roof["sin"]["efficiency"], roof["add"]["efficiency"]
    if sin < target:
        return (f"not met: the machine, not the code (the compute-bound np.sin control "
                f"reached only {100 * sin:.0f} %: another job holds the second core)")
    if add < target:
        return (f"not met: memory bandwidth (np.add on two threads {100 * add:.0f} %, "
                f"np.sin {100 * sin:.0f} %)")
    return (f"not met: the code (np.sin {100 * sin:.0f} % and np.add {100 * add:.0f} % "
            "reach the target; Python between NumPy calls holds the GIL)")


def markdown_rows(efficiency: float, target: float, roof: dict[str, Any]) -> list[str]:
    """The roofline table, the scaling curve of 1..16 workers (which rows
    are measured, which modelled) and the verdict."""
    r = roof
    lines = ["", f"Roofline of this machine ({r['cores']} cores; arrays of {r['elements']} "
             f"float64, least of {REPEATS}; load {r['load_before']:.1f} before, "
             f"{r['load_after']:.1f} after):", "",
             "| control | 1 thread [s] | 2 threads [s] | GB/s, 1 → 2 threads | T₁/(2·T₂) |",
             "| --- | --- | --- | --- | --- |"]
    for name, what in (("copy", "np.copyto (memory bandwidth: read + write)"),
                       ("add", "np.add (memory-bound: two reads + a write)"),
                       ("sin", "np.sin (compute-bound)")):
        m = r[name]
        rate = "—" if name == "sin" else f"{m['gb_per_s_one']:.1f} → {m['gb_per_s_two']:.1f}"
        lines.append(f"| {what} | {m['one_s']:.4f} | {m['two_s']:.4f} | {rate} | "
                     f"{100 * m['efficiency']:.0f} % |")
    curve = scaling_curve(efficiency, r)
    fraction = serial_fraction(efficiency, r["sin"]["efficiency"])
    lines += ["", f"Scaling of the sweep, 1..{len(curve)} workers: *measured* on this "
              f"machine up to its cores; *modelled* by Amdahl with serial fraction "
              f"{fraction:.3f} (the measured efficiency over the np.sin control's, so the "
              "other jobs' share is taken out: a quiet machine of p cores); the memory-bound "
              "ceiling is *modelled* from this machine's measured np.add bandwidth ratio "
              "(more cores on this memory system).", "",
              "| workers | measured speed-up | modelled speed-up (efficiency) | "
              "memory-bound ceiling |", "| --- | --- | --- | --- |"]
    lines += [f"| {c['workers']} | "
              f"{'—' if c['measured'] is None else format(c['measured'], '.2f')} | "
              f"{c['modelled']:.2f} ({100 * c['modelled'] / c['workers']:.0f} %) | "
              f"{c['memory_ceiling']:.2f} |" for c in curve]
    lines += ["", f"Parallel efficiency target ≥ {100 * target:.0f} %: "
              f"{verdict(efficiency, target, r)}."]
    return lines
