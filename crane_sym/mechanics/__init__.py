"""Mechanics: from physics to equations of motion and their solutions.

Lagrange's equations with Rayleigh dissipation, elimination to a relative
coordinate, linear ODEs, load laws, Duhamel's integral, the Euler–Poisson
extremals, guaranteed extrema and crossings, closed forms of one phase and
piecewise-linear runs (in double and in mpmath), a paper's hybrid model
behind one interface (``hybrid_models``), interval enclosures, involute gear
geometry, sampled loads.

May import: the top-level vocabulary (``symbols``, ``units``, ``dimensions``,
``latex``, ``derivation``, ``outcomes``, ...) and ``kernels``.
"""

# a double phase whose form rounding has spoilt falls back to mpmath's
# (piecewise_linear.precise_form): the provider (exact_forms, which
# exact_phases imports) registers itself on import
from crane_sym.mechanics import exact_phases as _exact_phases  # noqa: E402,F401
