"""The shape of the code: imports run one way, down the layers that
ARCHITECTURE.md states, and never in a circle.

The layer table of ARCHITECTURE.md is the single statement of the order: this
test reads it, so the page and the code cannot drift apart. Imports are read
from the source (``ast``), not by importing it.
"""
from __future__ import annotations

import ast
import re
import shutil
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
PACKAGE = "crane_sym"
#: Packages the machinery reaches only by name at run time (registry, codegen),
#: never by an import statement.
DATA_PACKAGES = ("crane_sym.derivations", "crane_sym.generated")


def stated_layers(page: Path) -> dict[str, int]:
    """Room -> layer number, from the table under "## Layers" of ``page``.

    A room is a subpackage of ``crane_sym`` (written ``mechanics/``) or a
    top-level module (written ``symbols``)."""
    text = page.read_text(encoding="utf-8")
    section = text.split("## Layers", 1)[1].split("\n## ", 1)[0]
    layers: dict[str, int] = {}
    for line in section.splitlines():
        cells = [c.strip() for c in line.strip().strip("|").split("|")]
        if len(cells) < 3 or not re.match(r"\d+$", cells[0]):
            continue
        for name in re.findall(r"`([A-Za-z_][A-Za-z0-9_]*/?)`", cells[2]):
            if name in layers:
                raise AssertionError(f"{page.name}: {name!r} is in two layers")
            layers[name] = int(cells[0])
    return layers


def room(module: str, packages: set[str]) -> str:
    """The room of a dotted module name: ``crane_sym.scenes.reading`` and
    ``crane_sym.scenes`` -> ``scenes/``, ``crane_sym.units`` -> ``units``,
    ``crane_sym`` -> ``__init__``; ``packages`` are the subpackages' names."""
    parts = module.split(".")[1:]
    if not parts:
        return "__init__"
    return parts[0] + "/" if len(parts) > 1 or module in packages else parts[0]


def subpackages(package_dir: Path, package: str) -> set[str]:
    """Dotted names of the subpackages of ``package``."""
    return {f"{package}.{p.parent.name}" for p in package_dir.glob("*/__init__.py")}


def _targets(node: ast.Import | ast.ImportFrom, module: str, is_package: bool) -> list[str]:
    """Absolute dotted names an import statement inside ``module`` reaches."""
    if isinstance(node, ast.Import):
        return [a.name for a in node.names]
    if node.level:
        parts = module.split(".") if is_package else module.split(".")[:-1]
        parts = parts[:len(parts) - node.level + 1]
        stem = ".".join(parts + ([node.module] if node.module else []))
    else:
        stem = node.module or ""
    return [f"{stem}.{a.name}" for a in node.names]


def import_graph(package_dir: Path, package: str) -> dict[str, set[str]]:
    """Module -> modules of ``package`` it imports (anywhere in its source,
    function bodies included); names are absolute, e.g. ``crane_sym.scenes.reading``.
    An import of a data package (``crane_sym.generated``, ``crane_sym.derivations``),
    absolute or relative, is kept as written, before a name could collapse it
    to ``crane_sym``."""
    files = {(package + "." + ".".join(p.relative_to(package_dir).with_suffix("").parts))
             .removesuffix(".__init__"): p for p in package_dir.rglob("*.py")}
    graph: dict[str, set[str]] = {}
    for name, path in files.items():
        targets: set[str] = set()
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            if not isinstance(node, (ast.Import, ast.ImportFrom)):
                continue
            for target in _targets(node, name, path.name == "__init__.py"):
                if target.startswith(tuple(d + "." for d in DATA_PACKAGES)):
                    targets.add(target)
                    continue
                while target and target not in files and "." in target:
                    target = target.rsplit(".", 1)[0]      # a name, not a module
                if target.startswith(package) and target != name:
                    targets.add(target)
        graph[name] = targets
    return graph


def cycles(graph: dict[str, set[str]]) -> list[list[str]]:
    """The strongly connected components with more than one module (Tarjan)."""
    index: dict[str, int] = {}
    low: dict[str, int] = {}
    stack: list[str] = []
    found: list[list[str]] = []

    def visit(v: str) -> None:
        index[v] = low[v] = len(index)
        stack.append(v)
        for w in sorted(graph.get(v, ())):
            if w not in graph:
                continue
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in stack:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            component = []
            while True:
                w = stack.pop()
                component.append(w)
                if w == v:
                    break
            if len(component) > 1:
                found.append(sorted(component))

    for v in sorted(graph):
        if v not in index:
            visit(v)
    return found


def layer_violations(graph: dict[str, set[str]], layers: dict[str, int],
                     packages: set[str]) -> list[str]:
    """Every import of a room in a higher layer, and every import of a data
    package; each as ``"a -> b"``."""
    bad = []
    for source, targets in sorted(graph.items()):
        here = layers.get(room(source, packages))
        if here is None:
            continue                        # reported as missing from the page
        for target in sorted(targets):
            if target.startswith(DATA_PACKAGES):
                bad.append(f"{source} -> {target} (a data package)")
                continue
            there = layers.get(room(target, packages), -1)
            if there > here:
                bad.append(f"{source} (layer {here}) -> {target} (layer {there})")
    return bad


