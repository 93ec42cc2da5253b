"""Audit: verdicts on published formulas, from checks that can fail.

Seeded sample points inside the physics, the three checks (symbolic identity,
mpmath at the points, dimensions), fits of unstated parameters, the printed
LaTeX read by machine, the verdict records and their formats (table, JSON,
Markdown).

May import: the top-level vocabulary (``derivation``, ``published``,
``sensitivity``, ``outcomes``, ``symbols``, ...). Not the mechanics: a verdict
rests on the derivation record, not on how it was built.
"""
