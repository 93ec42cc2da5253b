"""Natural frequencies of a component model in the mode its run is in: the
undamped modes of M q̈ + K q = 0 of that mode, their periods and their modal
damping.

A mode of the run (:class:`~crane_sym.components.hybrid.Mode`) fixes which
coordinates move and which links act: a group whose body a ``speed`` motor
law moves, or that its brakes hold, is fixed (its row and column dropped), a
link in its gap has no stiffness. What is left is the mode's own problem

.. math:: \\det(\\lambda M - K) = 0, \\qquad \\omega_k = \\sqrt{\\lambda_k},

whose roots that vanish in the symbols are the rigid-body motions (a free
drive's travel), never counted. The k-th of the others from the lowest is
ω_k. Symbolic where the roots are: one or two (the polynomial's own root or
the quadratic formula), else a function of the mode's matrices that mpmath
evaluates at each sampled point (``natural_frequency``: the k-th eigenvalue
of M^(-1/2) K M^(-1/2), :func:`mpmath.eigsy`).

The modal damping ratio of mode k is ζ_k = φ_kᵀ D φ_k / (2 ω_k φ_kᵀ M φ_k)
of its shape φ_k (exact for one degree of freedom and for damping
proportional to M and K, the classical modal approximation otherwise), its
damped frequency ω_k √(1 − ζ_k²), its period 2π/ω_k.

>>> from crane_sym.components import ElasticLink, Mass, Model
>>> model = Model([Mass("a", "1 kg"), Mass("b", "4 kg"),
...                ElasticLink("k", "a", "b", "100 N/m")])
>>> natural_frequency(model, ModeChoice()).omega
sqrt(c_k)*sqrt(m_a + m_b)/(sqrt(m_a)*sqrt(m_b))
"""
from __future__ import annotations

from dataclasses import dataclass

import mpmath
import numpy as np
import sympy as sp
from sympy.utilities.lambdify import implemented_function

from crane_sym.components import kinds
from crane_sym.components.hybrid import HELD, Mode
from crane_sym.components.model import Model
from crane_sym.components.parts import ComponentError

__all__ = ["LOWEST", "MODAL", "ModalFrequency", "ModeChoice", "mode_at", "modal_quantity",
           "natural_frequency"]

#: The modal quantities of a link, and what each is.
MODAL = {"frequency": "the k-th natural angular frequency ω_k of the run's mode",
         "period": "its period 2π/ω_k",
         "damping_ratio": "its modal damping ratio ζ_k",
         "damped_frequency": "its damped angular frequency ω_k √(1 − ζ_k²)"}
#: The default choice of frequency: the lowest.
LOWEST = "lowest"


@dataclass(frozen=True)
class ModeChoice:
    """Which natural frequency a formula means, of which mode of the run.

    Attributes
    ----------
    which : ``"lowest"``, the k-th from the lowest (an int ≥ 1), or a link's
        name: the mode in which that link holds the largest share of the strain
        energy (decided at the file's values)
    state : the run's mode, or None: every gap closed, no brake holding
    instant : how the mode is named in the derivation's text
    """

    which: int | str = LOWEST
    state: Mode | None = None
    instant: str = "the mode with every gap closed and no brake holding"


@dataclass(frozen=True)
class ModalFrequency:
    """ω_k of the chosen mode, its shape's damping ratio, and how they were found."""

    omega: sp.Expr
    zeta: sp.Expr
    index: int
    how: str


def _upper(A: sp.Matrix) -> list[sp.Expr]:
    return [A[i, j] for i in range(A.rows) for j in range(i, A.cols)]


def _mass(n: int, values: list) -> tuple[mpmath.matrix, int]:
    """M from the entries (diag(M) when they are n + n(n+1)/2, its upper
    triangle when n(n+1): a coupling of several coordinates makes it full)
    and how many entries it took."""
    M = mpmath.matrix(n, n)
    if len(values) == n + n * (n + 1) // 2:
        for i in range(n):
            M[i, i] = values[i]
        return M, n
    upper = iter(values)
    for i in range(n):
        for j in range(i, n):
            M[i, j] = M[j, i] = next(upper)
    return M, n * (n + 1) // 2


