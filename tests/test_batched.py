"""The batched hybrid solver (issue 28, item 1): every design of a seeded grid
of paper 001's emergency stop, hard cases included, against the per-design
solver to 1e-9 of the peak; the vectorised event search against
``first_crossing``; refused designs counted and run per design; a cap stated."""
from __future__ import annotations

from dataclasses import replace

import numpy as np
import pytest

from crane_sym.derivations.hoist_brakes.elastic_batched import HoistFamily, family_from
from crane_sym.derivations.hoist_brakes.model import G, TABLE1
from crane_sym.mechanics.batched_events import all_crossings, first_crossings
from crane_sym.mechanics.batched_forms import batch_forms
from crane_sym.mechanics.batched_signals import Signals
from crane_sym.mechanics.closed_forms import closed_form
from crane_sym.mechanics.phase_table import largest
from crane_sym.mechanics.event_search import first_crossing

RPM = 2 * np.pi / 60


def _base() -> dict[str, float]:
    q = {k: float(v) for k, v in TABLE1.items()}
    q.update(g=float(G), m_p=52e3, omega1=1500 * RPM, delta=np.radians(q["backlash_deg"]))
    return q


def hard_grid(seed: int = 28) -> HoistFamily:
    """Table 1's hoist: a seeded box of ordinary designs and the hard ones:
    backlash down to 0, stiffness over six decades, brakes that hold at once,
    contacts that chatter, a damped mesh."""
    rng = np.random.default_rng(seed)
    base, rows = _base(), []

    def add(zeta: float = 0.0, **kw) -> None:
        rows.append({**base, "zeta": zeta, **kw})
    for _ in range(10):                                           # the ordinary box
        add(c=10 ** rng.uniform(4, 5), delta=np.radians(rng.uniform(0.5, 3)),
            m_p=rng.uniform(0, 52e3), omega1=rng.uniform(500, 1500) * RPM)
    for deg in (0.0, 1e-9, 1e-6, 1e-3):                          # backlash -> 0
        add(delta=np.radians(deg))
    for c in (1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8):                # seven decades
        add(c=c)
    add(omega1=0.0, t_SB=0.0, t_BB=0.0)                           # held from the start
    add(M_SB=1e9, t_SB=0.0)                                       # a brake that holds at once
    add(M_SB=1e9, M_BB=1e9)                                       # both, after their delays
    add(delta=np.radians(0.01), c=1e6)                            # a contact that chatters
    add(delta=np.radians(0.05), c=3e5, m_p=0.0)
    add(zeta=0.02)                                                # a damped mesh
    add(zeta=0.3, delta=np.radians(0.5))
    q = {k: np.array([r[k] for r in rows]) for k in rows[0]}
    zeta = q.pop("zeta")
    plain = family_from(q, 1.0)
    reduced = plain.J1 * plain.J_d / (plain.J1 + plain.J_d)
    return family_from(q, 1.0, b=2 * zeta * np.sqrt(plain.c * reduced))


def _per_design(family: HoistFamily, i: int) -> float:
    run = family.run(i)
    return largest(run.solve(), run.system, run.output, magnitude=True)[1]


@pytest.fixture(scope="module")
def grid():
    family = hard_grid()
    return family, family.peaks()


def test_every_design_of_the_hard_grid_agrees_with_the_per_design_solver(grid):
    family, result = grid
    assert result.summary["capped"] == 0
    assert result.summary["batched"] + result.summary["fallback"] == family.J1.size
    for i in range(family.J1.size):
        expected = _per_design(family, i)
        assert abs(result.value[i]) == pytest.approx(abs(expected), rel=1e-9, abs=1e-12), i


def test_the_hard_cases_are_hard(grid):
    """The grid holds what it claims: a run held from the start, runs of
    hundreds of phases (a chattering contact), and stiffness spanning the
    phase counts."""
    family, result = grid
    held = np.flatnonzero(family.omega0 == 0)
    assert result.phases[held].min() <= 5
    assert result.phases.max() > 200
    assert np.all(result.time >= 0) and np.all(result.time <= family.t_end)


def test_a_refused_design_runs_per_design_and_is_counted():
    """cond_limit below 1 refuses every eigen-decomposition: all designs take
    the per-design route, the same numbers."""
    base = _base()
    q = {k: np.full(3, v) for k, v in base.items()}
    q["c"] = np.array([2e4, 4e4, 8e4])
    family = family_from(q, 1.0)
    forced = family.peaks(cond_limit=0.5, tail=0)
    assert forced.summary["fallback"] == 3 and forced.summary["batched"] == 0
    for i in range(3):
        assert forced.value[i] == _per_design(family, i)


