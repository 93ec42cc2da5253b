"""The support loads (3)–(4) from the statics of a reconstructed portal, and
Table 1's own arithmetic (each dynamic coefficient against its F_max and F_ср).
"""
from __future__ import annotations

import sympy as sp

from crane_sym.derivation import Derivation

from .model import (G_g, G_pch, G_vs, L_max, M_v, R_max, V_total, c_arm, psi, psi_cell,
                    x_o)
from .tables import TABLE1, TABLE1_F_MEAN_KN


def support_loads(d: Derivation) -> None:
    """(4) the moment of the vertical loads, (3) the largest load on a leg."""
    d.add("portal vertical load", sp.Eq(V_total, psi * G_g + G_pch + G_vs),
          "Load case 2в: the crane stands, the rated load is picked up at the largest "
          "reach with the dynamic coefficient ψ; the slewing part and the portal's upper "
          "structure add their weights.", "What the four legs carry together.",
          "Support loads (reconstructed portal)")
    d.add("(4)", sp.Eq(M_v, psi * G_g * L_max - G_pch * x_o),
          "Moments about the slewing axis: the load at the reach L_max against the "
          "slewing part's weight at x_o on the other side.")
    d.add("(3)", sp.Eq(R_max, (psi * G_g + G_pch + G_vs) / 4
                       + M_v / (2 * c_arm)),
          "Each of the four legs takes a quarter of V; the circular rail passes M_в as "
          "a couple ±M_в/c, and each force of the couple is shared by the two legs under "
          "it, so a leg on the loaded side takes M_в/(2c) more.")


def table1_arithmetic(d: Derivation) -> None:
    """Table 1: ψ = F_max/F_ср for each backlash, from the table's own cells."""
    for i, row in enumerate(TABLE1):
        d.add(f"Table 1, psi, backlash {row['backlash']}",
              sp.Eq(psi_cell, sp.Rational(row["F_max_kN"]) / TABLE1_F_MEAN_KN),
              f"F_max/F_ср = {row['F_max_kN']}/{TABLE1_F_MEAN_KN} from the same row.",
              title="Table 1's own arithmetic" if i == 0 else "")
