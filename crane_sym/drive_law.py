"""A user's piecewise-polynomial drive law and the rope response of the hoist.

The model is the two-mass hoist of paper 002 (derivation ``hoist_startup``):
drive m1 and load m2 on a rope of stiffness C, stretch :math:`x = x_1 - x_2`,

.. math::

    \\ddot x + \\Omega^2 x = S(t), \\qquad
    S(t) = \\frac{P(t)}{m_1} + \\frac{Q(t)}{m_2}, \\qquad
    P(t) = (m_1 + m_2)\\, a(t) + m_2 g                     \\quad (2), (28)-(31)

with :math:`Q = m_2 g` when lifting "from weight" (31) and
:math:`Q = m_2 g \\min(t/\\tau_0, 1)`, :math:`\\tau_0 = m_2 g/(C v_0)`, when
lifting "with pick-up" (28)-(29), :math:`v_0` the speed the law ends at. The
law :math:`a(t)` is given by numbers only (:func:`drive_law`); the stretch
follows by Duhamel's integral (15)-(24), once, symbolically, piece by piece
(``duhamel.duhamel``), the dynamic coefficient by (25)-(27), and
``render_drive_law_module`` prints them as NumPy functions of time only.

A drive-law scene (``derivations/scenes/hoist_user_drive_law.toml``) has the
tables ``[scene]`` (name, derivation = "hoist_startup", title),
``[parameters]`` (m1, m2, C, g with units, parsed by ``crane_sym.units``),
``[drive_law]`` (lifting = "from_weight" or "pickup", breakpoints,
coefficients, optional time_unit and acceleration_unit: c_kj is in
acceleration_unit per time_unit^j) and ``[options]`` (duration, points).
"""
from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path
from typing import Any, Sequence

import sympy as sp
from sympy.physics.units import acceleration, force, length, mass
from sympy.physics.units import time as _TIME

from . import registry, units
from .codegen import render_module
from .derivation import Derivation, Output
from .duhamel import DuhamelResult, duhamel
from .loads import DEFAULT_TIME, Piece, PiecewiseLoad, exact_number, piecewise_polynomial
from .scenes import _SAFE_NAME, SceneError, _locate, _options, read_toml
from .symbols import TIME, PhysicalSymbol, SymbolTable

__all__ = ["DriveLawResponse", "DriveLawScene", "FROM_WEIGHT", "PICKUP", "drive_law",
           "drive_law_files", "drive_law_outputs", "is_drive_law_scene",
           "load_drive_law_scene", "module_name", "render_drive_law_module", "respond"]

FROM_WEIGHT = "from_weight"
PICKUP = "pickup"
#: The derivation whose model this module evaluates.
MODEL = "hoist_startup"
_TABLES = ("scene", "parameters", "drive_law", "options")
_SYSTEM = {"m1": (mass, "kg", "reduced mass of the drive"),
           "m2": (mass, "kg", "mass of the load"),
           "C": (force / length, "N/m", "stiffness of the rope"),
           "g": (acceleration, "m/s^2", "acceleration of gravity")}
_LAW_KEYS = ("lifting", "breakpoints", "coefficients", "time_unit", "acceleration_unit")


# --- the law and the response ------------------------------------------------------
def drive_law(breakpoints: Sequence[Any], coefficients: Sequence[Sequence[Any]], *,
              t: sp.Symbol = DEFAULT_TIME) -> PiecewiseLoad:
    """The drive acceleration :math:`a(t)` from numbers only.

    .. math:: a(t) = \\sum_j c_{kj} (t - b_k)^j \\; (b_k \\le t < b_{k+1}),
              \\qquad a(t) = 0 \\; (t < b_0 \\text{ or } t \\ge b_N)

    Parameters
    ----------
    breakpoints : N + 1 numbers :math:`b_0 < \\dots < b_N` [s]
    coefficients : N sequences of numbers, :math:`c_{kj}` [m/s^(2+j)]
    t : Symbol

    Returns
    -------
    PiecewiseLoad
        N + 1 pieces, the last one 0. Entries are checked by type
        (``loads.exact_number``): a string raises ``TypeError`` and is never
        parsed or evaluated; counts and order raise ``ValueError``.
    """
    for what, seq in (("breakpoints", breakpoints), ("coefficients", coefficients)):
        if isinstance(seq, (str, bytes)) or not isinstance(seq, Sequence):
            raise TypeError(f"{what} must be a list of numbers, got {type(seq).__name__}")
    if len(breakpoints) < 2:
        raise ValueError(f"breakpoints needs at least 2 entries (start and end of the "
                         f"law), got {len(breakpoints)}")
    if len(coefficients) != len(breakpoints) - 1:
        raise ValueError(f"{len(breakpoints)} breakpoints bound {len(breakpoints) - 1} "
                         f"pieces, so coefficients needs {len(breakpoints) - 1} rows, "
                         f"got {len(coefficients)}")
    rows = list(coefficients) + [[0]]
    return piecewise_polynomial(list(breakpoints), rows, t=t)


