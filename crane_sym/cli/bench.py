"""`crane-sym bench`: speed against error of the generated code and the SciPy
alternatives, the targets table, piecewise-linear runs, sampled loads,
(with ``--audit``) the main job's time against its targets, (with
``--fast-paths``) the fast-path targets alone, (with ``--parallel``) both
cores against a roofline, (with ``--designs``) section (g) of the sweeps alone:
models from components at 10⁴ designs a block, (with ``--sweep``)
design sweeps and (with ``--components FILE``) component
models from the file to the run.

A subcommand imports its machinery when it runs (the imports inside the
functions below): importing every subcommand's at start-up costs 1.31 s of
CPU against 0.59 s for the command line alone (median of 5 whole-process runs),
and `crane-sym --help` or `crane-sym list` need none of it.
"""
from __future__ import annotations

import argparse
import json
import os
import sys
import tempfile
import time
from pathlib import Path
from typing import Sequence

from crane_sym import output_files, progress, registry
from crane_sym.cli import sweep as cli_sweep
from crane_sym.cli.unasked import say_no_files
from crane_sym.markdown import markdown_table

#: What each count option of ``bench`` accepts: (least, most).
COUNTS = {"--points": (2, 10**7), "--throughput-points": (1, 10**8),
          "--sizes": (1, 10**8), "--compare-points": (2, 10**7)}
#: Integrator tolerances ``--rtols`` accepts: solve_ivp raises one below
#: 100 eps (2.2e-14) to that, and one of 0.1 or more checks nothing.
RTOL_RANGE = (1e-13, 0.1)


def _ids(names: Sequence[str]) -> list[str]:
    return [registry.resolve(n) for n in names] if names else registry.ids()


def _machine() -> str:
    # imported on use: see the module docstring
    import platform

    import numpy
    import scipy
    return (f"{platform.machine()} {platform.processor() or platform.system()}, "
            f"Python {platform.python_version()}, NumPy {numpy.__version__}, "
            f"SciPy {scipy.__version__}")


def cmd_bench(args: argparse.Namespace) -> int:
    """Speed against error of the generated functions and the SciPy alternatives
    (without ``--out``: the same run, its files made in a temporary folder,
    removed at the end, and not named)."""
    quiet = getattr(args, "quiet", False)
    with progress.reporting(progress.Progress(progress.wanted(quiet))):
        if args.out:
            return _bench(args, Path(args.out), keep=True)
        with tempfile.TemporaryDirectory(prefix="crane_sym_bench_") as scratch:
            code = _bench(args, Path(scratch) / "bench", keep=False)
    say_no_files("--out DIR", "the Markdown and PNG files", stderr=args.format == "json")
    return code


def _wrote(paths: Sequence[Path], keep: bool) -> None:
    """Name the files written, when they are the user's to keep."""
    if keep and paths:
        print("wrote " + ", ".join(map(str, paths)))


def check_options(args: argparse.Namespace) -> None:
    """ValueError naming the first bench option out of its range (``COUNTS``,
    ``RTOL_RANGE``); an ``--out`` that cannot be written is an OutputError."""
    for option, (least, most) in COUNTS.items():
        given = getattr(args, option[2:].replace("-", "_"), None)
        each = "each " if isinstance(given, list) else ""
        for value in ([given] if isinstance(given, int) else given or []):
            if not least <= value <= most:
                raise ValueError(f"{option}: {each}must be an integer in {least}.."
                                 f"1e{len(str(most)) - 1}, got {value}")
    low, high = RTOL_RANGE
    for rtol in args.rtols or []:
        if not low <= rtol <= high:
            raise ValueError(f"--rtols: each tolerance must be in [{low:g}, {high:g}], "
                             f"got {rtol:g}")
    if args.out:
        output_files.check_folder(args.out)


