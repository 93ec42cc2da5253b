"""Kernels: the NumPy functions a generated module carries with it.

The printer copies the source of the kernels a module calls into that module
(``inspect.getsource``), so each kernel imports only NumPy and math and is
written to be read there: arithmetic, window cells, exact phases, gears.

May import: nothing of crane_sym (NumPy and the standard library only).
"""
