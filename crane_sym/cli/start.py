"""The command line's entry point: SIGTERM is one line from the first instant.

Importing the command line takes a second or two (SymPy, NumPy); a SIGTERM
in that time would end the process silently under Python's default
handler. This module installs the handler of :mod:`crane_sym.cli.sigterm`
first, then imports and runs :func:`crane_sym.cli.main.main`, which says
the line and exits 143 for a SIGTERM that comes later.
"""
from __future__ import annotations

import signal
import sys
import threading
from typing import Sequence

from crane_sym.cli.sigterm import TERMINATED, TERMINATED_CODE, Terminated, terminate

__all__ = ["main"]


def main(argv: Sequence[str] | None = None) -> int:
    """``crane-sym``: the handler first, then the command line (see
    :func:`crane_sym.cli.main.main` for the exit codes).

    Parameters
    ----------
    argv : sequence of str, optional
        The arguments after ``crane-sym`` (default: ``sys.argv[1:]``).
    """
    if threading.current_thread() is threading.main_thread():
        signal.signal(signal.SIGTERM, terminate)
    try:                              # the command line catches its own; this, the rest
        from crane_sym.cli.main import main as command_line
        return command_line(argv)
    except Terminated:
        print(TERMINATED, file=sys.stderr)
        return TERMINATED_CODE
