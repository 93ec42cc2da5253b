"""Which derivations exist, and where their modules are.

Derivation modules are imported, and built, only when asked for.
"""
from __future__ import annotations

import importlib
import importlib.util
from functools import lru_cache
from types import ModuleType

from crane_sym.derivation import Derivation, SceneLoad, SweepOutput
from crane_sym.repeatable import fixed_sympy_draws

#: id -> module under ``crane_sym.derivations``, in paper order.
DERIVATIONS: dict[str, str] = {
    "travel_braking": "crane_sym.derivations.travel_braking",
    "hoist_brakes": "crane_sym.derivations.hoist_brakes",
    "hoist_startup": "crane_sym.derivations.hoist_startup",
    "portal_travel": "crane_sym.derivations.portal_travel",
    "drum_drive": "crane_sym.derivations.drum_drive",
}
#: Paper file-number prefixes accepted as ids on the command line.
ALIASES: dict[str, str] = {"000": "travel_braking", "001": "hoist_brakes",
                           "002": "hoist_startup", "003": "portal_travel",
                           "004": "drum_drive"}

#: Seconds each paper last took, built and audited in one process of a quiet
#: machine (`crane-sym bench --audit`, its stages table): what orders the
#: papers longest first in a pool (``audit.papers.longest_first``). Only the
#: order matters; a paper missing here is taken first.
AUDIT_SECONDS: dict[str, float] = {"travel_braking": 2.3, "hoist_brakes": 4.8,
                                   "hoist_startup": 14.9, "portal_travel": 7.2,
                                   "drum_drive": 8.7}
#: Seconds each paper's share of `crane-sym generate` last took in one process
#: (its build, module, scenes and machine reading; measured at a load of 0.9),
#: for the same order.
GENERATE_SECONDS: dict[str, float] = {"travel_braking": 3.8, "hoist_brakes": 8.2,
                                      "hoist_startup": 24.6, "portal_travel": 10.2,
                                      "drum_drive": 7.5}

#: One example (or two) per subcommand, shown at the end of its --help; they
#: name registered papers and shipped scenes, so they live with the papers' list.
EXAMPLES = {
    "list": "crane-sym list\n  crane-sym list --scenes\n  crane-sym list --format json",
    "audit": "crane-sym audit 000 --format table\n  crane-sym audit travel_braking "
             "--format json --quiet > verdicts.json\n"
             "  crane-sym audit examples/drive_trains/hoist_rope_stretch.toml",
    "walkthrough": "crane-sym walkthrough 000 -o walkthrough.md\n"
                   "  crane-sym walkthrough 002 --format ipynb -o hoist_startup.ipynb\n"
                   "  crane-sym walkthrough 001 --format html -o hoist_brakes.html\n"
                   "  crane-sym walkthrough examples/drive_trains/hoist_fig9.toml -o fig9.md",
    "generate": "crane-sym generate\n  crane-sym generate --check\n"
                "  crane-sym generate --scene hoist_user_drive_law --out out/",
    "accuracy": "crane-sym accuracy 002",
    "bench": "crane-sym bench 000 002 004 --out bench/",
    "run": "crane-sym run overhead_crane_50t --out out/\n"
           "  crane-sym run examples/drive_trains/hoist_fig9.toml --out out/",
    "model": "crane-sym model show examples/drive_trains/hoist_fig9.toml",
    "sweep": "crane-sym sweep overhead_crane_50t --vary m1=1:100:200:log --vary P_t=5:50:200 "
             "\\\n      --output peak_elastic_force --limit \"peak_elastic_force<=40 kN\" "
             "--out sweep/ --format json",
}

def ids() -> list[str]:
    """Registered derivation ids, in paper order."""
    return list(DERIVATIONS)


def resolve(name: str) -> str:
    """The id for ``name`` (an id or a paper number such as ``000``).

    Parameters
    ----------
    name : str
        A derivation id or paper number (``000``).
    """
    key = ALIASES.get(name, name)
    if key not in DERIVATIONS:
        known = ", ".join(f"{k} ({a})" for a, k in ALIASES.items())
        raise KeyError(f"unknown derivation {name!r}; known: {known}")
    return key


