"""Printing a tabulated response (``derivation.TabulatedOutput``) as NumPy.

The scene's run is solved when the module is generated, in mpmath
(:func:`crane_sym.mechanics.exact_phases.exact_table`: no number of it depends on the
machine's libm, NumPy or LAPACK); the module carries its
:class:`~crane_sym.mechanics.phase_table.PhaseTable` as arrays and evaluates it with
``kernels.arithmetic._phase_sum``, one partition of the time array and each phase's
terms on its own points. Numbers are printed to 13 significant digits, so the
module is the same bytes on every machine and ``generate --check`` compares
bytes.
"""
from __future__ import annotations

import textwrap

import numpy as np

from crane_sym.derivation import TabulatedOutput
from crane_sym.mechanics.phase_table import PhaseTable

__all__ = ["render_tabulated", "rounded"]

#: Significant digits of the printed table.
DIGITS = 13
_NAMES = ("edges", "first", "powers", "sigmas", "omegas", "cos_amps", "sin_amps", "consts")
_WHAT = ("phase starts and the end of the run [s]", "first term of each phase",
         "power k of tau", "decay sigma [1/s]", "angular frequency omega [rad/s]",
         "cosine amplitudes", "sine amplitudes", "constant of each phase")


def _number(value: float) -> str:
    return repr(float(f"{value:.{DIGITS}g}")) if value else "0.0"


def rounded(table: PhaseTable) -> PhaseTable:
    """The table as the generated module prints it (for tests of that module)."""
    cut = lambda a: np.array([float(_number(v)) for v in a])  # noqa: E731
    return PhaseTable(cut(table.edges), table.first, table.powers, cut(table.sigmas),
                      cut(table.omegas), cut(table.cos_amps), cut(table.sin_amps),
                      cut(table.consts), table.events)


def _array(values: np.ndarray, integer: bool = False) -> str:
    items = ", ".join(str(int(v)) if integer else _number(v) for v in values)
    body = textwrap.wrap(items, width=84, break_long_words=False, break_on_hyphens=False)
    kind = ", dtype=np.intp" if integer else ""
    return "np.array([" + "\n              ".join(body) + f"]{kind})"


def render_tabulated(out: TabulatedOutput, table: PhaseTable, note: str) -> str:
    """Source of the table constant and of the validated function ``out.name(t)``.

    Parameters
    ----------
    out : TabulatedOutput
        The response: its name, summary and weights.
    table : PhaseTable
        The run's phases in closed form (exact numbers).
    note : str
        A line for the function's docstring (how the table was solved).
    """
    const = f"_TABLE_{out.name.upper()}"
    end = float(_number(table.edges[-1]))
    lines = [f"{const} = ("]
    for name, what, values in zip(_NAMES, _WHAT, table.arrays()):
        lines.append(f"    # {name}: {what}")
        lines.append(f"    {_array(values, integer=name in ('first', 'powers'))},")
    lines.append(")")
    events = textwrap.fill(", ".join(f"{t:.6g} s {e}" for t, e in
                                     zip(table.edges[1:], table.events)),
                           width=76, initial_indent="    ", subsequent_indent="    ")
    lines += ["", "", f"def {out.name}(t, *, out=None):",
              f'    """{out.summary} Eq {", ".join(out.labels)}.',
              "",
              textwrap.fill(note, width=80, initial_indent="    ",
                            subsequent_indent="    "),
              f"    The run has {len(table.events)} phases, each in closed form; they end at",
              events + ".",
              "",
              "    Parameters",
              "    ----------",
              "    t : array_like",
              f"        time [s], 0 <= t <= {end!r}",
              "    out : ndarray, optional",
              "        float64 array of t's shape; the result is written into it and returned.",
              "",
              "    Returns",
              "    -------",
              "    ndarray",
              f"        [{out.unit}], t's shape.",
              '    """',
              "    t = _checked('t', t, 'nonnegative', 'time, s')",
              f"    if t.size and t.max() > {end!r}:",
              f"        raise ValueError(f\"t must be <= {end!r} s (the end of the run this "
              "scene tabulates), got {t.max()!r}\")",
              f"    return _into(out, t.shape, _phase_sum(t, *{const}))"]
    return "\n".join(lines) + "\n"