def _bench(args: argparse.Namespace, out_dir: Path, keep: bool) -> int:
    # imported on use: see the module docstring
    from crane_sym.bench import functions as bench
    from crane_sym.bench import memory as bench_memory
    from crane_sym.bench import targets as bt
    from crane_sym.bench.fast_paths import bench_inputs
    from crane_sym.bench.report import as_markdown, headline, not_applicable, plot, plot_scaling
    say = progress.current()
    ids = _ids(args.ids)                 # an unknown id fails before the folder is made
    check_options(args)                  # so does an option out of its range
    # the sections (--audit, --fast-paths, --sweep, --components): without ids, only those
    sections_only = not args.ids and any(getattr(args, name, None) for name in (
        "audit", "fast_paths", "parallel", "designs", "sweep", "components"))
    show = args.format == "table"
    if getattr(args, "audit", False):
        with say.task("the main job: audit and generate --check"):
            _wrote([_bench_audit(out_dir, show)], keep and show)
    if getattr(args, "fast_paths", False):
        from crane_sym.bench import fast_paths
        with say.task("fast paths: np.cos at 1e5 points and peak memory on 1e6"):
            text = fast_paths.markdown(fast_paths.fast_paths(ids))
            _wrote([_write_section(text, out_dir / "bench_fast_paths.md", show)], keep and show)
    if getattr(args, "parallel", False):
        from crane_sym.bench.batched_targets import parallel_section
        with say.task("both cores: a batched sweep on 1 and 2 threads, the roofline"):
            _wrote([_write_section(parallel_section(), out_dir / "bench_parallel.md", show)],
                   keep and show)
    if getattr(args, "designs", False):
        from crane_sym.bench import design_targets
        with say.task("(g) 10⁴ designs of a model from components, one block each"):
            text = "\n".join(design_targets.markdown_rows(design_targets.run_rows())) + "\n"
            _wrote([_write_section(text, out_dir / "bench_designs.md", show)], keep and show)
    if args.sweep:
        output_files.out_folder(out_dir)
        with say.task("design sweeps against per-design integration"):
            _wrote([cli_sweep.run_bench(out_dir, args.format == "json")], keep and show)
    if getattr(args, "components", None):
        _wrote([_bench_components(args.components, out_dir, args.format)], keep and show)
    if sections_only:
        return 0
    everything, goals = [], []
    rtols = args.rtols or (bench.QUICK_RTOLS if args.quick else bench.RTOLS)
    sizes = args.sizes or (bt.QUICK_SIZES if args.quick else bt.SIZES)
    compare = args.compare_points or (bt.QUICK_COMPARE_POINTS if args.quick
                                      else bt.COMPARE_POINTS)
    for i in ids:
        found = bench_inputs(i)
        if found is None:
            print(f"{i}: no scene or no generated functions to bench", file=sys.stderr)
            continue
        d, chosen, values, duration = found
        start = time.perf_counter()
        with say.task(f"{i}: generated functions and integrators, {len(rtols)} tolerances"):
            rows = bench.bench(d, values, duration, points=args.points,
                               methods=args.methods or bench.METHODS, rtols=rtols)
        with say.task(f"{i}: throughput on {args.throughput_points} points"):
            big = bench.throughput(d, values, duration, points=args.throughput_points)
        everything += rows + big
        with say.task(f"{i}: against np.cos at {', '.join(f'{n:.0e}' for n in sizes)} points"):
            arrays = bt.array_ratios(d, values, duration, sizes)
            scalars = bt.scalar_call(d, values, duration)
        with say.task(f"{i}: closed form against the best integrator at N = "
                      + ", ".join(map(str, compare))):
            scaled = bt.scaling(d, values, duration, rows, compare)
        goals += bt.goals(i, arrays, scalars, scaled)
        memory_points = 10**6 if args.quick else 10**7
        with say.task(f"{i}: peak memory on {memory_points:.0e} points"):
            memory = bench_memory.function_memory(d, values, duration, memory_points)
        goals += bench_memory.goals(i, memory)
        with say.task(f"{i}: scene modules against the general module"):
            sized = [line for s in chosen
                     for line in bench.scene_comparison(
                         d, s, points=min(args.throughput_points, 200_000))]
        heads = headline(rows)
        skipped = not_applicable(d, rows)
        output_files.out_folder(out_dir)   # made when there is something to write
        md = out_dir / f"bench_{i}.md"
        lines = [f"# Bench: {i}", "",
                 f"Scenes {', '.join(s.name for s in chosen)}; {args.points} seeded times on "
                 f"[0, {duration:g}] s; time-free functions on {args.points} seeded parameter "
                 "sets (each scene value times 2^U(-1, 1)). Absolute times are this machine's "
                 f"({_machine()}); every ratio comes from this one run "
                 f"({time.perf_counter() - start:.0f} s).", "",
                 *[f"- {h}" for h in heads], "",
                 "## Targets", "", bt.goals_table([g for g in goals if g.paper == i]), "",
                 "## Closed form against the best tuned integrator, by number of points",
                 "", bt.scaling_table(scaled), "",
                 "## Against one np.cos over the same array (warm: repeated calls; cold: "
                 "a first call on a fresh array)", "", bt.arrays_table(arrays), "",
                 "Scalar calls (Python floats): " + ", ".join(
                     f"{f} {sec * 1e6:.2f} µs" for f, sec in scalars), "",
                 "## Peak memory of one call (traced NumPy allocations)", "",
                 bench_memory.as_markdown(memory), "",
                 "## Targets that do not apply", "",
                 markdown_table(["function", "target", "why"], skipped), "",
                 "## Scene modules against the general module", "",
                 *[f"- {s}" for s in sized],
                 "", f"## Throughput on {args.throughput_points} points against one np.cos",
                 "", as_markdown(big), "", "## Every function and alternative", "",
                 as_markdown(rows), ""]
        md.write_text("\n".join(lines), encoding="utf-8")
        pngs = plot(rows, out_dir / f"bench_{i}.png",
                    f"{i}: time against error ({args.points} points, this machine)")
        pngs += plot_scaling(scaled, out_dir / f"bench_{i}_points.png",
                             f"{i}: best tuned integrator / closed form against N")
        if args.format == "table":
            print("\n".join(lines[:5 + len(heads)]))
            _wrote([md, *pngs], keep)
    if goals and args.format == "table":
        print("\n## Targets (this run)\n")
        print(bt.goals_table(goals))
    for i in ids:
        if registry.get(i).tabulated:
            output_files.out_folder(out_dir)
            with say.task(f"{i}: piecewise-linear runs against solve_ivp"):
                _wrote([_bench_piecewise(i, out_dir, args.points, args.format == "table")],
                       keep and args.format == "table")
    if args.sampled:
        output_files.out_folder(out_dir)
        with say.task("loads sampled on a grid"):
            _wrote([_bench_sampled(out_dir, args.format == "table")],
                   keep and args.format == "table")
    if args.format == "json":
        print(json.dumps(bench.as_dicts(everything), indent=2))
    return 0


