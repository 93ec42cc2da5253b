"""The closed forms of a mode kept for the designs of a batched run.

A mode's (A, b) depend on the design only, so a design's closed form
(:func:`crane_sym.mechanics.batched_forms.batch_forms`) in a mode is computed
on its first phase there and kept for its returns; designs of equal (A, b)
share one stored form.
"""
from __future__ import annotations

from typing import Callable

import numpy as np

from crane_sym.mechanics.batched_forms import COND_LIMIT, BatchForm, batch_forms
from crane_sym.mechanics.batched_spectra import SpectraMemo, first_of_equal
from crane_sym.mechanics.row_chunks import RowChunks

__all__ = ["FormCache"]

#: Most distinct (A, b) of new designs a mode's cache looks up one by one.
KNOWN_LOOKUP = 512


def _distinct(A: np.ndarray, b: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Each design's (A, b) as one bytes key, the positions of the first of
    each distinct key and, per design, which of them it equals."""
    k = b.shape[0]
    rows = np.ascontiguousarray(np.concatenate([A.reshape(k, -1), b], axis=1))
    keys = rows.view(np.dtype((np.void, rows.dtype.itemsize * rows.shape[1]))).ravel()
    first, inverse = first_of_equal(rows)
    return keys, first, inverse


class FormCache:
    """The closed forms of one mode for designs 0 … size − 1, computed on a
    design's first phase in the mode and kept in stores (a part per spectral
    structure), a design pointing at its form. A design whose (A, b) equals,
    byte for byte, one met before (a swept value the mode does not read)
    points at that one's form instead of decomposing it again, where the
    designs new to the mode in a round bring at most :data:`KNOWN_LOOKUP`
    distinct (A, b) (more, a swept value in b, are decomposed: a lookup a
    key costs more than the decomposition it saves). The modes of a run may
    share one ``memo`` of spectra (:class:`SpectraMemo`): a mode that
    differs from another in b only decomposes none of its A again."""

    def __init__(self, size: int, cond_limit: float = COND_LIMIT,
                 memo: SpectraMemo | None = None) -> None:
        self.cond_limit, self.memo = cond_limit, memo
        self.signature = np.full(size, -2)          # −2 not yet, −1 refused, else a part
        self.slot = np.zeros(size, dtype=np.intp)   # the form's row in its part
        self.parts: list[_Store] = []
        #: (A, b) bytes met so far: (part, slot), part −1 where refused
        self.known: dict[bytes, tuple[int, int]] = {}

    def forms(self, idx: np.ndarray,
              matrices: Callable[[np.ndarray], tuple[np.ndarray, np.ndarray]]
              ) -> list[tuple[np.ndarray, BatchForm | None]]:
        """(positions in ``idx``, their form, or None where refused);
        ``matrices(designs)`` gives (A, b) of designs new to the mode."""
        new = np.flatnonzero(self.signature[idx] == -2)
        if new.size:
            self._add(idx[new], *matrices(idx[new]))
        out: list = []
        which = self.signature[idx]
        for key in np.unique(which):
            where = np.flatnonzero(which == key)
            if key < 0:
                out.append((where, None))
                continue
            out.append((where, self.parts[key].form(self.slot[idx[where]])))
        return out

    def _add(self, rows: np.ndarray, A: np.ndarray, b: np.ndarray) -> None:
        """The forms of designs ``rows`` (first time in the mode): found
        where their (A, b) was met before, decomposed together otherwise;
        each design's is computed alone, so a shared one is bit for bit what
        it would have got."""
        keys, first, inverse = _distinct(A, b)
        # a few distinct (A, b) (a mode the swept values barely move) are looked
        # up; many (a swept value in b) are decomposed: a lookup a key costs more
        look = first.size <= KNOWN_LOOKUP
        part, slot = np.full(first.size, -2), np.zeros(first.size, dtype=np.intp)
        if look:
            for j, f in enumerate(first):
                part[j], slot[j] = self.known.get(keys[f].tobytes(), (-2, 0))
        fresh = np.flatnonzero(part == -2)
        if fresh.size:
            parts, refused = batch_forms(A[first[fresh]], b[first[fresh]], self.cond_limit,
                                          self.memo)
            part[fresh[refused]] = -1
            for where, f in parts:
                key = next((i for i, p in enumerate(self.parts) if p.holds(f)), None)
                if key is None:
                    self.parts.append(_Store(f))
                    key = len(self.parts) - 1
                part[fresh[where]] = key
                slot[fresh[where]] = self.parts[key].append(f)
            for j in fresh if look else ():
                self.known[keys[first[j]].tobytes()] = (int(part[j]), int(slot[j]))
        self.signature[rows] = part[inverse]
        self.slot[rows] = slot[inverse]


class _Store:
    """The distinct forms of one spectral structure in a mode, a row each,
    kept in the chunks they were made in (:class:`RowChunks`)."""

    def __init__(self, f: BatchForm) -> None:
        self.real, self.pairs, self.powers, self.sine = f.real, f.pairs, f.powers, f.sine
        self.n = f.n
        self.rows = RowChunks()

    def holds(self, f: BatchForm) -> bool:
        """True where ``f`` has this structure (its terms in the same blocks)."""
        return (self.real == f.real and self.pairs == f.pairs
                and self.powers.shape == f.powers.shape)

    def append(self, f: BatchForm) -> np.ndarray:
        """Keep the k forms of ``f`` (the rows of the state only: the last
        row of each C_j is 0 … 0 1); their rows."""
        return self.rows.append((f.sigmas, f.omegas, f.coefficients[:, :, :f.n]))

    def form(self, rows: np.ndarray) -> BatchForm:
        """The forms of ``rows``, one per design (a row may repeat)."""
        sigmas, omegas, coefficients = self.rows.take(rows)
        return BatchForm(self.n, self.powers, self.sine, sigmas, omegas, coefficients,
                         self.real, self.pairs)
