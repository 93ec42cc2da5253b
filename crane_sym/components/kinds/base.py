"""What a kind of component declares, once: the table a component file gives
it in, its keys (how each is written, the kind of value it holds, the sign a
sweep must keep, its default), how its part is built from them, and what the
assembly, the equations and the reports ask of it (:class:`Kind`).

A key's ``form`` says how the file writes it:

============ ==============================================================
``quantity`` text with its unit (``"4e4 N*m/rad"``)
``number``   a bare number, or text with a unit (dimensionless: a ratio)
``word``     text: a name, or one of the kind's choices
``body``     text: the name of a body the part joins or acts on
``list``     a list of quantities as text (``["0.4 s", "0.8 s"]``)
``law``      numbers only, never text, checked by the law's own reader
``ends``     the two body names a link joins (one may be ``"ground"``, fixed)
``terms``    a table of body names, each with its factor (a number, or text
             with a unit): a point that moves as a linear combination of the
             bodies' coordinates (a span's end, ``{ drum = "250 mm", hub = -1 }``)
============ ==============================================================

A key's ``value`` is a kind of value (a key of
:data:`crane_sym.components.parts.VALUE_KINDS`, its dimension by the body's
motion) or a fixed dimension; a key without one is not a value a design sweep
varies (:mod:`crane_sym.components.designs`).
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Any, Callable

import sympy as sp
from sympy.physics.units import Dimension, length, time

from crane_sym.components.kinds.events import Events
from crane_sym.components.kinds.roles import (ROLE_FLAGS, Check, PartQuantity, ends_moving,
                                              has_role)
from crane_sym.components.loads import HENRY, OHM
from crane_sym.components.parts import VALUE_KINDS, Component, ComponentError, Value

__all__ = ["FIXED_UNITS", "FORMS", "ROLES", "ROLE_FLAGS", "Acting", "Check", "Coupling", "Factor",
           "Key", "Kind", "PartQuantity", "Symbolic", "ends_moving", "failure", "has_role",
           "load_key", "run_end"]

FORMS = ("quantity", "number", "word", "body", "list", "law", "ends", "terms")
#: The signs a swept value may be bound to keep ("": either).
SIGNS = ("positive", "nonnegative", "nonzero", "")


@dataclass(frozen=True)
class Key:
    """One key of a kind's table (see the module docstring)."""

    name: str
    form: str = "quantity"
    value: str | Dimension | None = None
    sign: str = ""
    required: bool = True
    default: Any = None
    #: Whether the key's value acts, given its table (a step brake has no
    #: build-up time); None: always.
    when: Callable[[dict], bool] | None = None

    def __post_init__(self) -> None:
        if self.form not in FORMS:
            raise ValueError(f"key {self.name!r}: form must be one of {FORMS}, got {self.form!r}")
        if self.sign not in SIGNS:
            raise ValueError(f"key {self.name!r}: sign must be one of {SIGNS}, got {self.sign!r}")
        if isinstance(self.value, str) and self.value not in VALUE_KINDS:
            raise ValueError(f"key {self.name!r}: value must be one of {tuple(VALUE_KINDS)} "
                             f"or a Dimension, got {self.value!r}")

    def acts(self, entry: dict) -> bool:
        """Whether this key's value acts in the table ``entry`` (a sweep varies
        only values that do)."""
        return self.when is None or self.when(entry)

    def given(self, v: Any, where: str) -> Any:
        """``v`` as the file gives it, checked against the key's form (text, or
        a bare number only where it is dimensionless); ComponentError naming
        the key otherwise."""
        if self.form == "law":
            return v
        if self.form == "ends":
            if not (isinstance(v, list) and len(v) == 2 and all(isinstance(e, str) for e in v)):
                raise ComponentError(f"{where}: {self.name} must be two body names, got {v!r}")
            return v
        if self.form == "terms":
            if not (isinstance(v, dict) and all(
                    isinstance(f, str) or (isinstance(f, (int, float)) and not isinstance(f, bool))
                    for f in v.values())):
                raise ComponentError(f"{where}: {self.name} must be a table of body names and "
                                     f"factors, e.g. {self.name} = {{ drum = \"250 mm\", "
                                     f"hub = -1 }}, got {v!r}")
            return v
        if self.form == "list":
            if not isinstance(v, list) or not all(isinstance(x, str) for x in v):
                raise ComponentError(f"{where}: {self.name} must be a list of values with "
                                     f"their units as text, e.g. [\"0.4 s\", \"0.8 s\"], "
                                     f"got {v!r}")
            return v
        if self.form in ("word", "body"):
            if not isinstance(v, str):
                raise ComponentError(f"{where}: {self.name} must be text, got {v!r}")
            return v
        if self.form == "number" and isinstance(v, (int, float)) and not isinstance(v, bool):
            return v
        if self.form == "quantity" and isinstance(v, Value):      # read already (a design's)
            return v
        if not isinstance(v, str):
            raise ComponentError(f"{where}: {self.name} needs a value with its unit as text, "
                                 f"e.g. {self.name} = \"0.1 s\", got {v!r}")
        return v


