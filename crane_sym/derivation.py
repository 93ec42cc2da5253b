"""The derivation model: steps tied to equation numbers, outputs for codegen.

A derivation is built from physics by a module in ``crane_sym.derivations``;
this module only holds the data types, so every paper shares one shape.
"""
from __future__ import annotations

import time
from dataclasses import dataclass, field
from typing import Any, Callable, Mapping

import sympy as sp

from crane_sym import progress
from crane_sym.published import PrintedItem, PublishedFormula
from crane_sym.sensitivity import Sensitivity
from crane_sym.symbols import PhysicalSymbol, SymbolTable


@dataclass(frozen=True)
class Step:
    """One step of a derivation.

    Parameters
    ----------
    label : str
        The paper's equation number as printed, e.g. ``"(4)"``; for a step the
        paper does not number, a short name such as ``"rigid limit"``.
    statement : sympy.Eq
        What the step establishes.
    how : str
        How it was obtained, in one sentence.
    why : str
        Why the step is taken (for the walkthrough); optional.
    title : str
        A short heading for the walkthrough.
    sensitivity : Sensitivity or None
        For a number of a reconstructed model that needs parameters the paper
        does not state: how far it moves over their plausible ranges.
    """

    label: str
    statement: sp.Eq
    how: str
    why: str = ""
    title: str = ""
    seconds: float = field(default=0.0, compare=False)
    sensitivity: Sensitivity | None = field(default=None, compare=False)

    @property
    def numbered(self) -> bool:
        """True when the label is one of the paper's equation numbers."""
        return self.label.startswith("(")


@dataclass(frozen=True)
class Output:
    """A derived quantity to emit as a generated NumPy function.

    ``args`` fixes the argument order of the generated function; every free
    symbol of ``expr`` must be among them. ``requires`` lists conditions
    between arguments that a sign per argument cannot state, each as
    (expression that must be > 0, the condition in words), e.g.
    (ω0 − ωn, "omega_0 > omega_n"): the generated function refuses the
    arguments that break one, rather than return a NaN.
    """

    name: str
    expr: sp.Expr
    args: tuple[sp.Symbol, ...]
    labels: tuple[str, ...]
    summary: str
    unit: str
    requires: tuple[tuple[sp.Expr, str], ...] = ()

    def __post_init__(self) -> None:
        missing = sorted(str(s) for s in self.expr.free_symbols - set(self.args))
        if missing:
            raise ValueError(
                f"output {self.name}: free symbols {missing} are not arguments "
                f"{[str(a) for a in self.args]}")


@dataclass(frozen=True)
class TabulatedOutput:
    """A response a scene's data decide the shape of, emitted as a table.

    A piecewise-linear run (backlash, brakes that stick) has phases whose
    number and ends depend on the data, so it has no one expression in the
    parameters. A scene fixes the data: ``run(values, settings)`` (SI values by
    name, the scene's settings) returns the ``crane_sym.mechanics.phase_table.HybridRun``,
    whose table (the phases in closed form) the scene's module carries as
    arrays; or a tuple of runs, one per case the scene's settings list (e.g.
    backlash values), and the module carries ``<name>_<k>`` for case k. A
    paper's ``run`` is its hybrid model's (``hybrid.py``,
    ``HybridModel.runner``). ``args`` are the parameters it needs; the
    generated function takes time only.
    """

    name: str
    args: tuple[sp.Symbol, ...]
    labels: tuple[str, ...]
    summary: str
    unit: str
    run: Callable[[Mapping[str, float], Mapping[str, Any]], Any]


@dataclass(frozen=True)
class ODESystem:
    """Equations of motion as a user would hand them to a numerical solver.

    The bench integrates them with SciPy as the alternative to the generated
    closed forms; ``quantities`` maps an output name to the expression, in the
    coordinates and their first derivatives, that the output computes (a name
    that is no output marks a response without a closed form). ``inputs``
    gives the time law of each input symbol of the equations (a load W = W(t),
    say); whoever integrates substitutes it.
    """

    name: str
    equations: tuple[sp.Eq, ...]
    coordinates: tuple[sp.Expr, ...]
    initial: tuple[tuple[sp.Expr, sp.Expr], ...]
    quantities: tuple[tuple[str, sp.Expr], ...]
    inputs: tuple[tuple[sp.Symbol, sp.Expr], ...] = ()


