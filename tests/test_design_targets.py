"""Section (g) of ``bench --sweep`` (``crane_sym.bench.design_targets``) on
tiny grids: a row is timed, judged against its target, and a row not met says
where its time goes."""
from __future__ import annotations

from dataclasses import replace
from pathlib import Path

import numpy as np

from crane_sym.bench import design_targets
from crane_sym.components.designs import designs

ROOT = Path(__file__).resolve().parents[1]


def test_a_component_file_row_not_met_says_where_the_time_goes(monkeypatch):
    """A 2 × 2 grid of the 5-body file against a target of 0 s: not met,
    no NaN, its profile functions of the package with shares in (0, 1), the
    largest first, all in the Markdown."""
    monkeypatch.setattr(design_targets, "PROFILE_DESIGNS", 4)
    case = replace(design_targets.FILE_CASES[0], n=2, target=0.0)
    row = design_targets.file_row(case, ROOT)
    assert row["designs"] == 4 and row["nan"] == 0 and row["met"] is False
    assert row["seconds"] > 0 and row["load_before"] >= 0
    shares = [share for _, share in row["profile"]]
    assert row["profile"] and all(name.startswith("crane_sym.") for name, _ in row["profile"])
    assert all(0 < s < 1 for s in shares) and shares == sorted(shares, reverse=True)
    text = "\n".join(design_targets.markdown_rows([row]))
    assert "| ≤ 0 s | not met |" in text and "where the time goes" in text
    assert row["profile"][0][0] in text


def test_the_floor_is_the_blocks_own_eigen_decompositions_timed_alone():
    """A 2 × 2 grid of the file: the floor counts the distinct A its block
    decomposed (the recorder holds them only while the block runs), times
    them, and the Markdown says whether the target is below it."""
    from crane_sym.mechanics import batched_spectra
    case = replace(design_targets.FILE_CASES[0], n=2, target=0.0)
    values = design_targets._file_values(case, 2)
    block = designs(ROOT / case.path)
    with batched_spectra.decomposed() as stacks:
        block.largest(case.output, values)
    assert stacks and all(A.ndim == 3 and A.shape[1] == A.shape[2] for A in stacks)
    assert not batched_spectra._DECOMPOSED
    floor = design_targets.eig_floor(stacks, repeats=1)
    assert floor["matrices"] == sum(len(A) for A in stacks) >= 4 and floor["seconds"] > 0
    row = {"name": "x", "designs": 4, "seconds": 0.1, "cpu_seconds": 0.1, "nan": 0,
           "load_before": 1.0, "load_after": 1.0, "target": 0.0, "met": False,
           "eig_floor": floor}
    text = "\n".join(design_targets.markdown_rows([row]))
    assert f"{floor['matrices']} distinct A" in text and "is below it" in text
    row.update(target=1e3, met=True)
    assert "is below it" not in "\n".join(design_targets.markdown_rows([row]))


def test_the_floor_on_two_threads_decomposes_the_same_stacks():
    """The floor of blocks that run on threads shares their stacks between as
    many threads (Dask's threaded scheduler): the same matrices, the same
    split between V⁻¹ and Aᵀ, and the Markdown says on how many threads."""
    rng = np.random.default_rng(5)
    stacks = [rng.standard_normal((40, 4, 4)) for _ in range(3)]
    jordan = np.zeros((2, 4, 4))
    jordan[:, 0, 1] = 1.0                            # x' = v, v' = 0: V singular, so Aᵀ
    stacks.append(jordan)
    one = design_targets.eig_floor(stacks, repeats=1)
    two = design_targets.eig_floor(stacks, repeats=1, threads=2)
    assert (one["matrices"], one["transposed"]) == (two["matrices"], two["transposed"]) == (122, 2)
    assert (one["threads"], two["threads"]) == (1, 2)
    row = {"name": "x", "designs": 4, "seconds": 0.1, "cpu_seconds": 0.1, "nan": 0,
           "load_before": 1.0, "load_after": 1.0, "target": 1e3, "met": True,
           "eig_floor": two, "blocks": 2, "scheduler": "threads"}
    text = "\n".join(design_targets.markdown_rows([row]))
    assert " on 2 threads, least of " in text and "| 4 designs of x, 2 blocks on threads |" in text


def test_a_row_met_prints_no_profile_and_a_missing_file_is_skipped(tmp_path):
    row = {"name": "x", "designs": 4, "seconds": 0.1, "cpu_seconds": 0.1, "nan": 0,
           "load_before": 1.0, "load_after": 1.0, "target": 1.0, "met": True,
           "profile": [("crane_sym.a.b", 0.5)]}
    text = "\n".join(design_targets.markdown_rows([row]))
    assert "| ≤ 1 s | met |" in text and "where the time goes" not in text
    skipped = design_targets.file_row(design_targets.FILE_CASES[0], tmp_path)
    assert "not found" in skipped["skipped"]
    assert "skipped" in "\n".join(design_targets.markdown_rows([skipped]))


def test_the_benched_file_batched_is_its_per_design_run_near_critical_and_in_other_modes(
        monkeypatch):
    """The 5-body file of the bench, batched against the per-design run
    (numeric closed forms) to 1e-9 of each peak, on designs that take
    different mode sequences (a start torque too small to move the bridge
    against its rolling friction, one just above it, the file's) and a
    trolley drive damped just below and just above the critical damping of
    the trolley swinging against the held bridge (2√(k m_t)), beside the
    file's own damping. (Exactly critical, to the double, the per-design
    route itself stops: ``spectral_clusters`` raises ClusterError, its Schur
    form finding none of the two eigenvalues about −7.07.)"""
    from crane_sym.mechanics import batched_runs
    seen = []
    solve = batched_runs.largest_of_runs

    def kept(*args, **kwargs):
        seen.append(solve(*args, **kwargs))
        return seen[-1]
    monkeypatch.setattr(batched_runs, "largest_of_runs", kept)
    found = designs(ROOT / design_targets.FILE_CASES[0].path)
    critical = 2 * np.sqrt(2e6 * 40e3)
    damping = np.array([critical * (1 - 1e-8), critical * (1 + 1e-6), critical * (1 + 1e-4),
                        1.4e3])
    values = {"start.torque": np.array([30.0, 60.0, 230.0])[:, None],
              "trolley_drive.damping": damping[None, :]}
    for output in ("drive_line.peak", "trolley_drive.peak"):
        swept = found.largest(output, values)
        reference = found.per_design(output, values, exact=False)
        assert swept.shape == (3, 4) and np.all(reference > 0)
        np.testing.assert_allclose(swept, reference, rtol=1e-9)
    phases = seen[-1].phases.reshape(3, 4)
    assert len({tuple(row) for row in phases}) == 3     # each torque its own sequence
    assert seen[-1].summary["capped"] == 0