#: The SI unit of each fixed dimension a key may hold.
FIXED_UNITS = {Dimension(1): "1", length: "m", 1 / length: "1/m", time: "s",
               length / time**2: "m/s^2",
               OHM: "ohm", HENRY: "H"}


@dataclass(frozen=True)
class Symbolic:
    """A value of a part that the equations hold as a symbol
    ``<letter>_<component>`` (``c_coupling``), with ``assumption``
    (``positive``, ``nonnegative`` or ``real``). ``key`` is the table's key it
    comes from (``torque`` is named ``force`` on a translating body); ``value``
    takes it in SI from the assembled item (the body, the rigid part, the
    ``topology.Link`` or ``topology.Load``; None: solved at the start);
    ``what`` says what it is, formatted with ``name``, ``body`` and ``key``;
    ``equations_only``: the value is read by nothing but the equations and
    what is derived from their values (the link's load, the run's bound on
    periods), so designs that differ only in it are one block of arrays
    (:mod:`crane_sym.components.design_block`)."""

    key: str
    letter: str
    assumption: str
    value: Callable[[Any], "float | None"]
    what: str
    equations_only: bool = False

    def symbol(self, component: str) -> sp.Symbol:
        """Its symbol for the component called ``component`` (made once: every
        design of a sweep asks for it)."""
        key = (self.letter, component, self.assumption)
        if key not in _SYMBOLS:
            _SYMBOLS[key] = sp.Symbol(f"{self.letter}_{component}", **{self.assumption: True})
        return _SYMBOLS[key]


#: The symbols :meth:`Symbolic.symbol` made, by (letter, component, assumption).
_SYMBOLS: dict[tuple[str, str, str], sp.Symbol] = {}


#: The lists of a mode's symbols a part acting on a body may join (fields of
#: :class:`crane_sym.components.equations.Equations`): a motor's switch and
#: torque, a brake's friction, a characteristic's slope, a law's value.
ROLES = ("switches", "motor_loads", "friction", "slopes", "signals")


@dataclass(frozen=True)
class Acting:
    """What a part acting on one body adds to the generalized force: its force
    ``force`` along the body's coordinate (None: an acceleration law, which
    drives the rigid drive instead), the mode's symbols it brings as
    ``(role, symbol)`` (a role of :data:`ROLES`), whether the force is
    ``constant`` in time (a weight, a resistance, a motor: what an
    acceleration law's rigid drive balances), its first-order ``states``
    with their rates (the force may hold them; a state two parts declare
    takes the sum of their rates) and the ``limits`` on them."""

    force: sp.Expr | None
    joins: tuple[tuple[str, sp.Symbol], ...] = ()
    constant: bool = False
    #: The part's first-order states, (s, ds/dt) each: the rate affine in the
    #: bodies' speeds q̇, the states and the signals (a DC motor's current).
    states: tuple[tuple[sp.Symbol, sp.Expr], ...] = ()
    #: Its limits, (s, bound, z) each: the state s kept within ±bound (an
    #: expression in the parameters); at a bound, the state z tracks
    #: (:mod:`crane_sym.components.first_order`: a torque limit holds the
    #: current, the controller's integral follows).
    limits: tuple[tuple[sp.Symbol, sp.Expr, sp.Symbol], ...] = ()
    #: What a run reports of it, (what, unit, value) each: the unit a row of
    #: :data:`~crane_sym.components.parts.UNITS` (by its body's motion) or a
    #: unit's text; the value affine in q, q̇ and the states (a DC motor's
    #: current, torque and speed), its peak printed.
    outputs: tuple[tuple[str, str, sp.Expr], ...] = ()


