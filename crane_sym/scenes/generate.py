"""Everything ``crane-sym generate`` writes: one module per derivation, one
per shipped scene, the package ``__init__``, and the machine reading's table of
parses (``crane_sym.audit.parse_table``).

A paper's module, its scenes' modules and its prints' parses need that paper
built and nothing of another paper's, so the papers are printed in processes
of their own when more than one core is free (SymPy holds the GIL), the
longest first (``registry.GENERATE_SECONDS``); the files
are the same bytes either way, assembled in the order one process gives.
"""
from __future__ import annotations

import contextlib
import time
from typing import Iterator

from crane_sym import progress, registry
from crane_sym.audit.machine_read import parse_table_text, table_entries
from crane_sym.audit.papers import in_processes, workers
from crane_sym.audit.parse_table import FILE as PARSE_TABLE
from crane_sym.codegen import module as codegen
from crane_sym.codegen import files as module_files
from crane_sym.scenes import specialize
from crane_sym.scenes.reading import list_scenes, read_toml, scene_path


def _scenes_of(paper: str) -> list[str]:
    """The shipped scenes of ``paper``, in ``list_scenes`` order."""
    return [name for name in list_scenes()
            if read_toml(scene_path(name))["scene"]["derivation"] == paper]


@contextlib.contextmanager
def _stage(stages: dict[str, float] | None, name: str) -> Iterator[None]:
    """Wall seconds of the block into ``stages[name]`` (nothing when None)."""
    start = time.perf_counter()
    try:
        yield
    finally:
        if stages is not None:
            stages[name] = time.perf_counter() - start


def paper_files(paper: str, stages: dict[str, float] | None = None
                ) -> tuple[dict[str, str], dict[str, dict[str, str]], dict]:
    """One paper's share of ``generated/``: its module (if it has outputs), each
    of its scenes' files by scene name, and its prints' entries in the table
    of parses.

    Parameters
    ----------
    paper : str
        The paper's id.
    stages : dict, optional
        Filled with each stage's wall seconds, in order: ``build``, ``module``,
        ``scene <name>`` for each scene, ``machine reading``
        (``crane-sym bench --audit``).
    """
    say = progress.current()
    with say.task(f"building {paper}"), _stage(stages, "build"):
        d = registry.get(paper)
    own = {}
    if d.outputs:
        with say.task(f"printing {paper}.py"), _stage(stages, "module"):
            own[f"{paper}.py"] = codegen.render_module(d)
    scenes = {}
    for name in _scenes_of(paper):
        with say.task(f"specializing scene {name}"), _stage(stages, f"scene {name}"):
            scenes[name] = specialize.scene_files(name)
    with say.task(f"reading the prints of {paper} by machine"), \
            _stage(stages, "machine reading"):
        entries = table_entries(d)
    return own, scenes, entries


def _printed(share: tuple) -> str:
    """One progress line on a paper's share of ``generated/``."""
    own, scenes, entries = share
    return (f"printed {', '.join(own) or 'no module'}; specialized scenes "
            f"{', '.join(scenes) or '(none)'}; {len(entries)} sides read by machine")


def all_files(processes: int | None = None) -> dict[str, str]:
    """File name -> source for the whole ``generated/`` folder.

    Parameters
    ----------
    processes : int, optional
        Papers printed at once in worker processes (default: one a core this
        process may use, at most one a paper; 1: all in this process).
    """
    papers = registry.ids()
    processes = workers(len(papers)) if processes is None else processes
    if processes > 1:
        shares = in_processes(paper_files, papers, processes, "printing modules and scenes",
                              _printed, registry.GENERATE_SECONDS).results
    else:
        shares = [paper_files(paper) for paper in papers]
    modules: dict[str, str] = {}
    for own, _, _ in shares:
        modules.update(own)
    scenes = {name: files for _, by_scene, _ in shares for name, files in by_scene.items()}
    for name in list_scenes():
        modules.update(scenes[name])
    files = module_files.with_package_init(modules)
    files[PARSE_TABLE] = parse_table_text({k: e for _, _, entries in shares
                                           for k, e in entries.items()})
    return files
