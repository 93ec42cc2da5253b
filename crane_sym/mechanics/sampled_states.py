"""The two states of a sampled-load response, summed chunk by chunk.

:mod:`crane_sym.mechanics.sampled_load` reads x, x' and x'' at every sample off one of
two states, :math:`w = \\dot x + i\\Omega x` and
:math:`u = \\dot x - i\\ddot x/\\Omega`, each a prefix sum of segment terms
turned by the sample's rotation (see that module). Here those sums run over
chunks of :data:`CHUNK` samples with the running sum carried between chunks
in double-double, so that the memory a call needs is its input, its output
and a few chunks, whatever the length of the record; a first pass over the
chunks finds how far each state is read (its error bound, a plain running
sum, is carried the same way).
"""
from __future__ import annotations

from typing import Callable, NamedTuple

import numpy as np

from crane_sym.kernels.arithmetic import _compensated_cumsum, _two_sum

__all__ = ["BLOCK", "CHUNK", "Weights", "prefix_sums", "respond"]

#: Terms per block of the prefix sum: rounding in a block stays below ~BLOCK
#: ulp of that block's own sums, however long the record.
BLOCK = 64
#: Samples per chunk (a multiple of BLOCK): the work arrays of a call.
CHUNK = 1 << 15


class Weights(NamedTuple):
    """Real and imaginary parts of the weights of a linear segment (see
    ``sampled_load.segment_weights``)."""

    a_re: np.ndarray
    a_im: np.ndarray
    b_re: np.ndarray
    b_im: np.ndarray
    e_re: np.ndarray
    e_im: np.ndarray


#: (first, end) -> e^{i phi_k} for the samples k in [first, end).
Rotations = Callable[[int, int], np.ndarray]
#: (first, end) -> (h_j, weights) of the segments j in [first, end): arrays,
#: or scalars when every segment has the same length.
Segments = Callable[[int, int], tuple]


def prefix_sums(terms: np.ndarray, n: int, compensated: bool) -> np.ndarray:
    """Prefix sums of the first ``n`` of ``terms`` (a 1-D array padded with
    zeros to a multiple of BLOCK), in place: a plain cumsum inside each block
    of BLOCK terms, and the blocks' totals accumulated by
    ``kernels.arithmetic._compensated_cumsum``. As accurate as the compensated sum of
    all terms (a few ulp of each sum) at about the cost of one ``np.cumsum``;
    ``compensated=False`` is the plain ``np.cumsum``, for comparison."""
    if not compensated:
        return np.cumsum(terms[:n], out=terms[:n])
    blocks = terms.reshape(-1, BLOCK)
    np.cumsum(blocks, axis=1, out=blocks)
    ends = blocks[:-1, -1]
    blocks[1:] += _compensated_cumsum(ends)[:, None]
    return terms[:n]


def _load_terms(h, wt: Weights, S: np.ndarray, out: np.ndarray) -> None:
    """:math:`\\int_0^{h_j} e^{-i\\Omega s} S(t_j + s)\\,ds = h_j (S_j A_j + S_{j+1} B_j)`
    into the complex array ``out``: what drives :math:`w`."""
    left, right = S[:-1], S[1:]
    if np.ndim(h) == 0:                          # one segment length: complex scalars
        np.multiply(left, complex(wt.a_re, wt.a_im) * h, out=out)
        out += right * (complex(wt.b_re, wt.b_im) * h)
        return
    for part, wa, wb in ((out.real, wt.a_re, wt.b_re), (out.imag, wt.a_im, wt.b_im)):
        np.multiply(left, wa, out=part)
        part += right * wb
        part *= h


def _slope_terms(wt: Weights, jump: np.ndarray, out: np.ndarray) -> None:
    """:math:`-(i/\\Omega) \\int_0^{h_j} e^{-i\\Omega s} S'\\,ds
    = -i\\,\\Delta_j E_j`, :math:`\\Delta_j = (S_{j+1} - S_j)/\\Omega`, into
    ``out``: what drives :math:`u` (at a jump of S, :math:`h_j = 0`, the jump
    of :math:`u`)."""
    if np.ndim(wt.e_re) == 0:
        np.multiply(jump, complex(wt.e_im, -wt.e_re), out=out)
        return
    np.multiply(jump, wt.e_im, out=out.real)
    np.multiply(jump, wt.e_re, out=out.imag)
    np.negative(out.imag, out=out.imag)


class _Choice(NamedTuple):
    """Which state each sample of a chunk is read off, and the error bounds
    carried to the next chunk."""

    x_by_w: np.ndarray
    v_by_w: np.ndarray
    a_by_w: np.ndarray
    next_w: float
    next_u: float