def _eigen(k, rigid, n, entries) -> tuple[mpmath.mpf, list]:
    """The (rigid + k)-th smallest λ of det(λ M − K) = 0 and its shape φ (φᵀ M φ = 1)
    from M's entries (:func:`_mass`) and K's upper triangle, in mpmath: the
    eigenvalues of L⁻¹ K L⁻ᵀ, M = L Lᵀ (L = diag(√m) for a diagonal M)."""
    k, rigid, n = int(k), int(rigid), int(n)
    values = [mpmath.mpf(v) for v in entries]
    M, used = _mass(n, values)
    upper = iter(values[used:])
    A = mpmath.matrix(n, n)
    if all(M[i, j] == 0 for i in range(n) for j in range(n) if i != j):
        scale = [1 / mpmath.sqrt(M[i, i]) for i in range(n)]
        for i in range(n):
            for j in range(i, n):
                A[i, j] = A[j, i] = next(upper) * scale[i] * scale[j]
        E, Q = mpmath.eigsy(A)
        j = sorted(range(n), key=lambda i: E[i])[rigid + k - 1]
        return E[j], [Q[i, j] * scale[i] for i in range(n)]
    for i in range(n):
        for j in range(i, n):
            A[i, j] = A[j, i] = next(upper)
    back = mpmath.cholesky(M) ** -1
    A = back * A * back.T
    E, Q = mpmath.eigsy((A + A.T) / 2)
    j = sorted(range(n), key=lambda i: E[i])[rigid + k - 1]
    phi = back.T * Q[:, j]
    return E[j], [phi[i] for i in range(n)]


def _omega(k, rigid, n, *entries):
    return mpmath.sqrt(max(_eigen(k, rigid, n, entries)[0], 0))


def _zeta(k, rigid, n, *entries):
    n = int(n)
    size = len(entries) - n * (n + 1) // 2
    lam, phi = _eigen(k, rigid, n, entries[:size])
    D, upper = mpmath.matrix(n, n), iter(mpmath.mpf(v) for v in entries[size:])
    for i in range(n):
        for j in range(i, n):
            D[i, j] = D[j, i] = next(upper)
    work = sum(phi[i] * D[i, j] * phi[j] for i in range(n) for j in range(n))
    return work / (2 * mpmath.sqrt(lam))


#: ω_k and ζ_k of the mode's matrices, evaluated by mpmath (lambdify finds the
#: implementation): ``natural_frequency(k, rigid, n, diag M, upper K)``,
#: ``modal_damping(k, rigid, n, diag M, upper K, upper D)``; with the upper
#: triangle of M in place of its diagonal where M is full.
NATURAL_FREQUENCY = implemented_function("natural_frequency", _omega)
MODAL_DAMPING = implemented_function("modal_damping", _zeta)


def _fixed(model: Model, state: Mode | None) -> set[int]:
    """The groups the mode holds still or a speed law moves."""
    a = model.assembly
    fixed = {a.place[l.part.body][0] for l in a.loads if kinds.plays(l.part, "sets speed")}
    if state is not None:
        fixed |= {g for g, m in enumerate(state.motion) if m == HELD}
    return fixed


