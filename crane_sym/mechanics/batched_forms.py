"""Closed forms of one phase for many designs at once, and their signals.

The batched sibling of :mod:`crane_sym.mechanics.closed_forms`' numeric route:
k designs in one mode have matrices M = [[A, b], [0, 0]] of one shape; one
call of ``np.linalg.eig`` on the stack of the distinct A (a swept value that
moves b only, a backlash, shares A) and one on their transposes give every
design's eigenvalues and right and left eigenvectors, b brought in
algebraically (:func:`_augmented_eig`), the left matched to the right by
nearest eigenvalue. Each simple nonzero
eigenvalue λ gives the spectral projector C_λ = v wᵀ / (wᵀ v); the
generalized kernel (rigid modes, the constant input) gets the exact
nilpotent series Σ_j (N t)^j / j! · Q with Q = I − Σ C_λ and N = M Q, as the
per-design route does. A pair λ = σ ± iω folds into t^0 e^{σt} cos ωt and
sin ωt terms.

Equal nonzero eigenvalues (within 10⁻⁶ of the spectrum's scale: two equal
drives) form a cluster with one projector C = R (Lᵀ R)⁻¹ Lᵀ from its right
and left eigenvectors, as the per-design route clusters them. A design is
refused (for the per-design route) where this is not safe: a cluster's
condition number ‖(L̂ᵀ R̂)⁻¹‖ above ``cond_limit`` (for a simple eigenvalue
1/|ŵᵀv̂|; a defective eigenvalue makes it huge), a complex pair closer to the
real axis than 10⁻⁵ of the scale, or spectra of M and Mᵀ that do not match.

:class:`FormCache` keeps each design's forms per mode: a mode's (A, b)
depend on the design only, so a design returning to a mode reuses them.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

__all__ = ["BatchForm", "FormCache", "batch_forms"]

#: Largest eigenvalue condition number the batched route accepts.
COND_LIMIT = 1e8


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
        beta = basis(t, self.powers, self.sigmas, self.omegas, self.sine)
        return np.einsum("kt,kti->ki", beta, vectors)[:, : self.n]


def basis(t: np.ndarray, powers: np.ndarray, sigmas: np.ndarray, omegas: np.ndarray,
          sine: np.ndarray) -> np.ndarray:
    """β_j(t) for each row, shape (m, T); ``t`` shape (m,)."""
    tt = t[:, None]
    wt = omegas * tt
    out = np.where(sine, np.sin(wt), np.cos(wt))
    out *= np.exp(sigmas * tt)
    if powers.any():
        out *= tt ** powers
    return out


def batch_forms(A: np.ndarray, b: np.ndarray,
                cond_limit: float = COND_LIMIT) -> tuple[list[tuple[np.ndarray, BatchForm]],
                                                         np.ndarray]:
    """The closed forms of x' = A x + b for a stack of designs.

    Returns ``(parts, refused)``: each part is (positions in the stack, its
    :class:`BatchForm`), designs of one spectral structure (the same clusters
    of nonzero real eigenvalues and of complex pairs); ``refused`` holds the
    positions the batched route does not take (see the module docstring).
    """
    k, n = b.shape
    size = n + 1
    M = np.zeros((k, size, size))
    M[:, :n, :n] = A
    M[:, :n, n] = b
    lam, vr, mu, vl = _augmented_eig(A, b)
    scale = np.maximum(np.abs(lam).max(axis=1), 1.0)[:, None]
    tol = 1e-6 * scale
    # both spectra in one order: real nonzero, upper half plane, lower, kernel
    lam, vr, cat = _ordered(lam, vr, tol)
    mu, vl, cat_mu = _ordered(mu, vl, tol)
    live = cat < 3
    bad = np.any(cat != cat_mu, axis=1) | np.any(live & (np.abs(lam - mu) >= tol), axis=1)
    im = np.abs(lam.imag)
    bad |= np.any(live & (im > 0) & (im < 1e-5 * scale), axis=1)
    bad |= ~np.all(np.isfinite(lam), axis=1) | ~np.all(np.isfinite(mu), axis=1)
    # clusters: equal nonzero eigenvalues (two equal drives), each one projector
    step = np.abs(np.diff(lam, axis=1)) >= tol
    starts = np.concatenate([np.ones((k, 1), bool), step | (np.diff(cat, axis=1) != 0)], axis=1)
    pattern = np.where(live, cat * 2 + starts, 7)
    parts, refused = [], list(np.flatnonzero(bad))
    ok = np.flatnonzero(~bad)
    if ok.size:
        kinds, which = _unique_rows(pattern[ok])
        for g, kind in enumerate(kinds):
            where = ok[which == g]
            form, fine = _form(M[where], lam[where], vr[where], vl[where], kind, cond_limit)
            refused.extend(where[~fine])
            if form is not None:
                parts.append((where[fine], form))
    return parts, np.array(sorted(refused), dtype=np.intp)


def _augmented_eig(A: np.ndarray, b: np.ndarray) -> tuple[np.ndarray, ...]:
    """Eigenvalues and unit right and left eigenvectors of each M = [[A, b], [0, 0]]
    from one ``np.linalg.eig`` of each distinct A (and Aᵀ): M's spectrum is A's
    and a 0; to λ ≠ 0 belong the right vector (v, 0) and the left (w, wᵀb/λ),
    b enters algebraically. The kernel's entries (A's near-zero eigenvalues
    and M's 0) keep placeholder vectors: the kernel's projector is
    I − Σ C_λ, its vectors are never read. Each distinct A is decomposed
    alone (a stack of one design gives the same bits)."""
    k, n = b.shape
    rows = np.ascontiguousarray(A.reshape(k, -1))
    keys = rows.view(np.dtype((np.void, rows.dtype.itemsize * rows.shape[1]))).ravel()
    _, first, inverse = np.unique(keys, return_index=True, return_inverse=True)
    inverse = inverse.ravel()
    lam_a, v_a = np.linalg.eig(A[first])
    mu_a, w_a = np.linalg.eig(np.swapaxes(A[first], 1, 2))
    size = n + 1
    lam = np.zeros((k, size), dtype=complex)
    mu = np.zeros((k, size), dtype=complex)
    lam[:, :n], mu[:, :n] = lam_a[inverse], mu_a[inverse]
    vr = np.zeros((k, size, size), dtype=complex)
    vr[:, :n, :n] = v_a[inverse]
    vr[:, n, n] = 1.0
    vl = np.zeros((k, size, size), dtype=complex)
    w = w_a[inverse]
    with np.errstate(all="ignore"):
        s = np.einsum("ki,kij->kj", b.astype(complex), w) / mu[:, :n]
    s = np.where(np.isfinite(s), s, 0.0)             # a kernel's λ ≈ 0: never read
    norm = np.sqrt(1.0 + np.abs(s) ** 2)                # |w| = 1 from eig
    vl[:, :n, :n] = w / norm[:, None, :]
    vl[:, n, :n] = s / norm
    vl[:, n, n] = 1.0
    return lam, vr, mu, vl


def _distinct(A: np.ndarray, b: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Positions of the first of each distinct (A, b) (bytes compared) and,
    per design, which of them it equals."""
    k = b.shape[0]
    rows = np.ascontiguousarray(np.concatenate([A.reshape(k, -1), b], axis=1))
    keys = rows.view(np.dtype((np.void, rows.dtype.itemsize * rows.shape[1]))).ravel()
    _, first, inverse = np.unique(keys, return_index=True, return_inverse=True)
    return first, inverse.ravel()


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


