"""The tail every ``crane-sym walkthrough`` shares: a paper's or a component
file's handout made under a progress line, then written to ``-o`` or printed
(``-o -`` or ``-o /dev/stdout`` print too)."""
from __future__ import annotations

import argparse
from typing import Callable

from crane_sym import output_files, progress
from crane_sym.cli.unasked import say_no_files

__all__ = ["deliver_walkthrough"]


def deliver_walkthrough(args: argparse.Namespace, name: str, make: Callable[[str], str]) -> int:
    """Make the walkthrough of ``name`` (``make(name)``), then write it to
    ``-o`` (the file's folder checked before the work; nothing written on an
    error) and say so, or print it and say on stderr how to get the file.

    Parameters
    ----------
    args : argparse.Namespace
        The command's arguments (``output``, ``quiet``).
    name : str
        The paper id or component file, as the progress line names it.
    make : callable
        Name -> the walkthrough's text.
    """
    printed = not args.output or output_files.is_stdout(args.output)
    target = None if printed else output_files.out_file(args.output, "-o")
    reporter = progress.Progress(progress.wanted(getattr(args, "quiet", False)))
    with progress.reporting(reporter) as say, say.task(f"walkthrough of {name}"):
        text = make(name)
    if target:
        output_files.write_text(target[0], target[1], text, "-o")
        print(f"wrote {args.output}")
    else:
        print(text)
        say_no_files("-o FILE", "it to a file", stderr=True)
    return 0
