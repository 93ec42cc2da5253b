"""The spectra of many designs' A at once: eigenvalues, right and left
eigenvectors, sorted and sorted out, for the batched closed forms
(:mod:`crane_sym.mechanics.batched_forms`).

One ``np.linalg.eig`` of the stack of distinct A (each matrix decomposed
alone, so a design's bits do not depend on its neighbours) gives λ and the
right vectors V. The left vectors are the rows of V⁻¹ (biorthogonal to V by
construction) where V is well conditioned (:data:`LEFT_COND`); where it is not
(a defective kernel: a body free to roll, x' = v, v' = 0, gives two nearly
parallel columns), they come from ``np.linalg.eig`` of Aᵀ, matched to the
right ones by their order, and the two spectra must agree.

:class:`SpectraMemo` keeps the spectra of the A met in one batched run: two
modes that differ in b only (a motor's torque switched, a brake's force)
share A, and a design's A is decomposed once for both (bridge_travel.toml:
43 248 distinct A of 114 098 decomposed mode by mode).
"""
from __future__ import annotations

import contextlib
import threading
from typing import Iterator

import numpy as np

from crane_sym.mechanics.row_chunks import RowChunks
from crane_sym.mechanics.spectral_clusters import CLUSTER

__all__ = ["EQUAL", "LEFT_COND", "NEAR_COND", "SpectraMemo", "decompose", "decomposed",
           "first_of_equal", "spectra"]

#: Largest condition number κ of an eigenvalue with a neighbour within
#: CLUSTER of it: near a defective pair (near-critical damping) the error
#: grows like eps·κ² (the eigenvalue off by eps·κ, times amplitudes κ large:
#: 3e-9 of the peak at κ = 3.6e3, damping 1e-8 below critical), so 200 keeps
#: it near 1e-11; the per-design route's clusters resolve the others.
NEAR_COND = 200.0
#: Two neighbouring eigenvalues are one (a cluster: one projector, their mean
#: its eigenvalue) where they are at most EQUAL·scale apart (scale: the
#: largest |λ|, at least 1): a few ulps of λ. Taking the mean moves each by
#: half the gap, x(t) by about t·gap/2·|C z|: no more than rounding λ itself
#: (32 ulps of λt), where 10⁻¹²·scale cost up to 1.4e-12 at t = 1 for a pair
#: of |λ| ≈ 2 a relative 10⁻¹² apart. Equal drives' eigenvalues come out
#: equal to the bit (003: a gap of 0) or within a few ulps (eig's rounding
#: of a double eigenvalue, ~ eps·|λ| times its condition: at most 35 ulps of
#: random A = S D S⁻¹ with cond S = 10); a gap above this
#: is twins (``batched_forms._twins``), accurate down to rounding gaps (the
#: error of (M − λ'I)P over the gap enters times a divided difference), or
#: refused where the pair's vectors are nearly dependent (``NEAR_COND``).
EQUAL = 64 * np.finfo(float).eps
#: Largest ‖V‖₁‖V⁻¹‖₁ (V's columns of unit length) for which the rows of V⁻¹
#: are the left vectors: their rounding is about eps times it (≤ 2e-12 here);
#: 003's start-up reaches 8.4e3 at most, and a defective kernel ~1e16.
LEFT_COND = 1e4
#: Bytes of spectra a :class:`SpectraMemo` keeps at most (past it, new A are
#: decomposed and not kept).
MEMO_BYTES = 1 << 27
#: Bytes a :class:`SpectraMemo` keeps before its first hit (bridge_travel.toml
#: meets its first after 46 MB, its fourth stack); past them with
#: none (every mode's A its own: 003's start-up) it lets all go and keeps no
#: more, so a run that cannot share holds no spectra.
MEMO_TRIAL = 1 << 26


#: The lists that keep the stacks of distinct A that :func:`spectra`
#: decomposes, one per open :func:`decomposed` (every thread's stacks: a
#: sweep's blocks run on Dask's threads, which do not share a context).
_DECOMPOSED: list[list[np.ndarray]] = []
_KEEPING = threading.Lock()


@contextlib.contextmanager
def decomposed() -> Iterator[list[np.ndarray]]:
    """The stacks of distinct A that the batched closed forms decompose while
    it is open, in any thread of the process (each (m, n, n), as
    ``np.linalg.eig`` takes it; those found in a :class:`SpectraMemo` are
    not decomposed, so not listed): what a bench times alone, by
    :func:`decompose`, as the floor of the method. Nothing is copied; the
    list holds the stacks the solver made anyway."""
    kept: list[np.ndarray] = []
    with _KEEPING:
        _DECOMPOSED.append(kept)
    try:
        yield kept
    finally:
        with _KEEPING:                       # by identity: lists compare by content
            del _DECOMPOSED[next(i for i, k in enumerate(_DECOMPOSED) if k is kept)]


