"""The crane-sym command line: one function per subcommand, and the parser.

A subcommand imports its machinery when it runs (the imports inside the
functions below): importing every subcommand's at start-up costs 1.31 s of
CPU against 0.59 s for the command line alone (median of 5 whole-process runs),
and `crane-sym --help` or `crane-sym list` need none of it.
"""
from __future__ import annotations

import argparse
import json
import signal
import sys
import threading
from importlib import metadata
from pathlib import Path
from typing import Sequence

from crane_sym import __version__, output_files, progress, registry
from crane_sym.cli import sweep as cli_sweep
from crane_sym.escapes import terminal_text
from crane_sym.cli.bench import cmd_bench
from crane_sym.cli.sigterm import TERMINATED, TERMINATED_CODE, Terminated, terminate
from crane_sym.cli.unasked import say_no_files

DESCRIPTION = """\
Derive, audit and generate code for the dynamics of crane mechanisms.

For each published paper crane-sym rebuilds the derivation with SymPy, checks
every printed formula against it, writes fast NumPy modules, and runs scenes
(one concrete question with its data, in TOML). Papers are named by id
or by the number of their source file: `crane-sym list` names them,
`crane-sym list --scenes` the scenes shipped with them."""

_PAPERS = "Papers by id or number: `crane-sym list` names them."
_SCENES = ("A scene by name (`crane-sym list --scenes` names the shipped ones)\n"
           "or by the path of a TOML file.")
#: Where the names an example uses come from, shown after it.
_FILES = ("\nA drive train of your own: its component TOML file (README, \"Your own "
          "drive train\").")
#: Where a component file to start from is (the repository's examples folder:
#: files to copy and edit, not installed with the package).
_EXAMPLES = ("\nA drive train of your own: its component TOML file (the repository's "
             "examples/drive_trains/ holds examples to copy).")
NAMES = {"audit": _PAPERS + _FILES, "walkthrough": _PAPERS + _FILES, "accuracy": _PAPERS,
         "bench": _PAPERS,
         "generate": _SCENES, "sweep": _SCENES,
         "run": _SCENES + _EXAMPLES,
         "model": _EXAMPLES.strip()}


def _ids(names: Sequence[str]) -> list[str]:
    return [registry.resolve(n) for n in names] if names else registry.ids()


def version() -> str:
    """The installed version of crane_sym (package metadata), or the source's."""
    try:
        return metadata.version("crane_sym")
    except metadata.PackageNotFoundError:
        return __version__


def _progress(args: argparse.Namespace) -> progress.Progress:
    """A reporter for this command: on when stderr is a terminal and not --quiet."""
    return progress.Progress(progress.wanted(getattr(args, "quiet", False)))


def cmd_list(args: argparse.Namespace) -> int:
    """Registered papers: id, number, authors, title; with ``--scenes``, the
    shipped scenes: name, paper id, title."""
    if args.scenes:
        return _list_scenes(args.format)
    numbers = {i: n for n, i in registry.ALIASES.items()}
    rows = []
    for i in registry.ids():
        paper = registry.module(i)
        rows.append({"id": i, "number": numbers.get(i, ""), "authors": list(paper.AUTHORS),
                     "title": paper.TITLE, "paper": paper.PAPER})
    if args.format == "json":
        print(json.dumps(rows, indent=2, ensure_ascii=False))
    else:
        for row in rows:
            print(f"{row['id']:<16} {row['number']:<4} {', '.join(row['authors'])}\n"
                  f"{'':<21} {row['title']}")
    return 0


def _list_scenes(form: str) -> int:
    """The shipped scenes, each with the paper it belongs to and its title."""
    from crane_sym.scenes.reading import list_scenes, read_toml, scene_path
    rows = []
    for name in list_scenes():
        head = read_toml(scene_path(name))["scene"]
        rows.append({"name": name, "derivation": head["derivation"], "title": head["title"]})
    if form == "json":
        print(json.dumps(rows, indent=2, ensure_ascii=False))
    else:
        for row in rows:
            print(f"{row['name']:<24} {row['derivation']:<16} {row['title']}")
    return 0


def _processes(text: str) -> int:
    """``--processes``: an integer in 1..64 (argparse prints the message, exit 2)."""
    if not text.isdigit() or not 1 <= int(text) <= 64:
        raise argparse.ArgumentTypeError(f"must be an integer in 1..64, got {text!r}")
    return int(text)


