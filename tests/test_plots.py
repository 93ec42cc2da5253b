"""Scene plots as a reader sees them: every shipped scene's figures hold at most
four panels, one title each, legends outside the data area, labels in
mathtext that render (Cyrillic included) without a missing glyph."""
from __future__ import annotations

import re
import warnings

import numpy as np
import pytest
from matplotlib.backends.backend_agg import FigureCanvasAgg

from crane_sym.scenes import plots
from crane_sym.scenes.run import run_scene
from crane_sym.scenes.reading import Panel, list_scenes


def _figures(name: str, folder) -> list:
    """[(figure, path)] of scene ``name``, as `crane-sym run` writes them."""
    seen = []
    save = plots.save

    def keep(fig, path):
        seen.append((fig, path))
        return save(fig, path)

    with pytest.MonkeyPatch.context() as mp:
        mp.setattr(plots, "save", keep)
        _, paths = run_scene(name, folder)
    # each figure drawn to a temporary, renamed onto its path at the end
    assert len(paths) == len(seen) and all(p.is_file() for p in paths)
    return [(fig, path) for (fig, _), path in zip(seen, paths)]


def _draw(fig):
    """Render ``fig``; a glyph missing from the font is an error."""
    canvas = FigureCanvasAgg(fig)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        canvas.draw()
    return canvas.get_renderer()


def _panels_and_title(fig, path) -> None:
    """At most four panels, one figure title, each panel's own title."""
    axes = fig.get_axes()
    assert 1 <= len(axes) <= plots.MAX_PANELS, path
    # one figure title (the suptitle), no other text on the figure
    assert fig.get_suptitle() and [t.get_text() for t in fig.texts] == [fig.get_suptitle()]
    titles = [ax.get_title() for ax in axes]
    if len(axes) == 1:
        assert titles == [""], path          # its caption is in the figure's title
    else:
        assert all(titles) and len(set(titles)) == len(titles), path
    width, height = fig.get_size_inches() * 120
    assert height <= 1600 and width <= 1300, path


def _legends_outside_the_data(fig, path) -> None:
    """Legends outside the data area and inside the figure."""
    renderer = _draw(fig)
    page = fig.bbox
    for ax in fig.get_axes():
        legend = ax.get_legend()
        lines = [ln for ln in ax.get_lines() if not ln.get_label().startswith("_")]
        if len(lines) < 2:
            continue
        assert legend is not None, path
        box, data = legend.get_window_extent(renderer), ax.get_window_extent(renderer)
        assert not box.overlaps(data), (path, ax.get_title())
        assert page.x0 <= box.x0 and box.x1 <= page.x1, path       # not cut off
        assert page.y0 <= box.y0 and box.y1 <= page.y1, path
        for line in lines:                   # no data point under the legend
            xy = ax.transData.transform(line.get_xydata())
            inside = ((xy[:, 0] >= box.x0) & (xy[:, 0] <= box.x1)
                      & (xy[:, 1] >= box.y0) & (xy[:, 1] <= box.y1))
            assert not inside.any(), (path, line.get_label())


def _outside_math(text: str) -> str:
    return re.sub(r"\$[^$]*\$", "", text)


def _symbols_in_mathtext(fig, path) -> None:
    """Subscripts and Cyrillic qualifiers sit inside $...$ (mathtext), never
    as plain text such as K_дин or x_ст."""
    for ax in fig.get_axes():
        texts = [ax.get_xlabel(), ax.get_ylabel(), ax.get_title()]
        texts += [ln.get_label() for ln in ax.get_lines()
                  if not ln.get_label().startswith("_")]
        for text in texts:
            plain = _outside_math(text)
            assert "_" not in plain and not re.search("[а-яА-Я]", plain), (path, text)


@pytest.mark.parametrize("name", list_scenes())
def test_each_scene_s_figures_read_well(name, tmp_path):
    """Each figure a shipped scene writes: at most four panels and one title,
    legends outside the data and inside the figure, symbols in mathtext that
    renders without a missing glyph. One test a scene, so that each scene runs
    once (a fixture of all of them ran them all on every pytest-xdist worker)."""
    for fig, path in _figures(name, tmp_path):
        _panels_and_title(fig, path)
        _legends_outside_the_data(fig, path)
        _symbols_in_mathtext(fig, path)


def test_drive_laws_are_split_by_lifting_case():
    """Nine panels become three figures: pick-up, from weight, Table 1."""
    def panel(group: str, k: int) -> Panel:
        return Panel(f"p{k}", "y", [("a", np.arange(3.0), np.arange(3.0))], group=group)
    nine = [panel("pick-up", k) for k in range(4)] + [panel("weight", k) for k in range(4)]
    nine.append(panel("", 8))
    assert [(g, len(ps)) for g, ps in plots.layout(nine)] == [("pick-up", 4), ("weight", 4),
                                                              ("", 1)]
    assert [len(ps) for _, ps in plots.layout([panel("", k) for k in range(9)])] == [3, 3, 3]
    assert [len(ps) for _, ps in plots.layout([panel("", k) for k in range(5)])] == [3, 2]
    titles = [f.get_suptitle() for f in plots.figures(nine, "Scene")]
    assert titles == ["Scene: pick-up", "Scene: weight", "Scene\np8"]


