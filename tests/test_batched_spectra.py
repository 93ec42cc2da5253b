"""The spectra of the batched closed forms: left vectors from V⁻¹ where V is
well conditioned and from Aᵀ where it is not, a run's memo of spectra, the
chunked stores, and the short-row sums of the signals."""
import numpy as np
import pytest

from crane_sym.mechanics import batched_spectra
from crane_sym.mechanics.batched_signals import _rowsum
from crane_sym.mechanics.batched_spectra import SpectraMemo, decompose, spectra
from crane_sym.mechanics.row_chunks import RowChunks


def _random_stack(k: int, n: int, seed: int) -> np.ndarray:
    rng = np.random.default_rng(seed)
    return rng.normal(size=(k, n, n))


def test_left_vectors_from_the_inverse_are_the_left_eigenvectors():
    """Where V is well conditioned the left vectors are V⁻¹'s rows: each
    wᵀA = λwᵀ to rounding, unit length, and parallel to ``eig`` of Aᵀ's
    vector of the same eigenvalue."""
    A = _random_stack(200, 6, 1)
    lam, vr, mu, vl, by_inverse = decompose(A)
    assert by_inverse.mean() > 0.9
    assert lam.dtype == vr.dtype == vl.dtype == complex
    W = vl[by_inverse]
    Ai, li = A[by_inverse], lam[by_inverse]
    residual = np.einsum("kij,kil->klj", Ai, W) - li[:, :, None] * np.swapaxes(W, 1, 2)
    assert np.abs(residual).max() < 1e-12 * np.abs(Ai).max()
    np.testing.assert_allclose(np.linalg.norm(W, axis=1), 1.0, rtol=1e-14)
    assert np.array_equal(mu[by_inverse], li)
    # the same direction as eig of Aᵀ's left vector of that eigenvalue
    nu, U = np.linalg.eig(np.swapaxes(Ai, 1, 2))
    for d in range(0, Ai.shape[0], 17):
        for j in range(6):
            u = U[d][:, np.argmin(np.abs(nu[d] - li[d, j]))]
            assert abs(abs(np.vdot(u, W[d][:, j])) - 1.0) < 1e-9


def test_a_defective_kernel_takes_the_left_vectors_from_the_transpose():
    """A body free to roll (x' = v, v' = 0: a Jordan block at 0) makes V
    singular: no inverse is taken, its left vectors come from ``eig`` of Aᵀ,
    and the live eigenvalue's projector is still right."""
    A = np.zeros((2, 4, 4))
    A[:, 0, 1] = 1.0                                  # the free body
    A[:, 2, 3] = 1.0
    A[:, 3, 2], A[:, 3, 3] = -4.0, -0.5               # a damped oscillator
    A[1, 3, 1] = 0.3                                  # coupled to the body's speed
    lam, vr, mu, vl, by_inverse = decompose(A)
    assert not by_inverse.any()
    out = spectra(A)
    first, inverse, lam, vr, mu, vl, cat, bad, twin = out
    assert not bad.any()
    assert np.all((cat == 3).sum(axis=1) == 2)        # the kernel: two zeros


def test_an_all_real_stack_keeps_complex_arrays():
    """``np.linalg.eig`` returns real arrays where every eigenvalue of the
    stack is real; a memo that kept those would cast later complex ones."""
    A = np.diag([-1.0, -2.0, -3.0])[None]
    lam, vr, mu, vl, _ = decompose(A)
    assert lam.dtype == vr.dtype == mu.dtype == vl.dtype == complex


def test_a_spectrum_found_in_the_memo_is_the_fresh_one_bit_for_bit():
    """Two modes that share A (a stack, then the same A shuffled with new
    ones): what the memo returns equals a fresh decomposition byte for byte."""
    A = _random_stack(50, 5, 2)
    memo = SpectraMemo()
    spectra(A[:30], memo)
    mixed = np.concatenate([A[20:50], A[5:15]])
    got = spectra(mixed, memo)
    fresh = spectra(mixed)
    for g, f in zip(got, fresh):
        assert g.dtype == f.dtype and np.array_equal(g.view(np.uint8), f.view(np.uint8))


def test_a_hash_shared_by_two_matrices_is_not_a_hit(monkeypatch):
    """Every A hashed alike (a collision): the bytes decide, no spectrum of
    another A is returned."""
    A = _random_stack(12, 4, 3)
    monkeypatch.setitem(batched_spectra._MIX, 16, np.zeros(16, np.int64))
    memo = SpectraMemo()
    spectra(A[:6], memo)
    got = spectra(A[3:12], memo)
    fresh = spectra(A[3:12])
    for g, f in zip(got, fresh):
        assert np.array_equal(g, f)


