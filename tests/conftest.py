"""Shared fixtures: a test module names its paper with ``DERIVATION = "<id>"``."""
import os

import pytest

# SymPy's multivariate factorization (paper 004's Jacobian, ``sp.factor``) takes
# a path that depends on the symbols' string hashes: one hash seed in a CI run
# of this session spent 17 min in it where others take 8 s. The test workers
# (spawned after this file loads) get one fixed seed; the open issue is to make
# that step independent of the seed.
os.environ.setdefault("PYTHONHASHSEED", "0")

from crane_sym import registry
from crane_sym.audit.verdicts import audit


@pytest.fixture(scope="module")
def derivation(request):
    """The module's derivation, built once per test run (``registry.get``)."""
    return registry.get(request.module.DERIVATION)


@pytest.fixture(scope="module")
def records(derivation):
    """Audit records of the module's derivation by label."""
    return {r.label: r for r in audit(derivation)}