def _piece_of(load: PiecewiseLoad, time: sp.Expr) -> sp.Expr:
    """The expression of the piece of ``load`` holding at ``time`` (0 before it starts)."""
    for piece in load.intervals:
        if piece.start <= time < piece.end:
            return piece.expr
    return sp.Integer(0)


def _system(value: Any, what: str) -> sp.Expr:
    """A positive exact number (SymPy expressions with a known sign pass as given)."""
    number = value if isinstance(value, sp.Expr) and value.is_number else exact_number(
        value, what)
    if not number.is_positive:
        raise ValueError(f"{what} must be > 0, got {number}")
    return number


@dataclass(frozen=True)
class DriveLawResponse:
    """The hoist's response to one drive law; the methods give SymPy expressions in ``t``.

    Attributes: the data ``lifting``, ``m1, m2, C, g`` (exact, SI); ``omega``,
    :math:`\\Omega` of (2); the loads ``law`` :math:`a(t)`, ``resistance``
    :math:`Q(t)` of (28) or (31) and ``forcing`` :math:`S(t)` of (2) on the
    union of their breakpoints; ``final_speed`` :math:`v_0 = \\int a\\,dt`
    (``oo`` if the law never ends); ``contact_time`` :math:`\\tau_0` of (29)
    (pick-up only, else None); ``reference``, the force of (25),
    :math:`(m_2 P(0) + m_1 Q(0))/(m_1 + m_2)`; ``stretch``, the
    ``DuhamelResult`` :math:`x(t)` of (21) or (23), one piece per forcing piece.
    """

    t: sp.Symbol
    lifting: str
    m1: sp.Expr
    m2: sp.Expr
    C: sp.Expr
    g: sp.Expr
    omega: sp.Expr
    law: PiecewiseLoad
    resistance: PiecewiseLoad
    forcing: PiecewiseLoad
    final_speed: sp.Expr
    contact_time: sp.Expr | None
    reference: sp.Expr
    stretch: DuhamelResult

    def _assemble(self, per_piece) -> sp.Expr:
        """One Piecewise of ``per_piece(x_k, start_k)`` over the forcing's pieces."""
        exprs = [per_piece(x.expr, p.start)
                 for x, p in zip(self.stretch.pieces, self.forcing.intervals)]
        return _piecewise(exprs, self.forcing.intervals, self.t)

    def acceleration(self) -> sp.Expr:
        """:math:`a(t)` (0 before the law starts and after it ends)."""
        return self._assemble(lambda x, b: _piece_of(self.law, b))

    def speed(self) -> sp.Expr:
        """Drive speed :math:`v(t) = \\int_0^t a\\,d\\theta` of the rigid hoist."""
        exprs, start = [], sp.Integer(0)
        for p in self.forcing.intervals:
            exprs.append(sp.expand(start + sp.integrate(_piece_of(self.law, p.start),
                                                        (self.t, p.start, self.t))))
            start = exprs[-1].subs(self.t, p.end) if p.end != sp.oo else start
        return _piecewise(exprs, self.forcing.intervals, self.t)

    def relative_forcing(self) -> sp.Expr:
        """:math:`S(t)` of (2)."""
        return self._assemble(lambda x, b: _piece_of(self.forcing, b))

    def rope_stretch(self) -> sp.Expr:
        """:math:`x(t)` by Duhamel's integral, (21) or (23)."""
        return self._assemble(lambda x, b: x)

    def rope_stretch_rate(self) -> sp.Expr:
        """:math:`\\dot x(t)` (18)."""
        return self._assemble(lambda x, b: x.diff(self.t))

    def rope_force(self) -> sp.Expr:
        """:math:`P_{дин}(t) = C x(t)`, (22) or (24)."""
        return self._assemble(lambda x, b: self.C * x)

    def dynamic_coefficient(self) -> sp.Expr:
        """:math:`K_{дин}(t)`: the rope force over the reference of (25); (26), (27)."""
        return self._assemble(lambda x, b: self.C * x / self.reference)

    def load_acceleration(self) -> sp.Expr:
        """:math:`\\ddot x_2 = (C x - Q)/m_2`, the load's equation (1)."""
        return self._assemble(
            lambda x, b: (self.C * x - _piece_of(self.resistance, b)) / self.m2)