def test_the_memo_keeps_no_more_than_its_limit():
    """Past its bytes, new spectra are computed and not kept."""
    A = _random_stack(100, 6, 4)
    memo = SpectraMemo(limit=20_000)
    spectra(A[:2], memo)
    spectra(A[:2], memo)                               # a hit: the memo is of use
    spectra(A, memo)
    assert 0 < memo.size <= 20_000
    kept = memo._tables[6].rows.count
    assert 0 < kept < 100
    found, _ = memo.find(A, batched_spectra._hashes(A.reshape(100, -1)))
    assert found.sum() == kept


def test_row_chunks_read_rows_across_chunks_in_order():
    rng = np.random.default_rng(6)
    parts = [(rng.normal(size=(k, 3)), rng.integers(0, 9, size=k)) for k in (4, 1, 7)]
    store = RowChunks()
    for p in parts:
        store.append(p)
    whole = tuple(np.concatenate(x) for x in zip(*parts))
    rows = np.array([11, 0, 4, 4, 5, 3, 10])
    got = store.take(rows)
    assert store.count == 12
    assert all(np.array_equal(g, w[rows]) for g, w in zip(got, whole))


@pytest.mark.parametrize("width", range(0, 13))
def test_short_row_sums_are_numpys_bits(width):
    """The signals' column-by-column sum is NumPy's own up to 7 terms (the
    same order) and NumPy's from 8 (pairwise along contiguous rows): the
    same bits either way, rows contiguous or not."""
    rng = np.random.default_rng(width)
    a = rng.normal(size=(5000, width)) * 10.0 ** rng.integers(-8, 8, size=(5000, width))
    assert np.array_equal(_rowsum(a), a.sum(axis=1))
    strided = np.asfortranarray(a)
    assert np.array_equal(_rowsum(strided), strided.sum(axis=1))


def test_a_designs_spectrum_does_not_depend_on_its_neighbours():
    """A stack where some designs take their left vectors from V⁻¹ and one
    from Aᵀ (a Jordan block at 0, made dense by a similarity): each design's
    spectrum is the one it gets decomposed alone, byte for byte (what lets
    a sweep's blocks be cut anywhere, and the memo share one)."""
    A = _random_stack(6, 4, 7)
    S = np.random.default_rng(8).normal(size=(4, 4))
    J = np.zeros((4, 4))
    J[0, 1], J[2, 2], J[3, 3] = 1.0, -1.0, -2.0
    A[2] = S @ J @ np.linalg.inv(S)
    together = decompose(A)
    assert not together[4][2] and together[4].sum() >= 4
    for i in range(6):
        alone = decompose(A[i:i + 1])
        for t, a in zip(together, alone):
            assert np.array_equal(t[i:i + 1], a)


def test_a_memo_without_hits_lets_its_spectra_go():
    """Every mode's A its own (003's start-up): once the trial's bytes pass
    with no hit, the memo holds nothing and keeps nothing more, and the
    spectra are the fresh ones."""
    A = _random_stack(60, 5, 9)
    memo = SpectraMemo(trial=20_000)
    spectra(A[:5], memo)
    assert memo.size > 0 and not memo.closed
    got = spectra(A[5:60], memo)
    assert memo.closed and memo.size == 0 and not memo._tables
    spectra(A[:5], memo)
    assert memo.hits == 0 and not memo._tables
    for g, f in zip(got, spectra(A[5:60])):
        assert np.array_equal(g, f)


def test_the_recorder_keeps_the_stacks_every_thread_decomposes():
    """``decomposed`` lists what a sweep's Dask threads decompose (they share
    no context with the bench that opened it), and lets go once closed."""
    from concurrent.futures import ThreadPoolExecutor
    rng = np.random.default_rng(3)
    stacks = [rng.standard_normal((5, 3, 3)) for _ in range(4)]
    with batched_spectra.decomposed() as kept:
        with ThreadPoolExecutor(2) as pool:
            list(pool.map(spectra, stacks))
    assert len(kept) == 4
    def matrices(stacks):                     # a stack's distinct A, in its own order
        return sorted(a.tobytes() for A in stacks for a in A)
    assert matrices(kept) == matrices(stacks)
    assert not batched_spectra._DECOMPOSED
    spectra(stacks[0])
    assert len(kept) == 4
