"""The ``crane-sym`` command line."""
from __future__ import annotations

import argparse
import json
import sys
import time
from pathlib import Path
from typing import Sequence

from . import registry


def _ids(names: Sequence[str]) -> list[str]:
    return [registry.resolve(n) for n in names] if names else registry.ids()


def cmd_list(args: argparse.Namespace) -> int:
    rows = [{"id": i, "paper": registry.module(i).PAPER, "title": registry.module(i).TITLE}
            for i in registry.ids()]
    if args.format == "json":
        print(json.dumps(rows, indent=2, ensure_ascii=False))
    else:
        for row in rows:
            print(f"{row['id']:<18} {row['paper']:<28} {row['title']}")
    return 0


def cmd_audit(args: argparse.Namespace) -> int:
    from .audit import audit
    from .report import FORMATS
    records, timings = [], []
    for i in _ids(args.ids):
        start = time.perf_counter()
        d = registry.get(i)
        built = time.perf_counter()
        records += audit(d)
        timings.append((i, built - start, time.perf_counter() - built))
    print(FORMATS[args.format](records))
    if args.profile:
        for i, b, a in timings:
            print(f"{i}: build {b:.2f} s, audit {a:.2f} s; slowest steps:", file=sys.stderr)
            steps = sorted(registry.get(i).steps, key=lambda s: -s.seconds)[:5]
            for s in steps:
                print(f"    {s.seconds:7.3f} s  {s.label}", file=sys.stderr)
    return 0


def cmd_walkthrough(args: argparse.Namespace) -> int:
    from .walkthrough import walkthrough
    text = walkthrough(registry.resolve(args.id))
    if args.output:
        Path(args.output).write_text(text, encoding="utf-8")
        print(f"wrote {args.output}")
    else:
        print(text)
    return 0


def cmd_generate(args: argparse.Namespace) -> int:
    from . import codegen, specialize
    from .generate import all_files
    if args.scene:
        directory = Path(args.out or ".")
        files = specialize.scene_files(args.scene)
    else:
        directory = Path(args.out) if args.out else codegen.default_directory()
        files = all_files()
    if args.check:
        bad = codegen.stale(files, directory)
        for name in bad:
            print(f"stale: {directory / name} differs from what the derivations produce")
        if bad:
            print("run `crane-sym generate` and commit generated/", file=sys.stderr)
            return 1
        print(f"generated/ is up to date ({len(files)} files in {directory})")
        return 0
    for path in codegen.write(files, directory):
        print(f"wrote {path}")
    return 0


def cmd_accuracy(args: argparse.Namespace) -> int:
    import importlib

    from .reference import accuracy
    # cond.·u: condition number times 2**-53 at the worst point (the error input
    # rounding alone causes); over target: largest error / max(1e-15, 2 cond.·u).
    print(f"{'function':<34} {'hard case':<40} {'points':>6} {'cond.·u':>9} "
          f"{'over target':>11}  max rel. error vs mpmath (50 digits)")
    for i in _ids(args.ids):
        cases = getattr(registry.module(i), "hard_cases", None)
        if cases is None:
            print(f"{i}: no hard cases defined")
            continue
        d = registry.get(i)
        generated = importlib.import_module(f"crane_sym.generated.{i}")
        for case, columns in cases().items():
            for out in (o for o in d.outputs if not o.expr.is_Matrix):
                row = accuracy(out, getattr(generated, out.name), case, columns)
                print(f"{out.name:<34} {case:<40} {row.points:>6} {row.bound:9.2e} "
                      f"{row.excess:11.2f}  {row.max_rel_error:.2e}")
    return 0


def _machine() -> str:
    import platform

    import numpy
    import scipy
    return (f"{platform.machine()} {platform.processor() or platform.system()}, "
            f"Python {platform.python_version()}, NumPy {numpy.__version__}, "
            f"SciPy {scipy.__version__}")


def cmd_bench(args: argparse.Namespace) -> int:
    from . import bench, scenes
    from .bench_report import as_markdown, headline, not_applicable, plot
    out_dir = Path(args.out)
    out_dir.mkdir(parents=True, exist_ok=True)
    everything = []
    for i in _ids(args.ids):
        chosen = [s for s in map(scenes.load_scene, scenes.list_scenes())
                  if s.derivation == i and not s.load_table and "duration" in s.options]
        d = registry.get(i)
        if not chosen or not d.outputs:
            print(f"{i}: no scene or no generated functions to bench", file=sys.stderr)
            continue
        values = bench.grid_values(d, chosen)
        duration = max(s.options["duration"] for s in chosen)
        start = time.perf_counter()
        rows = bench.bench(d, values, duration, points=args.points,
                           methods=args.methods or bench.METHODS,
                           rtols=args.rtols or bench.RTOLS)
        big = bench.throughput(d, values, duration, points=args.throughput_points)
        everything += rows + big
        sized = [line for s in chosen
                 for line in bench.scene_comparison(
                     d, s, points=min(args.throughput_points, 200_000))]
        heads = headline(rows)
        skipped = not_applicable(d, rows)
        md = out_dir / f"bench_{i}.md"
        lines = [f"# Bench: {i}", "",
                 f"Scenes {', '.join(s.name for s in chosen)}; {args.points} seeded times on "
                 f"[0, {duration:g}] s; time-free functions on {args.points} seeded parameter "
                 "sets (each scene value times 2^U(-1, 1)). Absolute times are this machine's "
                 f"({_machine()}); every ratio comes from this one run "
                 f"({time.perf_counter() - start:.0f} s).", "",
                 *[f"- {h}" for h in heads], "",
                 "## Targets that do not apply", "",
                 "| function | target | why |", "| --- | --- | --- |",
                 *[f"| {f} | {what} | {why} |" for f, what, why in skipped], "",
                 "## Scene modules against the general module", "",
                 *[f"- {s}" for s in sized],
                 "", f"## Throughput on {args.throughput_points} points against one np.cos",
                 "", as_markdown(big), "", "## Every function and alternative", "",
                 as_markdown(rows), ""]
        md.write_text("\n".join(lines), encoding="utf-8")
        png = plot(rows, out_dir / f"bench_{i}.png",
                   f"{i}: time against error ({args.points} points, this machine)")
        if args.format == "table":
            print("\n".join(lines[:5 + len(heads)]))
            print(f"wrote {md} and {png}")
    if args.sampled:
        _bench_sampled(out_dir, args.format == "table")
    if args.format == "json":
        print(json.dumps(bench.as_dicts(everything), indent=2))
    return 0