def cmd_audit(args: argparse.Namespace) -> int:
    """Verdicts on the printed formulas of the chosen papers (or on the
    [[formula]] tables of component files)."""
    from crane_sym.cli.components import cmd_audit_components, is_file_argument
    if any(is_file_argument(n) for n in args.ids):
        return cmd_audit_components(args)
    # imported on use: see the module docstring
    from crane_sym.audit.formats import FORMATS
    from crane_sym.audit.papers import audit_papers, schedule_text, workers
    ids = _ids(args.ids)
    processes = args.processes or workers(len(ids))
    reporter = _progress(args)
    with progress.reporting(reporter):
        audited = audit_papers(ids, processes)
    print(FORMATS[args.format]([r for a in audited for r in a.records]))
    recall = "\n".join(a.recall.text() for a in audited)
    recall = (f"\nRecall of the print (every numbered equation, table cell and number "
              f"stated as a result):\n{recall}")
    if args.format == "json":       # stdout stays the record list; recall is progress
        reporter.say(recall)
    else:
        print(recall)
    fresh = sum(a.parsed_fresh for a in audited)
    if fresh:
        print(f"machine reading: {fresh} printed sides parsed afresh, not from the committed "
              "table generated/machine_reading.json (`crane-sym generate` adds them)",
              file=sys.stderr)
    if args.profile:
        for a in audited:
            print(f"{a.paper}: build {a.build:.2f} s, audit {a.audit:.2f} s; slowest steps:",
                  file=sys.stderr)
            for seconds, label in a.slowest:
                print(f"    {seconds:7.3f} s  {label}", file=sys.stderr)
        slots = [a.slot for a in audited if a.slot is not None]
        print("schedule: " + schedule_text(slots).replace("\n", "\nschedule: "),
              file=sys.stderr)
    return 0


def cmd_walkthrough(args: argparse.Namespace) -> int:
    """The derivation step by step, as Markdown, a Jupyter notebook or a printable
    HTML page (a component file: the derivation of its model)."""
    from crane_sym.cli.components import cmd_walkthrough_components, is_file_argument
    if is_file_argument(args.id):
        return cmd_walkthrough_components(args)
    # imported on use: see the module docstring
    from crane_sym.cli.handout import deliver_walkthrough
    from crane_sym.docs.page import handout_page
    from crane_sym.docs.notebook import notebook
    from crane_sym.docs.walkthrough import walkthrough
    name = registry.resolve(args.id)
    make = {"ipynb": notebook, "html": handout_page}.get(args.format, walkthrough)
    return deliver_walkthrough(args, name, make)


def cmd_generate(args: argparse.Namespace) -> int:
    """Write generated/ (or one scene's module), or check that it is fresh."""
    # imported on use: see the module docstring
    from crane_sym.codegen import files as module_files
    from crane_sym.scenes import specialize
    from crane_sym.scenes.generate import all_files
    if args.scene and not args.out and not args.check:
        with progress.reporting(_progress(args)):
            files = specialize.scene_files(args.scene)
        for text in files.values():
            print(text, end="")
        say_no_files("--out DIR", "the module to a file", stderr=True)
        return 0
    if args.scene:
        directory = Path(args.out or ".")
    else:
        directory = Path(args.out) if args.out else module_files.default_directory()
    if not args.check:
        output_files.check_folder(directory)
    with progress.reporting(_progress(args)):
        files = specialize.scene_files(args.scene) if args.scene else all_files()
    if args.check:
        found = module_files.compare(files, directory, strays=not args.scene)
        for name in found.missing:
            print(f"missing: {directory / name} is not there")
        for name in found.differs:
            print(f"stale: {directory / name} differs from what the derivations produce")
        for name in found.stray:
            print(f"stray: {directory / name} is not produced by any derivation or scene")
        if not found.ok:
            print(f"{len(found.missing)} missing, {len(found.differs)} stale, "
                  f"{len(found.stray)} stray; run `crane-sym generate` (delete stray "
                  "files) and commit generated/", file=sys.stderr)
            return 1
        print(f"{directory} is up to date ({len(files)} files)")
        return 0
    for path in module_files.write(files, directory):
        print(f"wrote {path}")
    return 0