def _matrices(model: Model, state: Mode | None, signed: dict) -> tuple[list[int], sp.Matrix,
                                                                       sp.Matrix, sp.Matrix]:
    """(the moving groups, M, D, K) of the mode, in the parts' symbols: its gaps
    and the characteristics' steps put in, parts of value zero dropped."""
    eq = model.equations
    M, D, K, _ = eq.linear
    contacts = state.contacts if state is not None else (1,) * len(eq.contact)
    put = {chi: (0 if c == 0 else 1) for chi, c in zip(eq.contact, contacts)}
    stepped = [kinds.of(l.part).steps(l) for l in model.assembly.loads
               if kinds.of(l.part).steps is not None]
    steps = state.steps if state is not None else (0,) * len(stepped)
    for beta, slopes, step in zip(eq.slopes, stepped, steps):
        put[beta] = sp.Float(slopes[min(step, len(slopes) - 1)])
    put |= {s: 0 for s, v in eq.values.items() if v == 0}
    moving = [g for g in range(len(eq.coordinates)) if g not in _fixed(model, state)]
    pick = [(m.extract(moving, moving)).xreplace(put).xreplace(signed) for m in (M, D, K)]
    return moving, *pick


def _by_link(model: Model, link: str, moving: list[int], M: sp.Matrix, K: sp.Matrix,
             rigid: int, state: Mode | None, signed: dict) -> int:
    """The elastic mode (1 = lowest) in which ``link`` holds the largest share of
    the strain energy, at the file's values; ComponentError for a link in its gap
    or between bodies the mode holds still."""
    a, eq = model.assembly, model.equations
    names = [l.part.name for l in a.links]
    i = names.index(link)
    part = a.links[i]
    if part.gapped and state is not None and \
            state.contacts[[l for l in a.links if l.gapped].index(part)] == 0:
        raise ComponentError(f"the link {link!r} is in its gap in this mode; no mode loads it")
    weights = np.array([float(sp.diff(eq.twists[i], eq.coordinates[g]).xreplace(eq.values))
                        for g in moving])
    if not weights.any():
        raise ComponentError(f"the link {link!r} joins bodies the mode holds still")
    values = dict(eq.values) | {twin: eq.values[s] for s, twin in signed.items()}
    m = np.array(M.xreplace(values), dtype=float)
    k = np.array(K.xreplace(values), dtype=float)
    if np.count_nonzero(m - np.diag(np.diag(m))):      # full: M = L Lᵀ
        back = np.linalg.inv(np.linalg.cholesky(m))
        lam, psi = np.linalg.eigh(back @ k @ back.T)
        shapes = back.T @ psi
    else:
        scale = 1 / np.sqrt(m.diagonal())
        lam, psi = np.linalg.eigh(k * scale[:, None] * scale[None, :])
        shapes = psi * scale[:, None]
    share = [part.stiffness * (weights @ shapes[:, j]) ** 2 / (shapes[:, j] @ k @ shapes[:, j])
             for j in range(rigid, len(lam))]
    return int(np.argmax(share)) + 1


