"""The command line of design sweeps: ``crane-sym sweep`` and ``bench --sweep``.

A subcommand imports its machinery when it runs (the imports inside the
functions below): importing every subcommand's at start-up costs 1.31 s of
CPU against 0.59 s for the command line alone (median of 5 whole-process runs),
and `crane-sym --help` or `crane-sym list` need none of it.
"""
from __future__ import annotations

import argparse
import json
import logging
import sys
from contextlib import contextmanager
from pathlib import Path
from typing import Iterator

from crane_sym import output_files, progress

#: ``--time-limit``'s default, seconds (crane_sym.sweep.estimate.DEFAULT_TIME_LIMIT: the
#: command line does not import the sweep's machinery at start-up).
DEFAULT_TIME_LIMIT = 900.0


def cmd_sweep(args: argparse.Namespace) -> int:
    """A design sweep: outputs over a grid of designs, on Dask. Every option
    is checked, and ``--out`` and the grid's size against memory and disk,
    before anything is computed; the dataset and its PNG are written under
    temporary names and renamed together (:func:`crane_sym.sweep.store.sweep_stage`)."""
    # imported on use: see the module docstring
    from crane_sym.scenes.reading import load_scene
    from crane_sym.sweep.grid import check_grid, run_sweep
    from crane_sym.sweep.plan import SweepError
    from crane_sym.sweep.report import plot, summary, text_lines
    from crane_sym.sweep.spec import parse_chunk_mib, plan
    from crane_sym.sweep.store import sweep_stage
    chunk_bytes = parse_chunk_mib(args.chunk_mib)
    out = output_files.check_folder(args.out, "--out")
    from crane_sym.components.reading import is_component_file
    if is_component_file(args.scene):                 # a drive train of the user's own
        from crane_sym.sweep.component_plan import plan_file
        chosen = plan_file(args.scene, args.vary or [], args.output or [], args.at or [],
                           args.limit)
    else:
        chosen = plan(load_scene(args.scene), args.vary, args.output, args.at or [],
                      args.limit)
    check_grid(chosen, out, chunk_bytes)
    if not args.time_limit > 0:
        raise SweepError(f"--time-limit {args.time_limit:g}: must be > 0 s")
    certify = None
    if args.certify:                  # refuses before the estimate's pilot and any write
        from crane_sym.sweep.certify import prepare
        certify = prepare(chosen, args.certify_tol)
    from crane_sym.sweep.estimate import check_estimate, estimate
    cost = estimate(chosen, chunk_bytes)
    if not getattr(args, "quiet", False):     # a refusal names the estimate anyway
        print(cost.line(), file=sys.stderr, flush=True)
    check_estimate(cost, args.time_limit)
    say = progress.Progress(progress.wanted(getattr(args, "quiet", False)))
    with _distributed_quiet(), sweep_stage(out) as stage, progress.reporting(say):
        with say.task(f"computing {chosen.points} designs"):   # Dask's bar inside
            result = run_sweep(chosen, stage, scheduler=args.scheduler,
                               chunk_bytes=chunk_bytes, quiet=not say.enabled)
        with say.task("drawing the PNG"):
            plot(result, stage)
        if certify is not None:
            from crane_sym.sweep.certify import certify_result
            with say.task("certifying the worst case by intervals"):
                result.extra["certified"] = certify_result(certify, result, args.scheduler)
    data = summary(result)
    if args.format == "json":
        print(json.dumps(data, indent=2, ensure_ascii=False))
    else:
        print("\n".join(text_lines(data)))
    return 0


@contextmanager
def _distributed_quiet() -> Iterator[None]:
    """No log records while the sweep runs: dask.distributed logs a lost
    connection as an ERROR with its traceback (on loggers its configuration
    sets one by one); the command says it in one line."""
    previous = logging.root.manager.disable
    logging.disable(logging.CRITICAL)
    try:
        yield
    finally:
        logging.disable(previous)


def add_arguments(p: argparse.ArgumentParser) -> None:
    """The options of ``crane-sym sweep``."""
    p.add_argument("scene", help="scene name or path to a scene TOML file (the fixed values), "
                   "or a component model TOML file (axes COMPONENT.FIELD, outputs LINK.peak "
                   "and LINK.factor)")
    p.add_argument("--vary", action="append", metavar="NAME=START:STOP:N[:log] [UNIT]",
                   help="a grid axis over a parameter of the scene (of a component file: "
                   "COMPONENT.FIELD), in the unit the file gives it unless UNIT is named "
                   "(repeat for more axes)")
    p.add_argument("--output", action="append", metavar="NAME",
                   help="an output to sweep: a generated function or a simulated response "
                   "of the paper; of a component file LINK.peak or LINK.factor (repeatable)")
    p.add_argument("--at", action="append", metavar="NAME=VALUE [UNIT]",
                   help="a value for an argument the scene does not give (t=0.12, "
                   "t=120 ms), or a window t=START:STOP:N over which each output taking t "
                   "is maximised (sampled)")
    p.add_argument("--limit", metavar="\"NAME<=VALUE UNIT\"",
                   help="count the designs within it, draw its contour")
    p.add_argument("--time-limit", type=float, default=DEFAULT_TIME_LIMIT, metavar="SECONDS",
                   help="refuse a sweep whose estimate (from timed pilot blocks, printed before "
                   f"the sweep starts) passes it (default {DEFAULT_TIME_LIMIT:g} s)")
    p.add_argument("--out", required=True, help="folder for the Zarr dataset and the PNG "
                   "(both replaced together, or neither)")
    p.add_argument("--format", choices=("table", "json"), default="table")
    p.add_argument("--scheduler", metavar="ADDRESS", help="a dask.distributed scheduler, "
                   "e.g. tcp://10.0.0.5:8786 (default: Dask's local scheduler, threads for "
                   "closed forms, processes for simulated responses, synchronous for a "
                   "component file's or a grid of one block; 'threads', 'processes' or "
                   "'synchronous' force one)")
    p.add_argument("--chunk-mib", type=float, default=8.0,
                   help="output bytes per block of the grid, in MiB (default 8; at least "
                   "0.1, at most the free memory for one block per core)")
    p.add_argument("--certify", action="store_true", help="also bound the maximum of the "
                   "(limited) output over the whole box by interval branch-and-bound")
    p.add_argument("--certify-tol", type=float, default=1e-6, metavar="REL",
                   help="width of the certified enclosure, relative to its value "
                   "(default 1e-6)")


def run_bench(out_dir: Path, as_json: bool) -> Path:
    """Design sweeps against per-design integration, efficiency, 10⁸ designs,
    a LocalCluster against the local scheduler; hybrid outputs batched against
    their per-design loop; returns the Markdown file's path."""
    from crane_sym.bench.sweeps import bench_sweep, markdown
    results = bench_sweep()
    text = markdown(results)
    path = out_dir / "bench_sweep.md"
    path.write_text(text, encoding="utf-8")
    print(json.dumps(results, indent=2) if as_json else text)
    return path
