"""``crane-sym run FILE`` for a component file (a drive train of the user's own)."""
from __future__ import annotations

import argparse
from pathlib import Path

from crane_sym import progress

__all__ = ["cmd_run_components"]


def cmd_run_components(args: argparse.Namespace) -> int:
    """Run a component file: print the peak loads and the events, write the
    JSON and the plot into --out."""
    from crane_sym.components.report import run_component_file
    quiet = getattr(args, "quiet", False)
    with progress.reporting(progress.Progress(progress.wanted(quiet))) as say:
        with say.task(f"deriving and running {args.scene}"):
            report = run_component_file(args.scene, Path(args.out))
    model = report.run.model
    print(f"model {model.name}: {model.title}" if model.title else f"model {model.name}")
    for line in report.lines:
        print(f"  {line}")
    print("written: " + ", ".join(str(f) for f in report.files))
    return 0
