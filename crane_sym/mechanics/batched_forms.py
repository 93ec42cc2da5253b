"""Closed forms of one phase for many designs at once, and their signals.

The batched sibling of :mod:`crane_sym.mechanics.closed_forms`' numeric route:
k designs in one mode have matrices M = [[A, b], [0, 0]] of one shape; the
spectra of the distinct A (a swept value that moves b only, a backlash,
shares A), :mod:`crane_sym.mechanics.batched_spectra`, give every design's
eigenvalues and right and left eigenvectors. Each simple nonzero
eigenvalue λ of M (A's, with the right vector (v, 0) and the left (w, wᵀb/λ))
gives the spectral projector C_λ = v (wᵀ, wᵀb/λ) / (wᵀ v): its A-block once
per distinct A, its last column per design, b brought in algebraically. The
generalized kernel (rigid modes, the constant input) gets the exact
nilpotent series Σ_j (N t)^j / j! · Q with Q = I − Σ C_λ and N = M Q, as the
per-design route does. A pair λ = σ ± iω folds into t^0 e^{σt} cos ωt and
sin ωt terms.

Equal nonzero eigenvalues (equal to rounding, ``EQUAL`` of the spectrum's
scale: two equal drives) form a cluster with one projector
C = R (Lᵀ R)⁻¹ Lᵀ from its right and left eigenvectors. Two nearly equal
ones (within ``CLUSTER`` of each other but not equal: two sides equal but
for a little) are twins, two terms whose projectors come from their pair's
(:func:`_twins`): within 3e-14 of mpmath at gaps 0 to 5e-4
(``tests/test_batched.py``), where
projectors one by one from the vectors were off by rounding over the gap
(4e-10 at a gap of 1e-5) and were refused below 10⁻⁶ (about one design in
eleven of 003's start-up, sent to the per-design route). A design is refused (for the per-design route,
which resolves nearly equal and defective eigenvalues,
:mod:`crane_sym.mechanics.spectral_clusters`) where this is not safe:
three or more nearly equal eigenvalues, twins beside a cluster, nearly
defective twins (a condition number above ``NEAR_COND``), a cluster's
condition number ‖(L̂ᵀ R̂)⁻¹‖ above ``cond_limit`` (for a simple eigenvalue
1/|ŵᵀv̂|; a defective eigenvalue makes it huge), a complex pair closer to the
real axis than 10⁻⁵ of the scale, or (where the left vectors come from the
eigen-decomposition of Aᵀ) spectra of A and Aᵀ that do not match.

:class:`crane_sym.mechanics.batched_cache.FormCache` keeps the forms per
mode.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from crane_sym.mechanics.batched_spectra import EQUAL, SpectraMemo, spectra

__all__ = ["BatchForm", "COND_LIMIT", "batch_forms"]

#: Largest eigenvalue condition number the batched route accepts: a design's
#: error grows like eps times it, so 1e5 keeps it near 1e-11 (a nearly
#: defective pair, critical damping, goes to the per-design route).
COND_LIMIT = 1e5


@dataclass(frozen=True)
class BatchForm:
    """exp(M t) of k designs in one mode: Σ_j C_j β_j(t), β_j = t^p e^{σt} {cos, sin}(ωt).

    Attributes
    ----------
    n : int
        Dimension of the state.
    powers, sine : ndarray, shape (T,)
        p of each term, and True where it carries sin(ωt); shared by the designs.
    sigmas, omegas : ndarray, shape (k, T)
        σ and ω of each design's terms.
    coefficients : ndarray, shape (k, T, n + 1, n + 1) or (k, T, n, n + 1)
        The real matrices C_j of each design (their last row, that of the
        constant 1, may be left out: only the state's rows are used).
    real, pairs : int
        The terms are ``real`` exponentials, then ``pairs`` (cos, sin) pairs,
        then the powers 0, 1, … of the generalized kernel.
    """

    n: int
    powers: np.ndarray
    sine: np.ndarray
    sigmas: np.ndarray
    omegas: np.ndarray
    coefficients: np.ndarray
    real: int = 0
    pairs: int = 0

    def vectors(self, x0: np.ndarray) -> np.ndarray:
        """C_j (x0, 1) of each design, shape (k, T, rows of C_j)."""
        z0 = np.concatenate([x0, np.ones((x0.shape[0], 1))], axis=1)
        k, T, rows, size = self.coefficients.shape
        # one (T·rows, n + 1) matrix-vector product a design, not T small ones
        flat = self.coefficients.reshape(k, T * rows, size)
        return (flat @ z0[:, :, None]).reshape(k, T, rows)

    def take(self, rows: np.ndarray) -> "BatchForm":
        """The designs ``rows`` only (a row may repeat)."""
        return BatchForm(self.n, self.powers, self.sine, self.sigmas[rows], self.omegas[rows],
                         self.coefficients[rows], self.real, self.pairs)

    def state(self, t: np.ndarray, vectors: np.ndarray) -> np.ndarray:
        """x(t) of each design (t shape (k,)), from :meth:`vectors`."""
        return np.einsum("kt,kti->ki", self.basis(t), vectors)[:, : self.n]

    def basis(self, t: np.ndarray) -> np.ndarray:
        """β_j(t) of each design, shape (k, T), block by block: e^{σt}; one
        cos and one sin of a pair's ωt (times e^{σt} where σ ≠ 0); t^j."""
        q, p = self.real, self.pairs
        tt = t[:, None]
        out = np.empty((t.size, self.powers.size))
        if q:
            out[:, :q] = np.exp(self.sigmas[:, :q] * tt)
        if p:
            wt = self.omegas[:, q:q + 2 * p:2] * tt
            c, s = np.cos(wt), np.sin(wt)
            sigma = self.sigmas[:, q:q + 2 * p:2]
            if sigma.any():
                grow = np.exp(sigma * tt)
                c *= grow
                s *= grow
            out[:, q:q + 2 * p:2], out[:, q + 1:q + 2 * p:2] = c, s
        out[:, q + 2 * p:] = tt ** self.powers[q + 2 * p:]
        return out


def batch_forms(A: np.ndarray, b: np.ndarray, cond_limit: float = COND_LIMIT,
                memo: SpectraMemo | None = None) -> tuple[list[tuple[np.ndarray, BatchForm]],
                                                          np.ndarray]:
    """The closed forms of x' = A x + b for a stack of designs.

    Returns ``(parts, refused)``: each part is (positions in the stack, its
    :class:`BatchForm`), designs of one spectral structure (the same clusters
    of nonzero real eigenvalues and of complex pairs); ``refused`` holds the
    positions the batched route does not take (see the module docstring).
    The spectrum and the projectors' A-blocks come from the distinct A
    (:func:`crane_sym.mechanics.batched_spectra.spectra`, found in ``memo``
    where a mode before met the same A); b enters each design's last column
    algebraically.
    """
    k, n = b.shape
    first, inverse, lam, vr, mu, vl, cat, bad, twin = spectra(A, memo)
    live = cat < 3
    # clusters: equal nonzero eigenvalues (two equal drives), each one projector
    scale = np.maximum(np.abs(lam).max(axis=1, initial=0.0), 1.0)[:, None]
    step = np.abs(np.diff(lam, axis=1)) > EQUAL * scale
    starts = np.concatenate([np.ones((first.size, 1), bool),
                             step | (np.diff(cat, axis=1) != 0)], axis=1)
    pattern = np.where(live, cat * 2 + starts, 7)
    parts, refused = [], list(np.flatnonzero(bad[inverse]))
    ok = np.flatnonzero(~bad)
    if ok.size:
        kinds, which = _unique_rows(pattern[ok])
        group = np.full(first.size, -1)
        group[ok] = which
        of_design = group[inverse]
        for g, kind in enumerate(kinds):
            where = np.flatnonzero(of_design == g)
            d = ok[which == g]                        # its distinct A
            slot = np.full(first.size, -1)
            slot[d] = np.arange(d.size)
            form, fine = _form(A[where], b[where], slot[inverse[where]], lam[d], vr[d],
                               mu[d], vl[d], twin[d], kind, cond_limit)
            refused.extend(where[~fine])
            if form is not None:
                parts.append((where[fine], form))
    return parts, np.array(sorted(refused), dtype=np.intp)


def _unique_rows(pattern: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """``np.unique(pattern, axis=0, return_inverse=True)`` of small integer rows
    (0 … 7), each read as one base-8 number: the same rows in the same order."""
    if pattern.shape[1] > 20:
        kinds, which = np.unique(pattern, axis=0, return_inverse=True)
        return kinds, which.ravel()
    codes = pattern.astype(np.int64) @ (8 ** np.arange(pattern.shape[1] - 1, -1, -1,
                                                        dtype=np.int64))
    _, first, which = np.unique(codes, return_index=True, return_inverse=True)
    return pattern[first], which.ravel()


def _projector(A, b, slot, mu, R, L) -> tuple[np.ndarray, np.ndarray]:
    """The projector C = V G⁻¹ [Wᵀ | s] of M = [[A, b], [0, 0]] onto the
    eigenvalues of the columns R, L (right and left vectors of the distinct
    A, ``mu`` their eigenvalues), per design, and its condition number (see
    :func:`_form`)."""
    k, n = b.shape
    m = R.shape[2]
    gram = np.einsum("dim,din->dmn", L, R)
    with np.errstate(all="ignore"):
        if m == 1:                          # a simple eigenvalue: G⁻¹ = 1/(wᵀv)
            inv = 1.0 / gram
        else:
            inv = np.linalg.inv(gram) if np.all(np.isfinite(gram)) else gram * np.nan
        s_ = np.einsum("ki,kim->km", b.astype(complex), L[slot]) / mu[slot]
        norm = np.sqrt(1.0 + np.abs(s_) ** 2)
        scaled = inv[slot] * norm[:, None, :]
        cond = (np.linalg.norm(scaled, ord=2, axis=(1, 2)) if m > 1
                else np.abs(scaled[:, 0, 0]))
    safe = np.nan_to_num(inv)
    C = np.zeros((k, n + 1, n + 1), dtype=complex)
    if m == 1:                              # outer products, not three-operand einsums
        left = R[:, :, 0] * safe[:, 0]
        C[:, :n, :n] = (left[:, :, None] * L[:, None, :, 0])[slot]
        C[:, :n, n] = left[slot] * np.nan_to_num(s_)
    else:
        C[:, :n, :n] = np.einsum("dim,dmn,djn->dij", R, safe, L)[slot]
        C[:, :n, n] = np.einsum("kim,kmn,kn->ki", R[slot], safe[slot], np.nan_to_num(s_))
    return C, cond


def _twins(A, b, slot, lam, vr, mu, vl, j: int) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The projectors C, C' of twins j, j + 1 (two nearly equal eigenvalues
    λ, λ') per design, and their condition number: the pair's projector P
    (from both columns: whichever vectors of the nearly shared plane ``eig``
    returns, P is the same), then C = (M − λ' I) P / (λ − λ') and C' = P − C.
    Computed one by one from the vectors, they would be wrong in the plane
    by rounding over the gap, and the left and right vectors might not be
    each other's. Here the error of (M − λ' I) P, over the gap, enters
    e^{λt} C + e^{λ't} C' times (e^{λt} − e^{λ't}) / (λ − λ') ≈ t e^{λt}:
    no worse than the rounding of P."""
    n = b.shape[1]
    P, cond = _projector(A, b, slot, mu[:, j:j + 2], vr[:, :, j:j + 2], vl[:, :, j:j + 2])
    M = np.zeros_like(P)
    M[:, :n, :n] = A
    M[:, :n, n] = b
    other = lam[slot, j + 1][:, None, None]
    with np.errstate(all="ignore"):
        C = (M @ P - other * P) / (lam[slot, j] - lam[slot, j + 1])[:, None, None]
    return C, P - C, cond


def _form(A, b, slot, lam, vr, mu, vl, twin, kind, cond_limit: float) -> tuple[
        BatchForm | None, np.ndarray]:
    """The :class:`BatchForm` of designs of one cluster pattern ``kind`` (per
    eigenvalue: 2·category + starts-a-cluster, 7 for the kernel), and which
    designs it holds. ``lam``, ``vr``, ``mu``, ``vl`` belong to the designs'
    distinct A, design i to ``slot[i]``; ``twin`` marks the first of two
    nearly equal eigenvalues (:func:`_twins`).

    A cluster's projector of M = [[A, b], [0, 0]] is C = V G⁻¹ [Wᵀ | s]
    (G = WᵀV, s_j = w_jᵀb/μ_j: the left vector of M is (w, s)): its A-block
    is computed once per distinct A, its last column per design. Its
    condition number is ‖G⁻¹ diag(√(1 + |s|²))‖ (the unit left vectors of
    M); a cluster above ``cond_limit`` (nearly dependent vectors, a
    defective eigenvalue) refuses the design."""
    k, n = b.shape
    size = n + 1
    live = int(np.sum(kind < 7))
    heads = [j for j in range(live) if kind[j] % 2 == 1]
    clusters = [(j, (heads[h + 1] if h + 1 < len(heads) else live) - j, int(kind[j] // 2))
                for h, j in enumerate(heads)]
    fine = np.ones(k, dtype=bool)
    projector = np.zeros((k, size, size))
    real, pairs = [], []
    made = {j: _projector(A, b, slot, mu[:, j:j + m], vr[:, :, j:j + m], vl[:, :, j:j + m])
            for j, m, cat in clusters if cat != 2}
    for j in range(live - 1):                       # twins: their pair's projector
        rows = np.flatnonzero(twin[slot, j])
        if rows.size and j in made and j + 1 in made:
            C, C_next, cond = _twins(A[rows], b[rows], slot[rows], lam, vr, mu, vl, j)
            for c, part in ((j, C), (j + 1, C_next)):
                made[c][0][rows], made[c][1][rows] = part, cond
    for j, m, cat in clusters:
        if cat == 2:
            continue                                  # the conjugates of the upper half
        C, cond = made[j]
        fine &= cond <= cond_limit
        value = lam[slot, j:j + m].mean(axis=1)
        if cat == 0:
            real.append((value.real, C.real))
            projector += C.real
        else:
            pairs.append((value, C))
            projector += 2 * C.real
    if not fine.any():
        return None, fine
    powers, sine, sigmas, omegas = [], [], [], []
    # each term's C_j, the state's rows only (the constant's row is 0 … 0 1),
    # written in place: no list of full matrices stacked at the end
    coefficients = np.empty((k, len(real) + 2 * len(pairs) + size - live, n, size))

    def term_of(power: int, is_sine: bool, sigma, omega, rows) -> None:
        coefficients[:, len(powers)] = rows
        powers.append(power), sine.append(is_sine), sigmas.append(sigma), omegas.append(omega)
    for sigma, C in real:                                 # real: e^{σt}
        term_of(0, False, sigma, np.zeros(k), C.real[:, :n])
    for value, C in pairs:                                # a pair: 2 Re C cos, −2 Im C sin
        # an undamped pair's σ is rounding (~1e-15 ω): 0, so no e^{σt} is evaluated
        sigma = np.where(np.abs(value.real) <= 1e-12 * np.abs(value), 0.0, value.real)
        term_of(0, False, sigma, np.abs(value.imag), 2 * C.real[:, :n])
        term_of(0, True, sigma, np.abs(value.imag), -2 * C.imag[:, :n])
    M = np.zeros((k, size, size))
    M[:, :n, :n] = A
    M[:, :n, n] = b
    kept = np.flatnonzero(fine)
    with np.errstate(all="ignore"):                      # a refused design's may overflow
        Q = np.eye(size) - projector
        N = M @ Q
        term = Q
        for j in range(size - live):                     # the exact nilpotent series
            if j:
                term = N @ term / j
                if not term[kept].any():                 # N^j = 0 (a free side): no more
                    break
            term_of(j, False, np.zeros(k), np.zeros(k), term[:, :n])
    form = BatchForm(n, np.array(powers, dtype=float), np.array(sine, dtype=bool),
                     np.stack(sigmas, axis=1), np.stack(omegas, axis=1),
                     coefficients[:, :len(powers)], len(real), len(pairs))
    return (form if fine.all() else form.take(kept)), fine