@dataclass(frozen=True)
class Switch:
    """A part of the model a scene can turn off (``[options] <name> = false``).

    Turning it off fixes the parameters in ``off`` (usually to 0) before the
    scene's values are folded in, so the terms they carry vanish from the
    specialized code instead of being evaluated as zeros.
    """

    name: str
    description: str
    off: tuple[tuple[sp.Symbol, sp.Expr], ...]


@dataclass(frozen=True)
class SpecializedLoad:
    """What a scene load becomes for one scene: the functions to print, the
    note for the module header, and the symbols of their arguments."""

    outputs: list[Output]
    note: str
    symbols: SymbolTable


@dataclass(frozen=True)
class SceneLoad:
    """A load a scene gives as data, in a TOML table of its own.

    One more kind of scene input beside parameter values, switches and
    inputs: the scene reader hands the table to ``read``, and the specializer
    hands the validated scene to ``specialize``, which returns the scene's
    functions (e.g. Chovnyuk et al.'s drive law a(t), convolved by Duhamel's
    integral).
    A paper package declares its loads in ``SCENE_LOADS`` (table -> SceneLoad),
    readable without building the derivation.

    Attributes
    ----------
    table : str
        The TOML table, e.g. ``"drive_law"``.
    description : str
        One line: what the load is.
    parameters : tuple of PhysicalSymbol
        What the load's model needs from ``[parameters]`` (all required).
    outputs : tuple of str
        Names of the functions ``specialize`` returns, in order.
    read : callable
        ``read(table, where) -> data``: the table checked and converted (numbers
        by type, units by ``crane_sym.units``); raises ``ValueError`` or
        ``TypeError`` naming the key.
    specialize : callable
        ``specialize(scene) -> SpecializedLoad`` for a ``crane_sym.scenes.reading.Scene``
        whose ``load`` is what ``read`` returned and whose ``parameters`` (SI)
        hold every one of ``parameters``.
    """

    table: str
    description: str
    parameters: tuple[PhysicalSymbol, ...]
    outputs: tuple[str, ...]
    read: Callable[[Mapping[str, Any], str], Any]
    specialize: Callable[[Any], SpecializedLoad]


@dataclass(frozen=True)
class SweepOutput:
    """A response with no closed form that a design sweep can still map over
    its grid: each design simulated with the paper's generated functions.

    A paper package declares them in ``SWEEP_OUTPUTS`` (name -> SweepOutput),
    readable without building the derivation.

    Attributes
    ----------
    name, unit, summary : str
        As for an :class:`Output`; ``unit`` is the SI unit of the result.
    parameters : tuple of str
        Scene ``[parameters]`` the response depends on.
    options : tuple of str
        Values the scene gives in ``[options]`` with units (symbols of the
        derivation) that the response also depends on; they can be swept too.
    evaluate : callable
        ``evaluate(values, options) -> ndarray``: ``values`` maps every name of
        ``parameters + options`` to an SI array (all of one shape, or scalars),
        ``options`` is the scene's ``[options]`` (duration in s, points); one
        simulation per design, the result of the broadcast shape.
    batched : bool
        True where ``evaluate`` solves all the designs of a block together
        (a batched hybrid solver), so a sweep gives it blocks as large as its
        workers allow instead of many small ones.
    threads : bool or tuple of str
        True where such a block spends its time in NumPy calls on whole
        arrays (which release the GIL), not in Python per design: a sweep
        runs its blocks on threads, each of ``thread_block`` designs (fewer,
        larger blocks: a block's Python per phase is paid once for more
        designs). A tuple of names: so only where every swept parameter is
        one of them (others swept, the block builds each design in Python).
        False (a block that assembles or switches each design in Python):
        processes, as for any simulated output.
    thread_block : tuple of int, optional
        (fewest, most) designs of a block on threads: the fewest where the
        block's fixed cost is paid off, the most its memory allows (None:
        ``crane_sym.sweep.blocks.THREAD_DESIGNS`` and ``THREAD_MAX_DESIGNS``).
    cap : int or None
        The most phases a design's run may take (a chattering contact):
        ``evaluate`` gives NaN for a design stopped there, and the sweep
        flags it in its dataset (``<name>_capped``), states the cap and
        counts such designs in its summary; None where runs are not capped.
    """

    name: str
    unit: str
    summary: str
    parameters: tuple[str, ...]
    options: tuple[str, ...]
    evaluate: Callable[[Mapping[str, Any], Mapping[str, Any]], Any]
    batched: bool = False
    threads: bool | tuple[str, ...] = False
    cap: int | None = None
    thread_block: tuple[int, int] | None = None