def test_a_defective_eigenvalue_is_refused():
    """A critically damped oscillator has a double real eigenvalue without two
    eigenvectors: the batched closed forms refuse it; the undamped one they take."""
    c, J = 4e4, 20.0
    A = np.zeros((2, 2, 2))
    A[:, 0, 1] = 1.0
    A[:, 1, 0] = -c / J
    A[1, 1, 1] = -2 * np.sqrt(c / J)                  # ζ = 1
    parts, refused = batch_forms(A, np.zeros((2, 2)))
    assert list(refused) == [1] and [list(w) for w, _ in parts] == [[0]]


def test_003_designs_with_twin_eigenvalues_are_batched_to_1e_9(monkeypatch):
    """Designs of the 20 × 20 grid of ``fig12_startup_backlash`` (φ_b = π)
    whose phases have two nearly equal eigenvalues (gaps 1e-9 to 1e-6 of the
    scale: once sent to the per-design route) and their neighbours: all
    batched, twins met, each peak the per-design one to 1e-9."""
    from crane_sym.derivations.portal_travel import sweep_outputs
    from crane_sym.mechanics import batched_forms
    from crane_sym.mechanics.batched_runs import largest_of_runs
    from crane_sym.scenes.reading import load_scene
    met = []
    twins = batched_forms._twins

    def counting(*args):
        met.append(args[-1])
        return twins(*args)
    monkeypatch.setattr(batched_forms, "_twins", counting)
    c, zeta = np.meshgrid(np.linspace(2e6, 8e6, 20), np.linspace(0.02, 0.1, 20), indexing="ij")
    picks = np.array([155, 157, 158, 159, 160, 161])
    scene = load_scene("fig12_startup_backlash")
    values = {k: float(v) for k, v in scene.parameters.items()
              if k in sweep_outputs._PARAMETERS}
    values.update(c_l=c.ravel()[picks], zeta=zeta.ravel()[picks], phi_b=np.pi)
    _, runs = sweep_outputs._designs(values)
    result = largest_of_runs(runs, magnitude=False, max_events=sweep_outputs.MAX_PHASES)
    assert result.summary["fallback"] == 0 and result.summary["batched"] == picks.size
    assert met
    np.testing.assert_allclose(result.value, sweep_outputs.peak_per_design(values, {}),
                               rtol=1e-9)


@pytest.mark.parametrize("pair", ["real", "complex"])
def test_nearly_equal_eigenvalues_are_batched_and_agree_with_mpmath(pair):
    """Two eigenvalues a relative gap g apart (0 and 1e-14: equal, one
    eigenvalue, their mean; 1e-13 … 5e-4: twins), in a coupled system
    (A = S D S⁻¹, S seeded) with a constant input: no design is refused, and
    x(t) of the batched closed form agrees with mpmath's expm of
    [[A, b], [0, 0]] t to 1e-13 of |x| at t = 0.1, 1, 3 (measured: 2.3e-14 at
    most, at g = 1e-14, the mean's t·gap/2; projectors one by one from the
    vectors were 4e-10 off at g = 1e-5; equal up to 10⁻¹² of the scale, the
    pair of g = 1e-13 was 1.3e-13 off and that of g = 1e-12 1.3e-12)."""
    mpmath = pytest.importorskip("mpmath")
    gaps = [0.0, 1e-14, 1e-13, 1e-12, 1e-10, 1e-8, 1e-6, 1e-5, 1e-4, 5e-4]
    rng = np.random.default_rng(39)
    S = rng.normal(size=(4, 4)) + 3 * np.eye(4)
    A, b = [], []
    for g in gaps:
        if pair == "real":                         # -3, -3(1 + g), -0.5 ± 2i
            D = np.diag([-3.0, -3.0 * (1 + g), 0.0, 0.0])
            D[2:, 2:] = [[-0.5, 2.0], [-2.0, -0.5]]
        else:                                      # -0.5 ± 2i, (-0.5 ± 2i)(1 + g)
            D = np.zeros((4, 4))
            D[:2, :2] = [[-0.5, 2.0], [-2.0, -0.5]]
            D[2:, 2:] = (1 + g) * np.array([[-0.5, 2.0], [-2.0, -0.5]])
        A.append(S @ D @ np.linalg.inv(S))
        b.append(rng.normal(size=4))
    A, b = np.array(A), np.array(b)
    x0 = rng.normal(size=(len(gaps), 4))
    parts, refused = batch_forms(A, b)
    assert refused.size == 0
    mpmath.mp.dps = 30
    for rows, form in parts:
        vectors = form.vectors(x0[rows])
        for t in (0.1, 1.0, 3.0):
            got = form.state(np.full(rows.size, t), vectors)
            for r, i in enumerate(rows):
                M = mpmath.zeros(5, 5)
                for p in range(4):
                    M[p, 4] = b[i, p]
                    for q in range(4):
                        M[p, q] = A[i, p, q]
                z = mpmath.expm(M * t) * mpmath.matrix([*x0[i], 1.0])
                exact = np.array([float(z[p]) for p in range(4)])
                assert np.abs(got[r] - exact).max() <= 1e-13 * np.abs(exact).max(), (gaps[i], t)