def _piecewise(exprs: list[sp.Expr], intervals: Sequence[Piece], t: sp.Symbol) -> sp.Expr:
    if len(exprs) == 1:
        return exprs[0]
    args = [(e, t < p.end) for e, p in zip(exprs[:-1], intervals[:-1])]
    return sp.Piecewise(*args, (exprs[-1], True))


def respond(law: PiecewiseLoad, m1: Any, m2: Any, C: Any, g: Any, lifting: str, *,
            contact_time: Any = None) -> DriveLawResponse:
    """Solve the hoist's stretch equation (2) for the drive law ``law``.

    .. math:: x(t) = x_0 \\cos\\Omega t + \\frac{1}{\\Omega}
              \\int_0^t S(\\theta) \\sin\\Omega(t - \\theta)\\,d\\theta,
              \\qquad x_0 = Q(0)/C                              \\quad (21), (23)

    Parameters
    ----------
    law : PiecewiseLoad
        :math:`a(t)` [m/s²] with numeric breakpoints, e.g. from :func:`drive_law`.
    m1, m2, C, g : numbers (SI), > 0
        Drive mass, load mass, rope stiffness, gravity (strings are refused).
    lifting : {"from_weight", "pickup"}
        Rope preloaded by the weight (11) or slack (7) at the start.
    contact_time : number, optional
        :math:`\\tau_0` with pick-up; default (29) with the law's final speed.

    Returns
    -------
    DriveLawResponse
    """
    if lifting not in (FROM_WEIGHT, PICKUP):
        raise ValueError(f"lifting must be {FROM_WEIGHT!r} or {PICKUP!r}, got {lifting!r}")
    m1, m2, C, g = (_system(v, n) for v, n in ((m1, "m1"), (m2, "m2"), (C, "C"), (g, "g")))
    t = law.t
    law = law.starting_at_zero()
    omega = sp.sqrt((m1 + m2) * C / (m1 * m2))
    last = law.intervals[-1]
    final = sp.Integer(0)
    for p in law.intervals[:-1]:
        final += sp.integrate(p.expr, (t, p.start, p.end))
    final = final if last.expr == 0 else sp.oo
    weight = m2 * g
    tau0 = None
    if lifting == PICKUP:
        if contact_time is not None:
            tau0 = _system(contact_time, "contact_time")
        elif final.is_positive and final != sp.oo:
            tau0 = weight / (C * final)
        else:
            raise ValueError("lifting with pick-up needs tau_0 = m2 g/(C v0) of (29): the "
                             f"law must end (last piece 0) at a speed v0 > 0, got {final}")
        resistance = PiecewiseLoad((0, tau0), (weight * t / tau0, weight), t)
    else:
        resistance = PiecewiseLoad((0,), (weight,), t)
    cuts = sorted(set(law.breakpoints) | set(resistance.breakpoints), key=lambda b: sp.N(b, 30))
    pieces = [sp.expand((m1 + m2) / m1 * _piece_of(law, b) + weight / m1
                        + _piece_of(resistance, b) / m2) for b in cuts]
    forcing = PiecewiseLoad(tuple(cuts), tuple(pieces), t)
    q0 = resistance.pieces[0].subs(t, 0)
    p0 = (m1 + m2) * _piece_of(law, sp.Integer(0)).subs(t, 0) + weight
    reference = (m2 * p0 + m1 * q0) / (m1 + m2)
    if not reference.is_positive:
        raise ValueError(f"the reference force of (25) must be > 0, got {reference}: "
                         "a(0) < 0 pulls the load down at the start")
    stretch = duhamel(forcing, omega, t, u0=q0 / C, simplify=False)
    return DriveLawResponse(t, lifting, m1, m2, C, g, omega, law, resistance, forcing,
                            final, tau0, reference, stretch)


