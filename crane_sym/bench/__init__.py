"""Benches: speed against error, and accuracy against mpmath.

Generated functions against what a user would write (SciPy integrators,
quadrature, per-design loops), piecewise-linear runs, sampled loads, design
sweeps, memory, the speed targets, and the accuracy table of the hard cases;
the cases a paper offers are declared in the paper (``bench_cases.py``,
``hard_cases.py``) and found through ``registry``.

May import: everything below it (vocabulary, ``mechanics``, ``kernels``,
``audit``, ``codegen``, ``scenes``, ``sweep``); generated modules only by name
at run time.
"""