def test_a_design_past_the_event_cap_is_marked_not_truncated():
    base = _base()
    q = {k: np.full(2, v) for k, v in base.items()}
    q["delta"] = np.radians([3.0, 0.01])
    q["c"] = np.array([4e4, 1e6])
    result = family_from(q, 1.0).peaks(max_events=60, tail=0)
    assert list(result.capped) == [False, True]
    assert np.isnan(result.value[1]) and np.isfinite(result.value[0])
    assert result.summary["capped"] == 1


def test_the_tail_route_continues_where_the_batched_route_stopped():
    family = hard_grid()
    sub = np.arange(10)
    part = HoistFamily(*(getattr(family, f)[sub] for f in (
        "J1", "J_d", "c", "s", "M_L", "M_st", "M_SB", "M_BB", "M_M", "b", "omega0", "t_end",
        "t_M", "t_SB", "t_BB")))
    batched, alone = part.peaks(tail=0), part.peaks(tail=10 ** 6)
    assert alone.summary["finished_alone"] == 10
    np.testing.assert_allclose(np.abs(batched.value), np.abs(alone.value), rtol=1e-9)


def _random_systems(rng, k: int):
    """k random two-mass-like systems x' = A x + b (a pair and a rigid mode)."""
    A = np.zeros((k, 4, 4))
    A[:, 0, 1] = A[:, 2, 3] = 1.0
    c = 10 ** rng.uniform(2, 6, k)
    J1, J2 = rng.uniform(1, 50, k), rng.uniform(1, 500, k)
    damp = rng.uniform(0, 0.2, k) * np.sqrt(c * J1)
    A[:, 1, 0], A[:, 1, 2] = -c / J1, c / J1
    A[:, 3, 0], A[:, 3, 2] = c / J2, -c / J2
    A[:, 1, 1], A[:, 1, 3] = -damp / J1, damp / J1
    b = rng.normal(0, 100, (k, 4)) * np.array([0, 1, 0, 1])
    return A, b


@pytest.mark.parametrize("seed", [1, 2, 3])
def test_vectorised_search_finds_first_crossing_like_the_per_design_one(seed):
    rng = np.random.default_rng(seed)
    k = 40
    A, b = _random_systems(rng, k)
    x0 = rng.normal(0, 1, (k, 4))
    w = rng.normal(0, 1, (k, 4))
    const = rng.normal(0, 0.5, k)
    direction = rng.integers(-1, 2, k).astype(float)
    parts, refused = batch_forms(A, b)
    assert refused.size == 0
    for where, form in parts:
        amps = np.einsum("kti,ki->kt", form.vectors(x0[where])[:, :, :4], w[where])
        sig = Signals.of(form, amps, const[where])
        hits = first_crossings(sig, np.zeros(where.size), np.full(where.size, 0.5),
                               direction[where])
        for j, i in enumerate(where):
            ref = first_crossing(closed_form(A[i], b[i], False), x0[i], w[i], const[i], 0.5,
                                 direction=int(direction[i]))
            if ref is None:
                assert np.isnan(hits[j])
            else:
                assert hits[j] == pytest.approx(ref, abs=1e-12)
        # every crossing, found in one pass, are the successive first crossings
        which, when = all_crossings(sig, np.zeros(where.size), np.full(where.size, 0.5))
        for j in range(min(where.size, 5)):
            found = np.sort(when[which == j])
            i = where[j]
            form1, t, times = closed_form(A[i], b[i], False), 0.0, []
            while True:
                x = form1.state(t, x0[i])
                hit = first_crossing(form1, x, w[i], const[i], 0.5 - t)
                if hit is None or 0.5 - t - hit < 1e-12:
                    break
                t += hit
                times.append(t)
                t += 1e-9
            np.testing.assert_allclose(found[:len(times)], times, atol=1e-9)