def drive_law_outputs(response: DriveLawResponse) -> list[Output]:
    """The generated functions of a response: time is their only argument."""
    t = response.t
    pickup = response.lifting == PICKUP
    x_eq, f_eq, k_eq = ("(21)", "(22)", "(26)") if pickup else ("(23)", "(24)", "(27)")
    case = "lifting with pick-up" if pickup else "lifting from weight"
    spec = [
        ("drive_acceleration", response.acceleration(), ("(28)", "(31)"),
         "Drive acceleration a(t) of the scene's law.", "m/s^2"),
        ("drive_speed", response.speed(), ("(28)", "(31)"),
         "Drive speed v(t), the integral of a(t) (rigid hoist).", "m/s"),
        ("relative_forcing", response.relative_forcing(), ("(2)", "(28)" if pickup
                                                            else "(31)"),
         f"Load S(t) = P/m1 + Q/m2 of the stretch equation, {case}.", "m/s^2"),
        ("rope_stretch", response.rope_stretch(), ("(15)", x_eq),
         f"Rope stretch x(t) = x1 - x2 by Duhamel's integral, {case}.", "m"),
        ("rope_stretch_rate", response.rope_stretch_rate(), ("(18)", x_eq),
         f"Stretch rate dx/dt, {case}.", "m/s"),
        ("rope_force", response.rope_force(), (f_eq,), f"Rope force C x(t), {case}.", "N"),
        ("dynamic_coefficient", response.dynamic_coefficient(), ("(25)", k_eq),
         f"Dynamic coefficient K_din(t), {case}.", "1"),
        ("load_acceleration", response.load_acceleration(), ("(1)", "(57)"),
         f"Load acceleration (C x - Q)/m2, {case}.", "m/s^2"),
    ]
    return [Output(name, expr, (t,), labels, summary, unit)
            for name, expr, labels, summary, unit in spec]


# --- scenes ----------------------------------------------------------------------------
@dataclass(frozen=True)
class DriveLawScene:
    """A validated drive-law scene, exact and in SI: breakpoints [s],
    ``coefficients[k][j]`` [m/s^(2+j)], m1, m2 [kg], C [N/m], g [m/s²];
    ``duration`` [s] and ``points`` of a plot (``[options]``)."""

    name: str
    title: str
    derivation: str
    lifting: str
    breakpoints: tuple[sp.Rational, ...]
    coefficients: tuple[tuple[sp.Rational, ...], ...]
    m1: sp.Rational
    m2: sp.Rational
    C: sp.Rational
    g: sp.Rational
    duration: float
    points: int
    path: Path

    def law(self) -> PiecewiseLoad:
        """:math:`a(t)` of the scene (:func:`drive_law`)."""
        return drive_law(self.breakpoints, self.coefficients)

    def response(self) -> DriveLawResponse:
        """The symbolic response (:func:`respond`)."""
        return respond(self.law(), self.m1, self.m2, self.C, self.g, self.lifting)


def is_drive_law_scene(path_or_name: str | Path) -> bool:
    """True when the scene file (a path or a shipped name) has a ``[drive_law]`` table."""
    return isinstance(read_toml(_locate(path_or_name)).get("drive_law"), dict)


def _table(data: dict, key: str, allowed: Sequence[str], required: Sequence[str],
           where: str) -> dict[str, Any]:
    """``data[key]`` checked for unknown and missing keys."""
    table = data.get(key, {} if not required else None)
    if not isinstance(table, dict):
        raise SceneError(f"{where}: missing table [{key}]")
    unknown = sorted(set(table) - set(allowed))
    missing = [k for k in required if k not in table]
    if unknown or missing:
        wrong = " and ".join(([f"unknown keys {unknown}"] if unknown else [])
                             + ([f"missing {missing}"] if missing else []))
        raise SceneError(f"{where}: [{key}] has {wrong}; it takes {list(allowed)}")
    return table


def _quantity(key: str, value: Any, dim, where: str) -> float:
    try:
        return units.convert(key, value, dim)
    except units.UnitError as exc:
        raise SceneError(f"{where}: {exc}") from None


def _unit_factor(law: dict[str, Any], key: str, default: str, dim, where: str) -> sp.Rational:
    text = law.get(key, default)
    try:
        if not isinstance(text, str):
            raise units.UnitError(f"must be a unit text like {default!r}, got {text!r}")
        factor, found = units.parse_unit(text)
        if not units.same_dimension(found, dim):
            raise units.UnitError(f"{text!r} is {units.format_dimension(found)}, "
                                  f"expected {units.format_dimension(dim)}")
    except units.UnitError as exc:
        raise SceneError(f"{where}: [drive_law] {key}: {exc}") from None
    return exact_number(factor, key)


