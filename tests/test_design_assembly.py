"""A design's parts assembled on its template's assembly
(:mod:`crane_sym.components.design_assembly`) against the full assembly of
the same parts, on every example; parts that differ in more than their
values take the full assembly, and a design's bad values are refused as
there."""
from __future__ import annotations

from pathlib import Path

import pytest

from crane_sym import units
from crane_sym.components import design_assembly
from crane_sym.components.designs import designs
from crane_sym.components.parts import ComponentError, ElasticLink, Mass
from crane_sym.components.topology import assemble

EXAMPLES = sorted((Path(__file__).resolve().parents[1] / "examples" / "drive_trains")
                  .glob("*.toml"))


@pytest.mark.parametrize("path", EXAMPLES, ids=[p.stem for p in EXAMPLES])
def test_a_design_assembled_on_its_template_is_its_full_assembly(path, monkeypatch):
    found = designs(path)
    full = []
    monkeypatch.setattr(design_assembly, "assemble",
                        lambda parts: full.append(1) or assemble(parts))
    for name, field in list(found.fields.items())[:3]:
        value = units.parse_quantity(field.text).value if field.text else 0.0
        parts = found.parts({name: 1.5 * value if value else 2.0})
        again = design_assembly.reassemble(parts, found.model.components,
                                           found.model.assembly)
        assert again == assemble(parts), name
    assert not full                       # the template's lists taken, never the full walk


def test_parts_that_differ_in_more_than_their_values_are_assembled_in_full():
    template = [Mass("a", 10.0), Mass("b", 20.0), ElasticLink("ab", "a", "b", 1e4, 0.0, 0.01)]
    assembled = assemble(template)
    flipped = [Mass("a", 10.0), Mass("b", 20.0),
               ElasticLink("ab", "a", "b", 1e4, 0.0, 0.01, contact="negative")]
    swapped = [Mass("a", 10.0), Mass("b", 20.0), ElasticLink("ab", "b", "a", 2e4)]
    for parts in (flipped, swapped):
        assert not design_assembly._same_but_values(parts, template)
        assert design_assembly.reassemble(parts, template, assembled) == assemble(parts)
    assert design_assembly._same_but_values(
        [Mass("a", 1.0), Mass("b", 2.0), ElasticLink("ab", "a", "b", 5e3, 1.0, 0.02)], template)


def test_a_designs_bad_values_are_refused_as_by_the_full_assembly():
    template = [Mass("a", 10.0), Mass("b", 20.0), ElasticLink("ab", "a", "b", 1e4)]
    assembled = assemble(template)
    bare = [Mass("a", 0.0), Mass("b", 20.0), ElasticLink("ab", "a", "b", 1e4)]
    with pytest.raises(ComponentError) as full:
        assemble(bare)
    with pytest.raises(ComponentError) as again:
        design_assembly.reassemble(bare, template, assembled)
    assert str(again.value) == str(full.value) and "no inertia" in str(full.value)