def test_the_sweep_output_is_the_per_design_loop_to_1e_9():
    from crane_sym.derivations.hoist_brakes.sweep_outputs import SWEEP_OUTPUTS, peak_per_design
    base = _base()
    c, delta = np.meshgrid([1e4, 3e4, 1e5], np.radians([0.5, 1.5, 3.0]), indexing="ij")
    values = {**{k: v for k, v in base.items() if k in
                 SWEEP_OUTPUTS["peak_elastic_gearbox_torque"].parameters}, "c": c, "delta": delta}
    options = {"duration": 1.0}
    batched = SWEEP_OUTPUTS["peak_elastic_gearbox_torque"].evaluate(values, options)
    assert SWEEP_OUTPUTS["peak_elastic_gearbox_torque"].batched
    np.testing.assert_allclose(batched, peak_per_design(values, options), rtol=1e-9)


def test_bench_row_states_n_rates_and_the_difference():
    from dataclasses import replace

    from crane_sym.bench.batched import bench_batched, markdown_rows
    from crane_sym.bench.cases import batched_cases
    paper, case = next((p, c) for p, c in batched_cases()
                       if c.output == "peak_elastic_gearbox_torque")
    row = bench_batched(paper, replace(case, n=4, sample=3, breakdown=None))
    assert row["designs"] == 16 and row["sample"] == 3
    assert row["max_rel_difference"] <= 1e-9
    assert row["batched_designs_per_second"] > 0 and row["speedup"] > 0
    text = "\n".join(markdown_rows([row]))
    assert "| 001 |" in text or f"| {paper} |" in text
    assert "max rel. difference" in text


def test_a_numpy_bound_batched_output_gets_few_large_blocks_on_threads():
    """001's peaks (``threads=True``): a grid below 2·THREAD_DESIGNS is one
    block; larger ones are cut into blocks of THREAD_DESIGNS to
    THREAD_MAX_DESIGNS designs, one per worker at least, run on threads."""
    from crane_sym.scenes.reading import load_scene
    from crane_sym.sweep.blocks import (THREAD_DESIGNS, THREAD_MAX_DESIGNS, chunks_for,
                                        local_scheduler)
    from crane_sym.sweep.spec import plan
    scene = load_scene("hoist_table1")
    small = plan(scene, ["c=1e4:1e5:40:log", "delta=0.5:3:40"], ["peak_elastic_gearbox_torque"])
    assert [len(c) for c in chunks_for(small, workers=2)] == [1, 1]
    for n, count in ((300, 2), (1000, 20)):
        big = plan(scene, [f"c=1e4:1e5:{n}:log", f"delta=0.5:3:{n}"],
                   ["peak_elastic_gearbox_torque"])
        chunks = chunks_for(big, workers=2)
        blocks = [a * b for a in chunks[0] for b in chunks[1]]
        assert len(blocks) == count and sum(blocks) == n * n
        assert THREAD_DESIGNS <= min(blocks) and max(blocks) <= THREAD_MAX_DESIGNS
        assert local_scheduler(big, chunks) == "threads"


def test_003s_block_runs_on_threads_only_where_its_links_alone_are_swept():
    """003's start-up (``threads=("c_l", "zeta")``, ``thread_block`` 2 500 to
    10⁴): with only the links swept, a grid below 5 000 designs is one block
    in this process, a larger one blocks of 2 500 to 10⁴ designs on
    threads; with any other value swept (each design assembled in Python),
    blocks of at most BATCH_DESIGNS, one per worker, on processes."""
    from crane_sym.scenes.reading import load_scene
    from crane_sym.sweep.blocks import BATCH_DESIGNS, chunks_for, local_scheduler, thread_block
    from crane_sym.sweep.spec import plan
    scene = load_scene("fig12_startup_backlash")
    at = ["phi_b=3.14159"]

    def blocks(chunks):
        return [a * b for a in chunks[0] for b in chunks[1]]
    small = plan(scene, ["c_l=2:8:40", "zeta=0.02:0.1:40"], ["peak_startup_link_force"], at)
    assert thread_block(small) == (2_500, 10_000)
    chunks = chunks_for(small, workers=2)
    assert blocks(chunks) == [1600] and local_scheduler(small, chunks) == "synchronous"
    for n, count in ((100, 2), (300, 10)):           # 300 rows of 300: 30 a block
        links = plan(scene, [f"c_l=2:8:{n}", f"zeta=0.02:0.1:{n}"],
                     ["peak_startup_link_force"], at)
        chunks = chunks_for(links, workers=2)
        sizes = blocks(chunks)
        assert len(sizes) == count and sum(sizes) == n * n
        assert 2_500 <= min(sizes) and max(sizes) <= 10_000
        assert local_scheduler(links, chunks) == "threads"
    long = plan(scene, ["c_l=2:8:2", "zeta=0.02:0.1:30000"], ["peak_startup_link_force"], at)
    sizes = blocks(chunks_for(long, workers=2))          # a row alone past the most
    assert sum(sizes) == 60_000 and max(sizes) <= 10_000
    big = plan(scene, ["c_l=2:8:300", "m_k=1000:3000:300"], ["peak_startup_link_force"], at)
    chunks = chunks_for(big, workers=2)
    assert max(blocks(chunks)) <= BATCH_DESIGNS
    assert local_scheduler(big, chunks) == "processes"


