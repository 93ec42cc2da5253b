"""``crane-sym run FILE`` for a component file (a drive train of the user's own)."""
from __future__ import annotations

import argparse
import json
from pathlib import Path

from crane_sym import progress
from crane_sym.cli.unasked import say_no_files
from crane_sym.escapes import terminal_text

__all__ = ["cmd_run_components"]


def cmd_run_components(args: argparse.Namespace) -> int:
    """Run a component file: print the peak loads and the events, write the
    JSON and the plot into --out."""
    from crane_sym.components.report import run_component_file
    quiet = getattr(args, "quiet", False)
    with progress.reporting(progress.Progress(progress.wanted(quiet))) as say:
        with say.task(f"deriving and running {args.scene}"):
            report = run_component_file(args.scene, Path(args.out) if args.out else None)
    as_json = getattr(args, "format", "text") == "json"
    if as_json:
        from crane_sym.components.report import results
        print(json.dumps(results(report), indent=2, ensure_ascii=False))
    else:
        model = report.run.model
        print(f"model {model.name}: {terminal_text(model.title)}" if model.title
              else f"model {model.name}")
        for line in report.lines:
            print(f"  {line}")
        if args.out:
            print("written: " + ", ".join(str(f) for f in report.files))
    if not args.out:
        say_no_files("--out DIR", "the JSON, the module of its loads and the plot",
                     stderr=as_json)
    return 0


def model_text(path: str) -> str:
    """What ``crane-sym model show FILE`` prints: the components, the rigid
    groups with their referred inertia, the energies, the equations of motion
    in LaTeX, what the modes switch."""
    from crane_sym.components.component_file import read_component_file
    from crane_sym.components.hybrid import ComponentSystem
    import sympy as sp
    model = read_component_file(path).model
    a, eq = model.assembly, model.equations
    lines = [f"model {model.name}" + (f": {terminal_text(model.title)}" if model.title
                                      else ""), "",
             "components:"]
    lines += [f"  {p.label}" for p in model.components]
    lines += [f"  {d.line()}" for d in model.dropped]
    lines += ["", "rigid groups (one coordinate each; body = kappa * coordinate):"]
    for g, q in zip(a.groups, eq.coordinates):
        members = ", ".join(f"{b.name} = {sp.sstr(k)}" for (b, _), k in zip(g.members, g.factors))
        lines.append(f"  {q.func}: {members}; inertia referred {g.inertia:.6g}")
    lines += ["", f"T = {sp.latex(eq.T)}", f"Pi = {sp.latex(eq.V)}",
              f"Phi = {sp.latex(eq.dissipation)}", "",
              "equations of motion (Lagrange, with Rayleigh dissipation):"]
    lines += [f"  {text}" for text in eq.latex()]
    system = ComponentSystem(eq)
    lines += ["", "modes:"]
    lines += [f"  {l.part.label}: {', '.join(l.part.contacts)}" for l in system.backlash]
    parts = system.of_kind
    lines += [f"  {b.part.label} on {b.part.body}: off, engaged" for b in parts["brake"]]
    lines += [f"  {m.part.label}: on, off" for m in parts["motor"] if m.part.off_at is not None]
    lines += [f"  {c.part.label}: {len(c.part.slopes)} steps" for c in parts["characteristic"]]
    lines += [f"  {law.label}: {len(law.pieces())} pieces ({law.law} law)"
              for law in system.laws]
    lines += [f"  {limit.name}: within its limit, at + limit, at - limit"
              for limit in system.limits]
    if eq.states:
        lines += ["", "first-order states (d/dt):"]
        lines += [f"  {sp.sstr(s)}' = {sp.sstr(r)}" for s, r in zip(eq.states, eq.rates)]
    braked = sorted({a.groups[g].name for g in system.brake_group})
    lines += [f"  group {name}: free, sliding +/-, held" for name in braked]
    return "\n".join(lines)


def cmd_model(args: argparse.Namespace) -> int:
    """``crane-sym model show FILE``."""
    print(model_text(args.file))
    return 0


def is_file_argument(name: str) -> bool:
    """A command-line name that means a component file: a TOML path (an existing
    component file, or any ``.toml``, so that a missing one is named as a file)."""
    from crane_sym.components.reading import is_component_file
    return name.endswith(".toml") or is_component_file(name)


def cmd_audit_components(args: argparse.Namespace) -> int:
    """``crane-sym audit FILE ...``: verdicts on the [[formula]] tables of
    component files, in the papers' formats."""
    from crane_sym.audit.formats import FORMATS
    from crane_sym.components.file_audit import audit_file
    from crane_sym.components.component_file import read_component_file
    papers = [n for n in args.ids if not is_file_argument(n)]
    if papers:
        raise ValueError(f"audit: give paper ids or component files, not both "
                         f"({papers[0]!r} is no component file)")
    records = []
    quiet = getattr(args, "quiet", False)
    with progress.reporting(progress.Progress(progress.wanted(quiet))) as say:
        for name in args.ids:
            with say.task(f"auditing the formulas of {name}"):
                records += audit_file(read_component_file(name))
    print(terminal_text(FORMATS[args.format](records)))   # the file's names and formulas
    return 0


def cmd_walkthrough_components(args: argparse.Namespace) -> int:
    """``crane-sym walkthrough FILE``: the derivation of a component model as
    Markdown or a printable HTML page (nothing written on an error)."""
    from crane_sym.cli.handout import deliver_walkthrough
    from crane_sym.docs.drive_train import drive_train_page, drive_train_walkthrough
    if args.format == "ipynb":
        raise ValueError("walkthrough: a component file's walkthrough is Markdown or "
                         "html, not ipynb")
    make = drive_train_page if args.format == "html" else drive_train_walkthrough
    return deliver_walkthrough(args, args.id, make)
