"""Scene options declared by each paper and checked on load:
every bad option, unknown key, broken condition between options and
parameters, and drive law beyond its limits is refused by ``load_scene`` with
one line naming it; ``run`` and ``generate --scene`` exit 2 with that line and
write nothing. Bench options are refused by name before any folder is made."""
from __future__ import annotations

import re
from pathlib import Path

import pytest
from sympy.physics.units import mass

from crane_sym import registry
from crane_sym.cli.main import main
from crane_sym.scenes.options import (REQUIRED, OptionError, SceneCheck, SceneOption,
                                      options_for, read_options)
from crane_sym.scenes.reading import SceneError, list_scenes, load_scene, scene_path

ROOT = Path(__file__).resolve().parents[1]
LAW = "hoist_user_drive_law"
COEFFICIENTS = """coefficients = [
    [0.0, 2.0],     # a = 2 t                 [m/s^2], [m/s^3]
    [0.5],          # a = 0.5
    [0.5, -2.0],    # a = 0.5 - 2 (t - 1.0)
]"""


def _law(breakpoints: list[float], rows: list[list[float]]) -> dict[str, str]:
    return {"breakpoints = [0.0, 0.25, 1.0, 1.25]": f"breakpoints = {breakpoints}",
            COEFFICIENTS: f"coefficients = {rows}"}