def test_any_hybrid_run_goes_through_the_batched_solver():
    """Per-design runs of 001 seen as one family (each design's own Python
    rules, stacked) give the vectorised family's numbers."""
    from crane_sym.mechanics.batched_runs import largest_of_runs
    family = hard_grid()
    sub = list(range(8)) + [11, 14]
    runs = [family.run(i) for i in sub]
    result = largest_of_runs(runs, tail=0)
    assert result.summary["batched"] == len(sub)
    for k, i in enumerate(sub):
        assert abs(result.value[k]) == pytest.approx(abs(_per_design(family, i)), rel=1e-9)


def test_003_start_up_with_repeated_eigenvalues_is_batched():
    """Paper 003's travel drive has two equal sides: its modes have repeated
    eigenvalues, clustered with one projector each; the largest signed F1 + F2
    of each start-up agrees to 1e-9. One design's last phase has a nearly
    equal pair (-86.49137 and -86.49131, not defective: ‖(A − c)P‖ is the gap
    times ‖P‖), twins whose projectors come from their pair's: batched too."""
    from crane_sym.derivations.portal_travel.hybrid import STARTUP, rim_values
    from crane_sym.derivations.portal_travel.startup import CHOSEN, HOLDS
    from crane_sym.mechanics.batched_runs import largest_of_runs
    rng = np.random.default_rng(3)
    runs = []
    for k in range(8):
        p = {**CHOSEN, "c_l": 10 ** rng.uniform(6, 7.3), "zeta": rng.uniform(0.0, 0.1)}
        runs.append(STARTUP.run(rim_values(p, (0.0, np.pi, 2 * np.pi, 1.0)[k % 4]),
                                {"holds": HOLDS, "end": 4.0}))
    result = largest_of_runs(runs, magnitude=False, tail=0)
    assert result.summary["batched"] == 8 and result.summary["fallback"] == 0
    expected = [largest(r.solve(), r.system, r.output)[1] for r in runs]
    np.testing.assert_allclose(result.value, expected, rtol=1e-9)


def test_003_start_up_peak_is_sweepable_and_is_the_per_design_peak(tmp_path):
    xr = pytest.importorskip("xarray")
    from crane_sym.derivations.portal_travel.sweep_outputs import peak_per_design
    from crane_sym.scenes.reading import load_scene
    from crane_sym.sweep.grid import run_sweep
    from crane_sym.sweep.spec import plan
    chosen = plan(load_scene("fig12_startup_backlash"), ["c_l=2:8:2", "zeta=0.02:0.1:2"],
                  ["peak_startup_link_force"], ["phi_b=3.14159"])
    result = run_sweep(chosen, tmp_path / "sweep", scheduler="synchronous")
    swept = xr.open_zarr(result.dataset)["peak_startup_link_force"].values
    c, zeta = np.meshgrid(*[a.si() for a in chosen.axes], indexing="ij")
    values = {a: chosen.fixed[a] for a in chosen.output("peak_startup_link_force").args
              if a in chosen.fixed}
    expected = peak_per_design({**values, "c_l": c, "zeta": zeta}, {})
    np.testing.assert_allclose(swept, expected, rtol=1e-9)
    assert swept.max() > swept.min() > 0


