"""The natural frequencies the cycle limit rests on
(:func:`crane_sym.components.model_limits.frequencies`) against the closed
form of a two-mass chain, ground -c1- m1 -c2- m2, at 50 digits: the roots
ω² of m1 m2 λ² − (m2 (c1 + c2) + m1 c2) λ + c1 c2 = 0 (every group has
inertia: the assembly refuses one without, so NumPy's symmetric route)."""
from __future__ import annotations

import mpmath as mp
import numpy as np
import pytest

from crane_sym.components import ElasticLink, Mass
from crane_sym.components.model_limits import frequencies
from crane_sym.components.topology import assemble


def _closed(m1: float, m2: float, c1: float, c2: float) -> list[float]:
    with mp.workdps(50):
        a, b, c = mp.mpf(m1) * m2, -(mp.mpf(m2) * (c1 + c2) + mp.mpf(m1) * c2), mp.mpf(c1) * c2
        d = mp.sqrt(b * b - 4 * a * c)
        return sorted(float(mp.sqrt(r)) for r in ((-b - d) / (2 * a), (-b + d) / (2 * a)))


def _chain(m1: float, m2: float, c1: float, c2: float):
    return assemble([Mass("a", m1), Mass("b", m2), ElasticLink("l1", "ground", "a", c1, 0.0, 0.0),
                     ElasticLink("l2", "a", "b", c2, 0.0, 0.0)])


@pytest.mark.parametrize("m1, m2, c1, c2", [
    (1.0, 1.0, 1.0, 1.0),                 # equal subsystems
    (1e-3, 1e3, 1e6, 1e3),                # mass ratio 1e6
    (250e3, 250e3, 5e6, 5e6),             # 003's crane and side, both links alike
    (2.0, 3e-4, 7e8, 1e2),                # a light end on a soft link
])
def test_frequencies_equal_the_two_mass_closed_form(m1, m2, c1, c2):
    got = np.sort(frequencies(_chain(m1, m2, c1, c2)))
    np.testing.assert_allclose(got, _closed(m1, m2, c1, c2), rtol=1e-10)



def test_a_files_design_beyond_the_period_bound_is_refused_naming_its_values(tmp_path):
    """travel_braking_000 run for 1000 s: 4.2e3 periods of its slowest mode as
    written, 1.34e4 with the transmission ten times as stiff (ω ∝ √c); the
    block is refused in one line naming that design, before it is solved."""
    from pathlib import Path

    from crane_sym.components.designs import designs
    from crane_sym.components.parts import ComponentError
    example = Path(__file__).resolve().parents[1] / "examples" / "drive_trains"
    text = (example / "travel_braking_000.toml").read_text()
    assert 'duration = "1.5 s"' in text
    path = tmp_path / "long_travel.toml"
    path.write_text(text.replace('duration = "1.5 s"', 'duration = "1000 s"'))
    block = designs(str(path))
    assert np.isfinite(block.largest("transmission.peak",
                                     {"transmission.stiffness": np.array([3e6])})).all()
    with pytest.raises(ComponentError) as refused:
        block.largest("transmission.peak", {"transmission.stiffness": np.array([3e6, 3e7])})
    message = str(refused.value)
    assert "\n" not in message
    assert message.startswith("design transmission.stiffness = 3e+07 kg*s^-2: run: duration "
                              "1000 s spans 1.34e+04 periods")
    assert "at most 10000" in message


def test_a_blocks_cycle_check_is_each_designs_own():
    """A block's designs checked in one stack (``first_beyond``): the first
    design past the bound, among designs of two sizes, with the message
    ``check_cycles`` gives that design alone; None where every one is within."""
    from crane_sym.components import ComponentError
    from crane_sym.components.model_limits import MAX_CYCLES, check_cycles, first_beyond
    single = assemble([Mass("a", 10.0), ElasticLink("l", "ground", "a", 1e3, 0.0, 0.0)])
    free = assemble([Mass("z", 1.0)])               # no link: no mode, never beyond
    designs = [_chain(1.0, 2.0, 1e3, 5e2), single, _chain(1.0, 2.0, 1e2, 1e15),
               _chain(1.0, 2.0, 1e-6, 1e15), _chain(1.0, 2.0, 1e3, 1e3)]
    duration = 100.0
    alone = []
    for d, a in enumerate(designs):
        try:
            check_cycles(a, duration)
        except ComponentError as exc:
            alone.append((d, str(exc)))
    # 2: the stiff link on a soft one, many periods; 3: a slow mode under 1e-12 of
    # the fast one is not counted, so the fast one's periods are
    assert [d for d, _ in alone] == [2, 3]
    d, exc = first_beyond(designs, duration)
    assert (d, str(exc)) == alone[0]
    assert first_beyond([designs[0], single, designs[4]], duration) is None
    for a in designs:                # the stack's slowest ω as each design's own, to 0.1 %
        period = 2 * np.pi / frequencies(a).min()
        assert first_beyond([a], MAX_CYCLES * period * 0.999) is None
        assert first_beyond([free, a], MAX_CYCLES * period * 1.001)[0] == 1
