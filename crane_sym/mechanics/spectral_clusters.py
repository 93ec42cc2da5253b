"""exp(M t) by spectral clusters: exact where eigenvalues coincide or nearly do.

A phase x' = A x + b is z' = M z with z = (x, 1). Its eigenvalues are grouped
into clusters: the generalized kernel (rigid modes, the constant input, a
law's clock states), single eigenvalues, and groups closer together than
:data:`CLUSTER` of their size (critical damping, equal subsystems). Each
cluster c has its spectral projector P and the part N = (M − μI) P about its
centre μ, and exp(Mt) = Σ_c e^{μt} exp(N t) P. On a cluster the series is
summed in closed form, never from eigenvectors of nearly equal eigenvalues
(which lose as many digits as the eigenvalues are close):

- a single eigenvalue: e^{λt} P;
- the kernel (μ = 0, N nilpotent): Σ_{j<m} (N t)^j / j!, exactly;
- a cluster whose N² = q P (every 2 × 2 cluster, by Cayley–Hamilton, and
  equal subsystems): exp(Nt) P = cosh(√q t) P + sinh(√q t)/√q N, written as

  * q = 0 (a Jordan block, within rounding): P + t N;
  * e^{μt} times its Taylor polynomial in q t² where |q| τ² ≤ :data:`TAYLOR`
    (τ = 1/|Re μ|, the cluster's decay time): terms t^k e^{μt} whose
    coefficients stay bounded however close the eigenvalues are;
  * two exponentials e^{(μ ± √q) t} with (P ± N/√q)/2 elsewhere, where
    √q τ ≥ √TAYLOR bounds what their difference can cancel;

- any other cluster: its own eigenvectors where they are well conditioned,
  else refused by name (:class:`ClusterError`).

The terms come back as (power j, rate λ, complex matrix C): exp(Mt) =
Σ t^j e^{λt} C. The same rules serve NumPy (doubles, projectors from an
ordered Schur form) and mpmath (projectors from eigenvectors at twice the
working digits) through :class:`Algebra`.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any, Callable, Sequence

import numpy as np

__all__ = ["Algebra", "CLUSTER", "ClusterError", "KERNEL", "RESOLVED", "TAYLOR",
           "cluster_terms", "group", "numpy_terms", "resolution"]

#: Eigenvalues closer than this fraction of their modulus form one cluster.
CLUSTER = 1e-3
#: Eigenvalues below this fraction of the spectrum's scale are the kernel's.
KERNEL = 1e-6
#: A small eigenvalue this many times above its rounding bound is live.
RESOLVED = 10.0
#: Largest |q| τ² written as a Taylor polynomial (its 9 terms then reach 1e-19
#: at 50 decay times, past which e^{μt} has fallen below 1e-21).
TAYLOR = 1e-4
#: Terms k = 0 … TAYLOR_TERMS − 1 of the Taylor polynomials in q t².
TAYLOR_TERMS = 9


class ClusterError(ValueError):
    """A cluster of eigenvalues that no closed form here resolves."""


@dataclass(frozen=True)
class Algebra:
    """The few operations the rules need, for NumPy or mpmath matrices."""

    matmul: Callable[[Any, Any], Any]
    norm: Callable[[Any], float]
    sqrt: Callable[[Any], Any]
    trace: Callable[[Any], Any]
    eps: float


def group(values: Sequence[complex], scale: float, floor: float | None = None,
          errors: Sequence[float] | None = None) -> tuple[list[int], list[list[int]]]:
    """(kernel, clusters): indices of the eigenvalues below KERNEL·scale (or
    ``floor``) that their ``errors`` do not resolve, and the rest grouped
    (transitively) where |λ_i − λ_j| ≤ CLUSTER·max(|λ_i|, |λ_j|).

    ``errors`` bound each eigenvalue's rounding (:func:`resolution`): an
    eigenvalue RESOLVED times above it is a slow mode, however small beside
    the fastest (a soft rope beside a stiff coupling, 1e-7 of the scale), not
    the rounding of a rigid mode's zero."""
    floor = KERNEL * scale if floor is None else floor
    errors = [math.inf] * len(values) if errors is None else errors
    small = [abs(v) <= floor and abs(v) <= RESOLVED * e for v, e in zip(values, errors)]
    kernel = [i for i, v in enumerate(values) if small[i]]
    live = [i for i, v in enumerate(values) if not small[i]]
    parent = {i: i for i in live}

    def root(i: int) -> int:
        while parent[i] != i:
            i = parent[i]
        return i

    for a, i in enumerate(live):
        for j in live[a + 1:]:
            if abs(values[i] - values[j]) <= CLUSTER * max(abs(values[i]), abs(values[j])):
                parent[root(j)] = root(i)
    clusters: dict[int, list[int]] = {}
    for i in live:
        clusters.setdefault(root(i), []).append(i)
    return kernel, sorted(clusters.values(), key=lambda c: c[0])


