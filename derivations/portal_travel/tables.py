"""Tables 1–3 of paper 003 as data, copied from 003_5e8a923a75d2f7ba.txt.

Decimal commas are written as points; every number is as printed.
"""
from __future__ import annotations

#: Table 1: start-up loads and accelerations with a slip-ring motor, per backlash
#: on the fast shaft [rad]: hold time per start step [s], acceleration per step
#: [m/s²], largest longitudinal load on a portal support F_max [kN], dynamic
#: coefficient F_max/F_ср with F_ср = 150 kN.
TABLE1_F_MEAN_KN = 150
TABLE1 = (
    {"backlash": "0", "hold_s": ("0.4", "0.8", "0.8"), "accel": ("0.25", "0.32", "0.21"),
     "F_max_kN": "240", "psi": "1.6"},
    {"backlash": "pi", "hold_s": ("0.4", "0.8", "0.8"), "accel": ("0.45", "0.27", "0.14"),
     "F_max_kN": "350", "psi": "2.3"},
    {"backlash": "2pi", "hold_s": ("0.4", "0.8", "0.8"), "accel": ("0.54", "0.20", "0.13"),
     "F_max_kN": "390", "psi": "2.6"},
)

#: Table 2: programme tests of the portal crane КПП-10/30, largest changes of the
#: support loads: loading case -> (vertical pressure [% of the largest working
#: support load], transverse force [kN]).
TABLE2 = {
    "rope deflection in the boom plane": ("4.05", "60"),
    "rope deflection out of the boom plane": ("6.7", "38"),
    "jerky braking of the slewing mechanism": ("4.7", "62"),
    "centrifugal forces": ("2.6", "5"),
    "wind load": ("1.3", "5"),
    "travel of the resultant of the crane's weight": ("43", "21"),
    "inaccuracies of track and portal": ("35", "18"),
    "jerky change of reach": ("2.7", "8"),
    "lifting the grab after digging": ("21.6", "21"),
}

#: Table 3: service tests of the support loads of the crane КПП-10/32:
#: (load, work variant) -> (mean m_R, standard deviation σ_R). The unit is not
#: printed; both are in the same unit, so exceedance probabilities do not need it.
TABLE3 = {
    ("vertical pressure", "ship-to-store"): ("46.3", "4.3"),
    ("transverse force", "ship-to-store"): ("0.7", "0.85"),
    ("vertical pressure", "mixed"): ("40.1", "6.1"),
    ("transverse force", "mixed"): ("0.9", "0.77"),
}


def table3_normal(load: str, variant: str) -> tuple[float, float]:
    """(m_R, σ_R) of Table 3 for ``load`` and ``variant`` as floats."""
    mean, std = TABLE3[(load, variant)]
    return float(mean), float(std)
