"""Designs of a component file: its model with other values of its parts, and
the peak load and dynamic factor of each elastic link over a block of designs.

A *field* is one value a component's table gives, or may give, named
``<component>.<key>`` with the key the file writes (``gearbox_mesh.stiffness``,
``hook.mass``, ``safety_brakes.delay``). A design sets some fields to values
in SI; each varied component is rebuilt from its table with those values
(through the file's own reader, so every check of the file applies), the
model is assembled anew, and the symbolic derivation is the file's, shared
(:meth:`crane_sym.components.model.Model.with_parts`); a design whose gaps
differ from the file's (a backlash varied from or to zero) takes the
derivation of its own structure, made once
(:class:`~crane_sym.components.templates.Templates`, which a paper's drive
train uses for its own designs too).

The outputs, per elastic link ``L``: ``L.peak``, the largest |load| over the
run from the file's start (N·m, or N between translating bodies), and
``L.factor``, that peak over |reference| (the link's given ``reference``,
else its load at the start): the magnitude of what ``crane-sym run`` prints
as its dynamic factor; of a pendulum also ``L.angle``, its largest sway angle
in rad (its factor: its pull over the load's weight); per value a part reports
(``Acting.outputs``: a DC motor's current, torque, speed),
``<part>.<what>.peak``, its largest |value|. A block of designs is solved
together by the batched solver
(:func:`crane_sym.mechanics.batched_runs.largest_of_runs`: one
:class:`~crane_sym.components.hybrid.ComponentSystem` per design, the closed
forms, events and extrema batched); :meth:`Designs.per_design` is the same
numbers one design at a time by ``Model.run``, each model derived from
scratch, as ``crane-sym run`` does it.
"""
from __future__ import annotations

import hashlib
import math
import tomllib
from pathlib import Path
from typing import Mapping, Sequence

import numpy as np
from sympy.physics.units import time

from crane_sym.components import kinds
from crane_sym.components.hybrid import ComponentSystem
from crane_sym.components.kinds import by_table
from crane_sym.components.model import Model, start_load, started_at_rest
from crane_sym.components.model_limits import first_beyond
from crane_sym.components.templates import Templates, structure
from crane_sym.components.parts import (DIMENSIONS, GROUND, TRANSLATING, UNITS, Component,
                                        ComponentError, Value, value)
from crane_sym.components.pruning import Scope
from crane_sym.components.component_file import read_component_file
from crane_sym.components.design_fields import Field, given, read_entry, si_unit
from crane_sym.mechanics.phase_table import HybridRun, largest
from crane_sym.mechanics.piecewise_linear import MAX_PHASES

__all__ = ["OUTPUTS", "REACTION", "Designs", "Field", "Templates", "designs", "evaluate_block",
           "structure"]

#: The outputs of each elastic link: suffix -> what it is.
OUTPUTS = {"peak": "largest |load| of the elastic link {link} over the run",
           "factor": "dynamic factor of the elastic link {link}: its largest |load| over "
                     "|{reference}|",
           "angle": "largest sway angle of the pendulum {link}: its largest |pull| over "
                    "the load's weight"}
#: The unit of each output but the peak (a load, by the link's motion).
_UNITS = {"factor": "1", "angle": "rad"}
#: The output of each ground contact, ``<contact>.reaction``.
REACTION = "largest reaction of the ground contact {contact} over the run"