def cmd_accuracy(args: argparse.Namespace) -> int:
    """Generated functions against mpmath on the hard cases; exit 1 when one
    is over its target."""
    # imported on use: see the module docstring
    import importlib

    from crane_sym.bench.accuracy import accuracy
    ids = _ids(args.ids)                     # an unknown id fails before any output
    # cond.·u: condition number times 2**-53 at the worst point (the error input
    # rounding alone causes); over target: largest error / max(1e-15, 2 cond.·u).
    print(f"{'function':<34} {'hard case':<40} {'points':>6} {'cond.·u':>9} "
          f"{'over target':>11}  max rel. error vs mpmath (50 digits)")
    checked, over = 0, []
    with progress.reporting(_progress(args)) as say:
        for i in ids:
            cases = getattr(registry.module(i), "hard_cases", None)
            if cases is None:
                print(f"{i}: no hard cases defined")
                continue
            with say.task(f"building {i}"):
                d = registry.get(i)
            generated = importlib.import_module(f"crane_sym.generated.{i}")
            for case, columns in cases().items():
                for out in (o for o in d.outputs if not o.expr.is_Matrix):
                    say.step(f"{i}: {out.name} on {case}")
                    row = accuracy(out, getattr(generated, out.name), case, columns)
                    say.done()                  # the step line off the screen first
                    checked += 1
                    if not row.excess <= 1:
                        over.append(f"{out.name} ({case})")
                    print(f"{out.name:<34} {case:<40} {row.points:>6} {row.bound:9.2e} "
                          f"{row.excess:11.2f}  {row.max_rel_error:.2e}")
    if over:
        print(f"FAIL: {len(over)} of {checked} function/case pairs over target: "
              + ", ".join(over))
        return 1
    print(f"PASS: all {checked} function/case pairs within target")
    return 0


def cmd_run(args: argparse.Namespace) -> int:
    """Run one scene: print its numbers, write its module and plots (a
    component file: its peak loads and events, a JSON and a plot)."""
    # imported on use: see the module docstring
    from crane_sym.components.reading import is_component_file
    if is_component_file(args.scene):
        from crane_sym.cli.components import cmd_run_components
        return cmd_run_components(args)
    from crane_sym.scenes.run import run_scene
    from crane_sym.scenes.reading import load_scene
    from crane_sym.scenes.specialize import module_name
    with progress.reporting(_progress(args)) as say:
        with say.task(f"reading scene {args.scene}"):
            scene = load_scene(args.scene)
        report, figures = run_scene(scene, Path(args.out) if args.out else None)
    if args.format == "json":
        from crane_sym.scenes.results import scene_results
        files = [Path(args.out) / module_name(scene), *figures] if args.out else []
        print(json.dumps(scene_results(scene, report, files), indent=2, ensure_ascii=False))
    else:
        print(f"scene {scene.name}: {terminal_text(scene.title)}")
        for line in report.lines:
            print(f"  {line}")
        if args.out:
            print(f"{len(figures)} plot{'s' if len(figures) > 1 else ''} written: "
                  + ", ".join(str(f) for f in figures))
    if not args.out:
        say_no_files("--out DIR", "the scene's module and its plots",
                     stderr=args.format == "json")
    return 0


def _cmd_model(args: argparse.Namespace) -> int:
    """Show a component model (``crane_sym.cli.components``)."""
    from crane_sym.cli.components import cmd_model
    return cmd_model(args)


def _subcommand(sub, name: str, text: str, func, quiet: bool = False):
    """A subcommand with ``text`` as help and description, its example as the
    epilog, and (for the long commands) ``--quiet``."""
    p = sub.add_parser(name, help=text, description=text[0].upper() + text[1:] + ".",
                       epilog=("examples:" if "\n" in registry.EXAMPLES[name] else "example:")
                       + "\n  " + registry.EXAMPLES[name]
                       + (f"\n\n{NAMES[name]}" if name in NAMES else ""),
                       formatter_class=argparse.RawDescriptionHelpFormatter)
    if quiet:
        p.add_argument("-q", "--quiet", action="store_true", default=argparse.SUPPRESS,
                       help="no progress on stderr (progress is shown only on a terminal)")
    p.set_defaults(func=func)
    return p