def natural_frequency(model: Model, choice: ModeChoice,
                      signed: dict | None = None) -> ModalFrequency:
    """ω_k and ζ_k of the chosen mode (see the module docstring);
    ComponentError, one line, where the mode has no such frequency.

    Parameters
    ----------
    model : Model
        The assembled and derived model.
    choice : ModeChoice
        Which frequency, of which mode of the run.
    signed : dict, optional
        Symbols to replace before the roots are taken (a parameter the file
        gives negative, by its negative twin).
    """
    moving, M, D, K = _matrices(model, choice.state, signed or {})
    where = f"in {choice.instant}"
    if any(M[i, i] == 0 for i in range(M.rows)):
        raise ComponentError(f"a natural frequency {where}: a moving group has no inertia")
    lam = sp.Dummy("lambda")
    coefficients = sp.Poly(sp.expand((lam * M - K).det(method="berkowitz")),
                           lam).all_coeffs()[::-1]
    rigid = next((i for i, c in enumerate(coefficients) if sp.simplify(c) != 0), 0)
    count = len(moving) - rigid
    if count == 0:
        raise ComponentError(f"the model has no elastic mode {where}"
                             + (f" (groups moving: {len(moving)})" if moving else
                                ": every body is held or moved by a law"))
    which = choice.which
    if isinstance(which, str) and which != LOWEST:
        which = _by_link(model, which, moving, M, K, rigid, choice.state, signed or {})
    k = 1 if which == LOWEST else int(which)
    if not 1 <= k <= count:
        raise ComponentError(f"natural frequency number {k} {where}: the mode has "
                             f"{count} (k from 1 to {count})")
    a = coefficients[rigid:]
    if count == 1:
        square = -a[0] / a[1]
    elif count == 2:
        root = sp.sqrt(a[1] ** 2 - 4 * a[2] * a[0])
        square = (-a[1] + (-root if k == 1 else root)) / (2 * a[2])
    else:
        square = None
    n = len(moving)
    diagonal = M.is_diagonal()
    entries = ([M[i, i] for i in range(n)] if diagonal else _upper(M)) + _upper(K)
    omega = (sp.sqrt(sp.factor(sp.simplify(square))) if square is not None else
             NATURAL_FREQUENCY(k, rigid, n, *entries))
    if count == 1:            # K = λ M φ φᵀ M: φ is M⁻¹ times a column of K
        column = next(K[:, j] for j in range(n) if any(K[:, j]))
        phi = M.inv() * column
        zeta = sp.simplify((phi.T * D * phi)[0] / (2 * omega * (phi.T * M * phi)[0]))
    else:
        zeta = MODAL_DAMPING(k, rigid, n, *entries, *_upper(D))
    route = ("its root" if count == 1 else "the quadratic formula" if count == 2
             else "mpmath's eigsy at each point")
    how = (f"ω_{k} of det(λ M − K) = 0 {where} ({len(model.assembly.groups) - n} group(s) "
           f"fixed, {rigid} rigid-body root(s) dropped, {count} elastic: {route})")
    return ModalFrequency(omega, zeta, k, how)


def modal_quantity(model: Model, what: str, choice: ModeChoice,
                   signed: dict | None = None) -> tuple[sp.Expr, str]:
    """(expression, how) of the modal quantity ``what`` (a key of :data:`MODAL`).

    Parameters
    ----------
    model : Model
        The assembled and derived model.
    what : str
        ``frequency``, ``period``, ``damping_ratio`` or ``damped_frequency``.
    choice : ModeChoice
        Which frequency, of which mode of the run.
    signed : dict, optional
        As :func:`natural_frequency` takes it.
    """
    if model.equations.states:
        raise ComponentError("the modes of M, D and K leave out the parts' first-order "
                             f"states ({', '.join(map(str, model.equations.states))}): "
                             "no modal quantity of this model")
    f = natural_frequency(model, choice, signed)
    if what == "frequency":
        return f.omega, f.how
    if what == "period":
        return 2 * sp.pi / f.omega, f"T = 2π/ω, {f.how}"
    zeta = "ζ = φᵀDφ / (2ω φᵀMφ) of the mode's shape φ"
    if what == "damping_ratio":
        return f.zeta, f"{zeta}, {f.how}"
    return (sp.simplify(f.omega * sp.sqrt(1 - f.zeta ** 2)),
            f"ω_d = ω √(1 − ζ²), {zeta}, {f.how}")


def mode_at(model: Model, at: float | None, duration: float, body: str | None = None,
            speed=0.0, rest: bool = False) -> tuple[Mode, str]:
    """(the run's mode at the instant ``at``, its name): the start's mode when
    ``at`` is None or 0, else the mode of the phase holding ``at`` (the one
    after the events at ``at``).

    Parameters
    ----------
    model : Model
        The assembled and derived model.
    at : float or None
        The instant (s), within the run.
    duration : float
        The run's end (s).
    body, speed, rest
        The start, as :meth:`Model.start` takes it.
    """
    if not at:
        return model.start(body, speed, rest)[0], "the mode of the run's start"
    if not 0 < at <= duration:
        raise ComponentError(f"at = {at:g} s is outside the run (0 to {duration:g} s)")
    run = model.run(duration, body, speed, rest=rest)
    state = next(s.mode for s in reversed(run.result.segments) if s.t0 <= at)
    return state, f"the mode of the run at t = {at:g} s"
