"""Files only where asked: every command writes only under the folder or the
file its user names (``--out``, ``-o``); without one it prints its results,
writes nothing, and says in one line how to get the files."""
from __future__ import annotations

import sys

__all__ = ["say_no_files"]


def say_no_files(option: str, what: str, *, stderr: bool = False) -> None:
    """Print the one line that says no file was written and how to get them.

    Parameters
    ----------
    option : str
        The option that names where to write (``--out DIR``).
    what : str
        The files it would write ("the module and the plots").
    stderr : bool
        On stderr (when stdout is JSON or source a reader pipes on).
    """
    print(f"no files written: add {option} to write {what}",
          file=sys.stderr if stderr else sys.stdout)