#: (case, shipped scene, {text: replacement}, what the one line says)
BAD = [
    # [options] read by their declarations
    ("integrator not among solve_ivp's", "drum_drive_example",
     {'method = "LSODA"': 'method = "Foo"'},
     r"\[options\] method \(integrator of scipy.integrate.solve_ivp\) must be one of "
     r"'RK23', 'RK45', 'DOP853', 'Radau', 'BDF', 'LSODA', got 'Foo'$"),
    ("negative simulation-only mass", "drum_drive_example",
     {'m3 = "800 kg"': 'm3 = "-800 kg"'},
     r"\[options\] m3 \(mass of the drum .*\) must be a quantity of mass \(e.g. kg\) in "
     r"\[5e-05, 5e\+09\] kg, got '-800 kg'$"),
    ("simulation-only mass missing", "drum_drive_example",
     {'m_L_empty = "1000 kg"': ""}, r"\[options\] lacks 'm_L_empty' \(mass of the run "
                                    r"without loads\), a quantity of mass"),
    ("load on the run of the wrong dimension", "drum_drive_undamped",
     {'W = "1 kN"': 'W = "1 kg"'}, r"option 'W' expects force \(e.g. N\), got '1 kg' which "
                                   r"is mass; W \(.*\) must be a quantity of force"),
    ("z_min above z_max", "fig10_shift_limits", {"z_min = 8": "z_min = 120"},
     r"\[options\] z_min = 120 must be below z_max = 100$"),
    ("z_min not an integer", "fig10_shift_limits", {"z_min = 8": 'z_min = "8"'},
     r"\[options\] z_min \(smallest tooth number of Fig. 10\) must be an integer in "
     r"3..10000, got '8'$"),
    ("centre distance too small", "form1_gear_pair", {'a_w = "340 mm"': 'a_w = "100 mm"'},
     r"a_w: the centre distance is too small for this mesh"),
    ("undercut pinion when forbidden", "form1_gear_pair",
     {'z1 = "25"': 'z1 = "10"', 'a_w = "340 mm"': 'a_w = "260 mm"'},
     r"z1 = 10 teeth are undercut with shift \S+: the shift must be at least 0.415"),
    ("pinion share above 1", "form1_gear_pair", {"pinion_share = 1.0": "pinion_share = 2"},
     r"\[options\] pinion_share \(.*\) must be a number in \[0, 1\], got 2$"),
    ("forbid_undercut not a bool", "form1_gear_pair",
     {"forbid_undercut = true": 'forbid_undercut = "yes"'},
     r"\[options\] forbid_undercut \(.*\) must be true or false, got 'yes'$"),
    ("reach not a number", "portal_support_loads",
     {"largest_reach_m = 30.0": 'largest_reach_m = "x"'},
     r"\[options\] largest_reach_m \(largest reach of the crane\) must be a number in "
     r"\[5e-05, 4e\+07\] m, got 'x'$"),
    ("backlash negative", "fig12_startup_backlash",
     {'backlash = ["0 rad", "0.5 rev", "1 rev"]': 'backlash = ["-1 rad"]'},
     r"\[options\] backlash \(.*\) must be a list of 1..6 quantities of dimensionless .*"
     r"got \['-1 rad'\]$"),
    ("plot ends before the start does", "fig12_startup_backlash",
     {'end = ["4 s"]': 'end = ["1 s"]'},
     r"\[options\] end = 1 s must exceed the sum of the holds, 2 s$"),
    ("synchronous speed below rated", "fig12_startup_backlash",
     {'omega_0 = "1000 rpm"': 'omega_0 = "900 rpm"'},
     r"parameter 'omega_0' \(no-load speed\) = 94.2478 rad/s must exceed omega_n"),
    ("payload above rated", "hoist_table1", {'m_p = "52 t"': 'm_p = "60 t"'},
     r"parameter 'm_p' \(payload\) = 60000 kg is above the rated payload m_r = 52000 kg"),
    ("payload limit not a choice", "hoist_table1",
     {'payload_limit = "rated"': 'payload_limit = "maybe"'},
     r"\[options\] payload_limit \(.*\) must be one of 'rated', 'any', got 'maybe'$"),
    ("figure unknown, with a hint", "hoist_fig3", {'figure = "fig3"': 'figure = "fig4"'},
     r"must be one of 'fig3', 'fig5', 'drive_laws', got 'fig4'; did you mean 'fig[35]' or "
     r"'fig[35]'\?$"),
    ("Omega that (2) does not give", "hoist_fig3", {'Omega = "25 rad/s"': 'Omega = "26 rad/s"'},
     r"parameter 'Omega' = 26.0 does not follow from m1, m2, C: \(2\)"),
    ("figure without its parameters", "hoist_fig3",
     {'figure = "fig3"': 'figure = "drive_laws"'},
     r"figure 'drive_laws' reads the parameters \['g', 'v0', 't_n', 'tau_0'\]"),
    ("points out of range", "overhead_crane_50t", {"points = 1501": "points = 0"},
     r"\[options\] points \(time samples on \[0, duration\]\) must be an integer in "
     r"2..1000000, got 0$"),
    # unknown keys in every table, with the closest name
    ("unknown option", "overhead_crane_50t",
     {'duration = "1.5 s"': 'duration = "1.5 s"\npointz = 5'},
     r"unknown \[options\] key 'pointz'; did you mean 'points'\? this scene takes "
     r"duration, points$"),
    ("option of another kind of scene", LAW,
     {'duration = "2.5 s"': 'duration = "2.5 s"\nfigure = "fig3"'},
     r"unknown \[options\] key 'figure'; this scene takes duration, points$"),
    ("unknown [scene] key", "overhead_crane_50t",
     {'title = "50 t': 'titel = "x"\ntitle = "50 t'},
     r"unknown \[scene\] key 'titel'; did you mean 'title'\?"),
    ("unknown table", "overhead_crane_50t", {"[options]": "[option]\n[options]"},
     r"unknown table 'option'; did you mean 'options'\? expected scene, parameters, options$"),
    ("unknown parameter", "overhead_crane_50t", {'W = "11 kN"': 'W = "11 kN"\nWW = "1 kN"'},
     r"unknown parameter 'WW'; did you mean 'W'\?"),
    ("unknown [drive_law] key", LAW, {'time_unit = "s"': 'time_units = "s"'},
     r"\[drive_law\] has unknown keys \['time_units'\]; did you mean 'time_unit'\?"),
    # bounded symbolic work: a drive law beyond its limits
    ("coefficient of 1e308", LAW, _law([0.0, 1.0], [[1e308]]),
     r"\[drive_law\] coefficients\[0\]\[0\] = 1e\+308 \(SI\) is too large: \|c\| = 1e\+308 "
     r"m/s\^2, more than 1000 m/s\^2$"),
    ("a high power late in the law", LAW,
     _law([0.0, 990.0, 1000.0], [[0.0], [0, 0, 0, 0, 1e-6]]),
     r"coefficients\[1\]\[4\] = 1e-06 \(SI\) is too large: \|c\|\*b\^4 = 1e\+06 m/s\^2 "
     r"\(b = 1000 s, the piece's end\), more than 1000 m/s\^2$"),
    ("a piece shorter than 10 ms", LAW, _law([0.0, 0.001], [[1.0]]),
     r"piece 0 \[0 s, 0.001 s\] lasts 0.001 s, less than 0.01 s, the shortest piece$"),
    ("degree-60 piece", LAW, _law([0.0, 1.0], [[0.1] * 61]),
     r"\[drive_law\] coefficients\[0\] has degree 60; at most 5 is allowed"),
    ("2,000 breakpoints", LAW, _law([k / 1000 for k in range(2000)], [[0.1]] * 1999),
     r"\[drive_law\] has 1999 pieces; at most 5 are allowed"),
    ("six pieces", LAW, _law([0.0, 0.1, 0.2, 0.3, 0.4, 0.5, 0.6], [[0.1]] * 6),
     r"\[drive_law\] has 6 pieces; at most 5 are allowed \(len\(coefficients\) <= 5\)$"),
    ("a span of 40 periods where maxima are certified", LAW,
     {'duration = "2.5 s"': 'duration = "10 s"'},
     r"\[options\] duration = 10 s holds 39.79 periods 2 pi/Omega = 0.2513 s; at most 20 "
     r"are allowed where the maximum is certified \(duration <= 5.027 s\)$"),
    ("the same for the figure of the drive laws", "hoist_drive_laws",
     {'duration = "2 s"': 'duration = "100 s"'}, r"holds 397.9 periods"),
    ("a law that ends after 1000 s", LAW, _law([0.0, 2000.0], [[0.0]]),
     r"\[drive_law\] breakpoints\[1\] = 2000 s is after 1000 s"),
]