#: The :class:`Acting` of a part on its body, given the body's κ and its
#: group's coordinate q(t).
Acts = Callable[[Component, sp.Expr, sp.Expr], Acting]


#: The values of a part that switch the model rather than enter its equations,
#: given the part and its body's motion: (key, SI value, dimension, SI unit,
#: what it is) each, for a [[formula]] to name.
Switching = Callable[[Component, str], "tuple[tuple[str, float, Dimension, str, str], ...]"]


#: Why a part does nothing over a run of ``duration`` seconds (from rest when
#: ``rest``), so the run may drop it; None when it may act.
Idle = Callable[[Component, float, bool], "str | None"]

#: Builds a kind's part from its keys as given (the optional ones not given at
#: their defaults), the table as written, and where it is (for messages).
Builder = Callable[[dict[str, Any], dict, str], Component]


@dataclass(frozen=True)
class Factor:
    """A value of a coupling's share of the energies that is not a
    :class:`Symbolic` of its kind (a span's factor): its parameter's name
    after the part's (``end.drum``), its symbol, its SI value, its dimension
    and what it is."""

    key: str
    symbol: sp.Symbol
    value: float
    dimension: Dimension
    what: str


@dataclass(frozen=True)
class Coupling:
    """What a part that joins several coordinates by its own energies (a
    span: :mod:`crane_sym.components.kinds.span`) gives the toolkit:
    ``bodies(part)``, the names of the bodies it joins; ``check(part,
    bodies)``, its values against those bodies (their motion, its factors'
    dimensions; ComponentError, one line); ``energies(part, where)``, its
    share (T, Π, Φ) of the energies, given each body's (κ, q(t));
    ``factors(part, bodies)``, each :class:`Factor` of that share;
    ``stretch(part, where, bodies)``, for a part that reports its load, its
    stretch u in the coordinates, what its load is (``force``, ``torque``)
    and its SI unit; the
    toolkit derives from its energies, ∂Π/∂u + ∂Φ/∂u̇
    (:mod:`crane_sym.components.coupling_loads`)."""

    bodies: Callable[[Component], tuple[str, ...]]
    check: Callable[[Component, dict], None]
    energies: Callable[[Component, dict], tuple[sp.Expr, sp.Expr, sp.Expr]]
    factors: Callable[[Component, dict], "tuple[Factor, ...]"]
    stretch: Callable[[Component, dict, dict], tuple[sp.Expr, str, str]] | None = None


