"""Scene options a paper declares, read and checked when the scene is loaded.

A scene's ``[options]`` table holds what is neither a parameter of a
generated function nor a scene load: the simulated span, a figure to draw, a
simulation-only mass, an integrator. Each paper declares the options its
report reads (``SCENE_OPTIONS`` of its package, a tuple of
:class:`SceneOption`) and the conditions between options and parameters that
its report needs (``SCENE_CHECKS``, a tuple of :class:`SceneCheck`);
``crane_sym.scenes.reading.load_scene`` reads every option by its declaration, refuses
an unknown key, fills the defaults and runs the checks, all before any file
is written. Reports then read ``scene.settings``: validated values, in SI.

An option is one of these kinds:

``bool``
    ``true`` or ``false``.
``int``
    An integer within ``[low, high]``.
``number``
    A plain number within the bounds, in ``unit`` (``largest_reach_m = 30.0``).
``quantity``
    A quantity with a unit (``"800 kg"``), read by ``crane_sym.units`` and
    checked against ``dimension``; the bounds are in SI (``unit``).
``choice``
    One of ``choices`` (strings).
``quantities``
    A list of ``length[0]..length[1]`` quantities, each within the bounds.

Text is parsed by ``crane_sym.units`` (quantities) or compared with the
choices; it is never evaluated.
"""
from __future__ import annotations

import difflib
import math
import numbers
from dataclasses import dataclass
from typing import Any, Callable, Mapping, Sequence

from sympy.physics.units import Dimension
from sympy.physics.units import time as _TIME

from crane_sym import registry, units
from crane_sym.symbols import PhysicalSymbol

__all__ = ["GENERAL_OPTIONS", "KINDS", "REQUIRED", "OptionError", "SceneCheck", "SceneOption",
           "applies", "did_you_mean", "failed_check", "from_symbol", "options_for",
           "read_options"]

KINDS = ("bool", "int", "number", "quantity", "choice", "quantities")


class _Required:
    """The default of an option a scene must give."""

    def __repr__(self) -> str:
        return "REQUIRED"


#: The default of an option without one: the scene must give it.
REQUIRED: Any = _Required()


class OptionError(ValueError):
    """An option that its declaration refuses; the message names it."""


def did_you_mean(key: str, known: Sequence[str]) -> str:
    """``"did you mean 'points'? "`` for a key close to a known one, else ``""``.

    Parameters
    ----------
    key : str
        The unknown key.
    known : sequence of str
        The keys that are known there.
    """
    close = difflib.get_close_matches(key, list(known), n=3, cutoff=0.6)
    return f"did you mean {' or '.join(map(repr, close))}? " if close else ""