def _write_section(text: str, path: Path, show: bool) -> Path:
    """One bench section written as Markdown into its folder (made if missing),
    and with ``show`` printed; its path."""
    output_files.out_folder(path.parent)
    path.write_text(text, encoding="utf-8")
    if show:
        print(text)
    return path


def _bench_audit(out_dir: Path, show: bool) -> Path:
    """The main job (`audit` of every paper, `generate --check`) in fresh
    processes against its targets, and an audit's time stage by stage."""
    # imported on use: see the module docstring
    from crane_sym.bench import audit_times as at
    say = progress.current()
    start = time.perf_counter()
    with say.task("`crane-sym audit` of every paper in a fresh process"):
        audit = at.command_time(["audit", "--format", "json", "--quiet", "--profile"],
                                at.AUDIT_TARGET)
    with say.task("`crane-sym generate --check` in a fresh process"):
        check = at.command_time(["generate", "--check", "--quiet"], at.CHECK_TARGET)
    with say.task("an audit stage by stage, paper by paper"):
        papers = at.paper_times(registry.ids())
    with say.task("generate's share of each paper stage by stage, in a fresh process"):
        shares = at.share_times(registry.ids())
    text = "\n".join(["# Bench: the main job (audit and generate --check)", "",
                      f"Absolute times are this machine's ({_machine()}, {os.cpu_count()} "
                      f"cores, shared), from this one run ({time.perf_counter() - start:.0f} "
                      "s); the one-minute load average is given with each command.", "",
                      at.as_markdown([audit, check], papers, shares), ""])
    return _write_section(text, out_dir / "bench_audit.md", show)