def load_drive_law_scene(path_or_name: str | Path) -> DriveLawScene:
    """Read and validate a drive-law scene (format: the module docstring).

    Raises ``SceneError`` naming the table and key: unknown or missing keys, a
    wrong derivation, bad units, counts that do not match, an entry that is
    not a number (text in the law is refused by type, never evaluated).
    """
    path = _locate(path_or_name)
    data = read_toml(path)
    where = f"scene file {path.name!r}"
    extra = sorted(set(data) - set(_TABLES))
    if extra:
        raise SceneError(f"{where}: unknown tables {extra}; expected {list(_TABLES)}")
    head = _table(data, "scene", ("name", "derivation", "title"),
                  ("name", "derivation", "title"), where)
    if not isinstance(head["name"], str) or not _SAFE_NAME.fullmatch(head["name"]):
        raise SceneError(f"{where}: name must be letters, digits, '_', '-' or '.', "
                         f"got {head['name']!r}")
    where = f"scene {head['name']!r}"
    try:
        derivation = registry.resolve(str(head["derivation"]))
    except KeyError as exc:
        raise SceneError(f"{where}: {exc.args[0]}") from None
    if derivation != MODEL or not isinstance(head["title"], str):
        raise SceneError(f"{where}: a drive law drives the model of {MODEL!r} (got "
                         f"{derivation!r}) and needs a text title")
    raw = _table(data, "parameters", _SYSTEM, _SYSTEM, where)
    system = {k: exact_number(_quantity(k, raw[k], dim, where), k)
              for k, (dim, _, _) in _SYSTEM.items()}
    for key, value in system.items():
        if not value > 0:
            raise SceneError(f"{where}: parameter {key!r} ({_SYSTEM[key][2]}) must be > 0")
    law = _table(data, "drive_law", _LAW_KEYS, _LAW_KEYS[:3], where)
    if law["lifting"] not in (FROM_WEIGHT, PICKUP):
        raise SceneError(f"{where}: [drive_law] lifting must be {FROM_WEIGHT!r} or "
                         f"{PICKUP!r}, got {law['lifting']!r}")
    to_s = _unit_factor(law, "time_unit", "s", _TIME, where)
    to_acc = _unit_factor(law, "acceleration_unit", "m/s^2", acceleration, where)
    try:                                   # every entry checked by type before use
        checked = drive_law(law["breakpoints"], law["coefficients"])
    except (TypeError, ValueError) as exc:
        raise SceneError(f"{where}: [drive_law] {exc}") from None
    rows = tuple(tuple(exact_number(c, "c") * to_acc / to_s ** j for j, c in enumerate(row))
                 for row in law["coefficients"])
    options = _options(_table(data, "options", ("duration", "points"), ("duration",),
                              where), where)
    return DriveLawScene(head["name"], head["title"], derivation, law["lifting"],
                         tuple(b * to_s for b in checked.breakpoints), rows,
                         system["m1"], system["m2"], system["C"], system["g"],
                         options["duration"], options["points"], path)


# --- code generation -------------------------------------------------------------------
def module_name(scene: DriveLawScene) -> str:
    """File name of the scene's module, ``scene_<name>.py``."""
    return f"scene_{scene.name}.py"


def render_drive_law_module(scene: DriveLawScene) -> str:
    """Source of the NumPy module of the scene's drive law (pure; deterministic).

    The convolution is done once, symbolically, with the scene's exact numbers
    folded in; every function takes time ``t`` [s] only.
    """
    model = registry.module(scene.derivation)
    t = DEFAULT_TIME
    table = SymbolTable([PhysicalSymbol(t, _TIME, "s", "time from the start of the drive",
                                        TIME, "nonnegative", (1e-2, 2.0))])
    d = Derivation(id=scene.derivation, paper=model.PAPER, title=model.TITLE,
                   citation="", model="", symbols=table)
    response = scene.response()
    law = "; ".join(f"[{sp.sstr(b)}, {sp.sstr(e)}): {sp.sstr(p)}" for b, e, p in
                    response.law.intervals if p != 0)
    note = (f"Drive law of scene {scene.name!r} ({scene.title}), {scene.lifting}:\n"
            f"a(t) [m/s^2] = {law}; 0 elsewhere.\n"
            f"Folded in (SI): m1 = {sp.sstr(scene.m1)} kg, m2 = {sp.sstr(scene.m2)} kg, "
            f"C = {sp.sstr(scene.C)} N/m, g = {sp.sstr(scene.g)} m/s^2"
            + (f", tau_0 = {sp.sstr(response.contact_time)} s" if response.contact_time
               is not None else "") + ".")
    return render_module(d, drive_law_outputs(response), scene_note=note)


def drive_law_files(path_or_name: str | Path) -> dict[str, str]:
    """File name -> source for ``crane-sym generate --scene FILE`` of a drive-law scene."""
    scene = load_drive_law_scene(path_or_name)
    return {module_name(scene): render_drive_law_module(scene)}
