"""What a design sweep of a component file is asked to do, checked.

``crane-sym sweep FILE --vary COMPONENT.FIELD=START:STOP:N[:log] [UNIT] ...
--output LINK.peak|LINK.factor`` sweeps a drive train of the user's own: the
axes are values of its components (:class:`crane_sym.components.design_fields.Field`:
``gearbox_mesh.stiffness``, ``hook.mass``), in the unit the file writes them
unless the argument names another of the same dimension; the outputs are the
largest |load| of each elastic link over the file's run and its dynamic
factor. The arguments are read by the scene sweep's own parsers
(:func:`crane_sym.sweep.spec.parse_vary`, :func:`~crane_sym.sweep.spec.parse_limit`),
so ranges, units and signs are checked the same way; an unknown component or
field, and a value a component refuses at either end of an axis, are a
:class:`SweepError` naming the option. Every output of a drive train depends
on every value of it but the links' ``reference`` (a link's factor on its own):
an axis over another link's reference is refused as an axis no output depends on.
"""
from __future__ import annotations

from functools import partial
from pathlib import Path

from crane_sym import units
from crane_sym.components.designs import OUTPUTS, REACTION, Designs, designs
from crane_sym.components.model import start_load
from crane_sym.components.parts import ComponentError
from crane_sym.scenes.options import did_you_mean
from crane_sym.sweep.plan import Axis, OutputSpec, SweepError, SweepPlan
from crane_sym.sweep.spec import (_VARY, _not_an_argument, display_units, parse_limit,
                                  parse_vary)

__all__ = ["plan_file"]

#: Keys whose unit is the unit a link's load is shown in.
_LOAD_KEYS = ("torque", "force", "reference")


def _axis(text: str, found: Designs) -> Axis:
    """One ``--vary`` over a field of the file."""
    m = _VARY.fullmatch(text.strip())
    name = m.group(1) if m else ""
    model = found.model.name
    if m is not None and "." not in name:
        raise SweepError(f"--vary {text!r}: name a value of a component as COMPONENT.FIELD, "
                         f"e.g. {next(iter(found.fields), 'motor.inertia')}")
    if m is not None:
        component, key = name.split(".")
        if component not in found.entries:
            known = tuple(found.entries)
            raise SweepError(f"--vary {text!r}: no component {component!r} in model "
                             f"{model!r}; {did_you_mean(component, known)}components: "
                             f"{', '.join(known)}")
        if name not in found.fields:
            keys = tuple(f.key for f in found.fields.values() if f.component == component)
            raise SweepError(f"--vary {text!r}: component {component!r} has no value "
                             f"{key!r} to vary; {did_you_mean(key, keys)}it has "
                             f"{', '.join(keys) or 'none'}")
    field = found.fields.get(name)
    axis = parse_vary(text, {name: field.unit if field else "1"}, {name: field})
    if field.sign == "nonzero" and axis.start <= 0 <= axis.stop:
        raise SweepError(f"--vary {text!r}: {name} must not be 0 and the range reaches it")
    for end in (axis.start, axis.stop):
        try:
            found.start(found.design({name: end * axis.to_si}))
        except ComponentError as exc:
            raise SweepError(f"--vary {text!r}: at {end:g} {axis.unit}".rstrip()
                             + f": {exc}") from None
    return axis


def _outputs(found: Designs, names: list[str]) -> tuple[OutputSpec, ...]:
    known = found.outputs()
    specs = []
    for name in names:
        if name not in known:
            raise SweepError(f"--output {name!r}: not an output of component model "
                             f"{found.model.name!r}; known: {', '.join(known)}")
        index, kind, unit = known[name]
        if kind == "reaction":
            specs.append(OutputSpec(name, "component", found.depends(name), unit,
                                    REACTION.format(contact=name.rsplit(".", 1)[0])))
            continue
        if kind == "part":                  # a value a part reports: <part>.<what>.peak
            part, what, _ = name.split(".")
            specs.append(OutputSpec(name, "component", found.depends(name), unit,
                                    f"largest |{what}| of {part} over the run"))
            continue
        link = found.links[index]
        reference = "its reference" if found.model.assembly.links[index].reference \
            is not None else "its load at the start"
        if kind == "factor":
            mode, x0, system = found.start(found.model)
            if start_load(system, mode, x0, index)[1] is None:
                raise SweepError(f"--output {name!r}: the link {link!r} carries no load at "
                                 "the start; give it a reference load in the file "
                                 "(reference = \"...\")")
        summary = OUTPUTS[kind].format(link=link, reference=reference)
        specs.append(OutputSpec(name, "component", found.depends(name), unit, summary))
    if len({s.name for s in specs}) != len(specs):
        raise SweepError(f"--output: an output is given twice in {names}")
    return tuple(specs)


def _file_given(found: Designs, output: OutputSpec) -> set[str]:
    """The units the file writes its loads of ``output``'s dimension in."""
    dimension = units.parse_unit(output.unit)[1]
    return {f.unit for f in found.fields.values() if f.key in _LOAD_KEYS
            and f.text is not None and units.same_dimension(f.dimension, dimension)}


def plan_file(path: str | Path, vary: list[str], outputs: list[str], at: list[str] = (),
              limit: str | None = None) -> SweepPlan:
    """Check a sweep of the component file ``path``.

    Parameters
    ----------
    path : str or Path
        The component TOML file.
    vary : list of str
        ``--vary`` texts over ``COMPONENT.FIELD``.
    outputs : list of str
        ``--output`` names, ``LINK.peak`` or ``LINK.factor``.
    at : list of str, optional
        ``--at`` texts: refused (the outputs are maxima over the run).
    limit : str, optional
        The ``--limit`` text.

    Raises
    ------
    SweepError
        Naming the option and its text.
    ComponentError
        For a file that cannot be read.
    """
    if at:
        raise SweepError(f"--at {at[0]!r}: the outputs of a component file are maxima over "
                         "its run; they take no further value")
    if not vary:
        raise SweepError("--vary: give at least one axis, e.g. --vary "
                         "gearbox_mesh.stiffness=1e4:1e5:10:log")
    if not outputs:
        raise SweepError("--output: give at least one output to sweep, e.g. LINK.peak")
    found = designs(path)
    specs = _outputs(found, list(outputs))
    axes = tuple(_axis(v, found) for v in vary)
    names = [a.name for a in axes]
    if len(set(names)) != len(names):
        raise SweepError(f"--vary: a value is varied twice in {names}")
    for axis in axes:
        if not any(axis.name in s.depends for s in specs):
            raise SweepError(f"--vary {axis.name}: {_not_an_argument(axis.name, specs)}")
    found_limit = parse_limit(limit, specs) if limit else None
    display = display_units(specs, partial(_file_given, found), found_limit)
    if found_limit is not None:
        found_limit = found_limit.shown_in(*display[found_limit.output])
    options = {"duration": found.duration, "component_file": str(Path(path).resolve()),
               "digest": found.digest}
    return SweepPlan(found.model.name, str(path), axes, specs, {}, found_limit, display,
                     options)