@dataclass
class Derivation:
    """A paper rebuilt from its equations of motion.

    Attributes
    ----------
    id : str
        Registry id, also the name of the generated module.
    paper : str
        File name of the source paper.
    title, citation : str
        What the paper is.
    model : str
        The mechanical model in a few sentences (walkthrough introduction).
    symbols : SymbolTable
        Every symbol with dimension, unit, role and sampling range.
    steps : list of Step
        In the paper's order.
    published : list of PublishedFormula
        The paper's formulas, transcribed as printed.
    printed_items : list of PrintedItem
        The inventory of the print (numbered equations, table cells, numbers
        stated as results), each naming the records that judge it: the audit's
        recall counts these.
    outputs : list of Output
        What ``crane-sym generate`` emits.
    tabulated : list of TabulatedOutput
        Responses a scene's module carries as tables (scene outputs only).
    ode_systems : list of ODESystem
        The equations of motion in solver-ready form, for the bench.
    switches : dict of str to Switch
        Parts of the model a scene may turn off.
    bench_parameters : dict of Symbol to Expr
        Values the bench gives to arguments no scene of the derivation sets:
        numbers (SI) or expressions in the scene parameters.
    latex_names : dict of Symbol to str
        The LaTeX the paper uses for symbols whose SymPy name differs
        (``Q_at0`` is printed ``Q(0)``): audit details and walkthroughs use it.
    code : bool
        False for a build without the parts only code and the bench read
        (outputs, tabulated outputs, ODE systems, switches, bench
        parameters): what the audit builds (``registry.get(..., code=False)``).
    """

    id: str
    paper: str
    title: str
    citation: str
    model: str
    symbols: SymbolTable
    steps: list[Step] = field(default_factory=list)
    published: list[PublishedFormula] = field(default_factory=list)
    printed_items: list[PrintedItem] = field(default_factory=list)
    outputs: list[Output] = field(default_factory=list)
    tabulated: list[TabulatedOutput] = field(default_factory=list)
    ode_systems: list[ODESystem] = field(default_factory=list)
    switches: dict[str, Switch] = field(default_factory=dict)
    bench_parameters: dict[sp.Symbol, sp.Expr] = field(default_factory=dict)
    latex_names: dict[sp.Basic, str] = field(default_factory=dict)
    code: bool = True
    _clock: float = field(default_factory=time.perf_counter, repr=False, compare=False)

    def step(self, label: str) -> Step:
        """The step with this label."""
        for step in self.steps:
            if step.label == label:
                return step
        raise KeyError(f"{self.id}: no step labelled {label!r}")

    def output(self, name: str) -> Output:
        """The output with this function name."""
        for out in self.outputs:
            if out.name == name:
                return out
        raise KeyError(f"{self.id}: no output named {name!r}")

    def add(self, label: str, statement: sp.Eq, how: str, why: str = "",
            title: str = "", sensitivity: Sensitivity | None = None) -> sp.Eq:
        """Append a step and return its statement, so a derivation reads
        ``eq4 = d.add("(4)", ..., how="...")``. The step records the time
        spent since the previous one (``crane-sym audit --profile``); a number
        of a model with chosen parameters carries its ``sensitivity``."""
        if any(s.label == label for s in self.steps):
            raise ValueError(f"{self.id}: step {label!r} added twice")
        now = time.perf_counter()
        self.steps.append(Step(label, statement, how, why, title, now - self._clock,
                               sensitivity))
        self._clock = now
        progress.current().step(f"{self.id}: step {label} done")
        return statement