@dataclass(frozen=True)
class Kind:
    """A kind of component: its ``table`` (``[[table]]`` in a component file),
    its ``keys`` (the required ones first), how its part is built, one line
    saying what it is, how messages name its parts (``label``, default the
    table: ``Component.kind``), when a run may drop one (``idle``; None:
    never), the values its equations hold as symbols (``symbols``), what
    its derivation rests on beside them (``shape``), for a part acting on
    one body its share of Q (``acts``), the values that switch the model
    (``switching``), and for a part that joins several coordinates by its
    own energies its :class:`Coupling` (``couples``); then its ``check``
    against its bodies' motion, its ``roles`` (:data:`ROLE_FLAGS`), for a
    rigid link its symbolic factor (``rigid``), the slopes its mode steps
    (``steps``), the count of the model's bounds it joins (``counted``) and
    the quantities its parts report (``quantities``); and how its parts
    switch the model (``events``)."""

    table: str
    keys: tuple[Key, ...]
    build: Builder
    text: str
    label: str = ""
    idle: Idle | None = None
    symbols: tuple[Symbolic, ...] = ()
    #: What the derivation of a part rests on beside its values (whether a
    #: link has a gap); None: nothing.
    shape: Callable[[Component], Any] | None = None
    #: What a part that acts on one body adds to Q (None: it joins bodies).
    acts: Acts | None = None
    #: The values that switch the model rather than enter its equations.
    switching: Switching | None = None
    #: A link's stiffness in the parts' symbols, given the part (None: its
    #: own ``c_<name>``; a pendulum's m g/L).
    stiffness: Callable[[Component], sp.Expr] | None = None
    #: For a part that joins several coordinates by its own T, Π and Φ.
    couples: Coupling | None = None
    # declared for reading, loads and reports
    #: Its values against its bodies' motion (ComponentError, one line): for a
    #: part acting on one body (``acts``) its Load, in SI; for a rigid link,
    #: None once its bodies' motions fit.
    check: Check | None = None
    #: What the assembly asks of a part, given the part: a subset of
    #: :data:`ROLE_FLAGS` (a brake holds its group at rest; a speed law sets it).
    roles: Callable[[Component], frozenset[str]] | None = None
    #: For a rigid link (a gear, a drum): the κ of its second end per unit of
    #: its first in its symbols (1/i, r/n); its parts merge rigid groups.
    rigid: Callable[[Component], sp.Expr] | None = None
    #: For a part whose slope its mode steps (a characteristic's β): the slopes
    #: in SI, given its Load.
    steps: Callable[[Any], tuple[float, ...]] | None = None
    #: The count of :mod:`crane_sym.components.model_limits` its parts join
    #: (``bodies``, ``links``, ``brakes``; "": none).
    counted: str = ""
    #: The quantities its parts report beyond a body's, a link's and a
    #: contact's (a DC motor's time constant), each a :class:`PartQuantity`.
    quantities: tuple[PartQuantity, ...] = ()
    # declared for modes and events
    #: How its parts switch the model: the mode's values they own, their
    #: events, guards and rules (:class:`~crane_sym.components.kinds.events.Events`;
    #: None: they switch nothing).
    events: Events | None = None

    @property
    def part_kind(self) -> str:
        """What its parts' ``kind`` is (``elastic link`` for ``[[elastic]]``)."""
        return self.label or self.table

    @property
    def required(self) -> tuple[str, ...]:
        return tuple(k.name for k in self.keys if k.required)

    @property
    def optional(self) -> tuple[str, ...]:
        return tuple(k.name for k in self.keys if not k.required)

    @property
    def places(self) -> tuple[Key, ...]:
        """The keys that name the bodies a part joins or acts on (a span's
        points)."""
        return tuple(k for k in self.keys if k.form in ("body", "ends", "terms"))

    def key(self, name: str) -> Key:
        """The key called ``name``; KeyError if the kind has none."""
        for k in self.keys:
            if k.name == name:
                return k
        raise KeyError(name)

    def read(self, entry: dict, where: str) -> Component:
        """The part of one table ``entry`` whose keys are known and complete
        (the reader checks that first): each key as given, then the part."""
        forms = {k.name: k for k in self.keys}
        ordered = [k for k in entry if forms[k].form != "ends"] + \
                  [k for k in entry if forms[k].form == "ends"]
        given = {k.name: k.default for k in self.keys if not k.required}
        given.update({k: forms[k].given(entry[k], where) for k in ordered})
        return self.build(given, entry, where)


def load_key(entry: dict, where: str, optional: bool = False) -> str | None:
    """Which of ``torque`` (on a rotating body) and ``force`` (on a translating
    one) ``entry`` gives: one, not both; None only if ``optional``.

    Parameters
    ----------
    entry : dict
        A table of a component file.
    where : str
        The table, as messages name it.
    optional : bool
        Whether giving neither is allowed.
    """
    given = [k for k in ("torque", "force") if k in entry]
    if len(given) > 1:
        raise ComponentError(f"{where}: give torque or force, not both")
    if not given and not optional:
        raise ComponentError(f"{where}: lacks 'torque' (on a rotating body) or 'force' "
                             "(on a translating one)")
    return given[0] if given else None


def failure(part: Component, what: str) -> tuple:
    """The switching value of a part that fails (``fails_at``, s), or none."""
    t = getattr(part, "fails_at", None)
    return () if t is None else (("fails_at", t, time, "s", f"instant {what} fails"),)


def run_end(duration: float) -> str:
    """How an ``idle`` reason names the run's end."""
    return f"the run ends at {duration:g} s"
