"""Design sweeps: a grid of designs of one scene or component file, block-wise on Dask.

The checked request (axes, outputs, limit), the plan, the Dask computation and
its shutdown, the Zarr store with its PNG written together, the summary and the
worst case certified by intervals.

May import: the top-level vocabulary, ``mechanics``, ``kernels``, ``audit``,
``codegen``, ``scenes`` and ``components`` (a component file's designs).
"""
