"""Code generation: rewrite rules -> printer -> module text -> files.

Exact rewrites to numerically stable forms, the NumPy printers (in-place
chains, window cells, the scalar fast path, tabulated piecewise-linear runs),
the module template and the files of ``generated/``.

May import: the top-level vocabulary, ``mechanics``, ``kernels`` and
``audit``. Never ``crane_sym.generated`` or ``crane_sym.derivations`` by an
import statement (``files.default_directory`` finds the folder by name).
"""
