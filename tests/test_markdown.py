"""The one Markdown table writer: its layout, and a malformed table refused."""
from __future__ import annotations

import doctest

import pytest

import crane_sym.markdown
from crane_sym.markdown import markdown_table


def test_the_docstring_example_holds():
    assert doctest.testmod(crane_sym.markdown).failed == 0


def test_layout_header_rule_rows():
    text = markdown_table(["a", "b", "c"], [["x", "", 3], (1.5, "y", "z")], align="lrc")
    assert text == "| a | b | c |\n| --- | ---: | :---: |\n| x |  | 3 |\n| 1.5 | y | z |"


def test_no_rows_leaves_header_and_rule():
    assert markdown_table(["a"], []) == "| a |\n| --- |"


def test_a_row_of_the_wrong_width_is_refused():
    with pytest.raises(ValueError, match=r"row 1 has 2 cells, the header 3"):
        markdown_table(["a", "b", "c"], [[1, 2, 3], [1, 2]])


@pytest.mark.parametrize("align", ["lr", "lrx"])
def test_an_align_that_does_not_fit_is_refused(align):
    with pytest.raises(ValueError, match="one of l, r, c for each of the 3 columns"):
        markdown_table(["a", "b", "c"], [], align=align)
