"""Progress messages for the long commands (audit, generate, accuracy,
walkthrough): on stderr only, so what goes to stdout (JSON, Markdown) stays
clean, and only when asked for (``crane-sym`` turns them on when stderr is a
terminal and ``--quiet`` is not given).

The machinery reports through :func:`current`, which is silent unless a
command has installed a reporter with :func:`reporting`; a library user sees
nothing.
"""
from __future__ import annotations

import sys
import time
from contextlib import contextmanager
from typing import Iterator, TextIO

__all__ = ["Progress", "current", "reporting", "wanted"]


class Progress:
    """Writes progress lines to ``stream`` (default: ``sys.stderr``) when
    ``enabled``. Steps overwrite one status line; other messages are lines."""

    def __init__(self, enabled: bool, stream: TextIO | None = None) -> None:
        self.enabled = enabled
        self._stream = stream
        self._status = False

    @property
    def stream(self) -> TextIO:
        """Where messages go (``sys.stderr`` as it is now, unless given)."""
        return self._stream if self._stream is not None else sys.stderr

    def _clear(self) -> None:
        if self._status:
            self.stream.write("\r\x1b[K")
            self._status = False

    def say(self, message: str) -> None:
        """One line of progress (a derivation, a file, a scene)."""
        if self.enabled:
            self._clear()
            self.stream.write(message + "\n")
            self.stream.flush()

    def step(self, message: str) -> None:
        """A cheap per-step note, written over the previous one."""
        if self.enabled:
            self._clear()
            self.stream.write(message[:100])
            self.stream.flush()
            self._status = True

    @contextmanager
    def task(self, what: str) -> Iterator[None]:
        """Say ``what``, run the block, then say how long it took."""
        start = time.perf_counter()
        self.say(f"{what} ...")
        yield
        self.say(f"{what}: {time.perf_counter() - start:.1f} s")

    def done(self) -> None:
        """Clear a pending step line."""
        if self.enabled:
            self._clear()
            self.stream.flush()


_CURRENT = [Progress(False)]


def current() -> Progress:
    """The reporter in use (a silent one unless a command installed one)."""
    return _CURRENT[-1]


@contextmanager
def reporting(progress: Progress) -> Iterator[Progress]:
    """Use ``progress`` for the duration of the block.

    Parameters
    ----------
    progress : Progress
        The reporter ``current()`` returns inside the block.
    """
    _CURRENT.append(progress)
    try:
        yield progress
    finally:
        progress.done()
        _CURRENT.pop()


def wanted(quiet: bool, stream: TextIO | None = None) -> bool:
    """Whether to show progress: not ``quiet`` and ``stream`` (default
    ``sys.stderr``) is a terminal.

    Parameters
    ----------
    quiet : bool
        The user's ``--quiet``.
    stream : text stream, optional
        Where progress would go.
    """
    stream = stream if stream is not None else sys.stderr
    isatty = getattr(stream, "isatty", None)
    return not quiet and callable(isatty) and bool(isatty())
