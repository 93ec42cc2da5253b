"""Bench cases of paper 003 (``crane_sym.bench.cases``).

- Batched: the start-up's largest F1 + F2 (``peak_startup_link_force``) over
  the link stiffness C_пр and its damping ratio ζ of scene
  ``fig12_startup_backlash``, backlash half a turn of the fast shaft (π rad),
  30 × 30 designs solved as one block by the batched solver (each design's
  own rules, ``crane_sym.mechanics.batched_runs``), against the per-design
  loop on a sample; and its 100 × 100 designs as one block against the
  target of 1 s (``crane_sym.bench.design_targets``, issue 39).
"""
from __future__ import annotations

from crane_sym.bench.cases import BatchedBenchCase

from .sweep_outputs import peak_per_design


BATCHED_BENCH_CASES = (
    BatchedBenchCase("peak_startup_link_force", "fig12_startup_backlash",
                     ("c_l=2:8:{n}", "zeta=0.02:0.1:{n}"), peak_per_design, n=30, sample=24,
                     at=("phi_b=3.141592653589793",), block_target=1.0, block_n=100),
)