def decompose(A: np.ndarray) -> tuple[np.ndarray, ...]:
    """λ, V and the left vectors of a stack of A (m, n, n), in LAPACK's order:
    ``(lam, vr, mu, vl, by_inverse)``. Where ``by_inverse`` (V well
    conditioned, :data:`LEFT_COND`) μ = λ and the columns of ``vl`` are the
    rows of V⁻¹; elsewhere μ, W are ``np.linalg.eig`` of Aᵀ, in its order.
    Each column of V and W has unit length.

    Parameters
    ----------
    A : ndarray, shape (m, n, n)
        The matrices, each decomposed alone (a matrix's results do not
        depend on the others of the stack).
    """
    lam, vr = np.linalg.eig(A)                 # real where all of the stack's are
    lam, vr = lam.astype(complex, copy=False), vr.astype(complex, copy=False)
    mu, vl = lam.copy(), np.empty_like(vr)
    by_inverse = np.zeros(A.shape[0], dtype=bool)
    with np.errstate(all="ignore"):
        try:
            can, rows, V = np.arange(A.shape[0]), np.linalg.inv(vr), vr
        except np.linalg.LinAlgError:                        # an exactly singular V
            det = np.linalg.det(vr)
            can = np.flatnonzero(np.isfinite(det) & (det != 0))  # no zero pivot
            V = vr[can]
            rows = np.linalg.inv(V) if can.size else None
    if can.size:
        with np.errstate(all="ignore"):
            cond = (np.abs(V).sum(axis=1).max(axis=1)
                    * np.abs(rows).sum(axis=1).max(axis=1))
        good = np.isfinite(cond) & (cond <= LEFT_COND)
        W = np.swapaxes(rows[good], 1, 2)
        vl[can[good]] = W / np.linalg.norm(W, axis=1, keepdims=True)
        by_inverse[can[good]] = True
    rest = np.flatnonzero(~by_inverse)
    if rest.size:
        mu[rest], vl[rest] = np.linalg.eig(np.swapaxes(A[rest], 1, 2))
    return lam, vr, mu, vl, by_inverse