class Designs:
    """The designs of one component file (read and derived once)."""

    def __init__(self, path: str | Path) -> None:
        self.path = Path(path)
        text = self.path.read_bytes()
        self.digest = hashlib.sha256(text).hexdigest()
        self.file = read_component_file(self.path)
        self.model = self.file.model
        self.data = tomllib.loads(text.decode("utf-8"))
        self.entries: dict[str, tuple[str, dict]] = {}
        for kind in by_table():
            for entry in self.data.get(kind, []):
                self.entries[entry["name"]] = (kind, entry)
        self.position = {p.name: i for i, p in enumerate(self.model.components)}
        self.links = [l.part.name for l in self.model.assembly.links]
        self.templates = Templates(self.model.name, self.model.title, self.model.scope,
                                   [self.model])
        self.fields = self._fields()
        self._entries_read: dict[str, dict] = {}       # entries read once (:func:`_read`)

    def _fields(self) -> dict[str, Field]:
        a = self.model.assembly
        out = {}
        for name, (kind, entry) in self.entries.items():
            for declared in by_table()[kind].keys:
                key = declared.name
                if declared.value is None or (key in ("torque", "force") and key not in entry):
                    continue
                raw = entry.get(key)
                if (isinstance(raw, str) and raw == "steady") or not declared.acts(entry):
                    continue                 # solved at the start, or without effect
                if isinstance(declared.value, str):     # by the motion of its body
                    body = entry.get("body") or next(
                        (e for e in entry.get("between") or () if e != GROUND), name)
                    own = next((p for p in self.model.components if p.name == name), None)
                    motion = a.bodies[body].motion if body in a.bodies else (  # a span's own
                        getattr(own, "motion", None) or TRANSLATING)
                    dimension = DIMENSIONS[declared.value][motion]
                else:
                    dimension = declared.value
                text = raw if isinstance(raw, str) else None if raw is None else repr(raw)
                out[f"{name}.{key}"] = Field(name, kind, key, text, dimension, declared.sign)
        return out

    def outputs(self) -> dict[str, tuple[int, str, str]]:
        """Output name -> (link index, ``peak`` or ``factor``, SI unit),
        (contact index, ``reaction``, SI unit) for each ground contact, and for
        each value a part reports, ``<part>.<what>.peak`` -> (its index among
        ``Equations.outputs``, ``part``, SI unit)."""
        out = {}
        a = self.model.assembly
        for i, link in enumerate(a.links):
            motion = a.motion(link)
            for kind in OUTPUTS:
                if kind == "angle" and not link.part.reports_angle:
                    continue
                unit = UNITS["load"][motion] if kind == "peak" else _UNITS[kind]
                out[f"{link.part.name}.{kind}"] = (i, kind, unit)
        for j, contact in enumerate(self.model.assembly.contacts):
            motion = self.model.assembly.bodies[contact.part.body].motion
            out[f"{contact.part.name}.reaction"] = (j, "reaction", UNITS["load"][motion])
        bodies = {l.part.name: a.bodies[l.part.body] for l in a.loads}
        for i, (part, what, unit, _) in enumerate(self.model.equations.outputs):
            si = UNITS[unit][bodies[part].motion] if unit in UNITS else unit
            out[f"{part}.{what}.peak"] = (i, "part", si)
        return out

    def depends(self, output: str) -> tuple[str, ...]:
        """The fields an output depends on: every field but the links'
        ``reference`` (only a link's own factor divides by its own)."""
        link, kind = output.rsplit(".", 1)
        return tuple(n for n, f in self.fields.items()
                     if f.key != "reference" or (kind == "factor" and f.component == link))

    def parts(self, values: Mapping[str, float]) -> list:
        """The components with ``values`` (field name -> SI) put in: the
        tables they change built again from the entries read once
        (:func:`~crane_sym.components.design_fields.read_entry`), each value given as a
        :class:`Value` (:func:`~crane_sym.components.design_fields.given`)."""
        parts = list(self.model.components)
        changed: dict[str, dict] = {}
        for name, v in values.items():
            f = self.fields[name]
            if f.component not in changed:
                if f.component not in self._entries_read:
                    self._entries_read[f.component] = read_entry(*self.entries[f.component])
                changed[f.component] = dict(self._entries_read[f.component])
            changed[f.component][f.key] = given(v, f)
        for component, entry in changed.items():
            kind = self.entries[component][0]
            parts[self.position[component]] = by_table()[kind].read(
                entry, f"component model {self.model.name!r}: [[{kind}]] {component!r}")
        return parts

    def design(self, values: Mapping[str, float]) -> Model:
        """The model of one design, its derivation shared with the file's (or
        with the first design of its structure)."""
        return self.templates.design(self.parts(values))

    def start(self, model: Model):
        """(mode, state, system) of a design's run from the file's start."""
        f = self.file
        return model.started(f.body, f.speed, f.rest)

    @property
    def duration(self) -> float:
        """The run's end [s]."""
        return value("run", "duration", self.file.duration, time).si

    def runs(self, output: str, values: Mapping[str, np.ndarray]
             ) -> tuple[tuple[int, ...], list[HybridRun], np.ndarray]:
        """(shape, one run a design with ``output``'s load as its output, each
        link's reference for a factor or an angle, NaN where it has none or
        the output is a peak) of a block
        (``values`` as :meth:`largest` takes them): what the batched solver
        solves together, each design built from its structure's template and
        checked against the bound on its run's periods (ComponentError naming
        the design's values, as a run of the file alone is); from rest, the
        designs' starts found together (``started_at_rest``)."""
        index, kind, _ = self.outputs()[output]
        names = list(values)
        arrays = np.broadcast_arrays(*[np.asarray(values[n], dtype=float) for n in names]) \
            if names else [np.zeros(())]
        shape = arrays[0].shape
        runs, reference = [], np.full(arrays[0].size, np.nan)
        t_end = self.duration
        given = [{n: float(a[at]) for n, a in zip(names, arrays)} for at in np.ndindex(shape)]
        models = [self.design(one) for one in given]
        beyond = first_beyond([model.assembly for model in models], t_end)
        if beyond is not None:
            d, exc = beyond
            values = ", ".join(f"{n} = {v:g} {si_unit(self.fields[n].dimension)}"
                               for n, v in given[d].items())
            raise ComponentError(f"design {values}: {exc}")
        starts = started_at_rest(models) if self.file.rest and \
            self.model.steady_motor is None else [self.start(model) for model in models]
        for k, (model, (mode, x0, system)) in enumerate(zip(models, starts)):
            if kind == "reaction":
                load = system.contact_load(index)
            elif kind == "part":
                load = _reported(system, model, index)
            else:
                load = system.link_load(index)
                if kind != "peak":               # what a factor or an angle divides by
                    ref = start_load(system, mode, x0, index)[1]
                    reference[k] = abs(ref) if ref else np.nan
            runs.append(HybridRun(system, mode, x0, t_end, model.schedule(self.file.rest), load))
        return shape, runs, reference

    def largest(self, output: str, values: Mapping[str, np.ndarray]) -> np.ndarray:
        """``output`` of every design of a block (``values``: field -> SI arrays
        of one shape, or scalars), the designs solved together."""
        from crane_sym.mechanics.batched_runs import largest_of_runs
        kind = self.outputs()[output][1]
        shape, result = self._block(output, values)
        if result is None:
            shape, runs, reference = self.runs(output, values)
            result = largest_of_runs(runs, magnitude=True)
        if result.capped.any():
            k = int(np.flatnonzero(result.capped)[0])
            raise RuntimeError(f"{output}: more than {MAX_PHASES} phases in the run of design {k} "
                               "of a block")
        peak = np.abs(result.value)
        return (peak if kind in ("peak", "reaction", "part") else peak / reference).reshape(shape)

    def _block(self, output: str, values: Mapping[str, np.ndarray]):
        """(shape, the batched result) of a link's peak where the designs
        differ only in values the equations alone read, solved as one block
        (:meth:`plain`; the numbers :meth:`runs` gives, no model a design);
        (shape, None) where they do not."""
        shape, block, solve = self.plain(output, values)
        return shape, None if block is None else solve()

    def plain(self, output: str, values: Mapping[str, np.ndarray]):
        """(shape, the designs of a block as one
        :class:`~crane_sym.components.design_block.DesignBlock` started at
        rest and checked against the bound on periods, ``solve()``: its
        batched result for ``output``) where the output is a link's peak and
        the designs differ only in values the equations alone read; (shape,
        None, None) where not, or where a value breaks its sign (the designs
        built one by one then say which)."""
        from crane_sym.components.design_block import plain_block
        index, kind, _ = self.outputs()[output]
        names = list(values)
        arrays = [a.ravel() for a in np.broadcast_arrays(
            *[np.asarray(values[n], dtype=float) for n in names])] if names else []
        shape = np.broadcast_shapes(*[np.shape(values[n]) for n in names])
        if kind != "peak" or not self.file.rest or not names or \
                not all(_keeps(a, self.fields[n].sign) for n, a in zip(names, arrays)):
            return shape, None, None

        def given(d: int) -> dict[str, float]:
            return {n: float(a[d]) for n, a in zip(names, arrays)}
        model = self.design(given(0))
        block = plain_block(model, {(self.fields[n].component, self.fields[n].key): a
                                    for n, a in zip(names, arrays)})
        if block is None:
            return shape, None, None
        t_end = self.duration
        beyond = block.first_beyond(t_end)
        if beyond is not None:
            d, exc = beyond
            said = ", ".join(f"{n} = {v:g} {si_unit(self.fields[n].dimension)}"
                             for n, v in given(d).items())
            raise ComponentError(f"design {said}: {exc}")

        def build(d: int, mode, x0) -> HybridRun:           # design d's own run
            own = self.design(given(d))
            system = ComponentSystem(own.equations)
            return HybridRun(system, mode, x0, t_end, own.schedule(True),
                             system.link_load(index))
        return shape, block, lambda: block.largest((index,), t_end, build, magnitude=True)

    def per_design(self, output: str, values: Mapping[str, np.ndarray],
                   exact: bool | None = None) -> np.ndarray:
        """:meth:`largest` one design at a time: each design's model derived
        from scratch and run by ``Model.run`` (the reference of the bench and
        the tests); ``exact`` as ``Model.run`` takes it (None: as ``crane-sym
        run`` solves it, SymPy's exact Jordan forms for up to two bodies;
        False: numeric eigenvectors, the cheaper per-design route)."""
        index, kind, _ = self.outputs()[output]
        names = list(values)
        arrays = np.broadcast_arrays(*[np.asarray(values[n], dtype=float) for n in names])
        out = np.empty(arrays[0].shape)
        f = self.file
        for at in np.ndindex(out.shape):
            parts = self.parts({n: float(a[at]) for n, a in zip(names, arrays)})
            run = Model(parts, self.model.name).run(f.duration, f.body, f.speed, exact=exact,
                                                    rest=f.rest)
            if kind == "reaction":
                out[at] = abs(run.reactions[index].value)
                continue
            if kind == "part":
                affine = _reported(run.system, run.model, index)
                out[at] = abs(largest(run.result, run.system, affine, magnitude=True)[1])
                continue
            peak = run.peaks[index]
            out[at] = abs(peak.value) if kind == "peak" else (
                abs(peak.factor) if peak.factor is not None else math.nan)
        return out