@dataclass(frozen=True)
class SceneOption:
    """One option of a scene's ``[options]`` table.

    Attributes
    ----------
    name : str
        The key in ``[options]``.
    kind : str
        One of :data:`KINDS`.
    description : str
        What the option sets, in a few words (named in every message).
    default : object
        The value (as a scene file would write it) used when the scene leaves
        the option out, read like a given one; :data:`REQUIRED` if the scene
        must give it.
    unit : str
        The SI unit of a quantity's bounds, or the unit of a plain number.
    dimension : Dimension, optional
        Of a ``quantity`` or ``quantities`` option.
    low, high : float, optional
        Bounds (SI) of an ``int``, ``number``, ``quantity`` or each of
        ``quantities``; ``low`` excluded when ``above`` is true.
    above : bool
        The value must exceed ``low`` (not merely equal it).
    choices : tuple of str
        Of a ``choice`` option.
    length : (int, int)
        Least and most entries of a ``quantities`` option.
    outputs : tuple of str
        The scenes the option belongs to: those naming one of these outputs;
        empty, every scene of the paper that gives no scene load.
    """

    name: str
    kind: str
    description: str
    default: Any = REQUIRED
    unit: str = ""
    dimension: Dimension | None = None
    low: float | None = None
    high: float | None = None
    above: bool = False
    choices: tuple[str, ...] = ()
    length: tuple[int, int] = (1, 1)
    outputs: tuple[str, ...] = ()

    def __post_init__(self) -> None:
        if self.kind not in KINDS:
            raise ValueError(f"option {self.name!r}: kind must be one of {KINDS}, "
                             f"got {self.kind!r}")
        if self.kind in ("quantity", "quantities") and self.dimension is None:
            raise ValueError(f"option {self.name!r}: a {self.kind} needs a dimension")
        if self.kind == "choice" and not self.choices:
            raise ValueError(f"option {self.name!r}: a choice needs choices")
        if not 0 <= self.length[0] <= self.length[1]:
            raise ValueError(f"option {self.name!r}: length must be (least, most)")

    @property
    def required(self) -> bool:
        """True if the scene must give the option."""
        return self.default is REQUIRED

    def bounds(self) -> str:
        """The bounds as a message states them: ``"in 3..10000"``, ``"> 0 kg"``."""
        unit = f" {self.unit}" if self.unit and self.unit != "1" else ""
        lo, hi = self.low, self.high
        if self.kind == "int":
            return f"in {lo:.0f}..{hi:.0f}" if lo is not None and hi is not None else (
                f">= {lo:.0f}" if lo is not None else f"<= {hi:.0f}" if hi is not None else "")
        if lo is not None and hi is not None:
            return f"in {'(' if self.above else '['}{lo:g}, {hi:g}]{unit}"
        if lo is not None:
            return f"{'>' if self.above else '>='} {lo:g}{unit}"
        return f"<= {hi:g}{unit}" if hi is not None else ""

    def what(self) -> str:
        """What a valid value is, for messages and documentation."""
        bounds = f" {self.bounds()}" if self.bounds() else ""
        if self.kind == "bool":
            return "true or false"
        if self.kind == "int":
            return f"an integer{bounds}"
        if self.kind == "number":
            return f"a number{bounds}"
        if self.kind == "choice":
            return f"one of {', '.join(map(repr, self.choices))}"
        dim = units.describe_dimension(self.dimension)
        if self.kind == "quantity":
            return f"a quantity of {dim}{bounds}"
        least, most = self.length
        count = f"{least}" if least == most else f"{least}..{most}"
        return f"a list of {count} quantities of {dim}, each{bounds}"

    def read(self, raw: Any) -> Any:
        """The value of ``raw`` (as TOML gives it): a bool, an int, a float (SI),
        a str of the choices or a tuple of floats (SI); :class:`OptionError`
        naming the option, what it must be and what was given."""
        if self.kind == "quantities":
            if not isinstance(raw, list) or not self.length[0] <= len(raw) <= self.length[1]:
                raise self._refuse(raw)
            return tuple(self._one(item, raw) for item in raw)
        return self._one(raw, raw)

    def _one(self, raw: Any, given: Any) -> Any:
        if self.kind == "bool":
            if not isinstance(raw, bool):
                raise self._refuse(given)
            return raw
        if self.kind == "choice":
            if not isinstance(raw, str) or raw not in self.choices:
                hint = did_you_mean(raw, self.choices) if isinstance(raw, str) else ""
                raise self._refuse(given, hint)
            return raw
        if self.kind == "int":
            if isinstance(raw, bool) or not isinstance(raw, numbers.Integral):
                raise self._refuse(given)
            value: float = int(raw)
        elif self.kind == "number":
            if isinstance(raw, bool) or not isinstance(raw, numbers.Real) \
                    or not math.isfinite(raw):
                raise self._refuse(given)
            value = float(raw)
        else:
            try:
                value = units.convert(self.name, raw, self.dimension, what="option")
            except units.UnitError as exc:
                raise OptionError(f"[options] {exc}; {self.name} ({self.description}) "
                                  f"must be {self.what()}") from None
        if self.low is not None and (value <= self.low if self.above else value < self.low) \
                or self.high is not None and value > self.high:
            raise self._refuse(given)
        return value

    def _refuse(self, given: Any, hint: str = "") -> OptionError:
        return OptionError(f"[options] {self.name} ({self.description}) must be "
                           f"{self.what()}, got {given!r}" + (f"; {hint.strip()}" if hint
                                                              else ""))


