"""Closed forms of one phase for many designs at once, and their signals.

The batched sibling of :mod:`crane_sym.mechanics.closed_forms`' numeric route:
k designs in one mode have matrices M = [[A, b], [0, 0]] of one shape, so
one call of ``np.linalg.eig`` on the stack (k, n + 1, n + 1) gives every
design's eigenvalues, and one on the transposed stack its left eigenvectors
(matched to the right ones by nearest eigenvalue). Each simple nonzero
eigenvalue λ gives the spectral projector C_λ = v wᵀ / (wᵀ v); the
generalized kernel (rigid modes, the constant input) gets the exact
nilpotent series Σ_j (N t)^j / j! · Q with Q = I − Σ C_λ and N = M Q, as the
per-design route does. A pair λ = σ ± iω folds into t^0 e^{σt} cos ωt and
sin ωt terms.

A design is refused (``ok`` False, for the per-design route) where this is
not safe: an eigenvalue condition number 1/|ŵᵀv̂| above ``cond_limit``, two
nonzero eigenvalues closer than 10⁻⁶ of the spectrum's scale (a repeated
eigenvalue, which the per-design route clusters), a complex pair closer to
the real axis than 10⁻⁵ of the scale, or a left eigenvector it cannot match.

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
    coefficients : ndarray, shape (k, T, n + 1, n + 1)
        The real matrices C_j of each design.
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
        """C_j (x0, 1) of each design, shape (k, T, n + 1)."""
        z0 = np.concatenate([x0, np.ones((x0.shape[0], 1))], axis=1)
        return np.einsum("ktij,kj->kti", self.coefficients, z0)

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
    :class:`BatchForm`), designs of one spectral structure (as many nonzero
    real eigenvalues and complex pairs); ``refused`` holds the positions the
    batched route does not take (see the module docstring).
    """
    k, n = b.shape
    M = np.zeros((k, n + 1, n + 1))
    M[:, :n, :n] = A
    M[:, :n, n] = b
    lam, vr = np.linalg.eig(M)
    mu, vl = np.linalg.eig(np.swapaxes(M, 1, 2))
    scale = np.maximum(np.abs(lam).max(axis=1), 1.0)[:, None]
    live = np.abs(lam) > 1e-6 * scale
    # left eigenvector of each λ: the eigenvector of Mᵀ with the nearest eigenvalue
    match = np.argmin(np.abs(lam[:, :, None] - mu[:, None, :]), axis=2)
    gap = np.abs(lam - np.take_along_axis(mu, match, axis=1))
    w = np.take_along_axis(vl, match[:, None, :], axis=2)               # (k, n+1, n+1)
    dots = np.einsum("kij,kij->kj", w, vr)
    norms = np.linalg.norm(w, axis=1) * np.linalg.norm(vr, axis=1)
    with np.errstate(divide="ignore", invalid="ignore"):
        cond = np.where(live, norms / np.abs(dots), 1.0)
    bad = np.any(live & ~(cond <= cond_limit), axis=1)
    bad |= np.any(live & (gap > 1e-9 * scale), axis=1)
    close = np.abs(lam[:, :, None] - lam[:, None, :]) < 1e-6 * scale[:, :, None]
    pair = live[:, :, None] & live[:, None, :] & ~np.eye(n + 1, dtype=bool)
    bad |= np.any(close & pair, axis=(1, 2))
    im = np.abs(lam.imag)
    bad |= np.any(live & (im > 0) & (im < 1e-5 * scale), axis=1)
    bad |= ~np.all(np.isfinite(lam), axis=1)
    # order: real nonzero, then upper half plane, then lower half plane, then kernel
    key = np.where(~live, 3, np.where(lam.imag == 0, 0, np.where(lam.imag > 0, 1, 2)))
    real_count = np.sum(key == 0, axis=1)
    pair_count = np.sum(key == 1, axis=1)
    parts = []
    ok = np.flatnonzero(~bad)
    signature = real_count[ok] * (n + 2) + pair_count[ok]
    for sig in np.unique(signature):
        where = ok[signature == sig]
        q, p = int(real_count[where[0]]), int(pair_count[where[0]])
        parts.append((where, _form(M[where], lam[where], vr[where], w[where], dots[where],
                                   key[where], q, p)))
    return parts, np.flatnonzero(bad)


def _form(M, lam, vr, w, dots, key, q: int, p: int) -> BatchForm:
    """The :class:`BatchForm` of designs with q real nonzero eigenvalues and p pairs."""
    k, size, _ = M.shape
    n = size - 1
    order = np.argsort(key, axis=1, kind="stable")
    lam = np.take_along_axis(lam, order, axis=1)
    vr = np.take_along_axis(vr, order[:, None, :], axis=2)
    w = np.take_along_axis(w, order[:, None, :], axis=2)
    dots = np.take_along_axis(dots, order, axis=1)
    live = q + 2 * p
    C = np.einsum("kiv,kjv->kvij", vr[:, :, :live], w[:, :, :live]) / dots[:, :live, None, None]
    projector = C.sum(axis=1).real
    powers, sine, sigmas, omegas, coefs = [], [], [], [], []
    for v in range(q):                                   # real: e^{σt}
        powers.append(0), sine.append(False)
        sigmas.append(lam[:, v].real), omegas.append(np.zeros(k)), coefs.append(C[:, v].real)
    for v in range(q, q + p):                            # a pair: 2 Re C cos, −2 Im C sin
        # an undamped pair's σ is rounding (~1e-15 ω): 0, so no e^{σt} is evaluated
        sigma = np.where(np.abs(lam[:, v].real) <= 1e-12 * np.abs(lam[:, v]), 0.0,
                         lam[:, v].real)
        for is_sine, part in ((False, 2 * C[:, v].real), (True, -2 * C[:, v].imag)):
            powers.append(0), sine.append(is_sine)
            sigmas.append(sigma), omegas.append(np.abs(lam[:, v].imag))
            coefs.append(part)
    Q = np.eye(size) - projector
    N = M @ Q
    term = Q
    for j in range(size - live):                         # the exact nilpotent series
        if j:
            term = N @ term / j
        powers.append(j), sine.append(False)
        sigmas.append(np.zeros(k)), omegas.append(np.zeros(k)), coefs.append(term)
    return BatchForm(n, np.array(powers, dtype=float), np.array(sine, dtype=bool),
                     np.stack(sigmas, axis=1), np.stack(omegas, axis=1),
                     np.stack(coefs, axis=1), q, p)


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
            parts, refused = batch_forms(A[new], b[new], self.cond_limit)
            self.signature[idx[new[refused]]] = -1
            for where, f in parts:
                key = next((i for i, p in enumerate(self.parts)
                            if p[0] == f.real and p[1] == f.pairs
                            and p[2].shape == f.powers.shape), None)
                if key is None:
                    T = f.powers.size
                    self.parts.append((f.real, f.pairs, f.powers, f.sine,
                                       np.zeros((self.size, T)), np.zeros((self.size, T)),
                                       np.zeros((self.size,) + f.coefficients.shape[1:])))
                    key = len(self.parts) - 1
                rows = idx[new[where]]
                _, _, _, _, sig, om, coef = self.parts[key]
                sig[rows], om[rows], coef[rows] = f.sigmas, f.omegas, f.coefficients
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
            n = coef.shape[-1] - 1
            out.append((where, BatchForm(n, powers, sine, sig[rows], om[rows], coef[rows],
                                         q, p)))
        return out