def _keeps(values: np.ndarray, sign: str) -> bool:
    """Whether every value is finite and keeps ``sign`` (a field's)."""
    with np.errstate(invalid="ignore"):
        held = {"positive": values > 0, "nonnegative": values >= 0,
                "nonzero": values != 0}.get(sign, True)
    return bool(np.all(np.isfinite(values)) and np.all(held))


def _reported(system: ComponentSystem, model: Model, index: int):
    """The affine map (w, 0) of value ``index`` that a part reports."""
    w = system.first_order.weights(model.equations.outputs[index][3])
    return lambda mode: (w, 0.0)


_CACHE: dict[tuple[str, str], Designs] = {}


def designs(path: str | Path, digest: str | None = None) -> Designs:
    """The :class:`Designs` of a file, read once per process; ComponentError
    if the file is no longer the one with ``digest``.

    Parameters
    ----------
    path : str or Path
        The component file.
    digest : str, optional
        The SHA-256 of its bytes when the sweep was planned.
    """
    resolved = Path(path).resolve()
    current = hashlib.sha256(resolved.read_bytes()).hexdigest()
    if digest is not None and current != digest:
        raise ComponentError(f"{str(path)!r} changed while the sweep ran")
    key = (str(resolved), current)              # an edited file is read anew
    if key not in _CACHE:
        _CACHE[key] = Designs(resolved)
    return _CACHE[key]