def parser() -> argparse.ArgumentParser:
    """The argument parser (exposed for documentation and tests)."""
    top = argparse.ArgumentParser(
        prog="crane-sym", description=DESCRIPTION,
        epilog="example:\n  " + registry.EXAMPLES["audit"].split("\n")[0]
               + "\n\nRun `crane-sym COMMAND --help` for "
               "the options and an example of each command.",
        formatter_class=argparse.RawDescriptionHelpFormatter)
    top.add_argument("--version", action="version", version=f"crane-sym {version()}")
    top.add_argument("-q", "--quiet", action="store_true",
                     help="no progress on stderr (progress is shown only on a terminal)")
    sub = top.add_subparsers(dest="command", required=True, metavar="COMMAND")
    ids_help = "derivation ids or paper numbers (default: all)"
    p = _subcommand(sub, "list", "registered papers: id, number, authors, title", cmd_list)
    p.add_argument("--scenes", action="store_true",
                   help="the shipped scenes instead: name, paper id, title")
    p.add_argument("--format", choices=("table", "json"), default="table")
    p = _subcommand(sub, "audit", "verdict on every published formula", cmd_audit, True)
    p.add_argument("ids", nargs="*", help=ids_help + "; or component TOML files: their "
                   "[[formula]] tables")
    p.add_argument("--format", choices=("table", "json", "markdown"), default="table")
    p.add_argument("--profile", action="store_true", help="time per derivation on stderr")
    p.add_argument("--processes", type=_processes, metavar="N",
                   help="papers audited in N processes at once (default: one a core, at most "
                        "one a paper; 1: all in this process)")
    p = _subcommand(sub, "walkthrough", "step-by-step derivation as Markdown, a notebook "
                    "or a printable page", cmd_walkthrough, True)
    p.add_argument("id", help="derivation id or paper number, or a component TOML file")
    p.add_argument("--format", choices=("markdown", "ipynb", "html"), default="markdown",
                   help="ipynb: a Jupyter notebook with a code cell per step; html: one "
                   "self-contained page (math as MathML, the first scene's figures, "
                   "contents) to print or post")
    p.add_argument("-o", "--output", help="write to this file instead of stdout")
    p = _subcommand(sub, "generate", "write generated/ (or check that it is up to date)",
                    cmd_generate, True)
    p.add_argument("--check", action="store_true", help="write nothing; name the missing, "
                   "stale and stray files; exit 1 if there are any")
    p.add_argument("--out", help="folder to write to or check (default: the package's "
                   "generated/; with --scene: print the module, or check it in .)")
    p.add_argument("--scene", help="write only the module specialized to this scene "
                   "(name or TOML path)")
    p = _subcommand(sub, "accuracy", "generated functions against mpmath on the hard cases; "
                    "exit 1 if one is over its target", cmd_accuracy, True)
    p.add_argument("ids", nargs="*", help=ids_help)
    p = _subcommand(sub, "bench", "speed against error, with SciPy alternatives", cmd_bench,
                    True)
    p.add_argument("ids", nargs="*", help=ids_help)
    p.add_argument("--format", choices=("table", "json"), default="table")
    p.add_argument("--out", help="folder for the Markdown and PNG files (default: none "
                   "written, the tables printed)")
    p.add_argument("--points", type=int, default=2000, help="grid points for the comparison (2 to 1e7)")
    p.add_argument("--throughput-points", type=int, default=10**6,
                   help="array length for the large-array np.cos comparison (1 to 1e8)")
    p.add_argument("--methods", nargs="+", choices=("RK45", "DOP853", "LSODA", "Radau", "BDF"),
                   help="solve_ivp methods (default: RK45 DOP853 LSODA Radau; odeint "
                   "always runs)")
    p.add_argument("--quick", action="store_true",
                   help="fewer tolerances (1e-6 1e-9 1e-12), arrays of 1e4 and 1e5 points, "
                   "the integrator comparison at 100 and 2000 points")
    p.add_argument("--sizes", nargs="+", type=int,
                   help="array lengths for the targets against np.cos, each 1 to 1e8 "
                   "(default: 1e4 1e5 1e6 1e7)")
    p.add_argument("--compare-points", nargs="+", type=int,
                   help="numbers of points at which the closed form meets the best tuned "
                   "integrator, each 2 to 1e7 (default: 100 2000 100000)")
    p.add_argument("--sampled", action="store_true",
                   help="also bench loads sampled on a grid against the closed forms")
    p.add_argument("--audit", action="store_true",
                   help="bench the main job: `audit` of every paper and `generate --check`, "
                        "each in a fresh process, against their targets, and an audit's "
                        "time paper by paper and stage by stage")
    p.add_argument("--fast-paths", action="store_true",
                   help="bench the fast-path targets alone: each time function against "
                   "np.cos at 1e5 points (with the hand-written floor) and its peak memory "
                   "on 1e6, met / not met")
    p.add_argument("--parallel", action="store_true",
                   help="bench both cores alone: a batched sweep on 2 threads against the "
                   "same blocks on one, with a roofline (memory bandwidth, np.sin, np.add) "
                   "and a scaling curve of 1..16 workers, met / not met and why")
    p.add_argument("--designs", action="store_true",
                   help="bench section (g) of --sweep alone: 10^4 designs of a model from "
                   "components (003's start-up, a 5-body file) as a sweep runs them, met / not "
                   "met, and where the time goes")
    p.add_argument("--sweep", action="store_true", help="bench design sweeps (Dask) against "
                   "per-design integration; alone, only that")
    p.add_argument("--components", nargs="+", metavar="FILE",
                   help="bench component model files: where the time goes from the file to "
                   "the run, against item 7's targets; alone, only that")
    p.add_argument("--rtols", nargs="+", type=float,
                   help="integrator tolerances, each 1e-13 to 0.1 (default: every half "
                   "decade 1e-6 ... 1e-13)")
    p = _subcommand(sub, "run", "run a scene: print its results, write its module and plots",
                    cmd_run, True)
    p.add_argument("scene", help="scene name or path to a scene TOML file, or a component "
                   "model TOML file (a [model] table; README, \"Your own drive train\")")
    p.add_argument("--out", help="folder for the scene module and the plots (a component "
                   "file: its JSON, module and plot); without it nothing is written")
    p.add_argument("--format", choices=("text", "json"), default="text",
                   help="text (default) or JSON on stdout: every result with its unit, the "
                   "warnings as a list")
    p = _subcommand(sub, "model", "a component model: its parts, rigid groups, equations "
                    "of motion and modes", _cmd_model)
    p.add_argument("action", choices=("show",))
    p.add_argument("file", help="component model TOML file (a [model] table)")
    p = _subcommand(sub, "sweep", "a design sweep: outputs over a grid of designs, on Dask",
                    cli_sweep.cmd_sweep, True)
    cli_sweep.add_arguments(p)
    return top