def _bench_piecewise(i: str, out_dir: Path, points: int, show: bool) -> Path:
    """Piecewise-linear runs in closed form against solve_ivp with events."""
    # imported on use: see the module docstring
    from crane_sym.bench.piecewise import scene_sections
    start = time.perf_counter()
    sections = scene_sections(i, points)
    text = "\n".join([f"# Bench: {i}, piecewise-linear runs against solve_ivp", "",
                      f"Absolute times are this machine's ({_machine()}); every ratio comes "
                      f"from this one run ({time.perf_counter() - start:.0f} s).", "",
                      *sections])
    path = out_dir / f"bench_piecewise_{i}.md"
    path.write_text(text, encoding="utf-8")
    if show:
        print(text)
    return path


def _bench_components(files: Sequence[str], out_dir: Path, form: str) -> Path:
    """Component models from file to run, stage by stage, against item 7's
    targets; the table printed, or with ``form`` "json" the rows as JSON."""
    # imported on use: see the module docstring
    from crane_sym.bench.components import as_dicts, as_markdown, time_model
    from crane_sym.components.reading import read_parts
    for f in files:                    # a bad file fails before the folder is made
        read_parts(f)
    start = time.perf_counter()
    with progress.current().task(f"component models: {len(files)} files, stage by stage"):
        timings = [time_model(f) for f in files]
    text = "\n".join(["# Bench: component models, from the file to the run", "",
                      f"Absolute times are this machine's ({_machine()}), from this one run "
                      f"({time.perf_counter() - start:.0f} s); SymPy's cache and the closed "
                      "forms' cleared before each stage.", "", as_markdown(timings)])
    if form == "json":
        print(json.dumps(as_dicts(timings), indent=2))
    return _write_section(text, out_dir / "bench_components.md", form == "table")


def _bench_sampled(out_dir: Path, show: bool) -> Path:
    """Sampled-load Duhamel responses against the closed forms, and their memory."""
    # imported on use: see the module docstring
    from crane_sym.bench import memory as bench_memory
    from crane_sym.bench.sampled import as_markdown, sampled_comparison
    from crane_sym.bench.sampled_accuracy import accuracy_markdown, sampled_accuracy
    start = time.perf_counter()
    speed, accuracy = as_markdown(sampled_comparison()), accuracy_markdown(sampled_accuracy())
    text = "\n".join([
        "# Bench: loads sampled on a grid (crane_sym.mechanics.sampled_load)", "",
        f"N = 1e5 samples; exact references by mpmath (50 digits). Absolute times are this "
        f"machine's ({_machine()}); ratios come from this one run "
        f"({time.perf_counter() - start:.0f} s).", "", "## Speed against the closed form", "",
        speed, "", "## Accuracy on loads with a closed form", "", accuracy, "",
        "## Peak memory of one call (traced NumPy allocations)", "",
        bench_memory.as_markdown(bench_memory.sampled_memory()), ""])
    path = out_dir / "bench_sampled.md"
    path.write_text(text, encoding="utf-8")
    if show:
        print(text)
    return path
