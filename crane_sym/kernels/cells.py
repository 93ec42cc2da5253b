"""NumPy kernels that evaluate a piecewise function window by window.

The generated function marks once which points fall in which window (one
boolean pass per condition), then evaluates each window's formula on its own
points only and writes it into the output buffer. Where the points of a window
are contiguous (a sorted time array, windows with scalar edges) a window is a
slice: a view, no gather and no scatter. A function without windows is
evaluated block by block the same way (``_spans``). Ordinary functions, tested in
``tests/test_cell_kernels.py``; the code generator copies the ones a module
calls (``DEPENDS``), so generated modules need NumPy alone.
"""
from __future__ import annotations

import numpy as np


def _selector(mask):
    """The flat positions where ``mask`` (1-D bool) holds: None if none, a
    slice if they are contiguous, else an index array."""
    n = int(np.count_nonzero(mask))
    if n == 0:
        return None
    first = int(np.argmax(mask))
    if n == mask.size or mask[first:first + n].all():
        return slice(first, first + n)
    return np.flatnonzero(mask)


def _cells(shape, choices):
    """Selectors over the flattened broadcast ``shape``, one per combination of
    branches: ``choices`` lists, per piecewise, its conditions in order (the
    last branch, the rest, left out); a point takes the first branch whose
    condition holds. Combinations in row-major order (the first piecewise
    varies slowest)."""
    size = int(np.prod(shape, dtype=np.int64))
    cells = [np.ones(size, dtype=bool)]
    for conditions in choices:
        rest = np.ones(size, dtype=bool)
        branches = []
        for condition in conditions:
            mask = np.broadcast_to(condition, shape).reshape(-1) & rest
            rest &= ~mask
            branches.append(mask)
        branches.append(rest)
        cells = [cell & branch for cell in cells for branch in branches]
    return [_selector(cell) for cell in cells]


def _at(where, shape, *values):
    """``values`` on the points ``where`` (a selector of ``_cells``): arrays
    broadcast to ``shape``, flattened and selected; scalars as they are."""
    return tuple(v if np.ndim(v) == 0 else np.broadcast_to(v, shape).reshape(-1)[where]
                 for v in values)


def _put(out, where, value):
    """Write ``value`` into ``out`` at the flat positions ``where``."""
    if out.flags.c_contiguous:
        out.reshape(-1)[where] = value
    else:
        out.flat[where] = value


def _blocks(where, size=16384):
    """``where`` (a selector of ``_cells``) in pieces of at most ``size``
    points: a cell's temporaries then stay in the cache and below the
    allocator's mmap threshold, so a call does not page-fault on every new
    array; none for an empty cell."""
    if where is None:
        return ()
    if isinstance(where, slice):
        return [slice(i, min(i + size, where.stop)) for i in range(where.start, where.stop, size)]
    return [where[i:i + size] for i in range(0, where.size, size)]


def _spans(out, shape, *values, size=16384):
    """(a piece of ``out``, ``values`` on it) for each block of at most
    ``size`` points of the flat ``out``, when ``out`` and every array among
    ``values`` are C-contiguous of the full ``shape``: an expression's
    temporaries then stay block-sized and in the cache, so a call needs no
    full-size work array. Else one piece, the whole (broadcasting as is)."""
    full = tuple(shape)
    flat = out.flags.c_contiguous and all(
        np.ndim(v) == 0 or (v.shape == full and v.flags.c_contiguous) for v in values)
    if not flat or out.size <= size:
        return [(out, values)]
    o = out.reshape(-1)
    arrays = [v if np.ndim(v) == 0 else v.reshape(-1) for v in values]
    return [(o[i:i + size], tuple(v if np.ndim(v) == 0 else v[i:i + size] for v in arrays))
            for i in range(0, o.size, size)]


def _cancelled(value, bound):
    """A selector of the points of the 1-D ``value`` below half its error
    scale ``bound``, where a fast sum cancels and the cell's own formula is
    evaluated again (``wave_sums``); None if there is none."""
    return _selector(np.abs(value) < 0.5 * bound)


#: kernel -> kernels it calls, so a module carries only what it uses.
DEPENDS = {"_selector": (), "_cells": ("_selector",), "_at": (), "_put": (),
           "_cancelled": ("_selector",), "_blocks": (), "_spans": ()}