def cluster_terms(P: Any, N: Any, mu: Any, size: int, algebra: Algebra,
                  scale: float) -> list[tuple[int, Any, Any]]:
    """The terms (j, λ, C) of e^{μt} exp(N t) P for one live cluster of ``size``
    eigenvalues about ``mu`` (N = (M − μI) P), by the rules of the module."""
    mul, norm, eps = algebra.matmul, algebra.norm, algebra.eps
    tiny = 1e3 * eps
    n_norm = norm(N)
    if size == 1 or n_norm <= tiny * scale * max(norm(P), 1.0):
        return [(0, mu, P)]                         # one eigenvalue, or equal and semisimple
    N2 = mul(N, N)
    q = algebra.trace(N2) / size
    if size > 2 and norm(N2 - P * q) > tiny * n_norm ** 2:
        raise ClusterError(
            f"{size} eigenvalues within {CLUSTER:g} of each other about {complex(mu):.6g}"
            " form neither a Jordan block nor equal subsystems; no closed form here resolves"
            " them")
    if abs(q) <= tiny * n_norm ** 2:                # a Jordan block within rounding
        return [(0, mu, P), (1, mu, N)]
    decay = abs(complex(mu).real)
    if decay > 0 and abs(complex(q)) <= TAYLOR * decay ** 2:
        terms, power = [], 1
        for k in range(TAYLOR_TERMS):
            terms.append((2 * k, mu, P * (power / math.factorial(2 * k))))
            terms.append((2 * k + 1, mu, N * (power / math.factorial(2 * k + 1))))
            power = power * q
        return terms
    root_q = algebra.sqrt(q)
    half = N * (1 / root_q)
    return [(0, mu + root_q, (P + half) * 0.5), (0, mu - root_q, (P - half) * 0.5)]


def _np_algebra() -> Algebra:
    return Algebra(matmul=np.matmul, norm=lambda X: float(np.linalg.norm(X)),
                   sqrt=lambda q: complex(np.sqrt(complex(q))),
                   trace=lambda X: complex(np.trace(X)), eps=float(np.finfo(float).eps))


def _schur_projector(M: np.ndarray, centre: complex, radius: float, size: int) -> np.ndarray:
    """The spectral projector of the eigenvalues within ``radius`` of ``centre``,
    from an ordered complex Schur form (stable for a defective cluster)."""
    from scipy.linalg import schur, solve_sylvester

    T, Z, m = schur(M.astype(complex), output="complex",
                    sort=lambda x: abs(x - centre) <= radius)
    if m != size:
        raise ClusterError(f"the Schur form found {m} eigenvalues about {centre:.6g},"
                           f" the eigenvalues {size}")
    Y = solve_sylvester(T[:m, :m], -T[m:, m:], T[:m, m:])
    Z1, Z2 = Z[:, :m], Z[:, m:]
    return Z1 @ (Z1.conj().T + Y @ Z2.conj().T)


def resolution(left: np.ndarray, right: np.ndarray, norm: float, eps: float) -> np.ndarray:
    """First-order rounding bounds eps·κ_i·‖M‖ of the eigenvalues, κ_i =
    ‖l_i‖‖r_i‖/|l_iᴴ r_i| (infinite where l_iᴴ r_i = 0: a defective one)."""
    dots = np.abs(np.sum(left.conj() * right, axis=0))
    sizes = np.linalg.norm(left, axis=0) * np.linalg.norm(right, axis=0)
    with np.errstate(divide="ignore"):
        return np.where(dots > 0, eps * norm * sizes / np.where(dots > 0, dots, 1.0), np.inf)


