"""The package list, found rather than written by hand.

A list typed into pyproject.toml goes stale the day a room is added (the wheel
once shipped without ``crane_sym.components`` and failed every command), so the
packages are found here: every package under ``crane_sym/``, and the papers
(``derivations/``) and the generated modules (``generated/``) under the names
``crane_sym.derivations`` and ``crane_sym.generated`` that pyproject.toml's
``package-dir`` maps them to. Everything else is declared in pyproject.toml.
"""
from setuptools import find_packages, setup

MAPPED = ("derivations", "generated")

packages = find_packages(include=["crane_sym", "crane_sym.*"]) + [
    f"crane_sym.{name}"
    for name in find_packages(include=[p for m in MAPPED for p in (m, f"{m}.*")])
]

package_data = {name: ["scenes/*.toml"] for name in packages
                if name.startswith("crane_sym.derivations.")}
# the machine reading's committed table of parses (crane_sym.audit.parse_table)
package_data["crane_sym.generated"] = ["machine_reading.json"]

setup(packages=packages, package_data=package_data)