def test_a_batched_sweep_on_a_local_cluster_is_bit_for_bit_the_local_one(tmp_path,
                                                                           monkeypatch):
    """A design gives the same bits wherever it runs and whichever designs
    share its block (each distinct A is decomposed alone, b enters per
    design, no design finishes by the per-design route): the grid is one
    block in this process and three on the cluster's two workers."""
    distributed = pytest.importorskip("distributed")
    xr = pytest.importorskip("xarray")
    from crane_sym.scenes.reading import load_scene
    from crane_sym.sweep import blocks
    from crane_sym.sweep.grid import run_sweep
    monkeypatch.setattr(blocks.os, "cpu_count", lambda: 2)
    from crane_sym.sweep.spec import plan
    chosen = plan(load_scene("hoist_table1"), ["c=1e4:1e5:12:log", "delta=0.5:3:10"],
                  ["peak_elastic_gearbox_torque"])
    local = run_sweep(chosen, tmp_path / "local")
    monkeypatch.setattr(blocks, "THREAD_DESIGNS", 40)    # blocks of 40 on the cluster
    monkeypatch.setattr(blocks, "THREAD_MAX_DESIGNS", 40)
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                  dashboard_address=":0") as cluster:
        remote = run_sweep(chosen, tmp_path / "cluster", scheduler=cluster.scheduler_address)
    assert local.blocks == 1 and local.scheduler == "synchronous" and remote.blocks > 1
    a, b = (xr.open_zarr(r.dataset).load()["peak_elastic_gearbox_torque"].values
            for r in (local, remote))
    assert np.array_equal(a.view(np.uint64), b.view(np.uint64)) and local.worst == remote.worst


def test_003s_blocks_on_threads_are_bit_for_bit_its_one_block(tmp_path, monkeypatch):
    """003's start-up with its links swept runs its blocks side by side on
    Dask's threads (``threads``): each design's bits are the ones it gets in
    one block in this process (no state shared between the threads' runs)."""
    xr = pytest.importorskip("xarray")
    from crane_sym.scenes.reading import load_scene
    from crane_sym.sweep import blocks
    from crane_sym.sweep.grid import run_sweep
    from crane_sym.sweep.spec import plan
    from crane_sym.derivations.portal_travel import sweep_outputs
    chosen = plan(load_scene("fig12_startup_backlash"), ["c_l=2:8:8", "zeta=0.02:0.1:6"],
                  ["peak_startup_link_force"], ["phi_b=3.14159"])
    one = run_sweep(chosen, tmp_path / "one")
    monkeypatch.setattr(blocks.os, "cpu_count", lambda: 2)
    spec = sweep_outputs.SWEEP_OUTPUTS["peak_startup_link_force"]
    monkeypatch.setitem(sweep_outputs.SWEEP_OUTPUTS, "peak_startup_link_force",
                        replace(spec, thread_block=(12, 12)))     # 4 blocks of 2 × 6
    threaded = run_sweep(chosen, tmp_path / "threads")
    assert one.blocks == 1 and one.scheduler == "synchronous"
    assert threaded.blocks == 4 and threaded.scheduler == "threads"
    a, b = (xr.open_zarr(r.dataset).load()["peak_startup_link_force"].values
            for r in (one, threaded))
    assert np.array_equal(a.view(np.uint64), b.view(np.uint64)) and one.worst == threaded.worst


def test_with_out_each_simulated_block_is_computed_once(tmp_path, monkeypatch):
    """Summaries, PNG data and the Zarr store read the same blocks: each block
    of a simulated output is evaluated once (Dask's optimisation renamed its
    tasks for each reader, three evaluations a block)."""
    pytest.importorskip("xarray")
    from crane_sym.scenes.reading import load_scene
    from crane_sym.sweep import grid
    from crane_sym.sweep.spec import plan
    calls = []
    evaluate = grid.evaluate_block

    def counting(*args):
        if all(len(b) for b in args[7:]):            # not Dask's zero-size probe
            calls.append(tuple(len(b) for b in args[7:]))
        return evaluate(*args)
    monkeypatch.setattr(grid, "evaluate_block", counting)
    from crane_sym.sweep import blocks
    monkeypatch.setattr(blocks, "THREAD_DESIGNS", 40)   # several blocks of a small grid
    monkeypatch.setattr(blocks, "THREAD_MAX_DESIGNS", 40)
    chosen = plan(load_scene("hoist_table1"), ["c=1e4:1e5:12:log", "delta=0.5:3:10"],
                  ["peak_elastic_gearbox_torque"])
    result = grid.run_sweep(chosen, tmp_path / "out", scheduler="synchronous")
    assert result.blocks > 1 and len(calls) == result.blocks
    assert result.dataset.exists() and result.view is not None