def from_symbol(symbol: PhysicalSymbol, *, default: Any = REQUIRED,
                outputs: tuple[str, ...] = (), kind: str = "quantity",
                length: tuple[int, int] = (1, 1)) -> SceneOption:
    """An option that gives a value of a symbol of the paper (a simulation-only
    mass, a backlash the report runs): its dimension, its description, its
    sign and the range its generated functions serve (``PhysicalSymbol.serves``).

    Parameters
    ----------
    symbol : PhysicalSymbol
        The paper's symbol the option sets.
    default : optional
        The value when the scene leaves the option out (default: the scene must
        give it).
    outputs : tuple of str, optional
        As :attr:`SceneOption.outputs` (empty: every scene of the paper that
        gives no scene load).
    kind : str, optional
        ``quantity`` or ``quantities``.
    length : tuple of int, optional
        Least and most entries of a ``quantities`` option.
    """
    low, high = symbol.serves
    return SceneOption(symbol.name, kind, symbol.description, default, symbol.unit,
                       symbol.dimension, low=low, high=high, length=length, outputs=outputs)


@dataclass(frozen=True)
class SceneCheck:
    """A condition between a scene's options and parameters that its report
    needs (``z_min < z_max``, a payload within the rated one), run on load.

    Attributes
    ----------
    description : str
        The condition in a few words.
    test : callable
        ``test(scene) -> str | None``: ``None`` when the condition holds, else
        one line naming the values that break it (the scene's name is put in
        front). A ``ValueError`` it raises (a generated function refusing the
        scene's values) counts as a failure with its message.
    outputs : tuple of str
        As :attr:`SceneOption.outputs`.
    """

    description: str
    test: Callable[[Any], str | None]
    outputs: tuple[str, ...] = ()


def applies(item: SceneOption | SceneCheck, outputs: Sequence[str], load: str) -> bool:
    """Whether a declared option or check belongs to a scene with these
    ``outputs`` and scene load table ``load`` (``""`` for none)."""
    if item.outputs:
        return any(o in outputs for o in item.outputs)
    return not load


def read_options(raw: Mapping[str, Any], declared: Sequence[SceneOption]) -> dict[str, Any]:
    """Every declared option's value (given, or its default), in declaration
    order; :class:`OptionError` for an unknown key (with a close name), a
    missing required option or a value its declaration refuses."""
    names = [o.name for o in declared]
    for key in raw:
        if key not in names:
            raise OptionError(f"unknown [options] key {key!r}; {did_you_mean(key, names)}"
                              + (f"this scene takes {', '.join(names)}" if names
                                 else "this scene takes no options"))
    values: dict[str, Any] = {}
    for option in declared:
        if option.name in raw:
            values[option.name] = option.read(raw[option.name])
        elif option.required:
            raise OptionError(f"[options] lacks {option.name!r} ({option.description}), "
                              f"{option.what()}")
        else:
            values[option.name] = option.read(option.default)
    return values


#: Most time samples a scene may ask for.
MAX_POINTS = 1_000_000
#: The options of every scene of a derivation with time: its span and samples.
GENERAL_OPTIONS = (
    SceneOption("duration", "quantity", "simulated span", unit="s", dimension=_TIME,
                low=0.0, above=True),
    SceneOption("points", "int", "time samples on [0, duration]", 1001, low=2,
                high=MAX_POINTS),
)


def options_for(derivation: str, outputs: Sequence[str], load: str = "",
                timed: bool = True) -> tuple[SceneOption, ...]:
    """The options a scene of ``derivation`` with these ``outputs`` (and scene
    load table ``load``) takes: :data:`GENERAL_OPTIONS` when the derivation has
    time, its switches (a scene without a load), and what the paper declares
    for such a scene (``SCENE_OPTIONS``)."""
    general = GENERAL_OPTIONS if timed else ()
    switches = () if load else tuple(
        SceneOption(name, "bool", f"{switch.description}; false turns it off", True)
        for name, switch in registry.get(derivation).switches.items())
    taken = [o.name for o in (*general, *switches)]
    declared = tuple(o for o in registry.scene_options(derivation)
                     if applies(o, outputs, load))
    for option in declared:
        if option.name in taken:
            raise OptionError(f"{derivation}: SCENE_OPTIONS declares {option.name!r}, "
                              "which its scenes take already")
    return (*general, *switches, *declared)


def failed_check(scene: Any) -> str | None:
    """The message of the first of the paper's ``SCENE_CHECKS`` that the scene
    (a ``crane_sym.scenes.reading.Scene`` with its settings read) breaks, or None."""
    for check in registry.scene_checks(scene.derivation):
        if applies(check, scene.outputs, scene.load_table):
            try:
                failure = check.test(scene)
            except ValueError as exc:
                failure = str(exc)
            if failure:
                return failure
    return None