#: Blocks solved lately in this process: (file, output, the block's values) -> result.
_SOLVED: dict[tuple, np.ndarray] = {}
#: How many of them are kept.
SOLVED_BLOCKS = 16


def evaluate_block(path: str, digest: str, output: str, values: Mapping[str, np.ndarray],
                   cached: bool = True) -> np.ndarray:
    """One block of a sweep of a component file: ``output`` at every design
    of ``values`` (field name -> SI array), solved together. A sweep that
    writes its dataset asks for each block three times (its summary, the
    PNG's data and the Zarr store do not share the block's task); the last
    :data:`SOLVED_BLOCKS` results are kept in the process and handed out
    again (the same bits: the solve is a function of the file, the output and
    the values alone).

    Parameters
    ----------
    path : str
        The component file.
    digest : str
        Its SHA-256 when planned.
    output : str
        ``<link>.peak`` or ``<link>.factor``.
    values : mapping
        Each varied field's SI values, of one shape.
    cached : bool, optional
        False: solve the block afresh, neither reading nor keeping a result
        (a timed pilot must time the solve, not a look-up of a block a
        sweep before it solved).
    """
    arrays = {n: np.asarray(v, dtype=float) for n, v in values.items()}
    if not cached:
        return designs(path, digest).largest(output, arrays)
    key = (str(path), digest, output,
           tuple((n, a.shape, a.tobytes()) for n, a in sorted(arrays.items())))
    if key not in _SOLVED:
        while len(_SOLVED) >= SOLVED_BLOCKS:
            _SOLVED.pop(next(iter(_SOLVED)))
        _SOLVED[key] = designs(path, digest).largest(output, arrays)
    return _SOLVED[key].copy()

