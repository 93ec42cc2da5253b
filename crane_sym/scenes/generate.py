"""Everything ``crane-sym generate`` writes: one module per derivation, one
per shipped scene, and the package ``__init__``."""
from __future__ import annotations

from crane_sym import progress, registry
from crane_sym.codegen import module as codegen
from crane_sym.codegen import files as module_files
from crane_sym.scenes import specialize
from crane_sym.scenes.reading import list_scenes


def all_files() -> dict[str, str]:
    """File name -> source for the whole ``generated/`` folder."""
    say = progress.current()
    derivations = []
    for i in registry.ids():
        with say.task(f"building {i}"):
            derivations.append(registry.get(i))
    modules = {}
    for d in (d for d in derivations if d.outputs):
        with say.task(f"printing {d.id}.py"):
            modules[f"{d.id}.py"] = codegen.render_module(d)
    for name in list_scenes():
        with say.task(f"specializing scene {name}"):
            modules.update(specialize.scene_files(name))
    return module_files.with_package_init(modules)
