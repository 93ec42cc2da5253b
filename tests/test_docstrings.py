"""Every function of a room's face documents its parameters (numpydoc).

The face of a room (a subpackage of ``crane_sym`` or a top-level module, as
``tests/test_layers.py`` reads them) is what other rooms and the papers
import of it: a public function of ``crane_sym`` that a module of another
room, or of a paper in ``derivations/``, names in ``from M import f`` or
reaches as ``m.f`` after ``from P import m`` / ``import M as m``. Each
needs a "Parameters" section naming every one of its parameters (``self``
aside; ``*args`` and ``**kwargs`` by their names). The set is read from the
source (``ast``), so a new import puts a function in the face at once.
"""
from __future__ import annotations

import ast
import importlib
import inspect
import re
from pathlib import Path
from types import FunctionType

from test_layers import PACKAGE, room, subpackages

ROOT = Path(__file__).resolve().parents[1]
PAPERS = "crane_sym.derivations"
#: A numpydoc section: a heading, then a line of dashes.
_SECTION = re.compile(r"^Parameters\n-{3,}\n(.*?)(?=^\S[^\n]*\n-{3,}\n|\Z)", re.M | re.S)


def _modules() -> list[tuple[Path, str]]:
    """(file, dotted name) of every module of the machinery and the papers."""
    def dotted(path: Path, base: Path, package: str) -> str:
        parts = path.relative_to(base).with_suffix("").parts
        return f"{package}.{'.'.join(parts)}".removesuffix(".__init__")
    found = [(p, dotted(p, ROOT / PACKAGE, PACKAGE)) for p in (ROOT / PACKAGE).rglob("*.py")]
    return found + [(p, dotted(p, ROOT / "derivations", PAPERS))
                    for p in (ROOT / "derivations").rglob("*.py")]


def imported_names(path: Path, module: str) -> set[tuple[str, str]]:
    """(module, name) for every ``from M import name`` of ``crane_sym`` in
    ``path`` (relative ones made absolute), and every ``m.name`` where ``m``
    is bound by such an import or by ``import M as m``."""
    tree = ast.parse(path.read_text(encoding="utf-8"))
    found: set[tuple[str, str]] = set()
    bound: dict[str, str] = {}
    for node in ast.walk(tree):
        if isinstance(node, ast.ImportFrom):
            if node.level:
                parts = module.split(".") if path.name == "__init__.py" \
                    else module.split(".")[:-1]
                parts = parts[:len(parts) - node.level + 1]
                stem = ".".join(parts + ([node.module] if node.module else []))
            else:
                stem = node.module or ""
            if stem.split(".")[0] != PACKAGE:
                continue
            for a in node.names:
                found.add((stem, a.name))
                bound[a.asname or a.name] = f"{stem}.{a.name}"
        elif isinstance(node, ast.Import):
            bound.update({a.asname: a.name for a in node.names
                          if a.asname and a.name.split(".")[0] == PACKAGE})
    found |= {(bound[node.value.id], node.attr) for node in ast.walk(tree)
              if isinstance(node, ast.Attribute) and isinstance(node.value, ast.Name)
              and node.value.id in bound}
    return found


def face() -> dict[str, FunctionType]:
    """Qualified name -> function, for every function of a room's face."""
    packages = subpackages(ROOT / PACKAGE, PACKAGE)
    found: dict[str, FunctionType] = {}
    for path, module in _modules():
        here = "paper" if module.startswith(PAPERS) else room(module, packages)
        for stem, name in sorted(imported_names(path, module)):
            if name.startswith("_") or stem.startswith((PAPERS, f"{PACKAGE}.generated")):
                continue
            try:
                obj = getattr(importlib.import_module(stem), name, None)
            except ImportError:                 # ``stem.name`` is a module
                continue
            if not inspect.isfunction(obj) or obj.__module__.startswith(PAPERS) \
                    or obj.__module__.split(".")[0] != PACKAGE \
                    or room(obj.__module__, packages) == here:
                continue
            found[f"{obj.__module__}.{obj.__qualname__}"] = obj
    return found


def documented(doc: str | None) -> set[str] | None:
    """The names a numpydoc "Parameters" section lists (``a, b : type`` names
    two), or None without the section."""
    section = _SECTION.search(inspect.cleandoc(doc or ""))
    if section is None:
        return None
    names: set[str] = set()
    for line in section.group(1).splitlines():
        if line and not line[0].isspace():
            names |= {n.strip().lstrip("*") for n in line.split(" : ")[0].split(",")}
    return names


def undocumented(functions: dict[str, FunctionType]) -> list[str]:
    """One line per function whose parameters are not all documented."""
    problems = []
    for name, fn in sorted(functions.items()):
        wanted = [p for p in inspect.signature(fn).parameters if p not in ("self", "cls")]
        if not wanted:
            continue
        listed = documented(fn.__doc__)
        if listed is None:
            problems.append(f"{name}: no Parameters section")
        elif missing := [p for p in wanted if p not in listed]:
            problems.append(f"{name}: Parameters does not name {', '.join(missing)}")
    return problems


def test_the_face_is_found_and_reasonable():
    found = face()
    # functions the papers and other rooms are known to import, by each route
    assert "crane_sym.registry.resolve" in found                # from M import f
    assert "crane_sym.mechanics.loads.step" in found            # m.f after from P import m
    assert "crane_sym.codegen.files.write" in found             # ... as an alias
    assert not any(n.rsplit(".", 1)[1].startswith("_") for n in found)
    assert 100 < len(found) < 250, len(found)


def test_every_function_of_a_face_documents_its_parameters():
    assert undocumented(face()) == []


def test_a_missing_parameter_is_caught():
    def f(a, b, *args, c=1, **kwargs):
        """Do.

        Parameters
        ----------
        a, b : int
            Two.
        *args
            More.
        c : int, optional
        """

    def g(x):
        """No section."""

    assert undocumented({"f": f, "g": g}) == [
        "f: Parameters does not name kwargs", "g: no Parameters section"]
