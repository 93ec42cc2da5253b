"""Files a command writes: only inside the folder the user names, each one
whole or not at all, nothing left behind.

Every file is first written under a fresh temporary name in its target
folder (the process id and a random part, created exclusively, so two runs
never share one) and then renamed over the target name. A rename replaces a
symbolic link at the target name, it never writes through it. Only a regular
file is replaced (:func:`check_target`): a target that is, or links to, a
device, a FIFO or a socket is refused (``-o /dev/null`` as root would
otherwise turn the device into a file), and so is one of the command's own
inputs (:func:`inputs`; ``walkthrough x.toml -o x.toml``). A
:class:`Stage` collects the files of one result (a dataset and its plot, a
scene's module and its figures) and renames them together at the end, with
SIGINT and SIGTERM held off between the renames; on any failure, or a
signal, its temporaries are removed.

An operating-system failure becomes an :class:`OutputError`: one line that
names the option or path, for the command line to print.
"""
from __future__ import annotations

import os
import secrets
import shutil
import signal
import stat
import threading
from contextlib import contextmanager
from contextvars import ContextVar
from pathlib import Path
from typing import Iterable, Iterator

__all__ = ["OutputError", "Stage", "check_folder", "check_target", "deferred_signals",
           "describe", "folder_lock", "inputs", "is_stdout", "out_file", "out_folder",
           "staged", "write_text"]


class OutputError(OSError):
    """A file or folder could not be written; the message names it and why."""


_REASONS = {"EEXIST": "exists", "ENOTDIR": "is not a folder", "EISDIR": "is a folder",
            "EACCES": "permission denied", "EPERM": "permission denied",
            "EROFS": "read-only file system", "ENOSPC": "no space left on the device",
            "ENOENT": "no such file or folder", "EDQUOT": "disk quota exceeded"}


def describe(err: OSError) -> str:
    """The reason of an operating-system error in a few words.

    Parameters
    ----------
    err : OSError
        The error.
    """
    import errno
    name = errno.errorcode.get(err.errno or 0, "")
    return _REASONS.get(name, err.strerror or type(err).__name__)


#: The (device, inode) of each file the running command reads (:func:`inputs`).
_INPUTS: ContextVar[frozenset[tuple[int, int]]] = ContextVar("inputs", default=frozenset())

_KINDS = ((stat.S_ISCHR, "character device"), (stat.S_ISBLK, "block device"),
          (stat.S_ISFIFO, "FIFO"), (stat.S_ISSOCK, "socket"))


@contextmanager
def inputs(paths: Iterable[str | Path]) -> Iterator[None]:
    """Inside the block, the existing files among ``paths`` are the command's
    inputs, which :func:`check_target` never lets a write replace (by device
    and inode, so another spelling, a link or a hard link of an input is one
    too).

    Parameters
    ----------
    paths : iterable of str or Path
        What the command reads; names that are no file are ignored.
    """
    found = set(_INPUTS.get())
    for path in paths:
        try:
            info = os.stat(path)
        except (OSError, ValueError):
            continue
        if stat.S_ISREG(info.st_mode):
            found.add((info.st_dev, info.st_ino))
    token = _INPUTS.set(frozenset(found))
    try:
        yield
    finally:
        _INPUTS.reset(token)


def check_target(path: str | Path, option: str = "-o") -> None:
    """Nothing if a write may replace ``path``: it is missing, a regular file
    or a link to one (the link is replaced, never followed); :class:`OutputError`
    naming ``option`` if it is, or links to, a device, a FIFO or a socket, or
    is one of the command's :func:`inputs`. A folder is left to the caller.

    Parameters
    ----------
    path : str or Path
        The file a command is to write.
    option : str, optional
        The command-line option an error names.
    """
    try:
        info = os.stat(path)                       # through a link: what it names
    except OSError:
        return                                     # missing or a broken link
    for test, kind in _KINDS:
        if test(info.st_mode):
            raise OutputError(f"{option} {str(path)!r} is a {kind}, not a regular file; "
                              "not replaced (write to a file, or leave out the option to "
                              "print)")
    if (info.st_dev, info.st_ino) in _INPUTS.get():
        raise OutputError(f"{option} {str(path)!r} is one of this command's inputs; "
                          "not replaced (name another file)")


def is_stdout(path: str | Path) -> bool:
    """Whether ``path`` means the standard output: ``-``, or a name of the
    very file, pipe or terminal the standard output is (``/dev/stdout``).

    Parameters
    ----------
    path : str or Path
        A file name from the command line.
    """
    if str(path) == "-":
        return True
    try:
        mine, there = os.fstat(1), os.stat(path)
    except (OSError, ValueError):
        return False
    return (mine.st_dev, mine.st_ino) == (there.st_dev, there.st_ino)