def numpy_terms(M: np.ndarray) -> list[tuple[int, complex, np.ndarray]]:
    """The terms (j, λ, C) of exp(M t) = Σ t^j e^{λt} C in doubles."""
    from scipy.linalg import eig

    algebra = _np_algebra()
    lam, vl, vr = eig(M, left=True, right=True)
    scale = max(float(np.abs(lam).max()), 1.0)
    errors = resolution(vl, vr, float(np.linalg.norm(M)), algebra.eps)
    kernel, clusters = group(list(lam), scale, errors=list(errors))
    size = M.shape[0]
    terms, projector = [], np.zeros((size, size), dtype=complex)
    for cluster in clusters:
        members = lam[cluster]
        mu = complex(np.mean(members))
        if len(cluster) > 1 and abs(mu.imag) <= 1e-6 * abs(mu):
            mu = complex(mu.real, 0.0)               # a real cluster (conjugate-closed)
        if len(cluster) == 1:
            r, l = vr[:, cluster], vl[:, cluster].conj().T
            P = r @ l / (l @ r)
        else:
            spread = float(np.abs(members - mu).max())
            others = np.delete(lam, cluster)
            gap = float(np.abs(others - mu).min()) if others.size else np.inf
            # a defective cluster of k splits by O(eps^(1/k)) in the Schur form's rounding
            floor = 4 * algebra.eps ** (1 / len(cluster)) * max(scale, float(np.linalg.norm(M)))
            radius = min(max(4 * spread, floor), 0.5 * gap)
            P = _schur_projector(M, mu, radius, len(cluster))
        projector += P
        if mu.imag < 0:
            continue                                 # its conjugate's terms carry it
        terms += cluster_terms(P, (M - mu * np.eye(size)) @ P, mu, len(cluster), algebra,
                               scale)
    if not kernel:
        return terms
    Q = np.eye(size) - projector.real
    N = M @ Q
    term = Q.astype(complex)                         # the kernel: Σ_j (N t)^j / j! Q
    for j in range(len(kernel)):
        if j:
            term = N @ term / j
        terms.append((j, 0j, term))
    # N^m Q = 0 up to its rounding (eps ‖M‖ ‖N‖^(m−1) ‖Q‖), else a mode slower
    # than the kernel's bound sits in it
    m = len(kernel)
    rounding = algebra.eps * float(np.linalg.norm(M)) * float(np.linalg.norm(Q)) * float(
        np.linalg.norm(N)) ** (m - 1) / math.factorial(m - 1)
    if np.linalg.norm(N @ term) > 1e3 * m * rounding:
        raise ClusterError(f"{m} eigenvalues below {KERNEL:g} of the spectrum's scale are"
                           " not a rigid kernel: a mode too slow beside the fastest to be"
                           " resolved in double precision")
    return _kernel_top_on_null(M, terms, len(terms) - m, algebra.eps)


def _kernel_top_on_null(M: np.ndarray, terms: list, first: int, eps: float) -> list:
    """The kernel's highest live term N^j Q / j! (its columns in ker M: the
    rigid drift's rates) projected onto the null space of M from its SVD.

    Q = I − Σ P carries the rounding of the other clusters' projectors, eps
    ‖P‖ |z|, and N = M Q multiplies it by ‖M‖: a constant input of 4e5 in a
    state's row (a PI loop's voltage) gives that state a drift of 1e-9 per
    second that M's equations do not have. The projection removes what of
    the term lies outside ker M, where the exact term has nothing; kept only
    where it moves the term by rounding (a slow mode in the kernel would not
    lie in ker M: then the term stays as it was)."""
    kernel = terms[first:]
    norms = [float(np.linalg.norm(C)) for _, _, C in kernel]
    live = [k for k in range(1, len(kernel)) if norms[k] > 1e-8 * max(norms)]
    if not live:
        return terms
    top = live[-1]
    _, sigma, vh = np.linalg.svd(M)
    null = vh[np.sum(sigma > M.shape[0] * eps * sigma[0]):].conj().T
    if not null.shape[1]:
        return terms
    j, lam, C = kernel[top]
    projected = null @ (null.conj().T @ C)
    if np.linalg.norm(projected - C) > 1e-8 * norms[top]:
        return terms
    return terms[:first + top] + [(j, lam, projected)] + terms[first + top + 1:]