def _choice(S: np.ndarray, Omega: float, h, first: int, end: int, by_w0: float,
            by_u0: float) -> _Choice:
    """Bounds on the sums of |terms| (:math:`|I_j| \\le h_j (|S_j| + |S_{j+1}|)/2`,
    :math:`|J_j| \\le |\\Delta_j|`), which bound each state's rounding errors,
    at the samples [first, end), running on from ``by_w0`` and ``by_u0``. A
    ramp's w grows with S while its x' and x'' do not; after a sudden load u
    starts at S/Omega while x and x' start at 0."""
    stop = min(end + 1, S.size)                  # one sample on: the carry
    size = np.abs(S[first:stop])
    by_w = np.empty(stop - first)
    by_w[0] = by_w0
    np.add(size[:-1], size[1:], out=by_w[1:])
    by_w[1:] *= 0.5 * h
    np.cumsum(by_w, out=by_w)
    by_u = np.empty(stop - first)
    by_u[0] = by_u0
    np.subtract(S[first + 1:stop], S[first:stop - 1], out=by_u[1:])
    by_u[1:] /= Omega
    np.abs(by_u[1:], out=by_u[1:])
    np.cumsum(by_u, out=by_u)
    size /= Omega                                # |S|/Omega, the gap between w and u
    m = end - first
    bw, bu, sz = by_w[:m], by_u[:m], size[:m]
    return _Choice(bw <= bu + sz, bw <= bu, bw + sz <= bu,
                   float(by_w[-1]), float(by_u[-1]))


def _reach(mask: np.ndarray) -> int:
    """1 + the index of the last True in ``mask``, 0 if none."""
    return mask.size - int(np.argmax(mask[::-1])) if mask.any() else 0


class _Sum:
    """first + Σ_{j<k} conj(rot_j) term_j, carried in double-double from chunk
    to chunk."""

    def __init__(self, first: complex, compensated: bool) -> None:
        self.hi, self.lo = complex(first), 0j
        self.compensated = compensated

    def chunk(self, fill: Callable[[np.ndarray], None], rot: np.ndarray, m: int,
              segments: int) -> np.ndarray:
        """The state at the chunk's m samples; ``fill(out)`` writes the terms of
        its ``segments`` segments (m, or m - 1 in the last chunk) into ``out``."""
        sums = np.zeros(-(-(m + 1) // BLOCK) * BLOCK, dtype=complex)
        fill(sums[1:segments + 1])
        sums[1:segments + 1] *= np.conjugate(rot[:segments])
        sums = prefix_sums(sums, segments + 1, self.compensated)
        state = sums[:m] + self.hi
        if self.lo:
            state += self.lo
        if segments == m:                        # carry the chunk's total on
            total = complex(sums[m])
            hi = self.hi + total
            lo = complex(*(_two_sum(p, q)[1] for p, q in ((self.hi.real, total.real),
                                                          (self.hi.imag, total.imag))))
            self.hi, self.lo = hi, self.lo + lo
        state *= rot[:m]
        return state


def respond(S: np.ndarray, Omega: float, rotations: Rotations, segments: Segments,
            x0: float, v0: float, acceleration: bool,
            compensated: bool) -> tuple[np.ndarray, np.ndarray, np.ndarray | None]:
    """x, x', x'' at every sample, each read off whichever of the states
    :math:`w = \\dot x + i\\Omega x` and :math:`u = \\dot x - i\\ddot x/\\Omega`
    has the smaller error bound there; each state is summed only as far as
    it is read, chunk by chunk."""
    n = S.size
    w0 = complex(v0, Omega * x0)
    u0 = complex(v0, Omega * x0 - S[0] / Omega)
    starts = list(range(0, n, CHUNK))
    carries, reach_w, reach_u = [], 0, 0
    bw, bu = abs(w0), abs(u0)
    for first in starts:                         # pass 1: how far each state is read
        end = min(first + CHUNK, n)
        carries.append((bw, bu))
        h, _ = segments(first, min(end, n - 1))
        c = _choice(S, Omega, h, first, end, bw, bu)
        bw, bu = c.next_w, c.next_u
        if c.x_by_w.any():                       # x_by_w >= v_by_w >= a_by_w
            reach_w = first + _reach(c.x_by_w)
        need_u = ~c.a_by_w if acceleration else ~c.v_by_w
        if need_u.any():
            reach_u = first + _reach(need_u)

    x, v = np.empty(n), np.empty(n)
    a = np.empty(n) if acceleration else None
    W, U = _Sum(w0, compensated), _Sum(u0, compensated)
    for first, (bw, bu) in zip(starts, carries):
        end = min(first + CHUNK, n)
        m, last = end - first, min(end, n - 1)
        h, wt = segments(first, last)
        c = _choice(S, Omega, h, first, end, bw, bu)
        rot = rotations(first, min(end + 1, n))
        part = S[first:last + 1]
        if first < reach_w:
            w = W.chunk(lambda out: _load_terms(h, wt, part, out), rot, m, last - first)
            np.divide(w.imag, Omega, out=x[first:end])
            v[first:end] = w.real
            if acceleration:
                np.subtract(S[first:end], Omega * w.imag, out=a[first:end])
        if first < reach_u:                      # past reach_w every mask is False
            jump = np.subtract(part[1:], part[:-1])
            jump /= Omega
            u = U.chunk(lambda out: _slope_terms(wt, jump, out), rot, m, last - first)
            np.copyto(x[first:end], (u.imag + S[first:end] / Omega) / Omega,
                      where=~c.x_by_w)
            np.copyto(v[first:end], u.real, where=~c.v_by_w)
            if acceleration:
                np.copyto(a[first:end], u.imag * -Omega, where=~c.a_by_w)
    return x, v, a
