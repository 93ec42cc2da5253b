"""Writes ``box_extremes.py``: the extremes of 003's Table 1 numbers over the box
of the plausible parameters (:func:`.startup.table1_sensitivities`), studied
afresh (about 700 start-ups). Run after changing the start-up model or the box:

    python -m crane_sym.derivations.portal_travel.box_table
"""
from __future__ import annotations

import pprint
from pathlib import Path

from crane_sym.sensitivity import extremes_table

from .startup import box_inputs, table1_sensitivities

HEADER = ('"""The extremes of 003\'s Table 1 numbers over the box of the plausible\n'
          "parameters, as studied by ``box_table.py`` (written by\n"
          "``python -m crane_sym.derivations.portal_travel.box_table``; do not edit).\n"
          "``INPUTS`` is the digest of the inputs they were found for\n"
          '(``startup.box_inputs``); tests/test_portal_box.py checks them."""\n')


def render() -> str:
    """The source of ``box_extremes.py``, every box studied now."""
    table = extremes_table(table1_sensitivities(committed=False))
    return (f"{HEADER}\nINPUTS = {box_inputs()!r}\n\n"
            f"EXTREMES = {pprint.pformat(table, width=88, sort_dicts=False)}\n")


if __name__ == "__main__":
    Path(__file__).with_name("box_extremes.py").write_text(render())