def check_folder(path: str | Path, option: str = "--out") -> Path:
    """``path`` if a command could write into it (an existing writable folder,
    or one that can be made in a writable folder), without making it;
    :class:`OutputError` naming ``option`` otherwise. A command checks its
    output folder so before its work, and makes it only when it writes.

    Parameters
    ----------
    path : str or Path
        The folder a command is to write into.
    option : str, optional
        The command-line option an error names.
    """
    folder = Path(path)
    if folder.exists() and not folder.is_dir():
        raise OutputError(f"{option} {str(folder)!r} is a file, not a folder")
    probe = folder
    while not probe.exists():
        if probe.is_symlink():
            raise OutputError(f"{option} {str(folder)!r}: {str(probe)!r} is a broken link")
        probe = probe.parent
    if not probe.is_dir():
        raise OutputError(f"{option} {str(folder)!r}: {str(probe)!r} is a file, not a folder")
    if not os.access(probe, os.W_OK | os.X_OK):
        raise OutputError(f"{option} {str(folder)!r}: {str(probe)!r} is not writable "
                          "(permission denied)")
    return folder


def out_folder(path: str | Path, option: str = "--out") -> Path:
    """The folder ``path``, created if missing; :class:`OutputError` naming
    ``option`` if it is a file or cannot be made or written.

    Parameters
    ----------
    path : str or Path
        The folder.
    option : str, optional
        The command-line option an error names.
    """
    folder = check_folder(path, option)
    try:
        folder.mkdir(parents=True, exist_ok=True)
    except OSError as err:
        raise OutputError(f"{option} {str(folder)!r}: cannot create the folder "
                          f"({describe(err)})") from None
    if not os.access(folder, os.W_OK | os.X_OK):
        raise OutputError(f"{option} {str(folder)!r}: the folder is not writable "
                          "(permission denied)")
    return folder


def out_file(path: str | Path, option: str = "-o") -> tuple[Path, str]:
    """(folder, name) of the file ``path`` a command is to write;
    :class:`OutputError` naming ``option`` if it is a folder or its folder
    is missing or not writable.

    Parameters
    ----------
    path : str or Path
        The file to write.
    option : str, optional
        The command-line option an error names.
    """
    target = Path(path)
    if target.is_dir():
        raise OutputError(f"{option} {str(target)!r} is a folder; give a file name")
    check_target(target, option)
    folder = target.parent
    if not folder.is_dir():
        raise OutputError(f"{option} {str(target)!r}: the folder {str(folder)!r} does not exist")
    return out_folder(folder, option), target.name


def _plain(name: str) -> str:
    """``name`` if it is a plain file name (no folder part), else ValueError."""
    if not name or name in (".", "..") or Path(name).name != name or "\0" in name:
        raise ValueError(f"{name!r} is not a plain file name")
    return name


class Stage:
    """Files of one result under temporary names in ``folder``, renamed onto
    their names by :meth:`commit` (see the module docstring)."""

    def __init__(self, folder: Path, option: str = "--out") -> None:
        self.folder = Path(folder)
        self.option = option
        self._moves: list[tuple[Path, Path]] = []

    def path(self, name: str, suffix: str = "") -> Path:
        """A fresh temporary path for the file (or folder) ``name``; whatever
        is written there becomes ``name`` at :meth:`commit`. ``suffix`` keeps
        an extension a writer looks at (``.png``)."""
        target = self.folder / _plain(name)
        tmp = self.folder / f".{name}.{os.getpid()}-{secrets.token_hex(4)}.partial{suffix}"
        self._moves.append((tmp, target))
        return tmp

    def text(self, name: str, text: str) -> Path:
        """Write ``text`` (UTF-8) for ``name``; return the final path."""
        return self.bytes(name, text.encode("utf-8"))

    def bytes(self, name: str, data: bytes) -> Path:
        """Write ``data`` for ``name``; return the final path."""
        self.write(name, data)
        return self.folder / name

    def write(self, name: str, data: bytes, suffix: str = "") -> Path:
        """Write ``data`` for ``name``; return the temporary path (to read it
        back before :meth:`commit`, e.g. to import a module written there)."""
        tmp = self.path(name, suffix)
        fd = os.open(tmp, os.O_WRONLY | os.O_CREAT | os.O_EXCL | getattr(os, "O_NOFOLLOW", 0),
                     0o644)
        with os.fdopen(fd, "wb") as handle:
            handle.write(data)
        return tmp

    def commit(self) -> list[Path]:
        """Rename every temporary onto its name, under :func:`folder_lock` and
        with signals deferred (:func:`deferred_signals`); a folder already at a
        name (a Zarr store) is replaced whole; a target :func:`check_target`
        refuses stops the commit before any rename."""
        with deferred_signals(), folder_lock(self.folder):
            for tmp, target in self._moves:
                if not (tmp.is_dir() and target.is_dir()):
                    check_target(target, self.option)
            done = []
            for tmp, target in self._moves:
                if not tmp.exists():
                    continue
                if tmp.is_dir() and target.is_dir() and not target.is_symlink():
                    old = target.with_name(f".{target.name}.{os.getpid()}.old")
                    os.replace(target, old)
                    os.replace(tmp, target)
                    shutil.rmtree(old, ignore_errors=True)
                else:
                    if target.is_dir() and not target.is_symlink():
                        raise OutputError(f"{str(target)!r} is a folder; not replaced by a file")
                    os.replace(tmp, target)
                done.append(target)
            self._moves.clear()
            return done

    def discard(self) -> None:
        """Remove every temporary not yet renamed."""
        for tmp, _ in self._moves:
            if tmp.is_dir() and not tmp.is_symlink():
                shutil.rmtree(tmp, ignore_errors=True)
            else:
                try:
                    tmp.unlink()
                except FileNotFoundError:
                    pass
        self._moves.clear()


