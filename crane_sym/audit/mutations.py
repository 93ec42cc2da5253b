"""Every check can fail: each record's transcription mutated in turn, and the
mutations the audit catches counted per paper.

The mutations are the slips a transcriber makes: a sign flipped, a factor 2, two
symbols swapped, a decimal point shifted (a number only). Only the
transcription is changed, never the printed LaTeX beside it, so a mutation is
caught when the record's verdict changes: its own check fails, or the print
read by machine no longer agrees with it (``tied_to_print``). A mutation that
leaves the relation as it was (a sign of 0, a swap of symbols that enter alike)
is not a mutant and is not counted.
"""
from __future__ import annotations

from dataclasses import dataclass, replace

import sympy as sp

from crane_sym.audit.machine_read import machine_read
from crane_sym.audit.verdicts import audit_formula, tied_to_print
from crane_sym.derivation import Derivation
from crane_sym.published import PublishedFormula
from crane_sym.symbols import PARAMETER, SymbolTable

__all__ = ["MUTATIONS", "KillTable", "kills", "mutants"]

MUTATIONS = ("sign", "factor 2", "swapped symbols", "decimal point")


def _swapped(expr: sp.Expr, symbols: SymbolTable) -> sp.Expr | None:
    """``expr`` with the first two of its parameters (by name) that share a
    dimension exchanged (m1 for m2), or None when no two do."""
    params = sorted((s for s in expr.free_symbols if isinstance(s, sp.Symbol)
                     and s in symbols and symbols[s].role == PARAMETER),
                    key=lambda s: s.name)
    for i, a in enumerate(params):
        for b in params[i + 1:]:
            if symbols[a].dimension == symbols[b].dimension:
                return expr.xreplace({a: b, b: a})
    return None


def mutants(relation: sp.Eq, symbols: SymbolTable) -> dict[str, sp.Eq]:
    """The mutations of ``relation``'s right-hand side that change it, by name.

    Parameters
    ----------
    relation : sympy.Eq
        A transcription.
    symbols : SymbolTable
        Its paper's symbols (a swap exchanges two parameters of one dimension).
    """
    rhs = relation.rhs
    found = {"sign": -rhs, "factor 2": 2 * rhs, "swapped symbols": _swapped(rhs, symbols),
             "decimal point": 10 * rhs if rhs.is_number else None}
    return {name: sp.Eq(relation.lhs, new, evaluate=False) for name, new in found.items()
            if new is not None and sp.simplify(new - rhs) != 0}


@dataclass(frozen=True)
class KillTable:
    """One paper's mutants: by mutation, how many were tried and caught, and the
    survivors (record label, mutation)."""

    paper: str
    tried: dict[str, int]
    caught: dict[str, int]
    survivors: tuple[tuple[str, str], ...]

    def row(self) -> str:
        """A Markdown row: paper, caught/tried per mutation, all."""
        cells = [f"{self.caught[m]}/{self.tried[m]}" for m in MUTATIONS]
        return (f"| {self.paper} | " + " | ".join(cells)
                + f" | {sum(self.caught.values())}/{sum(self.tried.values())} |")


def _verdict(d: Derivation, f: PublishedFormula) -> str:
    return tied_to_print(replace(audit_formula(d, f), machine_read=machine_read(d, f))).verdict


def kills(d: Derivation, labels: tuple[str, ...] | None = None) -> KillTable:
    """Each record of ``d`` (or those labelled ``labels``) mutated in turn.

    Parameters
    ----------
    d : Derivation
        The built paper.
    labels : tuple of str, optional
        Only these records (all with a transcription when None).
    """
    tried = dict.fromkeys(MUTATIONS, 0)
    caught = dict.fromkeys(MUTATIONS, 0)
    survivors = []
    for f in d.published:
        if f.printed is None or (labels is not None and f.label not in labels):
            continue
        before = _verdict(d, f)
        for name, relation in mutants(f.printed, d.symbols).items():
            tried[name] += 1
            if _verdict(d, replace(f, printed=relation)) != before:
                caught[name] += 1
            else:
                survivors.append((f.label, name))
    return KillTable(d.id, tried, caught, tuple(survivors))