def test_designs_past_the_phase_cap_are_flagged_in_the_sweep_not_an_error(tmp_path,
                                                                             monkeypatch):
    """A grid whose stiff, nearly backlash-free corner chatters past the cap:
    the sweep finishes, those designs are NaN and flagged in the dataset with
    the cap as an attribute, the summary counts them, and the worst case is
    taken over the others."""
    xr = pytest.importorskip("xarray")
    from dataclasses import replace

    from crane_sym.derivations.hoist_brakes import sweep_outputs
    from crane_sym.scenes.reading import load_scene
    from crane_sym.sweep.grid import run_sweep
    from crane_sym.sweep.report import summary, text_lines
    from crane_sym.sweep.spec import plan
    monkeypatch.setattr(sweep_outputs, "MAX_PHASES", 60)
    spec = sweep_outputs.SWEEP_OUTPUTS["peak_elastic_gearbox_torque"]
    monkeypatch.setitem(sweep_outputs.SWEEP_OUTPUTS, spec.name, replace(spec, cap=60))
    chosen = plan(load_scene("hoist_table1"), ["c=4e4:1e6:3:log", "delta=0.01:3:3"],
                  ["peak_elastic_gearbox_torque"])
    result = run_sweep(chosen, tmp_path / "out", scheduler="synchronous")
    data = xr.open_zarr(result.dataset).load()
    values = data["peak_elastic_gearbox_torque"].values
    flag = data["peak_elastic_gearbox_torque_capped"].values
    assert flag.dtype == bool and 0 < flag.sum() < flag.size
    assert np.array_equal(flag, np.isnan(values))
    assert data["peak_elastic_gearbox_torque"].attrs["cap_phases"] == 60
    assert result.capped["peak_elastic_gearbox_torque"] == int(flag.sum())
    worst, index = result.worst["peak_elastic_gearbox_torque"]
    assert worst == np.nanmax(values) and values[index] == worst
    lines = "\n".join(text_lines(summary(result)))
    assert f"{int(flag.sum())} of 9 designs stopped at the cap of 60 phases" in lines


def test_certify_of_a_hybrid_output_is_refused_in_one_line_naming_it(tmp_path, capsys):
    """--certify of a batched hybrid output: exit 2, one line naming the
    output and why (no enclosure of the event times), nothing written."""
    from crane_sym.cli.main import main
    out = tmp_path / "out"
    argv = ["sweep", "hoist_table1", "--vary", "c=1e4:1e5:3:log", "--vary", "delta=0.5:3:3",
            "--output", "peak_elastic_gearbox_torque", "--certify", "--out", str(out),
            "--quiet"]
    assert main(argv) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1
    assert "--certify" in err and "peak_elastic_gearbox_torque" in err
    assert "hybrid run" in err and "event times" in err
    assert not out.exists()


def test_target_rows_say_met_or_not_met():
    """Section (f) prints each target with its limit and met / not met, from
    the measured numbers (not a fixed verdict)."""
    from crane_sym.bench.batched_targets import markdown_rows
    one = {"designs": 10_000, "output": "peak", "batched_seconds": 1.5,
           "batched_cpu_seconds": 1.2, "sample": 3, "speedup": 600.0, "repeats": 3,
           "batched_seconds_all": [1.7, 1.5, 1.6]}
    ivp = [{"accuracy": tol, "per_design_seconds": 0.07, "sample": 3, "designs": 10_000,
            "extrapolated_seconds": 700.0, "speedup": s, "target": t, "met": s >= t,
            "settings": ["DOP853 rtol=1e-09"], "integrator_runs": 78,
            "runs_with_other_phase_count": 20}
           for tol, s, t in ((1e-6, 150.0, 100.0), (1e-9, 900.0, 1000.0))]
    text = "\n".join(markdown_rows({"one_block": one, "ivp": ivp}))
    rows = [line for line in text.splitlines() if line.startswith("| ") and "---" not in line]
    verdicts = [line.rstrip(" |").rsplit("| ", 1)[1] for line in rows[1:]]
    assert verdicts == ["not met", "met", "met", "not met"]
    assert "least of 3: 1.70, 1.50, 1.60 s" in rows[1]


def test_equal_designs_are_grouped_byte_for_byte_even_when_their_hashes_collide(monkeypatch):
    """Designs are grouped by a hash of their bytes, checked byte for byte: a
    hash that maps every row to one value (a collision) falls back to the
    sort of rows and groups the same; -0.0 and 0.0 differ in bytes."""
    from crane_sym.mechanics import batched_spectra
    rng = np.random.default_rng(5)
    base = rng.normal(size=(7, 6))
    rows = np.ascontiguousarray(base[rng.integers(0, 7, size=200)])
    rows[3, 2] = -0.0 if rows[3, 2] == 0.0 else rows[3, 2]
    rows = np.concatenate([rows, np.zeros((1, 6)), -np.zeros((1, 6))])
    first, inverse = batched_spectra.first_of_equal(rows)
    assert np.array_equal(rows[first][inverse].view(np.int64), rows.view(np.int64))
    assert len(first) == len({r.tobytes() for r in rows})
    monkeypatch.setitem(batched_spectra._MIX, rows.shape[1], np.zeros(rows.shape[1], np.int64))
    first2, inverse2 = batched_spectra.first_of_equal(rows)
    assert np.array_equal(rows[first2][inverse2].view(np.int64), rows.view(np.int64))
    assert len(first2) == len(first)