def _scene(tmp_path: Path, base: str, edits: dict[str, str]) -> Path:
    text = scene_path(base).read_text(encoding="utf-8")
    for old, new in edits.items():
        assert old in text, (base, old)
        text = text.replace(old, new, 1)
    path = tmp_path / f"bad_{base}.toml"
    path.write_text(text, encoding="utf-8")
    return path


@pytest.mark.parametrize("case, base, edits, message", BAD, ids=[b[0] for b in BAD])
def test_bad_scene_is_refused_on_load_and_nothing_is_written(case, base, edits, message,
                                                             tmp_path, capsys):
    path = _scene(tmp_path, base, edits)
    with pytest.raises(SceneError) as refused:
        load_scene(path)
    assert re.search(message, str(refused.value)), str(refused.value)
    for command in (["run", str(path), "--out", str(tmp_path / "run")],
                    ["generate", "--scene", str(path), "--out", str(tmp_path / "gen")]):
        capsys.readouterr()
        assert main(command) == 2, command
        out, err = capsys.readouterr()
        assert out == "" and err.count("\n") == 1, err
        assert err.startswith("crane-sym: error: scene ") and re.search(message, err), err
    for folder in ("run", "gen"):
        assert not (tmp_path / folder).exists() or not any((tmp_path / folder).iterdir())


def test_every_shipped_scene_reads_its_options_into_settings():
    for name in list_scenes():
        scene = load_scene(name)
        timed = "duration" in scene.settings
        declared = options_for(scene.derivation, scene.outputs, scene.load_table, timed)
        assert list(scene.settings) == [o.name for o in declared], name
        assert set(scene.options) <= set(scene.settings), name
    assert load_scene("drum_drive_example").settings["m3"] == 800.0
    assert load_scene("fig12_startup_backlash").settings["backlash"][1] == pytest.approx(
        3.141592653589793)


def test_every_declared_option_is_documented_and_its_default_reads():
    for paper in registry.ids():
        for option in registry.scene_options(paper):
            assert option.description and option.what(), option
            if option.default is not REQUIRED:
                option.read(option.default)
        for check in registry.scene_checks(paper):
            assert isinstance(check, SceneCheck) and check.description


