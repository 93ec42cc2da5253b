"""Everything ``crane-sym generate`` writes: one module per derivation, one
per shipped scene, and the package ``__init__``."""
from __future__ import annotations

from . import codegen, registry, specialize


def all_files() -> dict[str, str]:
    """File name -> source for the whole ``generated/`` folder."""
    derivations = [registry.get(i) for i in registry.ids()]
    return codegen.rendered(derivations, specialize.shipped_scene_modules())
