"""The ``crane-sym`` command line: one function per subcommand, and the parser.

Turns every failure into one line and an exit code; assembles nothing itself
(tables and reports come from the packages below).

May import: every other package.
"""
