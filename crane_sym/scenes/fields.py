"""The fields of a scene file, each read and checked: its outputs, inputs,
parameters (units, sign, the range the generated functions serve), switches,
required tables and known keys. A failure is a :class:`SceneError` naming the
scene and the field.
"""
from __future__ import annotations

from typing import Any, Sequence

from crane_sym import units
from crane_sym.scenes.options import did_you_mean
from crane_sym.symbols import PhysicalSymbol

__all__ = ["SceneError", "known_keys", "read_inputs", "read_outputs", "read_parameters",
           "required_table", "switches_off", "toml_reason"]


class SceneError(ValueError):
    """A scene file that cannot be read or does not fit its derivation."""


def toml_reason(err: Exception) -> str:
    """Why a TOML file could not be read, in one line: the parser's first line,
    or for values nested past Python's recursion limit (``x = [[[[…]]]]``
    5000 deep), that bound.

    Parameters
    ----------
    err : Exception
        What ``tomllib.loads`` (or the decoding before it) raised.
    """
    import sys
    if isinstance(err, RecursionError):
        return (f"arrays or tables nested too deep (the reader's limit is below "
                f"{sys.getrecursionlimit()})")
    return (str(err).splitlines() or [type(err).__name__])[0]


def read_outputs(raw: Any, known: list[str], owner: str, where: str) -> list[str]:
    """``[scene] outputs``: a non-empty list of known names, none twice."""
    if not isinstance(raw, list) or not raw or not all(isinstance(o, str) for o in raw):
        raise SceneError(f"{where}: outputs must be a non-empty list of names")
    for out in raw:
        if out not in known:
            raise SceneError(f"{where}: unknown output {out!r} of {owner!r}; "
                             f"known: {', '.join(known)}")
    if len(set(raw)) != len(raw):
        raise SceneError(f"{where}: an output is listed twice in {raw}")
    return list(raw)


def read_parameters(raw: dict[str, Any], entries: list[PhysicalSymbol],
                needed: list[PhysicalSymbol], owner: str, where: str) -> dict[str, float]:
    """``[parameters]`` in SI: every name known, every needed one given, each of
    the right dimension, of the sign its symbol admits and within the range
    its generated functions serve (``PhysicalSymbol.serves``)."""
    names = [e.name for e in entries]
    for key in raw:
        if key not in names:
            raise SceneError(f"{where}: unknown parameter {key!r}; {did_you_mean(key, names)}"
                             f"{owner!r} takes {', '.join(names)}")
    parameters: dict[str, float] = {}
    for entry in entries:
        if entry.name not in raw:
            if entry in needed:
                raise SceneError(f"{where}: parameter {entry.name!r} ({entry.description}, "
                                 f"{entry.unit}) is missing")
            continue
        try:
            value = units.convert(entry.name, raw[entry.name], entry.dimension)
        except units.UnitError as exc:
            raise SceneError(f"{where}: {exc}") from None
        bound = {"positive": (value > 0, "> 0"), "nonnegative": (value >= 0, ">= 0")}
        ok, text = bound.get(entry.sign, (True, ""))
        if not ok:
            raise SceneError(f"{where}: parameter {entry.name!r} ({entry.description}) "
                             f"must be {text}, got {raw[entry.name]!r}")
        low, high = entry.serves
        if not low <= value <= high:
            raise SceneError(f"{where}: parameter {entry.name!r} ({entry.description}) must "
                             f"be within [{low:g}, {high:g}] {entry.unit} (the range its "
                             f"generated functions serve), got {raw[entry.name]!r}")
        parameters[entry.name] = value
    return parameters


def switches_off(derivation, options: dict[str, Any], where: str) -> tuple[str, ...]:
    """Names of the derivation's switches the options turn off (true/false only)."""
    off = []
    for name, switch in derivation.switches.items():
        if name in options:
            if not isinstance(options[name], bool):
                raise SceneError(f"{where}: [options] {name} ({switch.description}) must be "
                                 f"true or false, got {options[name]!r}")
            if not options[name]:
                off.append(name)
    return tuple(off)


def read_inputs(raw: Any, takes: set[str], where: str) -> tuple[str, ...]:
    """``[scene] inputs``: parameters of the outputs left as arguments."""
    if not isinstance(raw, list) or not all(isinstance(x, str) for x in raw):
        raise SceneError(f"{where}: inputs must be a list of parameter names")
    for name in raw:
        if name not in takes:
            raise SceneError(f"{where}: input {name!r} is not a parameter of the scene's "
                             f"outputs ({', '.join(sorted(takes))})")
    return tuple(raw)


def required_table(data: dict[str, Any], key: str, where: str) -> dict[str, Any]:
    value = data.get(key)
    if not isinstance(value, dict):
        raise SceneError(f"{where}: missing table [{key}]")
    return value


def known_keys(table: dict[str, Any], known: Sequence[str], what: str, where: str) -> None:
    """SceneError for the first key of ``table`` that is not ``known``, with
    the known names close to it."""
    for key in table:
        if key not in known:
            raise SceneError(f"{where}: unknown {what} {key!r}; {did_you_mean(key, known)}"
                             f"expected {', '.join(known)}")
