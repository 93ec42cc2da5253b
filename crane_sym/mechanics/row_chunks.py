"""Rows of several arrays kept in the chunks they came in, never copied to
grow, read back by row number: the stores of the batched solver
(:mod:`crane_sym.mechanics.batched_cache`, :mod:`crane_sym.mechanics.batched_spectra`),
where a store grown by doubling spent a tenth of a block copying itself."""
from __future__ import annotations

import numpy as np

__all__ = ["RowChunks"]


class RowChunks:
    """Rows of a fixed tuple of arrays (one leading axis shared), appended a
    chunk at a time; the arrays of a chunk are held, not copied, and must
    not be written after."""

    def __init__(self) -> None:
        self.chunks: list[tuple[np.ndarray, ...]] = []
        self.starts = np.zeros(1, dtype=np.intp)      # each chunk's first row, then the count

    @property
    def count(self) -> int:
        """Rows kept."""
        return int(self.starts[-1])

    def append(self, arrays: tuple[np.ndarray, ...]) -> np.ndarray:
        """Keep ``arrays`` (their rows); the row numbers they get."""
        k = arrays[0].shape[0]
        first = self.count
        self.chunks.append(arrays)
        self.starts = np.append(self.starts, first + k)
        return np.arange(first, first + k)

    def take(self, rows: np.ndarray) -> tuple[np.ndarray, ...]:
        """The arrays' ``rows`` (a row may repeat), in that order."""
        if len(self.chunks) == 1:
            return tuple(a[rows] for a in self.chunks[0])
        which = np.searchsorted(self.starts, rows, side="right") - 1
        out = tuple(np.empty((rows.size,) + a.shape[1:], a.dtype) for a in self.chunks[0])
        for c in np.unique(which):
            sel = np.flatnonzero(which == c)
            local = rows[sel] - self.starts[c]
            for o, a in zip(out, self.chunks[c]):
                o[sel] = a[local]
        return out