@pytest.mark.parametrize("first_point", ["secant", "cubic and curvature"])
def test_refine_finds_each_root_to_xtol_against_mpmath(first_point):
    """Roots of g = a cos ωt + b sin ωt + c₁t + c₀ in brackets of the search's
    kind, refined from the secant or from the cubic through both ends'
    values and slopes with the stop a curvature bound allows: each within
    xtol + 4 ulp of mpmath's root at 30 digits."""
    import mpmath

    from crane_sym.mechanics.batched_events import refine
    rng = np.random.default_rng(11)
    k = 64
    a, b = rng.normal(size=k), rng.normal(size=k)
    w, c1 = rng.uniform(1, 300, k), rng.normal(size=k)
    t0 = rng.uniform(0, 0.5, k)
    c0 = -(a * np.cos(w * t0) + b * np.sin(w * t0) + c1 * t0)      # a root at t0
    sig = Signals(np.zeros((k, 0)), np.zeros((k, 0)), a[:, None], b[:, None],
                  np.zeros((k, 1)), w[:, None], np.stack([c0, c1], axis=1))
    slope = -a * w * np.sin(w * t0) + b * w * np.cos(w * t0) + c1
    width = 0.5 * np.abs(slope) / (w * w * np.hypot(a, b))          # g monotone on it
    lo, hi = t0 - rng.uniform(0.1, 1, k) * width, t0 + rng.uniform(0.1, 1, k) * width
    rows = np.arange(k)
    (fl, dl), (fh, dh) = sig.both(rows, lo), sig.both(rows, hi)
    flip = np.sign(fl) == np.sign(fh)
    assert not flip.any() and np.all(np.abs(slope) > 0)
    options = {} if first_point == "secant" else {
        "curvature": w * w * np.hypot(a, b), "slopes": (dl, dh)}
    found = refine(sig, rows, lo, hi, 1e-14, 0.0, fl, fh, **options)
    mpmath.mp.dps = 30
    for i in range(k):
        ai, bi, wi, c1i, c0i = (mpmath.mpf(float(v[i])) for v in (a, b, w, c1, c0))

        def g(t):
            return ai * mpmath.cos(wi * t) + bi * mpmath.sin(wi * t) + c1i * t + c0i
        root = mpmath.findroot(g, (mpmath.mpf(float(lo[i])), mpmath.mpf(float(hi[i]))),
                               solver="illinois", tol=mpmath.mpf(10) ** -28)
        assert abs(found[i] - float(root)) <= 1e-14 + 4 * np.spacing(float(root))


def test_003_starts_found_together_are_each_designs_own():
    """003's start-up from rest, its wind either side of the friction that
    holds the crane (held, or sliding at once), the wind or the friction 0
    in some designs (other templates: no wind, no brake): the starts found together
    (``rest_runs``) are each design's own (``hybrid_run``) to the bit, and
    their peaks the per-design ones to 1e-9."""
    from crane_sym.derivations.portal_travel import sweep_outputs
    from crane_sym.mechanics.batched_runs import largest_of_runs
    from crane_sym.scenes.reading import load_scene
    scene = load_scene("fig12_startup_backlash")
    values = {k: float(v) for k, v in scene.parameters.items()
              if k in sweep_outputs._PARAMETERS}
    wind = np.array([0.0, 2e4, 2.9e4, 3.1e4, 6e4, 2e4])
    friction = np.array([3e4, 3e4, 3e4, 3e4, 3e4, 0.0])
    values.update(W_w=wind, W_f=friction, phi_b=np.pi)
    _, together = sweep_outputs._designs(values)
    _, alone = sweep_outputs._designs(values, together=False)
    # three templates: friction and wind, no wind (W_w = 0), no friction (W_f = 0)
    assert len({id(r.system.equations.linear) for r in together}) == 3
    motions = set()
    for a, b in zip(together, alone):
        assert a.mode == b.mode
        np.testing.assert_array_equal(a.x0, b.x0)
        motions.add(a.mode.motion)
    assert len(motions) >= 2                       # held in some designs, sliding in others
    result = largest_of_runs(together, magnitude=False, max_events=sweep_outputs.MAX_PHASES)
    np.testing.assert_allclose(result.value, sweep_outputs.peak_per_design(values, {}),
                               rtol=1e-9)
