"""Scenes: one concrete question with its data, read, specialized, run.

Reading and checking a scene's TOML (units parsed, never evaluated), the
options a paper declares, laws given as tables, the specialized module
(stages 2 and 3), the kinds of scene a paper answers (``kinds``), the run
with its panels and plots, and everything ``crane-sym generate`` writes.

May import: the top-level vocabulary, ``mechanics``, ``kernels``, ``audit``
and ``codegen``; papers only through ``registry``.
"""
