"""Printing a tabulated response (``derivation.TabulatedOutput``) as NumPy.

The scene's run is solved when the module is generated; the module carries
its :class:`~crane_sym.phase_table.PhaseTable` as arrays and evaluates it
with ``kernels._phase_sum``, one partition of the time array and each phase's
terms on its own points. Numbers are printed to 13 significant digits.

A run of thirty phases carries each event time and state into the next, so
the last digits of the table follow the last bits of the libm and LAPACK
the machine uses (1e-12 relative has been seen from a change of summation
order alone). The rendering is deterministic on one machine; on another,
:func:`same_text` (what ``generate --check`` uses) accepts a table whose
numbers agree to ``CHECK_RTOL`` and demands everything else byte for byte.
"""
from __future__ import annotations

import re
import textwrap

import numpy as np

from .derivation import TabulatedOutput
from .phase_table import PhaseTable

__all__ = ["CHECK_RTOL", "render_tabulated", "rounded", "same_text"]

#: Significant digits of the printed table.
DIGITS = 13
#: How closely ``generate --check`` wants a table's numbers to agree (of the
#: table's largest number of the same array kind).
CHECK_RTOL = 1e-9
_BLOCK = re.compile(r"^(_TABLE_\w+) = \(\n(.*?)^\)$", re.MULTILINE | re.DOTALL)
_NUMBER = re.compile(r"-?\d+(?:\.\d*)?(?:e[-+]?\d+)?")
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
    """Source of the table constant and of the validated function ``out.name(t)``."""
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


def _tables(text: str) -> tuple[str, list[list[np.ndarray]]]:
    """``text`` with each table block replaced by its name, and the blocks'
    arrays (comments dropped) as numbers."""
    blocks = []
    for match in _BLOCK.finditer(text):
        code = "\n".join(line.split("#")[0] for line in match.group(2).splitlines())
        arrays = [np.array([float(n) for n in _NUMBER.findall(a)])
                  for a in code.split("np.array(")[1:]]
        blocks.append(arrays)
    return _BLOCK.sub(r"\1 = (...)", text), blocks


def same_text(disk: str, rendered: str) -> bool:
    """True when two module texts are equal, or differ only in table numbers that
    agree to ``CHECK_RTOL`` (the rendering machine's last bits, see above).
    Each table's event times also appear, to six digits, in its docstring."""
    if disk == rendered:
        return True
    (outer_a, blocks_a), (outer_b, blocks_b) = _tables(disk), _tables(rendered)
    strip = lambda t: re.sub(r"\d+\.\d+ s ", "", t)  # noqa: E731 (docstring event times)
    if not blocks_b or strip(outer_a) != strip(outer_b) or len(blocks_a) != len(blocks_b):
        return False
    for arrays_a, arrays_b in zip(blocks_a, blocks_b):
        for a, b in zip(arrays_a, arrays_b, strict=True):
            scale = max(np.max(np.abs(b), initial=0.0), 1e-300)
            if a.shape != b.shape or np.max(np.abs(a - b), initial=0.0) > CHECK_RTOL * scale:
                return False
    return True
