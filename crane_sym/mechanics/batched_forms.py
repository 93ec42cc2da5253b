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

:class:`Signals` holds m scalar signals g(t) = Σ_j a_j β_j(t) + k (one per
design and guard): values, slopes and the bounds of |g'| and |g''| of
:class:`crane_sym.mechanics.closed_forms.ClosedForm`, each on arrays.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

__all__ = ["BatchForm", "Signals", "batch_forms"]

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


@dataclass
class Signals:
    """m scalar signals g_i(t) = Σ_j a_ij β_ij(t) + k_i on their phase's own clock,
    in three blocks of terms, each evaluated with as few transcendentals as it needs:

    - ``real``: a e^{σt} (a nonzero real eigenvalue), amplitudes and σ (m, R);
    - ``pairs``: e^{σt}(a cos ωt + b sin ωt), amplitudes a, b and σ, ω (m, P);
    - ``poly``: Σ_j c_j t^j (the generalized kernel), c (m, D), the constant in c_0.

    Every method takes ``rows`` (the signals asked about) and arrays of that length.
    """

    real_amps: np.ndarray
    real_sigmas: np.ndarray
    cos_amps: np.ndarray
    sin_amps: np.ndarray
    pair_sigmas: np.ndarray
    pair_omegas: np.ndarray
    poly: np.ndarray

    @classmethod
    def of(cls, form: BatchForm, amps: np.ndarray, const: np.ndarray,
           owner: np.ndarray | None = None) -> "Signals":
        """Signals from a form's term amplitudes (m, T) and constants (m,);
        row i belongs to design ``owner[i]`` of the form (default: row i)."""
        q, p = form.real, form.pairs
        sig = form.sigmas if owner is None else form.sigmas[owner]
        om = form.omegas if owner is None else form.omegas[owner]
        poly = amps[:, q + 2 * p:].copy()
        poly[:, 0] += const
        return cls(amps[:, :q], sig[:, :q], amps[:, q:q + 2 * p:2], amps[:, q + 1:q + 2 * p:2],
                   sig[:, q:q + 2 * p:2], om[:, q:q + 2 * p:2], poly)

    @classmethod
    def concat(cls, parts: list["Signals"]) -> "Signals":
        """The rows of ``parts`` in one, each block padded with zero terms to the
        widest (a zero term adds an exact 0): one search for every mode."""
        if len(parts) == 1:
            return parts[0]
        rows = sum(p.poly.shape[0] for p in parts)
        blocks = []
        for name in cls._FIELDS:
            arrays = [getattr(p, name) for p in parts]
            out = np.zeros((rows, max(a.shape[1] for a in arrays)))
            at = 0
            for a in arrays:
                out[at:at + a.shape[0], : a.shape[1]] = a
                at += a.shape[0]
            blocks.append(out)
        return cls(*blocks)

    _FIELDS = ("real_amps", "real_sigmas", "cos_amps", "sin_amps", "pair_sigmas",
               "pair_omegas", "poly")

    def take(self, rows: np.ndarray) -> "Signals":
        """The signals ``rows`` only."""
        return Signals(*(a[rows] for a in (self.real_amps, self.real_sigmas, self.cos_amps,
                                           self.sin_amps, self.pair_sigmas, self.pair_omegas,
                                           self.poly)))

    def value(self, rows: np.ndarray, t: np.ndarray) -> np.ndarray:
        """g at ``t``."""
        return self.both(rows, t, slope=False)[0]

    def both(self, rows: np.ndarray, t: np.ndarray,
             slope: bool = True) -> tuple[np.ndarray, np.ndarray | None]:
        """g and (with ``slope``) g' at ``t``, from one evaluation of each term."""
        poly = self.poly[rows]
        D = poly.shape[1]
        g = poly[:, D - 1].copy()
        for j in range(D - 2, -1, -1):                 # Horner
            g = g * t + poly[:, j]
        d = None
        if slope:
            d = np.zeros_like(t)
            for j in range(D - 1, 0, -1):
                d = d * t + j * poly[:, j]
        tt = t[:, None]
        if self.cos_amps.shape[1]:
            a, b = self.cos_amps[rows], self.sin_amps[rows]
            s, w = self.pair_sigmas[rows], self.pair_omegas[rows]
            wt = w * tt
            c, sn = np.cos(wt), np.sin(wt)
            wave = a * c + b * sn
            grow = np.exp(s * tt) if s.any() else None
            if grow is not None:
                wave *= grow
            g += _rowsum(wave)
            if slope:
                turn = w * (b * c - a * sn)
                if grow is not None:
                    turn *= grow
                d += _rowsum(s * wave + turn)
        if self.real_amps.shape[1]:
            s = self.real_sigmas[rows]
            term = self.real_amps[rows] * np.exp(s * tt)
            g += _rowsum(term)
            if slope:
                d += _rowsum(s * term)
        return g, d

    def size(self, rows: np.ndarray) -> np.ndarray:
        """Σ |a_j| + |k|: the scale of a signal (the constant in c_0)."""
        return (np.abs(self.real_amps[rows]).sum(axis=1)
                + np.abs(self.cos_amps[rows]).sum(axis=1)
                + np.abs(self.sin_amps[rows]).sum(axis=1) + np.abs(self.poly[rows]).sum(axis=1))

    def bounds(self, rows: np.ndarray, t0: np.ndarray,
               t1: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Upper bounds of |g'| and |g''| on [t0, t1] (0 ≤ t0 ≤ t1), term by term
        as :meth:`crane_sym.mechanics.closed_forms.ClosedForm.derivative_bound`,
        a pair a cos + b sin = R cos(ωt − φ) with its amplitude R = √(a² + b²)."""
        poly = np.abs(self.poly[rows])
        D = poly.shape[1]
        L, M2 = np.zeros_like(t0), np.zeros_like(t0)
        for j in range(1, D):
            L += poly[:, j] * j * t1 ** (j - 1)
            if j > 1:
                M2 += poly[:, j] * j * (j - 1) * t1 ** (j - 2)
        a0, a1 = t0[:, None], t1[:, None]
        if self.cos_amps.shape[1]:
            s = self.pair_sigmas[rows]
            rate = np.abs(s) + self.pair_omegas[rows]
            amp = np.hypot(self.cos_amps[rows], self.sin_amps[rows])
            if s.any():
                amp = amp * np.exp(np.maximum(s * a0, s * a1))
            L += _rowsum(amp * rate)
            M2 += _rowsum(amp * rate * rate)
        if self.real_amps.shape[1]:
            s = self.real_sigmas[rows]
            amp = np.abs(self.real_amps[rows]) * np.exp(np.maximum(s * a0, s * a1))
            L += _rowsum(amp * np.abs(s))
            M2 += _rowsum(amp * s * s)
        return L, M2

    def spread(self, horizon: np.ndarray) -> np.ndarray:
        """A bound of |g(t) − g_c| on [0, horizon], g_c the constant term:
        Σ_{j≥1} |c_j| H^j, and for each pair √(a² + b²)·max(1, e^{σH}), each
        exponential |a|·max(1, e^{σH}). Where |g_c| exceeds it, g keeps the
        sign of g_c over the whole phase."""
        H = horizon
        D = self.poly.shape[1]
        out = np.zeros_like(H)
        for j in range(D - 1, 0, -1):               # Horner on |c_j|
            out = (out + np.abs(self.poly[:, j])) * H
        tt = H[:, None]
        if self.cos_amps.shape[1]:
            amp = np.hypot(self.cos_amps, self.sin_amps)
            s = self.pair_sigmas
            if s.any():
                amp = amp * np.maximum(1.0, np.exp(s * tt))
            out += _rowsum(amp)
        if self.real_amps.shape[1]:
            out += (np.abs(self.real_amps)
                    * np.maximum(1.0, np.exp(self.real_sigmas * tt))).sum(axis=1)
        return out

    def constant(self) -> np.ndarray:
        """True where a signal has no term but its constant."""
        return ~(np.any(self.real_amps != 0, axis=1) | np.any(self.cos_amps != 0, axis=1)
                 | np.any(self.sin_amps != 0, axis=1) | np.any(self.poly[:, 1:] != 0, axis=1))

    def window(self, rows: np.ndarray, scale: np.ndarray) -> np.ndarray:
        """A window over which the bounds stay tight: a quarter of the shortest
        period, no longer than the e-folding time of a growing term, nor ``scale``."""
        out = scale.copy()
        wmax = self.pair_omegas[rows].max(axis=1, initial=0.0)
        smax = np.maximum(self.pair_sigmas[rows].max(axis=1, initial=0.0),
                          self.real_sigmas[rows].max(axis=1, initial=0.0))
        with np.errstate(divide="ignore"):
            out = np.where(wmax > 0, np.minimum(out, 0.5 * np.pi / wmax), out)
            out = np.where(smax > 0, np.minimum(out, 1.0 / smax), out)
        return out


def _rowsum(a: np.ndarray) -> np.ndarray:
    """Σ over a row's terms; a single term as it is (a reduction costs more)."""
    return a[:, 0] if a.shape[1] == 1 else a.sum(axis=1)