def package_docstrings(package_dir: Path) -> list[str]:
    """Every subpackage without a docstring that says what it holds and what it
    may import."""
    missing = []
    for init in sorted(package_dir.glob("*/__init__.py")):
        doc = ast.get_docstring(ast.parse(init.read_text(encoding="utf-8"))) or ""
        if "May import" not in doc:
            missing.append(f"{init.parent.name}/ has no docstring saying what it may import")
    return missing


def check(root: Path) -> list[str]:
    """Every problem of the tree at ``root``: rooms missing from the layer
    table, stale table rows, circles, imports against the layer order,
    subpackages without their docstring."""
    layers = stated_layers(root / "ARCHITECTURE.md")
    graph = import_graph(root / PACKAGE, PACKAGE)
    packages = subpackages(root / PACKAGE, PACKAGE)
    rooms = {room(m, packages) for m in graph}
    problems = [f"{m} is in no layer of ARCHITECTURE.md" for m in sorted(rooms - set(layers))]
    problems += [f"ARCHITECTURE.md names {m}, which does not exist"
                 for m in sorted(set(layers) - rooms)]
    problems += [f"import circle: {' -> '.join(c)}" for c in cycles(graph)]
    problems += layer_violations(graph, layers, packages)
    problems += package_docstrings(root / PACKAGE)
    return problems


def test_crane_sym_imports_follow_the_stated_layers():
    assert check(ROOT) == []


def test_paper_packages_have_no_circles_and_stand_alone():
    """Each paper imports the machinery and itself, never another paper or the CLI."""
    for package_dir in sorted(p for p in (ROOT / "derivations").iterdir()
                              if (p / "__init__.py").is_file()):
        name = f"crane_sym.derivations.{package_dir.name}"
        graph = import_graph(package_dir, name)
        assert cycles(graph) == [], package_dir.name
        for source, _ in graph.items():
            text = (package_dir / (source.removeprefix(name).lstrip(".").replace(".", "/")
                                   or "__init__")).with_suffix(".py")
            tree = ast.parse(text.read_text(encoding="utf-8"))
            for node in ast.walk(tree):
                if isinstance(node, ast.ImportFrom) and not node.level and node.module:
                    assert not node.module.startswith("crane_sym.cli.main"), source
                    if node.module.startswith("crane_sym.derivations."):
                        assert node.module.startswith(name), (source, node.module)


@pytest.fixture()
def scratch(tmp_path: Path) -> Path:
    """A copy of the package and its architecture page to break on purpose."""
    shutil.copytree(ROOT / PACKAGE, tmp_path / PACKAGE,
                    ignore=shutil.ignore_patterns("__pycache__"))
    shutil.copy(ROOT / "ARCHITECTURE.md", tmp_path / "ARCHITECTURE.md")
    return tmp_path


def _append(path: Path, line: str) -> None:
    path.write_text(path.read_text(encoding="utf-8") + f"\n{line}\n", encoding="utf-8")


def test_a_circle_in_a_scratch_copy_is_caught(scratch):
    assert check(scratch) == []
    # symbols (layer 0) importing units (layer 0) and back: same layer, a circle.
    _append(scratch / PACKAGE / "symbols.py", "from . import units  # noqa")
    _append(scratch / PACKAGE / "units.py", "from .symbols import TIME  # noqa")
    problems = check(scratch)
    assert any(p.startswith("import circle:") and "crane_sym.symbols" in p
               and "crane_sym.units" in p for p in problems), problems


def test_an_upward_import_in_a_scratch_copy_is_caught(scratch):
    _append(scratch / PACKAGE / "mechanics" / "loads.py",
            "def _late():\n    from ..scenes.reading import Scene  # noqa")
    problems = check(scratch)
    assert any(p.startswith("crane_sym.mechanics.loads (layer") and "crane_sym.scenes.reading" in p
               for p in problems), problems


def test_a_module_missing_from_the_page_is_caught(scratch):
    (scratch / PACKAGE / "stray.py").write_text('"""x"""\n', encoding="utf-8")
    assert "stray is in no layer of ARCHITECTURE.md" in check(scratch)
    (scratch / PACKAGE / "attic").mkdir()
    (scratch / PACKAGE / "attic" / "__init__.py").write_text('"""x"""\n', encoding="utf-8")
    problems = check(scratch)
    assert "attic/ is in no layer of ARCHITECTURE.md" in problems
    assert "attic/ has no docstring saying what it may import" in problems


@pytest.mark.parametrize("line", [
    "from crane_sym.generated import travel_braking  # noqa",
    "from crane_sym.generated.travel_braking import peak_elastic_force  # noqa",
    "from ..generated.travel_braking import peak_elastic_force  # noqa",
    "from ..derivations import travel_braking  # noqa",
    "import crane_sym.generated.travel_braking  # noqa",
])
def test_an_import_of_a_generated_module_in_a_scratch_copy_is_caught(scratch, line):
    """The machinery reaches papers and generated modules by name at run time,
    never by an import statement, absolute or relative."""
    _append(scratch / PACKAGE / "bench" / "sweeps.py", f"def _late():\n    {line}")
    problems = check(scratch)
    assert any(p.startswith("crane_sym.bench.sweeps -> crane_sym.")
               and p.endswith("(a data package)") for p in problems), problems