#: settings["x"], settings.get("x", options["x"] ... in a paper's modules
_READ = re.compile(r"""(?:settings|options)(?:\[|\.get\()\s*["'](\w+)["']""")


def test_every_option_a_paper_reads_is_declared():
    """Reports read ``scene.settings``, and only options their paper declares (or
    the general ``duration`` and ``points``, or a switch)."""
    for paper in registry.ids():
        package = ROOT / "derivations" / paper
        names = {o.name for o in registry.scene_options(paper)} | {"duration", "points"} \
            | set(registry.get(paper).switches)
        for source in package.glob("*.py"):
            text = source.read_text(encoding="utf-8")
            assert "scene.options.get(" not in text, source
            for name in _READ.findall(text):
                assert name in names, f"{source.name} reads option {name!r}, not declared"


def test_option_kinds_refuse_by_name():
    mass_option = SceneOption("m", "quantity", "a mass", unit="kg", dimension=mass, low=0.0,
                              above=True)
    assert mass_option.read("2 t") == 2000.0
    with pytest.raises(OptionError, match=r"m \(a mass\) must be a quantity of mass "
                                          r"\(e.g. kg\) > 0 kg, got '0 kg'"):
        mass_option.read("0 kg")
    with pytest.raises(OptionError, match=r"option 'm': '2 tt': unknown unit"):
        mass_option.read("2 tt")
    count = SceneOption("n", "int", "a count", 3, low=1, high=5)
    for bad in (True, 2.0, 6, "3"):
        with pytest.raises(OptionError, match=r"n \(a count\) must be an integer in 1..5"):
            count.read(bad)
    with pytest.raises(OptionError, match=r"lacks 'n' \(a count\), an integer in 1..5"):
        read_options({}, [SceneOption("n", "int", "a count", low=1, high=5)])
    assert read_options({}, [count]) == {"n": 3}
    with pytest.raises(ValueError, match="kind must be one of"):
        SceneOption("x", "float", "no such kind")


@pytest.mark.parametrize("option, value, message", [
    ("--points", "0", r"--points: must be an integer in 2..1e7, got 0"),
    ("--rtols", "-1", r"--rtols: each tolerance must be in \[1e-13, 0.1\], got -1"),
    ("--rtols", "2", r"--rtols: each tolerance must be in \[1e-13, 0.1\], got 2"),
    ("--sizes", "0", r"--sizes: each must be an integer in 1..1e8, got 0"),
    ("--throughput-points", "0", r"--throughput-points: must be an integer in 1..1e8, got 0"),
    ("--compare-points", "0", r"--compare-points: each must be an integer in 2..1e7, got 0"),
])
def test_bench_options_are_refused_by_name_before_any_folder(option, value, message,
                                                              tmp_path, capsys):
    out = tmp_path / "bench"
    assert main(["bench", "000", option, value, "--out", str(out)]) == 2
    stdout, err = capsys.readouterr()
    assert stdout == "" and err.count("\n") == 1
    assert re.fullmatch(rf"crane-sym: error: {message}\n", err), err
    assert not out.exists()


def test_the_readme_names_every_option_and_the_drive_law_limits():
    from crane_sym.derivations.hoist_startup.drive_law_scene import LIMITS
    from crane_sym.derivations.hoist_startup.options import MAX_PERIODS
    text = (ROOT / "README.md").read_text(encoding="utf-8")
    scenes = text[text.index("#### Options, and what is checked on load"):]
    for paper in registry.ids():
        for option in registry.scene_options(paper):
            assert f"`{option.name}`" in scenes, option.name
    assert f"at most {LIMITS.pieces} pieces, each of degree at most {LIMITS.degree}" in text
    assert f"from 0 to {LIMITS.end:g} s, no piece shorter than {LIMITS.shortest * 1e3:g} ms" \
        in text
    assert f"≤ {LIMITS.value:g} m/s²" in text and f"at most {MAX_PERIODS} periods" in text