def _os_message(err: OSError) -> str:
    """One line for an operating-system error: the path and why."""
    if isinstance(err, output_files.OutputError):
        return str(err)
    where = f"{err.filename!r}: " if err.filename else ""
    return f"{where}{output_files.describe(err)}"


def _input_names(args: argparse.Namespace) -> list[str]:
    """The names a command reads (papers, scenes, component files): a write
    never replaces one of them (:func:`crane_sym.output_files.inputs`)."""
    names: list[str] = []
    for key in ("id", "ids", "scene", "file", "components"):
        value = getattr(args, key, None)
        names += [value] if isinstance(value, str) else list(value or ())
    return names


def main(argv: Sequence[str] | None = None) -> int:
    """Run the command line; return the exit code: 0 done, 1 a check failed
    (``generate --check``, ``accuracy``), 2 an error (one line on stderr),
    130 interrupted (SIGINT), 143 terminated (SIGTERM).

    Parameters
    ----------
    argv : sequence of str, optional
        The arguments after ``crane-sym`` (default: ``sys.argv[1:]``).
    """
    previous = None
    if threading.current_thread() is threading.main_thread():
        previous = signal.signal(signal.SIGTERM, terminate)
    try:
        args = parser().parse_args(argv)
        with output_files.inputs(_input_names(args)):
            return args.func(args)
    except (KeyError, ValueError) as err:
        message = err.args[0] if isinstance(err, KeyError) and err.args else err
        print(f"crane-sym: error: {message}", file=sys.stderr)
        return 2
    except OSError as err:
        print(f"crane-sym: error: {_os_message(err)}", file=sys.stderr)
        return 2
    except KeyboardInterrupt:
        print("crane-sym: interrupted (SIGINT); nothing half-written is left", file=sys.stderr)
        return 130
    except Terminated:
        print(TERMINATED, file=sys.stderr)
        return TERMINATED_CODE
    finally:
        if previous is not None:
            signal.signal(signal.SIGTERM, previous)