def module(name: str) -> ModuleType:
    """The derivation module for ``name``.

    Parameters
    ----------
    name : str
        A derivation id or paper number (``000``).
    """
    return importlib.import_module(DERIVATIONS[resolve(name)])


def module_path(name: str) -> str:
    """The file of the derivation's package (its ``__init__.py``), found
    without importing it (an import builds its printed formulas: a second
    in a process that only lists the shipped scenes).

    Parameters
    ----------
    name : str
        A derivation id or paper number (``000``).
    """
    package = DERIVATIONS[resolve(name)]
    spec = importlib.util.find_spec(package)
    if spec is None or spec.origin is None:
        raise ImportError(f"derivation package {package} is not installed")
    return spec.origin


def scene_loads(name: str) -> dict[str, SceneLoad]:
    """The loads a scene of this derivation may give as data (table -> SceneLoad),
    from the package's ``SCENE_LOADS``; no build needed.

    Parameters
    ----------
    name : str
        A derivation id or paper number (``000``).
    """
    return dict(getattr(module(name), "SCENE_LOADS", {}))


def scene_options(name: str) -> tuple:
    """The options scenes of this derivation may give beside ``duration`` and
    ``points`` (``crane_sym.scenes.options.SceneOption``), from the package's
    ``SCENE_OPTIONS``; no build needed.

    Parameters
    ----------
    name : str
        A derivation id or paper number (``000``).
    """
    return tuple(getattr(module(name), "SCENE_OPTIONS", ()))


def scene_checks(name: str) -> tuple:
    """Conditions between a scene's options and parameters, checked on load
    (``crane_sym.scenes.options.SceneCheck``), from the package's
    ``SCENE_CHECKS``; no build needed.

    Parameters
    ----------
    name : str
        A derivation id or paper number (``000``).
    """
    return tuple(getattr(module(name), "SCENE_CHECKS", ()))


def sweep_outputs(name: str) -> dict[str, SweepOutput]:
    """Simulated responses a design sweep may ask for (name -> SweepOutput),
    from the package's ``SWEEP_OUTPUTS``; no build needed.

    Parameters
    ----------
    name : str
        A derivation id or paper number (``000``).
    """
    return dict(getattr(module(name), "SWEEP_OUTPUTS", {}))


def value_units(name: str) -> dict[str, str]:
    """The unit of each number a scene report of this derivation gives
    (``SceneReport.values``, SI): pattern (``fnmatch``, the first that
    matches) -> unit, from the package's ``VALUE_UNITS``; no build needed.

    Parameters
    ----------
    name : str
        A derivation id or paper number (``000``).
    """
    return dict(getattr(module(name), "VALUE_UNITS", {}))


def get(name: str, code: bool = True) -> Derivation:
    """The built derivation for ``name``: one build per process, whether it is
    asked for by id or by paper number (:func:`built`).

    Parameters
    ----------
    name : str
        A derivation id or paper number (``000``).
    code : bool, optional
        False: the parts only code and the bench read may be left out
        (``Derivation.code``), what the audit asks for; a build with them,
        made before in this process, serves as well.
    """
    key = resolve(name)
    return built(key, code or key in _WITH_CODE)


#: The ids built with their code parts in this process.
_WITH_CODE: set[str] = set()


@lru_cache(maxsize=None)
def built(key: str, code: bool = True) -> Derivation:
    """The derivation registered as ``key`` built, once per process, under
    fixed SymPy draws (the same path and time in every process).

    Parameters
    ----------
    key : str
        A derivation id (:func:`resolve` gives it for a paper number).
    code : bool, optional
        False: without the parts only code and the bench read (the paper's
        ``build(code=False)``).
    """
    with fixed_sympy_draws():
        d = module(key).build(code=code)
    if code:
        _WITH_CODE.add(key)
    return d
