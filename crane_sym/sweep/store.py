"""Where a design sweep's files go: a dataset and its PNG, replaced together
or not at all, and nothing left that reads as a dataset.

A sweep writes ``<scene>_sweep.zarr`` and ``<scene>_sweep.png`` through one
:class:`crane_sym.output_files.Stage` (:func:`sweep_stage`): both under fresh
temporary names in ``--out`` (``.<name>.<pid>-<random>.partial``: hidden, and
not ending in ``.zarr``), renamed onto their names together at the end, while
holding an advisory lock on the folder (:func:`folder_lock`), so that two
sweeps into one folder replace the pair one after the other, never one file
each, and with SIGINT and SIGTERM deferred (:func:`deferred_signals`). On any
failure or signal the temporaries are removed, once the tasks that write into
them have stopped (the caller's job: :mod:`crane_sym.sweep.grid` waits for its own
pools, and asks a live ``dask.distributed`` scheduler); what a remote worker
of a lost scheduler may write later is removed while it keeps appearing for a
short while (:func:`remove_settled`).

The Zarr metadata is written by this process only (before the blocks, and
consolidated after them), so chunk files that a late worker writes into a
removed temporary never open as a dataset.
"""
from __future__ import annotations

import shutil
import time
from contextlib import contextmanager
from pathlib import Path
from typing import Iterator

from crane_sym import output_files
from crane_sym.output_files import OutputError, Stage, deferred_signals, folder_lock

__all__ = ["deferred_signals", "folder_lock", "remove_settled", "sweep_stage"]


def remove_settled(path: Path, settle: float = 0.0, grace: float = 10.0) -> bool:
    """Remove ``path`` (a folder or file) and keep removing it until it has
    stayed absent for ``settle`` seconds or ``grace`` seconds have passed;
    True if it is gone."""
    deadline = time.monotonic() + grace
    gone_since = None
    while True:
        if path.exists() or path.is_symlink():
            if time.monotonic() > deadline:
                return False
            gone_since = None
            if path.is_dir() and not path.is_symlink():
                shutil.rmtree(path, ignore_errors=True)
            else:
                path.unlink(missing_ok=True)
            continue
        now = time.monotonic()
        gone_since = gone_since or now
        if now - gone_since >= settle:
            return True
        if now > deadline:
            return not path.exists()
        time.sleep(0.05)


@contextmanager
def sweep_stage(out: Path, option: str = "--out") -> Iterator[Stage]:
    """A :class:`Stage` in the folder ``out`` (made if missing): its files are
    renamed into place when the block ends, under :func:`folder_lock` with
    signals deferred; on a failure or signal they are removed, and ``out`` too
    if this made it and it is empty. An operating-system error becomes an
    :class:`OutputError` naming ``option``.

    Parameters
    ----------
    out : Path
        The output folder.
    option : str, optional
        The command-line option an error names.
    """
    out = Path(out)
    made = not out.exists()
    stage = Stage(output_files.out_folder(out, option))
    try:
        yield stage
        stage.commit()
    except BaseException as err:
        with deferred_signals():
            stage.discard()
            if made:
                try:
                    out.rmdir()
                except OSError:
                    pass
        if isinstance(err, OSError) and not isinstance(err, OutputError):
            raise OutputError(f"{option} {str(out)!r}: cannot write "
                              f"({output_files.describe(err)})") from None
        raise