@contextmanager
def staged(folder: str | Path, option: str = "--out") -> Iterator[Stage]:
    """A :class:`Stage` in the folder ``folder`` (:func:`out_folder`): its files
    are renamed into place when the block ends normally, and removed when it
    raises (an error, KeyboardInterrupt, a SIGTERM turned into an exception).
    An operating-system error inside the block becomes an :class:`OutputError`
    naming ``option``: keep reads out of the block.

    Parameters
    ----------
    folder : str or Path
        The folder the files go into.
    option : str, optional
        The command-line option an error names.
    """
    stage = Stage(out_folder(folder, option), option)
    try:
        yield stage
        stage.commit()
    except OSError as err:
        stage.discard()
        if isinstance(err, OutputError):
            raise
        raise OutputError(f"{option} {str(folder)!r}: cannot write "
                          f"({describe(err)})") from None
    except BaseException:
        stage.discard()
        raise


def write_text(folder: str | Path, name: str, text: str, option: str = "--out") -> Path:
    """Write one file ``name`` into ``folder`` through a :class:`Stage`.

    Parameters
    ----------
    folder : str or Path
        The folder.
    name : str
        The file name.
    text : str
        The content (UTF-8).
    option : str, optional
        The command-line option an error names.
    """
    with staged(folder, option) as stage:
        path = stage.text(name, text)
    return path


@contextmanager
def deferred_signals() -> Iterator[None]:
    """SIGINT and SIGTERM held off inside the block and delivered at its end.

    Python runs a signal's handler in the main thread whichever thread the
    kernel hands the signal to, so blocking the signals in the main thread
    (``pthread_sigmask``) does not hold them off while another thread runs (a
    Dask pool, distributed's event loop): the handlers themselves are swapped
    for one that only notes the signal. Outside the main thread: no effect.
    """
    if threading.current_thread() is not threading.main_thread():
        yield
        return
    caught: list[int] = []

    def later(signum, frame) -> None:
        caught.append(signum)

    previous = {}
    for sig in (signal.SIGINT, signal.SIGTERM):
        if signal.getsignal(sig) is not None:      # None: not set from Python
            previous[sig] = signal.signal(sig, later)
    try:
        yield
    finally:
        for sig, handler in previous.items():
            signal.signal(sig, handler)
        if caught:
            signal.raise_signal(caught[0])         # the restored handler runs now


@contextmanager
def folder_lock(folder: Path) -> Iterator[None]:
    """An exclusive advisory lock (``flock``) on ``folder`` itself: no lock
    file is made, and the lock goes with the process. No-op where ``fcntl``
    is missing.

    Parameters
    ----------
    folder : Path
        An existing folder.
    """
    try:
        import fcntl
    except ImportError:                            # pragma: no cover (Windows)
        yield
        return
    fd = os.open(folder, os.O_RDONLY | getattr(os, "O_DIRECTORY", 0))
    try:
        fcntl.flock(fd, fcntl.LOCK_EX)
        yield
    finally:
        os.close(fd)                               # closing releases the lock