def _ordered(values, vectors, tol):
    """Eigenvalues and their vectors sorted by (category, real, imaginary part);
    category 0 real nonzero, 1 upper half plane, 2 lower, 3 the kernel."""
    live = np.abs(values) > tol
    cat = np.where(~live, 3, np.where(values.imag == 0, 0, np.where(values.imag > 0, 1, 2)))
    order = np.lexsort((values.imag, values.real, cat), axis=-1)
    return (np.take_along_axis(values, order, axis=1),
            np.take_along_axis(vectors, order[:, None, :], axis=2),
            np.take_along_axis(cat, order, axis=1))


def _form(M, lam, vr, vl, kind, cond_limit: float) -> tuple[BatchForm | None, np.ndarray]:
    """The :class:`BatchForm` of designs of one cluster pattern ``kind`` (per
    position: 2·category + starts-a-cluster, 7 for the kernel), and which
    designs it holds (a cluster whose left and right vectors are nearly
    dependent, a defective eigenvalue, is refused)."""
    k, size, _ = M.shape
    n = size - 1
    live = int(np.sum(kind < 7))
    heads = [j for j in range(live) if kind[j] % 2 == 1]
    clusters = [(j, (heads[h + 1] if h + 1 < len(heads) else live) - j, int(kind[j] // 2))
                for h, j in enumerate(heads)]
    fine = np.ones(k, dtype=bool)
    projector = np.zeros((k, size, size))
    real, pairs = [], []
    for j, m, cat in clusters:
        if cat == 2:
            continue                                  # the conjugates of the upper half
        R, L = vr[:, :, j:j + m], vl[:, :, j:j + m]
        gram = np.einsum("kim,kin->kmn", L, R)
        with np.errstate(all="ignore"):
            inv = np.linalg.inv(gram) if np.all(np.isfinite(gram)) else gram * np.nan
            cond = np.linalg.norm(inv, ord=2, axis=(1, 2)) if m > 1 else np.abs(inv[:, 0, 0])
        fine &= cond <= cond_limit
        C = np.einsum("kim,kmn,kjn->kij", R, np.nan_to_num(inv), L)
        value = lam[:, j:j + m].mean(axis=1)
        if cat == 0:
            real.append((value.real, C.real))
            projector += C.real
        else:
            pairs.append((value, C))
            projector += 2 * C.real
    if not fine.any():
        return None, fine
    if not fine.all():                                # the rest without the refused
        form, _ = _form(M[fine], lam[fine], vr[fine], vl[fine], kind, cond_limit)
        return form, fine
    powers, sine, sigmas, omegas, coefs = [], [], [], [], []
    for sigma, C in real:                                 # real: e^{σt}
        powers.append(0), sine.append(False)
        sigmas.append(sigma), omegas.append(np.zeros(k)), coefs.append(C)
    for value, C in pairs:                                # a pair: 2 Re C cos, −2 Im C sin
        # an undamped pair's σ is rounding (~1e-15 ω): 0, so no e^{σt} is evaluated
        sigma = np.where(np.abs(value.real) <= 1e-12 * np.abs(value), 0.0, value.real)
        for is_sine, part in ((False, 2 * C.real), (True, -2 * C.imag)):
            powers.append(0), sine.append(is_sine)
            sigmas.append(sigma), omegas.append(np.abs(value.imag))
            coefs.append(part)
    Q = np.eye(size) - projector
    N = M @ Q
    term = Q
    for j in range(size - live):                         # the exact nilpotent series
        if j:
            term = N @ term / j
            if not term.any():                           # N^j = 0 (a free side): no more
                break
        powers.append(j), sine.append(False)
        sigmas.append(np.zeros(k)), omegas.append(np.zeros(k)), coefs.append(term)
    return BatchForm(n, np.array(powers, dtype=float), np.array(sine, dtype=bool),
                     np.stack(sigmas, axis=1), np.stack(omegas, axis=1),
                     np.stack(coefs, axis=1), len(real), len(pairs)), fine


class FormCache:
    """The closed forms of one mode for designs 0 … size − 1, computed on a
    design's first phase in the mode and kept."""

    def __init__(self, size: int, cond_limit: float = COND_LIMIT) -> None:
        self.cond_limit = cond_limit
        self.signature = np.full(size, -2)          # −2 not yet, −1 refused, else a part
        self.parts: list[tuple[int, int, np.ndarray, np.ndarray, np.ndarray, np.ndarray,
                               np.ndarray]] = []
        self.size = size

    def forms(self, idx: np.ndarray, A: np.ndarray,
              b: np.ndarray) -> list[tuple[np.ndarray, BatchForm | None]]:
        """(positions in ``idx``, their form, or None where refused)."""
        new = np.flatnonzero(self.signature[idx] == -2)
        if new.size:
            # designs of equal (A, b) (a swept value the mode does not read)
            # share one decomposition: each design's is computed alone, so the
            # shared one is bit for bit what it would have got
            first, inverse = _distinct(A[new], b[new])
            parts, refused = batch_forms(A[new[first]], b[new[first]], self.cond_limit)
            self.signature[idx[new[np.isin(inverse, refused)]]] = -1
            for where_first, f in parts:
                slot = np.full(first.size, -1)
                slot[where_first] = np.arange(where_first.size)
                where = np.flatnonzero(slot[inverse] >= 0)
                f = f.take(slot[inverse[where]])
                key = next((i for i, p in enumerate(self.parts)
                            if p[0] == f.real and p[1] == f.pairs
                            and p[2].shape == f.powers.shape), None)
                if key is None:
                    T = f.powers.size
                    n = f.n           # the rows of the state only (the last is 0 … 0 1)
                    self.parts.append((f.real, f.pairs, f.powers, f.sine,
                                       np.zeros((self.size, T)), np.zeros((self.size, T)),
                                       np.zeros((self.size, T, n, n + 1))))
                    key = len(self.parts) - 1
                rows = idx[new[where]]
                _, _, _, _, sig, om, coef = self.parts[key]
                sig[rows], om[rows], coef[rows] = f.sigmas, f.omegas, f.coefficients[:, :, :f.n]
                self.signature[rows] = key
        out: list = []
        which = self.signature[idx]
        for key in np.unique(which):
            where = np.flatnonzero(which == key)
            if key < 0:
                out.append((where, None))
                continue
            q, p, powers, sine, sig, om, coef = self.parts[key]
            rows = idx[where]
            n = coef.shape[-2]
            out.append((where, BatchForm(n, powers, sine, sig[rows], om[rows], coef[rows],
                                         q, p)))
        return out