def test_a_panel_title_the_figure_title_already_says_is_not_repeated():
    """Fig. 10's scene title holds its panel's title: one line, not two."""
    curve = [("a", np.arange(3.0), np.arange(3.0))]
    said = plots.figures([Panel("Fig. 10: shift limits", "x", curve)],
                         "Paper 003, Fig. 10: shift limits against z")[0]
    assert said.get_suptitle() == "Paper 003, Fig. 10: shift limits against z"
    new = plots.figures([Panel("Fig. 10: shift limits", "x", curve)], "Paper 003, a gear")[0]
    assert new.get_suptitle() == "Paper 003, a gear\nFig. 10: shift limits"


def test_cyrillic_inside_mathtext_renders():
    fig = plots.figures([Panel(r"$K_\mathrm{дин}$", r"$x_\mathrm{ст}$",
                               [(r"$K_\mathrm{дин}(t)$", [0, 1], [0, 1]),
                                (r"$x/x_\mathrm{ст}$", [0, 1], [1, 0])])], "title")[0]
    _draw(fig)                                   # raises on a missing glyph
    fig = plots.figures([Panel("t", "\u0b85", [("y", [0, 1], [0, 1])])], "x")[0]
    with pytest.raises(UserWarning, match="missing from"):
        _draw(fig)                               # the check can fail: a Tamil letter


def test_bench_plot_splits_into_figures_of_three_panels(tmp_path, monkeypatch):
    from crane_sym.bench import report
    from crane_sym.bench.rows import GENERATED, INTEGRATOR, BenchRow
    rows = [BenchRow("demo", f"f{k}", method, 1e-3 * (1 + j), 100, err * (k + 1), 1.0,
                     err * (k + 1), kind=kind)
            for k in range(6)
            for j, (method, err, kind) in enumerate([("generated", 1e-16, GENERATED),
                                                     ("RK45 rtol=1e-3 [x]", 1e-3, INTEGRATOR),
                                                     ("RK45 rtol=1e-9 [x]", 1e-9, INTEGRATOR)])]
    made = []
    save = plots.save
    monkeypatch.setattr(report, "save", lambda fig, path, dpi=120: made.append(fig)
                        or save(fig, path, dpi))          # the name the bench report calls
    paths = report.plot(rows, tmp_path / "bench_demo.png", "demo")
    assert paths == [tmp_path / f"bench_demo_{k}.png" for k in (1, 2)]
    assert all(p.read_bytes()[:4] == b"\x89PNG" for p in paths)
    assert [sum(ax.get_visible() for ax in f.get_axes()) for f in made] == [3, 3]
    assert [f.get_suptitle() for f in made] == [f"demo, {k} of 2" for k in (1, 2)]
    for fig in made:                             # the legend lies below the panels
        renderer = _draw(fig)
        (legend,) = fig.legends
        box = legend.get_window_extent(renderer)
        assert not any(box.overlaps(ax.get_window_extent(renderer))
                       for ax in fig.get_axes() if ax.get_visible())
    assert report.plot(rows[:9], tmp_path / "bench_3.png", "3") == [tmp_path / "bench_3.png"]
    alone = [r for r in rows if r.kind == GENERATED]      # nothing to compare with
    assert report.plot(alone, tmp_path / "bench_none.png", "none") == []
    assert not (tmp_path / "bench_none.png").exists()


def test_bench_panels_hold_six_curves_and_draw_the_same_runs_once():
    """Nine methods in two coordinate systems: a panel per system, at most six
    curves each; a second function with the very same errors (a force that is a
    constant times the displacement it is computed from) shares its panels,
    whatever the noise of its timings; one with other errors has its own."""
    from crane_sym.bench import report
    from crane_sym.bench.rows import INTEGRATOR, BenchRow
    methods = [f"M{m} rtol=1e-{j} [{system}]" for system in ("x", "y") for m in range(9)
               for j in (3, 9)]
    rows = [BenchRow("demo", name, method, 1e-3, 100, 1e-6 * (1 + k), 1.0, 1e-6 * (1 + k),
                     kind=INTEGRATOR)
            for name in ("displacement", "force") for k, method in enumerate(methods)]
    found = report.panels(rows)
    assert [len(families) for _, _, families in found] == [5, 4, 5, 4]   # 9 = 5 + 4
    assert {title.split("\n")[0] for title, _, _ in found} == {
        "displacement, force (the same errors; times of displacement)"}
    noisy = [r if r.function == "displacement" else BenchRow(
        "demo", r.function, r.method, 1.1e-3, 100, r.max_error_over_peak, 1.0,
        r.max_rel_error, kind=INTEGRATOR) for r in rows]           # timed apart
    assert len(report.panels(noisy)) == 4
    other = [r if r.function == "displacement" else BenchRow(
        "demo", r.function, r.method, 1e-3, 100, r.max_rel_error, 1.0,
        2 * r.max_error_over_peak, kind=INTEGRATOR) for r in rows]
    assert len(report.panels(other)) == 8
