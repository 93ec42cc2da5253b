"""Natural frequencies of small chains in forms floating point keeps accurate.

The elastic modes of a free-free torsional chain satisfy a quadratic in ω²
whose textbook roots, (b ± √(b² − 4c))/2, cancel twice: b² − 4c when the two
frequencies are close (it can even come out negative and give NaN), and
b − √(b² − 4c) when they are far apart. Written as the eigenvalues of the 2×2
dynamic matrix ``A`` of the relative twists, the discriminant is
(a₁₁ − a₂₂)² + 4·a₁₂·a₂₁, a sum of non-negative terms when a₁₂·a₂₁ ≥ 0, and the
smaller root follows from the larger by Vieta: det A / λ₊.
"""
from __future__ import annotations

import sympy as sp

__all__ = ["relative_dynamic_matrix", "eigenvalues_2x2"]


def relative_dynamic_matrix(inertia: sp.Matrix, stiffness: sp.Matrix) -> sp.Matrix:
    """The dynamic matrix of the relative twists θ_i = φ_i − φ_{i+1} of a chain.

    For M·φ̈ + K·φ = 0 with K of a chain (rows summing to zero: the chain is
    free), θ = D·φ with D the difference matrix; then θ̈ = −A·θ where
    A = D·M⁻¹·K·D⁺ restricted to the n − 1 twists (K·φ depends on θ only).

    Parameters
    ----------
    inertia : sympy.Matrix
        The mass (inertia) matrix M of the chain.
    stiffness : sympy.Matrix
        Its stiffness matrix K (rows summing to zero).
    """
    n = inertia.shape[0]
    if any(sp.simplify(sum(stiffness.row(i))) != 0 for i in range(n)):
        raise ValueError("stiffness rows must sum to zero (a free chain)")
    D = sp.Matrix(n - 1, n, lambda i, j: 1 if j == i else (-1 if j == i + 1 else 0))
    # φ from θ up to a rigid rotation: φ_i = Σ_{k ≥ i} θ_k (φ_n = 0); K ignores the rotation
    back = sp.Matrix(n, n - 1, lambda i, j: 1 if j >= i else 0)
    return (D * inertia.inv() * stiffness * back).applyfunc(sp.factor)


def eigenvalues_2x2(A: sp.Matrix) -> tuple[sp.Expr, sp.Expr]:
    """Eigenvalues (smaller, larger) of a 2×2 matrix with positive trace and
    a₁₂·a₂₁ ≥ 0, free of cancellation (module docstring).

    Parameters
    ----------
    A : sympy.Matrix
        The 2x2 matrix.
    """
    if A.shape != (2, 2):
        raise ValueError(f"expected a 2x2 matrix, got {A.shape}")
    (a, b), (c, d) = A.tolist()
    larger = (a + d + sp.sqrt((a - d) ** 2 + 4 * b * c)) / 2
    return sp.factor(a * d - b * c) / larger, larger