class SpectraMemo:
    """The spectra of the distinct A met in one batched run, by A's bytes, for
    every mode of it (:func:`spectra`), up to :data:`MEMO_BYTES`. A spectrum
    depends on A alone, each decomposed alone: one found here is bit for bit
    the one a fresh decomposition gives."""

    def __init__(self, limit: int = MEMO_BYTES, trial: int = MEMO_TRIAL) -> None:
        self.limit, self.trial, self.size, self.hits = limit, trial, 0, 0
        self.closed = False
        self._tables: dict[int, _Table] = {}

    def find(self, A: np.ndarray, hashes: np.ndarray) -> tuple[np.ndarray, tuple | None]:
        """Which of the stack A (with its :func:`_hashes`) are kept: per matrix
        True where found, and the found ones' spectra (None if none)."""
        table = self._tables.get(A.shape[1])
        if table is None:
            return np.zeros(A.shape[0], dtype=bool), None
        found, kept = table.find(A, hashes)
        self.hits += int(found.sum())
        return found, kept

    def keep(self, A: np.ndarray, hashes: np.ndarray, values: tuple) -> None:
        """Keep the spectra ``values`` of the stack A, while there is room
        (none once the trial's bytes passed without a hit)."""
        n = A.shape[1]
        row_bytes = A[0].nbytes + 16 + sum(v[0].nbytes for v in values)
        if self.closed:
            return
        if not self.hits and self.size + A.shape[0] * row_bytes > self.trial:
            self.closed, self.size = True, 0        # nothing shared so far: let all go
            self._tables.clear()
            return
        table = self._tables.setdefault(n, _Table(n))
        take = min(A.shape[0], max(self.limit - self.size, 0) // row_bytes)
        if take:
            table.keep(A[:take], hashes[:take], tuple(v[:take] for v in values))
            self.size += take * row_bytes


class _Table:
    """The kept spectra of A of one size (:class:`RowChunks`: A's entries, then
    the spectra), looked up by hash (kept sorted) and confirmed byte for byte."""

    def __init__(self, n: int) -> None:
        self.n = n
        self.rows = RowChunks()
        self.keys = np.zeros(0, dtype=np.int64)
        self.order = np.zeros(0, dtype=np.intp)

    def find(self, A: np.ndarray, hashes: np.ndarray) -> tuple[np.ndarray, tuple | None]:
        if not self.keys.size:
            return np.zeros(A.shape[0], dtype=bool), None
        at = np.minimum(np.searchsorted(self.keys, hashes), self.keys.size - 1)
        found = self.keys[at] == hashes
        row = self.order[at[found]]
        kept = self.rows.take(row)
        same = np.all(kept[0] == A[found].reshape(-1, self.n ** 2), axis=1)
        if not same.all():                     # a hash shared by another A
            found[np.flatnonzero(found)[~same]] = False
            kept = tuple(v[same] for v in kept)
        return found, (kept[1:] if found.any() else None)

    def keep(self, A: np.ndarray, hashes: np.ndarray, values: tuple) -> None:
        rows = self.rows.append((A.reshape(A.shape[0], -1),) + values)
        keys = np.concatenate([self.keys, hashes])
        sort = np.argsort(keys, kind="stable")
        self.keys, self.order = keys[sort], np.concatenate([self.order, rows])[sort]


def spectra(A: np.ndarray, memo: SpectraMemo | None = None) -> tuple[np.ndarray, ...]:
    """Eigenvalues and unit right and left eigenvectors of each distinct A
    (bytes compared; :func:`decompose`, each A decomposed alone, or found in
    ``memo``), both spectra in one order (:func:`_ordered`): ``first`` (the
    first design of each distinct A), ``inverse`` (per design, its A), λ, V,
    μ, W, the categories, ``bad``: spectra of A and Aᵀ that do not match, a
    complex pair closer to the real axis than 10⁻⁵ of the scale, a value not
    finite, three nearly equal eigenvalues, or a nearly defective one (see
    ``batched_forms``' docstring); and ``twin``: True at the first of two
    nearly equal eigenvalues (not equal to rounding).

    Parameters
    ----------
    A : ndarray, shape (k, n, n)
        Each design's matrix (designs of equal A share one decomposition).
    memo : SpectraMemo, optional
        The run's spectra met so far: an A found there is not decomposed
        again, a fresh one is kept there.
    """
    k = A.shape[0]
    flat = np.ascontiguousarray(A.reshape(k, -1))
    first, inverse = first_of_equal(flat)
    distinct = A[first]
    if memo is None:
        return (first, inverse) + _sorted_out(distinct)
    hashes = _hashes(flat[first])
    found, kept = memo.find(distinct, hashes)
    fresh = np.flatnonzero(~found)
    values = None
    if fresh.size:
        new = distinct[fresh]
        values = _sorted_out(new)
        memo.keep(new, hashes[fresh], values)
    if kept is None:
        return (first, inverse) + values
    if values is None:
        return (first, inverse) + kept
    out = []
    for new, old in zip(values, kept):
        both = np.empty((distinct.shape[0],) + new.shape[1:], new.dtype)
        both[fresh], both[found] = new, old
        out.append(both)
    return (first, inverse) + tuple(out)


def _sorted_out(distinct: np.ndarray) -> tuple[np.ndarray, ...]:
    """λ, V, μ, W, categories, ``bad`` and ``twin`` of a stack of distinct A
    (:func:`spectra`)."""
    if _DECOMPOSED:
        with _KEEPING:
            for kept in _DECOMPOSED:
                kept.append(distinct)
    lam, vr, mu, vl, by_inverse = decompose(distinct)
    scale = np.maximum(np.abs(lam).max(axis=1), 1.0)[:, None]
    tol = 1e-6 * scale
    order = _order(lam, tol)
    lam, vr, cat = _ordered(lam, vr, order, tol)
    vl[by_inverse] = np.take_along_axis(vl[by_inverse], order[by_inverse, None, :], axis=2)
    mu[by_inverse] = lam[by_inverse]
    cat_mu = cat.copy()
    rest = np.flatnonzero(~by_inverse)
    if rest.size:
        m_, w_, c_ = _ordered(mu[rest], vl[rest], _order(mu[rest], tol[rest]), tol[rest])
        mu[rest], vl[rest], cat_mu[rest] = m_, w_, c_
    live = cat < 3
    bad = np.any(cat != cat_mu, axis=1) | np.any(live & (np.abs(lam - mu) >= tol), axis=1)
    im = np.abs(lam.imag)
    bad |= np.any(live & (im > 0) & (im < 1e-5 * scale), axis=1)
    bad |= ~np.all(np.isfinite(lam), axis=1) | ~np.all(np.isfinite(mu), axis=1)
    # a cluster is one eigenvalue with one projector where its members are equal
    # to rounding (equal drives); two nearly equal ones (two sides equal but for
    # a little) are twins: two terms whose projectors come from their pair's
    # (batched_forms._twins); three or more nearly equal, or twins beside a
    # cluster, go to the per-design route, whose clusters resolve them
    gap = np.abs(np.diff(lam, axis=1))
    same = live[:, 1:] & live[:, :-1] & (cat[:, 1:] == cat[:, :-1])
    equal = same & (gap <= EQUAL * scale)
    twin = same & (gap <= CLUSTER * np.abs(lam[:, :-1])) & ~equal
    bad |= np.any(twin[:, 1:] & (twin[:, :-1] | equal[:, :-1]), axis=1)
    bad |= np.any(twin[:, :-1] & equal[:, 1:], axis=1)
    # nearly defective: a neighbour within CLUSTER (a pair's conjugate included)
    # and a condition number above NEAR_COND
    with np.errstate(divide="ignore", over="ignore", invalid="ignore"):  # defective: inf
        kappa = 1.0 / np.abs(np.sum(vl * vr, axis=1))
    near = np.zeros_like(live)
    for j in range(lam.shape[1]):
        d = np.abs(lam - lam[:, j:j + 1])
        d[:, j] = np.inf
        d[d <= EQUAL * scale] = np.inf                # equal: one cluster, one projector
        near[:, j] = d.min(axis=1) <= CLUSTER * np.abs(lam[:, j])
    bad |= np.any(live & near & ~(kappa <= NEAR_COND), axis=1)
    first_twin = np.concatenate([twin, np.zeros((twin.shape[0], 1), bool)], axis=1)
    return lam, vr, mu, vl, cat, bad, first_twin


#: Odd multipliers of :func:`_hashes`, per row width (fixed: no run depends
#: on a seed).
_MIX: dict[int, np.ndarray] = {}


def _hashes(rows: np.ndarray) -> np.ndarray:
    """One int64 a row of float64 (its bits times fixed odd numbers, summed)."""
    bits = np.ascontiguousarray(rows).view(np.int64)
    width = bits.shape[1]
    if width not in _MIX:
        _MIX[width] = (np.random.default_rng(28 + width).integers(
            1, 2**62, size=width, dtype=np.int64) * 2 + 1)
    return (bits * _MIX[width]).sum(axis=1)


def first_of_equal(rows: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The first of each group of rows equal byte for byte, and per row its
    group: rows hashed to one integer (:func:`_hashes`), which is sorted (a
    sort of whole rows as bytes costs several times more); the groups checked
    byte for byte, and a collision falls back to the sort of rows.

    Parameters
    ----------
    rows : ndarray, shape (k, w), float64, C-contiguous
        The rows compared.
    """
    if rows.dtype.itemsize == 8 and rows.flags.c_contiguous:
        bits = rows.view(np.int64)
        _, first, inverse = np.unique(_hashes(rows), return_index=True, return_inverse=True)
        inverse = inverse.ravel()
        if np.array_equal(bits[first][inverse], bits):
            return first, inverse
    keys = np.ascontiguousarray(rows).view(
        np.dtype((np.void, rows.dtype.itemsize * rows.shape[1]))).ravel()
    _, first, inverse = np.unique(keys, return_index=True, return_inverse=True)
    return first, inverse.ravel()


def _order(values: np.ndarray, tol: np.ndarray) -> np.ndarray:
    """The order of :func:`_ordered`: by (category, real, imaginary part)."""
    return np.lexsort((values.imag, values.real, _categories(values, tol)), axis=-1)


def _categories(values: np.ndarray, tol: np.ndarray) -> np.ndarray:
    """0 real nonzero, 1 upper half plane, 2 lower, 3 the kernel (|λ| ≤ tol)."""
    live = np.abs(values) > tol
    return np.where(~live, 3, np.where(values.imag == 0, 0, np.where(values.imag > 0, 1, 2)))


def _ordered(values, vectors, order, tol):
    """Eigenvalues, their vectors and categories in ``order`` (:func:`_order`)."""
    values = np.take_along_axis(values, order, axis=1)
    return (values, np.take_along_axis(vectors, order[:, None, :], axis=2),
            _categories(values, tol))