def _bench_sampled(out_dir: Path, show: bool) -> None:
    """Sampled-load Duhamel responses against the closed forms (issue 5, item 5)."""
    from .bench_sampled import accuracy_markdown, as_markdown, sampled_accuracy, \
        sampled_comparison
    start = time.perf_counter()
    speed, accuracy = as_markdown(sampled_comparison()), accuracy_markdown(sampled_accuracy())
    text = "\n".join([
        "# Bench: loads sampled on a grid (crane_sym.sampled_load)", "",
        f"N = 1e5 samples; exact references by mpmath (50 digits). Absolute times are this "
        f"machine's ({_machine()}); ratios come from this one run "
        f"({time.perf_counter() - start:.0f} s).", "", "## Speed against the closed form", "",
        speed, "", "## Accuracy on loads with a closed form", "", accuracy, ""])
    path = out_dir / "bench_sampled.md"
    path.write_text(text, encoding="utf-8")
    if show:
        print(text)
        print(f"wrote {path}")


def cmd_run(args: argparse.Namespace) -> int:
    from .scene_run import run_scene
    from .scenes import load_scene
    scene = load_scene(args.scene)
    report, figure = run_scene(scene, Path(args.out))
    print(f"scene {scene.name}: {scene.title}")
    for line in report.lines:
        print(f"  {line}")
    print(f"plot written to {figure}")
    return 0


def parser() -> argparse.ArgumentParser:
    """The argument parser (exposed for documentation and tests)."""
    top = argparse.ArgumentParser(prog="crane-sym", description=__doc__)
    sub = top.add_subparsers(dest="command", required=True)
    p = sub.add_parser("list", help="registered derivations")
    p.add_argument("--format", choices=("table", "json"), default="table")
    p.set_defaults(func=cmd_list)
    p = sub.add_parser("audit", help="verdict on every published formula")
    p.add_argument("ids", nargs="*", help="derivation ids or paper numbers (default: all)")
    p.add_argument("--format", choices=("table", "json", "markdown"), default="table")
    p.add_argument("--profile", action="store_true", help="time per derivation on stderr")
    p.set_defaults(func=cmd_audit)
    p = sub.add_parser("walkthrough", help="step-by-step derivation as Markdown")
    p.add_argument("id")
    p.add_argument("-o", "--output", help="write to this file instead of stdout")
    p.set_defaults(func=cmd_walkthrough)
    p = sub.add_parser("generate", help="write generated/ (or --check it)")
    p.add_argument("--check", action="store_true", help="exit 1 if generated/ is stale")
    p.add_argument("--out", help="folder to write to (default: the package's generated/, "
                   "or . with --scene)")
    p.add_argument("--scene", help="write only the module specialized to this scene "
                   "(name or TOML path)")
    p.set_defaults(func=cmd_generate)
    p = sub.add_parser("accuracy", help="generated functions vs mpmath on the hard cases")
    p.add_argument("ids", nargs="*", help="derivation ids or paper numbers (default: all)")
    p.set_defaults(func=cmd_accuracy)
    p = sub.add_parser("bench", help="speed against error, with SciPy alternatives")
    p.add_argument("ids", nargs="*", help="derivation ids or paper numbers (default: all)")
    p.add_argument("--format", choices=("table", "json"), default="table")
    p.add_argument("--out", default="bench", help="folder for Markdown and PNG (default: bench/)")
    p.add_argument("--points", type=int, default=2000, help="grid points for the comparison")
    p.add_argument("--throughput-points", type=int, default=10**6,
                   help="array length for the large-array np.cos comparison")
    p.add_argument("--methods", nargs="+", choices=("RK45", "DOP853", "LSODA", "Radau", "BDF"),
                   help="solve_ivp methods (default: RK45 DOP853 LSODA Radau; odeint "
                   "always runs)")
    p.add_argument("--sampled", action="store_true",
                   help="also bench loads sampled on a grid against the closed forms")
    p.add_argument("--rtols", nargs="+", type=float,
                   help="integrator and quadrature tolerances (default: 1e-3 1e-6 1e-9 1e-12)")
    p.set_defaults(func=cmd_bench)
    p = sub.add_parser("run", help="run a scene: print its results, write its plot")
    p.add_argument("scene", help="scene name or path to a scene TOML file")
    p.add_argument("--out", default=".", help="folder for the scene module and the plot "
                   "(default: .)")
    p.set_defaults(func=cmd_run)
    return top


def main(argv: Sequence[str] | None = None) -> int:
    args = parser().parse_args(argv)
    try:
        return args.func(args)
    except (KeyError, ValueError) as err:
        message = err.args[0] if isinstance(err, KeyError) and err.args else err
        print(f"crane-sym: error: {message}", file=sys.stderr)
        return 2
