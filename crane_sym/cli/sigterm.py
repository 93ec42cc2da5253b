"""SIGTERM as an exception: the handler the command line installs, and the
one line and exit code it ends with. Imports nothing of crane_sym, so the
entry point (:mod:`crane_sym.cli.start`) can install it before the rest."""
from __future__ import annotations

__all__ = ["TERMINATED", "TERMINATED_CODE", "Terminated", "terminate"]

#: The line a SIGTERM ends the command with, and its exit code.
TERMINATED = "crane-sym: terminated (SIGTERM); nothing half-written is left"
TERMINATED_CODE = 143


class Terminated(BaseException):
    """SIGTERM, raised in the main thread so that every ``finally`` runs (the
    temporaries of :mod:`crane_sym.output_files` are removed)."""


def terminate(signum, frame) -> None:
    """The SIGTERM handler: raise :class:`Terminated` where the main thread is."""
    raise Terminated()
