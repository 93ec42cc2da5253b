"""crane_sym: derive, audit and generate code for the dynamics of crane mechanisms."""
from pathlib import Path as _Path

__version__ = "0.1.0"

# Installed, pyproject.toml's package-dir maps derivations/ and generated/ to
# crane_sym.derivations and crane_sym.generated. Run from a clone without
# installing (`python -m crane_sym` in its root), the clone's root on the
# package's path finds them under the same names.
_clone = _Path(__file__).resolve().parent.parent
if (_clone / "pyproject.toml").is_file() and (_clone / "derivations" / "__init__.py").is_file():
    __path__.append(str(_clone))
